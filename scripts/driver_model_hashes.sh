#!/usr/bin/env bash
# The driver-model outputs that every speed-up of issue 31 must leave byte-identical: the
# trajectory CSV and the event log (SHA-256, streamed: the 4,000-vehicle CSV is ~1 GB) of
#   idm and mobil on the scale highway at 1,000 vehicles x 300 s and 4,000 x 150 s,
#   acc at 1,000 x 60 s, the scale highway with --vehicle-model mobil (60 s),
#   every scenario of crates/engine/tests/files/controller (errors: stderr and exit code),
#   esmini's swarm.xosc with --traffic-model idm and mobil.
# Usage: scripts/driver_model_hashes.sh OSCSIM SCALE > hashes.txt
#   OSCSIM  the release binary; SCALE the folder scripts/sumo_side_by_side.sh filled
#   (SCALE/scale_1000/xosc/{scale,idm,mobil}_1000.xosc, SCALE/scale_4000/xosc/{idm,mobil}_4000.xosc).
# Compare two runs with diff. Run it through /work/bin/slot on the shared machine.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="$1" scale="$(cd "$2" && pwd)"
corpus="$(cd "${CORPUS:-$root/../shared/corpus}" && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
acc="$scale/scale_1000/xosc/acc_1000.xosc"
[ -f "$acc" ] || python3 "$root/scripts/traffic_scale.py" oscsim "$scale/scale_1000/xosc/scale_1000.xosc" acc "$acc"

# NAME FILE ARGS...: one line "NAME csv=… events=… rc=… stderr=…" (a run that fails before
# opening an output hashes it empty). The outputs are fifos read by sha256sum.
mkfifo "$tmp/out.csv" "$tmp/out.jsonl"
case_() {
    local name="$1" file="$2"
    shift 2
    local rc=0 f
    sha256sum <"$tmp/out.csv" | cut -c1-16 >"$tmp/csv.sum" &
    local csum=$!
    sha256sum <"$tmp/out.jsonl" | cut -c1-16 >"$tmp/jsonl.sum" &
    local esum=$!
    "$bin" run "$file" --quiet --csv "$tmp/out.csv" --events "$tmp/out.jsonl" "$@" \
        >/dev/null 2>"$tmp/stderr" || rc=$?
    # A reader still waiting to open its fifo: the run never opened it (an error); a writer
    # that opens and closes it ends it (bounded, in case the reader has just ended).
    for f in csv:$csum jsonl:$esum; do
        if kill -0 "${f#*:}" 2>/dev/null; then timeout 2 sh -c ": >'$tmp/out.${f%%:*}'" || true; fi
    done
    wait "$csum" "$esum"
    echo "$name csv=$(cat "$tmp/csv.sum") events=$(cat "$tmp/jsonl.sum") rc=$rc stderr=$(sed "s|$root/||g; s|$corpus/||g; s|$tmp/||g" "$tmp/stderr" | sha256sum | cut -c1-16)"
}
case_ idm_1000_300 "$scale/scale_1000/xosc/idm_1000.xosc" --duration 300
case_ mobil_1000_300 "$scale/scale_1000/xosc/mobil_1000.xosc" --duration 300
case_ idm_4000_150 "$scale/scale_4000/xosc/idm_4000.xosc" --duration 150
case_ mobil_4000_150 "$scale/scale_4000/xosc/mobil_4000.xosc" --duration 150
case_ acc_1000_60 "$acc" --duration 60
case_ vehicle_model_mobil_1000_60 "$scale/scale_1000/xosc/scale_1000.xosc" --duration 60 --vehicle-model mobil
for f in "$root"/crates/engine/tests/files/controller/*.xosc; do
    case_ "controller/$(basename "$f")" "$f"
done
for m in idm mobil; do
    case_ "swarm_$m" "$corpus/esmini/xosc/swarm.xosc" --traffic-model "$m"
done
