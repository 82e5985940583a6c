//! Distance keeping in esmini's scenarios against esmini's reference runs
//! (`shared/corpus/reference/esmini/NAME.csv` and `NAME.events.txt`: esmini 3.6.0, default
//! controllers, dt 0.05 s, rows every 0.1 s): LongitudinalDistanceAction (OpenSCENARIO 1.3
//! §7.7.2.1) in highway_merge, highway_merge_advanced and distance_test, LateralDistanceAction
//! (§7.7.2.2) in keep_lateral_distance. Each test states what pins the numbers down.

use crate::runtime_support;

use engine::storyboard::Transition;
use engine::{EngineConfig, EventRecord};
use runtime_support::{
    corpus, esmini_reference, esmini_reference_events, first_transition, run_with, Recorder, RefRow,
};

/// esmini writes positions and speeds to 1 mm and 1 mm/s.
const ESMINI_ROUNDING: f64 = 1e-3;

/// Runs corpus scenario `scenario` (esmini/xosc) with the default settings.
fn run(scenario: &str) -> (Recorder, Vec<EventRecord>) {
    let path = corpus(&format!("esmini/xosc/{scenario}.xosc"));
    let (_, frames, events) = run_with(&path, &[], EngineConfig::default());
    (frames, events)
}

/// The largest position (m) and speed (m/s) differences of `entity` from the reference over
/// the reference rows oscsim also has.
fn worst(frames: &Recorder, rows: &[RefRow], entity: &str) -> (f64, f64) {
    let mut worst = (0.0_f64, 0.0_f64);
    for r in rows.iter().filter(|r| r.name == entity) {
        let Some(o) = frames
            .0
            .iter()
            .find(|o| o.name == entity && (o.time - r.time).abs() < 1e-6)
        else {
            continue;
        };
        worst.0 = worst.0.max((o.x - r.x).hypot(o.y - r.y));
        worst.1 = worst.1.max((o.speed - r.speed).abs());
    }
    worst
}

/// The time of the first `transition` of storyboard element `element` in oscsim's run.
fn ours(events: &[EventRecord], element: &str, transition: Transition) -> f64 {
    events
        .iter()
        .find_map(|e| match e {
            EventRecord::Transition(r) if r.name == element && r.transition == transition => {
                Some(r.time)
            }
            _ => None,
        })
        .unwrap_or_else(|| panic!("{element} has no {transition:?}"))
}

/// The time of the first `transition` of `element` in esmini's log of `scenario`.
fn esmini(scenario: &str, element: &str, transition: Transition) -> f64 {
    first_transition(&esmini_reference_events(scenario), element, transition)
        .unwrap_or_else(|| panic!("{element}: no {transition} in {scenario}.events.txt"))
}

/// highway_merge: A2 keeps timeGap 1 s (freespace) behind A1, A3 1.5 s behind A2, both with
/// maxAcceleration 2, maxDeceleration 5. The time gap is taken at the reference's speed: with
/// the actor's own speed (A2 reaches 32.3 m/s at 3.7 s while A1 drives 25 m/s) A2 wanted 7 m
/// more and braked from 3.7 s, 4.5 m off esmini. Now both agree within 0.01 m and 0.01 m/s,
/// which also pins the spring law (stiffness 0.4 /m × maxAcceleration when dropping back,
/// × maxDeceleration when closing up; the other pairing is 0.5 m off in highway_merge_advanced).
#[test]
fn highway_merge_time_gaps_agree_with_esmini() {
    let rows = esmini_reference("highway_merge");
    let (frames, _) = run("highway_merge");
    for entity in ["A2", "A3"] {
        let (pos, speed) = worst(&frames, &rows, entity);
        assert!(pos < 0.01 && speed < 0.01, "{entity}: {pos} m, {speed} m/s");
    }
}

