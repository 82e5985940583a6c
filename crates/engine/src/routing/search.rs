//! Dijkstra's algorithm over the OpenDRIVE lane graph (OpenDRIVE 1.8 §10.3 road linkage,
//! §11.4 lane linkage, §10 junctions; through `opendrive::RoadNetwork::successors`) with the
//! cost of a routeStrategy (see `cost`).
//!
//! Nodes are lanes of lane sections, each driven in its driving direction. Moves: drive to
//! the section's end and onto a successor lane; or change to an adjacent drivable lane of the
//! same driving direction in the same section, at the point where the current lane was
//! entered (a lane change takes no length of its own). Only drivable lanes are used between
//! the two ends. This is the model of `RoadNetwork::route`, with the strategy's cost in place
//! of length; under `shortest` both give the same route.

use std::cmp::Ordering;
use std::collections::{BinaryHeap, HashMap};

use opendrive::{Direction, LaneHandle, LanePosition, Real, RouteSegment, LENGTH_EPSILON};

use super::cost::{Cost, CostModel};

/// A node of the search: a lane, and whether this is the start itself (the start lane
/// reached again later, e.g. round a closed loop, is a different node).
type Key = (LaneHandle, bool);

#[derive(Clone, Copy)]
struct Queued {
    cost: Cost,
    node: Option<Key>,
}

impl PartialEq for Queued {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Queued {}
impl Ord for Queued {
    /// Reversed, so that `BinaryHeap` pops the cheapest; ties broken by the handle, so that
    /// the result does not depend on insertion order.
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

/// Best known way to reach a lane: cost, s where it is entered, previous lane, whether by a
/// lane change.
#[derive(Clone, Copy)]
struct Label {
    cost: Cost,
    entry: Real,
    prev: Option<Key>,
    lane_change: bool,
}

/// The s where lane `h` is left when driven to its section's end.
fn exit_s(model: &CostModel<'_>, h: LaneHandle) -> Real {
    let road = model.network.handle_road(h);
    let k = h.section as usize;
    match model.network.driving_direction(h) {
        Direction::Forward => road.lane_section_end(k),
        Direction::Backward => road.lane_sections[k].s,
    }
}

/// The s where lane `h` is entered from its section's start side.
fn entry_s(model: &CostModel<'_>, h: LaneHandle) -> Real {
    let road = model.network.handle_road(h);
    let k = h.section as usize;
    match model.network.driving_direction(h) {
        Direction::Forward => road.lane_sections[k].s,
        Direction::Backward => road.lane_section_end(k),
    }
}

fn drivable(model: &CostModel<'_>, h: LaneHandle) -> bool {
    model.network.handle_road(h).lane_sections[h.section as usize]
        .lane(h.lane)
        .is_some_and(|l| l.lane_type.is_drivable())
}

/// The cheapest path from `from` to `to` under `model`, as lane stretches in driving order;
/// `None` when either position names no lane or `to` cannot be reached.
pub(crate) fn search(
    model: &CostModel<'_>,
    from: &LanePosition,
    to: &LanePosition,
) -> Option<LegPath> {
    let net = model.network;
    let start = net.lane_handle(&from.road_id, from.lane_id, from.s)?;
    let goal = net.lane_handle(&to.road_id, to.lane_id, to.s)?;
    let mut labels: HashMap<Key, Label> = HashMap::new();
    let mut heap = BinaryHeap::new();
    labels.insert(
        (start, true),
        Label {
            cost: Cost::default(),
            entry: from.s,
            prev: None,
            lane_change: false,
        },
    );
    heap.push(Queued {
        cost: Cost::default(),
        node: Some((start, true)),
    });
    let mut best_goal: Option<(Cost, Key)> = None;
    while let Some(Queued { cost, node }) = heap.pop() {
        let Some(key) = node else { break };
        let (h, is_start) = key;
        let label = labels[&key];
        if cost.total_cmp(&label.cost) == Ordering::Greater {
            continue;
        }
        if h == goal {
            let ahead = match net.driving_direction(h) {
                Direction::Forward => to.s >= label.entry - LENGTH_EPSILON,
                Direction::Backward => to.s <= label.entry + LENGTH_EPSILON,
            };
            if ahead {
                let total = cost.plus(model.along(h, label.entry, (to.s - label.entry).abs()));
                if best_goal.map_or(true, |(c, _)| total.total_cmp(&c) == Ordering::Less) {
                    best_goal = Some((total, key));
                    heap.push(Queued {
                        cost: total,
                        node: None,
                    });
                }
            }
        }
        let mut relax = |n: LaneHandle, c: Cost, entry: Real, lane_change: bool| {
            if n != goal && !drivable(model, n) {
                return;
            }
            // A lane change keeps the start's own node kind; every other move leaves it.
            let nk = (n, lane_change && is_start);
            if labels
                .get(&nk)
                .map_or(true, |l| c.total_cmp(&l.cost) == Ordering::Less)
            {
                labels.insert(
                    nk,
                    Label {
                        cost: c,
                        entry,
                        prev: Some(key),
                        lane_change,
                    },
                );
                heap.push(Queued {
                    cost: c,
                    node: Some(nk),
                });
            }
        };
        let exit = exit_s(model, h);
        let along = cost.plus(model.along(h, label.entry, (exit - label.entry).abs()));
        for n in net.successors(h) {
            relax(n, along.plus(model.enter(h, n)), entry_s(model, n), false);
        }
        let section = &net.handle_road(h).lane_sections[h.section as usize];
        for side in [h.lane - 1, h.lane + 1] {
            if side != 0 && side.signum() == h.lane.signum() && section.lane(side).is_some() {
                let c = cost.plus(model.lane_change(h, label.entry));
                relax(LaneHandle { lane: side, ..h }, c, label.entry, true);
            }
        }
    }
    let (_, goal_key) = best_goal?;
    Some(segments(model, &labels, goal_key, to.s))
}

/// A lane change of a leg: on road `road_id` at `s`, `path_s` metres after the leg's start.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LegChange {
    pub(crate) path_s: Real,
    pub(crate) road_id: String,
    pub(crate) s: Real,
    pub(crate) from_lane: i32,
    pub(crate) to_lane: i32,
}

/// The result of a search: stretches in driving order and the lane changes between them.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LegPath {
    pub(crate) segments: Vec<RouteSegment>,
    pub(crate) lane_changes: Vec<LegChange>,
}

