//! Helpers shared by the `domain_*` integration tests (OpenSCENARIO 2.0 §8.7): corpus road
//! networks, the standard test car and the curve_r100 arc in closed form.
//!
//! Not every test file uses every helper.
#![allow(dead_code)]

use engine::domain::{
    BoundingBox, MovableObject, PhysicalObject, Position3d, TrafficParticipant, Vector3,
};
use opendrive::{Pose, RoadNetwork};

/// A road network of the shared corpus, by its path below `corpus/`.
pub fn network(name: &str) -> RoadNetwork {
    // The corpus is part of the test fixture; a missing file is a broken checkout.
    RoadNetwork::from_file(&crate::corpus::corpus(name)).expect("corpus road network loads")
}

/// The test car's box: length 4, width 2, height 1.5, centre (1.5, 0, 0.75), so that from the
/// reference point it spans x ∈ [−0.5, 3.5], y ∈ [−1, 1], z ∈ [0, 1.5].
pub fn car_box() -> BoundingBox {
    BoundingBox::new(Position3d::new(1.5, 0.0, 0.75), 4.0, 2.0, 1.5).expect("valid dimensions")
}

/// A traffic participant with `bb` at `pose`, moving forward at `speed` m/s.
pub fn participant_with(bb: BoundingBox, pose: Pose, speed: f64) -> TrafficParticipant {
    let mut m = MovableObject::new(PhysicalObject::new(bb, pose));
    m.velocity.translational = Vector3::new(speed, 0.0, 0.0);
    TrafficParticipant::new(m, Vec::new())
}

/// The test car at `pose`, at rest.
pub fn participant(pose: Pose) -> TrafficParticipant {
    participant_with(car_box(), pose, 0.0)
}

/// The pose at (s, t) on the arc of esmini's curve_r100.xodr (s ∈ [500, 500 + 50π]): the arc
/// starts at (500, 0) heading +x with curvature 0.01, so its centre is (500, 100); the angle
/// swept is φ = (s − 500)/100, the point lies 100 − t from the centre in direction
/// (sin φ, −cos φ), and the heading is φ.
pub fn arc_pose(s: f64, t: f64) -> Pose {
    let phi = (s - 500.0) / 100.0;
    let r = 100.0 - t;
    Pose {
        x: 500.0 + r * phi.sin(),
        y: 100.0 - r * phi.cos(),
        h: phi,
        ..Pose::default()
    }
}

/// Asserts that `got` equals `expected` within `tol`, or that both are `None`; `name` labels
/// the case in the failure message.
pub fn assert_close_opt(name: &str, got: Option<f64>, expected: Option<f64>, tol: f64) {
    match (got, expected) {
        (Some(g), Some(e)) => assert!((g - e).abs() < tol, "{name}: got {g}, expected {e}"),
        (None, None) => {}
        _ => panic!("{name}: got {got:?}, expected {expected:?}"),
    }
}
