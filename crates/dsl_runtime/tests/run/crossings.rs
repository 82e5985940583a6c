//! Crossings crossed by every actor that moves, and the walker's place across them
//! (`plan/crossing_walk.rs`; ASAM OpenSCENARIO DSL 2.1 §8.12.2.2.9 `crossing_connects`, §8.9
//! `lateral`). Positions worked by hand in the scenario files' comments.

use crate::support::{error_on, run_on, run_to_error_on};

/// Positions along a straight crossing on a straight road: float round-off only.
const XY_TOL: f64 = 1e-6;
/// Phase ends are step times.
const T_TOL: f64 = 1e-9;

fn refused(name: &str, text: &str, place: &str) {
    let e = error_on(name, "crosswalk");
    assert!(
        e.contains(text) && e.ends_with(&format!("{name}.osc:{place}")),
        "{e}"
    );
}

fn at(r: &crate::support::Run, who: &str, t: f64, x: f64, y: f64) {
    let p = r.at(t, who);
    assert!(
        (p.x - x).abs() < XY_TOL && (p.y - y).abs() < XY_TOL,
        "{who} at {t} s: {p:?}, expected ({x}, {y})"
    );
}

/// `who` at `t` between steps: the line is straight, so the place is interpolated from the
/// two steps around it (the engine's pose at each is on the line).
fn between(r: &crate::support::Run, who: &str, t: f64, (x, y): (f64, f64)) {
    let dt = crate::support::DT;
    let (t0, t1) = ((t / dt).floor() * dt, (t / dt).ceil() * dt);
    let (p0, p1) = (r.at(t0, who), r.at(t1, who));
    let f = (t - t0) / (t1 - t0);
    let (gx, gy) = (p0.x + f * (p1.x - p0.x), p0.y + f * (p1.y - p0.y));
    assert!(
        (gx - x).abs() < XY_TOL && (gy - y).abs() < XY_TOL,
        "{who} at {t} s: ({gx}, {gy}), expected ({x}, {y})"
    );
}

#[test]
fn an_animal_and_a_vehicle_cross_the_road_on_crossings() {
    let r = run_on("crossing_others", "crosswalk");
    for (t, y) in [(0.0, -1.75), (1.75, 0.0), (3.5, 1.75)] {
        at(&r, "dog", t, 100.0, y);
    }
    assert_eq!(r.at(0.0, "dog").lane, -1);
    assert_eq!(r.at(3.5, "dog").lane, 1);
    for (t, y) in [(0.0, 1.75), (0.5, 0.75), (1.75, -1.75)] {
        at(&r, "bike", t, 99.0, y);
    }
    assert!(
        (r.at(0.5, "bike").h + std::f64::consts::FRAC_PI_2).abs() < XY_TOL,
        "bike heads -y"
    );
    assert_eq!(r.at(1.75, "bike").lane, -1);
    for (phase, end) in [("do.trot", 3.5), ("do.ride", 1.75)] {
        let (_, e) = r.phase(phase);
        assert!((e - end).abs() < T_TOL, "{phase} ends at {e}");
    }
}

#[test]
fn a_walker_ends_beside_a_crossing_or_keeps_a_distance_from_its_border() {
    let r = run_on("crossing_lateral", "crosswalk");
    let (len, v) = (3.5f64.hypot(0.5), 0.5);
    at(&r, "alice", 0.0, 100.0, -1.75);
    between(&r, "alice", len / v / 2.0, (99.75, 0.0));
    assert_eq!(r.at(7.0, "alice").lane, 1);
    // At 7 s, t/T of the way from (100, -1.75) to (99.5, 1.75), T = 7.071068 s (after T she
    // walks on at her speed until the phase's end at the step 7.1 s).
    let f = 7.0 / (len / v);
    at(&r, "alice", 7.0, 100.0 - 0.5 * f, -1.75 + 3.5 * f);
    let (_, e) = r.phase("do.aside");
    assert!((e - 7.1).abs() < T_TOL, "aside ends at {e}");
    for (t, y) in [(0.0, -1.75), (1.75, 0.0), (3.5, 1.75)] {
        at(&r, "bob", t, 99.0, y);
    }
}

