//! OpenSCENARIO 2.0 §8.7.18.1 actor vehicle_group (non-normative): "a list of vehicles being
//! part of this group", used "to create multiple vehicles with predefined initial conditions,
//! for example a single-lane or convoy formation".
//!
//! oscsim's helper builds the single-lane formation: copies of one template vehicle placed
//! one behind the other on the centre line of one lane, heading in the lane's driving
//! direction (OpenDRIVE 1.8 §11.2), with a given bumper-to-bumper gap. The group stays on
//! the one road; a vehicle that would fall off its start or end is an error.

use std::f64::consts::PI;

use opendrive::{normalize_angle, Direction, Real, RoadNetwork};

use super::{DomainError, DomainErrorKind, Vehicle};

/// §8.7.18.1 vehicle_group: the vehicles of a group.
#[derive(Debug, Clone, PartialEq)]
pub struct VehicleGroup {
    /// §8.7.18.1 `vehicles`, the first one at the head of the formation.
    pub vehicles: Vec<Vehicle>,
}

impl VehicleGroup {
    /// `count` copies of `template` in lane `lane_id` of road `road_id`: the head's reference
    /// point at `s_head`, each following vehicle's bounding box `gap` metres behind the one
    /// ahead (so reference points are `length + gap` apart along s), all centred in the lane
    /// and heading in its driving direction. Velocity and acceleration are the template's.
    ///
    /// Errors with `InvalidParameter` for a negative or non-finite gap or a zero spacing (box
    /// length + gap), and `LanePosition` when the lane does not exist at some vehicle's s or
    /// the formation reaches beyond the road (reported at the last vehicle's s).
    pub fn single_lane(
        network: &RoadNetwork,
        template: &Vehicle,
        count: usize,
        road_id: &str,
        lane_id: i32,
        s_head: Real,
        gap: Real,
    ) -> Result<Self, DomainError> {
        if !(gap.is_finite() && gap >= 0.0) {
            return Err(DomainError::parameter(
                "vehicle_group gap",
                "a finite length >= 0 m",
                gap,
            ));
        }
        let off_lane = |s: Real| {
            DomainError::new(DomainErrorKind::LanePosition {
                road_id: road_id.to_string(),
                lane_id,
                s,
            })
        };
        let handle = network
            .lane_handle(road_id, lane_id, s_head)
            .filter(|_| lane_id != 0)
            .ok_or_else(|| off_lane(s_head))?;
        // Followers lie behind the head, i.e. against the driving direction.
        let (behind, turn) = match network.driving_direction(handle) {
            Direction::Forward => (-1.0, 0.0),
            Direction::Backward => (1.0, PI),
        };
        let pitch = template.participant.bounding_box.length() + gap;
        if pitch <= 0.0 {
            return Err(DomainError::parameter(
                "vehicle_group spacing (bounding_box.length + gap)",
                "a length > 0 m",
                pitch,
            ));
        }
        // The last vehicle first: a formation longer than the road fails before any work.
        let last = s_head + behind * pitch * count.saturating_sub(1) as Real;
        let road = network.road(road_id).ok_or_else(|| off_lane(s_head))?;
        if !(0.0..=road.length).contains(&last) {
            return Err(off_lane(last));
        }
        let mut vehicles = Vec::with_capacity(count);
        for i in 0..count {
            let s = s_head + behind * pitch * i as Real;
            if network.lane_handle(road_id, lane_id, s).is_none() {
                return Err(off_lane(s));
            }
            let mut pose = network
                .lane_pose(road_id, lane_id, s, 0.0)
                .map_err(|_| off_lane(s))?;
            pose.h = normalize_angle(pose.h + turn);
            let mut v = template.clone();
            v.participant.movable.object.pose = pose;
            vehicles.push(v);
        }
        Ok(Self { vehicles })
    }
}
