//! The actors of OpenSCENARIO 2.0 §8.7.2–8.7.5, 8.7.7 and 8.7.8: physical_object,
//! stationary_object, movable_object, traffic_participant, person and animal (vehicle, with
//! its own parameters, is in `vehicle`).
//!
//! The seed's inheritance (its "inherited parameters and variables" tables) is modelled by
//! composition plus `Deref` to the parent: a `Vehicle` derefs to its `TrafficParticipant`,
//! which derefs to its `MovableObject`, which derefs to its `PhysicalObject`, so
//! `vehicle.pose` and `vehicle.speed()` read as in the seed. `StationaryObject` has `Deref` but
//! no `DerefMut`: its location is fixed for the whole scenario (§8.7.3.1.1). A method that
//! takes "a reference physical_object" accepts any actor through the `Physical` trait, which
//! also supplies the velocity (zero for anything that cannot move).

use std::ops::{Deref, DerefMut};

use opendrive::{Pose, Real};

use super::{Acceleration6d, BoundingBox, Color, IntendedInfrastructure, Position3d, Velocity6d};

/// §8.7.2 physical_object: a tangible object close to earth; its parameters and its state
/// variable `pose`.
#[derive(Debug, Clone, PartialEq)]
pub struct PhysicalObject {
    /// §8.7.2 `bounding_box` (mandatory).
    pub bounding_box: BoundingBox,
    /// §8.7.2 `color` (optional).
    pub color: Option<Color>,
    /// §8.7.2 `geometry_reference` (optional): opaque reference of a 3D model; oscsim fills it
    /// from OpenSCENARIO 1.x `model3d`.
    pub geometry_reference: Option<String>,
    /// §8.7.2 `center_of_gravity` (mandatory), object coordinates, m.
    pub center_of_gravity: Position3d,
    /// §8.7.2 state variable `pose`: position and orientation of the object's reference
    /// point in world coordinates.
    pub pose: Pose,
}

impl PhysicalObject {
    /// An object with `bounding_box` at `pose`, no colour, no geometry reference, and the
    /// centre of gravity at the box's centre, as §8.7.2 allows when it is unknown.
    pub fn new(bounding_box: BoundingBox, pose: Pose) -> Self {
        Self {
            center_of_gravity: bounding_box.center(),
            bounding_box,
            color: None,
            geometry_reference: None,
            pose,
        }
    }
}

/// Anything that can be the reference object of a §8.7 method: a physical_object and its
/// current velocity (§8.7.4 `velocity`; zero for objects that cannot move).
pub trait Physical {
    /// The physical_object part (§8.7.2).
    fn physical_object(&self) -> &PhysicalObject;

    /// The current velocity_6d in object coordinates (§8.7.4); zero unless movable.
    fn velocity(&self) -> Velocity6d {
        Velocity6d::ZERO
    }
}

impl Physical for PhysicalObject {
    fn physical_object(&self) -> &PhysicalObject {
        self
    }
}

/// §8.7.3 stationary_object: anchored; its location is set once (modifier `location()`,
/// §8.7.3.1.1) and cannot change during the scenario, so this type gives read access only.
#[derive(Debug, Clone, PartialEq)]
pub struct StationaryObject {
    object: PhysicalObject,
}

impl StationaryObject {
    /// §8.7.3.1.1 `location(pose)`: `object` placed at `pose` for the whole scenario.
    pub fn location(mut object: PhysicalObject, pose: Pose) -> Self {
        object.pose = pose;
        Self { object }
    }
}

impl Deref for StationaryObject {
    type Target = PhysicalObject;
    fn deref(&self) -> &PhysicalObject {
        &self.object
    }
}

impl Physical for StationaryObject {
    fn physical_object(&self) -> &PhysicalObject {
        &self.object
    }
}

/// §8.7.4 movable_object: not anchored; adds the state variables `velocity` and
/// `acceleration` (and `speed`, derived from velocity).
#[derive(Debug, Clone, PartialEq)]
pub struct MovableObject {
    /// The inherited physical_object (§8.7.4 Table 25).
    pub object: PhysicalObject,
    /// §8.7.4 `velocity` in object coordinates, world as reference.
    pub velocity: Velocity6d,
    /// §8.7.4 `acceleration` in object coordinates, world as reference.
    pub acceleration: Acceleration6d,
}

