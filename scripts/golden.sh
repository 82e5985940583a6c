#!/usr/bin/env bash
# Golden outputs: run every scenario of the corpus and the examples with `oscsim run` and compare
# the SHA-256 of each output (trajectory CSV, event log, OSI trace, exit status) with the
# committed manifest tests/golden/outputs.sha256. A refactoring must leave every line unchanged;
# a change of behaviour on purpose regenerates the manifest in the same commit and says in the
# commit message which scenarios changed and why.
#
# Usage: scripts/golden.sh [--update]
#   --update    rewrite the manifest from this run instead of comparing.
#   OSCSIM      the binary (default: built here with cargo build --release -p oscsim-cli).
#   CORPUS      the corpus folder (default ../shared/corpus next to the repository).
#   GOLDEN_OUT  where the outputs go (default target/golden; emptied first, kept afterwards
#               so that a difference can be looked at).
#   GOLDEN_JOBS runs in parallel (default 2).
#
# Scenarios: ../shared/corpus/esmini/xosc/*.xosc, ../shared/corpus/generated/xosc/*.xosc,
# examples/scenarios/*.xosc; output names GROUP.NAME.{csv,jsonl,osi,status}. Each runs from its
# own folder with a relative path (so that file names in messages do not depend on where the
# repository is checked out) with fixed options: --dt 0.05 --seed 1 --max-time 120 (the cap
# keeps the scenarios without a stop trigger short), SOURCE_DATE_EPOCH=0. A scenario that does
# not load has only its status line (exit 1). The stderr of each run is in GROUP.NAME.log, not
# hashed (it holds the wall time).
# Exit status: 0 all outputs as in the manifest (or --update done); 1 a difference or a failure.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
manifest="$root/tests/golden/outputs.sha256"
update=0
case "${1:-}" in
    --update) update=1 ;;
    "") ;;
    *) echo "usage: scripts/golden.sh [--update]" >&2; exit 1 ;;
esac
if [ -z "${OSCSIM:-}" ]; then
    cargo build --release --locked --quiet -p oscsim-cli --manifest-path "$root/Cargo.toml"
    # Where cargo built it: CARGO_TARGET_DIR when set (as .ci/run honours it), else target/.
    OSCSIM="${CARGO_TARGET_DIR:-$root/target}/release/oscsim"
fi
corpus="$(cd "${CORPUS:-$root/../shared/corpus}" && pwd)"
out="${GOLDEN_OUT:-$root/target/golden}"
options="--dt 0.05 --seed 1 --max-time 120"
mkdir -p "$out"
rm -f "$out"/*.csv "$out"/*.jsonl "$out"/*.osi "$out"/*.status "$out"/*.log
export OSCSIM OPTIONS="$options" OUT="$out" SOURCE_DATE_EPOCH=0

# One run: $1 = group, $2 = scenario path.
run_one() {
    local name dir
    name="$1.$(basename "$2" .xosc)"
    dir="$(dirname "$2")"
    # shellcheck disable=SC2086 # OPTIONS is a list of words
    (cd "$dir" && "$OSCSIM" run "$(basename "$2")" --quiet $OPTIONS \
        --csv "$OUT/$name.csv" --events "$OUT/$name.jsonl" --osi "$OUT/$name.osi") \
        >"$OUT/$name.log" 2>&1 && status=0 || status=$?
    echo "$status" >"$OUT/$name.status"
}
export -f run_one

{
    for s in "$corpus"/esmini/xosc/*.xosc; do printf 'esmini\0%s\0' "$s"; done
    for s in "$corpus"/generated/xosc/*.xosc; do printf 'generated\0%s\0' "$s"; done
    for s in "$root"/examples/scenarios/*.xosc; do printf 'examples\0%s\0' "$s"; done
} | xargs -0 -n 2 -P "${GOLDEN_JOBS:-2}" bash -c 'run_one "$0" "$1"'

current="$out/outputs.sha256"
{
    echo "# scripts/golden.sh: oscsim run $options (SOURCE_DATE_EPOCH=0), sha256 of each output"
    (cd "$out" && LC_ALL=C sha256sum -- *.status *.csv *.jsonl *.osi | LC_ALL=C sort -k 2)
} >"$current"
scenarios=$(ls "$out"/*.status | wc -l)

if [ "$update" -eq 1 ]; then
    mkdir -p "$(dirname "$manifest")"
    cp "$current" "$manifest"
    echo "golden: manifest rewritten ($scenarios scenarios, $(grep -vc '^#' "$manifest") outputs): $manifest"
    exit 0
fi
if [ ! -f "$manifest" ]; then
    echo "golden: no manifest at $manifest (scripts/golden.sh --update writes it)" >&2
    exit 1
fi
if diff -u "$manifest" "$current" >"$out/outputs.diff"; then
    echo "golden: $scenarios scenarios, $(grep -vc '^#' "$current") outputs byte-identical to the manifest"
    exit 0
fi
echo "GOLDEN OUTPUTS DIFFER (outputs in $out, diff in $out/outputs.diff):" >&2
grep -E '^[-+][0-9a-f]{64} ' "$out/outputs.diff" \
    | awk '{ side = substr($1, 1, 1) == "-" ? "manifest" : "now     "; print "  " side " " $2 }' >&2
exit 1
