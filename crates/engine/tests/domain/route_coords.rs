//! OpenSCENARIO 2.0 §8.7.2.1.2–8.7.2.1.4 get_s_coord(), get_t_coord(), get_route_point() on
//! corpus roads, with expected values worked out from the roads' definitions.
//!
//! `curve_r100.xodr` (esmini corpus), road "0", right-hand traffic: a line from (0, 0) along
//! +x for s ∈ [0, 500], then an arc of curvature 0.01 (radius 100, centre (500, 100)) for
//! s ∈ [500, 500 + 50π], then a line along +y to the road's end at s = 600 + 50π. Lanes 1 and −1 are 3.07 m wide, so their
//! centres lie at t = ±1.535. One lane section, starting at s = 0.
//!
//! `common_junction_creator0.xodr` (generated corpus): road "1" along +x from (0, 0) to
//! (100, 0), junction "100" whose connecting road "100" runs on to (200, 0), road "3" from
//! there. Lanes are 3 m wide.

use std::f64::consts::PI;

use engine::domain::{DomainErrorKind, OnRouteType, PhysicalObject, RouteElement};
use opendrive::Pose;

use crate::domain_support;
use domain_support::{arc_pose, car_box, network};

/// Round-trip tolerance: the road model inverts world → road by Newton iteration to 1e-10 m.
const TOL: f64 = 1e-7;

fn object(pose: Pose) -> PhysicalObject {
    PhysicalObject::new(car_box(), pose)
}

#[test]
fn route_points_on_a_curve() {
    let net = network("esmini/xodr/curve_r100.xodr");
    // Lane −1 centre at s = 550 on the arc, 0.25 m left of the lane centre: t = −1.285.
    // Lane −1 is driven towards +s from the section start (s = 0): lane s = 550,
    // lane t = +0.25.
    let a = object(arc_pose(550.0, -1.285));
    let cases = [
        (
            OnRouteType::OnRoad,
            RouteElement::Road {
                road_id: "0".into(),
            },
            550.0,
            -1.285,
        ),
        (
            OnRouteType::OnLaneSection,
            RouteElement::LaneSection {
                road_id: "0".into(),
                index: 0,
            },
            550.0,
            -1.285,
        ),
        (
            OnRouteType::OnLane,
            RouteElement::Lane {
                road_id: "0".into(),
                lane_section: 0,
                lane_id: -1,
            },
            550.0,
            0.25,
        ),
    ];
    for (route_type, element, s, t) in cases {
        let p = a.get_route_point(&net, route_type).expect("on the road");
        assert_eq!(p.element, element, "{route_type:?}");
        assert!((p.s - s).abs() < TOL, "{route_type:?} s {}", p.s);
        assert!((p.t - t).abs() < TOL, "{route_type:?} t {}", p.t);
        let s_only = a.get_s_coord(&net, route_type).expect("on the road");
        let t_only = a.get_t_coord(&net, route_type).expect("on the road");
        assert!((s_only - p.s).abs() < 1e-12 && (t_only - p.t).abs() < 1e-12);
    }
}

#[test]
fn lane_s_runs_in_the_driving_direction() {
    let net = network("esmini/xodr/curve_r100.xodr");
    // Lane 1 (right-hand traffic: driven towards −s) at s = 100 on the straight, 0.5 m
    // further from the reference line than its centre: world (100, 2.035), heading π.
    // Road: s = 100, t = 2.035. Lane: s from the lane's start at the section end (the road's
    // end, 500 + 50π + 100), so 600 + 50π − 100 = 500 + 50π; t = −0.5 (right of the driving
    // direction −x is +y).
    let b = object(Pose {
        x: 100.0,
        y: 2.035,
        h: PI,
        ..Pose::default()
    });
    let road = b
        .get_route_point(&net, OnRouteType::OnRoad)
        .expect("on the road");
    assert!(
        (road.s - 100.0).abs() < TOL && (road.t - 2.035).abs() < TOL,
        "{road:?}"
    );
    let lane = b
        .get_route_point(&net, OnRouteType::OnLane)
        .expect("in lane 1");
    assert_eq!(
        lane.element,
        RouteElement::Lane {
            road_id: "0".into(),
            lane_section: 0,
            lane_id: 1
        }
    );
    assert!((lane.s - (500.0 + 50.0 * PI)).abs() < TOL, "{}", lane.s);
    assert!((lane.t + 0.5).abs() < TOL, "{}", lane.t);
}

#[test]
fn route_point_errors() {
    let net = network("esmini/xodr/curve_r100.xodr");
    // (250, 50) is 50 m from the straight and 100 m from the arc's centre side: off the road
    // (the widest side reaches 3.07 + 7 = 10.07 m).
    let off = object(Pose {
        x: 250.0,
        y: 50.0,
        ..Pose::default()
    });
    let expected = [
        (OnRouteType::OnRoad, DomainErrorKind::NotOnRoad),
        (
            OnRouteType::OnLaneSection,
            DomainErrorKind::NotOnLaneSection,
        ),
        (OnRouteType::OnLane, DomainErrorKind::NotOnLane),
        (
            OnRouteType::OnCrossing,
            DomainErrorKind::NotOnCrossing { road_id: None },
        ),
    ];
    for (route_type, kind) in expected {
        let err = off
            .get_route_point(&net, route_type)
            .expect_err("off the road");
        assert_eq!(err.kind(), &kind, "{route_type:?}");
        assert_eq!(err.position(), Some((250.0, 50.0)));
    }
    let err = off
        .get_s_coord(&net, OnRouteType::OnRoad)
        .expect_err("off the road");
    assert_eq!(
        err.to_string(),
        "expected a position on a road, found none at world (250.000, 50.000)"
    );
    // On the road but outside any junction: not on a crossing.
    let on_road = object(arc_pose(550.0, -1.535));
    let err = on_road
        .get_t_coord(&net, OnRouteType::OnCrossing)
        .expect_err("no junction");
    assert_eq!(
        err.kind(),
        &DomainErrorKind::NotOnCrossing {
            road_id: Some("0".into())
        }
    );
    assert!(err
        .to_string()
        .starts_with("expected a position on a junction's connecting road, found road 0 at world"));
}

#[test]
fn route_point_on_a_crossing() {
    let net = network("generated/xodr/common_junction_creator0.xodr");
    // A point 1.5 m right of connecting road 100's reference line at s = 50, placed with the
    // road model's own forward evaluation, heading along the road.
    let pose = net
        .road_pose("100", 50.0, -1.5)
        .expect("road 100 is 100 m long");
    let a = object(pose);
    let p = a
        .get_route_point(&net, OnRouteType::OnCrossing)
        .expect("in junction 100");
    assert_eq!(
        p.element,
        RouteElement::Crossing {
            junction_id: "100".into(),
            road_id: "100".into()
        }
    );
    assert!((p.s - 50.0).abs() < TOL && (p.t + 1.5).abs() < TOL, "{p:?}");
    // The same point on_road names the connecting road itself.
    let road = a
        .get_route_point(&net, OnRouteType::OnRoad)
        .expect("on road 100");
    assert_eq!(
        road.element,
        RouteElement::Road {
            road_id: "100".into()
        }
    );
}
