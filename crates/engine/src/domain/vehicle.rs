//! OpenSCENARIO 2.0 §8.7.6 actor vehicle and §8.7.10 struct axle.

use opendrive::Real;

use super::object::traffic_participant_child;
use super::{
    DomainError, Physical, PhysicalObject, TrafficParticipant, VehicleCategory, Velocity6d,
};
use std::ops::{Deref, DerefMut};

/// §8.7.10 axle: taken from OpenSCENARIO 1.x `Axle` plus the number of wheels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axle {
    /// Maximum steering angle of the wheels on the axle, rad.
    pub max_steering: Real,
    /// Diameter of the wheels on the axle, m.
    pub wheel_diameter: Real,
    /// Distance between the centre lines of the outer wheels on opposing sides, m.
    pub track_width: Real,
    /// Position of the axle along the vehicle's x axis, m; the rear axle of a two-axle
    /// vehicle has 0.
    pub position_x: Real,
    /// Position of the axle along the vehicle's z axis, m.
    pub position_z: Real,
    /// Number of wheels on the axle (2 for a car axle, 1 for a motorcycle's, 4 for twin
    /// tyres).
    pub number_of_wheels: u32,
}

/// §8.7.6 vehicle: a land vehicle for people or cargo; a traffic_participant with a
/// category, axles and a rear overhang.
#[derive(Debug, Clone, PartialEq)]
pub struct Vehicle {
    /// The inherited traffic_participant (§8.7.6 Table 35).
    pub participant: TrafficParticipant,
    /// §8.7.6 `vehicle_category`.
    pub vehicle_category: VehicleCategory,
    /// §8.7.6 `axles`, front to rear as given.
    pub axles: Vec<Axle>,
    /// §8.7.6 `rear_overhang`: horizontal distance from the rear end of the bounding box to the
    /// centre of the rear axle, m.
    pub rear_overhang: Real,
}

impl Vehicle {
    /// A vehicle with the rear overhang taken from its bounding box and axles: the rear axle
    /// is the one with the smallest `position_x` (0, the reference point, without axles) and
    /// the box's rear end lies at `center.x − length / 2`, so `rear_overhang = rear_x −
    /// (center.x − length / 2)` (§8.7.6). Errors when that is negative (the box ends ahead of
    /// the rear axle).
    pub fn new(
        participant: TrafficParticipant,
        vehicle_category: VehicleCategory,
        axles: Vec<Axle>,
    ) -> Result<Self, DomainError> {
        let bb = participant.bounding_box;
        let rear_x = axles
            .iter()
            .map(|a| a.position_x)
            .reduce(Real::min)
            .unwrap_or(0.0);
        let rear_overhang = rear_x - (bb.center().x - 0.5 * bb.length());
        if rear_overhang < 0.0 {
            return Err(DomainError::parameter(
                "rear_overhang",
                "a length >= 0 m (bounding box reaching behind the rear axle)",
                rear_overhang,
            ));
        }
        Ok(Self {
            participant,
            vehicle_category,
            axles,
            rear_overhang,
        })
    }
}

traffic_participant_child!(Vehicle);
