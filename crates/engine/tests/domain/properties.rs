//! Property tests of the OpenSCENARIO 2.0 §8.7 measurement methods that need no road:
//! object_distance (§8.7.2.1.1) and time_to_collision (§8.7.5.1.1).

use engine::domain::{
    BoundingBox, DistanceDirection, DistanceMode, MovableObject, PhysicalObject, Position3d,
    TrafficParticipant, Vector3,
};
use opendrive::Pose;
use proptest::prelude::*;

/// A box of plausible road-user size whose centre is offset from the reference point by less
/// than half its extent, so the reference point lies inside the box (as for every vehicle,
/// whose reference point is the rear axle's centre).
fn bounding_box() -> impl Strategy<Value = BoundingBox> {
    (
        0.5..12.0f64,
        0.5..3.0f64,
        0.5..4.0f64,
        -0.49..0.49f64,
        -0.49..0.49f64,
    )
        .prop_map(|(l, w, h, fx, fy)| {
            BoundingBox::new(Position3d::new(fx * l, fy * w, 0.5 * h), l, w, h)
                .expect("positive finite dimensions")
        })
}

fn participant(bb: BoundingBox, x: f64, y: f64, h: f64, v: (f64, f64)) -> TrafficParticipant {
    let mut m = MovableObject::new(PhysicalObject::new(
        bb,
        Pose {
            x,
            y,
            h,
            ..Pose::default()
        },
    ));
    m.velocity.translational = Vector3::new(v.0, v.1, 0.0);
    TrafficParticipant::new(m, Vec::new())
}

proptest! {
    /// For objects with the same heading whose reference points lie inside their boxes, the
    /// box distance never exceeds the reference-point distance in magnitude and never has the
    /// opposite sign: the own interval contains 0 and the other contains the reference
    /// point's coordinate d, so the gap between them lies between 0 and d.
    #[test]
    fn bounding_box_distance_never_exceeds_reference_point_distance(
        a_box in bounding_box(), b_box in bounding_box(),
        x in -80.0..80.0f64, y in -80.0..80.0f64, h in -3.2..3.2f64,
        lateral in any::<bool>(),
    ) {
        let a = PhysicalObject::new(a_box, Pose { h, ..Pose::default() });
        let b = PhysicalObject::new(b_box, Pose { x, y, h, ..Pose::default() });
        let direction =
            if lateral { DistanceDirection::Lateral } else { DistanceDirection::Longitudinal };
        let rp = a.object_distance(&b, direction, DistanceMode::ReferencePoints);
        let bb = a.object_distance(&b, direction, DistanceMode::BoundingBoxes);
        prop_assert!(bb.abs() <= rp.abs() + 1e-9, "bb {bb} rp {rp}");
        prop_assert!(bb * rp >= 0.0, "opposite signs: bb {bb} rp {rp}");
    }

    /// The time to collision depends on the relative motion only, so asking from either
    /// object gives the same answer.
    #[test]
    fn time_to_collision_is_symmetric(
        a_box in bounding_box(), b_box in bounding_box(),
        x in -60.0..60.0f64, y in -60.0..60.0f64,
        ha in -3.2..3.2f64, hb in -3.2..3.2f64,
        va in (-30.0..30.0f64, -3.0..3.0f64), vb in (-30.0..30.0f64, -3.0..3.0f64),
    ) {
        let a = participant(a_box, 0.0, 0.0, ha, va);
        let b = participant(b_box, x, y, hb, vb);
        match (a.time_to_collision(&b), b.time_to_collision(&a)) {
            (Some(t), Some(u)) => prop_assert!((t - u).abs() <= 1e-9 * (1.0 + t), "{t} vs {u}"),
            (None, None) => {}
            (t, u) => prop_assert!(false, "asymmetric: {t:?} vs {u:?}"),
        }
    }

    /// At the reported time the boxes touch, and shortly before they are apart. Checked on
    /// copies moved to that time and frozen (zero velocity), where time_to_collision is
    /// `Some(0)` exactly when the boxes overlap or touch and `None` otherwise.
    #[test]
    fn boxes_touch_at_the_time_to_collision(
        a_box in bounding_box(), b_box in bounding_box(),
        x in -60.0..60.0f64, y in -60.0..60.0f64, hb in -3.2..3.2f64,
        va in 0.0..30.0f64, vb in (-30.0..30.0f64, -3.0..3.0f64),
    ) {
        let a = participant(a_box, 0.0, 0.0, 0.0, (va, 0.0));
        let b = participant(b_box, x, y, hb, vb);
        if let Some(t) = a.time_to_collision(&b) {
            let frozen_at = |time: f64| {
                let (s, c) = hb.sin_cos();
                let a2 = participant(a_box, va * time, 0.0, 0.0, (0.0, 0.0));
                let bx = x + (c * vb.0 - s * vb.1) * time;
                let by = y + (s * vb.0 + c * vb.1) * time;
                let b2 = participant(b_box, bx, by, hb, (0.0, 0.0));
                a2.time_to_collision(&b2)
            };
            prop_assert_eq!(frozen_at(t), Some(0.0));
            if t > 1e-3 {
                prop_assert_eq!(frozen_at(t - 1e-3), None);
            }
        }
    }
}
