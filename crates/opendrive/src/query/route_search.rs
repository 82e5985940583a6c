//! Dijkstra's algorithm over the lane graph of `graph` (OpenDRIVE 1.8 §10.3 road linkage,
//! §11.5 lane linkage, §12 junctions) under a caller's cost: the one search behind
//! [`RoadNetwork::route`] (length) and the route strategies of OpenSCENARIO (the engine's
//! `routing` module implements [`LaneCost`] per strategy).
//!
//! Nodes are lanes of lane sections, each driven in its driving direction. Moves: drive to the
//! section's end and onto a successor lane; or change to an adjacent drivable lane of the same
//! driving direction in the same section, at the point where the current lane was entered (a
//! lane change takes no length of its own). Only drivable lanes
//! ([`LaneType::is_drivable`](crate::LaneType::is_drivable)) are used between the two ends.
//! The start lane reached again later (round a closed loop) is a node of its own, so a goal
//! behind the start on its own lane section is reached by driving round the loop.
//!
//! Written by hand rather than with `petgraph`: the lane graph is implicit (successors are
//! derived on demand from road, lane and junction links, nothing is materialised), start and
//! goal lie inside lanes, and the route needs its path with entry and exit s per lane, which
//! `petgraph::algo::dijkstra` (costs only) does not give; the search is a plain binary heap.

use std::cmp::Ordering;
use std::collections::{BinaryHeap, HashMap};

use super::graph::{Direction, LaneHandle};
use crate::math::{Real, LENGTH_EPSILON};
use crate::network::RoadNetwork;

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

/// A path cost: summed along the path, totally ordered.
pub trait PathCost: Copy + Default {
    /// The sum of two costs.
    fn plus(self, other: Self) -> Self;
    /// A total order (the cheaper first).
    fn total_cmp(&self, other: &Self) -> Ordering;
}

impl PathCost for Real {
    fn plus(self, other: Self) -> Self {
        self + other
    }
    fn total_cmp(&self, other: &Self) -> Ordering {
        Real::total_cmp(self, other)
    }
}

/// What the moves of a search cost.
pub trait LaneCost {
    /// The cost type.
    type Cost: PathCost;
    /// Driving `length` m of lane `h`, entered at `s`.
    fn along(&self, h: LaneHandle, s: Real, length: Real) -> Self::Cost;
    /// Changing from lane `h` to an adjacent lane at `s`.
    fn lane_change(&self, h: LaneHandle, s: Real) -> Self::Cost;
    /// Moving from lane `from` onto its successor `to` (next section, next road, through a
    /// junction), on top of driving `from`.
    fn enter(&self, from: LaneHandle, to: LaneHandle) -> Self::Cost;
}

/// A lane change of a path: on road `road_id` at `s`, `path_s` metres after the path's start.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneChange {
    /// Path s where the path moves to the new lane (m), along the roads' reference lines; the
    /// latest point is the end of the lane section (the next stretch on `to_lane` says how far
    /// the path stays there).
    pub path_s: Real,
    /// Road id.
    pub road_id: String,
    /// Road s of the change (m).
    pub s: Real,
    /// Lane left.
    pub from_lane: i32,
    /// Lane entered.
    pub to_lane: i32,
}

/// The result of a search: lane stretches in driving order and the lane changes between them.
#[derive(Debug, Clone, PartialEq)]
pub struct LanePath {
    /// The lane stretches, in order.
    pub segments: Vec<RouteSegment>,
    /// The lane changes, in order.
    pub lane_changes: Vec<LaneChange>,
}

/// A node of the search: a lane, and whether this is the start itself.
type Key = (LaneHandle, bool);

#[derive(Clone, Copy)]
struct Queued<C> {
    cost: C,
    node: Option<Key>,
}

impl<C: PathCost> PartialEq for Queued<C> {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl<C: PathCost> Eq for Queued<C> {}
impl<C: PathCost> Ord for Queued<C> {
    /// Reversed, so that `BinaryHeap` pops the cheapest; ties broken by the handle, so that
    /// the result does not depend on insertion order.
    fn cmp(&self, other: &Self) -> Ordering {
        other
            .cost
            .total_cmp(&self.cost)
            .then_with(|| other.node.cmp(&self.node))
    }
}
impl<C: PathCost> PartialOrd for Queued<C> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// Best known way to reach a node: cost, s where it is entered, previous node, whether by a
/// lane change.
#[derive(Clone, Copy)]
struct Label<C> {
    cost: C,
    entry: Real,
    prev: Option<Key>,
    lane_change: bool,
}

impl RoadNetwork {
    /// The s where lane `h` is left when driven to its section's end.
    fn exit_s(&self, h: LaneHandle) -> Real {
        let road = self.handle_road(h);
        let k = h.section as usize;
        match self.driving_direction(h) {
            Direction::Forward => road.lane_section_end(k),
            Direction::Backward => road.lane_sections[k].s,
        }
    }

    /// The s where lane `h` is entered from its section's start side.
    fn entry_s(&self, h: LaneHandle) -> Real {
        let road = self.handle_road(h);
        let k = h.section as usize;
        match self.driving_direction(h) {
            Direction::Forward => road.lane_sections[k].s,
            Direction::Backward => road.lane_section_end(k),
        }
    }

