//! Following a planned route (OpenSCENARIO 1.3 §7.5 "Routes", §7.7.2.6 "RoutingAction": the
//! default controller of an entity with an assigned route follows it): which stretch of the
//! [`PlannedRoute`] the entity drives, which successor to take where its road ends (the
//! connecting road of a junction the route names), and which lane the route needs when the
//! entity's lane does not lead on to the route's next road.
//!
//! The route is followed by road: at a road's end the entity takes the successor on the
//! route's next road, in the planned lane if its lane links lead there, else in any lane of
//! that road. It changes lanes only where its own lane does not lead to the next road (a turn
//! reached from another lane); the planner's lane choices elsewhere are not imposed, so a
//! LaneChangeAction of the scenario is not undone. The standard leaves this open; it is also
//! how esmini 3.6.0 follows routes (road by road, its `Route::minimal_waypoints_`).
//!
//! An entity not yet on the route (or off it) takes, where its road ends, a successor on a
//! road of the route ahead, and so joins it. A closed route wraps: after its last stretch,
//! which ends at the first waypoint, the first stretch follows again. An open route ends at
//! its last waypoint; from there on the entity takes successors as without a route.

use opendrive::{Direction, LaneHandle, Real, RoadNetwork, RouteSegment, S_TOLERANCE};

use crate::routing::PlannedRoute;
use crate::world::lane_track::LaneTrack;
use crate::world::lanes::carry_lane;

use super::lane_change::RouteLaneChange;

/// The route the default controller follows and the entity's progress along it.
#[derive(Debug, Clone)]
pub struct RouteFollow {
    plan: PlannedRoute,
    /// Index of the stretch the entity drives, or reaches next on its road.
    cursor: usize,
    /// An open route driven to its end: no longer followed.
    ended: bool,
    /// The lane change the route needs, while it runs.
    pub(crate) change: Option<RouteLaneChange>,
}

/// Whether `s` has not yet passed the end of `seg` travelling in its direction.
fn not_past_end(seg: &RouteSegment, s: Real) -> bool {
    match seg.direction {
        Direction::Forward => s <= seg.s_end + S_TOLERANCE,
        Direction::Backward => s >= seg.s_end - S_TOLERANCE,
    }
}

/// Whether `b` continues `a` on the same road without a road end between them (a lane change,
/// or a waypoint between them).
fn continues(a: &RouteSegment, b: &RouteSegment) -> bool {
    a.road_id == b.road_id
        && a.direction == b.direction
        && (a.s_end - b.s_start).abs() <= S_TOLERANCE
}

impl RouteFollow {
    /// Starts following `plan` from its first stretch (the first move finds the entity on it).
    pub fn new(plan: PlannedRoute) -> Self {
        Self {
            plan,
            cursor: 0,
            ended: false,
            change: None,
        }
    }

    /// The stretch the entity drives now (or reaches next on its road); `None` once an open
    /// route has been driven to its end.
    pub fn current(&self) -> Option<&RouteSegment> {
        if self.ended {
            return None;
        }
        self.plan.segments.get(self.cursor)
    }

    /// The stretch after `i`, wrapping round a closed route; `None` after an open route's end.
    fn next_index(&self, i: usize) -> Option<usize> {
        let n = self.plan.segments.len();
        if i + 1 < n {
            Some(i + 1)
        } else if self.plan.closed && n > 0 {
            Some(0)
        } else {
            None
        }
    }

    /// The stretches from the cursor on: round a closed route, to the end of an open one.
    fn ahead(&self) -> impl Iterator<Item = usize> {
        let n = self.plan.segments.len();
        let count = if self.plan.closed {
            n
        } else {
            n.saturating_sub(self.cursor)
        };
        let cursor = self.cursor;
        (0..count).map(move |k| (cursor + k) % n)
    }

    /// The first stretch after the current one that starts on a road end (another road, or the
    /// same road entered again): the one the successor at the current road's end must match.
    fn next_entry(&self) -> Option<usize> {
        let segs = &self.plan.segments;
        let mut prev = self.cursor;
        for _ in 0..segs.len() {
            let i = self.next_index(prev)?;
            if !continues(&segs[prev], &segs[i]) {
                return Some(i);
            }
            prev = i;
        }
        None
    }

