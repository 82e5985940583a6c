//! The §8.8.3 actions that control the lateral position (`change_lane`, `follow_lane`) on
//! `tests/roads/straight.xodr` (lanes -3, -2, -1 with centres at y = -8.75, -5.25, -1.75 m):
//! lateral positions against the closed forms of each scenario's comment, phase ends where the
//! action ends.

use std::f64::consts::PI;

use crate::support::run;

/// Lateral positions are closed forms of the step times.
const Y_TOL: f64 = 1e-6;
/// Phase ends are step times.
const T_TOL: f64 = 1e-9;

fn close(got: f64, want: f64, what: &str) {
    assert!((got - want).abs() < Y_TOL, "{what}: {got} vs {want}");
}

fn phase(r: &crate::support::Run, path: &str, start: f64, end: f64) {
    let (a, b) = r.phase(path);
    assert!(
        (a - start).abs() < T_TOL && (b - end).abs() < T_TOL,
        "{path}: {a} {b}"
    );
}

#[test]
fn change_lane_at_a_rate_ends_in_the_target_lane() {
    let r = run("actions/change_lane_rate", 0, None);
    close(r.at(0.0, "ego").y, -8.75, "y(0)");
    close(r.at(2.0, "ego").y, -7.0, "y(2)");
    let end = r.at(4.0, "ego");
    close(end.y, -5.25, "y(4)");
    assert_eq!(end.lane, -2);
    phase(&r, "do.0", 0.0, 4.0);
    phase(&r, "do.1", 4.0, 5.0);
    close(r.at(5.0, "ego").y, -5.25, "y(5)");
}

#[test]
fn change_lane_with_defaults_is_sinusoidal_at_one_metre_per_second() {
    let r = run("actions/change_lane_default", 0, None);
    let span = PI * 3.5 / 2.0;
    let y = |t: f64| -8.75 + 3.5 * (1.0 - (PI * t / span).cos()) / 2.0;
    for t in [1.0, 2.75, 4.0] {
        close(r.at(t, "ego").y, y(t), &format!("y({t})"));
    }
    assert!((y(span / 2.0) + 7.0).abs() < 1e-12, "hand mid-point");
    // The phase ends in the first step at or after T = 5.4978 s.
    phase(&r, "do", 0.0, 5.5);
    let end = r.at(5.5, "ego");
    close(end.y, -5.25, "y(5.5)");
    assert_eq!(end.lane, -2);
}

#[test]
fn change_lane_beside_a_reference_with_an_offset() {
    let r = run("actions/change_lane_reference", 0, None);
    close(r.at(0.0, "npc").y, -5.25, "npc y");
    let y = |t: f64| -8.75 + 7.5 * (1.0 - (PI * t / 5.0).cos()) / 2.0;
    close(r.at(1.0, "ego").y, y(1.0), "y(1)");
    close(r.at(2.5, "ego").y, -5.0, "y(2.5)");
    let end = r.at(5.0, "ego");
    close(end.y, -1.25, "y(5)");
    assert_eq!(end.lane, -1);
    phase(&r, "do.0", 0.0, 5.0);
}

#[test]
fn follow_lane_moves_to_its_offset_and_holds_it() {
    let r = run("actions/follow_lane_offset", 0, None);
    close(r.at(0.0, "ego").y, -5.25, "y(0)");
    close(r.at(1.0, "ego").y, -5.0, "y(1)");
    close(r.at(2.0, "ego").y, -4.75, "y(2)");
    let end = r.at(6.0, "ego");
    close(end.y, -4.75, "y(6)");
    assert_eq!(end.lane, -2);
    phase(&r, "do", 0.0, 6.0);
}

/// The group form: each member does the action (docs/dsl.md).
#[test]
fn a_group_changes_lane_member_by_member() {
    let r = run("actions/group_change_lane", 0, None);
    for name in ["g.vehicles[0]", "g.vehicles[1]"] {
        close(r.at(2.0, name).y, -7.0, "y(2)");
        let end = r.at(4.0, name);
        close(end.y, -5.25, "y(4)");
        assert_eq!(end.lane, -2);
    }
    phase(&r, "do", 0.0, 4.0);
}

#[test]
fn change_lane_asap_is_at_the_lateral_limit() {
    let r = run("actions/change_lane_asap", 0, None);
    let span = PI * (3.5f64 / 20.0).sqrt();
    let y = |t: f64| -8.75 + 3.5 * (1.0 - (PI * t / span).cos()) / 2.0;
    // Peak lateral acceleration of the sinusoid: the vehicle's 10 m/s².
    assert!((PI * PI * 3.5 / (2.0 * span * span) - 10.0).abs() < 1e-9);
    for t in [0.3, 0.65, 1.0] {
        close(r.at(t, "ego").y, y(t), &format!("y({t})"));
    }
    phase(&r, "do.0", 0.0, 1.35);
    close(r.at(1.35, "ego").y, -5.25, "y(1.35)");
    phase(&r, "do.1", 1.35, 2.35);
}

/// change_lane_target.osc with `seed`: ego's lane at 4 s (the drawn l), after checking its
/// motion against the scenario's closed form for that lane.
fn change_lane_to_the_drawn_lane(seed: u64) -> i32 {
    let r = run("actions/change_lane_target", seed, None);
    let lane = r.at(4.0, "ego").lane;
    let delta = match lane {
        -3 => -3.5,
        -1 => 3.5,
        other => panic!("seed {seed}: drawn lane {other}, not -3 or -1"),
    };
    let y = |t: f64| -5.25 + delta * (1.0 - (PI * t / 4.0).cos()) / 2.0;
    close(r.at(0.0, "ego").y, -5.25, "y(0)");
    close(r.at(1.0, "ego").y, y(1.0), "y(1)");
    close(
        r.at(2.0, "ego").y,
        -5.25 + delta / 2.0,
        "y(2), the mid-point",
    );
    close(r.at(4.0, "ego").y, -5.25 + delta, "y(4)");
    phase(&r, "do.0", 0.0, 4.0);
    phase(&r, "do.1", 4.0, 6.0);
    let end = r.at(6.0, "ego");
    close(
        end.y,
        -5.25 + delta,
        "y(6): follow_lane(target: l) drives on in l",
    );
    assert_eq!(end.lane, lane);
    lane
}

#[test]
fn change_lane_to_a_lane_field_drawn_from_the_seed() {
    let lanes: Vec<i32> = (0..8).map(change_lane_to_the_drawn_lane).collect();
    // Both legal lanes are reached by some seed, and a seed draws the same lane again.
    assert!(lanes.contains(&-3) && lanes.contains(&-1), "{lanes:?}");
    assert_eq!(change_lane_to_the_drawn_lane(5), lanes[5]);
}
