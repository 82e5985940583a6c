//! Dense integer handles for roads, junctions and lanes, the road network's links resolved to
//! them at load (OpenDRIVE 1.8 §10.3 road linkage, §12 junction connections), and the lane
//! graph's edges worked out from them once ([`LaneGraph`]). String ids are read from and
//! written to files only; queries walk the resolved links.

use crate::model::{ContactPoint, ElementType, Junction, Road, RoadLink};

/// A road of a [`RoadNetwork`](crate::RoadNetwork): its index in
/// [`roads`](crate::RoadNetwork::roads). Valid for the network that gave it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct RoadHandle(pub u32);

impl RoadHandle {
    /// The index in [`RoadNetwork::roads`](crate::RoadNetwork::roads).
    #[inline]
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// A junction of a [`RoadNetwork`](crate::RoadNetwork): its index in
/// [`junctions`](crate::RoadNetwork::junctions).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct JunctionHandle(pub u32);

impl JunctionHandle {
    /// The index in [`RoadNetwork::junctions`](crate::RoadNetwork::junctions).
    #[inline]
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// A lane of one lane section: a node of the lane graph (`query::graph`). Cheap to copy and
/// compare.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct LaneHandle {
    /// Index of the road in [`RoadNetwork::roads`](crate::RoadNetwork::roads).
    pub road: u32,
    /// Index of the lane section in the road's `lane_sections`.
    pub section: u32,
    /// Lane id.
    pub lane: i32,
}

impl LaneHandle {
    /// The road the lane belongs to.
    #[inline]
    pub fn road_handle(self) -> RoadHandle {
        RoadHandle(self.road)
    }
}

/// The lane graph's edges (OpenDRIVE 1.8 §10–12: lane, road and junction links), worked out
/// once when the network is built (`RoadNetwork::build_lane_graph`, query/graph.rs): for each
/// lane of each lane section, the lanes that follow it and the lanes it follows in its driving
/// direction, so that `RoadNetwork::successors` and `predecessors` return a slice of it and
/// allocate nothing. Stored flat (compressed rows): every lane of the network has a slot, a
/// section's slots running from its rightmost lane (id −right.len()) through the centre lane
/// to its leftmost (id left.len()).
#[derive(Debug, Clone, Default)]
pub(crate) struct LaneGraph {
    /// Per road, per lane section: the slot of its rightmost lane.
    section_base: Vec<Vec<u32>>,
    /// Slot i's successors are `successors[successor_start[i]..successor_start[i + 1]]`.
    successor_start: Vec<u32>,
    successors: Vec<LaneHandle>,
    /// Slot i's predecessors, as `successor_start`.
    predecessor_start: Vec<u32>,
    predecessors: Vec<LaneHandle>,
}

impl LaneGraph {
    /// The graph of `roads`, `edges` giving the (successors, predecessors) of each lane.
    pub(crate) fn build(
        roads: &[Road],
        mut edges: impl FnMut(LaneHandle) -> (Vec<LaneHandle>, Vec<LaneHandle>),
    ) -> Self {
        let mut g = Self {
            successor_start: vec![0],
            predecessor_start: vec![0],
            ..Self::default()
        };
        let mut slot = 0u32;
        for (ri, r) in roads.iter().enumerate() {
            let mut bases = Vec::with_capacity(r.lane_sections.len());
            for (k, section) in r.lane_sections.iter().enumerate() {
                bases.push(slot);
                let (right, left) = (section.right.len() as i32, section.left.len() as i32);
                for lane in -right..=left {
                    slot += 1;
                    // A slot whose id the section does not hold where its place says (lanes not
                    // numbered in order) has no edges, as `slot` finds none for it.
                    if section.lane(lane).is_some() {
                        let (next, before) = edges(LaneHandle {
                            road: ri as u32,
                            section: k as u32,
                            lane,
                        });
                        g.successors.extend(next);
                        g.predecessors.extend(before);
                    }
                    g.successor_start.push(g.successors.len() as u32);
                    g.predecessor_start.push(g.predecessors.len() as u32);
                }
            }
            g.section_base.push(bases);
        }
        g
    }

