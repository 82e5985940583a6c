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

/// An action's own `duration:` is its length: assign_position and assign_speed given one last
/// it (assign_with_duration.osc's comment, by hand).
#[test]
fn an_action_that_ends_at_once_given_a_duration_lasts_it() {
    let r = run("actions/assign_with_duration", 0, None);
    assert_eq!(r.phase("do.1"), (2.0, 5.0));
    close(r.at(2.05, "ego").x, 120.0, "x(2.05)");
    let end = r.at(5.0, "ego");
    close(end.x, 149.5, "x(5)");
    close(end.y, -1.25, "y(5)");
    assert_eq!(end.lane, -1);
    assert_eq!(r.phase("do.2"), (5.0, 7.0));
    close(r.at(5.05, "ego").speed, 20.0, "v(5.05)");
    close(r.at(7.0, "ego").x, 189.5, "x(7)");
    assert_eq!(r.phase("do.3"), (7.0, 8.0));
    close(r.at(8.0, "ego").x, 209.5, "x(8)");
}

/// §8.8.2.4 with a route_point (assign_position_route.osc's comment, by hand).
#[test]
fn assign_position_to_a_route_point_on_the_runtimes_route() {
    let r = run("actions/assign_position_route", 0, None);
    close(r.at(2.0, "ego").x, 50.0, "x(2) before the jump");
    close(r.at(2.0, "ego").y, -8.75, "y(2) before the jump");
    assert_eq!(r.phase("do.1"), (2.0, 2.0));
    close(r.at(2.05, "ego").x, 150.0, "x(2.05)");
    close(r.at(2.05, "ego").y, -5.25, "y(2.05)");
    let after = r.at(3.0, "ego");
    close(after.x, 159.5, "x(3)");
    assert_eq!(after.lane, -2);
    let end = r.at(4.0, "ego");
    close(end.x, 169.5, "x(4)");
    close(end.y, -5.25, "y(4)");
    close(end.speed, 10.0, "v(4)");
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

/// change_position_then_lane.osc's comment, by hand: the line's heading atan(7/24) while on
/// it, the lane's (0 on the straight road) where it ends and after (issue 27: it kept the
/// line's, driving on crabwise).
#[test]
fn after_a_straight_change_position_the_actor_faces_along_its_lane() {
    let r = run("actions/change_position_then_lane", 0, None);
    close(r.at(1.25, "ego").h, (7.0f64 / 24.0).atan(), "h(1.25)");
    for (t, x) in [(2.5, 54.0), (3.0, 59.0), (3.5, 64.0)] {
        let ego = r.at(t, "ego");
        close(ego.x, x, &format!("x({t})"));
        close(ego.y, -1.75, &format!("y({t})"));
        close(ego.h, 0.0, &format!("h({t})"));
        assert_eq!(ego.lane, -1, "lane({t})");
    }
}

#[test]
fn follow_trajectory_reaches_each_point_at_its_time_stamp() {
    reaches_each_point_at_its_time_stamp("actions/follow_trajectory");
}

/// follow_trajectory.osc's trajectory followed by `name`: each point at its time stamp, by hand
/// (follow_trajectory.osc).
pub(crate) fn reaches_each_point_at_its_time_stamp(name: &str) {
    let r = run(name, 0, None);
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

/// The Hermite curve's closed forms (B(1/2), its heading) and the Gauss–Legendre length are
/// worked to 1e-4 m in the scenarios' comments; the engine's NURBS arc-length table inverts s
/// to 1e-10 m.
const CURVE_TOL: f64 = 1e-3;

#[test]
fn change_position_smooth_follows_the_hermite_curve_at_its_speed() {
    let r = run("actions/change_position_smooth", 0, None);
    // At 2.0 s ego has come 20 m, 0.0917 m short of the mid-point (40, -7) along the heading
    // 0.13077 rad there (the curve is straight to within 1e-4 m over 0.09 m).
    let (h, back) = (0.13077f64, 0.0917);
    let at2 = r.at(2.0, "ego");
    assert!(
        (at2.x - (40.0 - back * h.cos())).abs() < CURVE_TOL,
        "x(2) = {}",
        at2.x
    );
    assert!(
        (at2.y - (-7.0 - back * h.sin())).abs() < CURVE_TOL,
        "y(2) = {}",
        at2.y
    );
    assert!((at2.h - h).abs() < CURVE_TOL, "h(2) = {}", at2.h);
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < 1e-9 && (e - 4.05).abs() < 1e-9, "{s} {e}");
    let end = r.at(4.05, "ego");
    assert!((end.y + 5.25).abs() < CURVE_TOL, "y(4.05) = {}", end.y);
    assert!(end.h.abs() < CURVE_TOL, "h(4.05) = {}", end.h);
    assert_eq!(end.lane, -2);
}

/// The hand-worked motion of follow_trajectory_smooth.osc (and of the relative trajectory that
/// resolves to it).
fn check_smooth_trajectory(name: &str) {
    let r = run(name, 0, None);
    for (t, x, y, h) in [
        (2.0, 40.0, -7.0, 0.13077),
        (4.0, 60.0, -5.25, 0.0),
        (6.0, 80.0, -5.25, 0.0),
        (8.0, 100.0, -5.25, 0.0),
    ] {
        let ego = r.at(t, "ego");
        assert!((ego.x - x).abs() < CURVE_TOL, "x({t}) = {}", ego.x);
        assert!((ego.y - y).abs() < CURVE_TOL, "y({t}) = {}", ego.y);
        assert!((ego.h - h).abs() < CURVE_TOL, "h({t}) = {}", ego.h);
    }
    assert_eq!(r.at(8.0, "ego").lane, -2);
    assert!((r.at(7.0, "ego").speed - 10.0).abs() < CURVE_TOL);
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < 1e-9 && (e - 8.0).abs() < 1e-9, "{s} {e}");
}

