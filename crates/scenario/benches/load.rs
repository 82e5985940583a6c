//! Load time of the largest corpus scenarios with their catalogs (the road network file is
//! only checked to exist; parsing it is the opendrive crate's benchmark).
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]
// A benchmark: its set-up unwraps (a panic stops the benchmark).
#![allow(clippy::unwrap_used)]

use std::path::Path;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use scenario::Scenario;

fn corpus(rel: &str) -> std::path::PathBuf {
    Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus"
    ))
    .join(rel)
}

fn load(c: &mut Criterion) {
    let mut group = c.benchmark_group("load");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(3))
        .warm_up_time(Duration::from_secs(1));
    // parking_demo.xosc (68 kB, OpenSCENARIO 1.x, the largest corpus scenario) with the
    // esmini vehicle catalog (40 kB).
    let parking = corpus("esmini/xosc/parking_demo.xosc");
    group.bench_function("parking_demo", |b| {
        b.iter(|| Scenario::load(&parking).unwrap())
    });
    // end_of_road_reset_traffic0.xosc (61 kB, 1.3, generated) with its vehicle catalog.
    let traffic = corpus("generated/xosc/end_of_road_reset_traffic0.xosc");
    group.bench_function("end_of_road_reset_traffic0", |b| {
        b.iter(|| Scenario::load(&traffic).unwrap())
    });
    group.finish();
}

criterion_group!(benches, load);
criterion_main!(benches);
