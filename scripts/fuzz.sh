#!/usr/bin/env bash
# Runs every fuzz target of fuzz/ for SECONDS each (default 600), one after another, one
# libFuzzer job at a time under `nice -n 19` (the machine is shared), and prints per target the
# executions, coverage and outcome. See docs/robustness.md.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]
#
# Needs the nightly toolchain (`cargo +nightly`); installs cargo-fuzz from crates.io if missing.
# Seed corpora are generated into fuzz/corpus/<target>/ (scripts/fuzz_seeds.py; kept between
# runs, so a run goes on from what the last one found); crash and hang inputs land in
# fuzz/artifacts/<target>/, logs in fuzz/logs/<target>-*.log, one summary line per target run
# in fuzz/artifacts/summary.tsv. Exit status 1 if any target found something.
#
# Environment: FUZZ_SANITIZER (default none: every oscsim crate forbids unsafe code, so
# AddressSanitizer would find nothing Rust's own checks miss and costs 2-3x the executions;
# set `address` to use it anyway), FUZZ_EXTRA (more libFuzzer flags).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

seconds="${1:-600}"
shift || true
sanitizer="${FUZZ_SANITIZER:-none}"

if ! rustc +nightly -V >/dev/null 2>&1; then
    echo "fuzz.sh: expected the nightly toolchain (rustup toolchain list), found none" >&2
    exit 1
fi
if ! cargo +nightly fuzz --version >/dev/null 2>&1; then
    cargo install cargo-fuzz --locked
fi

python3 scripts/fuzz_seeds.py corpus 65536

# Per target: largest input (bytes) and dictionary. Hangs: an input that takes more than 10 s
# of CPU is written to fuzz/artifacts/<target>/hang-* by the targets' own watchdog
# (fuzz/fuzz_targets/support.rs; real scenarios and roads load in milliseconds). libFuzzer's
# -timeout (wall time) is only a backstop: its signal handler can deadlock in malloc.
declare -A max_len=([expr]=4096 [distribution]=16384 [opendrive]=65536 [xosc]=65536 [dsl]=16384 [structured]=4096)
declare -A dict=([opendrive]=opendrive [xosc]=openscenario [distribution]=openscenario [dsl]=dsl)

# Default: every target of fuzz/Cargo.toml, so a new one is run (and, in CI, checked) too.
if [ "$#" -gt 0 ]; then targets=("$@"); else
    mapfile -t targets < <(cd fuzz && cargo +nightly fuzz list)
fi

(cd fuzz && nice -n 19 cargo +nightly fuzz build -a -s "$sanitizer")

summary=fuzz/artifacts/summary.tsv
mkdir -p fuzz/artifacts
[ -f "$summary" ] || printf 'date\ttarget\tseconds\texecutions\tcov\tft\tcorpus\toutcome\n' >"$summary"

failed=0
for t in "${targets[@]}"; do
    mkdir -p "fuzz/artifacts/$t" "fuzz/corpus/$t" fuzz/logs
    log="fuzz/logs/$t-$(date -u +%Y%m%dT%H%M%S).log"
    flags=(-max_total_time="$seconds" -max_len="${max_len[$t]:-65536}" -timeout=600
        -rss_limit_mb=2048 -print_final_stats=1)
    d="$root/fuzz/dict/${dict[$t]:-none}.dict"
    if [ -f "$d" ]; then flags+=(-dict="$d"); fi
    # shellcheck disable=SC2206
    flags+=(${FUZZ_EXTRA:-})
    echo "== $t: ${seconds}s (log $log)"
    outcome=ok
    # The binary itself (not `cargo fuzz run`), so that the backstop `timeout` reaches it.
    bin="fuzz/target/$(rustc +nightly -vV | sed -n 's/^host: //p')/release/$t"
    FUZZ_ARTIFACTS="$root/fuzz/artifacts/$t" nice -n 19 timeout --signal=KILL $((seconds + 600)) \
        "$bin" -artifact_prefix="$root/fuzz/artifacts/$t/" "${flags[@]}" "fuzz/corpus/$t" \
        >"$log" 2>&1 || outcome=finding
    execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | tail -n 1 | grep -o '[0-9]*$' || true)
    line=$(grep -E '^#[0-9]+.*cov: [0-9]+' "$log" | tail -n 1 || true)
    cov=$(grep -o 'cov: [0-9]*' <<<"$line" | grep -o '[0-9]*' || true)
    ft=$(grep -o 'ft: [0-9]*' <<<"$line" | grep -o '[0-9]*' || true)
    corpus=$(find "fuzz/corpus/$t" -type f | wc -l)
    if [ "$outcome" != ok ]; then
        failed=1
        grep -E 'panicked at|ERROR: libFuzzer|Test unit written to|==WATCHDOG==' "$log" | head -n 5 || true
    fi
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$t" "$seconds" "${execs:-?}" \
        "${cov:-?}" "${ft:-?}" "$corpus" "$outcome" | tee -a "$summary"
done
exit "$failed"
