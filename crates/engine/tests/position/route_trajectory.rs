//! RoutePosition (OpenSCENARIO 1.3 §7.5, InRoutePosition), TrajectoryPosition (§7.6, 1.1+)
//! hand-computed on esmini's straight_500m.xodr (road "1" along +x; lane −1
//! centre at t = −1.535 driven towards +s, lane 1 at t = 1.535 driven towards −s).

use crate::condition_support;

use std::f64::consts::{FRAC_PI_2, PI};

use condition_support::{at, corpus_road, FakeWorld};
use engine::position::{resolve, PositionErrorKind};
use scenario::{
    InRoutePosition, PositionKind, Route, RouteStrategy, Shape, Trajectory, Vertex, Waypoint,
};

/// Tolerance of positions computed in closed form (m, rad).
const TOL: f64 = 1e-6;

fn straight() -> FakeWorld {
    FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"))
}

fn lane_waypoint(lane: &str, s: f64) -> Waypoint {
    Waypoint {
        route_strategy: RouteStrategy::Shortest,
        position: at(PositionKind::Lane {
            road_id: "1".into(),
            lane_id: lane.into(),
            s,
            offset: None,
            orientation: None,
        }),
    }
}

fn route(lane: &str, from: f64, to: f64) -> Box<Route> {
    Box::new(Route {
        name: "R".into(),
        closed: false,
        waypoints: vec![lane_waypoint(lane, from), lane_waypoint(lane, to)],
        catalog: None,
    })
}

fn on_route(route: Box<Route>, in_route: InRoutePosition) -> scenario::Position {
    at(PositionKind::Route {
        route,
        orientation: None,
        in_route,
    })
}

#[test]
fn from_road_coordinates_counts_path_s_from_the_first_waypoint() {
    let w = straight();
    // Route on lane −1 from s = 10 to 200 (towards +s): pathS 50 is s = 60.
    let p = on_route(
        route("-1", 10.0, 200.0),
        InRoutePosition::FromRoadCoordinates {
            path_s: 50.0,
            t: -1.535,
        },
    );
    let r = resolve(&p, &w).unwrap();
    assert!((r.pose.x - 60.0).abs() < TOL && (r.pose.y + 1.535).abs() < TOL);
    assert!(r.pose.h.abs() < TOL);
}

#[test]
fn from_lane_coordinates_on_a_route_driven_towards_minus_s() {
    let w = straight();
    // Route on lane 1 from s = 400 to 100: travel towards −s, so pathS 50 is s = 350 and the
    // heading of travel is π.
    let p = on_route(
        route("1", 400.0, 100.0),
        InRoutePosition::FromLaneCoordinates {
            path_s: 50.0,
            lane_id: "1".into(),
            lane_offset: Some(0.2),
        },
    );
    let r = resolve(&p, &w).unwrap();
    assert!((r.pose.x - 350.0).abs() < TOL && (r.pose.y - 1.735).abs() < TOL);
    assert!((r.pose.h.abs() - PI).abs() < TOL);
}

#[test]
fn from_current_entity_and_off_route() {
    let mut w = straight();
    w.place_on_lane("Ego", "1", 1, 300.0, true);
    let p = on_route(
        route("1", 400.0, 100.0),
        InRoutePosition::FromCurrentEntity {
            entity_ref: "Ego".into(),
        },
    );
    // The entity's own point; heading of the route's travel (π), not the entity's (0).
    let r = resolve(&p, &w).unwrap();
    assert!((r.pose.x - 300.0).abs() < TOL && (r.pose.y - 1.535).abs() < TOL);
    assert!((r.pose.h.abs() - PI).abs() < TOL);
    // At s = 450 the entity is beyond the route's stretch [100, 400].
    w.place_on_lane("Ego", "1", 1, 450.0, false);
    let e = resolve(&p, &w).unwrap_err();
    assert!(matches!(e.kind(), PositionErrorKind::EntityOffRoute { .. }));
    assert_eq!(
        e.to_string(),
        "expected entity \"Ego\" on route \"R\", found it off the route at test.xosc:7:9"
    );
}