    /// Brings the cursor to where `track` is: on the current stretch, moved on to a stretch
    /// continuing it once its end is passed, or (after a teleport or a detour) the first
    /// stretch [`ahead`](Self::ahead) that lies on the track's road, in its direction, not yet
    /// passed. Off the route the cursor stays. Passing the end of an open route's last
    /// stretch ends the route.
    pub(crate) fn sync(&mut self, track: &LaneTrack) {
        let segs = &self.plan.segments;
        let n = segs.len();
        if self.ended {
            return;
        }
        let on = |seg: &RouteSegment| {
            seg.road_id == track.road_id
                && seg.direction == track.direction
                && not_past_end(seg, track.s)
        };
        if self.cursor < n && segs[self.cursor].road_id == track.road_id {
            // Passed the current stretch's end: on to the stretches continuing it.
            for _ in 0..n {
                let seg = &segs[self.cursor];
                let passed = match seg.direction {
                    Direction::Forward => track.s >= seg.s_end - S_TOLERANCE,
                    Direction::Backward => track.s <= seg.s_end + S_TOLERANCE,
                };
                match self.next_index(self.cursor) {
                    Some(i) if passed && continues(seg, &segs[i]) => self.cursor = i,
                    None if passed => {
                        self.ended = true;
                        return;
                    }
                    _ => break,
                }
            }
            if on(&segs[self.cursor]) {
                return;
            }
        }
        if let Some(i) = self.ahead().find(|&i| on(&segs[i])) {
            self.cursor = i;
        }
    }

    /// Where the track's road ends: the successor of `candidates` on the route's next road
    /// (in the planned lane if it is one of them). Off the route (not yet on it, or its lane
    /// does not lead on) the first successor on a road of the route ahead, so the entity joins
    /// it. `None` when no successor is on the route or the route has ended, which leaves the
    /// choice to the caller. Moves the cursor onto the chosen stretch.
    pub(crate) fn choose(
        &mut self,
        net: &RoadNetwork,
        from_road: &str,
        candidates: &[LaneHandle],
    ) -> Option<LaneHandle> {
        let on_route = self.current()?.road_id == from_road;
        let road_of = |h: &LaneHandle| net.handle_road(*h).id.as_str();
        if on_route {
            let Some(j) = self.next_entry() else {
                // Leaving the road of an open route's last stretch: the route is done.
                self.ended = true;
                return None;
            };
            let next = &self.plan.segments[j];
            let pick = candidates
                .iter()
                .filter(|h| road_of(h) == next.road_id)
                .find(|h| h.lane == next.lane_id)
                .or_else(|| candidates.iter().find(|h| road_of(h) == next.road_id));
            if let Some(&h) = pick {
                self.cursor = j;
                return Some(h);
            }
        }
        // Join the route: the nearest stretch ahead that a successor enters.
        let (k, h) = self.ahead().find_map(|k| {
            let seg = &self.plan.segments[k];
            candidates
                .iter()
                .find(|h| road_of(h) == seg.road_id && net.driving_direction(**h) == seg.direction)
                .map(|&h| (k, h))
        })?;
        self.cursor = k;
        Some(h)
    }

    /// The successor [`choose`](Self::choose) would take, without moving the cursor: the lane
    /// a gap search follows where the road ends.
    pub(crate) fn peek(
        &self,
        net: &RoadNetwork,
        from_road: &str,
        candidates: &[LaneHandle],
    ) -> Option<LaneHandle> {
        self.clone().choose(net, from_road, candidates)
    }

    /// The lane the entity must change to on its current road, when the lane it follows (as
    /// lane links carry it to the road's end) does not lead to the route's next road: the
    /// planned lane where the entity is (the stretch of this road that covers its s, or the
    /// first one ahead in its lane section). `None` when its lane leads on, when the route ends
    /// on this road, or when the entity is off the route.
    pub(crate) fn needed_lane(&self, net: &RoadNetwork, track: &LaneTrack) -> Option<i32> {
        let current = self.current()?;
        if current.road_id != track.road_id || current.direction != track.direction {
            return None;
        }
        let j = self.next_entry()?;
        let next = &self.plan.segments[j];
        let road = net.road(&track.road_id)?;
        let end = match track.direction {
            Direction::Forward => road.length,
            Direction::Backward => 0.0,
        };
        let exit_lane = carry_lane(
            net,
            &track.road_id,
            track.lane_id,
            track.s,
            end,
            track.direction,
        );
        let leads_on = net
            .lane_handle(&track.road_id, exit_lane, end)
            .is_some_and(|h| {
                net.successors(h)
                    .iter()
                    .any(|n| net.handle_road(*n).id == next.road_id)
            });
        if leads_on {
            return None;
        }
        // The stretches of this road from the cursor up to the next entry; the last that
        // covers the entity's s (a lane change point is covered by the stretches on both sides).
        let n = self.plan.segments.len();
        let mut covering = None;
        let mut i = self.cursor;
        while i != j {
            let seg = &self.plan.segments[i];
            let (lo, hi) = (seg.s_start.min(seg.s_end), seg.s_start.max(seg.s_end));
            if (lo - S_TOLERANCE..=hi + S_TOLERANCE).contains(&track.s) {
                covering = Some(seg);
            }
            i = (i + 1) % n;
        }
        let wanted = match covering {
            Some(seg) => seg.lane_id,
            None if road.lane_section_index(current.s_start)
                == road.lane_section_index(track.s) =>
            {
                current.lane_id
            }
            None => return None,
        };
        (wanted != track.lane_id && road.lane_span(wanted, track.s).is_ok()).then_some(wanted)
    }
}
