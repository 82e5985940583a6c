//! The §8.8.2 actions that put an actor somewhere (`assign_position`) on
//! `tests/roads/straight.xodr` (road 1 along +x from the origin; lanes -3, -2, -1 with centres
//! at y = -8.75, -5.25, -1.75 m): positions against each scenario's comment.

use crate::support::run;

/// Positions are the teleport's target and constant-speed steps from it.
const TOL: f64 = 1e-6;

fn close(got: f64, want: f64, what: &str) {
    assert!((got - want).abs() < TOL, "{what}: {got} vs {want}");
}

#[test]
fn assign_position_to_an_odr_point_ends_at_once() {
    let r = run("actions/assign_position_odr", 0, None);
    close(r.at(2.0, "ego").x, 50.0, "x(2) before the jump");
    close(r.at(1.0, "ego").y, -8.75, "y(1)");
    assert_eq!(r.phase("do.1"), (2.0, 2.0));
    close(r.at(2.05, "ego").x, 120.0, "x(2.05)");
    let after = r.at(3.0, "ego");
    close(after.x, 129.5, "x(3)");
    close(after.y, -1.25, "y(3)");
    assert_eq!(after.lane, -1);
    close(r.at(4.0, "ego").x, 139.5, "x(4)");
    assert_eq!(r.phase("do.2"), (2.0, 4.0));
}

#[test]
fn assign_position_to_a_world_point() {
    let r = run("actions/assign_position_3d", 0, None);
    let ego = r.at(1.0, "ego");
    close(ego.x, 200.0, "x(1)");
    close(ego.y, -5.0, "y(1)");
    close(ego.speed, 0.0, "v(1)");
    assert_eq!(ego.lane, -2);
}

#[test]
fn assign_orientation_turns_the_actor_where_it_is() {
    let r = run("actions/assign_orientation", 0, None);
    close(r.at(1.0, "ego").h, 0.0, "h(1)");
    assert_eq!(r.phase("do.1"), (1.0, 1.0));
    for t in [1.05, 2.0] {
        let ego = r.at(t, "ego");
        close(ego.h, 0.5, &format!("h({t})"));
        close(ego.x, 50.0, &format!("x({t})"));
        close(ego.y, -5.25, &format!("y({t})"));
    }
}

#[test]
fn change_position_moves_along_a_straight_line_and_ends_there() {
    let r = run("actions/change_position", 0, None);
    let mid = r.at(1.25, "ego");
    close(mid.x, 42.0, "x(1.25)");
    close(mid.y, -5.25, "y(1.25)");
    close(mid.h, (7.0f64 / 24.0).atan(), "h(1.25)");
    let end = r.at(2.5, "ego");
    close(end.x, 54.0, "x(2.5)");
    close(end.y, -1.75, "y(2.5)");
    assert_eq!(end.lane, -1);
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < 1e-9 && (e - 2.5).abs() < 1e-9, "{s} {e}");
}

#[test]
fn follow_trajectory_reaches_each_point_at_its_time_stamp() {
    let r = run("actions/follow_trajectory", 0, None);
    close(r.at(1.0, "ego").x, 30.0, "x(1)");
    close(r.at(1.0, "ego").y, -8.75, "y(1)");
    close(r.at(2.0, "ego").x, 40.0, "x(2)");
    let mid = r.at(3.0, "ego");
    close(mid.x, 52.0, "x(3)");
    close(mid.y, -5.25, "y(3)");
    let end = r.at(4.0, "ego");
    close(end.x, 64.0, "x(4)");
    close(end.y, -1.75, "y(4)");
    assert_eq!(end.lane, -1);
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < 1e-9 && (e - 4.0).abs() < 1e-9, "{s} {e}");
}