#[test]
fn path_s_beyond_the_route_is_an_error() {
    let w = straight();
    let p = on_route(
        route("-1", 10.0, 200.0),
        InRoutePosition::FromRoadCoordinates {
            path_s: 191.0,
            t: 0.0,
        },
    );
    // Length 200 − 10 = 190.
    let e = resolve(&p, &w).unwrap_err();
    assert_eq!(
        e.to_string(),
        "expected pathS in [0, 190] along route \"R\", found 191 at test.xosc:7:9"
    );
}

fn world(x: f64, y: f64) -> Vertex {
    Vertex {
        time: None,
        position: at(PositionKind::World {
            x,
            y,
            z: Some(0.0),
            h: None,
            p: None,
            r: None,
        }),
    }
}

fn trajectory_pos(s: f64, t: Option<f64>) -> scenario::Position {
    at(PositionKind::Trajectory {
        trajectory: Box::new(Trajectory {
            name: "T".into(),
            closed: false,
            shape: Shape::Polyline(vec![world(0.0, 0.0), world(10.0, 0.0), world(10.0, 10.0)]),
            catalog: None,
        }),
        s,
        t,
        orientation: None,
    })
}

#[test]
fn trajectory_position_on_a_polyline() {
    let w = straight();
    // s = 15 is 5 m into the second segment (10, 0) → (10, 10), heading π/2; t = 1 to its
    // left is −x: (9, 5).
    let r = resolve(&trajectory_pos(15.0, Some(1.0)), &w).unwrap();
    assert!((r.pose.x - 9.0).abs() < TOL && (r.pose.y - 5.0).abs() < TOL);
    assert!((r.pose.h - FRAC_PI_2).abs() < TOL);
    // s = 4 on the first segment, heading 0.
    let r = resolve(&trajectory_pos(4.0, None), &w).unwrap();
    assert!((r.pose.x - 4.0).abs() < TOL && r.pose.y.abs() < TOL && r.pose.h.abs() < TOL);
    let e = resolve(&trajectory_pos(25.0, None), &w).unwrap_err();
    assert_eq!(
        e.to_string(),
        "expected s in [0, 20] along trajectory \"T\", found 25 at test.xosc:7:9"
    );
}

#[test]
fn trajectory_position_on_a_clothoid_spline_arc() {
    use scenario::{ClothoidSpline, ClothoidSplineSegment};
    let w = straight();
    // One segment of constant curvature 0.01 from the origin heading +x: a circle of radius 100
    // about (0, 100). At s = 50 the angle is 0.5 rad; t = 1 to the left is radius 99.
    let spline = ClothoidSpline {
        time_end: None,
        segments: vec![ClothoidSplineSegment {
            curvature_start: 0.01,
            curvature_end: 0.01,
            length: 60.0,
            h_offset: None,
            time_start: None,
            position_start: Some(at(PositionKind::World {
                x: 0.0,
                y: 0.0,
                z: Some(0.0),
                h: Some(0.0),
                p: None,
                r: None,
            })),
        }],
    };
    let p = at(PositionKind::Trajectory {
        trajectory: Box::new(Trajectory {
            name: "Arc".into(),
            closed: false,
            shape: Shape::ClothoidSpline(spline),
            catalog: None,
        }),
        s: 50.0,
        t: Some(1.0),
        orientation: None,
    });
    let r = resolve(&p, &w).unwrap();
    assert!(
        (r.pose.x - 99.0 * 0.5f64.sin()).abs() < TOL,
        "x = {}",
        r.pose.x
    );
    assert!(
        (r.pose.y - (100.0 - 99.0 * 0.5f64.cos())).abs() < TOL,
        "y = {}",
        r.pose.y
    );
    assert!((r.pose.h - 0.5).abs() < TOL);
}
