//! Throughput of the syntax front end: lexing, parsing into the lossless tree, and formatting,
//! on the fixture with every construct repeated to about 100 KB.
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion, Throughput};

fn source() -> String {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/files/syntax/all_constructs.osc"
    );
    let one = std::fs::read_to_string(path).expect("fixture");
    // The imports must stay first (prelude): repeat the rest.
    let body: String = one
        .lines()
        .filter(|l| !l.starts_with("import"))
        .map(|l| format!("{l}\n"))
        .collect();
    body.repeat(100_000 / body.len() + 1)
}

fn bench(c: &mut Criterion) {
    let text = source();
    assert!(dsl::syntax::parse(&text).errors().is_empty());
    let mut group = c.benchmark_group("dsl_syntax");
    group.throughput(Throughput::Bytes(text.len() as u64));
    group.bench_function("lex", |b| b.iter(|| dsl::syntax::lex(&text)));
    group.bench_function("parse", |b| b.iter(|| dsl::syntax::parse(&text)));
    group.bench_function("format", |b| b.iter(|| dsl::syntax::format(&text)));
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
