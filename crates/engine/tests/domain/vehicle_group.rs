//! OpenSCENARIO 2.0 §8.7.18.1 vehicle_group (non-normative): the single-lane formation
//! helper on curve_r100.xodr (road "0": straight along +x up to s = 500; lanes ∓1 centred at
//! t = ∓1.535; right-hand traffic, so lane −1 runs towards +s and lane 1 towards −s).

use std::f64::consts::PI;

use engine::domain::{
    BoundingBox, DistanceDirection, DomainErrorKind, MovableObject, PhysicalObject, Position3d,
    TrafficParticipant, Vehicle, VehicleCategory, VehicleGroup,
};
use opendrive::{Pose, RoadNetwork};

use crate::domain_support;

/// Poses come from the road model's forward evaluation on a straight line.
const TOL: f64 = 1e-9;

fn network() -> RoadNetwork {
    domain_support::network("esmini/xodr/curve_r100.xodr")
}

fn template() -> Vehicle {
    let bb = BoundingBox::new(Position3d::new(1.5, 0.0, 0.75), 4.0, 2.0, 1.5).expect("valid");
    let m = MovableObject::new(PhysicalObject::new(bb, Pose::default()));
    Vehicle::new(
        TrafficParticipant::new(m, Vec::new()),
        VehicleCategory::Car,
        Vec::new(),
    )
    .expect("the box reaches behind the reference point")
}

#[test]
fn convoy_in_lane_minus_1() {
    let net = network();
    // Head at s = 100, box length 4 + gap 6 = 10 m between reference points: s = 100, 90, 80
    // → world (100, −1.535), (90, −1.535), (80, −1.535), heading 0.
    let g = VehicleGroup::single_lane(&net, &template(), 3, "0", -1, 100.0, 6.0).expect("fits");
    assert_eq!(g.vehicles.len(), 3);
    for (v, x) in g.vehicles.iter().zip([100.0, 90.0, 80.0]) {
        let p = v.pose;
        assert!(
            (p.x - x).abs() < TOL && (p.y + 1.535).abs() < TOL && p.h.abs() < TOL,
            "{p:?}"
        );
    }
    // Each follower's bumper-to-bumper gap to the one ahead is the 6 m asked for.
    for pair in g.vehicles.windows(2) {
        let gap = pair[0]
            .space_gap(&net, &pair[1], DistanceDirection::Longitudinal)
            .expect("same road");
        assert!((gap - 6.0).abs() < 1e-7, "{gap}");
    }
}

#[test]
fn convoy_in_lane_1_faces_minus_s() {
    let net = network();
    // Lane 1 runs towards −s: followers lie at larger s (100, 110), heading π.
    let g = VehicleGroup::single_lane(&net, &template(), 2, "0", 1, 100.0, 6.0).expect("fits");
    for (v, x) in g.vehicles.iter().zip([100.0, 110.0]) {
        let p = v.pose;
        assert!((p.x - x).abs() < TOL && (p.y - 1.535).abs() < TOL, "{p:?}");
        assert!((p.h.abs() - PI).abs() < TOL, "{p:?}");
    }
}

#[test]
fn vehicle_group_errors() {
    let net = network();
    // Three vehicles 10 m apart from s = 5: the last would stand at s = −15, off the road.
    let err = VehicleGroup::single_lane(&net, &template(), 3, "0", -1, 5.0, 6.0)
        .expect_err("falls off the road start");
    assert_eq!(
        err.kind(),
        &DomainErrorKind::LanePosition {
            road_id: "0".into(),
            lane_id: -1,
            s: -15.0
        }
    );
    assert_eq!(
        err.to_string(),
        "expected a position in lane -1 of road 0, found s = -15 outside it"
    );
    let err = VehicleGroup::single_lane(&net, &template(), 2, "0", -1, 100.0, -1.0)
        .expect_err("negative gap");
    assert!(matches!(
        err.kind(),
        DomainErrorKind::InvalidParameter { .. }
    ));
    // A huge count fails at once on the last vehicle's s, without building any.
    let err = VehicleGroup::single_lane(&net, &template(), usize::MAX, "0", -1, 100.0, 1.0)
        .expect_err("far longer than the road");
    assert!(matches!(err.kind(), DomainErrorKind::LanePosition { .. }));
    // A point-sized template with no gap would stack every vehicle on one spot.
    let mut point = template();
    point.participant.movable.object.bounding_box =
        engine::domain::BoundingBox::new(engine::domain::Position3d::ZERO, 0.0, 0.0, 0.0)
            .expect("zero box is valid");
    let err =
        VehicleGroup::single_lane(&net, &point, 3, "0", -1, 100.0, 0.0).expect_err("zero spacing");
    assert!(matches!(
        err.kind(),
        DomainErrorKind::InvalidParameter { .. }
    ));
    let err = VehicleGroup::single_lane(&net, &template(), 2, "0", -5, 100.0, 1.0)
        .expect_err("no lane −5");
    assert!(matches!(
        err.kind(),
        DomainErrorKind::LanePosition { lane_id: -5, .. }
    ));
}
