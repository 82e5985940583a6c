//! The §8.8.3 gap actions (`change_space_gap`, `keep_space_gap`, `change_time_headway`,
//! `keep_time_headway`) through the engine's LongitudinalDistanceAction on
//! `tests/roads/straight.xodr`: each change ends when its gap is reached (the engine's 0.1 m),
//! each keep holds it to its phase's end, against the scenario's hand-worked comment.

use crate::support::{run, Run, DT};

/// The engine's distance controller ends a change within this of its distance (m).
const REACHED: f64 = 0.1;
/// Phase ends are step times.
const T_TOL: f64 = 1e-9;

#[test]
fn change_space_gap_ends_at_the_gap_and_keep_space_gap_holds_it() {
    let r = run("actions/space_gap", 0, None);
    // Boxes: front 3.5 m, rear 0.5 m ahead of / behind the reference points.
    space_gap_law(&r, |t| (r.at(t, "lead").s - 0.5) - (r.at(t, "ego").s + 3.5));
    assert!((r.at(30.0, "lead").s - 550.0).abs() < 1e-9);
}

/// actions/space_gap.osc's law (its comment, by hand) on a run of it, `gap(t)` the space gap
/// between the boxes along the direction of travel (also driven against s: `opposite_gaps`).
pub(crate) fn space_gap_law(r: &Run, gap: impl Fn(f64) -> f64) {
    assert!((gap(0.0) - 66.0).abs() < 1e-9, "gap(0) = {}", gap(0.0));
    // Mid-points of the saturated part (2 m/s² from the first step): gap = 66 − t² − t·dt,
    // v = 15 + 2·t.
    for (t, want_gap, want_v) in [(2.0, 61.9, 19.0), (5.0, 40.75, 25.0)] {
        assert!((gap(t) - want_gap).abs() < LAW_TOL, "gap({t}) = {}", gap(t));
        let v = r.at(t, "ego").speed;
        assert!((v - want_v).abs() < LAW_TOL, "v({t}) = {v}");
    }
    let (s, e) = r.phase("do.1.close");
    // The stepped law reaches |u| <= 0.1 m first at the step from 8.95 s (u = 0.0904 m; 0.1046 m
    // at 8.90 s); the action's end is logged with the next step and the phase's stop trigger
    // sees it one step later: 9.05 s.
    assert!(
        s.abs() < T_TOL && (e - 9.05).abs() < T_TOL,
        "close [{s}, {e}] (9.05 s by the law)"
    );
    let at_end = gap(e - 2.0 * DT);
    assert!(
        (at_end - 20.0904).abs() < LAW_TOL && (at_end - 20.0).abs() <= REACHED,
        "gap {at_end} at {e}"
    );
    assert!(gap(8.9) - 20.0 > REACHED, "not reached a step earlier");
    let v_end = r.at(8.95, "ego").speed;
    assert!((v_end - 15.2833).abs() < LAW_TOL, "v(8.95) = {v_end}");
    // Closing only: the gap never falls below the target by more than the tolerance.
    for (t, _) in r.frames.iter().filter(|(t, _)| *t <= e) {
        assert!(gap(*t) > 20.0 - REACHED, "gap {} at {t}", gap(*t));
    }
    let (s2, e2) = r.phase("do.1.hold");
    assert!(
        (s2 - e).abs() < T_TOL && (e2 - 30.0).abs() < T_TOL,
        "hold [{s2}, {e2}]"
    );
    assert!(
        (gap(30.0) - 20.0).abs() < REACHED,
        "gap(30) = {}",
        gap(30.0)
    );
    let ego = r.at(30.0, "ego");
    assert!((ego.speed - 15.0).abs() < 0.05, "ego v(30) = {}", ego.speed);
}

#[test]
fn change_time_headway_ends_at_the_headway_and_keep_time_headway_holds_it() {
    let r = run("actions/time_headway", 0, None);
    time_headway_law(&r, |t| r.at(t, "lead").s - r.at(t, "ego").s);
    assert!((r.at(40.0, "lead").s - 950.0).abs() < 1e-9);
}

