//! Same inputs → byte-identical CSV and event log (the determinism requirement).

use crate::runtime_support;

use engine::output::{CsvWriter, JsonlWriter};
use engine::{Engine, EngineConfig};
use runtime_support::{corpus, file};

/// Runs `path` once, returning the CSV and the JSON-lines event log as bytes.
fn run_bytes(path: &std::path::Path) -> (Vec<u8>, Vec<u8>) {
    let mut engine = Engine::load(path, &[], EngineConfig::default()).expect("scenario loads");
    let mut csv = CsvWriter::new(Vec::new());
    let mut events = JsonlWriter::new(Vec::new());
    engine.run(&mut csv, &mut events).expect("scenario runs");
    (csv.into_inner(), events.into_inner())
}

#[test]
fn two_runs_give_identical_bytes() {
    for path in [
        corpus("esmini/xosc/cut-in.xosc"),
        file("lane_change_sinusoidal.xosc"),
        file("junction_follow.xosc"),
    ] {
        let (csv_a, events_a) = run_bytes(&path);
        let (csv_b, events_b) = run_bytes(&path);
        assert!(csv_a.len() > 1000, "{} wrote a CSV", path.display());
        assert!(!events_a.is_empty(), "{} wrote events", path.display());
        assert!(csv_a == csv_b, "{}: CSVs differ", path.display());
        assert!(
            events_a == events_b,
            "{}: event logs differ",
            path.display()
        );
    }
}

/// The CSV header is the reference files' (corpus `reference/esmini/*.csv`).
#[test]
fn csv_header_matches_reference_layout() {
    let (csv, _) = run_bytes(&file("speed_linear.xosc"));
    let reference =
        std::fs::read_to_string(corpus("reference/esmini/cut-in.csv")).expect("reference");
    let ours = String::from_utf8(csv).expect("utf-8");
    assert_eq!(ours.lines().next(), reference.lines().next());
    // One row per entity per step: 1 entity, frames at 0, 0.05, …, 6.0 → 121 rows.
    assert_eq!(ours.lines().count(), 1 + 121);
}
