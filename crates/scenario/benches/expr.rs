//! Criterion benchmarks of the OpenSCENARIO 1.3 §9.2 expression evaluator and the §9.5
//! distribution expansion: parse + evaluate of a typical attribute expression, evaluation of
//! a parsed expression, and the 20 000-run stochastic plan of the test fixtures.
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use scenario::distribution::DistributionPlan;
use scenario::expr::{evaluate, Expression, Value};

/// A typical attribute expression: a braking distance with a safety margin.
const SOURCE: &str =
    "max(sqrt(2 * $acceleration * $distance), $speed / 3.6 * 1.5) + round($margin) % 3";

fn lookup(name: &str) -> Option<Value> {
    match name {
        "acceleration" => Some(Value::Double(4.5)),
        "distance" => Some(Value::Double(30.0)),
        "speed" => Some(Value::Double(120.0)),
        "margin" => Some(Value::Double(7.4)),
        _ => None,
    }
}

fn expressions(c: &mut Criterion) {
    c.bench_function("expr/parse_and_evaluate", |b| {
        b.iter(|| evaluate(black_box(SOURCE), &lookup))
    });
    let parsed = Expression::parse(SOURCE).unwrap_or_else(|e| panic!("{e}"));
    c.bench_function("expr/evaluate_parsed", |b| {
        b.iter(|| black_box(&parsed).evaluate(&lookup))
    });
}

fn distributions(c: &mut Criterion) {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/distribution/stochastic_all.xosc");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{e}"));
    c.bench_function("distribution/stochastic_20000_runs_7_parameters", |b| {
        b.iter(|| DistributionPlan::from_text(black_box(&text), &path))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).measurement_time(Duration::from_secs(3));
    targets = expressions, distributions
}
criterion_main!(benches);
