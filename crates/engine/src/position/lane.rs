//! Lane-coordinate positions (OpenSCENARIO 1.3 §6.3.4 lane coordinate system; XSD
//! `LanePosition`, `RelativeLanePosition`).
//!
//! * LanePosition: s along road `roadId`'s reference line, then `offset` from the centre of
//!   lane `laneId` along the road's t-axis (positive left of the reference line). An s past
//!   the road's ends continues on the connecting road (module `beyond`).
//! * RelativeLanePosition with `ds`: s of the reference entity plus ds along the reference
//!   line; lane = the entity's lane plus dLane (lane ids counted across the reference line,
//!   so positive dLane moves towards the road's left, and the centre lane 0 is skipped:
//!   −1 + 1 = 1); then `offset` from that lane's centre.
//! * RelativeLanePosition with `dsLane` (1.1+): the 1.3 text — "travel the lane center line
//!   difference dsLane from the position of the reference entity in the direction the
//!   reference entity is facing" — is followed literally: the distance is measured along the
//!   centre line of the entity's lane (arc length, not reference-line s), forwards when the
//!   entity faces along +s (|relative heading| ≤ π/2), else backwards; then the lane changes
//!   by dLane at that s. The arc length is integrated by `lane_length` (Simpson's rule on the
//!   exact centre-line speed, exact on arcs and straights).
//!
//! With `ds` the walk follows the entity's lane through lane sections and onto connecting
//! roads (`lane_walk`, the 1.3 continuation rule), and dLane is counted on the road reached
//! (negated where that road runs against the start road). `dsLane` continues the same way
//! along the lane centre lines of the roads passed (module `beyond`). Orientation: relative headings count from the target lane's driving
//! direction (see `orientation`).

use std::f64::consts::PI;

use opendrive::{Direction, Pose, Real, RoadNetwork, LENGTH_EPSILON};
use scenario::{Orientation, SourcePos};

use super::beyond::carried;
use super::error::road_error;
use super::lane_length::{lane_arc_length, s_at_lane_distance};
use super::lane_walk::walk;
use super::orientation::on_surface;
use super::world::finite;
use super::{EntityView, PositionError, PositionErrorKind, ResolvedPosition};

/// Heading of lane `lane_id`'s driving direction at a point where its centre line heads
/// `centre_h`: `centre_h`, turned by π for lanes driven towards −s.
pub(crate) fn driving_heading(
    network: &RoadNetwork,
    road_id: &str,
    lane_id: i32,
    s: Real,
    centre_h: Real,
) -> Real {
    match network.lane_handle(road_id, lane_id, s) {
        Some(h) if lane_id != 0 && network.driving_direction(h) == Direction::Backward => {
            opendrive::normalize_angle(centre_h + PI)
        }
        _ => centre_h,
    }
}

/// Lane id `lane` moved by `d_lane` across the road, skipping the centre lane 0.
pub(crate) fn add_lanes(lane: i32, d_lane: i32) -> i32 {
    let target = lane.saturating_add(d_lane);
    if lane > 0 && target <= 0 {
        target - 1
    } else if lane < 0 && target >= 0 {
        target + 1
    } else {
        target
    }
}

/// Parses an XSD `laneId` string.
pub(crate) fn parse_lane_id(text: &str, pos: &SourcePos) -> Result<i32, PositionError> {
    text.trim()
        .parse()
        .map_err(|_| PositionError::new(PositionErrorKind::InvalidLaneId(text.into()), pos))
}

/// `LanePosition`.
pub(crate) fn lane(
    network: &RoadNetwork,
    road_id: &str,
    lane_id: i32,
    [s, offset]: [Real; 2],
    orientation: Option<&Orientation>,
    pos: &SourcePos,
) -> Result<ResolvedPosition, PositionError> {
    finite(&[("s", s), ("offset", offset)], pos)?;
    // Past the road's ends: carried onto the connecting road (module `beyond`).
    if let Some(end) = carried(network, road_id, Some(lane_id), s, 0.0) {
        let offset = if end.flipped { -offset } else { offset };
        return lane(
            network,
            &end.road_id,
            end.lane_id,
            [end.s, offset],
            orientation,
            pos,
        );
    }
    let surface = network
        .lane_pose(road_id, lane_id, s, offset)
        .map_err(|e| road_error(e, pos))?;
    let reference_h = driving_heading(network, road_id, lane_id, s, surface.h);
    let a = on_surface(orientation, &surface, reference_h);
    let pose = Pose {
        h: a.h,
        p: a.p,
        r: a.r,
        ..surface
    };
    Ok(ResolvedPosition::on_road(network, road_id, pose))
}

