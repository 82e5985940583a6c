//! ASAM OpenDRIVE 1.4–1.8 road model for oscsim.
//!
//! Parses `.xodr` files (on `roxmltree`) into typed data and evaluates the road geometry
//! exactly: f64 throughout, analytic reference-line geometry (line, arc, clothoid spiral,
//! poly3, paramPoly3), no pre-sampled polylines.
//!
//! # Overview
//! - [`RoadNetwork`]: [`from_file`](RoadNetwork::from_file) / [`from_str`](RoadNetwork::from_str),
//!   then [`roads`](RoadNetwork::roads), [`road`](RoadNetwork::road),
//!   [`junctions`](RoadNetwork::junctions), [`junction`](RoadNetwork::junction),
//!   [`header`](RoadNetwork::header).
//! - Positions: [`RoadNetwork::road_pose`] (road, s, t) → [`Pose`];
//!   [`RoadNetwork::lane_pose`] (road, lane, s, offset from the lane centre) → [`Pose`];
//!   [`RoadNetwork::lane_width`], [`RoadNetwork::lane_boundaries`] ([`LaneSpan`]). The same
//!   on a [`Road`] directly: [`Road::pose`], [`Road::lane_pose`], [`Road::lane_span`].
//!   No allocation per call; geometry and lane section at s by binary search.
//! - World → road: [`RoadNetwork::locate`] (a grid and an R*-tree over road pieces, then
//!   exact Newton projection) and [`RoadNetwork::locate_on_road`], both giving a
//!   [`RoadPosition`].
//! - Lane graph: [`RoadNetwork::lane_handle`], [`RoadNetwork::successors`],
//!   [`RoadNetwork::predecessors`], [`RoadNetwork::driving_direction`], [`is_drivable`];
//!   routes: [`RoadNetwork::route`] from one [`LanePosition`] to another → [`LaneRoute`];
//!   [`RoadNetwork::route_by`] under a caller's [`LaneCost`] → [`LanePath`].
//! - Georeferencing (§8.5): [`GeoTransform`] between local x/y and WGS 84 latitude/longitude
//!   through the header's `<geoReference>` and `<offset>`.
//! - Errors: [`Error`] with [`ErrorKind`] and a [`SourcePos`] (file, 1-based line:col; the
//!   workspace's one position type, from `oscsim-source`).
//! - Data: [`Road`] (`id`, `length`, `junction`, `rule`, `links`, `types`, `plan_view`,
//!   `elevation`, `superelevation`, `lane_offsets`, `lane_sections`, `objects`, `signals`),
//!   [`LaneSection`] (`left` 1, 2, …; `center`; `right` −1, −2, …), [`Lane`] (with its
//!   [`RoadMark`]s), [`Junction`], [`Controller`] ([`RoadNetwork::controllers`]),
//!   [`Header`]; [`RoadNetwork::bounding_box`] of all road surfaces.
//!
//! Semantics worth knowing: a lane pose's heading is the true (horizontal) tangent of the
//! offset curve, road heading + atan2(dt/ds, 1 − κt) on unbanked roads; `paramPoly3` maps s
//! to p linearly (§9.6); lane `<height>` records hold until the next (§11.6); at a
//! lane-section start the new section applies; s up to [`S_TOLERANCE`] beyond a road's ends
//! is clamped; problems tolerated on load (plan-view gaps, lane links to missing lanes) are
//! in [`RoadNetwork::warnings`].
//!
//! Conventions (OpenDRIVE 1.8 §8): s along the reference line, t positive to the left, lane
//! ids positive left; heading counter-clockwise from +x; pitch positive nose down; roll
//! positive right side down; angles in radians, lengths in metres.
//!
//! ```no_run
//! use opendrive::RoadNetwork;
//! let net = RoadNetwork::from_file(std::path::Path::new("examples/roads/highway.xodr"))?;
//! let pose = net.lane_pose("1", -1, 10.0, 0.0)?;
//! let back = net.locate(pose.x, pose.y, Some(pose.h));
//! # Ok::<(), opendrive::Error>(())
//! ```
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod error;
mod geo;
mod geometry;
mod handles;
mod math;
mod model;
mod network;
mod parse;
mod query;
mod road;

pub use error::{Error, ErrorKind};
pub use geo::{GeoError, GeoTransform};
pub use geometry::{
    Arc, Geometry, GeometryKind, LocalPoint, ParamPoly3, ParamRange, PlanView, Poly3, RefPoint,
    Spiral,
};
pub use handles::{JunctionHandle, RoadHandle};
pub use math::{
    angle_difference, normalize_angle, Cubic, Pose, Real, GEOMETRY_GAP_TOLERANCE, LENGTH_EPSILON,
    SOLVER_TOLERANCE, S_TOLERANCE,
};
pub use model::{
    is_drivable, Connection, ContactPoint, Controller, Corner, ElementType, GeoReference, Header,
    Junction, JunctionKind, Lane, LaneHeight, LaneLink, LaneSection, LaneType, MarkStretch, Object,
    Offset, Road, RoadLink, RoadLinks, RoadMark, RoadMarkColor, RoadMarkLaneChange, RoadMarkLine,
    RoadMarkType, RoadType, SectionStretch, Signal, Speed, TrafficRule,
};
pub use network::RoadNetwork;
pub use query::{
    Direction, LaneChange, LaneCost, LaneHandle, LanePath, LanePosition, LaneRoute, PathCost,
    RoadPoint, RoadPosition, RouteSegment, LANE_CHANGE_COST,
};
pub use road::{FrameStretch, LaneSpan, CONSTANT_MARGIN};
pub use source::SourcePos;