    /// Whether a handle's lane is drivable.
    fn is_drivable(&self, h: LaneHandle) -> bool {
        self.handle_road(h).lane_sections[h.section as usize]
            .lane(h.lane)
            .is_some_and(|l| l.lane_type.is_drivable())
    }

    /// The cheapest path from `from` to `to` under `cost` (see the module doc for the moves),
    /// or `None` if either position names no lane or `to` cannot be reached in the driving
    /// direction.
    pub fn route_by<L: LaneCost>(
        &self,
        cost: &L,
        from: &LanePosition,
        to: &LanePosition,
    ) -> Option<LanePath> {
        let start = self.lane_handle(&from.road_id, from.lane_id, from.s)?;
        let goal = self.lane_handle(&to.road_id, to.lane_id, to.s)?;
        let mut labels: HashMap<Key, Label<L::Cost>> = HashMap::new();
        let mut heap = BinaryHeap::new();
        labels.insert(
            (start, true),
            Label {
                cost: L::Cost::default(),
                entry: from.s,
                prev: None,
                lane_change: false,
            },
        );
        heap.push(Queued {
            cost: L::Cost::default(),
            node: Some((start, true)),
        });
        let mut best_goal: Option<(L::Cost, Key)> = None;
        while let Some(Queued { cost: c, node }) = heap.pop() {
            let Some(key) = node else { break };
            let (h, is_start) = key;
            let label = labels[&key];
            if c.total_cmp(&label.cost) == Ordering::Greater {
                continue;
            }
            if h == goal {
                let ahead = match self.driving_direction(h) {
                    Direction::Forward => to.s >= label.entry - LENGTH_EPSILON,
                    Direction::Backward => to.s <= label.entry + LENGTH_EPSILON,
                };
                if ahead {
                    let total = c.plus(cost.along(h, label.entry, (to.s - label.entry).abs()));
                    if best_goal.is_none_or(|(b, _)| total.total_cmp(&b) == Ordering::Less) {
                        best_goal = Some((total, key));
                        heap.push(Queued {
                            cost: total,
                            node: None,
                        });
                    }
                }
            }
            let mut relax = |n: LaneHandle, nc: L::Cost, entry: Real, lane_change: bool| {
                if n != goal && !self.is_drivable(n) {
                    return;
                }
                // A lane change keeps the start's own node kind; every other move leaves it.
                let nk = (n, lane_change && is_start);
                if labels
                    .get(&nk)
                    .is_none_or(|l| nc.total_cmp(&l.cost) == Ordering::Less)
                {
                    labels.insert(
                        nk,
                        Label {
                            cost: nc,
                            entry,
                            prev: Some(key),
                            lane_change,
                        },
                    );
                    heap.push(Queued {
                        cost: nc,
                        node: Some(nk),
                    });
                }
            };
            let exit = self.exit_s(h);
            let along = c.plus(cost.along(h, label.entry, (exit - label.entry).abs()));
            for &n in self.successors(h) {
                relax(n, along.plus(cost.enter(h, n)), self.entry_s(n), false);
            }
            let section = &self.handle_road(h).lane_sections[h.section as usize];
            for side in [h.lane - 1, h.lane + 1] {
                if side != 0 && side.signum() == h.lane.signum() && section.lane(side).is_some() {
                    let nc = c.plus(cost.lane_change(h, label.entry));
                    relax(LaneHandle { lane: side, ..h }, nc, label.entry, true);
                }
            }
        }
        let (_, goal_key) = best_goal?;
        Some(self.lane_path(&labels, goal_key, to.s))
    }

    /// The stretches from the start to the node `goal` (left at `goal_s`).
    fn lane_path<C: Copy>(
        &self,
        labels: &HashMap<Key, Label<C>>,
        goal: Key,
        goal_s: Real,
    ) -> LanePath {
        // (lane, entry s, exit s, whether it is left by a lane change), goal first.
        let mut label = labels[&goal];
        let mut chain = vec![(goal.0, label.entry, goal_s, false)];
        while let Some(p) = label.prev {
            let exit = if label.lane_change {
                label.entry
            } else {
                self.exit_s(p.0)
            };
            let pl = labels[&p];
            chain.push((p.0, pl.entry, exit, label.lane_change));
            label = pl;
        }
        chain.reverse();
        let last = chain.len() - 1;
        let mut path = LanePath {
            segments: Vec::with_capacity(chain.len()),
            lane_changes: Vec::new(),
        };
        let mut path_s = 0.0;
        for (i, &(h, s0, s1, changes)) in chain.iter().enumerate() {
            path_s += (s1 - s0).abs();
            let road_id = &self.handle_road(h).id;
            // Zero-length stretches (a lane changed where it was entered) carry no driving,
            // except the goal's, which names the final lane; their lane changes are kept.
            if i == last || (s1 - s0).abs() > LENGTH_EPSILON {
                path.segments.push(RouteSegment {
                    road_id: road_id.clone(),
                    lane_id: h.lane,
                    s_start: s0,
                    s_end: s1,
                    direction: self.driving_direction(h),
                });
            }
            if changes {
                path.lane_changes.push(LaneChange {
                    path_s,
                    road_id: road_id.clone(),
                    s: s1,
                    from_lane: h.lane,
                    // Only links before the goal are lane changes (the goal entry has `false`).
                    to_lane: chain[i + 1].0.lane,
                });
            }
        }
        path
    }
}
