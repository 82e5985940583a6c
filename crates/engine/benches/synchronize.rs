//! SynchronizeAction cost: wall time of the whole esmini synchronize.xosc run (build from the
//! loaded model, 32.2 s simulated at dt = 0.05 s = 644 steps, seven vehicles of which four
//! synchronise with the master for 10 s, CSV and event log to memory).

use criterion::{criterion_group, criterion_main, Criterion};
use engine::output::{CsvWriter, JsonlWriter};
use engine::{Engine, EngineConfig};
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Duration;

fn synchronize(c: &mut Criterion) {
    let path = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus/esmini/xosc/synchronize.xosc"
    ));
    let Ok(scenario) = scenario::Scenario::load(&path) else {
        eprintln!("synchronize.xosc not found; skipping");
        return;
    };
    let mut group = c.benchmark_group("synchronize");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(3));
    group.bench_function("synchronize.xosc whole run", |b| {
        b.iter(|| {
            let mut engine = Engine::build(&scenario, EngineConfig::default()).expect("builds");
            let mut csv = CsvWriter::new(Vec::new());
            let mut events = JsonlWriter::new(Vec::new());
            engine.run(&mut csv, &mut events).expect("runs");
            black_box(csv.into_inner().len())
        })
    });
    group.finish();
}

criterion_group!(benches, synchronize);
criterion_main!(benches);