/// crossing_speed.osc's comment, by hand: the speed actions' profiles along the crossings'
/// lines, the engine's steps (at each step's end speed) ahead of the integral by a·dt/2 per
/// second during a linear change.
#[test]
fn actions_on_the_speed_along_a_crossing_move_along_its_line_at_their_speed() {
    let r = run_on("crossing_speed", "crosswalk");
    crate::support::phases_are(
        &r,
        &[
            ("do.0.up", 0.0, 2.0),
            ("do.0.keep", 2.0, 4.5),
            ("do.1.stand", 0.0, 2.0),
            ("do.1.start", 2.0, 3.0),
            ("do.1.go", 3.0, 4.25),
        ],
    );
    // alice: 0.25 t (t + dt) m along the line over the change (0.5 m/s² from rest).
    let dt = crate::support::DT;
    for t in [1.0, 2.0] {
        at(&r, "alice", t, 100.0, -1.75 + 0.25 * t * (t + dt));
        assert!((r.at(t, "alice").speed - 0.5 * t).abs() < XY_TOL);
    }
    // keep_speed from the walked part's start (1 m along), at 1 m/s.
    for (t, y) in [(3.0, 0.25), (4.0, 1.25), (4.5, 1.75)] {
        at(&r, "alice", t, 100.0, y);
    }
    assert_eq!(r.at(4.5, "alice").lane, 1);
    // bob: standing on c2's start, then 2 m/s² from rest: 1 m at 3 s (the steps 1.05 m).
    for t in [0.0, 1.0, 2.0] {
        at(&r, "bob", t, 99.0, 1.75);
    }
    at(&r, "bob", 2.5, 99.0, 1.75 - (0.5 * 0.5 + 0.5 * dt));
    at(&r, "bob", 3.0, 99.0, 1.75 - (1.0 + dt));
    // walk() from 1 m along at 2 m/s: 2.5 m in 1.25 s.
    for (t, y) in [(3.5, -0.25), (4.25, -1.75)] {
        at(&r, "bob", t, 99.0, y);
    }
    assert_eq!(r.at(4.25, "bob").lane, -1);
}

/// crossing_beside.osc's comment, by hand: beside alice across the crossings' lines; bob's
/// place beside her (at: all) the engine's check held over his walk, which holds.
#[test]
fn a_walker_beside_another_is_beside_its_place_across_the_crossing() {
    let (error, records) = run_to_error_on("crossing_beside", "crosswalk");
    assert!(
        error.is_none() && records.is_empty(),
        "{error:?} {records:?}"
    );
    let r = run_on("crossing_beside", "crosswalk");
    // bob's place beside alice (at: all): the engine's check at every step of his walk.
    r.held("do.two/bob/1:across", (0.0, 7.0));
    for (t, y) in [(0.0, -1.75), (3.5, 0.0), (7.0, 1.75)] {
        at(&r, "alice", t, 100.0, y);
        at(&r, "bob", t, 98.5, y);
    }
    assert_eq!(r.at(7.0, "bob").lane, 1);
    let len = 3.5f64.hypot(0.25);
    at(&r, "dan", 0.0, 99.0, 1.75);
    between(&r, "dan", len / 2.0, (99.125, 0.0));
    let (_, e) = r.phase("do.three");
    assert!((e - 3.55).abs() < T_TOL, "three ends at {e}");
    // At 3.5 s, 3.5/len of the way from (99, 1.75) to (99.25, -1.75).
    let f = 3.5 / len;
    at(&r, "dan", 3.5, 99.0 + 0.25 * f, 1.75 - 3.5 * f);
}

/// crossing_beside_moving_fails.osc's comment, by hand: carl moves across c's line from the
/// start and is back by the end of bob's walk at 7 s, so the plan's check of the walk's ends
/// holds; the engine's check of bob beside carl, held over the walk, reads both as each step
/// starts: it holds as it starts and in the step from 0 s, and in the step from 0.05 s finds
/// bob 1.0375 m from the middle of carl's 0.7 m box where 1.0 m is asked: the one error
/// record, at the end of that step (0.10 s), and a failed run.
#[test]
fn a_walker_beside_another_that_moves_across_the_line_and_back_fails_in_the_walk() {
    let (error, records) = run_to_error_on("crossing_beside_moving_fails", "crosswalk");
    let error = error.expect("the run fails");
    let want = "expected 'bob' 1.000 m across the line from the middle of 'carl''s box across it, 0.700 m wide (within 0.01 m) (lateral(…) at ";
    assert!(error.starts_with(want), "{error}");
    let (place, found) = error
        .split_once("), found ")
        .unwrap_or_else(|| panic!("{error}"));
    assert!(
        place.ends_with("crossing_beside_moving_fails.osc:47:13"),
        "{error}"
    );
    let (got, when) = found
        .split_once(" m at t = ")
        .unwrap_or_else(|| panic!("{error}"));
    let got: f64 = got.parse().unwrap_or_else(|_| panic!("{error}"));
    assert!(
        (got - 1.0375).abs() <= 5e-4 + 1e-9 && when == "0.050 s",
        "{error}"
    );
    assert_eq!(records.len(), 1, "{records:?}");
    assert!((records[0].0 - 0.10).abs() < T_TOL, "{records:?}");
    assert_eq!(records[0].1, "do.walk/bob/1:across");
    assert_eq!(records[0].2, error);
}

#[test]
fn what_a_crossing_does_not_run_is_an_error_at_its_place() {
    refused(
        "err_crossing_lateral_beside",
        "expected `alice`'s place across crossing `c` beside `npc` the same at its walk's end, 7.00 s, as at its start (at: all)",
        "21:13",
    );
    refused(
        "err_crossing_speed_action",
        "expected `alice` on crossing `c` until its phase ends at 10.00 s, found it at the crossing's end (3.50 m along its line) at 3.50 s under keep_speed()",
        "12:9",
    );
    refused(
        "err_crossing_lane_action",
        "expected a movement of a person, animal or vehicle along crossing `c` (walk(), move(), drive(), or an action on its speed or acceleration: the crossing's line is the path), found `bike`'s change_lane(), whose path is its own",
        "10:9",
    );
}
