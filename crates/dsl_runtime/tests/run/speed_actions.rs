//! The §8.8.2 actions that control the speed or the acceleration (`change_speed`,
//! `assign_speed`, `keep_speed`, `remain_stationary`, `assign_acceleration`,
//! `change_acceleration`, `keep_acceleration`) on `tests/roads/straight.xodr`: speeds against
//! the closed forms of each scenario's comment, distances as the engine integrates them
//! (`support::stepped`: the speed of each step's end), phase ends where the action ends.

use std::f64::consts::PI;

use crate::ramp_lead;
use crate::support::{run, stepped};

/// Speeds are closed forms the engine evaluates at the step times; distances sums of a few
/// hundred of them.
const TOL: f64 = 1e-9;
/// Phase ends are step times.
const T_TOL: f64 = 1e-9;

fn close(got: f64, want: f64, what: &str) {
    assert!((got - want).abs() < TOL, "{what}: {got} vs {want}");
}

#[test]
fn change_speed_at_a_rate_ends_when_the_target_is_reached() {
    let r = run("actions/change_speed_rate", 0, None);
    let v = |t: f64| {
        if t <= 1.0 {
            10.0
        } else {
            (10.0 + 5.0 * (t - 1.0)).min(30.0)
        }
    };
    close(r.at(3.0, "ego").speed, 20.0, "v(3)");
    close(r.at(3.0, "ego").s, 20.0 + stepped(v, 0.0, 3.0), "s(3)");
    // The exact integral is 60 m; the engine's step lead is 5 m/s² · 2 s · dt/2.
    close(stepped(v, 0.0, 3.0), 40.0 + 0.25, "hand sum");
    close(r.at(5.0, "ego").speed, 30.0, "v(5)");
    close(r.at(6.0, "ego").s, 20.0 + stepped(v, 0.0, 6.0), "s(6)");
    assert!((stepped(v, 0.0, 6.0) - (120.0 + 0.5)).abs() < TOL);
    let (s, e) = r.phase("do.1");
    assert!(
        (s - 1.0).abs() < T_TOL && (e - 5.0).abs() < T_TOL,
        "{s} {e}"
    );
    let (s, e) = r.phase("do.2");
    assert!(
        (s - 5.0).abs() < T_TOL && (e - 6.0).abs() < T_TOL,
        "{s} {e}"
    );
}

#[test]
fn change_speed_smooth_over_a_duration_is_sinusoidal() {
    let r = run("actions/change_speed_smooth", 0, None);
    let v = |t: f64| 10.0 + 10.0 * (1.0 - (PI * t.min(4.0) / 4.0).cos()) / 2.0;
    close(r.at(2.0, "ego").speed, 15.0, "v(2)");
    close(r.at(2.0, "ego").s, 20.0 + stepped(v, 0.0, 2.0), "s(2)");
    // The sum is the exact 50 − 20/π m plus the step lead (dt/2 · 5 m/s) and its curvature term.
    assert!((20.0 + stepped(v, 0.0, 2.0) - (50.0 - 20.0 / PI + 0.125)).abs() < 1e-3);
    close(r.at(4.0, "ego").speed, 20.0, "v(4)");
    assert!((r.at(4.0, "ego").s - (80.0 + 0.25)).abs() < 1e-6);
    assert_eq!(r.phase("do"), (0.0, 4.0));
}

#[test]
fn change_speed_without_rate_or_duration_and_asap() {
    let r = run("actions/change_speed_default", 0, None);
    let v = |t: f64| {
        if t <= 3.0 {
            20.0 - 2.0 * t
        } else {
            (14.0 - 10.0 * (t - 3.0)).max(0.0)
        }
    };
    close(r.at(1.5, "ego").speed, 17.0, "v(1.5)");
    close(r.at(3.0, "ego").s, 10.0 + stepped(v, 0.0, 3.0), "s(3)");
    let (s, e) = r.phase("do.0");
    assert!(
        (s - 0.0).abs() < T_TOL && (e - 3.0).abs() < T_TOL,
        "{s} {e}"
    );
    let (s, e) = r.phase("do.1");
    assert!(
        (s - 3.0).abs() < T_TOL && (e - 4.4).abs() < T_TOL,
        "{s} {e}"
    );
    close(r.at(4.4, "ego").speed, 0.0, "v(4.4)");
    // 70.8 m exactly, less the lead of the two decelerations: (6 + 14) m/s · dt/2.
    close(r.at(4.4, "ego").s, 70.8 - 0.5, "s(4.4)");
}

