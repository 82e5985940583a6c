//! Positions (OpenSCENARIO 1.3 "Coordinate systems" and "Positions", XSD
//! `Position` and its ten choices). Distances in m, angles in rad.

use crate::model::routing::{Route, Trajectory};
use crate::model::ReferenceContext;
use crate::source::SourcePos;

/// An orientation (XSD `Orientation`): heading, pitch, roll in rad; absolute or relative
/// to the reference (default relative).
#[derive(Debug, Clone, PartialEq)]
pub struct Orientation {
    /// Heading, rad.
    pub h: f64,
    /// Pitch, rad.
    pub p: f64,
    /// Roll, rad.
    pub r: f64,
    /// `type`: absolute, or relative to the position's reference. Absent means relative.
    pub reference: Option<ReferenceContext>,
}

/// A position in one of the standard's ten forms (XSD `Position`), with where it was written.
#[derive(Debug, Clone, PartialEq)]
pub struct Position {
    /// The form and its values.
    pub kind: PositionKind,
    /// Where the position element starts.
    pub pos: SourcePos,
}

/// The forms of a position (XSD `Position` choice).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum PositionKind {
    /// `WorldPosition`: x, y, z in m; h, p, r in rad (absent ones are 0, z on the road).
    World {
        /// x, m.
        x: f64,
        /// y, m.
        y: f64,
        /// z, m (absent: on the road surface).
        z: Option<f64>,
        /// Heading, rad.
        h: Option<f64>,
        /// Pitch, rad.
        p: Option<f64>,
        /// Roll, rad.
        r: Option<f64>,
    },
    /// `RelativeWorldPosition`: offset from an entity in world axes, m.
    RelativeWorld {
        /// Reference entity.
        entity_ref: String,
        /// dx, m.
        dx: f64,
        /// dy, m.
        dy: f64,
        /// dz, m.
        dz: Option<f64>,
        /// Orientation.
        orientation: Option<Orientation>,
    },
    /// `RelativeObjectPosition`: offset from an entity in its own axes, m.
    RelativeObject {
        /// Reference entity.
        entity_ref: String,
        /// dx, m.
        dx: f64,
        /// dy, m.
        dy: f64,
        /// dz, m.
        dz: Option<f64>,
        /// Orientation.
        orientation: Option<Orientation>,
    },
    /// `RoadPosition`: s, t on a road's reference line, m.
    Road {
        /// OpenDRIVE road id.
        road_id: String,
        /// s, m.
        s: f64,
        /// t, m (left positive).
        t: f64,
        /// Orientation.
        orientation: Option<Orientation>,
    },
    /// `RelativeRoadPosition`: ds, dt from an entity in road coordinates, m.
    RelativeRoad {
        /// Reference entity.
        entity_ref: String,
        /// ds, m.
        ds: f64,
        /// dt, m.
        dt: f64,
        /// Orientation.
        orientation: Option<Orientation>,
    },
    /// `LanePosition`: s along the road, offset from the lane centre, m.
    Lane {
        /// OpenDRIVE road id.
        road_id: String,
        /// OpenDRIVE lane id (as written).
        lane_id: String,
        /// s, m.
        s: f64,
        /// Lateral offset from the lane centre, m.
        offset: Option<f64>,
        /// Orientation.
        orientation: Option<Orientation>,
    },
    /// `RelativeLanePosition`: dLane lanes and ds (or dsLane) m from an entity.
    RelativeLane {
        /// Reference entity.
        entity_ref: String,
        /// Lane difference.
        d_lane: i32,
        /// ds along the road's reference line, m.
        ds: Option<f64>,
        /// ds along the lane's centre line, m (1.1+).
        ds_lane: Option<f64>,
        /// Lateral offset from the lane centre, m.
        offset: Option<f64>,
        /// Orientation.
        orientation: Option<Orientation>,
    },
    /// `RoutePosition`: a place on a route.
    Route {
        /// The route (RouteRef: inline or from a catalog).
        route: Box<Route>,
        /// Orientation.
        orientation: Option<Orientation>,
        /// Where on the route.
        in_route: InRoutePosition,
    },
    /// `GeoPosition`: WGS84 latitude/longitude in degrees, altitude in m.
    Geo {
        /// Latitude, deg (the deprecated `latitude` in rad is converted).
        latitude_deg: f64,
        /// Longitude, deg.
        longitude_deg: f64,
        /// Altitude, m.
        altitude: Option<f64>,
        /// Vertical road selection (1.2+).
        vertical_road_selection: Option<i32>,
        /// Orientation.
        orientation: Option<Orientation>,
    },
    /// `TrajectoryPosition`: s (and t) along a trajectory, m (1.1+).
    Trajectory {
        /// The trajectory (TrajectoryRef: inline or from a catalog).
        trajectory: Box<Trajectory>,
        /// s, m.
        s: f64,
        /// t, m.
        t: Option<f64>,
        /// Orientation.
        orientation: Option<Orientation>,
    },
}

/// Where on a route a RoutePosition is (XSD `InRoutePosition`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum InRoutePosition {
    /// `FromCurrentEntity`: where the entity is.
    FromCurrentEntity {
        /// The entity.
        entity_ref: String,
    },
    /// `FromRoadCoordinates`: pathS and t, m.
    FromRoadCoordinates {
        /// s along the route, m.
        path_s: f64,
        /// t, m.
        t: f64,
    },
    /// `FromLaneCoordinates`: pathS, lane id, lane offset, m.
    FromLaneCoordinates {
        /// s along the route, m.
        path_s: f64,
        /// Lane id.
        lane_id: String,
        /// Offset from the lane centre, m.
        lane_offset: Option<f64>,
    },
}
