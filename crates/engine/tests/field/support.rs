//! Helpers of the field tests: the fixture folder, loading with parameters, the event log.

use std::path::PathBuf;

use engine::output::EventRecord;
use engine::storyboard::Transition;
use engine::{Engine, EngineConfig};

pub use crate::runtime_support::Recorder;

/// A fixture in `tests/files/field`.
pub fn file(name: &str) -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/files/field")).join(name)
}

/// Loads fixture `name` with parameter overrides; the load error's text if it does not load.
pub fn load(name: &str, params: &[(&str, &str)]) -> Result<Engine, String> {
    let params: Vec<(String, String)> = params
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    Engine::load(&file(name), &params, EngineConfig::default()).map_err(|e| e.to_string())
}

/// Loads and runs fixture `name` to its end.
pub fn run(name: &str, params: &[(&str, &str)]) -> (Engine, Recorder, Vec<EventRecord>) {
    crate::runtime_support::run_with(&file(name), params, EngineConfig::default())
}

/// Times of every `transition` of storyboard element `name`, in log order.
pub fn transitions(events: &[EventRecord], name: &str, transition: Transition) -> Vec<f64> {
    events
        .iter()
        .filter_map(|e| match e {
            EventRecord::Transition(r) if r.name == name && r.transition == transition => {
                Some(r.time)
            }
            _ => None,
        })
        .collect()
}

/// Asserts that each `(name, x, y)` is at that world point in the frame at `t`, within `tol`.
pub fn assert_at(rows: &Recorder, t: f64, expected: &[(&str, f64, f64)], tol: f64) {
    for &(name, x, y) in expected {
        let r = rows.at(name, t);
        assert!(
            (r.x - x).abs() < tol && (r.y - y).abs() < tol,
            "{name} at {t}: ({}, {}), expected ({x}, {y})",
            r.x,
            r.y
        );
    }
}
