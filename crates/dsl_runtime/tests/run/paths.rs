//! Paths through points of the road network as along's routes (issue 27; ASAM OpenSCENARIO
//! DSL 2.1 §8.12.2.1.11 `create_path_odr_points`, §8.12.2.1.12 `create_path_route_points`):
//! the points placed on the network before the plan, the path of their world points followed
//! as `follow_path` follows one. Motions worked by hand in the scenario files' comments.

use crate::support::{error_on, run, run_on};

/// A path along a lane's centre heading as the actor does: float round-off only.
const S_TOL: f64 = 1e-6;

#[test]
fn a_path_through_odr_and_route_points_is_the_path_of_their_world_points() {
    let r = run("paths/path_odr_points", 0, None);
    for (t, x) in [(0.0, 20.0), (2.0, 40.0), (4.0, 60.0)] {
        let p = r.at(t, "ego");
        assert!(
            (p.x - x).abs() < S_TOL && (p.y + 5.25).abs() < S_TOL,
            "ego at {t} s: {p:?}"
        );
    }
    for (t, x) in [(0.0, 40.0), (2.0, 50.0), (6.0, 70.0), (12.0, 100.0)] {
        let p = r.at(t, "npc");
        assert!(
            (p.x - x).abs() < S_TOL && (p.y + 8.75).abs() < S_TOL,
            "npc at {t} s: {p:?}"
        );
    }
    // Each drive ends at the step that reaches its path's end (4 s, 12 s).
    for (phase, end) in [("do.0", 4.0), ("do.1", 12.0)] {
        let (s, e) = r.phase(phase);
        assert!(
            s.abs() < 1e-9 && (end..=end + 0.05 + 1e-9).contains(&e),
            "{phase}: {s} {e}"
        );
    }
}

/// follow_path(absolute:) takes such a path (§8.8.2.16: a path); smooth, its points heading
/// along their lanes: follow_path.osc's S-curve (follow_path_odr.osc).
#[test]
fn follow_path_follows_a_path_through_odr_points() {
    crate::position_actions::follows_the_s_curve("paths/follow_path_odr");
}

/// follow_trajectory(absolute:) of map.create_trajectory_odr_points(…) (§8.12.2.1.14): odr
/// points whose world points are follow_trajectory.osc's, with its stamps: its motion
/// (follow_trajectory_odr.osc).
#[test]
fn follow_trajectory_follows_a_trajectory_through_odr_points() {
    crate::position_actions::reaches_each_point_at_its_time_stamp("paths/follow_trajectory_odr");
}

/// follow_path's steering within the vehicle's limits from the lane's heading onto a chord
/// 0.179 rad off it (m; as `position_actions`' S-curve).
const PURSUIT_TOL: f64 = 0.02;

#[test]
fn a_path_through_odr_points_on_a_bend_is_the_chord_between_their_world_points() {
    let r = run_on("paths/path_odr_bend", "bend");
    let p = r.at(0.0, "ego");
    assert!(
        (p.x - 80.0).abs() < S_TOL && (p.y + 1.75).abs() < S_TOL,
        "{p:?}"
    );
    let p = r.at(3.5, "ego");
    assert!(
        (p.x - 114.4398).abs() < PURSUIT_TOL && (p.y - 4.4869).abs() < PURSUIT_TOL,
        "at 3.5 s: {p:?}"
    );
    // The drive ends at the step that reaches the path's end, 6.990 s.
    let (s, e) = r.phase("do");
    assert!(s.abs() < 1e-9 && (6.99..=7.05).contains(&e), "{s} {e}");
    let p = r.at(e, "ego");
    assert!(
        (p.x - 148.7815).abs() < 0.2 && (p.y - 10.7060).abs() < 0.2,
        "at {e} s: {p:?}"
    );
}

#[test]
fn a_path_off_the_network_or_through_a_point_it_lacks_is_an_error_at_its_place() {
    let e = error_on("paths/err_path_off_road", "bend");
    assert!(
        e.starts_with("expected the path's line on the road network (on_road_network: true")
            && e.ends_with("err_path_off_road.osc:10:9"),
        "{e}"
    );
    let e = crate::support::error("paths/err_path_point");
    assert!(
        e.starts_with(
            "expected point 2 of the path (road 1, lane -4, s = 60 m, t = 0 m) on the road network"
        ) && e.ends_with("err_path_point.osc:7:9"),
        "{e}"
    );
    let e = crate::support::error("paths/err_trajectory_stamps");
    assert!(
        e.starts_with("expected two or more points with as many rising time stamps, found 3 points and 2 time stamps")
            && e.ends_with("err_trajectory_stamps.osc:8:40"),
        "{e}"
    );
    let e = crate::support::error("paths/err_path_points");
    assert!(
        e.starts_with("expected a list of two or more route_points")
            && e.contains("found 1 point at")
            && e.ends_with("err_path_points.osc:7:42"),
        "{e}"
    );
}

