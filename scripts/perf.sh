#!/usr/bin/env bash
# Performance figures of issue 17 in one command (docs/performance.md explains each):
#   scale highway (1,000 vehicles, 20 km, default controller, dt 0.05): entity-steps/s with no
#   output, CSV rows/s with --csv, OSI moving objects/s with --osi; peak memory at 60 s and at
#   300 s simulated; the same with every vehicle driven by idm and by mobil (issue 31); load
#   of the 60 MB town grid; the esmini corpus loop (one process each).
#
# Usage: scripts/perf.sh [OUT]      (OUT: scratch folder, default target/perf)
# Needs: python3 with scenariogeneration (pip install scenariogeneration) for
# ../shared/tools/make_scale.py, and /usr/bin/time (GNU time) for CPU time and peak memory.
# Each figure is printed with wall and CPU (user + system) time: on a shared machine the CPU
# time is the steadier one. The machine's load average is printed first.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/target/perf}"
corpus="$(cd "${CORPUS:-$root/../shared/corpus}" && pwd)"
tools="$(cd "$corpus/../tools" && pwd)"
mkdir -p "$out"
cargo build --release --quiet -p oscsim-cli -p oscsim-opendrive --examples --bins \
    --manifest-path "$root/Cargo.toml"
oscsim="$root/target/release/oscsim"
echo "machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo), load average $(cut -d' ' -f1-3 /proc/loadavg)"

# timed LABEL UNITS COMMAND...: runs COMMAND, prints wall, CPU, peak RSS and UNITS per second.
timed() {
    local label="$1" units="$2"
    shift 2
    /usr/bin/time -f "%e %U %S %M" -o "$out/time.txt" "$@" >/dev/null
    read -r wall user sys rss <"$out/time.txt"
    python3 - "$label" "$units" "$wall" "$user" "$sys" "$rss" <<'EOF'
import sys
label, units, wall, user, sys_, rss = sys.argv[1], float(sys.argv[2]), *map(float, sys.argv[3:])
cpu = user + sys_
rate = lambda t: f"{units / t / 1e6:.2f} M/s" if units and t > 0 else "-"
print(f"{label:<34} wall {wall:6.2f} s ({rate(wall)})  CPU {cpu:6.2f} s ({rate(cpu)})  peak {rss / 1024:6.1f} MB")
EOF
}

n=1000
for d in 60 300; do
    python3 "$tools/make_scale.py" "$out/scale$d" $n $d >/dev/null
done
steps300=$((300 * 20 + 1))
steps60=$((60 * 20 + 1))
scale300="$out/scale300/xosc/scale_$n.xosc"
scale60="$out/scale60/xosc/scale_$n.xosc"
# Entity-steps: one per vehicle per step; rows: one per vehicle per frame (steps + the t = 0
# frame); OSI moving objects: one per vehicle per frame.
timed "scale 300 s, no output (steps)" $((n * steps300)) "$oscsim" run "$scale300" --quiet
timed "scale 60 s, no output (steps)" $((n * steps60)) "$oscsim" run "$scale60" --quiet
timed "scale 300 s, --csv (rows)" $((n * (steps300 + 1))) "$oscsim" run "$scale300" --quiet --csv "$out/scale.csv"
timed "scale 60 s, --osi (objects)" $((n * (steps60 + 1))) "$oscsim" run "$scale60" --quiet --osi "$out/scale.osi"
timed "scale load only (0 s)" 0 "$oscsim" run "$scale60" --quiet --duration 0.05
# Driver-model traffic (issue 31): every vehicle driven by idm, then mobil (ObjectController
# activated in the Init, scripts/traffic_scale.py); 300 s and 60 s for the peak memory.
for m in idm mobil; do
    for d in 300 60; do
        python3 "$root/scripts/traffic_scale.py" oscsim "$out/scale$d/xosc/scale_$n.xosc" $m "$out/scale$d/xosc/${m}_$n.xosc"
        steps=$((d * 20 + 1))
        timed "scale $d s, $m (steps)" $((n * steps)) "$oscsim" run "$out/scale$d/xosc/${m}_$n.xosc" --quiet
    done
done
rm -f "$out/scale.csv" "$out/scale.osi"

"$root/target/release/examples/grid_xodr" "$out/grid.xodr" 60
# World → road look-ups on the grid: points on the lane centres every 2 m (oscsim road
# sample), as x,y,h; the load of the grid (above) is part of the wall time.
# (the sampler stops when head has its million lines: its broken pipe is no failure here)
{ "$oscsim" road sample "$out/grid.xodr" --step 2 || true; } | head -n 1000001 \
    | awk -F, 'NR > 1 { print $4 "," $5 "," $7 }' >"$out/points.csv"
points=$(wc -l <"$out/points.csv")
timed "road locate ($points points, grid)" "$points" bash -c '"$1" road locate "$2" <"$3"' _ "$oscsim" "$out/grid.xodr" "$out/points.csv"
rm -f "$out/grid.xodr" "$out/points.csv"

# The esmini corpus loop: every scenario, one process each, dt 0.05, no output.
start=$(date +%s.%N)
/usr/bin/time -f "%U %S" -o "$out/corpus_cpu.txt" bash -c '
    for s in "$1"/esmini/xosc/*.xosc; do
        (cd "$(dirname "$s")" && "$2" run "$(basename "$s")" --quiet --dt 0.05 --seed 1 >/dev/null 2>&1 || true)
    done' _ "$corpus" "$oscsim"
end=$(date +%s.%N)
read -r user sys <"$out/corpus_cpu.txt"
python3 -c "import sys; w=float(sys.argv[2])-float(sys.argv[1]); c=float(sys.argv[3])+float(sys.argv[4]); print(f'esmini corpus loop ({sys.argv[5]} scenarios)   wall {w:6.2f} s  CPU {c:6.2f} s  (esmini 3.6.0: 3.33 s wall, ratio {w/3.33:.2f})')" \
    "$start" "$end" "$user" "$sys" "$(ls "$corpus"/esmini/xosc/*.xosc | wc -l)"
