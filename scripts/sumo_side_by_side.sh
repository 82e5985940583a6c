#!/usr/bin/env bash
# Driver-model traffic, oscsim against Eclipse SUMO side by side (issue 31; docs/performance.md):
# the scale highway of ../shared/tools/make_scale.py with every vehicle driven by `idm` or
# `mobil` (oscsim: ObjectController activated in the Init; SUMO: IDM with the same parameters,
# LC2013 lane changes for mobil, none for idm; same placements, speeds and sizes; step 0.05 s),
# 1,000 vehicles for 300 s and 4,000 vehicles for 150 s (the front vehicles stay on the 20 km
# road). The runs alternate (oscsim, SUMO, oscsim, …) REPEAT times; the table gives the least
# CPU time (user + system, the whole process: loading included) of each and the ratio.
#
# Usage: scripts/sumo_side_by_side.sh [OUT]     (OUT: scratch folder, default target/sumo)
#   REPEAT  runs of each (default 3)
#   OSCSIM  the oscsim binary (default: built here with cargo build --release -p oscsim-cli)
# SUMO is a measuring tool only: eclipse-sumo and scenariogeneration (for make_scale.py) are
# installed on first use into the venv OUT/venv, never into the project.
# Needs /usr/bin/time (GNU time). Run it through /work/bin/slot on the shared machine.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/target/sumo}"
repeat="${REPEAT:-3}"
corpus="$(cd "${CORPUS:-$root/../shared/corpus}" && pwd)"
tools="$(cd "$corpus/../tools" && pwd)"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
venv="$out/venv"
if [ ! -x "$venv/bin/python" ] || ! "$venv/bin/python" -c "import sumo, scenariogeneration" 2>/dev/null; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet "eclipse-sumo==1.28.0" "scenariogeneration==0.16.7"
fi
py="$venv/bin/python"
sumo_home="$("$py" -c 'import sumo; print(sumo.SUMO_HOME)')"
sumo_bin="$sumo_home/bin/sumo"
export PATH="$sumo_home/bin:$PATH" SUMO_HOME="$sumo_home"
if [ -z "${OSCSIM:-}" ]; then
    cargo build --release --quiet -p oscsim-cli --manifest-path "$root/Cargo.toml"
    OSCSIM="$root/target/release/oscsim"
fi
oscsim="$OSCSIM"
echo "machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo), load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "oscsim $oscsim ($(git -C "$root" rev-parse --short HEAD)), $("$sumo_bin" --version | head -1)"

cases=()
for nd in 1000:300 4000:150; do
    n="${nd%%:*}" d="${nd##*:}"
    "$py" "$tools/make_scale.py" "$out/scale_$n" "$n" "$d" >/dev/null
    for m in idm mobil; do
        "$py" "$root/scripts/traffic_scale.py" oscsim "$out/scale_$n/xosc/scale_$n.xosc" "$m" "$out/scale_$n/xosc/${m}_$n.xosc"
        "$py" "$root/scripts/traffic_scale.py" sumo "$out/scale_$n/xosc/scale_$n.xosc" "$m" "$d" "$out/sumo_${m}_$n"
        cases+=("$n:$d:$m")
    done
done

# CPU (user + system) and wall time of one run, appended to $out/times.txt as
# "CASE TOOL WALL CPU PEAK_KB".
timed() {
    local case="$1" tool="$2"
    shift 2
    /usr/bin/time -f "%e %U %S %M" -o "$out/time.txt" "$@" >"$out/run.log" 2>&1
    read -r wall user sys rss <"$out/time.txt"
    echo "$case $tool $wall $(python3 -c "print($user + $sys)") $rss" >>"$out/times.txt"
}
: >"$out/times.txt"
for _ in $(seq "$repeat"); do
    for c in "${cases[@]}"; do
        IFS=: read -r n d m <<<"$c"
        timed "$c" oscsim "$oscsim" run "$out/scale_$n/xosc/${m}_$n.xosc" --quiet
        timed "$c" sumo "$sumo_bin" -c "$out/sumo_${m}_$n/run.sumocfg"
        grep -q "Inserted: $n" "$out/run.log" || { echo "SUMO did not insert all $n vehicles:" >&2; cat "$out/run.log" >&2; exit 1; }
    done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$out/times.txt" <<'EOF'
import sys
from collections import defaultdict
runs = defaultdict(list)
for line in open(sys.argv[1]):
    case, tool, wall, cpu, rss = line.split()
    runs[(case, tool)].append((float(cpu), float(wall), int(rss)))
print(f"{'vehicles':>8} {'model':>6} {'sim s':>6} {'entity-steps':>13} {'oscsim CPU':>11} {'M/s':>6} "
      f"{'SUMO CPU':>9} {'M/s':>6} {'SUMO/oscsim':>11}  (least of {len(runs[next(iter(runs))])} runs; wall, peak MB: oscsim | SUMO)")
for case in dict.fromkeys(c for c, _ in runs):
    n, d, m = case.split(":")
    steps = int(n) * (round(float(d) / 0.05) + 1)
    o, s = min(runs[(case, "oscsim")]), min(runs[(case, "sumo")])
    print(f"{n:>8} {m:>6} {d:>6} {steps:>13,} {o[0]:>10.2f}s {steps / o[0] / 1e6:>6.2f} {s[0]:>8.2f}s "
          f"{steps / s[0] / 1e6:>6.2f} {s[0] / o[0]:>10.1f}x  ({o[1]:.2f} s, {o[2] / 1024:.0f} MB | {s[1]:.2f} s, {s[2] / 1024:.0f} MB)")
EOF