#[test]
fn follow_trajectory_smooth_passes_each_point_with_its_heading_at_its_time() {
    check_smooth_trajectory("actions/follow_trajectory_smooth");
}

#[test]
fn a_relative_trajectory_in_the_actors_frame_is_the_absolute_one() {
    check_smooth_trajectory("actions/relative_trajectory");
}

#[test]
fn a_relative_trajectory_in_road_coordinates_of_another_actor() {
    follows_lead_road_relative("actions/relative_trajectory_road");
}

/// ego's follow_trajectory through (20, -8.75), (60, -5.25), (100, -5.25) at 0, 4, 8 s, lead's
/// road coordinates at the start (s 40 m, lane -2) moved by (-20, -3.5), (20, 0), (60, 0)
/// (relative_trajectory_road.osc, by hand).
pub(crate) fn follows_lead_road_relative(name: &str) {
    let r = run(name, 0, None);
    for (t, x, y) in [
        (2.0, 40.0, -7.0),
        (4.0, 60.0, -5.25),
        (6.0, 80.0, -5.25),
        (8.0, 100.0, -5.25),
    ] {
        let ego = r.at(t, "ego");
        close(ego.x, x, &format!("x({t})"));
        close(ego.y, y, &format!("y({t})"));
    }
    assert_eq!(r.at(8.0, "ego").lane, -2);
    close(r.at(8.0, "lead").x, 120.0, "lead x(8)");
    let (s, e) = r.phase("do.follow");
    assert!(s.abs() < 1e-9 && (e - 8.0).abs() < 1e-9, "{s} {e}");
}

/// How far the engine's pure pursuit (look-ahead 5.13 m) may lag the path across it on the
/// S-curve (m): the curve's radius is 76.8 m or more, so the goal point's chord departs from
/// it by L²/(2·76.8) < 0.2 m ahead, of which the pursuit arc keeps a tenth (the run: 1.2 cm).
const PURSUIT_TOL: f64 = 0.02;

#[test]
fn follow_path_steers_along_a_path_made_by_create_path() {
    follows_the_s_curve("actions/follow_path");
}

