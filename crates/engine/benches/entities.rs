//! Cost of the entity features of the runtime: (1) esmini's swarm.xosc, 10 s simulated at
//! dt = 0.05 s with its 75-vehicle TrafficSwarmAction around Ego on e6mini.xodr (spawning,
//! removal, lane look-ups for free points); (2) a truck pulling two trailers through a 90°
//! curve, 15 s (the one-axle trailer stage). Both build the engine from the loaded model
//! inside the measured loop.
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use engine::{Engine, EngineConfig};
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Duration;

/// Runs `path` for `duration` s (or to its stop trigger) and returns the number of steps.
fn whole_run(scenario: &scenario::Scenario, duration: Option<f64>) -> u64 {
    let config = EngineConfig {
        duration,
        ..EngineConfig::default()
    };
    let network = engine::load::road_network(scenario).expect("road network loads");
    let mut engine = Engine::new(scenario, network, config).expect("builds");
    engine.run(&mut (), &mut ()).expect("runs");
    engine.steps()
}

fn entities(c: &mut Criterion) {
    let swarm = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus/esmini/xosc/swarm.xosc"
    ));
    let chain = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/files/entities/trailer_chain.xosc"
    ));
    let mut group = c.benchmark_group("entities");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(5));
    if let Ok(scenario) = scenario::Scenario::load(&swarm) {
        group.throughput(Throughput::Elements(200));
        group.bench_function("swarm.xosc 10 s (steps)", |b| {
            b.iter(|| black_box(whole_run(&scenario, Some(10.0))))
        });
    } else {
        eprintln!("swarm.xosc not found; skipping");
    }
    let scenario = scenario::Scenario::load(&chain).expect("trailer_chain.xosc loads");
    group.throughput(Throughput::Elements(301));
    group.bench_function("3-unit trailer chain 15 s (steps)", |b| {
        b.iter(|| black_box(whole_run(&scenario, None)))
    });
    group.finish();
}

criterion_group!(benches, entities);
criterion_main!(benches);
