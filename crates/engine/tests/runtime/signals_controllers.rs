//! Traffic signal controllers at runtime (OpenSCENARIO 1.3 TrafficSignalController, Phase,
//! TrafficSignalControllerAction; TrafficSignalControllerCondition, TrafficSignalCondition) and
//! monitors (MonitorDeclaration, SetMonitorAction), on `tests/files/signals/controllers.xosc`.
//!
//! Controller A: go [0, 8), attention [8, 10), stop [10, 20), then again from 20 (cycle 20 s).
//! Controller B references A with delay 3: its first phase virtually starts at 3 s, so B at t is
//! where A was at t − 3 — stop at t = 0 (cycle position 17), go from 3, attention from 11, stop
//! from 13, go from 23. At t = 31 the TrafficSignalControllerAction puts A into "go": A's cycle
//! restarts (go [31, 39), attention [39, 41), stop [41, 51)), and B keeps its 3 s delay to A:
//! go from 34.

use crate::runtime_support;

use engine::output::EventRecord;
use engine::signals::SignalKind;
use engine::storyboard::Transition;
use engine::{Engine, EngineConfig};
use runtime_support::{monitor_values, Recorder};

fn run() -> Vec<EventRecord> {
    let path = std::path::PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/files/signals/controllers.xosc"
    ));
    let mut engine = Engine::load(&path, &[], EngineConfig::default()).expect("loads");
    let mut events = Vec::new();
    engine
        .run(&mut Recorder::default(), &mut events)
        .expect("runs");
    events
}

/// The start times of storyboard element `name`.
fn starts(events: &[EventRecord], name: &str) -> Vec<f64> {
    events
        .iter()
        .filter_map(|e| match e {
            EventRecord::Transition(t) if t.name == name && t.transition == Transition::Start => {
                Some(t.time)
            }
            _ => None,
        })
        .collect()
}

/// (time, from, to) of every phase change of controller `name`.
fn phases(events: &[EventRecord], name: &str) -> Vec<(f64, Option<String>, String)> {
    runtime_support::signal_records(events, SignalKind::Controller)
        .into_iter()
        .filter(|(_, element, _, _)| element == name)
        .map(|(time, _, from, to)| (time, from, to))
        .collect()
}

fn close(actual: &[f64], expected: &[f64]) -> bool {
    actual.len() == expected.len()
        && actual
            .iter()
            .zip(expected)
            .all(|(a, b)| (a - b).abs() < 1e-9)
}

#[test]
fn phase_conditions_fire_at_the_steps_their_phases_begin() {
    let events = run();
    // conditionEdge none: A is in "go" at t = 0, the first evaluation.
    assert!(close(&starts(&events, "GoAtStart"), &[0.0]));
    // Rising: the first evaluation (t = 0, go) only records its value, so the first rise into
    // "go" is A's second green at 20 s.
    assert!(close(&starts(&events, "GoRising"), &[20.0]));
    // A enters "attention" at 8, 28 and — after the switch at 31 — 39 s.
    assert!(close(
        &starts(&events, "AttentionRising"),
        &[8.0, 28.0, 39.0]
    ));
    assert!(close(&starts(&events, "StopRising"), &[10.0]));
    // B: go at 3 and 23 s; after A's switch at 31 s B's go comes at 34 s, not at 43 s.
    assert!(close(&starts(&events, "BGoRising"), &[3.0, 23.0, 34.0]));
    // Signal S1 is A's: yellow ("off;on;off") from 8 s.
    assert!(close(&starts(&events, "S1Yellow"), &[8.0]));
}

#[test]
fn the_event_log_shows_every_phase_change() {
    let events = run();
    let a = phases(&events, "A");
    let a: Vec<(f64, Option<&str>, &str)> = a
        .iter()
        .map(|(t, f, to)| (*t, f.as_deref(), to.as_str()))
        .collect();
    // Hand-listed from the cycle; at 31 s A was in "stop" (entered at 30 s) when switched.
    let expected_a = [
        (0.0, None, "go"),
        (8.0, Some("go"), "attention"),
        (10.0, Some("attention"), "stop"),
        (20.0, Some("stop"), "go"),
        (28.0, Some("go"), "attention"),
        (30.0, Some("attention"), "stop"),
        (31.0, Some("stop"), "go"),
        (39.0, Some("go"), "attention"),
        (41.0, Some("attention"), "stop"),
    ];
    assert_eq!(a.len(), expected_a.len(), "{a:?}");
    for (got, want) in a.iter().zip(&expected_a) {
        assert!(
            (got.0 - want.0).abs() < 1e-9 && got.1 == want.1 && got.2 == want.2,
            "{got:?} vs {want:?}"
        );
    }
    // B at 31 s: it entered "attention" at the end of the step before (position 28 − 20 = 8 of
    // its cycle), and A's switch in the step at 31 s moved it to cycle position −3 ≡ 17: stop.
    let b: Vec<(f64, String)> = phases(&events, "B")
        .into_iter()
        .map(|(t, _, to)| (t, to))
        .collect();
    let at_31: Vec<&str> = b
        .iter()
        .filter(|(t, _)| (t - 31.0).abs() < 1e-9)
        .map(|(_, to)| to.as_str())
        .collect();
    assert_eq!(at_31, ["attention", "stop"]);
}

#[test]
fn monitors_start_at_their_declared_values_and_log_each_change() {
    let events = run();
    let monitor = |name: &str| monitor_values(&events, name);
    // Declared false; set true when its Event first starts; the later starts set the same
    // value again, which is no change.
    assert_eq!(monitor("SeenAttentionRising"), [(0.0, false), (8.0, true)]);
    assert_eq!(monitor("SeenGoRising"), [(0.0, false), (20.0, true)]);
}
