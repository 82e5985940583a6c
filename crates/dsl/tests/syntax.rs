//! Syntax fixtures (roxmltree style): `tests/files/syntax/NAME.osc` beside either `NAME.tree`
//! (the tree dump of a file that parses without error) or `NAME.errors` (every syntax error,
//! one per line, "MESSAGE at NAME.osc:LINE:COL"). One line per case below; the index of cases
//! is `tests/files/syntax/README.md`.
//!
//! Every case also checks that the tree is lossless (its text is the input, byte for byte).
//! `OSC_BLESS=1 cargo test -p oscsim-dsl --test syntax` writes the expectation files from the
//! current parser: review their diff before committing.

use dsl::syntax::{debug_dump, parse, LineIndex};
use std::path::{Path, PathBuf};

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/syntax")
}

fn check(name: &str) {
    let osc = dir().join(format!("{name}.osc"));
    let source = std::fs::read_to_string(&osc).unwrap_or_else(|e| panic!("{}: {e}", osc.display()));
    let parse = parse(&source);
    assert_eq!(
        parse.syntax().to_string(),
        source,
        "{name}: the tree is not lossless"
    );
    let index = LineIndex::new(&source);
    let file = format!("{name}.osc");
    let errors: String = parse
        .errors()
        .iter()
        .map(|e| format!("{}\n", e.display(&file, &index)))
        .collect();
    let tree_path = dir().join(format!("{name}.tree"));
    let errors_path = dir().join(format!("{name}.errors"));
    let (path, other, actual) = if errors.is_empty() {
        (tree_path, errors_path, debug_dump(&parse.syntax()))
    } else {
        (errors_path, tree_path, errors)
    };
    if std::env::var_os("OSC_BLESS").is_some() {
        std::fs::write(&path, &actual).unwrap();
        let _ = std::fs::remove_file(other);
        return;
    }
    assert!(
        !other.exists(),
        "{name}: {} should not exist",
        other.display()
    );
    let expected = std::fs::read_to_string(&path).unwrap_or_else(|_| {
        panic!(
            "{name}: missing {} — the parse gave:\n{actual}",
            path.display()
        )
    });
    assert_eq!(actual, expected, "{name}: {} differs", path.display());
}

macro_rules! cases {
    ($($name:ident),* $(,)?) => {
        $(#[test] fn $name() { check(stringify!($name)); })*

        /// Every fixture file has a case line above.
        #[test]
        fn every_fixture_is_listed() {
            let listed = [$(stringify!($name)),*];
            for entry in std::fs::read_dir(dir()).unwrap() {
                let path = entry.unwrap().path();
                if path.extension().is_some_and(|e| e == "osc") {
                    let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
                    assert!(listed.contains(&stem.as_str()), "{stem}.osc has no case line");
                }
            }
        }
    };
}

cases! {
    // The domain model's examples (seed 000, §8.7): must parse.
    seed_wide_car,
    seed_motorcycle,
    seed_bicycle,
    seed_stationary_location,
    seed_prevent_collision,
    seed_driving_alongside_group,
    // One file with every construct of the grammar.
    all_constructs,
}
