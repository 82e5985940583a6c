//! Issue 34 class 6 — TrafficSignalGroupState (OpenSCENARIO 1.3, XSD `Phase`): "Each phase can
//! have one TrafficSignalGroupState to provide the observable state for all traffic signals
//! that are controlled by the controller if they share the same state". The controller is the
//! group: TrafficSignalController@name is the "ID of the traffic signal controller in the road
//! network", whose `<control signalId>`s (OpenDRIVE 1.8 §14) are its signals (engine
//! `signals::group`).
//!
//! Fixture `group_state.xosc` on `group_signals.xodr`: controller "crossing" switches N and S;
//! phases stop (3 s, "on;off;off") and go (10 s, "off;off;on"), group states only. Ego waits at
//! x = 10 until S shows green, then drives at 10 m/s.

use engine::output::EventRecord;
use engine::signals::SignalKind;
use engine::storyboard::Transition;

use crate::support::{load, run, transitions};

/// A straight road: closed forms up to round-off.
const POS_TOL: f64 = 1e-6;
/// Step times are sums of dt = 0.05 s.
const TIME_TOL: f64 = 1e-9;

/// (time, signal, state) of every signal change in the log.
fn signal_changes(events: &[EventRecord]) -> Vec<(f64, String, String)> {
    crate::runtime_support::signal_records(events, SignalKind::Signal)
        .into_iter()
        .map(|(time, id, _, to)| (time, id, to))
        .collect()
}

#[test]
fn a_group_state_sets_every_signal_of_the_controller() {
    let (engine, rows, events) = run("group_state.xosc", &[]);
    // Phase stop from t = 0 sets N and S (the controller's <control> order) to red; phase go
    // from t = 3 s sets both to green. Before: group states were read and ignored, no signal
    // had a state and Go never started.
    let changes = signal_changes(&events);
    let expected = [
        (0.0, "N", "on;off;off"),
        (0.0, "S", "on;off;off"),
        (3.0, "N", "off;off;on"),
        (3.0, "S", "off;off;on"),
    ];
    assert_eq!(changes.len(), expected.len(), "{changes:?}");
    for ((t, id, state), (et, eid, estate)) in changes.iter().zip(expected) {
        assert!(
            (t - et).abs() < TIME_TOL && id == eid && state == estate,
            "{changes:?}"
        );
    }
    assert_eq!(
        engine.signal_states(),
        [
            ("N".into(), "off;off;on".into()),
            ("S".into(), "off;off;on".into())
        ]
    );
    // Go starts in the step at t = 3 s, whose conditions see the phase entered at 3 s; the
    // step speed action moves Ego from there: x = 10 + 10 (t − 3).
    let go = transitions(&events, "Go", Transition::Start);
    assert_eq!(go.len(), 1);
    assert!((go[0] - 3.0).abs() < TIME_TOL, "{go:?}");
    assert!((rows.at("Ego", 2.95).x - 10.0).abs() < POS_TOL);
    assert!((rows.at("Ego", 5.0).x - 30.0).abs() < POS_TOL);
}

#[test]
fn a_group_state_without_signals_is_an_error_at_its_phase() {
    // No <controller id="elsewhere"> in the road network and no TrafficSignalState: the group
    // state would set nothing. The phase "stop" is written at line 14, column 9.
    let err = load("group_state.xosc", &[("Controller", "elsewhere")]).expect_err("no signals");
    assert!(
        err.starts_with(
            "expected a traffic signal controlled by 'elsewhere' for the TrafficSignalGroupState \
             of phase 'stop' (a <controller id=\"elsewhere\"> of the road network, or a \
             TrafficSignalState of its phases), found none at "
        ) && err.ends_with("group_state.xosc:14:9"),
        "{err}"
    );
}
