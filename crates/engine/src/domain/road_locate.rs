//! Where an object is on the road network, and how one object's road s/t maps onto another's:
//! the shared ground of the road-based methods of OpenSCENARIO 2.0 §8.7 (get_s_coord …,
//! time_headway, space_gap).
//!
//! "Along s" between two objects (§8.7.5.1.2, §8.7.5.1.3): on one road it is that road's s.
//! On different roads joined by road links or junctions, oscsim extends the calling object's
//! road s-axis along the shortest path along roads (`road_path`) between the two road
//! positions: a point of the reference's road is placed on that extended axis at its distance
//! along the path. Its t keeps its sign when the path runs along both roads' s the same way,
//! and flips otherwise.

use opendrive::{Real, RoadHandle, RoadNetwork, RoadPoint, RoadPosition, LENGTH_EPSILON};

use super::road_path::shortest_road_path;
use super::{DomainError, DomainErrorKind, PhysicalObject};

/// The road position of `object`'s reference point (§8.7.2 `pose`), its heading choosing
/// between overlapping roads; `NotOnRoad` when the point lies off every road surface.
pub(crate) fn locate(
    network: &RoadNetwork,
    object: &PhysicalObject,
) -> Result<RoadPosition, DomainError> {
    locate_point(network, object).map(|p| network.road_position(&p))
}

/// [`locate`] with the road as a handle (no allocation); the same point.
pub(crate) fn locate_point(
    network: &RoadNetwork,
    object: &PhysicalObject,
) -> Result<RoadPoint, DomainError> {
    let p = &object.pose;
    match network.locate_point(p.x, p.y, Some(p.h)) {
        Some(pos) if pos.distance <= LENGTH_EPSILON => Ok(pos),
        _ => Err(DomainError::at(DomainErrorKind::NotOnRoad, p.x, p.y)),
    }
}

/// The world point (x, y) projected onto road `road` (s and t; the point may lie beside the
/// road surface, as a box corner may).
pub(crate) fn project(
    network: &RoadNetwork,
    road: RoadHandle,
    x: Real,
    y: Real,
) -> Result<(Real, Real), DomainError> {
    network
        .locate_point_on_road(road, x, y)
        .map(|p| (p.s, p.t))
        .ok_or_else(|| DomainError::at(DomainErrorKind::NotOnRoad, x, y))
}

/// An affine map from (s, t) of the reference's road to the caller's extended s/t axes:
/// `s' = offset + flip · s`, `t' = flip · t`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct AxisMap {
    offset: Real,
    flip: Real,
}

impl AxisMap {
    /// The identity (both on one road).
    const IDENTITY: AxisMap = AxisMap {
        offset: 0.0,
        flip: 1.0,
    };

    /// (s, t) of the reference's road on the caller's axes.
    pub(crate) fn apply(&self, s: Real, t: Real) -> (Real, Real) {
        (self.offset + self.flip * s, self.flip * t)
    }

    /// [`between`](Self::between) for positions given by road handle: the identity without a
    /// look-up when both are on one road, else the road ids are looked up for the path.
    pub(crate) fn between_points(
        network: &RoadNetwork,
        caller: &RoadPoint,
        reference: &RoadPoint,
    ) -> Result<AxisMap, DomainError> {
        if caller.road == reference.road {
            return Ok(Self::IDENTITY);
        }
        Self::between(
            network,
            &network.road_position(caller),
            &network.road_position(reference),
        )
    }

    /// The map for `caller` and `reference` positions; see the module doc.
    pub(crate) fn between(
        network: &RoadNetwork,
        caller: &RoadPosition,
        reference: &RoadPosition,
    ) -> Result<AxisMap, DomainError> {
        if caller.road_id == reference.road_id {
            return Ok(Self::IDENTITY);
        }
        // The caller is at path distance 0 and leaves its road in direction d_c; the
        // reference is at `length`, on a road run in direction d_r. A point at s of the
        // reference's road lies at length + d_r·(s − s_r) along the path, which on the
        // caller's axis is s_c + d_c·(that distance).
        if let Some(path) = shortest_road_path(
            network,
            &caller.road_id,
            caller.s,
            &reference.road_id,
            reference.s,
        ) {
            let (dc, dr) = (path.start_direction, path.end_direction);
            let flip = dc * dr;
            return Ok(AxisMap {
                offset: caller.s + dc * path.length - flip * reference.s,
                flip,
            });
        }
        Err(DomainError::new(DomainErrorKind::NoRouteBetween {
            from: caller.road_id.clone(),
            to: reference.road_id.clone(),
        }))
    }
}
