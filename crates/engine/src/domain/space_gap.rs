//! OpenSCENARIO 2.0 §8.7.5.1.3 method space_gap(): the space distance between the
//! bounding boxes of the calling traffic participant and a reference physical_object, as a
//! relative s-coordinate (longitudinal; positive when the caller is ahead of the reference)
//! or t-coordinate (lateral; positive when the caller is left of the reference).
//!
//! Road coordinates of a box: the four corners of its ground-plane footprint (see
//! `footprint`) are projected onto the road its reference point is on
//! (`RoadNetwork::locate_on_road`); the extreme s and t of the corners bound the box. The
//! reference's corners are then carried onto the caller's extended axes (`road_locate`), so
//! two objects on roads joined by a junction are compared along the roads. On a circular arc
//! the extreme s of a rectangle lies at a corner, so the longitudinal interval is exact; the
//! extreme t may lie inside an edge, and the corners miss it by at most the sagitta
//! L² / (8 R) (2 cm for a 4 m box at R = 100 m).
//!
//! The gap: with the caller's interval [a0, a1] and the reference's [b0, b1] on the chosen
//! axis, the caller is ahead (left) when its interval's midpoint is beyond the reference's;
//! the gap is then a0 − b1 (the classical bumper-to-bumper gap seen from the front
//! object), and otherwise a1 − b0. Separated boxes give |gap| = the clear distance, signed by
//! who is ahead. Overlapping intervals give, from the object ahead, a negative gap whose
//! magnitude is the overlap; from the object behind, the same with a positive sign. Either
//! way `space_gap(A, B) = −space_gap(B, A)` (exactly on one road, to round-off across roads);
//! coinciding midpoints, where neither is ahead, give 0.

use opendrive::{Real, RoadNetwork};

use super::road_locate::{locate, project, AxisMap};
use super::{DistanceDirection, DomainError, Physical, PhysicalObject, TrafficParticipant};

impl TrafficParticipant {
    /// §8.7.5.1.3 `space_gap(reference, direction)`, m; see the module doc for the box
    /// projection and the sign. Errors when either object is off the roads (`NotOnRoad`) or
    /// their roads are not joined (`NoRouteBetween`).
    pub fn space_gap(
        &self,
        network: &RoadNetwork,
        reference: &impl Physical,
        direction: DistanceDirection,
    ) -> Result<Real, DomainError> {
        let a = self.physical_object();
        let b = reference.physical_object();
        let caller = locate(network, a)?;
        let other = locate(network, b)?;
        let map = AxisMap::between(network, &caller, &other)?;
        let axis = match direction {
            DistanceDirection::Longitudinal => 0,
            DistanceDirection::Lateral => 1,
        };
        let own = road_interval(network, a, &caller.road_id, None, axis)?;
        let theirs = road_interval(network, b, &other.road_id, Some(&map), axis)?;
        Ok(signed_gap(own, theirs))
    }
}

/// The (min, max) of s (axis 0) or t (axis 1) over the footprint corners of `object`
/// projected onto `road_id`, carried through `map` when given.
fn road_interval(
    network: &RoadNetwork,
    object: &PhysicalObject,
    road_id: &str,
    map: Option<&AxisMap>,
    axis: usize,
) -> Result<(Real, Real), DomainError> {
    let (mut lo, mut hi) = (Real::INFINITY, Real::NEG_INFINITY);
    for [x, y] in object.bounding_box.footprint(&object.pose).corners() {
        let (s, t) = project(network, road_id, x, y)?;
        let (s, t) = map.map_or((s, t), |m| m.apply(s, t));
        let v = if axis == 0 { s } else { t };
        lo = lo.min(v);
        hi = hi.max(v);
    }
    Ok((lo, hi))
}

/// The gap from interval `own` to `other`, positive when `own` is ahead; see the module doc.
pub(crate) fn signed_gap(own: (Real, Real), other: (Real, Real)) -> Real {
    let (own_mid, other_mid) = (own.0 + own.1, other.0 + other.1);
    if own_mid > other_mid {
        own.0 - other.1
    } else if own_mid < other_mid {
        own.1 - other.0
    } else {
        0.0
    }
}
