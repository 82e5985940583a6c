//! The lane-level road graph (OpenDRIVE 1.8 §10 road linkage, §11 lane linkage, §12
//! junction connections and lane links): which lanes follow a lane in its driving direction.
//!
//! Driving direction (§10 `road/@rule`, §11): with right-hand traffic, lanes with negative
//! ids run towards +s and positive ids towards −s; left-hand traffic swaps the two. Lane
//! `<successor>` links name the lane at the section's end side (larger s), `<predecessor>` the
//! lane at its start side, whatever the driving direction.

pub use crate::handles::LaneHandle;
use crate::handles::{LaneGraph, Link, RoadHandle};
use crate::model::{ContactPoint, Road, TrafficRule};
use crate::network::RoadNetwork;

/// Travel along a road: towards increasing or decreasing s.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Direction {
    /// Towards increasing s.
    Forward,
    /// Towards decreasing s.
    Backward,
}

impl Direction {
    /// The opposite direction.
    pub fn reverse(self) -> Self {
        match self {
            Self::Forward => Self::Backward,
            Self::Backward => Self::Forward,
        }
    }
}

/// Driving direction of lane `id` on `road`.
pub(crate) fn driving_direction(road: &Road, id: i32) -> Direction {
    match (road.rule, id < 0) {
        (TrafficRule::RightHand, true) | (TrafficRule::LeftHand, false) => Direction::Forward,
        _ => Direction::Backward,
    }
}

impl RoadNetwork {
    /// The handle of lane `lane_id` in the lane section of `road_id` at `s`.
    pub fn lane_handle(&self, road_id: &str, lane_id: i32, s: f64) -> Option<LaneHandle> {
        let (ri, _) = self.road_or_err(road_id).ok()?;
        self.lane_handle_on(RoadHandle(ri as u32), lane_id, s)
    }

    /// [`lane_handle`](Self::lane_handle) on the road of handle `road` (no hash of its id).
    /// Inlined where the compiler sees fit in other crates (the lane index, the driver
    /// models' view call it per entity and step; issue 31).
    ///
    /// # Panics
    /// If the handle is of another, larger network.
    #[inline]
    pub fn lane_handle_on(&self, road: RoadHandle, lane_id: i32, s: f64) -> Option<LaneHandle> {
        let r = self.road_at(road);
        // A lane ending at s is found at its end (`Road::lane_section_holding`).
        let k = r.lane_section_index_holding(lane_id, s);
        r.lane_sections[k].lane(lane_id)?;
        Some(LaneHandle {
            road: road.0,
            section: k as u32,
            lane: lane_id,
        })
    }

    /// The road a handle belongs to.
    pub fn handle_road(&self, h: LaneHandle) -> &Road {
        &self.roads[h.road as usize]
    }

    /// The driving direction of a lane (right- or left-hand traffic from `road/@rule`).
    pub fn driving_direction(&self, h: LaneHandle) -> Direction {
        driving_direction(self.handle_road(h), h.lane)
    }

    /// Lanes that follow `h` in its driving direction (through lane sections, road links and
    /// junction lane links), keeping only those driven the same way. A view of the lane graph
    /// worked out when the network was built (`handles::LaneGraph`): no allocation. Empty for
    /// a handle of no lane of this network.
    #[inline]
    pub fn successors(&self, h: LaneHandle) -> &[LaneHandle] {
        self.lane_graph.successors(&self.roads, h)
    }

    /// Lanes that `h` follows in its driving direction (a view, as
    /// [`successors`](Self::successors)).
    #[inline]
    pub fn predecessors(&self, h: LaneHandle) -> &[LaneHandle] {
        self.lane_graph.predecessors(&self.roads, h)
    }

    /// The lane graph of this network, for `handles::LaneGraph` when the network is built:
    /// each lane's successors and predecessors, from its lane, road and junction links.
    pub(crate) fn build_lane_graph(&self) -> LaneGraph {
        LaneGraph::build(&self.roads, |h| {
            let dir = self.driving_direction(h);
            let follow = self
                .connected(h, dir)
                .into_iter()
                .filter(|&(l, d)| self.driving_direction(l) == d)
                .map(|(l, _)| l);
            let precede = self
                .connected(h, dir.reverse())
                .into_iter()
                .filter(|&(l, d)| self.driving_direction(l) == d.reverse())
                .map(|(l, _)| l);
            (follow.collect(), precede.collect())
        })
    }

