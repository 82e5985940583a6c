//! Lateral motion in esmini's scenarios against esmini's reference runs
//! (`shared/corpus/reference/esmini/NAME.csv` and `NAME.events.txt`: esmini 3.6.0, default
//! controllers, dt 0.05 s, rows every 0.1 s). Each test pins down where oscsim's
//! LaneChangeAction / LaneOffsetAction (OpenSCENARIO 1.3 §7.7.2.2) agree with esmini's and
//! shows, in numbers, the cause of each difference that remains.

use crate::runtime_support;

use approx::assert_abs_diff_eq;
use engine::storyboard::Transition;
use engine::{EngineConfig, EventRecord};
use runtime_support::{
    corpus, esmini_reference, esmini_reference_events, run_with, Recorder, RefRow,
};

/// Tolerance for values that the runtime computes exactly up to rounding.
const EXACT: f64 = 1e-9;

/// esmini writes positions to 1 mm.
const ESMINI_ROUNDING: f64 = 1e-3;

/// The reference rows of `entity` in scenario `name` with `from <= time < to`.
fn reference(name: &str, entity: &str, from: f64, to: f64) -> Vec<RefRow> {
    esmini_reference(name)
        .into_iter()
        .filter(|r| r.name == entity && (from..to).contains(&r.time))
        .collect()
}

/// Asserts the times storyboard element `element` starts in oscsim's run (`events`) and in
/// esmini's reference log of `scenario`: `(ours, esmini)`.
fn assert_starts(events: &[EventRecord], scenario: &str, element: &str, want: (f64, f64)) {
    let ours = events.iter().find_map(|e| match e {
        EventRecord::Transition(r) if r.name == element && r.transition == Transition::Start => {
            Some(r.time)
        }
        _ => None,
    });
    let esmini = esmini_reference_events(scenario).into_iter().find_map(|e| {
        (e.element == element && e.from == "standbyState" && e.transition == Transition::Start)
            .then_some(e.time)
    });
    assert_abs_diff_eq!(ours.unwrap_or(f64::NAN), want.0, epsilon = EXACT);
    assert_abs_diff_eq!(esmini.unwrap_or(f64::NAN), want.1, epsilon = EXACT);
}

/// Runs esmini's scenario `name` from the corpus.
fn run_esmini(name: &str) -> (Recorder, Vec<EventRecord>) {
    let path = corpus(&format!("esmini/xosc/{name}.xosc"));
    let (_, frames, events) = run_with(&path, &[], EngineConfig::default());
    (frames, events)
}

/// alks_cut-out: TargetCutOut drives lane −1 (t = −1.535) from s = 50 at 20 m/s, 1 m a step;
/// its cubic lane change to lane 1 (t = +1.535) over 2 s starts on a ReachPositionCondition,
/// tolerance 1.0 m, at s = 96 of lane −1. After 45 steps, at 2.25 s, it stands at x = 95.000
/// exactly, 1.000 m from the position: inside a tolerance circle that includes its rim (§7.6.3
/// ReachPosition tolerance, "radius of tolerance circle around given position", range
/// [0..inf[; a closed circle, so that tolerance 0 can be met), so oscsim starts the change at
/// 2.25 s. esmini tests `dist < tolerance` (OSCCondition.cpp, TrigByReachPosition) and starts
/// at 2.30 s. That one step is the whole difference: oscsim's frame at T − 0.05 s is esmini's
/// at T, 1 m further on, to esmini's rounding laterally; along the road within 4 mm (esmini
/// shortens a step by the lateral speed at the step's start, oscsim by its mean).
#[test]
fn alks_cut_out_lane_change_is_esmini_s_one_step_earlier() {
    let (frames, events) = run_esmini("alks_cut-out");
    assert_starts(&events, "alks_cut-out", "CutOutEvent", (2.25, 2.30));
    let trigger = frames.at("TargetCutOut", 2.25);
    let rim = ((trigger.x - 96.0).powi(2) + (trigger.y + 1.535).powi(2)).sqrt();
    assert_abs_diff_eq!(rim, 1.0, epsilon = EXACT);

    let rows = reference("alks_cut-out", "TargetCutOut", 2.3, 4.55);
    assert_eq!(rows.len(), 23, "reference rows 2.3 s to 4.5 s");
    for r in rows {
        let ours = frames.at("TargetCutOut", r.time - 0.05);
        let (_, _, _, t, _) = ours.road.clone().unwrap_or_default();
        assert_abs_diff_eq!(t, r.t, epsilon = ESMINI_ROUNDING);
        assert_abs_diff_eq!(ours.x + 1.0, r.x, epsilon = 4e-3);
    }
}

