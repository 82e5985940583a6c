//! The route argument of OpenSCENARIO 2.0 §8.7.4.1.1 distance_along_route(): "either a
//! route_element or a compound_route", here a sequence of stretches of roads or lanes, each
//! run from `s_start` to `s_end` (towards −s when `s_end < s_start`). The route's s-axis is
//! the distance travelled along the stretches' reference lines from the route's start point.
//!
//! Directions of whole elements: a lane is run in its driving direction (OpenDRIVE 1.8
//! §11.2); a road, lane section or crossing in the direction that joins it to its neighbours
//! in the sequence (OpenDRIVE road links and junction connections), towards +s when it has
//! none.

use opendrive::{Direction, LaneRoute, Real, RoadNetwork, S_TOLERANCE};

use super::road_path::{neighbours, road_indices};
use super::{DomainError, DomainErrorKind, RouteElement};

/// One stretch of a route (§8.7.4.1.1 route / compound_route): road `road_id` (only lane `lane_id` of it, if given) from
/// `s_start` to `s_end`.
#[derive(Debug, Clone, PartialEq)]
pub struct RouteStretch {
    /// OpenDRIVE road id.
    pub road_id: String,
    /// The lane the stretch is restricted to, if any.
    pub lane_id: Option<i32>,
    /// s where the route enters the stretch, m.
    pub s_start: Real,
    /// s where it leaves; below `s_start` when run towards −s.
    pub s_end: Real,
}

/// A route (route_element or compound_route, §8.7.4.1.1): stretches in travel order.
#[derive(Debug, Clone, PartialEq)]
pub struct Route {
    stretches: Vec<RouteStretch>,
    length: Real,
}

impl Route {
    /// A route of the given stretches, checked against `network`: at least one stretch,
    /// known roads, s within each road, lanes that exist at the stretch's start.
    pub fn new(network: &RoadNetwork, stretches: Vec<RouteStretch>) -> Result<Self, DomainError> {
        let invalid = |found: String| DomainError::new(DomainErrorKind::InvalidRoute { found });
        if stretches.is_empty() {
            return Err(invalid("no element".into()));
        }
        for st in &stretches {
            let road = network
                .road(&st.road_id)
                .ok_or_else(|| invalid(format!("unknown road {}", st.road_id)))?;
            for s in [st.s_start, st.s_end] {
                if !(s.is_finite() && (-S_TOLERANCE..=road.length + S_TOLERANCE).contains(&s)) {
                    return Err(invalid(format!("s = {s} outside road {}", st.road_id)));
                }
            }
            if let Some(lane) = st.lane_id {
                if network.lane_handle(&st.road_id, lane, st.s_start).is_none() || lane == 0 {
                    return Err(invalid(format!("no lane {lane} on road {}", st.road_id)));
                }
            }
        }
        let length = stretches
            .iter()
            .map(|st| (st.s_end - st.s_start).abs())
            .sum();
        Ok(Self { stretches, length })
    }

    /// A route along one whole route element (§8.7.4.1.1 "route_element").
    pub fn element(network: &RoadNetwork, element: &RouteElement) -> Result<Self, DomainError> {
        Self::compound(network, std::slice::from_ref(element))
    }

    /// A route along whole route elements in sequence (§8.7.4.1.1 "compound_route"); see the
    /// module doc for the direction each is run in.
    pub fn compound(network: &RoadNetwork, elements: &[RouteElement]) -> Result<Self, DomainError> {
        let invalid = |found: String| DomainError::new(DomainErrorKind::InvalidRoute { found });
        let index = road_indices(network);
        let road_index = |e: &RouteElement| {
            let id = element_road(e);
            index
                .get(id)
                .copied()
                .ok_or_else(|| invalid(format!("unknown road {id}")))
        };
        let mut stretches = Vec::with_capacity(elements.len());
        let mut previous: Option<(usize, bool)> = None;
        for (i, e) in elements.iter().enumerate() {
            let road = road_index(e)?;
            let forward = match e {
                RouteElement::Lane {
                    road_id,
                    lane_section,
                    lane_id,
                } => {
                    let r = &network.roads()[road];
                    let s = r
                        .lane_sections
                        .get(*lane_section)
                        .map_or(Real::NAN, |ls| ls.s);
                    let h = network
                        .lane_handle(road_id, *lane_id, s)
                        .filter(|_| *lane_id != 0)
                        .ok_or_else(|| invalid(format!("no lane {lane_id} on road {road_id}")))?;
                    network.driving_direction(h) == Direction::Forward
                }
                _ => match (previous, elements.get(i + 1)) {
                    (Some((p, pf)), _) => neighbours(network, p, pf)
                        .into_iter()
                        .find(|&(n, _)| n == road)
                        .is_none_or(|(_, f)| f),
                    (None, Some(next)) => {
                        let next = road_index(next)?;
                        let reaches =
                            |f| neighbours(network, road, f).iter().any(|&(n, _)| n == next);
                        reaches(true) || !reaches(false)
                    }
                    (None, None) => true,
                },
            };
            let (lo, hi) = element_range(network, e, road)?;
            let (s_start, s_end) = if forward { (lo, hi) } else { (hi, lo) };
            let lane_id = match e {
                RouteElement::Lane { lane_id, .. } => Some(*lane_id),
                _ => None,
            };
            stretches.push(RouteStretch {
                road_id: element_road(e).to_string(),
                lane_id,
                s_start,
                s_end,
            });
            previous = Some((road, forward));
        }
        Self::new(network, stretches)
    }

    /// The route a lane router found (`opendrive::RoadNetwork::route`), stretch by stretch.
    pub fn from_lane_route(route: &LaneRoute) -> Self {
        let stretches: Vec<RouteStretch> = route
            .segments
            .iter()
            .map(|seg| RouteStretch {
                road_id: seg.road_id.clone(),
                lane_id: Some(seg.lane_id),
                s_start: seg.s_start,
                s_end: seg.s_end,
            })
            .collect();
        let length = stretches
            .iter()
            .map(|st| (st.s_end - st.s_start).abs())
            .sum();
        Self { stretches, length }
    }

    /// The stretches in travel order (§8.7.4.1.1: the route's s-axis runs through them).
    pub fn stretches(&self) -> &[RouteStretch] {
        &self.stretches
    }

    /// Total length along the stretches, m: the route s of its end point (§8.7.4.1.1).
    pub fn length(&self) -> Real {
        self.length
    }
}

/// The road a route element lies on.
fn element_road(e: &RouteElement) -> &str {
    match e {
        RouteElement::Road { road_id }
        | RouteElement::LaneSection { road_id, .. }
        | RouteElement::Lane { road_id, .. }
        | RouteElement::Crossing { road_id, .. } => road_id,
    }
}

/// The s range (low, high) an element covers on its road (index `road`).
fn element_range(
    network: &RoadNetwork,
    e: &RouteElement,
    road: usize,
) -> Result<(Real, Real), DomainError> {
    let r = &network.roads()[road];
    let section = |k: usize| {
        r.lane_sections
            .get(k)
            .map(|ls| (ls.s, r.lane_section_end(k)))
            .ok_or_else(|| {
                DomainError::new(DomainErrorKind::InvalidRoute {
                    found: format!("no lane section {k} on road {}", r.id),
                })
            })
    };
    match e {
        RouteElement::Road { .. } | RouteElement::Crossing { .. } => Ok((0.0, r.length)),
        RouteElement::LaneSection { index, .. } => section(*index),
        RouteElement::Lane { lane_section, .. } => section(*lane_section),
    }
}
