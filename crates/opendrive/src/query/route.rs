//! Shortest lane-level route between two lane positions: Dijkstra's algorithm over the lane
//! graph of `graph` (lane sections × lanes as nodes).
//!
//! Cost model: the length driven along s (|Δs| on each lane section, measured on the reference
//! line) plus [`LANE_CHANGE_COST`] for each change to an adjacent drivable lane of the same
//! driving direction within a lane section. A lane change takes no length of its own: it
//! happens at the point where the previous lane was entered. Only drivable lanes
//! ([`LaneType::is_drivable`](crate::LaneType::is_drivable)) are used between start and end.
//!
//! Written by hand rather than with `petgraph`: the lane graph is implicit (successors are
//! derived on demand from road, lane and junction links, nothing is materialised), start and
//! goal lie inside lanes, and the route needs its path with entry and exit s per lane, which
//! `petgraph::algo::dijkstra` (costs only) does not give; the search is a plain binary heap.

use std::cmp::Ordering;
use std::collections::{BinaryHeap, HashMap};

use super::graph::{Direction, LaneHandle};
use crate::math::Real;
use crate::network::RoadNetwork;

/// Extra cost (m) of one lane change, so that a route changes lanes only when it must or when
/// that saves more than this distance.
pub const LANE_CHANGE_COST: Real = 10.0;

/// A position in a lane: road, lane, s, and offset from the lane centre (positive left).
#[derive(Debug, Clone, PartialEq)]
pub struct LanePosition {
    /// Road id.
    pub road_id: String,
    /// Lane id.
    pub lane_id: i32,
    /// s (m).
    pub s: Real,
    /// Offset from the lane centre (m), positive left.
    pub offset: Real,
}

/// One piece of a route: a stretch of one lane.
#[derive(Debug, Clone, PartialEq)]
pub struct RouteSegment {
    /// Road id.
    pub road_id: String,
    /// Lane id.
    pub lane_id: i32,
    /// s where the route enters this stretch (m).
    pub s_start: Real,
    /// s where it leaves (m); below `s_start` when driving towards −s.
    pub s_end: Real,
    /// Direction of travel along s.
    pub direction: Direction,
}

/// A route: segments in driving order and the total length driven (m, sum of |Δs|).
#[derive(Debug, Clone, PartialEq)]
pub struct LaneRoute {
    /// The lane stretches, in order.
    pub segments: Vec<RouteSegment>,
    /// Total length (m), lane-change costs excluded.
    pub length: Real,
    /// Number of lane changes.
    pub lane_changes: usize,
}

