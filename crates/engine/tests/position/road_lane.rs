//! RoadPosition, LanePosition and their relative forms (OpenSCENARIO 1.3 §6.3.3, §6.3.4),
//! hand-computed on esmini's straight_500m.xodr (road "1" along +x from the origin; lanes ±1
//! 3.07 m wide, shoulders ±2 1.68 m wide: lane −2's centre at t = −(3.07 + 0.84) = −3.91) and
//! curve_r100.xodr (road "0": 500 m along +x, then an arc of curvature 0.01 turning left
//! about the centre (500, 100), then straight along +y; lanes ±1 3.07 m wide).

use crate::condition_support;

use std::f64::consts::PI;

use condition_support::{
    at, corpus_road, orientation, relative_lane_to_ego, relative_road_to, FakeWorld,
};
use engine::position::resolve;
use scenario::PositionKind;

/// Tolerance of positions computed in closed form (m, rad).
const TOL: f64 = 1e-7;

fn lane_pos(
    road: &str,
    lane: &str,
    s: f64,
    offset: Option<f64>,
    o: Option<scenario::Orientation>,
) -> scenario::Position {
    at(PositionKind::Lane {
        road_id: road.into(),
        lane_id: lane.into(),
        s,
        offset,
        orientation: o,
    })
}

#[test]
fn road_position_on_the_arc() {
    let w = FakeWorld::new(corpus_road("esmini/xodr/curve_r100.xodr"));
    // s = 550 is 50 m into the arc: angle 50/100 = 0.5 rad about (500, 100), radius 100 − t.
    for (t, o, h) in [
        (0.0, None, 0.5),
        (2.0, orientation(0.1, false), 0.6),
        (2.0, orientation(0.1, true), 0.1),
    ] {
        let p = at(PositionKind::Road {
            road_id: "0".into(),
            s: 550.0,
            t,
            orientation: o,
        });
        let r = resolve(&p, &w).unwrap();
        let radius = 100.0 - t;
        assert!((r.pose.x - (500.0 + radius * 0.5f64.sin())).abs() < TOL);
        assert!((r.pose.y - (100.0 - radius * 0.5f64.cos())).abs() < TOL);
        assert!((r.pose.h - h).abs() < TOL, "h = {} for t = {t}", r.pose.h);
        let rp = r.road_position.unwrap();
        assert!((rp.s - 550.0).abs() < 1e-6 && (rp.t - t).abs() < 1e-6);
    }
}

#[test]
fn lane_position_heading_follows_the_driving_direction() {
    // Pitfall 15: relative heading 0 on a lane means its driving direction; with right-hand
    // traffic lane 1 is driven towards −s, so its heading is π on a road along +x.
    let w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    let r = resolve(&lane_pos("1", "1", 50.0, None, None), &w).unwrap();
    assert!((r.pose.x - 50.0).abs() < TOL && (r.pose.y - 1.535).abs() < TOL);
    assert!((r.pose.h.abs() - PI).abs() < TOL);
    let r = resolve(&lane_pos("1", "1", 50.0, None, orientation(0.2, false)), &w).unwrap();
    assert!((opendrive::angle_difference(r.pose.h, PI + 0.2)).abs() < TOL);
    // Lane −1 runs along +s: heading 0; offset 0.5 m towards +t: y = −1.535 + 0.5.
    let r = resolve(&lane_pos("1", "-1", 50.0, Some(0.5), None), &w).unwrap();
    assert!((r.pose.y + 1.035).abs() < TOL && r.pose.h.abs() < TOL);
    let rp = r.road_position.unwrap();
    assert_eq!(rp.lane_id, -1);
    assert!((rp.offset - 0.5).abs() < 1e-6);
    // Absolute heading is world heading whatever the lane.
    let r = resolve(&lane_pos("1", "1", 50.0, None, orientation(1.0, true)), &w).unwrap();
    assert!((r.pose.h - 1.0).abs() < TOL);
}

#[test]
fn lane_position_on_the_arc() {
    let w = FakeWorld::new(corpus_road("esmini/xodr/curve_r100.xodr"));
    // Lane −1's centre is at t = −1.535: radius 101.535 about (500, 100), angle 0.5.
    let r = resolve(&lane_pos("0", "-1", 550.0, None, None), &w).unwrap();
    assert!((r.pose.x - (500.0 + 101.535 * 0.5f64.sin())).abs() < TOL);
    assert!((r.pose.y - (100.0 - 101.535 * 0.5f64.cos())).abs() < TOL);
    assert!((r.pose.h - 0.5).abs() < TOL);
}

