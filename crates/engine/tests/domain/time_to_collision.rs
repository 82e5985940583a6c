//! OpenSCENARIO 2.0 §8.7.5.1.1 time_to_collision(): a table of hand-computed cases.
//!
//! Every car below has the box length 4, width 2, height 1.5 with centre (1.5, 0, 0.75) in
//! object coordinates: with the reference point at the rear axle the box spans x ∈ [−0.5, 3.5]
//! and y ∈ [−1, 1] of the car's own frame.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, SQRT_2};

use engine::domain::{
    BoundingBox, PhysicalObject, Position3d, StationaryObject, TrafficParticipant,
};
use opendrive::Pose;

use crate::domain_support;
use domain_support::{assert_close_opt, car_box, participant_with};

/// Tolerance of the closed forms below: they involve a handful of operations on numbers of
/// order 10, so 1e-9 s leaves three orders of magnitude for round-off.
const TOL: f64 = 1e-9;

fn square_box() -> BoundingBox {
    BoundingBox::new(Position3d::new(0.0, 0.0, 0.75), 2.0, 2.0, 1.5).expect("valid dimensions")
}

/// A participant with `bb` at (x, y, z) heading h, moving forward at `v` m/s.
fn participant(bb: BoundingBox, x: f64, y: f64, z: f64, h: f64, v: f64) -> TrafficParticipant {
    participant_with(
        bb,
        Pose {
            x,
            y,
            z,
            h,
            ..Pose::default()
        },
        v,
    )
}

fn car(x: f64, y: f64, h: f64, v: f64) -> TrafficParticipant {
    participant(car_box(), x, y, 0.0, h, v)
}

/// (name, caller, reference, expected)
fn cases() -> Vec<(
    &'static str,
    TrafficParticipant,
    TrafficParticipant,
    Option<f64>,
)> {
    vec![
        // B at x = 50 facing −x: its box centre is 50 − 1.5 = 48.5, x ∈ [46.5, 50.5].
        // Gap 46.5 − 3.5 = 43 m, closing speed 10 + 10 = 20 m/s → 2.15 s.
        (
            "head-on approach",
            car(0.0, 0.0, 0.0, 10.0),
            car(50.0, 0.0, PI, 10.0),
            Some(2.15),
        ),
        // B ahead at 30, box x ∈ [29.5, 33.5]: gap 26 m, closing 20 − 10 = 10 m/s → 2.6 s.
        (
            "rear-end approach",
            car(0.0, 0.0, 0.0, 20.0),
            car(30.0, 0.0, 0.0, 10.0),
            Some(2.6),
        ),
        // Same gap, B faster: the gap only grows.
        (
            "receding",
            car(0.0, 0.0, 0.0, 10.0),
            car(30.0, 0.0, 0.0, 20.0),
            None,
        ),
        // Adjacent lane 3.5 m to the left, y ranges [−1, 1] and [2.5, 4.5] never meet.
        (
            "parallel, adjacent lane",
            car(0.0, 0.0, 0.0, 20.0),
            car(30.0, 3.5, 0.0, 10.0),
            None,
        ),
        // Oncoming in the adjacent lane (pitfall 11: must not trigger).
        (
            "oncoming, adjacent lane",
            car(0.0, 0.0, 0.0, 20.0),
            car(60.0, -3.5, PI, 20.0),
            None,
        ),
        // Same speed, same lane: the gap stays 26 m.
        (
            "parallel, same speed",
            car(0.0, 0.0, 0.0, 15.0),
            car(30.0, 0.0, 0.0, 15.0),
            None,
        ),
        // Lateral offset exactly 2 = width: the sides touch (y = 1) from the moment the x
        // ranges meet, as in the rear-end case: 2.6 s. Touching counts as contact.
        (
            "grazing contact",
            car(0.0, 0.0, 0.0, 20.0),
            car(30.0, 2.0, 0.0, 10.0),
            Some(2.6),
        ),
        // One millimetre further out: a miss.
        (
            "near miss",
            car(0.0, 0.0, 0.0, 20.0),
            car(30.0, 2.001, 0.0, 10.0),
            None,
        ),
        // Boxes x ∈ [−0.5, 3.5] and [2.5, 6.5] overlap now.
        (
            "already overlapping",
            car(0.0, 0.0, 0.0, 0.0),
            car(3.0, 0.0, 0.0, -5.0),
            Some(0.0),
        ),
        // B drives +y from (20, −20): its box is x ∈ [19, 21], y ∈ [−20.5 + 10t, −16.5 + 10t];
        // A's is x ∈ [−0.5 + 10t, 3.5 + 10t], y ∈ [−1, 1]. x overlap for t ∈ [1.55, 2.15],
        // y overlap for t ∈ [1.55, 2.15] → 1.55 s.
        (
            "crossing, collide",
            car(0.0, 0.0, 0.0, 10.0),
            car(20.0, -20.0, FRAC_PI_2, 10.0),
            Some(1.55),
        ),
        // B at 5 m/s: y overlap needs −16.5 + 5t ≥ −1, t ≥ 3.1, after A has passed (2.15).
        (
            "crossing, A passes first",
            car(0.0, 0.0, 0.0, 10.0),
            car(20.0, -20.0, FRAC_PI_2, 5.0),
            None,
        ),
        // Stationary 2 × 2 square turned 45° at (20, 2): a diamond |x − 20| + |y − 2| ≤ √2.
        // At A's left side y = 1 it spans |x − 20| ≤ √2 − 1, so A's front (3.5 + 10t) touches at
        // x = 20 − (√2 − 1): t = (16.5 − √2 + 1) / 10. (An axis-aligned hull would say
        // (16.5 − √2) / 10, 0.1 s early.)
        (
            "rotated box, corner contact",
            car(0.0, 0.0, 0.0, 10.0),
            participant(square_box(), 20.0, 2.0, 0.0, FRAC_PI_4, 0.0),
            Some((17.5 - SQRT_2) / 10.0),
        ),
        // The same diamond on the lane centre: its left vertex x = 20 − √2 is hit first.
        (
            "rotated box, vertex contact",
            car(0.0, 0.0, 0.0, 10.0),
            participant(square_box(), 20.0, 0.0, 0.0, FRAC_PI_4, 0.0),
            Some((16.5 - SQRT_2) / 10.0),
        ),
        // Both cars turned by 30°, the geometry of the rear-end case rotated: still 2.6 s.
        (
            "rear-end, rotated frame",
            car(0.0, 0.0, PI / 6.0, 20.0),
            car(
                30.0 * (PI / 6.0).cos(),
                30.0 * (PI / 6.0).sin(),
                PI / 6.0,
                10.0,
            ),
            Some(2.6),
        ),
        // B's box 10 m up (a bridge): the vertical ranges [0, 1.5] and [10, 11.5] are apart.
        (
            "different levels",
            car(0.0, 0.0, 0.0, 20.0),
            participant(car_box(), 30.0, 0.0, 10.0, 0.0, 0.0),
            None,
        ),
    ]
}

