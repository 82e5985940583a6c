//! What a distance-based condition measures to (OpenSCENARIO 1.3 §6.4 "Distances": an
//! entity or a position), as an OpenSCENARIO 2.0 §8.7 traffic participant with its box or a
//! point box (`freespace`), and moved along its velocity for a distance's rate. Below both
//! `measure` and `road_distance`, which measure to it.

use opendrive::{Pose, Real};

use crate::domain::{BoundingBox, MovableObject, PhysicalObject, TrafficParticipant};
use crate::position::{local_to_world, EntityView};

/// What a distance is measured to.
// A short-lived stack value built once per evaluation; boxing the view would cost an
// allocation per condition per step for nothing.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, Copy)]
pub(crate) enum Target<'a> {
    /// Another entity, with its box and motion.
    Entity(EntityView<'a>),
    /// A fixed point (a resolved Position), with no extent.
    Point(Pose),
}

/// A box of no extent at the reference point.
pub(super) fn point_box() -> BoundingBox {
    // Invariant: BoundingBox::new accepts finite, non-negative values, and these are 0.
    BoundingBox::new(crate::domain::Position3d::ZERO, 0.0, 0.0, 0.0).expect("zero box is valid")
}

impl Target<'_> {
    /// The target as a §8.7 object with its velocity (`freespace`: with its box).
    pub(super) fn participant(&self, freespace: bool) -> TrafficParticipant {
        match self {
            Target::Entity(e) => participant(e, freespace),
            Target::Point(pose) => TrafficParticipant::new(
                MovableObject::new(PhysicalObject::new(point_box(), *pose)),
                Vec::new(),
            ),
        }
    }

    /// The target moved along its velocity for `dt` seconds.
    pub(super) fn advanced(&self, dt: Real) -> Self {
        match self {
            Target::Entity(e) => Target::Entity(advanced(e, dt)),
            Target::Point(p) => Target::Point(*p),
        }
    }
}

/// The entity as a §8.7 traffic participant; with a point box unless `freespace`.
pub(super) fn participant(e: &EntityView<'_>, freespace: bool) -> TrafficParticipant {
    let mut p = e.traffic_participant();
    if !freespace {
        p.movable.object.bounding_box = point_box();
    }
    p
}

/// The entity moved along its world velocity for `dt` seconds (pose only).
pub(super) fn advanced<'a>(e: &EntityView<'a>, dt: Real) -> EntityView<'a> {
    let v = e.velocity.translational;
    let [vx, vy, vz] = local_to_world(&e.pose, v.x, v.y, v.z);
    let mut moved = *e;
    moved.pose.x += vx * dt;
    moved.pose.y += vy * dt;
    moved.pose.z += vz * dt;
    moved
}