/// A relative path of route points (§8.12.33 `relative_path_st`), given by the keeps of its
/// declaration (a list, or point by point): their s and t from the reference's road
/// coordinates (`road_relative`, follow_path) or from its lane's centre (`lane_relative`,
/// resolve_relative_path): both the line (20, -5.25) -> (60, -5.25) beside npc of
/// along_relative_path.osc (relative_path_st.osc, along_relative_st_lane.osc, by hand).
#[test]
fn a_relative_path_of_route_points_is_placed_in_the_references_road_coordinates() {
    crate::position_actions::follows_the_line_beside_npc("paths/relative_path_st", "do.1");
    crate::position_actions::follows_the_line_beside_npc("paths/along_relative_st_lane", "do.1");
}

/// relative_path_st_opposite.osc: relative_path_st.osc's route points on `theirs`, which
/// routes_are_opposite binds to the plan's roads against s: (30, 3.5) and (-10, 3.5) along
/// `theirs` and to its left are (-30, -3.5) and (10, -3.5) of the road from npc's (50, -1.75),
/// the same line (20, -5.25) -> (60, -5.25) (by hand). Before, the binding was not read and
/// the points lay at (80, 1.75) and (40, 1.75).
#[test]
fn a_relative_route_point_on_a_route_the_map_binds_is_read_along_it() {
    crate::position_actions::follows_the_line_beside_npc("paths/relative_path_st_opposite", "do.1");
}

/// relative_st_in_sequence.osc on road_link_unequal_number_of_lanes0.xodr, by hand: route
/// points (-30, 3) and (70, 3) along b, which routes_are_in_sequence binds after a, from npc's
/// (50, -4.5) (lane -2, the lane along a that runs on onto b): s continues from road 1 onto
/// road 2, the line (20, -1.5) -> (120, -1.5), road 2's s = 20 m at its end; ego x = 20 + 10 t,
/// y = -1.5 m (lane -1 of road 1 to 8 s, of road 2 after), the phase ending at the line's end,
/// 10 s. Before, an error at the path (20:35).
#[test]
fn a_relative_route_point_on_a_road_field_in_sequence_runs_on_along_the_sequence() {
    let r = crate::support::run_on(
        "paths/relative_st_in_sequence",
        "road_link_unequal_number_of_lanes0",
    );
    for (t, road) in [(0.0, "1"), (5.0, "1"), (7.5, "1"), (8.5, "2"), (9.5, "2")] {
        let p = r.at(t, "ego");
        assert!(
            (p.x - (20.0 + 10.0 * t)).abs() < 1e-6
                && (p.y + 1.5).abs() < 1e-6
                && p.lane == -1
                && p.road == road,
            "ego at {t} s: {p:?}"
        );
    }
    let (s, e) = r.phase("do.1");
    assert!(
        s.abs() < 1e-9 && (10.0..=10.05 + 1e-9).contains(&e),
        "{s} {e}"
    );
}

/// A relative trajectory of odr points (§8.12.41 `relative_trajectory_odr`): each in its
/// lane, s from lead's at the start: relative_trajectory_road.osc's trajectory and motion
/// (relative_trajectory_odr.osc, by hand).
#[test]
fn a_relative_trajectory_of_odr_points_is_placed_in_their_lanes_from_the_references_s() {
    crate::position_actions::follows_lead_road_relative("paths/relative_trajectory_odr");
}

#[test]
fn relative_route_points_in_another_frame_or_missing_are_errors_at_their_place() {
    let e = crate::support::error("paths/err_relative_st_object");
    assert!(
        e.starts_with(
            "expected road_relative or lane_relative for a relative path of route or odr points"
        ) && e.contains("found object_relative")
            && e.ends_with("err_relative_st_object.osc:16:66"),
        "{e}"
    );
    let e = crate::support::error("paths/err_relative_st_missing");
    assert!(
        e.starts_with("expected point 1 of `rp`")
            && e.ends_with("err_relative_st_missing.osc:15:35"),
        "{e}"
    );
    // A route the map makes in create_route_point: a relative point's s and t are along the
    // plan's roads from the reference's, not along it (issue 27: it was not read).
    let e = crate::support::error("paths/err_relative_st_route");
    assert!(
        e.starts_with("expected a route the runtime chooses (a `route` field nothing defines: the plan's roads) as the `route` of create_route_point(route, s, t), point 0 of the relative `rp`, found a route the map makes")
            && e.ends_with("err_relative_st_route.osc:11:51"),
        "{e}"
    );
}
