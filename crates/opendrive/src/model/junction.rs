//! `<junction>` with connections and lane links (OpenDRIVE 1.8 §12, junctions: common and
//! direct junctions).

/// Where a connecting or linked road is entered: its start (s = 0) or its end (s = length).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactPoint {
    /// s = 0.
    Start,
    /// s = length.
    End,
}

/// `junction/@type`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JunctionKind {
    /// `default`: connecting roads inside the junction.
    Default,
    /// `direct`: incoming roads linked directly, without connecting roads.
    Direct,
    /// `virtual` or `crossing`: kept, routed like a default junction.
    Other,
}

/// `<laneLink from to>`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LaneLink {
    /// Lane id on the incoming road.
    pub from: i32,
    /// Lane id on the connecting (or linked) road.
    pub to: i32,
}

/// `<connection>`.
#[derive(Debug, Clone, PartialEq)]
pub struct Connection {
    /// `id`.
    pub id: String,
    /// `incomingRoad`.
    pub incoming_road: String,
    /// `connectingRoad` (default junctions) or `linkedRoad` (direct junctions).
    pub connecting_road: String,
    /// `contactPoint` on the connecting/linked road.
    pub contact_point: ContactPoint,
    /// The lane links.
    pub lane_links: Vec<LaneLink>,
}

/// `<junction>`.
#[derive(Debug, Clone, PartialEq)]
pub struct Junction {
    /// `id`.
    pub id: String,
    /// `name`.
    pub name: String,
    /// `type` (default when absent).
    pub kind: JunctionKind,
    /// The connections.
    pub connections: Vec<Connection>,
}
