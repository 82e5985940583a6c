//! The shortest distance along roads between two road positions, ignoring lanes and driving
//! directions: the "along s" of OpenSCENARIO 2.0 §8.7.5.1.2 (time_headway) and §8.7.5.1.3
//! (space_gap) when the two objects are on different roads.
//!
//! Road linkage follows OpenDRIVE 1.8 §10.3 (road `<predecessor>`/`<successor>` with contact
//! point) and §10.6–10.7 (junction `<connection>`: the incoming road enters the connecting
//! road at its contact point). Dijkstra's algorithm over (road, direction of travel) nodes,
//! with the length of every road passed as the edge weight.
//!
//! Why not `RoadNetwork::route`: that is a lane route in the driving direction, which has no
//! answer for an object in an oncoming lane or on a sidewalk; the distance along s between two
//! objects is a question about the road geometry only.

use std::cmp::Ordering;
use std::collections::{BinaryHeap, HashMap};

use opendrive::{ContactPoint, ElementType, Real, RoadLink, RoadNetwork};

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
    let index: HashMap<&str, usize> = roads
        .iter()
        .enumerate()
        .map(|(i, r)| (r.id.as_str(), i))
        .collect();
    let (&start, &goal) = (index.get(from_road)?, index.get(to_road)?);
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
        for (next, next_forward) in neighbours(network, &index, start, forward) {
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
            if found.map_or(true, |f| total < f.length) {
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
        for (next, next_forward) in neighbours(network, &index, road, forward) {
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
/// its start), with the direction of travel on each.
pub(crate) fn neighbours(
    network: &RoadNetwork,
    index: &HashMap<&str, usize>,
    road: usize,
    forward: bool,
) -> Vec<(usize, bool)> {
    let r = &network.roads()[road];
    let link = if forward {
        &r.links.successor
    } else {
        &r.links.predecessor
    };
    let entered = |cp: ContactPoint| cp == ContactPoint::Start;
    let mut out = Vec::new();
    match link {
        Some(RoadLink {
            element_type: ElementType::Road,
            element_id,
            contact_point,
        }) => {
            if let Some(&i) = index.get(element_id.as_str()) {
                out.push((i, entered(contact_point.unwrap_or(ContactPoint::Start))));
            }
        }
        Some(RoadLink {
            element_type: ElementType::Junction,
            element_id,
            ..
        }) => {
            if let Some(j) = network.junction(element_id) {
                for c in j.connections.iter().filter(|c| c.incoming_road == r.id) {
                    if let Some(&i) = index.get(c.connecting_road.as_str()) {
                        out.push((i, entered(c.contact_point)));
                    }
                }
            }
        }
        None => {}
    }
    out
}
