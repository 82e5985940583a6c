//! The schedule against hand-worked phase tables.

use std::path::Path;

use scenario::{Phase, SourcePos, TrafficSignalController};

use super::schedule::Schedule;
use super::{SignalKind, Signals};
use crate::output::EventRecord;

fn pos() -> SourcePos {
    SourcePos {
        file: Path::new("signals.xosc").into(),
        line: 3,
        col: 7,
    }
}

fn phase(name: &str, duration: f64, state: &str) -> Phase {
    Phase {
        name: name.into(),
        duration,
        signal_states: vec![("S1".into(), state.into())],
        group_state: None,
        pos: pos(),
    }
}

/// Green 8 s, yellow 2 s, red 10 s: a cycle of 20 s.
fn traffic_light(name: &str, reference: Option<(&str, f64)>) -> TrafficSignalController {
    TrafficSignalController {
        name: name.into(),
        delay: reference.map(|r| r.1),
        reference: reference.map(|r| r.0.into()),
        phases: vec![
            phase("go", 8.0, "off;off;on"),
            phase("attention", 2.0, "off;on;off"),
            phase("stop", 10.0, "on;off;off"),
        ],
        pos: pos(),
    }
}

fn names(schedule: &Schedule, i: usize, times: &[f64]) -> Vec<&'static str> {
    const PHASES: [&str; 3] = ["go", "attention", "stop"];
    times
        .iter()
        .map(|&t| PHASES[schedule.clocks()[i].phase_at(t).unwrap()])
        .collect()
}

#[test]
fn a_controller_cycles_green_8_yellow_2_red_10() {
    let s = Schedule::new(&[traffic_light("A", None)]).unwrap();
    // Phase starts 0, 8, 10; cycle 20 s: t = 20 is the cycle's start again, t = 28 = 20 + 8
    // the second yellow.
    let times = [0.0, 7.95, 8.0, 10.0, 20.0, 28.0];
    assert_eq!(
        names(&s, 0, &times),
        ["go", "go", "attention", "stop", "go", "attention"]
    );
    // Steps of 0.05 s land on 8 s as 160 · 0.05 and on 10 s as 200 · 0.05, which round off to
    // within 1e-15 s of the boundary: still the new phase.
    assert_eq!(
        names(&s, 0, &[160.0 * 0.05, 200.0 * 0.05]),
        ["attention", "stop"]
    );
}

#[test]
fn a_referencing_controller_starts_its_first_phase_delay_after_the_reference() {
    // B's first phase virtually starts 3 s after A's: B at t is where A was at t − 3. At t = 0
    // that is cycle position −3 ≡ 17 s: B is red; green from 3 s, yellow from 11 s, red from
    // 13 s, green again from 23 s.
    let s = Schedule::new(&[
        traffic_light("A", None),
        traffic_light("B", Some(("A", 3.0))),
    ])
    .unwrap();
    let times = [0.0, 2.95, 3.0, 10.95, 11.0, 13.0, 23.0];
    assert_eq!(
        names(&s, 1, &times),
        ["stop", "stop", "go", "go", "attention", "stop", "go"]
    );
}

#[test]
fn a_chain_of_references_adds_the_delays() {
    // C references B (delay 4), B references A (delay 3): C's cycle starts at 7 s.
    let s = Schedule::new(&[
        traffic_light("C", Some(("B", 4.0))),
        traffic_light("A", None),
        traffic_light("B", Some(("A", 3.0))),
    ])
    .unwrap();
    assert_eq!(
        names(&s, 0, &[6.95, 7.0, 15.0]),
        ["stop", "go", "attention"]
    );
}

#[test]
fn set_phase_restarts_the_cycle_and_moves_connected_controllers() {
    let mut s = Schedule::new(&[
        traffic_light("A", None),
        traffic_light("B", Some(("A", 3.0))),
    ])
    .unwrap();
    // At 4 s A is put into "stop" (offset 10 s in the cycle): A's origin becomes 4 − 10 = −6,
    // so A is red until 14 s and green from 14 s; B (origin −6 + 3 = −3) is at cycle position
    // t + 3: at 4 s position 7 (go), at 5 s position 8 (attention), at 7 s position 10 (stop).
    s.set_phase(0, 2, 4.0);
    assert_eq!(names(&s, 0, &[4.0, 13.95, 14.0]), ["stop", "stop", "go"]);
    assert_eq!(names(&s, 1, &[4.0, 5.0, 7.0]), ["go", "attention", "stop"]);
}

#[test]
fn zero_durations_are_skipped_and_a_zero_cycle_holds() {
    let mut c = traffic_light("A", None);
    c.phases[1].duration = 0.0;
    let s = Schedule::new(&[c]).unwrap();
    // Go [0, 8), stop [8, 18): the zero-length yellow is never reported.
    assert_eq!(
        names(&s, 0, &[7.95, 8.0, 17.95, 18.0]),
        ["go", "stop", "stop", "go"]
    );
    let mut c = traffic_light("A", None);
    for p in &mut c.phases {
        p.duration = 0.0;
    }
    let mut s = Schedule::new(&[c]).unwrap();
    assert_eq!(names(&s, 0, &[0.0, 100.0]), ["go", "go"]);
    s.set_phase(0, 2, 5.0);
    assert_eq!(names(&s, 0, &[5.0, 100.0]), ["stop", "stop"]);
}

