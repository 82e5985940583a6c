//! Driver-model traffic (issues 13 and 31): entity-steps per second of the scale highway
//! (tests/support/scale.rs: the 20 km road of `../shared/tools/make_scale.py`, vehicle i in
//! lane −(1 + i mod 4) at s = 100 + 15·⌊i/4⌋ m, 20 + (i mod 7) m/s) with every vehicle driven
//! by an ObjectController `idm` or `mobil` (the models' defaults, desired speed = the start
//! speed) activated in the Init, at 1,000 and 4,000 vehicles; and for comparison the 1,000
//! vehicles under the default controller. Each step builds the per-lane index, and each
//! vehicle asks for its leader (`idm`) or also weighs the lanes beside it (`mobil`).
//!
//! `cargo bench -p oscsim-engine --bench controllers` (criterion's "elem/s" = vehicles ×
//! steps per second); docs/performance.md lists the figures with the machine. Each measured
//! iteration continues the same run (the vehicles stay on the 20 km road for the ~150 s of
//! simulated time the longest benchmark reaches).
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

#[path = "../tests/support/scale.rs"]
mod scale;

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use engine::{Engine, EngineConfig};

/// Steps per measured iteration.
const STEPS: u64 = 20;
/// Simulated seconds of the scenario's stop trigger: past what the benchmark can reach.
const DURATION: f64 = 1e6;

fn highway(c: &mut Criterion) {
    let dir = scale::scratch("bench-controllers");
    let config = EngineConfig {
        max_time: DURATION,
        ..EngineConfig::default()
    };
    let mut group = c.benchmark_group("controllers");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(4));
    let runs = [
        (1_000, None),
        (1_000, Some("idm")),
        (4_000, Some("idm")),
        (1_000, Some("mobil")),
        (4_000, Some("mobil")),
    ];
    for (vehicles, model) in runs {
        let path = match model {
            Some(m) => scale::write_traffic(dir.path(), vehicles, DURATION, m),
            None => scale::write_scale(dir.path(), vehicles, DURATION),
        };
        let mut engine = Engine::load(&path, &[], config).expect("scale scenario loads");
        group.throughput(Throughput::Elements(vehicles as u64 * STEPS));
        let label = format!(
            "{vehicles} vehicles, {}",
            model.unwrap_or("default controller")
        );
        group.bench_function(label, |b| {
            b.iter(|| {
                for _ in 0..STEPS {
                    black_box(engine.step(&mut (), &mut ()).expect("steps"));
                }
            })
        });
    }
    group.finish();
}

criterion_group!(benches, highway);
criterion_main!(benches);
