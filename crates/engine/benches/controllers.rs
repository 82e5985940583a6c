//! Driver-model traffic (issues 13 and 31): entity-steps per second of the scale highway
//! (tests/support/scale.rs: the 20 km road of `../shared/tools/make_scale.py`, vehicle i in
//! lane −(1 + i mod 4) at s = 100 + 15·⌊i/4⌋ m, 20 + (i mod 7) m/s) with every vehicle driven
//! by an ObjectController `idm` or `mobil` (the models' defaults, desired speed = the start
//! speed) activated in the Init, at 1,000 and 4,000 vehicles; and for comparison the 1,000
//! vehicles under the default controller. Each step builds the per-lane index, and each
//! vehicle asks for its leader (`idm`) or also weighs the lanes beside it (`mobil`).
//!
//! `cargo bench -p oscsim-engine --bench controllers` (criterion's "elem/s" = vehicles ×
//! [`STEPS`] per second of the timed steps); docs/performance.md lists the figures with the
//! machine. Every measured iteration does the same simulated work, so builds compare: the
//! [`STEPS`] steps from t = 10 s to t = 11 s of an engine rebuilt, untimed, from the scenario
//! kept in memory, checked before timing to end with every vehicle on the road
//! (tests/support/fixed_work.rs, shared with benches/scale.rs).
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

#[path = "../tests/support/fixed_work.rs"]
mod fixed_work;
#[path = "../tests/support/scale.rs"]
mod scale;

use std::time::Duration;

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use fixed_work::{check_fixed_work, steps, Start, DURATION, STEPS};

fn highway(c: &mut Criterion) {
    let dir = scale::scratch("bench-controllers");
    let mut group = c.benchmark_group("controllers");
    group.sample_size(10).warm_up_time(Duration::from_secs(1));
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
        let start = Start::load(&path);
        check_fixed_work(&start, vehicles);
        // Criterion's time budget counts the untimed rebuild too (20–50 ms per iteration at
        // 1,000 vehicles, 250–360 ms at 4,000 on the team's VM under load): 110 iterations or
        // more at 1,000, at 4,000 criterion's minimum of 55 for 10 samples.
        group
            .measurement_time(Duration::from_secs(if vehicles > 1_000 { 12 } else { 4 }))
            .throughput(Throughput::Elements(vehicles as u64 * STEPS));
        let label = format!(
            "{vehicles} vehicles, {}",
            model.unwrap_or("default controller")
        );
        group.bench_function(label, |b| {
            b.iter_batched(
                || start.at_t0(),
                |e| steps(e, &mut ()),
                BatchSize::PerIteration,
            )
        });
    }
    group.finish();
}

criterion_group!(benches, highway);
criterion_main!(benches);