impl MovableObject {
    /// `object` at rest (§8.7.4: velocity and acceleration zero).
    pub fn new(object: PhysicalObject) -> Self {
        Self {
            object,
            velocity: Velocity6d::ZERO,
            acceleration: Acceleration6d::ZERO,
        }
    }

    /// §8.7.4 `speed`: `sqrt(vx² + vy²) · sign(vx)` of `velocity.translational`, m/s.
    ///
    /// The seed does not say what sign(0) is; oscsim takes sign(0) = +1, so an object moving
    /// purely sideways (a pedestrian crossing) has a positive speed rather than 0.
    pub fn speed(&self) -> Real {
        let v = self.velocity.translational;
        let magnitude = v.x.hypot(v.y);
        if v.x < 0.0 {
            -magnitude
        } else {
            magnitude
        }
    }
}

impl Deref for MovableObject {
    type Target = PhysicalObject;
    fn deref(&self) -> &PhysicalObject {
        &self.object
    }
}

impl DerefMut for MovableObject {
    fn deref_mut(&mut self) -> &mut PhysicalObject {
        &mut self.object
    }
}

impl Physical for MovableObject {
    fn physical_object(&self) -> &PhysicalObject {
        &self.object
    }
    fn velocity(&self) -> Velocity6d {
        self.velocity
    }
}

/// §8.7.5 traffic_participant: a movable_object relevant within traffic; adds
/// `intended_infrastructure` and the methods time_to_collision and space_gap.
#[derive(Debug, Clone, PartialEq)]
pub struct TrafficParticipant {
    /// The inherited movable_object (§8.7.5 Table 29).
    pub movable: MovableObject,
    /// §8.7.5 `intended_infrastructure` (mandatory list; may hold several values).
    pub intended_infrastructure: Vec<IntendedInfrastructure>,
}

impl TrafficParticipant {
    /// `movable` with the given §8.7.5 `intended_infrastructure`.
    pub fn new(
        movable: MovableObject,
        intended_infrastructure: Vec<IntendedInfrastructure>,
    ) -> Self {
        Self {
            movable,
            intended_infrastructure,
        }
    }
}

impl Deref for TrafficParticipant {
    type Target = MovableObject;
    fn deref(&self) -> &MovableObject {
        &self.movable
    }
}

impl DerefMut for TrafficParticipant {
    fn deref_mut(&mut self) -> &mut MovableObject {
        &mut self.movable
    }
}

impl Physical for TrafficParticipant {
    fn physical_object(&self) -> &PhysicalObject {
        &self.movable.object
    }
    fn velocity(&self) -> Velocity6d {
        self.movable.velocity
    }
}

/// Implements `Deref`/`DerefMut` to `TrafficParticipant` and `Physical` for a wrapper with a
/// `participant` field (person, animal, vehicle).
macro_rules! traffic_participant_child {
    ($t:ty) => {
        impl Deref for $t {
            type Target = TrafficParticipant;
            fn deref(&self) -> &TrafficParticipant {
                &self.participant
            }
        }
        impl DerefMut for $t {
            fn deref_mut(&mut self) -> &mut TrafficParticipant {
                &mut self.participant
            }
        }
        impl Physical for $t {
            fn physical_object(&self) -> &PhysicalObject {
                &self.participant.movable.object
            }
            fn velocity(&self) -> Velocity6d {
                self.participant.movable.velocity
            }
        }
    };
}
pub(crate) use traffic_participant_child;

/// §8.7.7 person: a human being, a traffic_participant with no parameters of its own.
#[derive(Debug, Clone, PartialEq)]
pub struct Person {
    /// The inherited traffic_participant (§8.7.7 Table 37).
    pub participant: TrafficParticipant,
}

traffic_participant_child!(Person);

/// §8.7.8 animal: a living being that is not a human, a traffic_participant with no
/// parameters of its own.
#[derive(Debug, Clone, PartialEq)]
pub struct Animal {
    /// The inherited traffic_participant (§8.7.8 Table 39).
    pub participant: TrafficParticipant,
}

traffic_participant_child!(Animal);
