//! OpenSCENARIO 2.0 §8.7.5.1.3 method space_gap(): the space distance between the
//! bounding boxes of the calling traffic participant and a reference physical_object, as a
//! relative s-coordinate (longitudinal; positive when the caller is ahead of the reference)
//! or t-coordinate (lateral; positive when the caller is left of the reference).
//!
//! Road coordinates of a box: the four corners of its ground-plane footprint (see
//! `footprint`) are projected onto the road its reference point is on
//! (`RoadNetwork::locate_point_on_road`); the extreme s and t of the corners bound the box. The
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
//!
//! A caller measuring several gaps between the same two objects (a distance condition wants
//! the boxes' gap and the reference points' order, or both axes) locates them once:
//! `RoadPair` holds the roads found and the axis map, and gives each gap from them.

use opendrive::{Real, RoadHandle, RoadNetwork};

use super::road_locate::{locate_point, project, AxisMap};
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
        let (a, b) = (self.physical_object(), reference.physical_object());
        RoadPair::locate(network, a, b)?.space_gap(network, a, b, direction)
    }
}

/// The (min, max) of one road coordinate over a box's corners, m.
pub(crate) type Interval = (Real, Real);

/// Two objects located on the roads for space_gap: the road of each reference point and the
/// map of the reference's road onto the caller's extended axes (`road_locate`). Valid for
/// any objects at the same two reference poses (their boxes may differ).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RoadPair {
    caller: RoadHandle,
    other: RoadHandle,
    map: AxisMap,
}

impl RoadPair {
    /// Locates caller `a` and reference `b`; errors as [`TrafficParticipant::space_gap`].
    pub(crate) fn locate(
        network: &RoadNetwork,
        a: &PhysicalObject,
        b: &PhysicalObject,
    ) -> Result<Self, DomainError> {
        let caller = locate_point(network, a)?;
        let other = locate_point(network, b)?;
        let map = AxisMap::between_points(network, &caller, &other)?;
        Ok(RoadPair {
            caller: caller.road,
            other: other.road,
            map,
        })
    }

    /// §8.7.5.1.3 space_gap of `a` to `b`, which stand at the poses this pair was located at.
    pub(crate) fn space_gap(
        &self,
        network: &RoadNetwork,
        a: &PhysicalObject,
        b: &PhysicalObject,
        direction: DistanceDirection,
    ) -> Result<Real, DomainError> {
        let (own, theirs) = self.intervals(network, a, b, direction)?;
        Ok(signed_gap(own, theirs))
    }

    /// The (min, max) road coordinate along `direction` of the footprint corners of `a` and
    /// of `b` on the caller's axes: the intervals whose [`signed_gap`] is the space_gap.
    pub(crate) fn intervals(
        &self,
        network: &RoadNetwork,
        a: &PhysicalObject,
        b: &PhysicalObject,
        direction: DistanceDirection,
    ) -> Result<(Interval, Interval), DomainError> {
        let axis = match direction {
            DistanceDirection::Longitudinal => 0,
            DistanceDirection::Lateral => 1,
        };
        let own = road_interval(network, a, self.caller, None, axis)?;
        let theirs = road_interval(network, b, self.other, Some(&self.map), axis)?;
        Ok((own, theirs))
    }
}

/// The (min, max) of s (axis 0) or t (axis 1) over the footprint corners of `object`
/// projected onto `road`, carried through `map` when given. A corner equal (bit for bit) to
/// the one before it is not projected again: a box of no extent has four equal corners.
fn road_interval(
    network: &RoadNetwork,
    object: &PhysicalObject,
    road: RoadHandle,
    map: Option<&AxisMap>,
    axis: usize,
) -> Result<Interval, DomainError> {
    let (mut lo, mut hi) = (Real::INFINITY, Real::NEG_INFINITY);
    let mut last: Option<([u64; 2], (Real, Real))> = None;
    for [x, y] in object.bounding_box.footprint(&object.pose).corners() {
        let key = [x.to_bits(), y.to_bits()];
        let (s, t) = match last {
            Some((k, st)) if k == key => st,
            _ => project(network, road, x, y)?,
        };
        last = Some((key, (s, t)));
        let (s, t) = map.map_or((s, t), |m| m.apply(s, t));
        let v = if axis == 0 { s } else { t };
        lo = lo.min(v);
        hi = hi.max(v);
    }
    Ok((lo, hi))
}

/// The gap from interval `own` to `other`, positive when `own` is ahead; see the module doc.
pub(crate) fn signed_gap(own: Interval, other: Interval) -> Real {
    let (own_mid, other_mid) = (own.0 + own.1, other.0 + other.1);
    if own_mid > other_mid {
        own.0 - other.1
    } else if own_mid < other_mid {
        own.1 - other.0
    } else {
        0.0
    }
}