#[test]
fn time_to_collision_table() {
    for (name, a, b, expected) in cases() {
        assert_close_opt(name, a.time_to_collision(&b), expected, TOL);
        // The reverse question has the same answer: the relative motion is the same.
        assert_close_opt(name, b.time_to_collision(&a), expected, TOL);
    }
}

#[test]
fn time_to_collision_with_stationary_object() {
    // A StationaryObject reference has no velocity: the rear-end gap of 26 m closes at
    // A's 10 m/s → 2.6 s.
    let a = car(0.0, 0.0, 0.0, 10.0);
    let obstacle = StationaryObject::location(
        PhysicalObject::new(car_box(), Pose::default()),
        Pose {
            x: 30.0,
            ..Pose::default()
        },
    );
    let t = a
        .time_to_collision(&obstacle)
        .expect("A drives into the obstacle");
    assert!((t - 2.6).abs() < TOL, "got {t}");
}

#[test]
fn time_to_collision_uses_lateral_velocity() {
    // B beside A (y = 4, box y ∈ [3, 5]) drifting right at 1 m/s in its own frame, same
    // forward speed: the gap 3 − 1 = 2 m closes in 2 s.
    let a = car(0.0, 0.0, 0.0, 10.0);
    let mut b = car(0.0, 4.0, 0.0, 10.0);
    b.velocity.translational.y = -1.0;
    let t = a.time_to_collision(&b).expect("B drifts into A");
    assert!((t - 2.0).abs() < TOL, "got {t}");
}

#[test]
fn non_finite_input_gives_no_time() {
    // A NaN position or an infinite speed must not be read as a collision.
    let a = car(0.0, 0.0, 0.0, 10.0);
    let mut b = car(f64::NAN, 0.0, 0.0, 0.0);
    assert_eq!(a.time_to_collision(&b), None);
    b = car(30.0, 0.0, 0.0, f64::INFINITY);
    assert_eq!(a.time_to_collision(&b), None);
    assert_eq!(b.time_to_collision(&a), None);
}
