//! Batch throughput (issue 15): variants per second of the bundled cut-in
//! (`examples/scenarios/cut_in_highway.xosc`, 22 s simulated each, the default 0.05 s step),
//! 24 variants per iteration (`benches/cut_in_variants.xosc`), on one worker thread and on two.
//! Variants per second per core = elements/s of `jobs_1`; the speed-up from one core to two is
//! `jobs_1` time / `jobs_2` time. The plan (distribution, scenario, road network) is loaded
//! once outside the timing, as `oscsim batch` does.
//!
//! `journal_jobs_N` runs the same variants as `oscsim batch --out DIR` does (issue 32):
//! `run_durable` into an empty folder, each row appended to `DIR/batch.journal` as its variant
//! ends, the results files written at the end. Its time over `jobs_N`'s is the cost of the
//! journal, the sweep's digest and the three files. The folder is emptied outside the timing.
//!
//! `batch_seeds_5s` (issue 29) sweeps 100 seeds of `tests/files/seeded_cut_in.osc` (an
//! OpenSCENARIO DSL cut-in, 5 s simulated, 0.05 s step) on `examples/roads/highway.xodr`:
//! `seeds_jobs_N` as `oscsim batch X.osc --seeds 1..100` runs it (each variant re-solves the
//! constraints, plans and lowers the scenario, then runs it), and `resolve_only` the first part
//! alone (`load::Source::load` per seed), so its share of a variant's time is
//! `resolve_only` / `seeds_jobs_1`. The `.osc` is checked and the road read once outside the
//! timing, as `oscsim batch` does.
//!
//! `cargo bench -p oscsim-batch --bench variants`
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

use std::path::Path;

use batch::{run, run_durable, Options, Plan};
use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};

fn variants(c: &mut Criterion) {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/cut_in_variants.xosc");
    let plan = match Plan::load(&file) {
        Ok(p) => p,
        Err(e) => panic!("{}: {e}", file.display()),
    };
    let n = plan.variants.len() as u64;
    let mut group = c.benchmark_group("batch_cut_in_22s");
    group.sample_size(10);
    group.throughput(Throughput::Elements(n));
    for jobs in [1usize, 2] {
        let options = Options {
            jobs,
            ..Options::default()
        };
        group.bench_function(format!("jobs_{jobs}"), |b| {
            b.iter(|| {
                let table = match run(&plan, &options, &|_, _| {}) {
                    Ok(t) => t,
                    Err(e) => panic!("{e}"),
                };
                assert_eq!(table.rows.len() as u64, n);
                table
            })
        });
    }
    // Removed with its contents when `tmp` drops, also if the benchmark panics.
    let tmp = match tempfile::Builder::new()
        .prefix("oscsim-bench-journal-")
        .tempdir()
    {
        Ok(t) => t,
        Err(e) => panic!("temp dir: {e}"),
    };
    let out = tmp.path().join("out");
    for jobs in [1usize, 2] {
        let options = Options {
            jobs,
            ..Options::default()
        };
        group.bench_function(format!("journal_jobs_{jobs}"), |b| {
            b.iter_batched(
                || {
                    let _ = std::fs::remove_dir_all(&out);
                },
                |()| {
                    let finished = match run_durable(&plan, &options, &out, &|_, _| {}, &|_, _| {})
                    {
                        Ok(f) => f,
                        Err(e) => panic!("{e}"),
                    };
                    assert_eq!(finished.table.rows.len() as u64, n);
                    finished
                },
                BatchSize::PerIteration,
            )
        });
    }
    group.finish();
}

fn seeds(c: &mut Criterion) {
    let here = Path::new(env!("CARGO_MANIFEST_DIR"));
    let options = load::Options {
        road: Some(here.join("../../examples/roads/highway.xodr")),
        ..load::Options::default()
    };
    let n = 100u64;
    let plan = match Plan::seeds(
        &here.join("tests/files/seeded_cut_in.osc"),
        &options,
        (1..=n).collect(),
    ) {
        Ok(p) => p,
        Err(e) => panic!("{e}"),
    };
    let mut group = c.benchmark_group("batch_seeds_5s");
    group.sample_size(10);
    group.throughput(Throughput::Elements(n));
    for jobs in [1usize, 2] {
        let options = Options {
            jobs,
            ..Options::default()
        };
        group.bench_function(format!("seeds_jobs_{jobs}"), |b| {
            b.iter(|| {
                let table = match run(&plan, &options, &|_, _| {}) {
                    Ok(t) => t,
                    Err(e) => panic!("{e}"),
                };
                assert!(table.rows.iter().all(|r| r.result.is_ok()));
                table
            })
        });
    }
    let Some(seeds) = &plan.seeds else {
        panic!("a plan of seeds")
    };
    group.bench_function("resolve_only", |b| {
        b.iter(|| {
            seeds
                .seeds
                .iter()
                .map(|&s| match seeds.source.load(s) {
                    Ok(l) => l.resolved.len(),
                    Err(e) => panic!("{e}"),
                })
                .sum::<usize>()
        })
    });
    group.finish();
}

criterion_group!(benches, variants, seeds);
criterion_main!(benches);