#[test]
fn relative_road_position_adds_ds_and_dt() {
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    w.place_on_lane("Ego", "1", -1, 100.0, true);
    let p = relative_road_to("Ego", 20.0, 3.0);
    // (s, t) = (100 + 20, −1.535 + 3) on a road along +x: (120, 1.465), heading along s.
    let r = resolve(&p, &w).unwrap();
    assert!((r.pose.x - 120.0).abs() < TOL && (r.pose.y - 1.465).abs() < TOL);
    assert!(r.pose.h.abs() < TOL);
}

#[test]
fn relative_lane_position_with_ds_skips_the_centre_lane() {
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"));
    w.place_on_lane("Ego", "1", -1, 100.0, true);
    let rel = relative_lane_to_ego;
    // −1 + 1 = 1 (lane 0 has no width and is no target): centre t = 1.535, driven towards −s.
    let r = resolve(&rel(1, 10.0), &w).unwrap();
    assert!((r.pose.x - 110.0).abs() < TOL && (r.pose.y - 1.535).abs() < TOL);
    assert!((r.pose.h.abs() - PI).abs() < TOL);
    assert_eq!(r.road_position.unwrap().lane_id, 1);
    // −1 − 1 = −2, the shoulder, centre t = −3.91.
    let r = resolve(&rel(-1, -5.0), &w).unwrap();
    assert!((r.pose.x - 95.0).abs() < TOL && (r.pose.y + 3.91).abs() < TOL);
}

#[test]
fn relative_lane_position_with_ds_lane_measures_along_the_lane_centre() {
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/curve_r100.xodr"));
    // Ego at the start of the arc (s = 500) on lane −1, facing +s. The lane centre has radius
    // 101.535, so dsLane = 101.535 · 0.5 m along it turns 0.5 rad: s = 500 + 100 · 0.5 = 550.
    w.place_on_lane("Ego", "0", -1, 500.0, true);
    let p = at(PositionKind::RelativeLane {
        entity_ref: "Ego".into(),
        d_lane: 0,
        ds: None,
        ds_lane: Some(101.535 * 0.5),
        offset: None,
        orientation: None,
    });
    let r = resolve(&p, &w).unwrap();
    // Simpson's rule is exact for the constant centre-line speed of an arc; the bisection
    // places s to picometres, so 1e-5 m is round-off slack.
    let rp = r.road_position.unwrap();
    assert!((rp.s - 550.0).abs() < 1e-5, "s = {}", rp.s);
    assert!((r.pose.x - (500.0 + 101.535 * 0.5f64.sin())).abs() < 1e-5);
    // Facing −s (on the straight part, s = 300), dsLane = 10 goes back to s = 290.
    w.place_on_lane("Ego", "0", -1, 300.0, false);
    let p = at(PositionKind::RelativeLane {
        entity_ref: "Ego".into(),
        d_lane: 0,
        ds: None,
        ds_lane: Some(10.0),
        offset: None,
        orientation: None,
    });
    let r = resolve(&p, &w).unwrap();
    assert!((r.pose.x - 290.0).abs() < 1e-6, "x = {}", r.pose.x);
}

#[test]
fn pitch_and_roll_follow_the_road_surface_for_the_heading() {
    // esmini's curves_elevation.xodr climbs and falls, without superelevation. Facing along the
    // road an entity takes the road's pitch P; turned to the left by π/2 it looks across the
    // slope (pitch 0) with its right side towards +s, so its roll is P (right side down when
    // the road falls along +s, OpenDRIVE signs); facing back (lane 1, driven towards −s) its
    // pitch is −P.
    let w = FakeWorld::new(corpus_road("esmini/xodr/curves_elevation.xodr"));
    let road = w.network.roads()[0].id.clone();
    let s = (0..200)
        .map(|i| f64::from(i) * 10.0)
        .find(|&s| {
            w.network
                .road_pose(&road, s, 0.0)
                .is_ok_and(|p| p.p.abs() > 0.01)
        })
        .expect("the road has a slope");
    let slope = w.network.road_pose(&road, s, 0.0).unwrap();
    assert!(slope.r.abs() < 1e-12, "no superelevation expected");
    let along = |h| {
        at(PositionKind::Road {
            road_id: road.clone(),
            s,
            t: 0.0,
            orientation: orientation(h, false),
        })
    };
    let r = resolve(&along(0.0), &w).unwrap();
    assert!((r.pose.p - slope.p).abs() < TOL && r.pose.r.abs() < TOL);
    let r = resolve(&along(std::f64::consts::FRAC_PI_2), &w).unwrap();
    assert!(r.pose.p.abs() < TOL && (r.pose.r - slope.p).abs() < TOL);
    let r = resolve(&lane_pos(&road, "1", s, None, None), &w).unwrap();
    assert!((r.pose.p + slope.p).abs() < TOL, "p = {}", r.pose.p);
}
