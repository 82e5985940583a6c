//! Road-coordinate positions (OpenSCENARIO 1.3 §6.3.3 road coordinate system; XSD
//! `RoadPosition`, `RelativeRoadPosition`).
//!
//! * RoadPosition: the point (s, t) of road `roadId` (OpenDRIVE s along the reference line,
//!   t positive left), on the road surface; an s past the road's ends continues on the
//!   connecting road (module `beyond`).
//! * RelativeRoadPosition: the reference entity's (s, t) on its road plus (ds, dt). Beyond the
//!   road's end the reference line continues on the road that the entity's lane continues on
//!   (`lane_walk`); where that road runs the other way, t changes sign so that the point stays
//!   on the same side. Where nothing continues, s outside the road is an error.
//!
//! Orientation: relative headings count from the road's s-tangent at the target
//! (`orientation::on_surface`).

use opendrive::{Real, RoadNetwork};
use scenario::{Orientation, SourcePos};

use super::beyond::carried;
use super::error::road_error;
use super::lane_walk::walk;
use super::orientation::on_surface;
use super::world::finite;
use super::{EntityView, PositionError, PositionErrorKind, ResolvedPosition};

/// `RoadPosition`: (road, s, t).
pub(crate) fn road(
    network: &RoadNetwork,
    road_id: &str,
    [s, t]: [Real; 2],
    orientation: Option<&Orientation>,
    pos: &SourcePos,
) -> Result<ResolvedPosition, PositionError> {
    finite(&[("s", s), ("t", t)], pos)?;
    // Past the road's ends: carried onto the connecting road (module `beyond`).
    if let Some(end) = carried(network, road_id, None, s, t) {
        let t = if end.flipped { -t } else { t };
        return road(network, &end.road_id, [end.s, t], orientation, pos);
    }
    let surface = network
        .road_pose(road_id, s, t)
        .map_err(|e| road_error(e, pos))?;
    let a = on_surface(orientation, &surface, surface.h);
    let pose = opendrive::Pose {
        h: a.h,
        p: a.p,
        r: a.r,
        ..surface
    };
    Ok(ResolvedPosition::on_road(network, road_id, pose))
}

/// `RelativeRoadPosition`: the entity's (s, t) plus (ds, dt) on its road; `reference` gives
/// the entity `entity_ref` names (`resolve::resolve_with`).
pub(crate) fn relative_road<'q>(
    network: &RoadNetwork,
    entity_ref: &str,
    reference: impl FnOnce(&str) -> Result<EntityView<'q>, PositionError>,
    [ds, dt]: [Real; 2],
    orientation: Option<&Orientation>,
    pos: &SourcePos,
) -> Result<ResolvedPosition, PositionError> {
    finite(&[("ds", ds), ("dt", dt)], pos)?;
    let e = reference(entity_ref)?;
    let rp = e.road_position.ok_or_else(|| {
        PositionError::new(PositionErrorKind::EntityOffRoad(entity_ref.into()), pos)
    })?;
    let inside = network
        .road(&rp.road_id)
        .is_some_and(|r| (0.0..=r.length).contains(&(rp.s + ds)));
    if !inside {
        if let Some(end) = walk(network, &rp.road_id, rp.lane_id, rp.s, ds) {
            let t = if end.flipped { -(rp.t + dt) } else { rp.t + dt };
            return road(network, &end.road_id, [end.s, t], orientation, pos);
        }
    }
    road(
        network,
        &rp.road_id,
        [rp.s + ds, rp.t + dt],
        orientation,
        pos,
    )
}