/// cut-in_sloppy: OverTaker's sinusoidal cut-in over 3 s (from 7.25 s in both runs) agrees
/// with esmini to 3 mm up to the brake. The 1.8 m the comparison reports come after it:
/// OvertakerBrakeEvent starts on Ego's TimeHeadwayCondition to OverTaker, greaterThan 2.7 s,
/// alongRoute="true", which oscsim measures in road coordinates (√(ds² + dt²); the cars share a
/// lane by then, so along the road; see cut-in_sloppy's note in docs/conformance-notes.tsv)
/// and esmini straight. At 17.90 s Ego (30 m/s) is 81.15 m of road behind OverTaker, 2.705 s,
/// but only 80.97 m away in a straight line, 2.699 s, so oscsim brakes one step (0.05 s)
/// before esmini. OverTaker then brakes at 4 m/s² from 36 m/s, 0.2 m/s slower than esmini's
/// throughout, and stops 36·0.05 = 1.8 m short of it.
#[test]
fn cut_in_sloppy_lane_change_agrees_and_the_brake_comes_one_step_early() {
    let (frames, events) = run_esmini("cut-in_sloppy");
    assert_starts(&events, "cut-in_sloppy", "CutInEvent", (7.25, 7.25));
    assert_starts(
        &events,
        "cut-in_sloppy",
        "OvertakerBrakeEvent",
        (17.90, 17.95),
    );
    for r in reference("cut-in_sloppy", "OverTaker", 7.0, 17.95) {
        let ours = frames.at("OverTaker", r.time);
        let gap = (ours.x - r.x).hypot(ours.y - r.y);
        assert!(gap < 3e-3, "{gap} m off esmini at {} s", r.time);
    }
    // The headway at 17.90 s: along the road above 2.7 s, in a straight line below.
    let (ego, over) = (frames.at("Ego", 17.9), frames.at("OverTaker", 17.9));
    let s = |row: &runtime_support::Row| row.road.clone().unwrap_or_default().2;
    assert!((s(over) - s(ego)) / ego.speed > 2.7);
    assert!((over.x - ego.x).hypot(over.y - ego.y) / ego.speed < 2.7);
    let (ego, over) = (frames.at("Ego", 17.85), frames.at("OverTaker", 17.85));
    assert!((s(over) - s(ego)) / ego.speed < 2.7, "not a step earlier");
    // Standing still at 30 s: 1.8 m short of esmini (esmini's rounding and the chord's bend
    // on the curve: 5 mm).
    let end = reference("cut-in_sloppy", "OverTaker", 29.99, 30.01);
    let ours = frames.at("OverTaker", 30.0);
    let short = end
        .first()
        .map_or(f64::NAN, |r| (ours.x - r.x).hypot(ours.y - r.y));
    assert_abs_diff_eq!(short, 1.8, epsilon = 5e-3);
}

/// lane_change: Ego's LaneOffsetAction (EgoGoOffRoadEvent, 7.05 s in both runs) to 8 m,
/// sinusoidal, maxLateralAcc 3.5 m/s², at 20 m/s: T = π·√(8/(2·3.5)) = 3.3585 s.
///
/// The 0.65 m the comparison reports are two traits of esmini's LatLaneOffsetAction::Step:
/// 1. It evaluates the shape before stepping it, so its offset moves from the step after the
///    action starts: oscsim's offset at T − 0.05 s is esmini's at T (to its rounding). At the
///    peak lateral speed, 8·π/(2·3.3585) = 3.742 m/s, one step is 0.19 m.
/// 2. It moves the entity the full speed·dt along the road and the lateral motion on top, so
///    the entity moves faster than its speed; its own LaneChangeAction does not (it takes the
///    longitudinal step as √(step² − lateral step²)). oscsim keeps the speed the speed along the
///    path for both actions, so Ego falls behind by
///    v·∫(1 − cos θ)dt, sin θ = x̂·sin(πτ/T), x̂ = 3.742/20 = 0.18709:
///    v·T·(x̂²/4 + 3x̂⁴/64 + …) = 20·3.3585·(0.0087505 + 0.0000574) = 0.5916 m.
///
/// oscsim follows §7.7.2.2 here: "lane offset keeping starts immediately at start of the
/// action" (LaneOffsetAction in the model documentation), and a LaneOffsetAction moves the car
/// sideways at the speed set by the longitudinal domain as a LaneChangeAction does. (With both traits copied, as an experiment, Ego agrees with esmini
/// to 0.011 m.)
#[test]
fn lane_change_offset_differs_from_esmini_by_its_lag_and_its_extra_travel() {
    let (frames, events) = run_esmini("lane_change");
    assert_starts(&events, "lane_change", "EgoGoOffRoadEvent", (7.05, 7.05));
    let during = reference("lane_change", "Ego", 7.1, 10.55);
    assert_eq!(during.len(), 35, "reference rows 7.1 s to 10.5 s");
    for r in during {
        let ours = frames.at("Ego", r.time - 0.05);
        let offset = ours.road.clone().unwrap_or_default().4;
        assert_abs_diff_eq!(offset, r.offset, epsilon = ESMINI_ROUNDING);
    }
    let behind = |time: f64| {
        let r = reference("lane_change", "Ego", time - 0.01, time + 0.01);
        let s = frames.at("Ego", time).road.clone().unwrap_or_default().2;
        r.first().map_or(f64::NAN, |r| r.s - s)
    };
    assert_abs_diff_eq!(behind(10.5) - behind(7.0), 0.5916, epsilon = 3e-3);
}
