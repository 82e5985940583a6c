//! WorldPosition, RelativeWorldPosition and RelativeObjectPosition (OpenSCENARIO 1.3 §6.3.1,
//! §6.3.2), hand-computed on esmini's straight_500m.xodr (one straight road "1" along +x,
//! flat; lanes ±1 are 3.07 m wide, so lane −1's centre is at t = −1.535).

use crate::condition_support;

use std::f64::consts::FRAC_PI_2;

use condition_support::{at, corpus_road, orientation, FakeWorld};
use engine::position::resolve;
use opendrive::Pose;
use scenario::PositionKind;

/// Tolerance of positions computed in closed form (m, rad).
const TOL: f64 = 1e-9;

fn straight() -> FakeWorld {
    FakeWorld::new(corpus_road("esmini/xodr/straight_500m.xodr"))
}

/// "Ego" at (100, −1.535) on lane −1, heading π/2 (across the road, facing +y).
fn place_ego_facing_north(w: &mut FakeWorld) {
    w.place(
        "Ego",
        Pose {
            x: 100.0,
            y: -1.535,
            h: FRAC_PI_2,
            ..Pose::default()
        },
    );
}

#[test]
fn world_position_keeps_its_coordinates_and_finds_its_lane() {
    let w = straight();
    let p = at(PositionKind::World {
        x: 10.0,
        y: -1.535,
        z: None,
        h: Some(0.3),
        p: None,
        r: None,
    });
    let r = resolve(&p, &w).unwrap();
    // z absent: on the flat road surface, 0; p and r absent: 0.
    assert!((r.pose.x - 10.0).abs() < TOL && (r.pose.y + 1.535).abs() < TOL);
    assert!(r.pose.z.abs() < TOL && r.pose.p.abs() < TOL && r.pose.r.abs() < TOL);
    assert!((r.pose.h - 0.3).abs() < TOL);
    let rp = r.road_position.unwrap();
    assert_eq!((rp.road_id.as_str(), rp.lane_id), ("1", -1));
    // s = x on a road starting at the origin along +x; offset from lane −1's centre 0.
    assert!((rp.s - 10.0).abs() < 1e-7 && rp.offset.abs() < 1e-7);
}

#[test]
fn relative_world_position_adds_world_offsets() {
    let mut w = straight();
    place_ego_facing_north(&mut w);
    let rel = |orientation| {
        at(PositionKind::RelativeWorld {
            entity_ref: "Ego".into(),
            dx: 5.0,
            dy: 1.0,
            dz: None,
            orientation,
        })
    };
    // World axes: (100 + 5, −1.535 + 1); the heading does not turn the offset.
    let r = resolve(&rel(None), &w).unwrap();
    assert!((r.pose.x - 105.0).abs() < TOL && (r.pose.y + 0.535).abs() < TOL);
    // Missing orientation: the entity's heading.
    assert!((r.pose.h - FRAC_PI_2).abs() < TOL);
    // Relative: π/2 + 0.1; absolute: 0.2.
    let r = resolve(&rel(orientation(0.1, false)), &w).unwrap();
    assert!((r.pose.h - (FRAC_PI_2 + 0.1)).abs() < TOL);
    let r = resolve(&rel(orientation(0.2, true)), &w).unwrap();
    assert!((r.pose.h - 0.2).abs() < TOL);
}

#[test]
fn relative_object_position_turns_offsets_with_the_entity() {
    let mut w = straight();
    place_ego_facing_north(&mut w);
    let p = at(PositionKind::RelativeObject {
        entity_ref: "Ego".into(),
        dx: 4.0,
        dy: 1.0,
        dz: None,
        orientation: None,
    });
    // Heading π/2: forward is +y, left is −x, so (dx, dy) = (4, 1) lands at
    // (100 − 1, −1.535 + 4) = (99, 2.465).
    let r = resolve(&p, &w).unwrap();
    assert!((r.pose.x - 99.0).abs() < TOL, "x = {}", r.pose.x);
    assert!((r.pose.y - 2.465).abs() < TOL, "y = {}", r.pose.y);
    assert_eq!(r.road_position.unwrap().lane_id, 1);
}

#[test]
fn relative_object_position_follows_pitch() {
    let mut w = straight();
    // Pitch 0.1 rad, nose down (OpenDRIVE sign): a point 10 m ahead at dz = 0 lies
    // 10·sin 0.1 = 0.998334 m lower and 10·cos 0.1 = 9.950042 m further along x.
    w.place(
        "Ego",
        Pose {
            x: 50.0,
            y: 0.0,
            z: 5.0,
            p: 0.1,
            ..Pose::default()
        },
    );
    let p = at(PositionKind::RelativeObject {
        entity_ref: "Ego".into(),
        dx: 10.0,
        dy: 0.0,
        dz: Some(0.0),
        orientation: None,
    });
    let r = resolve(&p, &w).unwrap();
    assert!((r.pose.x - (50.0 + 10.0 * 0.1f64.cos())).abs() < TOL);
    assert!((r.pose.z - (5.0 - 10.0 * 0.1f64.sin())).abs() < TOL);
    assert!((r.pose.p - 0.1).abs() < TOL);
}

#[test]
fn relative_object_position_follows_roll() {
    let mut w = straight();
    // Roll 0.1 rad, right side down (OpenDRIVE sign): a point 1 m to the left at dz = 0 lies
    // sin 0.1 = 0.099833 m higher and cos 0.1 = 0.995004 m to the left; with heading π/2
    // "left" is −x.
    w.place(
        "Ego",
        Pose {
            x: 50.0,
            y: 0.0,
            z: 1.0,
            h: FRAC_PI_2,
            r: 0.1,
            ..Pose::default()
        },
    );
    let p = at(PositionKind::RelativeObject {
        entity_ref: "Ego".into(),
        dx: 0.0,
        dy: 1.0,
        dz: Some(0.0),
        orientation: None,
    });
    let r = resolve(&p, &w).unwrap();
    assert!(
        (r.pose.x - (50.0 - 0.1f64.cos())).abs() < TOL,
        "x = {}",
        r.pose.x
    );
    assert!(r.pose.y.abs() < TOL, "y = {}", r.pose.y);
    assert!(
        (r.pose.z - (1.0 + 0.1f64.sin())).abs() < TOL,
        "z = {}",
        r.pose.z
    );
}