    /// Lanes joined to the end of `h` reached when travelling `dir`, with the direction of
    /// travel on them.
    pub(crate) fn connected(&self, h: LaneHandle, dir: Direction) -> Vec<(LaneHandle, Direction)> {
        let road = self.handle_road(h);
        let k = h.section as usize;
        let Some(lane) = road.lane_sections[k].lane(h.lane) else {
            return Vec::new();
        };
        let (next_id, next_k, link) = match dir {
            Direction::Forward => (
                lane.successor,
                k + 1,
                self.topology.links[h.road as usize][1],
            ),
            Direction::Backward => (
                lane.predecessor,
                k.wrapping_sub(1),
                self.topology.links[h.road as usize][0],
            ),
        };
        let mut out = Vec::new();
        if next_k < road.lane_sections.len() {
            if let Some(id) = next_id {
                if road.lane_sections[next_k].lane(id).is_some() {
                    out.push((
                        LaneHandle {
                            road: h.road,
                            section: next_k as u32,
                            lane: id,
                        },
                        dir,
                    ));
                }
            }
            return out;
        }
        match link {
            Some(Link::Road(ri, contact_point)) => {
                if let Some(id) = next_id {
                    let cp = contact_point.unwrap_or(ContactPoint::Start);
                    if let Some(e) = self.entry(ri as usize, cp, id) {
                        out.push(e);
                    }
                }
            }
            Some(Link::Junction(ji)) => {
                self.through_junction(h, ji as usize, dir, &mut out);
            }
            None => {}
        }
        out
    }

    /// The roads joined to the end of road `road` reached travelling `dir` (its successor end
    /// forward, its predecessor end backward), each with the direction of travel on it
    /// (`Forward`: entered at its start), in a fixed order without repeats. Road level: lanes
    /// and driving directions are not looked at (the lane graph, [`RoadNetwork::successors`],
    /// reads the same links per lane). The road link (OpenDRIVE 1.8 §10.3; a missing
    /// `contactPoint` is the start), or through a junction (§10.6–10.7), connection by
    /// connection: the connecting road of a connection whose incoming road this is; the
    /// incoming road of a connection whose connecting road this is, entered at this end
    /// (connections written from the other side); a connecting road whose own road link names
    /// this end.
    pub fn joined_roads(&self, road: RoadHandle, dir: Direction) -> Vec<(RoadHandle, Direction)> {
        let ri = road.index();
        let entered = |cp: ContactPoint| match cp {
            ContactPoint::Start => Direction::Forward,
            ContactPoint::End => Direction::Backward,
        };
        let (link, our_end) = match dir {
            Direction::Forward => (self.topology.links[ri][1], ContactPoint::End),
            Direction::Backward => (self.topology.links[ri][0], ContactPoint::Start),
        };
        let mut out: Vec<(RoadHandle, Direction)> = Vec::new();
        match link {
            Some(Link::Road(next, cp)) => {
                out.push((RoadHandle(next), entered(cp.unwrap_or(ContactPoint::Start))));
            }
            Some(Link::Junction(ji)) => {
                let mut add = |n: (RoadHandle, Direction)| {
                    if !out.contains(&n) {
                        out.push(n);
                    }
                };
                let (j, resolved) = (
                    &self.junctions[ji as usize],
                    &self.topology.connections[ji as usize],
                );
                let here = Some(road.0);
                for (c, rc) in j.connections.iter().zip(resolved) {
                    if let (true, Some(ci)) = (rc.incoming == here, rc.connecting) {
                        add((RoadHandle(ci), entered(c.contact_point)));
                    }
                    if let (true, true, Some(ii)) = (
                        rc.connecting == here,
                        c.contact_point == our_end,
                        rc.incoming,
                    ) {
                        let touches = |l: Option<Link>| l == Some(Link::Junction(ji));
                        let [pred, succ] = self.topology.links[ii as usize];
                        if touches(succ) {
                            add((RoadHandle(ii), Direction::Backward));
                        } else if touches(pred) {
                            add((RoadHandle(ii), Direction::Forward));
                        }
                    }
                    if let Some(ci) = rc.connecting {
                        let joins_us = |l: Option<Link>| {
                            matches!(l, Some(Link::Road(r, cp))
                                if r == road.0 && cp.is_none_or(|cp| cp == our_end))
                        };
                        let [pred, succ] = self.topology.links[ci as usize];
                        if joins_us(pred) {
                            add((RoadHandle(ci), Direction::Forward));
                        }
                        if joins_us(succ) {
                            add((RoadHandle(ci), Direction::Backward));
                        }
                    }
                }
            }
            None => {}
        }
        out
    }