#[test]
fn bad_controllers_are_refused_with_their_position() {
    let unknown = Schedule::new(&[traffic_light("B", Some(("A", 3.0)))]).unwrap_err();
    assert_eq!(
        unknown.to_string(),
        "expected the name of a TrafficSignalController as reference, found 'A' at signals.xosc:3:7"
    );
    let mut no_delay = traffic_light("B", Some(("A", 3.0)));
    no_delay.delay = None;
    let err = Schedule::new(&[traffic_light("A", None), no_delay]).unwrap_err();
    assert!(
        err.to_string()
            .starts_with("expected a delay with the reference"),
        "{err}"
    );
    let cycle = Schedule::new(&[
        traffic_light("A", Some(("B", 1.0))),
        traffic_light("B", Some(("A", 1.0))),
    ])
    .unwrap_err();
    assert!(cycle.to_string().contains("without a cycle"), "{cycle}");
    let mut negative = traffic_light("A", None);
    negative.phases[0].duration = -1.0;
    let err = Schedule::new(&[negative]).unwrap_err();
    assert_eq!(
        err.to_string(),
        "expected a Phase duration ≥ 0 s, found -1 at signals.xosc:3:7"
    );
}

#[test]
fn signals_record_phases_and_states_once_per_change() {
    let mut s = Signals::new(&[traffic_light("A", None)], &[]).unwrap();
    let mut log = Vec::new();
    s.advance(0.0, &mut log);
    s.advance(0.05, &mut log);
    assert_eq!(s.phase("A"), Some("go"));
    assert_eq!(s.state("S1"), Some("off;off;on"));
    s.advance(8.0, &mut log);
    assert_eq!(s.state("S1"), Some("off;on;off"));
    // The action sets a state; the next phase sets it again.
    s.set_state("S1", "off;off;off", 9.0, &mut log);
    s.advance(10.0, &mut log);
    assert_eq!(s.state("S1"), Some("on;off;off"));
    let summary: Vec<(f64, SignalKind, Option<&str>, &str)> = log
        .iter()
        .map(|r| match r {
            EventRecord::Signal {
                time,
                kind,
                from,
                to,
                ..
            } => (*time, *kind, from.as_deref(), to.as_str()),
            other => panic!("unexpected {other:?}"),
        })
        .collect();
    use SignalKind::{Controller as C, Signal as S};
    assert_eq!(
        summary,
        [
            (0.0, C, None, "go"),
            (0.0, S, None, "off;off;on"),
            (8.0, C, Some("go"), "attention"),
            (8.0, S, Some("off;off;on"), "off;on;off"),
            (9.0, S, Some("off;on;off"), "off;off;off"),
            (10.0, C, Some("attention"), "stop"),
            (10.0, S, Some("off;off;off"), "on;off;off"),
        ]
    );
    let err = s
        .set_phase("A", "blink", 11.0, &pos(), &mut log)
        .unwrap_err();
    assert_eq!(
        err.to_string(),
        "expected a phase of controller 'A' (go, attention, stop), found 'blink' at signals.xosc:3:7"
    );
}

/// TrafficSignalGroupState (signals/group.rs): the group is the road network's controller of
/// the same id (its signals in `<control>` order) followed by the signals the controller's
/// TrafficSignalStates name; a phase with both forms applies its own states after the group's.
#[test]
fn a_group_state_sets_the_controllers_signals() {
    let road = opendrive::Controller {
        id: "A".into(),
        name: String::new(),
        signal_ids: vec!["R2".into(), "R1".into()],
    };
    let mut c = traffic_light("A", None);
    c.phases[0].signal_states.clear();
    c.phases[0].group_state = Some("off;off;on".into());
    c.phases[1].group_state = Some("off;on;off".into());
    c.phases[1].signal_states = vec![("R1".into(), "off;off;off".into())];
    let mut s = Signals::new(&[c], &[road]).unwrap();
    let mut log = Vec::new();
    s.advance(0.0, &mut log);
    // Phase go: group state on R2, R1 (road controller) and S1 (named in phase stop).
    let states: Vec<(&str, &str)> = s.states().collect();
    assert_eq!(
        states,
        [
            ("R1", "off;off;on"),
            ("R2", "off;off;on"),
            ("S1", "off;off;on")
        ]
    );
    // Phase attention at 8 s: the group state, then R1's own state.
    s.advance(8.0, &mut log);
    let states: Vec<(&str, &str)> = s.states().collect();
    assert_eq!(
        states,
        [
            ("R1", "off;off;off"),
            ("R2", "off;on;off"),
            ("S1", "off;on;off")
        ]
    );
    // Phase stop at 10 s: no group state, only S1.
    s.advance(10.0, &mut log);
    assert_eq!(s.state("S1"), Some("on;off;off"));
    assert_eq!(s.state("R2"), Some("off;on;off"));
}
