//! Mapping from the OpenSCENARIO 1.x entities (OpenSCENARIO 1.3 §7.2 "Entities"; XSD
//! `Vehicle`, `Pedestrian`, `MiscObject`, `BoundingBox`, `Axles`) onto the 2.0 §8.7 actors.
//!
//! | 1.x | 2.0 §8.7 |
//! | --- | --- |
//! | `BoundingBox` (Center, Dimensions) | bounding_box (center, length, width, height); centre of gravity = box centre (§8.7.2 allows it when unknown) |
//! | `model3d` | geometry_reference |
//! | `Vehicle` car, van | vehicle, `car` (van is UN N1, in the seed's car row), infrastructure `driving` |
//! | `Vehicle` bus / truck | `bus` / `truck`, `driving` |
//! | `Vehicle` trailer, semitrailer | `trailer`, `driving` |
//! | `Vehicle` bicycle / motorbike | `vru_vehicle`, `biking` / `driving`; one wheel per axle |
//! | `Vehicle` tram / train | `other` (rail vehicles; the seed's vehicle is a road vehicle), `tram` / `rail` |
//! | `Axles` | axles: FrontAxle, RearAxle, AdditionalAxle in that order; two wheels per axle unless a two-wheeler |
//! | `Pedestrian` pedestrian | person, `sidewalk` |
//! | `Pedestrian` wheelchair | vehicle `vru_vehicle` (the seed names wheelchairs there), no axles, `sidewalk` |
//! | `Pedestrian` animal | animal, no intended infrastructure |
//! | `MiscObject` obstacle, none, wind | movable_object (not anchored: a rock, a box) |
//! | `MiscObject` other categories (barrier, building, pole, tree, …) | stationary_object at its initial pose |
//!
//! 1.x has no colour for entities, so `color` stays unset; `ExternalObjectReference` objects
//! (they live in the road network, without a bounding box here) are not mapped. A 1.3
//! `Trailer` is an entity of its own and maps like any vehicle; the hitch/coupler joint has
//! no counterpart in §8.7 and is left to the runtime.

use opendrive::Pose;
use scenario::{EntityObject, MiscObjectCategory, PedestrianCategory, ScenarioObject};

use super::{
    Actor, Animal, Axle, BoundingBox, DomainError, DomainErrorKind, IntendedInfrastructure,
    MovableObject, Person, PhysicalObject, Position3d, StationaryObject, TrafficParticipant,
    Vehicle, VehicleCategory,
};

impl BoundingBox {
    /// The 2.0 bounding_box (§8.7.9) of a 1.x `BoundingBox`; errors like [`BoundingBox::new`].
    pub fn from_scenario(bb: &scenario::BoundingBox) -> Result<Self, DomainError> {
        let [x, y, z] = bb.center;
        BoundingBox::new(Position3d::new(x, y, z), bb.length, bb.width, bb.height)
    }
}

impl VehicleCategory {
    /// The §8.7.12 vehicle_category of a 1.x `vehicleCategory` (see the module table).
    pub fn from_scenario(c: scenario::VehicleCategory) -> Self {
        use scenario::VehicleCategory as C;
        match c {
            C::Car | C::Van => VehicleCategory::Car,
            C::Bus => VehicleCategory::Bus,
            C::Truck => VehicleCategory::Truck,
            C::Trailer | C::Semitrailer => VehicleCategory::Trailer,
            C::Bicycle | C::Motorbike => VehicleCategory::VruVehicle,
            // Tram, train, and categories later versions may add.
            _ => VehicleCategory::Other,
        }
    }
}

/// The §8.7.13 intended_infrastructure of a 1.x vehicle category (see the module table).
fn vehicle_infrastructure(c: scenario::VehicleCategory) -> IntendedInfrastructure {
    use scenario::VehicleCategory as C;
    match c {
        C::Bicycle => IntendedInfrastructure::Biking,
        C::Tram => IntendedInfrastructure::Tram,
        C::Train => IntendedInfrastructure::Rail,
        _ => IntendedInfrastructure::Driving,
    }
}