    /// Lanes of the roads of junction `ji` joined to the end of lane `h` that is reached
    /// travelling `dir`: from the junction's `<laneLink>`s whose `incomingRoad` is the road,
    /// from those whose connecting/linked road is the road (read backwards), and from the
    /// connecting roads' own road and lane links back to the road (files often write a
    /// connection in one direction only).
    fn through_junction(
        &self,
        h: LaneHandle,
        ji: usize,
        dir: Direction,
        out: &mut Vec<(LaneHandle, Direction)>,
    ) {
        let (j, resolved) = (&self.junctions[ji], &self.topology.connections[ji]);
        let here = Some(h.road);
        let our_end = match dir {
            Direction::Forward => ContactPoint::End,
            Direction::Backward => ContactPoint::Start,
        };
        for (c, rc) in j.connections.iter().zip(resolved) {
            let (true, Some(ci)) = (rc.incoming == here, rc.connecting) else {
                continue;
            };
            for ll in c.lane_links.iter().filter(|ll| ll.from == h.lane) {
                if let Some(e) = self.entry(ci as usize, c.contact_point, ll.to) {
                    out.push(e);
                }
            }
        }
        // Connections written from the other side: this road is the connecting (or linked)
        // road, entered at the end we are leaving; go back to the incoming road's lane.
        for (c, rc) in j.connections.iter().zip(resolved) {
            let (true, true, Some(ii)) = (
                rc.connecting == here,
                c.contact_point == our_end,
                rc.incoming,
            ) else {
                continue;
            };
            let touches = |l: Option<Link>| l == Some(Link::Junction(ji as u32));
            let [pred, succ] = self.topology.links[ii as usize];
            let inc_end = if touches(succ) {
                ContactPoint::End
            } else if touches(pred) {
                ContactPoint::Start
            } else {
                continue;
            };
            for ll in c.lane_links.iter().filter(|ll| ll.to == h.lane) {
                if let Some(e) = self.entry(ii as usize, inc_end, ll.from) {
                    if !out.contains(&e) {
                        out.push(e);
                    }
                }
            }
        }
        let mut seen: Vec<u32> = Vec::new();
        for rc in resolved {
            let Some(ci) = rc.connecting else { continue };
            if seen.contains(&ci) {
                continue;
            }
            seen.push(ci);
            let conn = &self.roads[ci as usize];
            let [pred, succ] = self.topology.links[ci as usize];
            for (conn_end, link) in [(ContactPoint::Start, pred), (ContactPoint::End, succ)] {
                let joins_us = match link {
                    Some(Link::Road(r, cp)) => r == h.road && cp.is_none_or(|cp| cp == our_end),
                    _ => false,
                };
                if !joins_us {
                    continue;
                }
                let k = match conn_end {
                    ContactPoint::Start => 0,
                    ContactPoint::End => conn.lane_sections.len() - 1,
                };
                for lane in conn.lane_sections[k].lanes() {
                    let back = match conn_end {
                        ContactPoint::Start => lane.predecessor,
                        ContactPoint::End => lane.successor,
                    };
                    if back == Some(h.lane) {
                        if let Some(e) = self.entry(ci as usize, conn_end, lane.id) {
                            if !out.contains(&e) {
                                out.push(e);
                            }
                        }
                    }
                }
            }
        }
    }

    /// Lane `id` of road `ri` entered at its start or end, with the direction of travel.
    fn entry(&self, ri: usize, cp: ContactPoint, id: i32) -> Option<(LaneHandle, Direction)> {
        let road = &self.roads[ri];
        let (k, dir) = match cp {
            ContactPoint::Start => (0, Direction::Forward),
            ContactPoint::End => (road.lane_sections.len() - 1, Direction::Backward),
        };
        road.lane_sections[k].lane(id)?;
        Some((
            LaneHandle {
                road: ri as u32,
                section: k as u32,
                lane: id,
            },
            dir,
        ))
    }
}
