//! Runtime cost: (1) wall time of the whole esmini cut-in scenario (build from the loaded
//! model, 22 s simulated at dt = 0.05 s, CSV and event log to memory); (2) the whole esmini
//! synchronize scenario (SynchronizeAction). Entity-steps per second of many vehicles:
//! benches/scale.rs.
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use engine::output::{CsvWriter, JsonlWriter};
use engine::{Engine, EngineConfig};
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Duration;

/// Wall time of a whole run of the esmini corpus scenario `file`: build from the loaded model,
/// run to the storyboard's end, CSV and event log to memory.
fn whole_run(c: &mut Criterion, group: &str, file: &str, measurement: Duration) {
    let path = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus/esmini/xosc"
    ))
    .join(file);
    let Ok(scenario) = scenario::Scenario::load(&path) else {
        eprintln!("{file} not found; skipping");
        return;
    };
    let mut group = c.benchmark_group(group);
    group.sample_size(10).measurement_time(measurement);
    group.bench_function(format!("{file} whole run"), |b| {
        b.iter(|| {
            // The road network is read in every iteration, as a one-off run reads it.
            let network = engine::load::road_network(&scenario).expect("road network loads");
            let mut engine =
                Engine::new(&scenario, network, EngineConfig::default()).expect("builds");
            let mut csv = CsvWriter::new(Vec::new());
            let mut events = JsonlWriter::new(Vec::new());
            engine.run(&mut csv, &mut events).expect("runs");
            black_box(csv.into_inner().len())
        })
    });
    group.finish();
}

fn cut_in(c: &mut Criterion) {
    whole_run(c, "runtime", "cut-in.xosc", Duration::from_secs(5));
}

/// SynchronizeAction cost: synchronize.xosc, 32.2 s simulated = 644 steps, seven vehicles of
/// which four synchronise with the master for 10 s.
fn synchronize(c: &mut Criterion) {
    whole_run(c, "synchronize", "synchronize.xosc", Duration::from_secs(3));
}

criterion_group!(benches, cut_in, synchronize);
criterion_main!(benches);
