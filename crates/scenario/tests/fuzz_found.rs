//! Inputs the fuzzers found (fuzz/, docs/robustness.md), kept as regression tests: each test is
//! named after the bug, its input is in `tests/files/fuzz/` as the fuzzer wrote it (or cut down
//! by hand where the comment says so).

use std::path::Path;

use scenario::distribution::{DistributionErrorKind, DistributionPlan, MAX_REJECTED_DRAWS};
use scenario::expr::{evaluate, ExprErrorKind, Value};

/// A file of `tests/files/fuzz/`.
fn fuzz_file(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/files/fuzz")
        .join(name)
}

fn no_parameters(_: &str) -> Option<Value> {
    None
}

/// The product of two unsigned literals near 2^64 overflowed the 128-bit intermediate
/// ((2^64 − 1)² > 2^127 − 1): a panic with overflow checks, a wrap-around without. It is now
/// the 64-bit overflow error at the `*`.
#[test]
fn expr_unsigned_product_overflows_i128() {
    // 13333333666666666666² ≈ 1.78e38 > i128::MAX ≈ 1.70e38; the `*` is at byte 20.
    let err = evaluate("13333333666666666666*13333333666666666666", &no_parameters).unwrap_err();
    assert!(matches!(
        err.kind(),
        ExprErrorKind::IntegerOverflow { operator: "*" }
    ));
    assert_eq!(err.offset(), 20);
    assert_eq!(
        err.to_string(),
        "expected a result of * within the 64-bit integer range, found an overflow"
    );
    // The fuzzer's input: the same product inside a longer sum, an error too.
    let found = include_str!("files/fuzz/expr_unsigned_product_overflows_i128.txt");
    let err = evaluate(found, &no_parameters).unwrap_err();
    assert!(
        matches!(err.kind(), ExprErrorKind::IntegerOverflow { .. }),
        "{err}"
    );
}

/// A truncation Range that accepts one draw in a few hundred, over 100 000 runs and several
/// parameters, took billions of draws (the per-value limit of MAX_ATTEMPTS never tripped): a
/// hang. Discarded draws are now limited over the whole plan.
#[test]
fn distribution_truncation_draws_unbounded() {
    let path = &fuzz_file("distribution_truncation_draws_unbounded.xosc");
    let err = DistributionPlan::load(path).unwrap_err();
    assert!(
        matches!(
            err.kind(),
            DistributionErrorKind::RangeRarelyReached {
                limit: MAX_REJECTED_DRAWS
            }
        ),
        "{err}"
    );
    // At the StochasticDistribution element: line 11, column 7.
    assert_eq!((err.pos().line, err.pos().col), (11, 7));
    assert!(err.to_string().ends_with(&format!(
        "found more than {MAX_REJECTED_DRAWS} draws outside them at {}:11:7",
        path.display()
    )));
}

/// A DistributionRange of 1.1e83 in steps of 0.3 (3.7e83 values) overflowed the count of its
/// values (`as u128` saturates, the `+ 1` after it did not): now "too many parameter sets",
/// the count saturated at u128::MAX, at the range's element.
#[test]
fn distribution_range_count_overflows_u128() {
    let path = &fuzz_file("distribution_range_count_overflows_u128.xosc");
    let err = DistributionPlan::load(path).unwrap_err();
    assert!(
        matches!(
            err.kind(),
            DistributionErrorKind::TooManyRuns { found, .. } if *found == u128::MAX
        ),
        "{err}"
    );
    assert!(err.to_string().contains("parameter sets, found"), "{err}");
}

/// Not a reader bug: the distribution target's own check counted lines at `\n` only, and this
/// input has 109 lone `\r` (its 1025 bytes hold 17 `\n` and no `\r\n`). XML 1.0 §2.11 makes a
/// lone `\r` a line end, and the reader counts lines so (source::LineIndex): the bad
/// `numberOfTestRuns` comes after 7 `\n` and 109 `\r`, so on line 1 + 7 + 109 = 117, at column
/// 17 after the 16 characters `    <Stochastic `; the text has 1 + 17 + 109 = 127 lines by that
/// count and 18 by `\n` alone. The fuzz targets now count lines as the reader does.
#[test]
fn distribution_lone_cr_line_ends() {
    let name = "distribution_lone_cr_line_ends.xosc";
    let bytes = std::fs::read(fuzz_file(name)).unwrap();
    let text = std::str::from_utf8(&bytes).unwrap();
    assert_eq!(text.matches('\r').count(), 109);
    assert_eq!(text.matches('\n').count(), 17);
    let err = scenario::distribution::read(text, Path::new(name)).unwrap_err();
    assert!(
        matches!(err.kind(), DistributionErrorKind::InvalidAttribute { .. }),
        "{err}"
    );
    assert_eq!((err.pos().line, err.pos().col), (117, 17));
    assert!(
        err.to_string().starts_with(
            "expected an unsignedInt for Stochastic@numberOfTestRuns, found '10000VVV"
        ),
        "{err}"
    );
    assert!(
        err.to_string().ends_with(&format!("at {name}:117:17")),
        "{err}"
    );
    // The line the error names exists and holds the attribute it names.
    let index = source::LineIndex::new(text);
    let line = index.line_range(text, 117).map(|r| &text[r]);
    assert!(
        line.is_some_and(|l| l.starts_with("    <Stochastic numberOfTestRuns=")),
        "{line:?}"
    );
    assert!(index.line_range(text, 127).is_some());
    assert!(index.line_range(text, 128).is_none());
}
