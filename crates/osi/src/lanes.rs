//! ASAM OSI 3.8 `Lane` and `LaneBoundary` from an ASAM OpenDRIVE road network (the
//! `opendrive` crate's exact road model).
//!
//! - One OSI lane per OpenDRIVE lane per lane_section (the centre lane 0 excluded), id from
//!   [`IdKey::Lane`]; one boundary per lane's outer border plus the centre line, id from
//!   [`IdKey::LaneBoundary`] (lane 0 is the centre line).
//! - `centerline` and `boundary_line` run towards increasing s, sampled by
//!   [`crate::polyline`]; `centerline_is_driving_direction` is true where the lane is
//!   driven towards +s (right-hand traffic: negative ids; OpenDRIVE 1.8 §10.2).
//! - Left and right are seen along the centre line (+s): for lane −n the left boundary is
//!   the border it shares with lane −(n−1) (or the centre line), the right one its own
//!   outer border; for lane +n the other way round. Neighbours likewise (id ± 1, across
//!   the centre lane).
//! - `lane_pairing`: every (lane before, lane after) pair along +s from the lane graph.
//! - `type`: `TYPE_INTERSECTION` on junction roads, else `TYPE_DRIVING` for drivable
//!   OpenDRIVE types and `TYPE_NONDRIVING`; `subtype` from the OpenDRIVE lane type.
//! - Boundary classification: the opendrive crate does not read `<roadMark>` yet, so the
//!   boundary type is `TYPE_OTHER` (never `TYPE_UNKNOWN`, which ground truth must not use).
//! - `source_reference`: type `net.asam.opendrive`, identifiers [road id, lane_section s,
//!   lane id] as OSI 3.8 asks for OpenDRIVE lanes.

use opendrive::{
    Direction, LaneHandle, LaneType, Road, RoadNetwork, RoadPosition, LENGTH_EPSILON, S_TOLERANCE,
};

use crate::error::{Error, ErrorKind};
use crate::ids::{IdAllocator, IdKey};
use crate::osi3::lane::classification::{LanePairing, Subtype, Type as LaneKind};
use crate::osi3::lane::Classification;
use crate::osi3::lane_boundary::classification::Type as BoundaryKind;
use crate::osi3::lane_boundary::{BoundaryPoint, Classification as BoundaryClassification};
use crate::osi3::{ExternalReference, Identifier, Lane, LaneBoundary, Vector3d};
use crate::polyline::{sample, Sampling};

/// `ExternalReference.type` of OpenDRIVE sources.
pub const OPENDRIVE_REFERENCE_TYPE: &str = "net.asam.opendrive";

/// Lanes and lane boundaries of a road network.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RoadLanes {
    /// `GroundTruth.lane`.
    pub lanes: Vec<Lane>,
    /// `GroundTruth.lane_boundary`.
    pub lane_boundaries: Vec<LaneBoundary>,
}

fn opendrive_error(e: opendrive::Error) -> Error {
    Error::new(ErrorKind::OpenDrive(e))
}

fn lane_key(road: &Road, section: usize, lane: i32) -> IdKey {
    IdKey::Lane {
        road: road.id.clone(),
        lane_section: section,
        lane,
    }
}

fn boundary_key(road: &Road, section: usize, lane: i32) -> IdKey {
    IdKey::LaneBoundary {
        road: road.id.clone(),
        lane_section: section,
        lane,
    }
}

fn vector(p: [f64; 3]) -> Vector3d {
    Vector3d {
        x: Some(p[0]),
        y: Some(p[1]),
        z: Some(p[2]),
    }
}

fn subtype(lane_type: &LaneType) -> Subtype {
    match lane_type {
        LaneType::Driving => Subtype::Normal,
        LaneType::Biking => Subtype::Biking,
        LaneType::Sidewalk | LaneType::Walking => Subtype::Sidewalk,
        LaneType::Parking => Subtype::Parking,
        LaneType::Stop => Subtype::Stop,
        LaneType::Restricted => Subtype::Restricted,
        LaneType::Border => Subtype::Border,
        LaneType::Shoulder => Subtype::Shoulder,
        LaneType::Exit => Subtype::Exit,
        LaneType::Entry => Subtype::Entry,
        LaneType::OnRamp => Subtype::Onramp,
        LaneType::OffRamp => Subtype::Offramp,
        LaneType::ConnectingRamp => Subtype::Connectingramp,
        _ => Subtype::Other,
    }
}

/// The OSI id of the lane a position (road, lane, s) lies on, if the lanes were built
/// with `ids` (for `moving_object_classification.assigned_lane_id`).
pub fn assigned_lane(
    ids: &IdAllocator,
    network: &RoadNetwork,
    road_id: &str,
    lane_id: i32,
    s: f64,
) -> Option<Identifier> {
    let road = network.road(road_id)?;
    // Borrowed look-up: no key is built, nothing allocated per call.
    ids.lane(&road.id, road.lane_section_index(s), lane_id)
}

/// The OSI id of the lane a road position (as `RoadNetwork::locate` gives it) lies on;
/// `None` off the road surface (`distance` > 0) or if the lanes were not built with `ids`.
pub fn assigned_lane_at(
    ids: &IdAllocator,
    network: &RoadNetwork,
    position: &RoadPosition,
) -> Option<Identifier> {
    if position.distance > LENGTH_EPSILON {
        return None;
    }
    assigned_lane(
        ids,
        network,
        &position.road_id,
        position.lane_id,
        position.s,
    )
}