#[test]
fn assign_speed_ends_at_once_and_keep_speed_holds() {
    let r = run("actions/assign_and_keep_speed", 0, None);
    assert_eq!(r.phase("do.0"), (0.0, 1.0));
    // assign_speed's Act starts and ends in the step at 1 s; keep_speed starts with it.
    assert_eq!(r.phase("do.1"), (1.0, 1.0));
    assert_eq!(r.phase("do.2"), (1.0, 3.0));
    close(r.at(1.0, "ego").s, 20.0, "s(1)");
    close(r.at(1.05, "ego").speed, 25.0, "v(1.05)");
    close(r.at(2.0, "ego").s, 45.0, "s(2)");
    close(r.at(3.0, "ego").s, 70.0, "s(3)");
}

#[test]
fn remain_stationary_stands_then_the_vehicle_pulls_away() {
    let r = run("actions/remain_stationary", 0, None);
    let ego = r.at(0.0, "ego");
    assert_eq!(ego.lane, -2);
    close(ego.speed, 0.0, "v(0)");
    close(r.at(2.0, "ego").s, 50.0, "s(2)");
    let v = |t: f64| (2.0 * (t - 2.0)).clamp(0.0, 10.0);
    close(r.at(4.5, "ego").speed, 5.0, "v(4.5)");
    close(r.at(4.5, "ego").s, 50.0 + stepped(v, 2.0, 4.5), "s(4.5)");
    // Hand: 56.25 m and the lead 5 m/s · dt/2.
    close(50.0 + stepped(v, 2.0, 4.5), 56.25 + 0.125, "hand sum");
    assert_eq!(r.phase("do.0"), (0.0, 2.0));
    assert_eq!(r.phase("do.1"), (2.0, 7.0));
}

/// Code 110 of the standard (§8.8.2.15).
#[test]
fn change_keep_and_change_acceleration() {
    let r = run("actions/acceleration_actions", 0, None);
    // v(t) of the scenario's comment.
    let v = |t: f64| {
        if t <= 1.2 {
            10.0 + 1.25 * t * t
        } else if t <= 3.2 {
            11.8 + 3.0 * (t - 1.2)
        } else if t <= 4.4 {
            let u = t - 3.2;
            17.8 + 3.0 * u - 1.25 * u * u
        } else {
            19.6
        }
    };
    for (t, want) in [
        (0.6, 10.45),
        (1.2, 11.8),
        (3.2, 17.8),
        (4.4, 19.6),
        (5.4, 19.6),
    ] {
        assert!(
            (r.at(t, "ego").speed - want).abs() < 1e-6,
            "v({t}) = {}",
            r.at(t, "ego").speed
        );
    }
    for t in [1.2, 3.2, 4.4, 5.4] {
        let s = r.at(t, "ego").s;
        assert!(
            (s - (10.0 + stepped(v, 0.0, t))).abs() < 1e-6,
            "s({t}) = {s}"
        );
    }
    // The exact distances of the comment and the lead (Δv · dt/2) of the engine's steps.
    assert!((10.0 + stepped(v, 0.0, 5.4) - (94.72 + 9.6 * 0.025)).abs() < 1e-3);
    for (path, s, e) in [
        ("do.0", 0.0, 1.2),
        ("do.1", 1.2, 3.2),
        ("do.2", 3.2, 4.4),
        ("do.3", 4.4, 5.4),
    ] {
        let (a, b) = r.phase(path);
        assert!(
            (a - s).abs() < T_TOL && (b - e).abs() < T_TOL,
            "{path}: {a} {b}"
        );
    }
}

#[test]
fn an_assigned_acceleration_holds_until_a_speed_action() {
    let r = run("actions/assign_acceleration", 0, None);
    let v = |t: f64| {
        if t <= 7.0 {
            (20.0 - 4.0 * t).max(0.0)
        } else {
            (5.0 * (t - 7.0)).min(10.0)
        }
    };
    close(r.at(2.0, "ego").speed, 12.0, "v(2)");
    close(r.at(2.0, "ego").s, 10.0 + stepped(v, 0.0, 2.0), "s(2)");
    close(r.at(6.0, "ego").speed, 0.0, "v(6)");
    // Stopped at 60 m exactly, less the lead 20 m/s · dt/2.
    close(r.at(6.0, "ego").s, 60.0 - 0.5, "s(6)");
    close(r.at(9.0, "ego").speed, 10.0, "v(9)");
    assert_eq!(r.phase("do.0"), (0.0, 0.0));
    assert_eq!(r.phase("do.2"), (7.0, 9.0));
}

