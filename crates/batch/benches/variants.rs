//! Batch throughput (issue 15): variants per second of the bundled cut-in
//! (`examples/scenarios/cut_in_highway.xosc`, 22 s simulated each, the default 0.05 s step),
//! 24 variants per iteration (`benches/cut_in_variants.xosc`), on one worker thread and on two.
//! Variants per second per core = elements/s of `jobs_1`; the speed-up from one core to two is
//! `jobs_1` time / `jobs_2` time. The plan (distribution, scenario, road network) is loaded
//! once outside the timing, as `oscsim batch` does.
//!
//! `cargo bench -p oscsim-batch --bench variants`

use std::path::Path;

use batch::{run, Options, Plan};
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

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
    group.finish();
}

criterion_group!(benches, variants);
criterion_main!(benches);
