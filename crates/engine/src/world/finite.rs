//! Whether an entity's state is finite (OpenSCENARIO 1.3 §6.3 coordinates and §7.2.2 entity
//! states are real numbers): the test of the step's finite-state guard (engine
//! runtime/finite.rs), here beside the state it reads so that the stage that moves the
//! entities (controller/stage.rs) can apply it in its own walk over them, and the name of the
//! first value that is not, for the guard's error.

use super::entity::Entity;

/// The first state value of `e` that is not finite, by name.
pub(crate) fn first_non_finite(e: &Entity) -> Option<(&'static str, f64)> {
    let p = &e.pose;
    let v = &e.velocity;
    let a = &e.acceleration;
    let values = [
        ("x", p.x),
        ("y", p.y),
        ("z", p.z),
        ("heading", p.h),
        ("pitch", p.p),
        ("roll", p.r),
        ("speed", e.speed),
        ("velocity x", v.translational.x),
        ("velocity y", v.translational.y),
        ("velocity z", v.translational.z),
        ("yaw rate", v.rotational.z),
        ("acceleration x", a.translational.x),
        ("acceleration y", a.translational.y),
        ("acceleration z", a.translational.z),
    ];
    let road = e
        .road_position
        .as_ref()
        .map(|r| [("road s", r.s), ("road t", r.t), ("lane offset", r.offset)]);
    // On the stack, in the order of the message: no allocation per entity and step.
    values
        .into_iter()
        .chain(road.into_iter().flatten())
        .find(|(_, value)| !value.is_finite())
}

/// Whether every state value of `e` (the values [`first_non_finite`] names) is finite.
///
/// The test of the step's moves (controller/stage.rs), one addition per value: a sum is finite
/// only if every term is (a NaN term makes it NaN; ±inf plus finite values is ±inf; +inf plus
/// −inf is NaN), so a finite sum of the 17 values proves them all finite, each value read by
/// the addition itself (an `addsd` from memory). A sum that is not finite is a value that is
/// not, or finite values whose sum overflows (only near f64::MAX, where a step is about to
/// overflow anyway): that rare case is decided by the named search, out of line, so the answer
/// is exactly "no value is NaN or ±inf", as before (the x·0 products it replaces cost two
/// operations per value and a load of their own, 55 instructions per entity-step of `mobil`).
/// Summed pairwise, a tree of depth 5: as a chain, the 16 additions, each waiting for the one
/// before, took ~50 cycles a vehicle and showed in the step's time (issue 31: 1.5 % of `mobil`
/// at 1,000 vehicles). Any order gives the same answer: a finite sum proves every term
/// finite, and a sum that is not finite goes to the search.
#[inline]
pub(crate) fn all_finite(e: &Entity) -> bool {
    let p = &e.pose;
    let v = &e.velocity;
    let a = &e.acceleration;
    let pose = ((p.x + p.y) + (p.z + p.h)) + ((p.p + p.r) + e.speed);
    let motion = ((v.translational.x + v.translational.y) + (v.translational.z + v.rotational.z))
        + ((a.translational.x + a.translational.y) + a.translational.z);
    let state = pose + motion;
    let sum = match &e.road_position {
        Some(r) => state + ((r.s + r.t) + r.offset),
        None => state,
    };
    sum.is_finite() || all_finite_by_name(e)
}

