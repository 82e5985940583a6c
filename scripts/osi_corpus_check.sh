#!/usr/bin/env bash
# Run every corpus scenario with `oscsim run --osi`, once to .osi and once to .mcap, then
# check every trace with the official OSI Python bindings (scripts/osi_check.sh, which
# runs ../shared/tools/osi_check.py and, for .mcap, the schema comparison).
#
# Usage: scripts/osi_corpus_check.sh [OUT_DIR]
#   OUT_DIR (default target/osi-corpus) receives the traces and logs.
#   OSCSIM      the binary (default target/release/oscsim; build it first:
#               cargo build --release --locked -p oscsim-cli).
#   CORPUS      the corpus folder (default ../shared/corpus next to the repository).
#   OSI_CORPUS_DURATION  simulated seconds per scenario (--duration), or "full" (the
#               default): each scenario to its end, at most the 3600 s cap (5 scenarios
#               without stop trigger reach it). Full: 74 scenarios, 148 traces,
#               ~716k frames, ~670 MB, under 2 minutes on a 2-core VM after the release build.
#   OSI_CORPUS_KEEP=1    keep the traces after a passing check (they are deleted then,
#               to spare the disk; a failing check always keeps them).
#   OSI_CHECK_OPTIONAL=1 lets a missing Python toolchain pass (loudly), as in osi_check.sh.
#
# A scenario "runs" when `oscsim run` succeeds on it without --osi. One that fails with
# --osi but runs without is an OSI failure. One that fails both ways (a broken corpus
# file, a feature the engine refuses) is listed as not running and skipped.
# Exit status: 0 all checks passed; 1 a run with --osi or a trace check failed;
#   3 the OSI Python packages could not be installed (unless OSI_CHECK_OPTIONAL=1).
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/target/osi-corpus}"
# The release binary where cargo builds: CARGO_TARGET_DIR when set, else target/.
oscsim="${OSCSIM:-${CARGO_TARGET_DIR:-$root/target}/release/oscsim}"
corpus="${CORPUS:-$root/../shared/corpus}"
duration="${OSI_CORPUS_DURATION:-full}"

if [ ! -x "$oscsim" ]; then
    echo "osi_corpus_check: no oscsim binary at $oscsim (cargo build --release -p oscsim-cli)" >&2
    exit 1
fi
if [ ! -d "$corpus" ]; then
    echo "osi_corpus_check: no corpus at $corpus" >&2
    exit 1
fi
limit=()
case "$duration" in
    0 | full) ;;
    *) limit=(--duration "$duration") ;;
esac

mkdir -p "$out"
# Only what an earlier run of this script left there (OUT_DIR may be any folder).
rm -f "$out"/*.osi "$out"/*.mcap "$out"/*.log "$out/osi_check.txt"
# Same bytes on every run: pin the clock-dependent parts (see crates/cli/src/osi_sink.rs).
export SOURCE_DATE_EPOCH="${SOURCE_DATE_EPOCH:-0}"

traces=()
ran=0
not_running=()
osi_failed=()
for scenario in "$corpus"/esmini/xosc/*.xosc "$corpus"/generated/xosc/*.xosc; do
    name="$(basename "$(dirname "$(dirname "$scenario")")")_$(basename "$scenario" .xosc)"
    log="$out/$name.log"
    if "$oscsim" run "$scenario" --quiet "${limit[@]}" \
        --osi "$out/$name.osi" >"$log" 2>&1 \
        && "$oscsim" run "$scenario" --quiet "${limit[@]}" \
            --osi "$out/$name.mcap" >>"$log" 2>&1; then
        ran=$((ran + 1))
        traces+=("$out/$name.osi" "$out/$name.mcap")
    elif "$oscsim" run "$scenario" --quiet "${limit[@]}" >>"$log" 2>&1; then
        osi_failed+=("$name")
        echo "FAIL (runs without --osi, fails with it): $name" >&2
        sed 's/^/    /' "$log" >&2
    else
        not_running+=("$name")
    fi
done

echo "scenarios that run: $ran; traces: ${#traces[@]}; duration limit: ${limit[*]:-none}"
if [ "${#not_running[@]}" -gt 0 ]; then
    echo "scenarios that do not run (skipped, see $out/*.log): ${not_running[*]}"
fi
if [ "${#traces[@]}" -eq 0 ]; then
    echo "osi_corpus_check: no scenario ran" >&2
    exit 1
fi

report="$out/osi_check.txt"
"$root/scripts/osi_check.sh" "${traces[@]}" >"$report" 2>&1
check=$?
grep -v -E '^(== |[0-9]+ passed, [0-9]+ failed$|schema of .*: [0-9]+ official fields not written)' "$report" \
    | head -50
if [ "$check" -eq 3 ] || grep -q 'OSI CHECK NOT RUN' "$report"; then
    cat "$report" >&2
    [ "$check" -eq 0 ] || exit 3
    exit 0
fi
# The report holds, per trace, "== TRACE", osi_check.py's "N passed, M failed" (frames), and
# for .mcap the schema comparison's own "N passed, M failed" (fields) after "schema of …".
read -r checked passed failed schemas schema_failed < <(awk '
    /^== /                                { frames = 1; next }
    /^[0-9]+ passed, [0-9]+ failed$/ && frames { n++; p += $1; f += $3; frames = 0; next }
    /^[0-9]+ passed, [0-9]+ failed$/      { s++; sf += $3 }
    END { print n + 0, p + 0, f + 0, s + 0, sf + 0 }' "$report")
echo "OSI check: $checked of ${#traces[@]} traces checked; frames: $passed passed, $failed failed"
echo "MCAP schema comparison: $schemas traces, $schema_failed mismatches"
grep -m1 -E '^schema of .*official fields not written' "$report" | sed 's/^schema of [^:]*:/(each .mcap schema:/; s/$/)/'
if [ "$check" -ne 0 ] || [ "$failed" -ne 0 ] || [ "$schema_failed" -ne 0 ] \
    || [ "$checked" -ne "${#traces[@]}" ] || [ "${#osi_failed[@]}" -gt 0 ]; then
    echo "OSI CORPUS CHECK FAILED (details in $report)" >&2
    exit 1
fi
echo "OSI corpus check passed"
if [ "${OSI_CORPUS_KEEP:-0}" != "1" ]; then
    rm -f "${traces[@]}"
fi
