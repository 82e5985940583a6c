//! [`PlannedRoute`]: what route planning hands the runtime (OpenSCENARIO 1.3 §7.5 "Routes"):
//! the lane stretches to drive in order, the lane changes the route needs, where each
//! waypoint lies along it, and the route as a [`domain::Route`](crate::domain::Route), whose
//! s-axis (path s, from the first waypoint, along the roads' reference lines) is the one of
//! RoutePosition's `pathS` and of OpenSCENARIO 2.0 §8.7.4.1.1 distance_along_route.

use opendrive::{LaneChange, LanePosition, Real, RouteSegment, S_TOLERANCE};

use crate::domain::Route;

/// A waypoint as planned: its lane position and its path s.
#[derive(Debug, Clone, PartialEq)]
pub struct RoutedWaypoint {
    /// Where the waypoint's position lies on the road network.
    pub lane: LanePosition,
    /// Path s of the waypoint (m); a closed route's first waypoint also ends the route, at
    /// its total length.
    pub path_s: Real,
}

/// A planned route.
#[derive(Debug, Clone, PartialEq)]
pub struct PlannedRoute {
    pub(crate) name: String,
    pub(crate) closed: bool,
    pub(crate) waypoints: Vec<RoutedWaypoint>,
    pub(crate) segments: Vec<RouteSegment>,
    pub(crate) lane_changes: Vec<LaneChange>,
    pub(crate) junctions: usize,
    pub(crate) route: Route,
}

impl PlannedRoute {
    /// `Route/@name`.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// `Route/@closed`: the path returns from the last waypoint to the first.
    pub fn closed(&self) -> bool {
        self.closed
    }

    /// The waypoints in order, with their path s.
    pub fn waypoints(&self) -> &[RoutedWaypoint] {
        &self.waypoints
    }

    /// The lane stretches in driving order (consecutive pieces of one lane merged).
    pub fn segments(&self) -> &[RouteSegment] {
        &self.segments
    }

    /// The lane changes in driving order, their `path_s` along this route.
    pub fn lane_changes(&self) -> &[LaneChange] {
        &self.lane_changes
    }

    /// Number of junctions the path enters.
    pub fn junctions(&self) -> usize {
        self.junctions
    }

    /// Total length along the roads' reference lines (m).
    pub fn length(&self) -> Real {
        self.route.length()
    }

    /// The route for distance_along_route, get_s_coord and RoutePosition (OpenSCENARIO 2.0
    /// §8.7.4.1.1): one stretch per lane stretch, restricted to its lane.
    pub fn route(&self) -> &Route {
        &self.route
    }

    /// The stretch at path s and the road s there; `None` beyond the route. At a stretch's
    /// end the earlier stretch answers.
    pub fn at(&self, path_s: Real) -> Option<(&RouteSegment, Real)> {
        if !(-S_TOLERANCE..=self.length() + S_TOLERANCE).contains(&path_s) {
            return None;
        }
        let mut start = 0.0;
        let n = self.segments.len();
        for (i, seg) in self.segments.iter().enumerate() {
            let len = (seg.s_end - seg.s_start).abs();
            if path_s <= start + len || i + 1 == n {
                let along = (path_s - start).clamp(0.0, len);
                let s = seg.s_start + along * (seg.s_end - seg.s_start).signum();
                return Some((seg, s));
            }
            start += len;
        }
        None
    }

    /// The path s of a point on lane `lane_id` of road `road_id` at `s`, if one of the
    /// route's stretches covers it, searching stretches from path s `from` on (so that a
    /// route passing a road twice answers for the pass ahead). `lane_id` `None` matches any
    /// lane (a vehicle between lanes, or changing lanes).
    pub fn path_s_of(
        &self,
        road_id: &str,
        lane_id: Option<i32>,
        s: Real,
        from: Real,
    ) -> Option<Real> {
        let mut start = 0.0;
        for seg in &self.segments {
            let len = (seg.s_end - seg.s_start).abs();
            let (lo, hi) = (seg.s_start.min(seg.s_end), seg.s_start.max(seg.s_end));
            let on = seg.road_id == road_id
                && lane_id.is_none_or(|l| l == seg.lane_id)
                && s >= lo - S_TOLERANCE
                && s <= hi + S_TOLERANCE;
            let path_s = start + (s - seg.s_start).abs().min(len);
            if on && path_s >= from - S_TOLERANCE {
                return Some(path_s);
            }
            start += len;
        }
        None
    }
}