/// [`all_finite`] where the sum of the values is not finite: by the named search.
#[cold]
#[inline(never)]
fn all_finite_by_name(e: &Entity) -> bool {
    first_non_finite(e).is_none()
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::domain::{BoundingBox, Vector3};
    use crate::world::entity::{EntityId, EntityKind};

    pub(crate) fn car() -> Entity {
        let b = BoundingBox::new(Vector3::new(1.4, 0.0, 0.75), 5.0, 2.0, 1.5).expect("box");
        let mut e = Entity::new(EntityId(0), "car", EntityKind::Vehicle, b);
        e.road_position = Some(opendrive::RoadPosition {
            road_id: "1".into(),
            road: opendrive::RoadHandle(0),
            lane_id: -1,
            s: 10.0,
            t: -1.75,
            offset: 0.0,
            junction_id: None,
            relative_heading: 0.0,
            distance: 0.0,
        });
        e
    }

    /// Every value of the state, by the name first_non_finite reports it with.
    pub(crate) fn slot<'a>(e: &'a mut Entity, name: &str) -> &'a mut f64 {
        let rp = e.road_position.as_mut().expect("set above");
        match name {
            "x" => &mut e.pose.x,
            "y" => &mut e.pose.y,
            "z" => &mut e.pose.z,
            "heading" => &mut e.pose.h,
            "pitch" => &mut e.pose.p,
            "roll" => &mut e.pose.r,
            "speed" => &mut e.speed,
            "velocity x" => &mut e.velocity.translational.x,
            "velocity y" => &mut e.velocity.translational.y,
            "velocity z" => &mut e.velocity.translational.z,
            "yaw rate" => &mut e.velocity.rotational.z,
            "acceleration x" => &mut e.acceleration.translational.x,
            "acceleration y" => &mut e.acceleration.translational.y,
            "acceleration z" => &mut e.acceleration.translational.z,
            "road s" => &mut rp.s,
            "road t" => &mut rp.t,
            "lane offset" => &mut rp.offset,
            _ => unreachable!("{name}"),
        }
    }

    const NAMES: [&str; 17] = [
        "x",
        "y",
        "z",
        "heading",
        "pitch",
        "roll",
        "speed",
        "velocity x",
        "velocity y",
        "velocity z",
        "yaw rate",
        "acceleration x",
        "acceleration y",
        "acceleration z",
        "road s",
        "road t",
        "lane offset",
    ];

    /// The one-pass test agrees with the named search for each value set to NaN, +inf and
    /// −inf, and lets finite extremes through (f64::MAX everywhere: the sum overflows to +inf
    /// after the second value, and the named search finds every value finite).
    #[test]
    fn the_fast_test_finds_every_non_finite_value() {
        let e = car();
        assert!(all_finite(&e) && first_non_finite(&e).is_none());
        for name in NAMES {
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                let mut e = car();
                *slot(&mut e, name) = bad;
                assert!(!all_finite(&e), "{name} = {bad}");
                assert_eq!(first_non_finite(&e).map(|(n, _)| n), Some(name));
            }
        }
        let mut e = car();
        for name in NAMES {
            *slot(&mut e, name) = f64::MAX;
        }
        assert!(all_finite(&e) && first_non_finite(&e).is_none());
    }

    /// The sum's test gives the named search's answer for every pair of distinct values set
    /// to one of eight values, with and without a road position (136 pairs of the 17 names,
    /// 8 · 8 values each: 8,704 states per pass): finite ones that sum without overflow (1.5,
    /// −0.0, the subnormal 2⁻¹⁰⁷⁴), finite ones whose sum overflows (f64::MAX + f64::MAX =
    /// +inf and −f64::MAX − f64::MAX = −inf: the named search decides, finite), and NaN,
    /// +inf, −inf (the sum NaN or ±inf; +inf + −inf = NaN where both are set).
    #[test]
    fn the_sum_decides_as_the_named_search() {
        let values = [
            1.5,
            -0.0,
            f64::from_bits(1),
            f64::MAX,
            -f64::MAX,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        let (mut finite, mut overflowed) = (0, 0);
        for road in [true, false] {
            for (i, a) in NAMES.iter().enumerate() {
                for b in &NAMES[i + 1..] {
                    for (&x, &y) in values
                        .iter()
                        .flat_map(|x| values.iter().map(move |y| (x, y)))
                    {
                        let mut e = car();
                        *slot(&mut e, a) = x;
                        *slot(&mut e, b) = y;
                        if !road {
                            e.road_position = None;
                        }
                        let named = first_non_finite(&e).is_none();
                        assert_eq!(all_finite(&e), named, "{a} = {x}, {b} = {y}, road {road}");
                        finite += usize::from(named);
                        overflowed += usize::from(road && x.abs() == f64::MAX && x == y);
                    }
                }
            }
        }
        // With the road position every value is read: 136 pairs · 5 · 5 finite = 3,400.
        // Without it the road's three are not: of the pairs of names, C(14, 2) = 91 with
        // neither a road value (5 · 5 finite), 14 · 3 = 42 with one (5 · 8), C(3, 2) = 3 with
        // both (8 · 8): 2,275 + 1,680 + 192 = 4,147.
        assert_eq!(finite, 3_400 + 4_147);
        // The overflowing sums, with the road position: 136 pairs, both +MAX or both −MAX.
        assert_eq!(overflowed, 272);
    }
}
