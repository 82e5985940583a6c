//! Routes and trajectories (OpenSCENARIO 1.3 "Routes" and "Trajectories", XSD
//! `Route`, `Waypoint`, `Trajectory`, `Shape`, `Polyline`, `Clothoid`, `ClothoidSpline`,
//! `Nurbs`). Lengths in m, times in s, curvature in 1/m.

use crate::model::{CatalogOrigin, Position, RouteStrategy};

/// A route (XSD `Route`): waypoints joined by the road network.
#[derive(Debug, Clone, PartialEq)]
pub struct Route {
    /// `name`.
    pub name: String,
    /// `closed`: the last waypoint leads back to the first.
    pub closed: bool,
    /// Waypoints, at least two in a valid route.
    pub waypoints: Vec<Waypoint>,
    /// Set when the route came from a catalog.
    pub catalog: Option<CatalogOrigin>,
}

/// A route point (XSD `Waypoint`).
#[derive(Debug, Clone, PartialEq)]
pub struct Waypoint {
    /// How to reach this waypoint from the previous one.
    pub route_strategy: RouteStrategy,
    /// The point.
    pub position: Position,
}

/// A trajectory (XSD `Trajectory`).
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    /// `name`.
    pub name: String,
    /// `closed`.
    pub closed: bool,
    /// The geometry.
    pub shape: Shape,
    /// Set when the trajectory came from a catalog.
    pub catalog: Option<CatalogOrigin>,
}

/// The geometry of a trajectory (XSD `Shape`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Shape {
    /// `Polyline`: vertices joined by straight segments.
    Polyline(Vec<Vertex>),
    /// `Clothoid` (deprecated since 1.3 in favour of ClothoidSpline).
    Clothoid(Clothoid),
    /// `ClothoidSpline` (1.3).
    ClothoidSpline(ClothoidSpline),
    /// `Nurbs`.
    Nurbs(Nurbs),
}

/// A polyline vertex (XSD `Vertex`).
#[derive(Debug, Clone, PartialEq)]
pub struct Vertex {
    /// Time at this vertex, s.
    pub time: Option<f64>,
    /// The point.
    pub position: Position,
}

/// A clothoid (XSD `Clothoid`).
#[derive(Debug, Clone, PartialEq)]
pub struct Clothoid {
    /// Start curvature, 1/m.
    pub curvature: f64,
    /// Curvature change per length, 1/m² (`curvaturePrime`, or the deprecated `curvatureDot`).
    pub curvature_prime: f64,
    /// Length, m.
    pub length: f64,
    /// Start time, s.
    pub start_time: Option<f64>,
    /// Stop time, s.
    pub stop_time: Option<f64>,
    /// Start point.
    pub position: Position,
}

/// A clothoid spline (XSD `ClothoidSpline`, 1.3).
#[derive(Debug, Clone, PartialEq)]
pub struct ClothoidSpline {
    /// Time at the end, s.
    pub time_end: Option<f64>,
    /// Segments.
    pub segments: Vec<ClothoidSplineSegment>,
}

/// A clothoid spline segment (XSD `ClothoidSplineSegment`).
#[derive(Debug, Clone, PartialEq)]
pub struct ClothoidSplineSegment {
    /// Start curvature, 1/m.
    pub curvature_start: f64,
    /// End curvature, 1/m.
    pub curvature_end: f64,
    /// Length, m.
    pub length: f64,
    /// Heading offset, rad.
    pub h_offset: Option<f64>,
    /// Start time, s.
    pub time_start: Option<f64>,
    /// Start point (first segment only, or to break continuity).
    pub position_start: Option<Position>,
}

/// A NURBS curve (XSD `Nurbs`).
#[derive(Debug, Clone, PartialEq)]
pub struct Nurbs {
    /// Order (degree + 1).
    pub order: u32,
    /// Control points.
    pub control_points: Vec<ControlPoint>,
    /// Knot vector (XSD `Knot@value`).
    pub knots: Vec<f64>,
}

/// A NURBS control point (XSD `ControlPoint`).
#[derive(Debug, Clone, PartialEq)]
pub struct ControlPoint {
    /// Time, s.
    pub time: Option<f64>,
    /// Weight.
    pub weight: Option<f64>,
    /// The point.
    pub position: Position,
}
