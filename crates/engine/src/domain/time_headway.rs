//! OpenSCENARIO 2.0 §8.7.5.1.2 method time_headway(): "the time distance between traffic
//! participant and reference physical_object, measured from reference point to reference
//! point along s-coordinate, assuming the reference physical_object keeps moving with its
//! current speed".
//!
//! oscsim's reading (pitfall 12: say who measures and with which sign): the calling vehicle
//! measures. Δs is the reference's reference point minus the caller's along the caller's road
//! s-axis (extended across links and junctions, see `road_locate`), counted positive in the
//! caller's direction of travel (the road's +s when the caller's heading is within 90° of the
//! road's, −s otherwise). The headway is the time the caller needs at its current speed to
//! reach the point where the reference is now, `Δs / speed`: the classical time gap, i.e. the
//! time between the reference and the caller passing the same point when the reference keeps
//! moving (its speed therefore does not enter). It is positive when the reference is ahead and
//! the caller drives towards it, negative when the reference is behind (the time since the
//! caller was there), and `None` when the caller stands still (speed exactly 0: it never gets
//! there) or its speed is not finite. Measured along the road, not straight (esmini #139).

use opendrive::{Real, RoadNetwork, RoadPosition};

use super::road_locate::{locate, AxisMap};
use super::{DomainError, Physical, Vehicle};

impl Vehicle {
    /// §8.7.5.1.2 `time_headway(reference)`, s; see the module doc for the definition and
    /// sign. Errors when either object is off the roads (`NotOnRoad`) or their roads are not
    /// joined (`NoRouteBetween`).
    pub fn time_headway(
        &self,
        network: &RoadNetwork,
        reference: &impl Physical,
    ) -> Result<Option<Real>, DomainError> {
        let caller = locate(network, self.physical_object())?;
        let other = locate(network, reference.physical_object())?;
        time_headway_between(network, &caller, self.speed(), &other)
    }
}

/// [`Vehicle::time_headway`] for a caller and a reference whose road positions are known (the
/// runtime has located every entity already): the caller's road position (its
/// `relative_heading` gives the direction of travel) and signed speed, and the reference's
/// road position.
pub fn time_headway_between(
    network: &RoadNetwork,
    caller: &RoadPosition,
    speed: Real,
    reference: &RoadPosition,
) -> Result<Option<Real>, DomainError> {
    let map = AxisMap::between(network, caller, reference)?;
    let (s_reference, _) = map.apply(reference.s, reference.t);
    let travel = if caller.relative_heading.cos() >= 0.0 {
        1.0
    } else {
        -1.0
    };
    let ahead = travel * (s_reference - caller.s);
    Ok((speed != 0.0 && speed.is_finite()).then(|| ahead / speed))
}