/// highway_merge_advanced: A3 closes the gap to 7 m behind A2 (reference points) whenever Ego
/// tries to merge, up to three times, with maxAcceleration 10 (bounded by the car's Performance
/// maxAcceleration 5, which it never needs), maxDeceleration 7.
#[test]
fn highway_merge_advanced_gap_closing_agrees_with_esmini() {
    let rows = esmini_reference("highway_merge_advanced");
    let (frames, _) = run("highway_merge_advanced");
    let (pos, speed) = worst(&frames, &rows, "A3");
    assert!(pos < 0.01 && speed < 0.01, "A3: {pos} m, {speed} m/s");
}

/// keep_lateral_distance: OverTaker keeps 0.5 m (freespace, road frame) left of Ego with only
/// maxSpeed 2 m/s from 1.05 s. The first step only sets the lateral speed going, then it moves
/// 0.2 m per 0.1 s: t = −3.925 at 1.1 s and −4.125 at 1.2 s, as in esmini's run. Because the
/// approach is gradual, Ego's RelativeDistance lateral freespace < 0.6 m trigger (delay 1 s)
/// starts LaneChange1Event at 2.75 s, and the next LateralDistanceAction at 5.75 s, as esmini.
/// The largest position difference, 0.083 m at 12 s, is in OverTaker's tracking of Ego's 4 s
/// lane change with maxAcceleration 5 and maxSpeed 3: oscsim's lateral law is its own damped
/// spring (actions/distance/lateral.rs); esmini's lateral source was not at hand, and
/// the two differ there by less than the 0.1 m tolerance.
#[test]
fn keep_lateral_distance_approaches_gradually_like_esmini() {
    let scenario = "keep_lateral_distance";
    let rows = esmini_reference(scenario);
    let (frames, events) = run(scenario);
    for (time, want) in [(1.1, -3.925), (1.2, -4.125)] {
        let ours = frames.at("OverTaker", time).road.as_ref().map(|r| r.3);
        let esmini_t = rows
            .iter()
            .find(|r| r.name == "OverTaker" && (r.time - time).abs() < 1e-6)
            .map(|r| r.t);
        assert_eq!(esmini_t, Some(want));
        assert!(
            ours.is_some_and(|t| (t - want).abs() < ESMINI_ROUNDING),
            "{time}: {ours:?}"
        );
    }
    for element in ["LaneChange1Event", "LateralDistanceMaxSpeedAndAccEvent"] {
        let (o, e) = (
            ours(&events, element, Transition::Start),
            esmini(scenario, element, Transition::Start),
        );
        assert!((o - e).abs() < 1e-6, "{element}: {o} vs {e}");
    }
    let (pos, _) = worst(&frames, &rows, "OverTaker");
    assert!(pos < 0.09, "OverTaker: {pos} m");
}

/// distance_test: the non-continuous LongitudinalDistanceAction (4 m freespace behind Ego)
/// ends once the error measured at a step's start is at most 0.1 m. At 16.75 s Dummy (car_red,
/// front 1.45 + 2.52 = 3.97 m ahead of its reference point) is 301.25 − 292.0586 = 9.1914 m
/// behind Ego (car_white, rear 2.52 − 1.4 = 1.12 m): error 9.1914 − 5.09 − 4 = 0.1014 m, just
/// over; at 16.80 s 0.0941 m. So the end is logged at 16.85 s, one step after esmini's 16.80 s:
/// esmini's freespace measure differs from the boxes' extents along the road by more than the
/// 1.4 mm margin here (positions agree to 1 mm). Within compare_run.py's 0.05 s.
#[test]
fn distance_test_non_continuous_end_within_a_step_of_esmini() {
    let (frames, events) = run("distance_test");
    let at = |t: f64| frames.at("Ego", t).x - frames.at("Dummy", t).x - 3.97 - 1.12 - 4.0;
    assert!((at(16.75) - 0.1014).abs() < 1e-3 && (at(16.8) - 0.0941).abs() < 1e-3);
    let o = ours(&events, "NonContinuousDistEvent", Transition::End);
    let e = esmini("distance_test", "NonContinuousDistEvent", Transition::End);
    assert!(
        (o - 16.85).abs() < 1e-6 && (e - 16.8).abs() < 1e-6,
        "{o} vs {e}"
    );
}
