//! OpenSCENARIO 2.0 §8.7 actors side by side: [`Actor`], one of the instantiable actors
//! (stationary_object, movable_object, vehicle, person, animal), and the parts every kind
//! shares. Above both `object` and `vehicle`, whose types it holds.

use super::object::{
    Animal, MovableObject, Person, Physical, PhysicalObject, StationaryObject, TrafficParticipant,
};
use super::{Vehicle, Velocity6d};

/// One instantiable actor of §8.7 (stationary_object, movable_object, vehicle, person,
/// animal), for stores that hold all kinds side by side.
#[derive(Debug, Clone, PartialEq)]
pub enum Actor {
    /// §8.7.3
    StationaryObject(StationaryObject),
    /// §8.7.4
    MovableObject(MovableObject),
    /// §8.7.6
    Vehicle(Vehicle),
    /// §8.7.7
    Person(Person),
    /// §8.7.8
    Animal(Animal),
}

impl Actor {
    /// The traffic_participant part (§8.7.5), if the actor is one.
    pub fn traffic_participant(&self) -> Option<&TrafficParticipant> {
        match self {
            Actor::Vehicle(v) => Some(&v.participant),
            Actor::Person(p) => Some(&p.participant),
            Actor::Animal(a) => Some(&a.participant),
            Actor::StationaryObject(_) | Actor::MovableObject(_) => None,
        }
    }

    /// The movable_object part (§8.7.4), if the actor can move.
    pub fn movable_object(&self) -> Option<&MovableObject> {
        match self {
            Actor::MovableObject(m) => Some(m),
            Actor::StationaryObject(_) => None,
            _ => self.traffic_participant().map(|t| &t.movable),
        }
    }

    /// Mutable movable_object part (§8.7.4), for the runtime to move the actor.
    pub fn movable_object_mut(&mut self) -> Option<&mut MovableObject> {
        match self {
            Actor::MovableObject(m) => Some(m),
            Actor::StationaryObject(_) => None,
            Actor::Vehicle(v) => Some(&mut v.participant.movable),
            Actor::Person(p) => Some(&mut p.participant.movable),
            Actor::Animal(a) => Some(&mut a.participant.movable),
        }
    }
}

impl Physical for Actor {
    fn physical_object(&self) -> &PhysicalObject {
        match self {
            Actor::StationaryObject(s) => s,
            Actor::MovableObject(m) => &m.object,
            Actor::Vehicle(v) => v.physical_object(),
            Actor::Person(p) => p.physical_object(),
            Actor::Animal(a) => a.physical_object(),
        }
    }
    fn velocity(&self) -> Velocity6d {
        self.movable_object()
            .map_or(Velocity6d::ZERO, |m| m.velocity)
    }
}
