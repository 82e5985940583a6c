//! Shared helpers of the integration tests: corpus paths and the reference CSV readers.
#![allow(dead_code)]

use std::path::PathBuf;

/// The shared test corpus (read-only), relative to this crate.
pub fn corpus() -> PathBuf {
    PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus"
    ))
}

/// Every road file of the corpus with its reference stem: (xodr path, reference path stem).
pub fn road_files() -> Vec<(PathBuf, PathBuf)> {
    let mut out = Vec::new();
    for group in ["esmini", "generated"] {
        let dir = corpus().join(group).join("xodr");
        let mut names: Vec<_> = std::fs::read_dir(&dir)
            .unwrap_or_else(|e| panic!("corpus folder {} unreadable: {e}", dir.display()))
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "xodr"))
            .collect();
        names.sort();
        for p in names {
            let stem = p
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default();
            out.push((
                p,
                corpus().join("reference/opendrive").join(group).join(stem),
            ));
        }
    }
    out
}

/// Rows of a reference CSV (the `#` comment line and the header skipped), split on commas.
pub fn csv_rows(path: &std::path::Path) -> Vec<Vec<String>> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.is_empty())
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

/// A CSV field as f64 (panics with the field on a malformed reference file).
pub fn num(field: &str) -> f64 {
    field
        .parse()
        .unwrap_or_else(|_| panic!("reference field {field:?} is not a number"))
}