/// actions/time_headway.osc's law (its comment, by hand) on a run of it, `between(t)` the
/// distance between the reference points along the direction of travel (also driven against
/// s: `opposite_gaps`).
pub(crate) fn time_headway_law(r: &Run, between: impl Fn(f64) -> f64) {
    assert!((between(0.0) - 130.0).abs() < 1e-9);
    // Mid-points of the saturated part (2 m/s² from the first step): 130 − t² − t·dt m,
    // v = 20 + 2·t.
    for (t, want, want_v) in [(5.0, 104.75, 30.0), (8.0, 65.6, 36.0)] {
        assert!(
            (between(t) - want).abs() < LAW_TOL,
            "{} m at {t}",
            between(t)
        );
        let v = r.at(t, "ego").speed;
        assert!((v - want_v).abs() < LAW_TOL, "v({t}) = {v}");
    }
    let (s, e) = r.phase("do.1.open");
    // |u| <= 0.1 m first at the step from 10.55 s (u = 0.0747 m, 0.5647 m at 10.50 s): the
    // phase ends two steps later, 10.65 s, ego still closing in at 29.80 m/s.
    assert!(
        s.abs() < T_TOL && (e - 10.65).abs() < T_TOL,
        "open [{s}, {e}] (10.65 s by the law)"
    );
    let at_end = between(e - 2.0 * DT);
    assert!(
        (at_end - 30.0747).abs() < LAW_TOL && (at_end - 30.0).abs() <= REACHED,
        "{at_end} m at {e}"
    );
    let v_end = r.at(10.55, "ego").speed;
    assert!((v_end - 29.8).abs() < LAW_TOL, "v(10.55) = {v_end}");
    let (s2, e2) = r.phase("do.1.follow");
    assert!(
        (s2 - e).abs() < T_TOL && (e2 - 40.0).abs() < T_TOL,
        "follow [{s2}, {e2}]"
    );
    assert!(
        (between(40.0) - 30.0).abs() < REACHED,
        "{} m at 40 s",
        between(40.0)
    );
    assert!((r.at(40.0, "ego").speed - 20.0).abs() < 0.05);
}

/// Lateral error (m) at which the engine's LateralDistanceAction has reached its distance.
const LATERAL_REACHED: f64 = 0.01;
/// Positions against the step-by-step law worked in the scenarios' comments (m): the engine
/// computes the same recurrence, so only rounding separates them.
const LAW_TOL: f64 = 1e-3;
/// The continuous closed form against the stepped law (m at 2 s; s at the end).
const CLOSED_FORM_GAP: f64 = 0.005;

/// The closed form of both lateral scenarios: a critically damped approach over 1 m with
/// ω = √(0.4 × 3 m/s²) = 1.0954 /s: the error left at t, u = (1 + ωt)e^(−ωt) m.
fn error_left(t: f64) -> f64 {
    let x = (0.4f64 * 3.0).sqrt() * t;
    (1.0 + x) * (-x).exp()
}

#[test]
fn change_space_gap_to_the_right_closes_across_the_road_and_keep_holds_it() {
    let r = run("actions/lateral_gap", 0, None);
    // Gap between the 2 m wide boxes: lead's y − 1 − (ego's y + 1).
    lateral_gap_law(&r, |t| (r.at(t, "lead").y - 1.0) - (r.at(t, "ego").y + 1.0));
    let ego = r.at(12.0, "ego");
    assert!(
        (ego.y + 7.75).abs() < LATERAL_REACHED,
        "ego y(12) = {}",
        ego.y
    );
    assert_eq!(ego.lane, -3, "ego stays in its lane");
    assert!((ego.x - 340.0).abs() < 0.05, "ego x(12) = {}", ego.x);
}

/// actions/lateral_gap.osc's law (its comment, by hand) on a run of it, `gap(t)` the gap
/// between the boxes across the road (also driven against s: `opposite_gaps`).
pub(crate) fn lateral_gap_law(r: &Run, gap: impl Fn(f64) -> f64) {
    assert!((gap(0.0) - 1.5).abs() < 1e-9, "gap(0) = {}", gap(0.0));
    // Mid-point: 0.3595 m left by the stepped law, 0.357 m in closed form.
    assert!((error_left(2.0) - 0.3595).abs() < CLOSED_FORM_GAP);
    assert!(
        (gap(2.0) - 0.8595).abs() < LAW_TOL,
        "gap(2) = {} (0.8595 by the stepped law)",
        gap(2.0)
    );
    let (s, e) = r.phase("do.1.close");
    assert!(s.abs() < T_TOL, "close starts at {s}");
    // The law's error falls to 0.01 m at the step starting at 6.30 s; the action ends in that
    // step, and the phase one step later (as the longitudinal gaps above).
    assert!(
        (e - 6.4).abs() < T_TOL,
        "close ends at {e} (6.40 s by hand)"
    );
    assert!(
        (gap(6.3) - 0.5).abs() <= LATERAL_REACHED,
        "gap {} when the change ends",
        gap(6.3)
    );
    assert!(
        (gap(6.25) - 0.5).abs() > LATERAL_REACHED,
        "not reached a step earlier"
    );
    let (s2, e2) = r.phase("do.1.hold");
    assert!(
        (s2 - e).abs() < T_TOL && (e2 - 12.0).abs() < T_TOL,
        "hold [{s2}, {e2}]"
    );
    assert!(
        (gap(12.0) - 0.5).abs() < LATERAL_REACHED,
        "gap(12) = {}",
        gap(12.0)
    );
    // Along the road nothing changed: 20 m/s.
    let ego = r.at(12.0, "ego");
    assert!((ego.speed - 20.0).abs() < 1e-9, "ego v(12) = {}", ego.speed);
}