    /// The slot of `h`, if `roads` (the network's) have its road, section and lane.
    #[inline]
    fn slot(&self, roads: &[Road], h: LaneHandle) -> Option<usize> {
        let base = *self
            .section_base
            .get(h.road as usize)?
            .get(h.section as usize)?;
        let section = roads
            .get(h.road as usize)?
            .lane_sections
            .get(h.section as usize)?;
        section.lane(h.lane)?;
        Some(base as usize + (h.lane + section.right.len() as i32) as usize)
    }

    /// Row `slot` of a compressed row table.
    #[inline]
    fn row<'a>(start: &[u32], items: &'a [LaneHandle], slot: usize) -> &'a [LaneHandle] {
        match (start.get(slot), start.get(slot + 1)) {
            (Some(&a), Some(&b)) => items.get(a as usize..b as usize).unwrap_or(&[]),
            _ => &[],
        }
    }

    /// The lanes that follow lane `h` (empty for a handle of no lane of `roads`).
    #[inline]
    pub(crate) fn successors(&self, roads: &[Road], h: LaneHandle) -> &[LaneHandle] {
        self.slot(roads, h).map_or(&[], |i| {
            Self::row(&self.successor_start, &self.successors, i)
        })
    }

    /// The lanes that lane `h` follows.
    #[inline]
    pub(crate) fn predecessors(&self, roads: &[Road], h: LaneHandle) -> &[LaneHandle] {
        self.slot(roads, h).map_or(&[], |i| {
            Self::row(&self.predecessor_start, &self.predecessors, i)
        })
    }
}

/// A road link with its target resolved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Link {
    /// To a road, entered at its start or end (`None`: contactPoint absent).
    Road(u32, Option<ContactPoint>),
    /// To a junction.
    Junction(u32),
}

/// One junction connection with its roads resolved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct ResolvedConnection {
    /// `incomingRoad` (`None` if it does not resolve; the loader refuses such files).
    pub(crate) incoming: Option<u32>,
    /// `connectingRoad` / `linkedRoad`.
    pub(crate) connecting: Option<u32>,
}

/// Every reference of the network as handles. Built once the references are known to resolve
/// (`parse::check_references`); a reference that does not resolve is `None`.
#[derive(Debug, Clone, Default)]
pub(crate) struct Topology {
    /// Per road: its (predecessor, successor) links.
    pub(crate) links: Vec<[Option<Link>; 2]>,
    /// Per road: the junction it belongs to.
    pub(crate) junction_of: Vec<Option<u32>>,
    /// Per junction: its connections, in file order (same indices as `Junction::connections`).
    pub(crate) connections: Vec<Vec<ResolvedConnection>>,
}

impl Topology {
    /// Resolves the links of `roads` and `junctions` with the id look-ups given.
    pub(crate) fn build(
        roads: &[Road],
        junctions: &[Junction],
        road: impl Fn(&str) -> Option<u32>,
        junction: impl Fn(&str) -> Option<u32>,
    ) -> Self {
        let link = |l: &Option<RoadLink>| {
            let l = l.as_ref()?;
            match l.element_type {
                ElementType::Road => Some(Link::Road(road(&l.element_id)?, l.contact_point)),
                ElementType::Junction => Some(Link::Junction(junction(&l.element_id)?)),
            }
        };
        Self {
            links: roads
                .iter()
                .map(|r| [link(&r.links.predecessor), link(&r.links.successor)])
                .collect(),
            junction_of: roads
                .iter()
                .map(|r| r.junction.as_deref().and_then(&junction))
                .collect(),
            connections: junctions
                .iter()
                .map(|j| {
                    j.connections
                        .iter()
                        .map(|c| ResolvedConnection {
                            incoming: road(&c.incoming_road),
                            connecting: road(&c.connecting_road),
                        })
                        .collect()
                })
                .collect(),
        }
    }
}
