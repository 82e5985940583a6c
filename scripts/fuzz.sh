#!/usr/bin/env bash
# Runs every fuzz target of fuzz/, one after another, one libFuzzer job at a time under
# `nice -n 19` (the machine is shared), and prints per target the executions, coverage and
# outcome. See docs/robustness.md.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]   # long local runs: SECONDS of wall time each (default 600)
#   scripts/fuzz.sh --ci [TARGET...]        # CI: the same inputs on any machine (below)
#
# Needs the nightly toolchain (`cargo +nightly`); installs cargo-fuzz from crates.io if missing.
# Local runs: seed corpora are generated into fuzz/corpus/<target>/ (scripts/fuzz_seeds.py;
# kept between runs, so a run goes on from what the last one found).
# --ci: deterministic. Each target starts from freshly generated seeds only (in
# fuzz/target/ci-seeds/, given to libFuzzer as a list in name order, never as a folder whose
# listing order and leftovers differ between machines), with -seed=1 and a fixed number of
# executions per target (ci_runs below) instead of a wall-clock budget: the same binary tries
# the same inputs everywhere, so a CI finding replays on any machine. The fuzz process is made
# deterministic too (std HashMap keys fixed by fuzz/deterministic_getrandom.c, built with `cc`;
# no compare tracing, which sees pointers and clock values; no watchdog thread: hangs are
# caught by libFuzzer's -timeout of 60 s).
# Both: crash and hang inputs land in fuzz/artifacts/<target>/, logs in
# fuzz/logs/<target>-*.log, one summary line per target run in fuzz/artifacts/summary.tsv
# (seconds = wall time taken). Exit status 1 if any target found something.
#
# Environment: FUZZ_SANITIZER (default none: every oscsim crate forbids unsafe code, so
# AddressSanitizer would find nothing Rust's own checks miss and costs 2-3x the executions;
# set `address` to use it anyway), FUZZ_EXTRA (more libFuzzer flags).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
# fuzz/ is its own workspace and the binaries are run from fuzz/target below: a CARGO_TARGET_DIR
# meant for the main workspace (.ci/run honours one) must not move them.
unset CARGO_TARGET_DIR

ci=0
if [ "${1:-}" = --ci ]; then
    ci=1
    shift
else
    seconds="${1:-600}"
    shift || true
fi
sanitizer="${FUZZ_SANITIZER:-none}"

if ! rustc +nightly -V >/dev/null 2>&1; then
    echo "fuzz.sh: expected the nightly toolchain (rustup toolchain list), found none" >&2
    exit 1
fi
if ! cargo +nightly fuzz --version >/dev/null 2>&1; then
    cargo install cargo-fuzz --locked
fi

if [ "$ci" = 1 ]; then
    seeds=fuzz/target/ci-seeds
    rm -rf "$seeds"
    python3 scripts/fuzz_seeds.py corpus 65536 "$seeds"
    mkdir -p fuzz/target
    cc -shared -fPIC -O2 -o fuzz/target/deterministic_getrandom.so fuzz/deterministic_getrandom.c
    # The fuzz process made deterministic: std HashMap keys fixed (the getrandom above) and no
    # watchdog thread (its once-a-second check runs instrumented code: coverage that depends
    # on when it ticks; hangs are then caught by libFuzzer's -timeout below and the backstop
    # `timeout`). The targets run rayon's work on their own thread (support::on_this_thread).
    # -use_cmp=0 below: libFuzzer's tracing of compared values sees pointers (moved by
    # address-space randomisation; `setarch -R` would need a personality(2) call that container
    # sandboxes refuse) and the engine's stage timers.
    det=(env LD_PRELOAD="$root/fuzz/target/deterministic_getrandom.so" FUZZ_WATCHDOG=off)
else
    python3 scripts/fuzz_seeds.py corpus 65536
fi

# Per target: largest input (bytes) and dictionary. Hangs: an input that takes more than 10 s
# of CPU is written to fuzz/artifacts/<target>/hang-* by the targets' own watchdog
# (fuzz/fuzz_targets/support.rs; real scenarios and roads load in milliseconds). libFuzzer's
# -timeout (wall time) is only a backstop: its signal handler can deadlock in malloc.
declare -A max_len=([expr]=4096 [distribution]=16384 [opendrive]=65536 [xosc]=65536 [dsl]=16384 [structured]=4096)
declare -A dict=([opendrive]=opendrive [xosc]=openscenario [distribution]=openscenario [dsl]=dsl)
# --ci: executions per target (seed inputs included), each 5-20 s on the shared 2-core VM.
declare -A ci_runs=([expr]=2000000 [distribution]=500000 [opendrive]=50000 [xosc]=30000 [structured]=20000 [dsl]=3000)

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
    flags=(-max_len="${max_len[$t]:-65536}" -rss_limit_mb=2048 -print_final_stats=1)
    d="$root/fuzz/dict/${dict[$t]:-none}.dict"
    if [ -f "$d" ]; then flags+=(-dict="$d"); fi
    if [ "$ci" = 1 ]; then
        # No corpus folder: the seeds as a list in name order (none for `structured`, whose
        # inputs are read by `arbitrary`), found inputs kept in memory.
        list="$root/$seeds/$t.list"
        printf '%s' "$(find "$root/$seeds/$t" -type f 2>/dev/null | LC_ALL=C sort | paste -sd, -)" >"$list"
        runs="${ci_runs[$t]:-10000}"
        flags+=(-seed=1 -runs="$runs" -timeout=60 -use_cmp=0)
        if [ -s "$list" ]; then flags+=(-seed_inputs=@"$list"); fi
        inputs=()
        budget=600
        echo "== $t: $runs executions, -seed=1 (log $log)"
    else
        flags+=(-max_total_time="$seconds" -timeout=600)
        inputs=("fuzz/corpus/$t")
        det=()
        budget=$((seconds + 600))
        echo "== $t: ${seconds}s (log $log)"
    fi
    # shellcheck disable=SC2206
    flags+=(${FUZZ_EXTRA:-})
    outcome=ok
    start=$SECONDS
    # The binary itself (not `cargo fuzz run`), so that the backstop `timeout` reaches it.
    bin="fuzz/target/$(rustc +nightly -vV | sed -n 's/^host: //p')/release/$t"
    FUZZ_ARTIFACTS="$root/fuzz/artifacts/$t" nice -n 19 timeout --signal=KILL "$budget" \
        "${det[@]}" "$bin" -artifact_prefix="$root/fuzz/artifacts/$t/" "${flags[@]}" "${inputs[@]}" \
        >"$log" 2>&1 || outcome=finding
    took=$((SECONDS - start))
    execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | tail -n 1 | grep -o '[0-9]*$' || true)
    line=$(grep -E '^#[0-9]+.*cov: [0-9]+' "$log" | tail -n 1 || true)
    cov=$(grep -o 'cov: [0-9]*' <<<"$line" | grep -o '[0-9]*' || true)
    ft=$(grep -o 'ft: [0-9]*' <<<"$line" | grep -o '[0-9]*' || true)
    corpus=$(grep -o 'corp: [0-9]*' <<<"$line" | grep -o '[0-9]*' || true)
    if [ "$outcome" != ok ]; then
        failed=1
        grep -E 'panicked at|ERROR: libFuzzer|Test unit written to|==WATCHDOG==' "$log" | head -n 5 || true
    fi
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$t" "$took" "${execs:-?}" \
        "${cov:-?}" "${ft:-?}" "${corpus:-?}" "$outcome" | tee -a "$summary"
done
exit "$failed"
