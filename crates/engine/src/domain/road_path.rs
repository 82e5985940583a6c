//! The shortest distance along roads between two road positions, ignoring lanes and driving
//! directions: the "along s" of OpenSCENARIO 2.0 §8.7.5.1.2 (time_headway) and §8.7.5.1.3
//! (space_gap) when the two objects are on different roads.
//!
//! Road linkage follows OpenDRIVE 1.8 §10.3 (road `<predecessor>`/`<successor>` with contact
//! point) and §10.6–10.7 (junction `<connection>`: the incoming road enters the connecting
//! road at its contact point). Dijkstra's algorithm over (road, direction of travel) nodes,
//! with the length of every road passed as the edge weight.
//!
//! Which roads join a road's end is `opendrive`'s [`RoadNetwork::joined_roads`], the road-level
//! reading of the links the lane graph (`query/graph.rs`) reads per lane: the road link, and
//! through a junction the connections whose incoming road this is, the connections whose
//! connecting (or linked) road this is, back to their incoming road, and the connecting roads
//! whose own road link names this road's end. Files often write a connection from one side
//! only; without the last two, a path that leaves a road backwards into a junction had no way
//! through, so the distance from A to B existed and the one from B to A did not.
//!
//! Why not `opendrive`'s search (`RoadNetwork::route_by`, `query/route_search.rs`): its nodes
//! are lanes driven in their driving direction, it moves only along lane links and over
//! drivable lanes. The distance along s between two objects is a question about the road
//! geometry only: it must have an answer for an object in an oncoming lane, on a sidewalk, on
//! a one-way road driven backwards, or where roads are linked but their lanes are not (a lane
//! that ends at the road's end). Served by that search it would lose those answers; made to
//! give them, the search would need road nodes beside lane nodes and moves against the driving
//! direction, which no route means. What the two share, the reading of road and junction
//! links at a road's end, is `joined_roads`.

use std::cmp::Ordering;
use std::collections::{BinaryHeap, HashMap};

use opendrive::{Direction, Real, RoadHandle, RoadNetwork};

/// A path from one road position to another along roads.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RoadPath {
    /// +1 when the path leaves the start road towards increasing s, −1 otherwise.
    pub(crate) start_direction: Real,
    /// +1 when the path runs along the end road towards increasing s (entered at its start),
    /// −1 otherwise.
    pub(crate) end_direction: Real,
    /// Distance along the roads' reference lines, m.
    pub(crate) length: Real,
}

/// A queue entry: distance travelled when entering road `road` in `direction`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Entry {
    cost: Real,
    road: usize,
    forward: bool,
}

impl Eq for Entry {}

impl Ord for Entry {
    fn cmp(&self, other: &Self) -> Ordering {
        // Reversed for a min-heap; ties broken by road index for determinism.
        other
            .cost
            .total_cmp(&self.cost)
            .then_with(|| other.road.cmp(&self.road))
            .then_with(|| other.forward.cmp(&self.forward))
    }
}

impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// The shortest path from (`from_road`, `from_s`) to (`to_road`, `to_s`) along roads, `None`
/// when no chain of links joins them or a road is unknown. The roads must differ.
pub(crate) fn shortest_road_path(
    network: &RoadNetwork,
    from_road: &str,
    from_s: Real,
    to_road: &str,
    to_s: Real,
) -> Option<RoadPath> {
    let roads = network.roads();
    let start = network.road_handle(from_road)?.index();
    let goal = network.road_handle(to_road)?.index();
    // best[road][forward as usize]: cheapest known entry cost; first[..]: direction the path
    // left the start road with.
    let mut best = vec![[Real::INFINITY; 2]; roads.len()];
    let mut first = vec![[true; 2]; roads.len()];
    let mut heap = BinaryHeap::new();
    let mut found: Option<RoadPath> = None;
    let start_length = roads[start].length;
    for forward in [true, false] {
        let exit = if forward {
            start_length - from_s
        } else {
            from_s
        };
        for (next, next_forward) in neighbours(network, start, forward) {
            relax(
                &mut best,
                &mut first,
                &mut heap,
                next,
                next_forward,
                exit.max(0.0),
                forward,
            );
        }
    }
    while let Some(Entry {
        cost,
        road,
        forward,
    }) = heap.pop()
    {
        if cost > best[road][forward as usize] {
            continue;
        }
        if found.is_some_and(|f| cost >= f.length) {
            break;
        }
        let length = roads[road].length;
        if road == goal {
            let inside = if forward { to_s } else { length - to_s };
            let total = cost + inside.max(0.0);
            if found.is_none_or(|f| total < f.length) {
                found = Some(RoadPath {
                    start_direction: if first[road][forward as usize] {
                        1.0
                    } else {
                        -1.0
                    },
                    end_direction: if forward { 1.0 } else { -1.0 },
                    length: total,
                });
            }
        }
        if road == start {
            continue;
        }
        let started_forward = first[road][forward as usize];
        for (next, next_forward) in neighbours(network, road, forward) {
            relax(
                &mut best,
                &mut first,
                &mut heap,
                next,
                next_forward,
                cost + length,
                started_forward,
            );
        }
    }
    found
}

