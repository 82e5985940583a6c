//! Issue 17's figures for the engine library, on the scale highway (1,000 vehicles on the
//! 20 km road of `../shared/tools/make_scale.py`, written by tests/support/scale.rs):
//!
//! - `steps`: entity-steps per second of the default controller with no output (criterion's
//!   "elem/s" = vehicles × steps per second);
//! - `csv`: trajectory CSV rows per second (one row per vehicle per step, formatted into a
//!   sink, so the figure is the engine plus the writer, not the disk);
//! - `load`: loading the 1,000-vehicle scenario and building the engine (parse the scenario
//!   and its road, resolve the Init positions).
//!
//! `cargo bench -p oscsim-engine --bench scale` (or `-- steps` for one); docs/performance.md
//! lists the figures with the machine. Each measured iteration continues the same run, so the
//! vehicles stay on the road for the whole benchmark (20–26 m/s for at most ~300 s of
//! simulated time on 20 km).
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

#[path = "../tests/support/scale.rs"]
mod scale;

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use engine::output::CsvWriter;
use engine::{Engine, EngineConfig};

/// Vehicles on the highway (issue 17).
const VEHICLES: usize = 1_000;
/// Steps per measured iteration.
const STEPS: u64 = 20;
/// Simulated seconds of the scenario's stop trigger: past what the benchmark can reach.
const DURATION: f64 = 1e6;

fn group<'a>(
    c: &'a mut Criterion,
    name: &str,
) -> criterion::BenchmarkGroup<'a, criterion::measurement::WallTime> {
    let mut g = c.benchmark_group(name);
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    g
}

fn engine(path: &std::path::Path) -> Engine {
    let config = EngineConfig {
        max_time: DURATION,
        ..EngineConfig::default()
    };
    Engine::load(path, &[], config).expect("the highway loads")
}

fn scale(c: &mut Criterion) {
    let dir = scale::scratch("bench-scale");
    let path = scale::write_scale(dir.path(), VEHICLES, DURATION);

    let mut g = group(c, "scale");
    g.throughput(Throughput::Elements(VEHICLES as u64 * STEPS));
    let mut quiet = engine(&path);
    g.bench_function("steps, 1000 vehicles, no output", |b| {
        b.iter(|| {
            for _ in 0..STEPS {
                black_box(quiet.step(&mut (), &mut ()).expect("steps"));
            }
        })
    });
    let mut with_csv = engine(&path);
    let mut csv = CsvWriter::new(std::io::sink());
    g.bench_function("csv rows, 1000 vehicles", |b| {
        b.iter(|| {
            for _ in 0..STEPS {
                black_box(with_csv.step(&mut csv, &mut ()).expect("steps"));
            }
        })
    });
    g.finish();

    let mut g = group(c, "scale load");
    g.throughput(Throughput::Elements(VEHICLES as u64));
    g.bench_function("load 1000-vehicle scenario", |b| {
        b.iter(|| black_box(engine(&path).steps()))
    });
    g.finish();
}

criterion_group!(benches, scale);
criterion_main!(benches);
