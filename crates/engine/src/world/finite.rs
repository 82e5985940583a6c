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

/// Whether every state value of `e` is finite, in one pass without branches: x·0 is 0 for a
/// finite x and NaN for ±inf and NaN, so the sum is 0 exactly when all are finite.
#[inline]
pub(crate) fn all_finite(e: &Entity) -> bool {
    let p = &e.pose;
    let v = &e.velocity;
    let a = &e.acceleration;
    let (s, t, offset) = e
        .road_position
        .as_ref()
        .map_or((0.0, 0.0, 0.0), |r| (r.s, r.t, r.offset));
    let values = [
        p.x,
        p.y,
        p.z,
        p.h,
        p.p,
        p.r,
        e.speed,
        v.translational.x,
        v.translational.y,
        v.translational.z,
        v.rotational.z,
        a.translational.x,
        a.translational.y,
        a.translational.z,
        s,
        t,
        offset,
    ];
    values.iter().map(|x| x * 0.0).sum::<f64>() == 0.0
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
    /// −inf, and lets finite extremes through (f64::MAX everywhere: x·0 = 0, no overflow).
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
}
