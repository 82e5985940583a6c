//! OpenSCENARIO 2.0 §8.7.2.1.1 object_distance(): hand-computed cases in the caller's frame.
//!
//! Caller A stands at (10, 5) heading π/2 (facing +y): its x axis is world +y, its y axis
//! world −x, so a world offset (dx, dy) has local coordinates (dy, −dx). All boxes are
//! length 4, width 2, centre (1.5, 0, 0.75): x ∈ [−0.5, 3.5], y ∈ [−1, 1] in the own frame.

use std::f64::consts::FRAC_PI_2;

use engine::domain::{BoundingBox, DistanceDirection, DistanceMode, PhysicalObject, Position3d};
use opendrive::Pose;

use DistanceDirection::{Lateral, Longitudinal};
use DistanceMode::{BoundingBoxes, ReferencePoints};

/// The expected values are sums of exact decimals and one rotation by π/2.
const TOL: f64 = 1e-9;

fn object(x: f64, y: f64, h: f64) -> PhysicalObject {
    let bb =
        BoundingBox::new(Position3d::new(1.5, 0.0, 0.75), 4.0, 2.0, 1.5).expect("valid dimensions");
    PhysicalObject::new(
        bb,
        Pose {
            x,
            y,
            h,
            ..Pose::default()
        },
    )
}

#[test]
fn object_distance_table() {
    let a = object(10.0, 5.0, FRAC_PI_2);
    let cases = [
        // B 20 m ahead, same heading: offset (0, 20) → local (20, 0). Boxes: B's x range is
        // [19.5, 23.5], A's ends at 3.5 → 16.
        (
            "ahead",
            object(10.0, 25.0, FRAC_PI_2),
            Longitudinal,
            ReferencePoints,
            20.0,
        ),
        (
            "ahead",
            object(10.0, 25.0, FRAC_PI_2),
            Longitudinal,
            BoundingBoxes,
            16.0,
        ),
        (
            "ahead",
            object(10.0, 25.0, FRAC_PI_2),
            Lateral,
            ReferencePoints,
            0.0,
        ),
        // B 20 m behind: B's box x ∈ [−20.5, −16.5], A's starts at −0.5 → −16.
        (
            "behind",
            object(10.0, -15.0, FRAC_PI_2),
            Longitudinal,
            ReferencePoints,
            -20.0,
        ),
        (
            "behind",
            object(10.0, -15.0, FRAC_PI_2),
            Longitudinal,
            BoundingBoxes,
            -16.0,
        ),
        // B at world (7, 15): offset (−3, 10) → local (10, 3): 3 m to the left. Box y range
        // [2, 4] against A's [−1, 1] → 1.
        (
            "left",
            object(7.0, 15.0, FRAC_PI_2),
            Lateral,
            ReferencePoints,
            3.0,
        ),
        (
            "left",
            object(7.0, 15.0, FRAC_PI_2),
            Lateral,
            BoundingBoxes,
            1.0,
        ),
        // B at (12, 25) heading 0 (across A): reference offset (2, 20) → local (20, −2).
        // Its box centre (13.5, 25) → local (20, −3.5); turned by −π/2 in A's frame, it spans
        // its width along A's x: [19, 21] → gap 19 − 3.5 = 15.5; its length along A's
        // y: [−5.5, −1.5] → −1.5 − (−1) = −0.5 (to the right).
        (
            "rotated",
            object(12.0, 25.0, 0.0),
            Longitudinal,
            ReferencePoints,
            20.0,
        ),
        (
            "rotated",
            object(12.0, 25.0, 0.0),
            Longitudinal,
            BoundingBoxes,
            15.5,
        ),
        (
            "rotated",
            object(12.0, 25.0, 0.0),
            Lateral,
            ReferencePoints,
            -2.0,
        ),
        (
            "rotated",
            object(12.0, 25.0, 0.0),
            Lateral,
            BoundingBoxes,
            -0.5,
        ),
        // B 3 m ahead: box x ∈ [2.5, 6.5] overlaps A's [−0.5, 3.5] → 0 (freespace rule).
        (
            "overlapping",
            object(10.0, 8.0, FRAC_PI_2),
            Longitudinal,
            BoundingBoxes,
            0.0,
        ),
        (
            "overlapping",
            object(10.0, 8.0, FRAC_PI_2),
            Longitudinal,
            ReferencePoints,
            3.0,
        ),
    ];
    for (name, b, direction, mode, expected) in cases {
        let got = a.object_distance(&b, direction, mode);
        assert!(
            (got - expected).abs() < TOL,
            "{name} {direction:?} {mode:?}: got {got}, expected {expected}"
        );
    }
}

#[test]
fn object_distance_in_pitched_frame() {
    // A pitched 30° nose down (p = π/6) at the origin: its x axis is (cos p, 0, −sin p).
    // A point 10 m along world x has local x = 10 cos p = 8.660…, local y = 0.
    let mut a = object(0.0, 0.0, 0.0);
    a.pose.p = std::f64::consts::FRAC_PI_6;
    let b = object(10.0, 0.0, 0.0);
    let got = a.object_distance(&b, Longitudinal, ReferencePoints);
    assert!(
        (got - 10.0 * (3.0f64).sqrt() / 2.0).abs() < TOL,
        "got {got}"
    );
}
