//! `yaw(…)` and `orientation(…)` measured in the world or from another object where the plan
//! does not know the actor's place: in a phase that starts at run time, at the end of a phase
//! whose end the plan does not know, or throughout such a phase for a moving actor. The engine
//! checks the heading then (its state check, `actions::check_heading`); a failure is an error
//! record and a failed run. Expectations worked by hand in the scenario files.

use crate::orientation::{turn, ARC_TOL};
use crate::support::{run_on, run_to_error_on};

/// Headings on the straight: float round-off.
const H_TOL: f64 = 1e-9;
/// Phase ends and record times are step times.
const T_TOL: f64 = 1e-9;

/// [`run_to_error_on`] bend.xodr.
fn run_to_error_on_bend(name: &str) -> (Option<String>, Vec<(f64, String, String)>) {
    run_to_error_on(name, "bend")
}

/// Every heading asked after `wait @go` holds (yaw_runtime.osc's comment): the run ends with
/// the headings worked by hand.
#[test]
fn yaws_in_phases_that_start_at_run_time_are_the_engines_checks_and_hold() {
    let (error, records) = run_to_error_on_bend("yaw_runtime");
    assert!(
        error.is_none() && records.is_empty(),
        "{error:?} {records:?}"
    );
    let r = run_on("yaw_runtime", "bend");
    let (s, e) = r.phase("do.signal.1.1");
    assert!(
        (s - 2.55).abs() < T_TOL && (e - 7.55).abs() < T_TOL,
        "[{s}, {e}]"
    );
    let (s, e) = r.phase("do.signal.1.2");
    assert!(
        (s - 7.55).abs() < T_TOL && (e - 15.0).abs() < T_TOL,
        "[{s}, {e}]"
    );
    for t in [2.55, 5.0, 7.55] {
        for who in ["ego", "car"] {
            let got = r.at(t, who).h;
            assert!(turn(got, 0.0) < H_TOL, "{who} heading {got} at {t} s");
        }
        let got = r.at(t, "post").h;
        assert!(turn(got, 0.5) < ARC_TOL, "post heading {got} at {t} s");
    }
    let h = 70.0 / 108.75;
    let got = r.at(15.0, "ego").h;
    assert!(
        turn(got, h) < ARC_TOL,
        "ego heading {got} at 15 s, expected {h}"
    );
}

/// The engine's heading checks that fail: each an error record naming the modifier and a
/// failed run, at the moment worked by hand in the scenario file (the record of a check held
/// over a phase at the end of the step that found it, as every failure in a step's actions).
#[test]
fn yaws_the_run_does_not_meet_where_the_plan_knows_no_place_fail_the_run() {
    for (name, (t, record), place, want, found) in [
        (
            "yaw_runtime_all_fails",
            (8.05, 8.1),
            "30:38",
            "expected 'ego' at heading 0.0000 rad (absolute 0.0000 rad, within 0.001 rad) (orientation(…) at ",
            "found it at 0.0046 rad, its lane's heading 0.0046 rad",
        ),
        (
            "yaw_runtime_end_fails",
            (15.0, 15.0),
            "37:29",
            "expected 'car' at heading 0.6437 rad (length_to_length from `ego` 0.0000 rad, 'ego' at heading 0.6437 rad, within 0.001 rad) (yaw(…) at the phase end at ",
            "found it at 0.6651 rad, its lane's heading 0.6651 rad",
        ),
        (
            "yaw_until_all_fails",
            (8.05, 8.1),
            "18:30",
            "expected 'ego' at heading 0.0000 rad (absolute 0.0000 rad, within 0.001 rad) (orientation(…) at ",
            "found it at 0.0046 rad, its lane's heading 0.0046 rad",
        ),
        (
            "yaw_until_end_fails",
            (10.05, 10.05),
            "17:17",
            "expected 'ego' at heading 0.0000 rad (relative to north (+y) -1.5708 rad, within 0.001 rad) (yaw(…) at the phase end at ",
            "found it at 0.1885 rad, its lane's heading 0.1885 rad",
        ),
    ] {
        let (error, records) = run_to_error_on_bend(name);
        let error = error.unwrap_or_else(|| panic!("{name}: the run ends"));
        let tail = format!("{name}.osc:{place}), {found} at t = {t:.3} s");
        assert!(
            error.starts_with(want) && error.ends_with(&tail),
            "{name}: {error}"
        );
        assert_eq!(records.len(), 1, "{name}: {records:?}");
        assert!((records[0].0 - record).abs() < T_TOL, "{name}: {records:?}");
        assert_eq!(records[0].2, error, "{name}");
    }
}

/// A first phase that starts at run time: no yaw from the run's start, the engine's check
/// (yaw_first_runtime_fails.osc).
#[test]
fn a_first_phase_at_run_time_sets_no_yaw_and_its_heading_is_the_engines_check() {
    let name = "yaw_first_runtime_fails";
    let (error, records) = run_to_error_on_bend(name);
    let error = error.unwrap_or_else(|| panic!("{name}: the run ends"));
    let want = "expected 'ego' at heading 0.7854 rad (absolute 0.7854 rad, within 0.001 rad) (orientation(…) at ";
    let tail = format!(
        "{name}.osc:30:38), found it at 0.0000 rad, its lane's heading 0.0000 rad at t = 2.550 s"
    );
    assert!(error.starts_with(want) && error.ends_with(&tail), "{error}");
    assert_eq!(records.len(), 1, "{records:?}");
    assert!((records[0].0 - 2.55).abs() < T_TOL, "{records:?}");
    assert_eq!(records[0].2, error);
}

/// After a run-time start an actor driving against s faces -s: absolute pi holds at every step,
/// ego's heading 0 at the next phase's start does not (yaw_runtime_against_fails.osc).
#[test]
fn yaws_at_run_time_of_an_actor_driving_against_s_are_its_heading_turned_by_pi() {
    let name = "yaw_runtime_against_fails";
    let (error, records) = run_to_error_on(name, "straight");
    let error = error.unwrap_or_else(|| panic!("{name}: the run ends"));
    let want = "expected 'npc' at heading 0.0000 rad (length_to_length from `ego` 0.0000 rad, 'ego' at heading 0.0000 rad, within 0.001 rad) (yaw(…) at ";
    let tail = format!(
        "{name}.osc:40:25), found it at 3.1416 rad, its lane's heading 3.1416 rad at t = 4.550 s"
    );
    assert!(error.starts_with(want) && error.ends_with(&tail), "{error}");
    assert_eq!(records.len(), 1, "{records:?}");
    assert!((records[0].0 - 4.55).abs() < T_TOL, "{records:?}");
}