/// How far along a RelativeLanePosition goes: `ds` along the reference line or `dsLane`
/// along the entity's lane centre.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Along {
    /// `ds`, m.
    Road(Real),
    /// `dsLane`, m.
    Lane(Real),
}

/// `RelativeLanePosition`; `reference` gives the entity `entity_ref` names
/// (`resolve::resolve_with`).
#[allow(clippy::too_many_arguments)] // the attributes of the XSD element, plus context.
pub(crate) fn relative_lane<'q>(
    network: &RoadNetwork,
    entity_ref: &str,
    reference: impl FnOnce(&str) -> Result<EntityView<'q>, PositionError>,
    d_lane: i32,
    along: Along,
    offset: Real,
    orientation: Option<&Orientation>,
    pos: &SourcePos,
) -> Result<ResolvedPosition, PositionError> {
    let e = reference(entity_ref)?;
    let rp = e.road_position.ok_or_else(|| {
        PositionError::new(PositionErrorKind::EntityOffRoad(entity_ref.into()), pos)
    })?;
    let (road_id, from_lane, s, d_lane) = match along {
        Along::Road(ds) => {
            finite(&[("ds", ds)], pos)?;
            match walk(network, &rp.road_id, rp.lane_id, rp.s, ds) {
                Some(end) => {
                    let d = if end.flipped { -d_lane } else { d_lane };
                    (end.road_id, end.lane_id, end.s, d)
                }
                None => (rp.road_id.clone(), rp.lane_id, rp.s + ds, d_lane),
            }
        }
        Along::Lane(ds_lane) => {
            finite(&[("dsLane", ds_lane)], pos)?;
            let forward = rp.relative_heading.abs() <= PI / 2.0;
            // A negative dsLane goes the other way.
            let forward = forward == (ds_lane >= 0.0);
            let (road_id, lane_id, s, flipped) = along_lane(
                network,
                &rp.road_id,
                rp.lane_id,
                rp.s,
                ds_lane.abs(),
                forward,
            )
            .map_err(|e| road_error(e, pos))?;
            (road_id, lane_id, s, if flipped { -d_lane } else { d_lane })
        }
    };
    let target = add_lanes(from_lane, d_lane);
    if let Err(err) = network.lane_boundaries(&road_id, target, s) {
        return Err(match err.kind() {
            opendrive::ErrorKind::NoSuchLane { .. } => PositionError::new(
                PositionErrorKind::NoTargetLane {
                    road: road_id.clone(),
                    from: from_lane,
                    d_lane,
                    lane: target,
                    s,
                },
                pos,
            ),
            _ => road_error(err, pos),
        });
    }
    lane(network, &road_id, target, [s, offset], orientation, pos)
}

/// Roads a `dsLane` walk may pass before it is abandoned (a guard against cyclic road graphs).
const MAX_ROADS: usize = 1_000;

/// Travels `distance` m along the centre line of `lane_id` from s on `road_id` (towards +s
/// when `forward`), onto the connecting roads where the road ends (module `beyond`'s rule for
/// dsLane): the road, lane and s reached, and whether that road runs against the first.
/// Where nothing connects, the road model's error for the s past the end.
fn along_lane(
    network: &RoadNetwork,
    road_id: &str,
    lane_id: i32,
    s: Real,
    distance: Real,
    forward: bool,
) -> Result<(String, i32, Real, bool), opendrive::Error> {
    let (mut road, mut lane, mut s, mut forward) = (road_id.to_owned(), lane_id, s, forward);
    let (mut left, mut flipped) = (distance, false);
    for _ in 0..MAX_ROADS {
        let end = match network.road(&road) {
            Some(r) if forward => r.length,
            _ => 0.0,
        };
        let room = lane_arc_length(network, &road, lane, s, end);
        let next = match room {
            Some(room) if left > room + LENGTH_EPSILON => {
                // Over the road's end by a hair: the walk lands on the connecting lane.
                let hair = if forward { HAIR } else { -HAIR };
                walk(network, &road, lane, end, hair).map(|w| (room, w))
            }
            _ => None,
        };
        let Some((room, w)) = next else {
            let s = s_at_lane_distance(network, &road, lane, s, left, forward)?;
            return Ok((road, lane, s, flipped));
        };
        left -= room + HAIR;
        flipped ^= w.flipped;
        forward ^= w.flipped;
        (road, lane, s) = (w.road_id, w.lane_id, w.s);
    }
    s_at_lane_distance(network, &road, lane, s, left, forward).map(|s| (road, lane, s, flipped))
}

/// The step (m) that carries a dsLane walk over a road's end onto the connecting lane.
const HAIR: Real = 1e-6;
