//! Issue 17's figures for the engine library, on the scale highway (1,000 vehicles on the
//! 20 km road of `../shared/tools/make_scale.py`, written by tests/support/scale.rs: vehicle
//! i in lane −(1 + i mod 4) at s = 100 + 15·⌊i/4⌋ m, 20 + (i mod 7) m/s, on the default
//! controller):
//!
//! - `steps`: entity-steps per second of the default controller with no output (criterion's
//!   "elem/s" = vehicles × steps per second);
//! - `csv`: trajectory CSV rows per second (one row per vehicle per step, formatted into a
//!   sink, so the figure is the engine plus the writer, not the disk);
//! - `load`: loading the 1,000-vehicle scenario and building the engine (parse the scenario
//!   and its road, resolve the Init positions).
//!
//! `cargo bench -p oscsim-engine --bench scale` (or `-- steps` for one); docs/performance.md
//! lists the figures with the machine. Every measured iteration of `steps` and `csv` times the
//! same simulated work (issue 31), so builds compare: the [`STEPS`] steps from t = 10 s to
//! t = 11 s of an engine rebuilt, untimed, from the scenario kept in memory and stepped to
//! t = 10 s, checked before timing to end with every vehicle on the road, at most 4,121 m
//! along it (tests/support/fixed_work.rs, shared with benches/controllers.rs). Until issue 31
//! each iteration continued one run: warm-up and measurement took far more steps than the
//! ~300 s of simulated time the road holds, so most of them were of vehicles past its end.
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

#[path = "../tests/support/fixed_work.rs"]
mod fixed_work;
#[path = "../tests/support/scale.rs"]
mod scale;

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use engine::output::CsvWriter;
use engine::Engine;
use fixed_work::{check_fixed_work, steps, Start, DURATION, STEPS};

/// Vehicles on the highway (issue 17).
const VEHICLES: usize = 1_000;

/// A group of 10 samples; criterion's budget counts the untimed rebuild of each iteration of
/// `steps` and `csv` (20–50 ms at 1,000 vehicles), so 4 s give about 80–200 iterations, above
/// criterion's minimum of 55 for 10 samples.
fn group<'a>(
    c: &'a mut Criterion,
    name: &str,
) -> criterion::BenchmarkGroup<'a, criterion::measurement::WallTime> {
    let mut g = c.benchmark_group(name);
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    g
}

fn scale(c: &mut Criterion) {
    let dir = scale::scratch("bench-scale");
    let path = scale::write_scale(dir.path(), VEHICLES, DURATION);
    let start = Start::load(&path);
    check_fixed_work(&start, VEHICLES);

    let mut g = group(c, "scale");
    g.throughput(Throughput::Elements(VEHICLES as u64 * STEPS));
    g.bench_function("steps, 1000 vehicles, no output", |b| {
        b.iter_batched(
            || start.at_t0(),
            |e| steps(e, &mut ()),
            BatchSize::PerIteration,
        )
    });
    // One writer for all iterations: its header is written once, before the first row.
    let mut csv = CsvWriter::new(std::io::sink());
    g.bench_function("csv rows, 1000 vehicles", |b| {
        b.iter_batched(
            || start.at_t0(),
            |e| steps(e, &mut csv),
            BatchSize::PerIteration,
        )
    });
    g.finish();

    let mut g = group(c, "scale load");
    g.throughput(Throughput::Elements(VEHICLES as u64));
    g.bench_function("load 1000-vehicle scenario", |b| {
        b.iter(|| {
            let engine = Engine::load(&path, &[], fixed_work::config()).expect("the highway loads");
            black_box(engine.steps())
        })
    });
    g.finish();
}

criterion_group!(benches, scale);
criterion_main!(benches);