/// keep_acceleration in the instant after assign_acceleration keeps the assigned acceleration
/// (assign_then_keep_acceleration.osc's comment, by hand).
#[test]
fn keep_acceleration_right_after_assign_acceleration_keeps_it() {
    let r = run("actions/assign_then_keep_acceleration", 0, None);
    let v = |t: f64| 10.0 + 2.0 * t;
    for t in [1.0, 2.0, 3.0] {
        close(r.at(t, "ego").speed, v(t), &format!("v({t})"));
    }
    close(stepped(v, 0.0, 3.0), 39.0 + 0.15, "hand sum");
    close(r.at(3.0, "ego").s, 10.0 + stepped(v, 0.0, 3.0), "s(3)");
    assert_eq!(r.phase("do.0"), (0.0, 0.0));
    assert_eq!(r.phase("do.1"), (0.0, 2.0));
    assert_eq!(r.phase("do.2"), (2.0, 3.0));
}

/// change_acceleration in the instant after assign_acceleration starts from the assigned
/// acceleration (assign_then_change_acceleration.osc's comment, by hand).
#[test]
fn change_acceleration_right_after_assign_acceleration_starts_from_it() {
    let r = run("actions/assign_then_change_acceleration", 0, None);
    for (t, want) in [(0.4, 10.6), (0.8, 10.8), (1.8, 10.8)] {
        assert!(
            (r.at(t, "ego").speed - want).abs() < 1e-6,
            "v({t}) = {}",
            r.at(t, "ego").speed
        );
    }
    assert_eq!(r.phase("do.0"), (0.0, 0.0));
    let (s, e) = r.phase("do.1");
    assert!(s.abs() < T_TOL && (e - 0.8).abs() < T_TOL, "[{s}, {e}]");
}

/// The group form: each member does the action (docs/dsl.md).
#[test]
fn a_group_changes_speed_member_by_member() {
    let r = run("actions/group_change_speed", 0, None);
    for (i, s0) in [100.0, 85.0].into_iter().enumerate() {
        let name = format!("g.vehicles[{i}]");
        assert!((r.at(0.0, &name).s - s0).abs() < 1e-6);
        close(r.at(1.0, &name).speed, 15.0, "v(1)");
        close(r.at(2.0, &name).speed, 20.0, "v(2)");
    }
    let gap = r.at(2.0, "g.vehicles[0]").s - r.at(2.0, "g.vehicles[1]").s;
    close(gap, 15.0, "gap(2)");
    assert_eq!(r.phase("do.0"), (0.0, 2.0));
}

/// §8.8.2.3 `move()`: a vehicle moves as its modifiers say.
#[test]
fn move_changes_speed_as_its_modifiers_say() {
    let r = run("actions/move_vehicle", 0, None);
    let v = |t: f64| 10.0 + 2.0 * t.min(3.0);
    close(r.at(1.5, "ego").speed, 13.0, "v(1.5)");
    close(r.at(3.0, "ego").speed, 16.0, "v(3)");
    // 59 m exactly, and the lead 6 m/s · dt/2 of the engine's steps.
    close(20.0 + stepped(v, 0.0, 3.0), 59.0 + 0.15, "hand sum");
    close(r.at(3.0, "ego").s, 20.0 + stepped(v, 0.0, 3.0), "s(3)");
    assert_eq!(r.at(3.0, "ego").lane, -2);
    assert_eq!(r.phase("do"), (0.0, 3.0));
}

