//! Lanes a lane section renumbers (ASAM OpenDRIVE 1.8 §11.5 lane linkage: a lane's
//! `<link><successor id=…>` names its continuation in the next lane section), read by the plan
//! where the engine has the actor: every lane the planner reads of an actor is its lane
//! followed along those links (`Track::lane_on`). On `tests/roads/lane_add_inner.xodr`; motions
//! worked by hand in the scenario files' comments.

use std::f64::consts::PI;

use crate::support::{phases_are, run_on};

/// Positions on a straight road in a lane: float round-off only.
const S_TOL: f64 = 1e-6;
/// change_position_renumbered.osc's worked integrals (midpoint rule, 100,000 points) against
/// the engine's steps of 0.05 s (m), as `run::position_actions` takes them.
const ROAD_TOL: f64 = 1e-4;

/// lateral_end_renumbered.osc: ego in lane -1 crosses s = 300 m into -2 (3.5 m wide); the
/// offset lateral(0.5m, measure_by: left_to_left, at: end) asks is 3.5/2 − 0.5 − 1 = 0.25 m
/// in that lane (before: in the new lane -1, under 2.744 m wide, a negative offset).
#[test]
fn a_lateral_position_is_measured_in_the_lane_a_lane_section_renumbered() {
    let r = run_on("links/lateral_end_renumbered", "lane_add_inner");
    phases_are(&r, &[("do.b", 10.0, 12.0), ("do.c", 12.0, 16.0)]);
    // The offset's sideways motion costs 0.001928 m along the lane (worked to 1e-6 m: the
    // engine's steps take the share of each step's mean, float round-off beside).
    let tol = |t: f64| if t > 10.0 { 1e-5 } else { S_TOL };
    for (t, x, y, lane) in [
        (10.0, 350.0, -3.5, -2),
        (12.0, 369.998072, -4.243915, -2),
        (16.0, 409.998072, -5.0, -2),
    ] {
        let p = r.at(t, "ego");
        assert!(
            (p.x - x).abs() < tol(t) && (p.y - y).abs() < tol(t) && p.lane == lane,
            "ego at {t} s: {p:?}, want ({x}, {y}) in lane {lane}"
        );
    }
}

/// change_position_renumbered.osc: ego in lane -3 (planned as -2 before s = 300 m) changes
/// into -2 on its way to the target, y = -8.75 + 3.5·(1 − cos(π·τ/T))/2 with T = 5.022425 s
/// (before: no action, ego stayed in -3).
#[test]
fn a_change_of_position_on_the_road_network_starts_from_the_lane_a_lane_section_renumbered() {
    let r = run_on("links/change_position_renumbered", "lane_add_inner");
    const T: f64 = 5.022425;
    let (s, e) = r.phase("do.b");
    assert!(
        (s - 16.0).abs() < 1e-9 && (e - 21.05).abs() < 1e-9,
        "[{s}, {e}]"
    );
    for t in [16.0, 17.0, 18.0, 19.0, 20.0, 21.0] {
        let want = -8.75 + 3.5 * (1.0 - (PI * (t - 16.0) / T).cos()) / 2.0;
        let p = r.at(t, "ego");
        assert!(
            (p.y - want).abs() < ROAD_TOL,
            "ego at {t} s: {p:?}, want y {want}"
        );
    }
    assert!((r.at(18.0, "ego").y + 7.550110).abs() < ROAD_TOL);
    let end = r.at(21.05, "ego");
    assert!((end.y + 5.25).abs() < S_TOL && end.lane == -2, "{end:?}");
}

/// same_lane_renumbered.osc: npc changes from -3 into -2 over [16, 20] s after both crossed
/// s = 300 m (planned in -2 before it); ego, lane(same_as: npc) at: all, follows: y = -8.75 +
/// 3.5·f for both, f = (1 − cos(π·τ/4))/2, τ = t − 16, the same lane at every step (-3 before
/// 18 s, -2 after). Before: refused, the plan saw no lane change of npc's.
#[test]
fn a_lane_same_as_another_that_changes_lane_after_a_renumbering_is_followed() {
    let r = run_on("links/same_lane_renumbered", "lane_add_inner");
    phases_are(&r, &[("do.both", 16.0, 20.0)]);
    let f = |t: f64| (1.0 - (PI * (t.clamp(16.0, 20.0) - 16.0) / 4.0).cos()) / 2.0;
    for k in 0..=80 {
        let t = 16.0 + k as f64 * crate::support::DT;
        let (ego, npc) = (r.at(t, "ego"), r.at(t, "npc"));
        let want = -8.75 + 3.5 * f(t);
        assert!((npc.y - want).abs() < S_TOL, "npc {t}: {npc:?}");
        assert!((ego.y - want).abs() < S_TOL, "ego {t}: {ego:?}");
        assert_eq!(ego.lane, npc.lane, "{t}: {ego:?} {npc:?}");
        if (t - 18.0).abs() > 0.025 {
            assert_eq!(ego.lane, if t < 18.0 { -3 } else { -2 }, "{t}: {ego:?}");
        }
    }
}

/// change_lane_across_renumbering.osc: a change of one lane to the left that starts in section
/// 0 (-2 into -1) and ends past s = 300 m, where -1 runs on into -2: by the action (ego, [2, 6]
/// s) and by the modifier (car, [6, 10] s), each then in lane(2) of section 1, -2, on its
/// centre y = -(w(x − 300) + 1.75), w(d) = 0.00105·d² − 0.000007·d³. Before: refused, the
/// track kept the id counted at the change's start (-1, section 1's new lane).
#[test]
fn a_lane_change_across_a_renumbering_ends_in_the_lane_its_target_runs_on_into() {
    let r = run_on("links/change_lane_across_renumbering", "lane_add_inner");
    phases_are(
        &r,
        &[
            ("do.0.b", 2.0, 6.0),
            ("do.0.c", 6.0, 8.0),
            ("do.1.e", 6.0, 10.0),
            ("do.1.f", 10.0, 12.0),
        ],
    );
    let w = |d: f64| 0.00105 * d * d - 0.000007 * d * d * d;
    let e = r.at(6.0, "ego");
    assert!((e.x - 329.81).abs() < 0.01, "{e:?}");
    assert!((w(29.810488) - 0.747658).abs() < 1e-6);
    for (who, from, to) in [("ego", 6.0, 8.0), ("car", 10.0, 12.0)] {
        let mut t = from;
        while t <= to + 1e-9 {
            let p = r.at(t, who);
            let y = -(w(p.x - 300.0) + 1.75);
            assert!(
                p.lane == -2 && (p.y - y).abs() < S_TOL,
                "{who} at {t}: {p:?}, want y {y} in lane -2"
            );
            t += crate::support::DT;
        }
    }
}
