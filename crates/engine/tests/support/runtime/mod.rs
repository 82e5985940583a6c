//! Shared helpers of the runtime tests: paths, a frame recorder, a run to the end, and the
//! readers of esmini's reference runs (`esmini_reference`).
#![allow(dead_code)]

mod esmini_reference;

use std::path::PathBuf;

use engine::output::{EventRecord, Frame, FrameSink};
use engine::{Engine, EngineConfig};

// Each test binary uses a different part, as with `dead_code` above.
#[allow(unused_imports)]
pub use esmini_reference::{
    esmini_reference, esmini_reference_events, first_transition, parse_reference,
    parse_reference_events, RefEvent, RefRow,
};

/// A test scenario in `tests/files/runtime`.
pub fn file(name: &str) -> PathBuf {
    crate::corpus::fixture("runtime").join(name)
}

/// A file of the shared corpus.
pub use crate::corpus::corpus;

/// One entity in one frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    pub time: f64,
    pub name: String,
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub h: f64,
    pub speed: f64,
    /// Velocity in world axes (vx, vy, vz).
    pub velocity: (f64, f64, f64),
    pub road: Option<(String, i32, f64, f64, f64)>,
}

/// Records every frame.
#[derive(Default)]
pub struct Recorder(pub Vec<Row>);

impl FrameSink for Recorder {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        for e in frame.objects() {
            self.0.push(Row {
                time: frame.time,
                name: e.name.to_owned(),
                x: e.pose.x,
                y: e.pose.y,
                z: e.pose.z,
                h: e.pose.h,
                speed: e.speed,
                velocity: (e.velocity.x, e.velocity.y, e.velocity.z),
                road: e
                    .road_position
                    .map(|r| (r.road_id.clone(), r.lane_id, r.s, r.t, r.offset)),
            });
        }
        Ok(())
    }
}

impl Recorder {
    /// The row of `name` at time `t` (within 1 ms).
    pub fn at(&self, name: &str, t: f64) -> &Row {
        self.0
            .iter()
            .find(|r| r.name == name && (r.time - t).abs() < 1e-3)
            .unwrap_or_else(|| panic!("no row for {name} at {t}"))
    }
}

/// Loads and runs a test scenario to its end with the default settings.
pub fn run(name: &str) -> (Engine, Recorder, Vec<EventRecord>) {
    run_with(&file(name), &[], EngineConfig::default())
}

/// Loads the scenario at `path` with parameter overrides `(name, value)` and runs it to its
/// end under `config`.
pub fn run_with(
    path: &std::path::Path,
    params: &[(&str, &str)],
    config: EngineConfig,
) -> (Engine, Recorder, Vec<EventRecord>) {
    let params: Vec<(String, String)> = params
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    let name = path.display();
    let mut engine =
        Engine::load(path, &params, config).unwrap_or_else(|e| panic!("{name} does not load: {e}"));
    let mut frames = Recorder::default();
    let mut events = Vec::new();
    engine
        .run(&mut frames, &mut events)
        .unwrap_or_else(|e| panic!("{name} fails: {e}"));
    (engine, frames, events)
}

/// Time of the step in which storyboard element `name` ended (its end transition), if it did.
pub fn end_time(events: &[EventRecord], name: &str) -> Option<f64> {
    events.iter().find_map(|e| match e {
        EventRecord::Transition(r)
            if r.name == name && r.transition == engine::storyboard::Transition::End =>
        {
            Some(r.time)
        }
        _ => None,
    })
}

/// (time, value) of every record of monitor `name` in the event log: its declared value at
/// t = 0, then each change.
pub fn monitor_values(events: &[EventRecord], name: &str) -> Vec<(f64, bool)> {
    events
        .iter()
        .filter_map(|e| match e {
            EventRecord::Monitor {
                time,
                element,
                value,
            } if element == name => Some((*time, *value)),
            _ => None,
        })
        .collect()
}

/// (time, element, from, to) of every signal record of `kind` in the event log: phase changes
/// of controllers or state changes of signals, in log order.
pub fn signal_records(
    events: &[EventRecord],
    kind: engine::signals::SignalKind,
) -> Vec<(f64, String, Option<String>, String)> {
    events
        .iter()
        .filter_map(|e| match e {
            EventRecord::Signal {
                time,
                element,
                kind: k,
                from,
                to,
            } if *k == kind => Some((*time, element.clone(), from.clone(), to.clone())),
            _ => None,
        })
        .collect()
}