/// §8.9 acceleration(…, faster_than/slower_than: x): the actor's acceleration relative to x's
/// planned one (acceleration_relative.osc's comment: 10 -> 19 m/s at 3 m/s² over 0-3 s, 19 ->
/// 15 m/s at −1 m/s² over 3-7 s, 15 -> 23 m/s at 4 m/s² over 7-9 s, by hand).
#[test]
fn acceleration_relative_to_another_actor_follows_its_planned_acceleration() {
    let r = run("acceleration_relative", 0, None);
    let v = |t: f64| {
        if t <= 3.0 {
            10.0 + 3.0 * t
        } else if t <= 7.0 {
            19.0 - (t - 3.0)
        } else {
            15.0 + 4.0 * (t.min(9.0) - 7.0)
        }
    };
    close(r.at(1.5, "ego").speed, 14.5, "v(1.5)");
    close(r.at(3.0, "ego").speed, 19.0, "v(3)");
    close(r.at(5.0, "ego").speed, 17.0, "v(5)");
    close(r.at(7.0, "ego").speed, 15.0, "v(7)");
    close(r.at(5.0, "npc").speed, 10.0, "npc v(5)");
    // The exact integrals 93.5 m and 161.5 m plus the step lead: 3 m/s² · 3 s · dt/2, then
    // −1 m/s² · 4 s · dt/2.
    close(stepped(v, 0.0, 3.0), 43.5 + 0.225, "hand sum to 3 s");
    close(stepped(v, 0.0, 7.0), 111.5 + 0.225 - 0.1, "hand sum to 7 s");
    close(r.at(3.0, "ego").s, 50.0 + stepped(v, 0.0, 3.0), "s(3)");
    close(r.at(7.0, "ego").s, 50.0 + stepped(v, 0.0, 7.0), "s(7)");
    close(r.at(8.0, "ego").speed, 19.0, "v(8)");
    close(r.at(9.0, "ego").speed, 23.0, "v(9)");
    close(r.at(8.5, "npc").speed, 14.0, "npc v(8.5)");
    // + 4 m/s² · 2 s · dt/2 = 0.2 m.
    close(
        stepped(v, 0.0, 9.0),
        149.5 + 0.225 - 0.1 + 0.2,
        "hand sum to 9 s",
    );
    close(r.at(9.0, "ego").s, 50.0 + stepped(v, 0.0, 9.0), "s(9)");
}

/// acceleration_relative_changing.osc's comment, by hand: ego gets npc's -3 m/s² to 5 s,
/// then 0, from the engine's RelativeAccelerationAction.
/// Asserts ego's and npc's speeds at each (t, ego's, npc's).
fn ego_and_npc_speeds(r: &crate::support::Run, at: &[(f64, f64, f64)]) {
    for &(t, ego, npc) in at {
        close(r.at(t, "ego").speed, ego, &format!("ego v({t})"));
        close(r.at(t, "npc").speed, npc, &format!("npc v({t})"));
    }
}

#[test]
fn acceleration_the_same_as_one_that_changes_in_the_phase_follows_it() {
    let r = run("acceleration_relative_changing", 0, None);
    ego_and_npc_speeds(
        &r,
        &[
            (3.0, 10.0, 16.0),
            (4.0, 7.0, 13.0),
            (5.0, 4.0, 10.0),
            (6.0, 4.0, 10.0),
            (7.0, 4.0, 10.0),
            (8.0, 4.0, 10.0),
        ],
    );
    let v = |t: f64| match t {
        t if t <= 3.0 => 10.0,
        t if t <= 5.0 => 10.0 - 3.0 * (t - 3.0),
        _ => 4.0,
    };
    close(r.at(7.0, "ego").s, 50.0 + stepped(v, 0.0, 7.0), "s(7)");
    close(
        r.at(7.0, "ego").s,
        102.0 + ramp_lead(-3.0, 2.0),
        "s(7) by hand",
    );
}

/// acceleration_relative_first_phase.osc's comment, by hand: the same in ego's first phase,
/// ego written before npc (issue 27: it kept 10 m/s).
#[test]
fn acceleration_the_same_as_one_that_changes_in_the_first_phase_follows_it() {
    let r = run("acceleration_relative_first_phase", 0, None);
    ego_and_npc_speeds(
        &r,
        &[
            (0.0, 10.0, 16.0),
            (1.0, 7.0, 13.0),
            (2.0, 4.0, 10.0),
            (3.0, 4.0, 10.0),
            (4.0, 4.0, 10.0),
            (5.0, 4.0, 10.0),
        ],
    );
    let v = |t: f64| if t <= 2.0 { 10.0 - 3.0 * t } else { 4.0 };
    close(r.at(4.0, "ego").s, 50.0 + stepped(v, 0.0, 4.0), "s(4)");
    close(
        r.at(4.0, "ego").s,
        72.0 + ramp_lead(-3.0, 2.0),
        "s(4) by hand",
    );
    close(
        r.at(5.0, "ego").s,
        76.0 + ramp_lead(-3.0, 2.0),
        "s(5) by hand",
    );
}