/// Lanes and boundaries of every road of `network`, ids from `ids`, polylines sampled
/// with `sampling`, `map_reference` (the `.xodr` URI) in every `source_reference`.
pub fn from_network(
    network: &RoadNetwork,
    ids: &mut IdAllocator,
    sampling: &Sampling,
    map_reference: Option<&str>,
) -> Result<RoadLanes, Error> {
    let mut out = RoadLanes::default();
    for (ri, road) in network.roads().iter().enumerate() {
        for (k, section) in road.lane_sections.iter().enumerate() {
            let s0 = section.s;
            // Inside a road the last sample stays 1 µm before the section end, where the
            // next section applies; the last section runs to the road's end exactly.
            let s1 = if k + 1 == road.lane_sections.len() {
                road.length
            } else {
                (road.lane_section_end(k) - S_TOLERANCE).max(s0)
            };
            if s1 - s0 < S_TOLERANCE {
                continue;
            }
            let reference = |lane: i32| ExternalReference {
                reference: map_reference.map(str::to_string),
                r#type: Some(OPENDRIVE_REFERENCE_TYPE.to_string()),
                identifier: vec![road.id.clone(), format!("{s0}"), lane.to_string()],
            };
            for lane in section.lanes() {
                let border = |s: f64| -> Result<[f64; 3], opendrive::Error> {
                    let t = road.lane_span(lane.id, s)?.outer;
                    let p = road.pose(s, t)?;
                    Ok([p.x, p.y, p.z])
                };
                let line = sample(s0, s1, sampling, &mut { border }).map_err(opendrive_error)?;
                out.lane_boundaries.push(LaneBoundary {
                    id: Some(ids.id(boundary_key(road, k, lane.id))),
                    boundary_line: line
                        .iter()
                        .map(|&(_, p)| BoundaryPoint {
                            position: Some(vector(p)),
                            ..Default::default()
                        })
                        .collect(),
                    classification: Some(BoundaryClassification {
                        r#type: Some(BoundaryKind::Other as i32),
                        ..Default::default()
                    }),
                    source_reference: vec![reference(lane.id)],
                    ..Default::default()
                });
            }
            for lane in section.lanes().filter(|l| l.id != 0) {
                let id = lane.id;
                let centre = |s: f64| -> Result<[f64; 3], opendrive::Error> {
                    let p = road.lane_pose(id, s, 0.0)?;
                    Ok([p.x, p.y, p.z])
                };
                let line = sample(s0, s1, sampling, &mut { centre }).map_err(opendrive_error)?;
                let inner = if id > 0 { id - 1 } else { id + 1 };
                let (left_border, right_border) = if id > 0 { (id, inner) } else { (inner, id) };
                let own_id = ids.id(lane_key(road, k, id));
                let mut neighbour = |n: i32| {
                    // Next to lane ±1 across the centre lane lies lane ∓1.
                    let n = if n == 0 { -id.signum() } else { n };
                    section.lane(n).map(|_| ids.id(lane_key(road, k, n)))
                };
                let left_adjacent_lane_id = neighbour(id + 1).into_iter().collect();
                let right_adjacent_lane_id = neighbour(id - 1).into_iter().collect();
                let handle = LaneHandle {
                    road: ri as u32,
                    section: k as u32,
                    lane: id,
                };
                let forward = network.driving_direction(handle) == Direction::Forward;
                let lane_pairing = pairings(network, handle, forward, ids);
                let kind = if road.junction.is_some() {
                    LaneKind::Intersection
                } else if lane.lane_type.is_drivable() {
                    LaneKind::Driving
                } else {
                    LaneKind::Nondriving
                };
                out.lanes.push(Lane {
                    id: Some(own_id),
                    classification: Some(Classification {
                        r#type: Some(kind as i32),
                        centerline: line.iter().map(|&(_, p)| vector(p)).collect(),
                        centerline_is_driving_direction: Some(forward),
                        left_adjacent_lane_id,
                        right_adjacent_lane_id,
                        lane_pairing,
                        left_lane_boundary_id: vec![ids.id(boundary_key(road, k, left_border))],
                        right_lane_boundary_id: vec![ids.id(boundary_key(road, k, right_border))],
                        subtype: Some(subtype(&lane.lane_type) as i32),
                        ..Default::default()
                    }),
                    source_reference: vec![reference(id)],
                });
            }
        }
    }
    Ok(out)
}

/// (lane before, lane after) pairs along +s for lane `h`.
fn pairings(
    network: &RoadNetwork,
    h: LaneHandle,
    forward: bool,
    ids: &mut IdAllocator,
) -> Vec<LanePairing> {
    let (mut before, mut after) = (network.predecessors(h), network.successors(h));
    if !forward {
        std::mem::swap(&mut before, &mut after);
    }
    let mut id = |l: LaneHandle| {
        let road = network.handle_road(l);
        ids.id(lane_key(road, l.section as usize, l.lane))
    };
    let before: Vec<Option<Identifier>> = before.iter().map(|&l| Some(id(l))).collect();
    let after: Vec<Option<Identifier>> = after.iter().map(|&l| Some(id(l))).collect();
    let before = if before.is_empty() {
        vec![None]
    } else {
        before
    };
    let after = if after.is_empty() { vec![None] } else { after };
    let mut out = Vec::new();
    for b in &before {
        for a in &after {
            if b.is_some() || a.is_some() {
                out.push(LanePairing {
                    antecessor_lane_id: *b,
                    successor_lane_id: *a,
                });
            }
        }
    }
    out
}
