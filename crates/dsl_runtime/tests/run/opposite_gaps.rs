//! The §8.8.3 gap actions between two actors driving against s (oncoming traffic): the
//! scenarios of `gap_actions` driven the other way on `tests/roads/straight.xodr`. The engine's
//! LongitudinalDistanceAction and LateralDistanceAction measure in road coordinates turned to
//! the actor's direction of travel (OpenSCENARIO 1.3 §6.4) and move the actor in that
//! direction, so each hand-worked number of the scenario in +s holds with u = 1000 − s for s
//! (x = s on this road) and −t for t; each scenario's comment gives them.

use crate::gap_actions::{lateral_gap_law, space_gap_law, time_headway_law};
use crate::support::{phases_are, run_on};

/// The lateral one within this (m).
const LATERAL_REACHED: f64 = 0.01;
/// Positions against the step-by-step law worked in the scenarios' comments (m).
const LAW_TOL: f64 = 1e-3;
/// Phase ends are step times.
const T_TOL: f64 = 1e-9;
/// The road's length: u = L − s.
const L: f64 = 1000.0;

#[test]
fn change_space_gap_between_oncoming_actors_closes_along_their_direction_of_travel() {
    let r = run_on("opposite_space_gap", "straight");
    let u = |t: f64, who: &str| L - r.at(t, who).s;
    // Boxes: front 3.5 m, rear 0.5 m ahead of / behind the reference points along the travel.
    space_gap_law(&r, |t| (u(t, "lead") - 0.5) - (u(t, "ego") + 3.5));
    assert_eq!((r.at(0.0, "ego").lane, r.at(0.0, "lead").lane), (2, 2));
    let (lead, ego) = (r.at(30.0, "lead"), r.at(30.0, "ego"));
    assert!((lead.x - 450.0).abs() < 1e-9, "lead x(30) = {}", lead.x);
    assert_eq!(ego.lane, 2, "{ego:?}");
}

#[test]
fn change_time_headway_between_oncoming_actors_closes_along_their_direction_of_travel() {
    let r = run_on("opposite_time_headway", "straight");
    // u = L − s: lead's u minus ego's is ego's s minus lead's.
    time_headway_law(&r, |t| r.at(t, "ego").s - r.at(t, "lead").s);
    assert!((r.at(40.0, "lead").x - 50.0).abs() < 1e-9);
}

#[test]
fn change_space_gap_to_the_right_of_an_oncoming_actor_is_to_the_drivers_right() {
    let r = run_on("opposite_lateral_gap", "straight");
    // ego right of lead in their direction of travel: at the larger t (y on this road).
    lateral_gap_law(&r, |t| (r.at(t, "ego").y - 1.0) - (r.at(t, "lead").y + 1.0));
    assert_eq!((r.at(0.0, "ego").lane, r.at(0.0, "lead").lane), (2, 1));
    let ego = r.at(12.0, "ego");
    assert!(
        (ego.y - 4.25).abs() < LATERAL_REACHED,
        "ego y(12) = {}",
        ego.y
    );
    assert_eq!(ego.lane, 2, "ego stays in its lane");
    assert!((ego.x - 660.0).abs() < 0.05, "ego x(12) = {}", ego.x);
}

/// Positions on straight roads at constant speeds: float round-off only.
const S_TOL: f64 = 1e-6;

#[test]
fn gaps_kept_between_oncoming_actors_after_an_until_are_the_ones_the_engine_measures_then() {
    let r = run_on("opposite_runtime_keep_gap", "straight");
    phases_are(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.slow", 3.35, 4.35),
            ("do.keep", 4.35, 6.35),
            ("do.headway", 6.35, 8.35),
        ],
    );
    assert!((r.at(3.35, "ego").x - 833.0).abs() < S_TOL);
    for t in [4.35, 5.35, 6.35, 7.35, 8.35] {
        let (ego, lead) = (r.at(t, "ego"), r.at(t, "lead"));
        assert!(
            (ego.s - lead.s - 59.8).abs() < S_TOL && ego.lane == 1,
            "{t}: {ego:?} {lead:?}"
        );
        assert!((ego.speed - 8.0).abs() < 1e-9, "{t}: {ego:?}");
    }
    assert!((r.at(8.35, "ego").x - 793.0).abs() < S_TOL);
}

#[test]
fn a_lateral_gap_to_an_oncoming_actor_after_an_until_is_checked_and_run_to_the_drivers_side() {
    let r = run_on("opposite_runtime_lateral_gap", "straight");
    phases_are(
        &r,
        &[
            ("do.approach", 0.0, 3.35),
            ("do.beside", 3.35, 5.35),
            ("do.closer", 5.35, 11.75),
        ],
    );
    for t in [3.35, 4.35, 5.35] {
        let ego = r.at(t, "ego");
        assert!(
            (ego.y - 1.75).abs() < S_TOL && ego.lane == 1,
            "{t}: {ego:?}"
        );
    }
    let mid = r.at(7.35, "ego");
    assert!((mid.y - 2.3905).abs() < LAW_TOL, "{mid:?}");
    let end = r.at(11.75, "ego");
    assert!(
        (end.y - 2.75).abs() < LATERAL_REACHED && end.lane == 1,
        "{end:?}"
    );
    assert!((end.speed - 20.0).abs() < 1e-9, "{end:?}");
}

#[test]
fn a_lateral_gap_to_an_oncoming_actor_off_its_sides_lanes_after_an_until_fails_the_run() {
    let lowered = crate::support::lower_at(
        "tests/scenarios/opposite_runtime_lateral_gap_fails.osc",
        "tests/roads/straight.xodr",
        0,
        None,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let (error, records) = crate::support::run_to_error(&lowered.scenario);
    let error = error.expect("the run fails");
    assert!(
        error.starts_with("expected 'ego''s place 2.500 m to the right of 'npc' in a driving lane of its side of road 1 (change_space_gap(…) at ")
            && error.contains("opposite_runtime_lateral_gap_fails.osc:39:9), ")
            && error.ends_with("found t = 7.750 m at s = 793.000 m, off them at t = 5.350 s"),
        "{error}"
    );
    assert_eq!(records.len(), 1, "{records:?}");
    assert!((records[0].0 - 5.35).abs() < T_TOL && records[0].2 == error);
}