#[derive(Clone, Copy, PartialEq)]
struct Queued {
    cost: Real,
    node: Option<LaneHandle>,
}
impl Eq for Queued {}
impl Ord for Queued {
    fn cmp(&self, other: &Self) -> Ordering {
        other
            .cost
            .total_cmp(&self.cost)
            .then_with(|| other.node.cmp(&self.node))
    }
}
impl PartialOrd for Queued {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// Best known way to reach a node: cost, entry s, previous node, whether by a lane change.
#[derive(Clone, Copy)]
struct Label {
    cost: Real,
    entry: Real,
    prev: Option<LaneHandle>,
    lane_change: bool,
}

impl RoadNetwork {
    /// The shortest route from `from` to `to` (see the module doc for the cost), or `None` if
    /// either position is unknown or `to` cannot be reached in the driving direction. Each lane
    /// section is entered once, so a goal behind the start on the start's own lane section is
    /// not reached by driving round a loop of the network.
    pub fn route(&self, from: &LanePosition, to: &LanePosition) -> Option<LaneRoute> {
        let start = self.lane_handle(&from.road_id, from.lane_id, from.s)?;
        let goal = self.lane_handle(&to.road_id, to.lane_id, to.s)?;
        let mut labels: HashMap<LaneHandle, Label> = HashMap::new();
        let mut heap = BinaryHeap::new();
        labels.insert(
            start,
            Label {
                cost: 0.0,
                entry: from.s,
                prev: None,
                lane_change: false,
            },
        );
        heap.push(Queued {
            cost: 0.0,
            node: Some(start),
        });
        let mut goal_label: Option<Label> = None;
        while let Some(Queued { cost, node }) = heap.pop() {
            let Some(h) = node else { break };
            let label = labels[&h];
            if cost > label.cost {
                continue;
            }
            let dir = self.driving_direction(h);
            let road = self.handle_road(h);
            let k = h.section as usize;
            let (sec_start, sec_end) = (road.lane_sections[k].s, road.lane_section_end(k));
            let exit = if dir == Direction::Forward {
                sec_end
            } else {
                sec_start
            };
            if h == goal {
                let ahead = match dir {
                    Direction::Forward => to.s >= label.entry - 1e-9,
                    Direction::Backward => to.s <= label.entry + 1e-9,
                };
                if ahead {
                    let total = cost + (to.s - label.entry).abs();
                    if goal_label.map_or(true, |g| total < g.cost) {
                        goal_label = Some(Label {
                            cost: total,
                            entry: label.entry,
                            prev: Some(h),
                            lane_change: false,
                        });
                        heap.push(Queued {
                            cost: total,
                            node: None,
                        });
                    }
                }
            }
            let mut relax = |n: LaneHandle, c: Real, entry: Real, lane_change: bool| {
                if n != goal && !self.is_drivable(n) {
                    return;
                }
                if labels.get(&n).map_or(true, |l| c < l.cost) {
                    labels.insert(
                        n,
                        Label {
                            cost: c,
                            entry,
                            prev: Some(h),
                            lane_change,
                        },
                    );
                    heap.push(Queued {
                        cost: c,
                        node: Some(n),
                    });
                }
            };
            let along = cost + (exit - label.entry).abs();
            for n in self.successors(h) {
                let nr = self.handle_road(n);
                let nk = n.section as usize;
                let entry = match self.driving_direction(n) {
                    Direction::Forward => nr.lane_sections[nk].s,
                    Direction::Backward => nr.lane_section_end(nk),
                };
                relax(n, along, entry, false);
            }
            for side in [h.lane - 1, h.lane + 1] {
                if side != 0
                    && side.signum() == h.lane.signum()
                    && road.lane_sections[k].lane(side).is_some()
                {
                    relax(
                        LaneHandle { lane: side, ..h },
                        cost + LANE_CHANGE_COST,
                        label.entry,
                        true,
                    );
                }
            }
        }
        let g = goal_label?;
        Some(self.build_route(&labels, goal, g, to.s))
    }

    /// Whether a handle's lane is drivable.
    fn is_drivable(&self, h: LaneHandle) -> bool {
        self.handle_road(h).lane_sections[h.section as usize]
            .lane(h.lane)
            .is_some_and(|l| l.lane_type.is_drivable())
    }

    fn build_route(
        &self,
        labels: &HashMap<LaneHandle, Label>,
        goal: LaneHandle,
        g: Label,
        goal_s: Real,
    ) -> LaneRoute {
        let mut chain = vec![(goal, g.entry, goal_s)];
        let mut lane_changes = 0;
        let mut cur = goal;
        let mut cur_label = labels[&goal];
        while let Some(p) = cur_label.prev {
            let pl = labels[&p];
            let exit = if cur_label.lane_change {
                lane_changes += 1;
                cur_label.entry
            } else {
                let road = self.handle_road(p);
                let k = p.section as usize;
                match self.driving_direction(p) {
                    Direction::Forward => road.lane_section_end(k),
                    Direction::Backward => road.lane_sections[k].s,
                }
            };
            chain.push((p, pl.entry, exit));
            cur = p;
            cur_label = pl;
        }
        debug_assert!(labels.contains_key(&cur));
        chain.reverse();
        let mut segments = Vec::new();
        let mut length = 0.0;
        let n = chain.len();
        for (i, (h, s0, s1)) in chain.into_iter().enumerate() {
            if (s1 - s0).abs() < 1e-12 && i + 1 != n {
                continue;
            }
            length += (s1 - s0).abs();
            segments.push(RouteSegment {
                road_id: self.handle_road(h).id.clone(),
                lane_id: h.lane,
                s_start: s0,
                s_end: s1,
                direction: self.driving_direction(h),
            });
        }
        LaneRoute {
            segments,
            length,
            lane_changes,
        }
    }
}