/// The stretches from the start to the node `goal` (left at `goal_s`).
fn segments(
    model: &CostModel<'_>,
    labels: &HashMap<Key, Label>,
    goal: Key,
    goal_s: Real,
) -> LegPath {
    // (lane, entry s, exit s, whether it is left by a lane change), goal first.
    let mut label = labels[&goal];
    let mut chain = vec![(goal.0, label.entry, goal_s, false)];
    while let Some(p) = label.prev {
        let exit = if label.lane_change {
            label.entry
        } else {
            exit_s(model, p.0)
        };
        let pl = labels[&p];
        chain.push((p.0, pl.entry, exit, label.lane_change));
        label = pl;
    }
    chain.reverse();
    let net = model.network;
    let last = chain.len() - 1;
    let mut path = LegPath {
        segments: Vec::with_capacity(chain.len()),
        lane_changes: Vec::new(),
    };
    let mut path_s = 0.0;
    for (i, &(h, s0, s1, changes)) in chain.iter().enumerate() {
        path_s += (s1 - s0).abs();
        let road_id = &net.handle_road(h).id;
        // Zero-length stretches (a lane changed where it was entered) carry no driving, except
        // the goal's, which names the final lane; their lane changes are kept below.
        if i == last || (s1 - s0).abs() > LENGTH_EPSILON {
            path.segments.push(RouteSegment {
                road_id: road_id.clone(),
                lane_id: h.lane,
                s_start: s0,
                s_end: s1,
                direction: net.driving_direction(h),
            });
        }
        if changes {
            path.lane_changes.push(LegChange {
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