/// The physical_object part: box, model reference, pose.
fn physical(
    bb: &scenario::BoundingBox,
    model3d: &Option<String>,
    pose: Pose,
) -> Result<PhysicalObject, DomainError> {
    let mut object = PhysicalObject::new(BoundingBox::from_scenario(bb)?, pose);
    object.geometry_reference = model3d.clone();
    Ok(object)
}

fn participant(
    object: PhysicalObject,
    infrastructure: Vec<IntendedInfrastructure>,
) -> TrafficParticipant {
    TrafficParticipant::new(MovableObject::new(object), infrastructure)
}

impl Vehicle {
    /// The §8.7.6 vehicle of a 1.x `Vehicle`, at rest at `pose` (see the module table).
    pub fn from_scenario(v: &scenario::Vehicle, pose: Pose) -> Result<Self, DomainError> {
        let object = physical(&v.bounding_box, &v.model3d, pose)?;
        let infrastructure = vec![vehicle_infrastructure(v.vehicle_category)];
        let two_wheeler = matches!(
            v.vehicle_category,
            scenario::VehicleCategory::Bicycle | scenario::VehicleCategory::Motorbike
        );
        let wheels = if two_wheeler { 1 } else { 2 };
        let axle = |a: &scenario::Axle| Axle {
            max_steering: a.max_steering,
            wheel_diameter: a.wheel_diameter,
            track_width: a.track_width,
            position_x: a.position_x,
            position_z: a.position_z,
            number_of_wheels: wheels,
        };
        let axles = v
            .axles
            .front_axle
            .iter()
            .chain(std::iter::once(&v.axles.rear_axle))
            .chain(&v.axles.additional_axles)
            .map(axle)
            .collect();
        Vehicle::new(
            participant(object, infrastructure),
            VehicleCategory::from_scenario(v.vehicle_category),
            axles,
        )
    }
}

impl Actor {
    /// The §8.7 actor for a 1.x scenario object at its initial `pose` (see the module table).
    /// Errors with `UnsupportedEntity` for an `ExternalObjectReference`, and with the
    /// bounding-box errors for invalid dimensions.
    pub fn from_scenario(object: &ScenarioObject, pose: Pose) -> Result<Self, DomainError> {
        match &object.entity_object {
            EntityObject::Vehicle(v) => Ok(Actor::Vehicle(Vehicle::from_scenario(v, pose)?)),
            EntityObject::Pedestrian(p) => {
                let o = physical(&p.bounding_box, &p.model3d, pose)?;
                Ok(match p.pedestrian_category {
                    PedestrianCategory::Animal => Actor::Animal(Animal {
                        participant: participant(o, Vec::new()),
                    }),
                    PedestrianCategory::Wheelchair => Actor::Vehicle(Vehicle::new(
                        participant(o, vec![IntendedInfrastructure::Sidewalk]),
                        VehicleCategory::VruVehicle,
                        Vec::new(),
                    )?),
                    // `pedestrian`, and categories later versions may add: a person.
                    _ => Actor::Person(Person {
                        participant: participant(o, vec![IntendedInfrastructure::Sidewalk]),
                    }),
                })
            }
            EntityObject::MiscObject(m) => {
                let o = physical(&m.bounding_box, &m.model3d, pose)?;
                Ok(match m.misc_object_category {
                    MiscObjectCategory::Obstacle
                    | MiscObjectCategory::None
                    | MiscObjectCategory::Wind => Actor::MovableObject(MovableObject::new(o)),
                    _ => Actor::StationaryObject(StationaryObject::location(o, pose)),
                })
            }
            _ => Err(DomainError::new(DomainErrorKind::UnsupportedEntity {
                name: object.name.clone(),
            })),
        }
    }
}
