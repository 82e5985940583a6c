//! Dense integer handles for roads and junctions, and the road network's links resolved to
//! them at load (OpenDRIVE 1.8 §10.4 road linkage, §12 junction connections). String ids are
//! read from and written to files only; queries walk the resolved links.

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