/// Each road's index in [`RoadNetwork::roads`], by id: the node numbers of `neighbours`.
pub(crate) fn road_indices(network: &RoadNetwork) -> HashMap<&str, usize> {
    network
        .roads()
        .iter()
        .enumerate()
        .map(|(i, r)| (r.id.as_str(), i))
        .collect()
}

/// Records a cheaper way to enter `road` travelling `forward`.
fn relax(
    best: &mut [[Real; 2]],
    first: &mut [[bool; 2]],
    heap: &mut BinaryHeap<Entry>,
    road: usize,
    forward: bool,
    cost: Real,
    started_forward: bool,
) {
    let slot = &mut best[road][forward as usize];
    if cost < *slot {
        *slot = cost;
        first[road][forward as usize] = started_forward;
        heap.push(Entry {
            cost,
            road,
            forward,
        });
    }
}

/// Roads entered when leaving road `road` travelling `forward` (at its end) or backward (at
/// its start), with the direction of travel on each (see the module doc for junctions).
/// The roads joined to the end of road `road` (an index of `network.roads()`) reached
/// travelling `forward`, as (road index, entered at its start): opendrive's
/// [`RoadNetwork::joined_roads`].
pub(crate) fn neighbours(network: &RoadNetwork, road: usize, forward: bool) -> Vec<(usize, bool)> {
    let dir = if forward {
        Direction::Forward
    } else {
        Direction::Backward
    };
    // Road indices come from `network.roads()`, whose handles are u32 (opendrive::RoadHandle).
    network
        .joined_roads(RoadHandle(road as u32), dir)
        .into_iter()
        .map(|(h, d)| (h.index(), d == Direction::Forward))
        .collect()
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;

    /// Tolerance of lengths summed from the file's road lengths (m).
    const TOL: Real = 1e-9;

    /// `tests/files/two_junction_choice.xodr`: road 1 (100 m) → junction 100 (connecting
    /// roads 11, 12 of 10 m) → road 2 (200 m) or road 3 (100 m) → junction 200 (connecting
    /// roads 21, 31 of 10 m) → road 4 (100 m). The junctions' connections are written from
    /// roads 1, 2 and 3 only; roads 2, 3 and 4 reach back into them only through the
    /// connecting roads' own links.
    fn network() -> RoadNetwork {
        fixture("two_junction_choice.xodr")
    }

    /// A road network of `tests/files/`.
    fn fixture(name: &str) -> RoadNetwork {
        let path = format!("{}/tests/files/{name}", env!("CARGO_MANIFEST_DIR"));
        // The fixture is part of the test; a missing file is a broken checkout.
        RoadNetwork::from_file(Path::new(&path)).expect("fixture road network loads")
    }

    /// The path from `a` to `b` (road, s) is `length` m long leaving and entering towards
    /// +s, and the path back is as long, towards −s at both ends.
    fn both_ways(net: &RoadNetwork, a: (&str, Real), b: (&str, Real), length: Real) {
        let there = shortest_road_path(net, a.0, a.1, b.0, b.1).expect("a path there");
        assert!((there.length - length).abs() < TOL, "{}", there.length);
        assert_eq!((there.start_direction, there.end_direction), (1.0, 1.0));
        let back = shortest_road_path(net, b.0, b.1, a.0, a.1).expect("a path back");
        assert!((back.length - length).abs() < TOL, "{}", back.length);
        assert_eq!((back.start_direction, back.end_direction), (-1.0, -1.0));
    }

    #[test]
    fn the_distance_along_roads_is_the_same_both_ways_through_junctions() {
        let net = network();
        // Road 1 from s = 10 to its end (90 m), connecting road 12 (10), road 3 (100),
        // connecting road 31 (10), road 4 to s = 50 (50): 260 m, towards +s on both ends.
        // Back: road 4 from s = 50 to its start, into junction 200 by road 31's successor
        // link, road 3, into junction 100 by road 12's, road 1 from its end to s = 10: the
        // same 260 m, towards −s on both ends.
        both_ways(&net, ("1", 10.0), ("4", 50.0), 260.0);
    }

    #[test]
    fn a_road_reaches_back_into_a_junction_written_from_the_other_side() {
        let net = network();
        let roads = net.roads();
        let index = road_indices(&net);
        let ids = |road: &str, forward: bool| {
            let mut v: Vec<(&str, bool)> = neighbours(&net, index[road], forward)
                .into_iter()
                .map(|(i, f)| (roads[i].id.as_str(), f))
                .collect();
            v.sort();
            v
        };
        // Leaving road 4 at its start: connecting roads 21 and 31, entered at their ends.
        assert_eq!(ids("4", false), [("21", false), ("31", false)]);
        // Leaving road 1 at its end (connections written from road 1): 11 and 12, at their
        // starts, once each although their own links name road 1 too.
        assert_eq!(ids("1", true), [("11", true), ("12", true)]);
    }

    #[test]
    fn a_linked_road_reaches_back_to_the_incoming_road_of_a_direct_junction() {
        // Road A (100 m) → direct junction D → road B (50 m), the connection written from A's
        // side only. A, s = 30 to B, s = 20: 70 + 20 = 90 m towards +s; back from B, s = 20
        // (20 m to B's start, then A from its end to s = 30: 70 m) the same 90 m towards −s.
        let net = fixture("position/direct_junction.xodr");
        both_ways(&net, ("A", 30.0), ("B", 20.0), 90.0);
    }
}