/// drive() with along(r) of a path (issue 27; was an error at the argument): the same run as
/// follow_path's of the same path (along_path.osc, by hand as follow_path.osc).
#[test]
fn a_drive_along_a_path_follows_it_as_follow_path_does() {
    follows_the_s_curve("actions/along_path");
}

/// drive() with along(m.resolve_relative_path(rp, npc, object_relative)): follow_path's
/// relative path against npc (issue 27). along_relative_path.osc, by hand: the line (20, -5.25)
/// -> (60, -5.25), x = 20 + 10 t at 0, 2 and 4 s, y = -5.25 m.
#[test]
fn a_drive_along_a_resolved_relative_path_follows_it_against_its_reference() {
    follows_the_line_beside_npc("actions/along_relative_path", "do.1");
}

/// ego along the line (20, -5.25) -> (60, -5.25) at 10 m/s from 0 s, its phase `phase` ending
/// at the line's end, 4 s (along_relative_path.osc, by hand).
pub(crate) fn follows_the_line_beside_npc(name: &str, phase: &str) {
    let r = run(name, 0, None);
    for t in [0.0, 2.0, 4.0] {
        let p = r.at(t, "ego");
        assert!(
            (p.x - (20.0 + 10.0 * t)).abs() < 1e-6 && (p.y + 5.25).abs() < 1e-6,
            "at {t} s: {p:?}"
        );
    }
    let (s, e) = r.phase(phase);
    assert!(
        s.abs() < 1e-9 && (4.0..=4.05 + 1e-9).contains(&e),
        "{s} {e}"
    );
}

/// walk() with along(p): a person follows the path as follow_path does (walk_along_path.osc,
/// by hand: (20, -1.75) -> (30, -1.75) at 1 m/s, (25, -1.75) at 5 s, the end at 10 s).
#[test]
fn a_person_walks_along_a_path() {
    let r = run("actions/walk_along_path", 0, None);
    for (t, x) in [(0.0, 20.0), (5.0, 25.0)] {
        let p = r.at(t, "alice");
        assert!(
            (p.x - x).abs() < 1e-6 && (p.y + 1.75).abs() < 1e-6,
            "at {t} s: {p:?}"
        );
    }
    let (s, e) = r.phase("do");
    assert!(
        s.abs() < 1e-9 && (10.0..=10.05 + 1e-9).contains(&e),
        "{s} {e}"
    );
}

/// A path along another action, or at: start only: errors at the along.
#[test]
fn a_path_along_another_action_or_at_one_moment_is_an_error_at_the_along() {
    for (name, at, what) in [
        ("err_along_path_action", "12:13", "found another action"),
        ("err_along_path_at", "11:13", "found at: start or end"),
    ] {
        let e = crate::support::error(&format!("actions/{name}"));
        assert!(
            e.starts_with("expected drive(), move() or walk() with along(…) of a path at: all")
                && e.contains(what)
                && e.ends_with(&format!("{name}.osc:{at}")),
            "{e}"
        );
    }
}

/// follow_path.osc's S-curve driven by `name`, checked by hand (follow_path.osc).
pub(crate) fn follows_the_s_curve(name: &str) {
    let r = run(name, 0, None);
    // At 2 s: 20 m along the S-curve, as in change_position_smooth: (39.909, -7.012), heading
    // 0.13077 rad.
    let mid = r.at(2.0, "ego");
    assert!((mid.x - 39.909).abs() < PURSUIT_TOL, "x(2) = {}", mid.x);
    assert!((mid.y + 7.012).abs() < PURSUIT_TOL, "y(2) = {}", mid.y);
    assert!((mid.h - 0.13077).abs() < PURSUIT_TOL, "h(2) = {}", mid.h);
    // On the straight part the pursuit is back on the line: at 8 s 80 m of the 80.1833 m
    // path are driven, x = 100 - 0.1833.
    let at8 = r.at(8.0, "ego");
    assert!((at8.x - 99.8167).abs() < CURVE_TOL, "x(8) = {}", at8.x);
    assert!((at8.y + 5.25).abs() < CURVE_TOL, "y(8) = {}", at8.y);
    assert!(at8.h.abs() < CURVE_TOL, "h(8) = {}", at8.h);
    assert_eq!(at8.lane, -2);
    assert!((at8.speed - 10.0).abs() < 1e-9, "v(8) = {}", at8.speed);
    // The end is reached at 8.018 s, in the step to 8.05 s, which ends the phase.
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < 1e-9 && (e - 8.05).abs() < 1e-9, "{s} {e}");
}

