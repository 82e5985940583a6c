//! OpenSCENARIO 2.0 §8.7.2.1.2 get_s_coord(), §8.7.2.1.3 get_t_coord() and §8.7.2.1.4
//! get_route_point(): the object's reference point in the s/t system of the road, lane
//! section, lane or crossing it is on (§8.7.16 on_route_type).
//!
//! oscsim's reading of the four systems on an OpenDRIVE network:
//! * `on_road`: the road's reference-line s and t (OpenDRIVE 1.8 §8.3), t positive left.
//! * `on_lane_section`: s from the lane section's start (s − section.s), t as on the road;
//!   the lane section is the one OpenDRIVE holds valid at s.
//! * `on_lane`: a lane exists only inside its lane section, and it is driven one way
//!   (OpenDRIVE 1.8 §11.2: with right-hand traffic negative lane ids run towards +s, positive
//!   ones towards −s; left-hand traffic swaps them). The lane's s therefore runs in its driving
//!   direction from where the lane begins in that direction (section start for lanes run
//!   towards +s, section end for the others), and its t is the offset from the lane centre,
//!   positive to the left of the driving direction. This is the lane coordinate a driver
//!   in the lane reads (pitfall 15); lane 0 (the centre lane, no width) is no lane.
//! * `on_crossing`: a crossing is a junction's connecting road (OpenDRIVE 1.8 §10.7); its s/t
//!   are that road's. An object on a road outside any junction is not on a crossing.
//!
//! The object must be on the road surface (`opendrive::RoadPosition::distance` = 0); its
//! heading chooses between overlapping roads in junctions.

use opendrive::{Direction, Real, RoadNetwork};

use super::road_locate::locate;
use super::{DomainError, DomainErrorKind, OnRouteType, PhysicalObject};

/// A route element (OpenSCENARIO 2.0 road abstraction, §8.7.16 on_route_type) on an
/// OpenDRIVE network: the thing a route_point's s/t refer to (§8.7.2.1.4).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum RouteElement {
    /// A whole road.
    Road {
        /// OpenDRIVE road id.
        road_id: String,
    },
    /// One lane section of a road.
    LaneSection {
        /// OpenDRIVE road id.
        road_id: String,
        /// Index of the section in the road's lane sections (0-based, in s order).
        index: usize,
    },
    /// One lane of one lane section.
    Lane {
        /// OpenDRIVE road id.
        road_id: String,
        /// Index of the lane section (0-based).
        lane_section: usize,
        /// OpenDRIVE lane id (non-zero).
        lane_id: i32,
    },
    /// A crossing: a connecting road of a junction.
    Crossing {
        /// OpenDRIVE junction id.
        junction_id: String,
        /// The connecting road's id.
        road_id: String,
    },
}

/// route_point (§8.7.2.1.4 return value): a route element and the s/t coordinates in its
/// system.
#[derive(Debug, Clone, PartialEq)]
pub struct RoutePoint {
    /// The element the coordinates refer to.
    pub element: RouteElement,
    /// s in the element's system, m.
    pub s: Real,
    /// t in the element's system, m, positive left.
    pub t: Real,
}

impl PhysicalObject {
    /// §8.7.2.1.4 `get_route_point(route_type)`: the route element of kind `route_type` the
    /// reference point is on, and its s/t there (see the module doc). Errors with
    /// `NotOnRoad`, `NotOnLaneSection`, `NotOnLane` or `NotOnCrossing` for the seed's four
    /// error cases.
    pub fn get_route_point(
        &self,
        network: &RoadNetwork,
        route_type: OnRouteType,
    ) -> Result<RoutePoint, DomainError> {
        let (x, y) = (self.pose.x, self.pose.y);
        let fail = |kind| DomainError::at(kind, x, y);
        let not_on = match route_type {
            OnRouteType::OnRoad => DomainErrorKind::NotOnRoad,
            OnRouteType::OnLaneSection => DomainErrorKind::NotOnLaneSection,
            OnRouteType::OnLane => DomainErrorKind::NotOnLane,
            OnRouteType::OnCrossing => DomainErrorKind::NotOnCrossing { road_id: None },
        };
        let pos = locate(network, self).map_err(|_| fail(not_on.clone()))?;
        let road = network
            .road(&pos.road_id)
            .ok_or_else(|| fail(not_on.clone()))?;
        let k = road.lane_section_index(pos.s);
        let (start, end) = (road.lane_sections[k].s, road.lane_section_end(k));
        match route_type {
            OnRouteType::OnRoad => Ok(RoutePoint {
                element: RouteElement::Road {
                    road_id: pos.road_id,
                },
                s: pos.s,
                t: pos.t,
            }),
            OnRouteType::OnLaneSection => Ok(RoutePoint {
                element: RouteElement::LaneSection {
                    road_id: pos.road_id,
                    index: k,
                },
                s: pos.s - start,
                t: pos.t,
            }),
            OnRouteType::OnLane => {
                let handle = network
                    .lane_handle(&pos.road_id, pos.lane_id, pos.s)
                    .filter(|_| pos.lane_id != 0)
                    .ok_or_else(|| fail(not_on))?;
                let (s, t) = match network.driving_direction(handle) {
                    Direction::Forward => (pos.s - start, pos.offset),
                    Direction::Backward => (end - pos.s, -pos.offset),
                };
                let element = RouteElement::Lane {
                    road_id: pos.road_id,
                    lane_section: k,
                    lane_id: pos.lane_id,
                };
                Ok(RoutePoint { element, s, t })
            }
            OnRouteType::OnCrossing => match pos.junction_id {
                Some(junction_id) => Ok(RoutePoint {
                    element: RouteElement::Crossing {
                        junction_id,
                        road_id: pos.road_id,
                    },
                    s: pos.s,
                    t: pos.t,
                }),
                None => Err(fail(DomainErrorKind::NotOnCrossing {
                    road_id: Some(pos.road_id),
                })),
            },
        }
    }

    /// §8.7.2.1.2 `get_s_coord(route_type)`: the s of [`get_route_point`](Self::get_route_point).
    pub fn get_s_coord(
        &self,
        network: &RoadNetwork,
        route_type: OnRouteType,
    ) -> Result<Real, DomainError> {
        self.get_route_point(network, route_type).map(|p| p.s)
    }

    /// §8.7.2.1.3 `get_t_coord(route_type)`: the t of [`get_route_point`](Self::get_route_point).
    pub fn get_t_coord(
        &self,
        network: &RoadNetwork,
        route_type: OnRouteType,
    ) -> Result<Real, DomainError> {
        self.get_route_point(network, route_type).map(|p| p.t)
    }
}