#[test]
fn change_space_gap_inside_is_to_the_left_in_right_hand_traffic() {
    let r = run("actions/lateral_gap_inside", 0, None);
    let gap = |t: f64| (r.at(t, "ego").y - 1.0) - (r.at(t, "lead").y + 1.0);
    assert!((gap(0.0) - 1.5).abs() < 1e-9, "gap(0) = {}", gap(0.0));
    let y2 = r.at(2.0, "ego").y;
    assert!(
        (y2 + 4.25 + 0.3595).abs() < LAW_TOL,
        "ego y(2) = {y2} (-4.6095 by the stepped law)"
    );
    let (_, e) = r.phase("do.widen");
    assert!(
        (e - 6.4).abs() < T_TOL,
        "widen ends at {e} (6.40 s by hand)"
    );
    let y = r.at(6.3, "ego").y;
    assert!(
        (y + 4.25).abs() <= LATERAL_REACHED,
        "ego y = {y} at the end"
    );
    assert!((gap(6.3) - 2.5).abs() <= LATERAL_REACHED);
    assert!((r.at(10.0, "ego").x - 200.0).abs() < 0.05);
}

/// `left` (the actor on the reference's left) and `outside` (away from the centre line: right
/// in right-hand traffic), each a 1 m move as in lateral_gap.osc, so the same stepped law
/// (lateral_gap_left.osc's and lateral_gap_outside.osc's comments, by hand).
#[test]
fn change_space_gap_left_and_outside_move_to_their_sides() {
    for (name, phase, want, gap_want) in [
        ("actions/lateral_gap_left", "do.1.narrow", -6.25, 0.5),
        ("actions/lateral_gap_outside", "do.widen", -9.75, 2.5),
    ] {
        let r = run(name, 0, None);
        // Both move 1 m to the right: the error left at 2 s is below the target.
        let y2 = r.at(2.0, "ego").y;
        assert!(
            (y2 - (want + 0.3595)).abs() < LAW_TOL,
            "{name}: ego y(2) = {y2} ({} by the stepped law)",
            want + 0.3595
        );
        let (_, e) = r.phase(phase);
        assert!(
            (e - 6.4).abs() < T_TOL,
            "{name}: ends at {e} (6.40 s by hand)"
        );
        let y = r.at(6.3, "ego").y;
        assert!(
            (y - want).abs() <= LATERAL_REACHED,
            "{name}: ego y = {y} at the end"
        );
        // The gap between the boxes, ego on lead's left (left) or right (outside).
        let (ly, ey) = (r.at(6.3, "lead").y, y);
        let gap = (ey - ly).abs() - 2.0;
        assert!(
            (gap - gap_want).abs() <= LATERAL_REACHED,
            "{name}: gap {gap}"
        );
        assert_eq!(
            r.at(10.0, "ego").lane,
            if want > -7.0 { -2 } else { -3 },
            "{name}"
        );
        assert!((r.at(10.0, "ego").x - 200.0).abs() < 0.05, "{name}");
    }
    // keep_space_gap after the left change holds the 0.5 m to the end.
    let r = run("actions/lateral_gap_left", 0, None);
    let gap = |t: f64| (r.at(t, "ego").y - 1.0) - (r.at(t, "lead").y + 1.0);
    assert!(
        (gap(10.0) - 0.5).abs() < LATERAL_REACHED,
        "gap(10) = {}",
        gap(10.0)
    );
}