/// The scenario's hand-worked integrals (midpoint rule, 100,000 points) against the engine's
/// steps of 0.05 s (m).
const ROAD_TOL: f64 = 1e-4;

#[test]
fn change_position_on_the_road_network_changes_lane_on_the_way() {
    let r = run("actions/change_position_on_road", 0, None);
    for (t, x, y) in [
        (1.0, 29.98311, -8.24199),
        (2.0, 39.90654, -7.01291),
        (4.0, 59.81131, -5.25019),
    ] {
        let ego = r.at(t, "ego");
        assert!((ego.x - x).abs() < ROAD_TOL, "x({t}) = {}", ego.x);
        assert!((ego.y - y).abs() < ROAD_TOL, "y({t}) = {}", ego.y);
    }
    assert_eq!(r.at(4.0, "ego").lane, -2);
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < 1e-9 && (e - 4.05).abs() < 1e-9, "{s} {e}");
    let end = r.at(4.05, "ego");
    assert!((end.x - 60.3113).abs() < ROAD_TOL, "x(4.05) = {}", end.x);
    assert!((end.y + 5.25).abs() < ROAD_TOL, "y(4.05) = {}", end.y);
}

#[test]
fn replay_path_follows_the_polyline_exactly_round_its_corner() {
    let r = run("actions/replay_path", 0, None);
    let h = (7.0f64 / 24.0).atan();
    for (t, x, y, hh) in [
        (1.25, 32.0, -5.25, h),
        (2.5, 44.0, -1.75, h),
        (5.0, 69.0, -1.75, 0.0),
        (7.5, 94.0, -1.75, 0.0),
    ] {
        let ego = r.at(t, "ego");
        close(ego.x, x, &format!("x({t})"));
        close(ego.y, y, &format!("y({t})"));
        if t != 2.5 {
            close(ego.h, hh, &format!("h({t})"));
        }
    }
    assert_eq!(r.at(7.5, "ego").lane, -1);
    // The end, 75 m at 10 m/s, falls on the step at 7.5 s, which ends the action and its phase.
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < 1e-9 && (e - 7.5).abs() < 1e-9, "{s} {e}");
}

#[test]
fn replay_trajectory_follows_it_beyond_the_vehicles_limits() {
    let r = run("actions/replay_trajectory", 0, None);
    close(r.at(1.0, "ego").x, 30.0, "x(1)");
    close(r.at(2.5, "ego").x, 90.0, "x(2.5)");
    close(r.at(3.0, "ego").x, 140.0, "x(3)");
    close(r.at(3.0, "ego").y, -8.75, "y(3)");
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < 1e-9 && (e - 3.0).abs() < 1e-9, "{s} {e}");
}

#[test]
fn a_trajectory_from_its_start_offset_to_its_end_offset() {
    let r = run("actions/trajectory_offsets", 0, None);
    for (t, x, y) in [
        (0.0, 30.0, -8.75),
        (1.0, 40.0, -8.75),
        (3.0, 60.0, -8.75),
        (4.0, 69.6, -5.95),
        (4.25, 72.0, -5.25),
    ] {
        let ego = r.at(t, "ego");
        close(ego.x, x, &format!("x({t})"));
        close(ego.y, y, &format!("y({t})"));
    }
    assert_eq!(r.at(4.25, "ego").lane, -2);
    let (s, e) = r.phase("do.0");
    assert!(s.abs() < 1e-9 && (e - 4.25).abs() < 1e-9, "{s} {e}");
}
