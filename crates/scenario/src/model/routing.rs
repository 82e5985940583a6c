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
    /// oscsim's smooth curve from the actor, a shape with no XML form (the DSL runtime writes
    /// it for ASAM OpenSCENARIO DSL 2.1 §8.8.2.11 `change_position(…, interpolation: smooth)`
    /// in a phase that starts at run time, where the plan does not know where the curve
    /// starts): the cubic Hermite curve ([`hermite_controls`]) from where the actor stands,
    /// facing its heading, when the action starts, to `end` facing `end`'s heading.
    SmoothFromActor(SmoothFromActor),
    /// oscsim's straight line from the actor, a shape with no XML form (the DSL runtime writes
    /// it for ASAM OpenSCENARIO DSL 2.1 §8.8.2.11 `change_position(…, interpolation:
    /// straight_line)` in a phase that starts at run time, where the plan does not know where
    /// the line starts, so no heading can be written for its vertices): from where the actor
    /// stands when the action starts to `end`'s point, facing along the line, and at the end
    /// facing `end`'s heading — the six-dimensional Polyline (§6.9) of the line's two ends at
    /// the line's heading and the end point again at `end`'s, which adds no length, as the
    /// plan writes at a known start. A Polyline from a RelativeObjectPosition at the actor
    /// would keep the line's heading after it.
    LineFromActor(LineFromActor),
}

/// What oscsim's straight line from the actor ([`Shape::LineFromActor`]) ends at.
#[derive(Debug, Clone, PartialEq)]
pub struct LineFromActor {
    /// Where the line ends, and the heading the actor faces there (a position without an
    /// orientation of its own faces the way its kind gives, e.g. along a lane).
    pub end: Position,
}

/// What oscsim's smooth curve from the actor ([`Shape::SmoothFromActor`]) ends at.
#[derive(Debug, Clone, PartialEq)]
pub struct SmoothFromActor {
    /// Where the curve ends; its heading is the curve's there (a position without an
    /// orientation of its own faces the way its kind gives, e.g. along a lane).
    pub end: Position,
}

/// The four control points of the cubic Bézier of the Hermite curve from pose `from` to pose
/// `to` (world x, y in m, heading in rad): `from`, `from` + L/3·(cos h₀, sin h₀), `to` −
/// L/3·(cos h₁, sin h₁), `to`, with L the chord |to − from| (tangents of length L, so a curve
/// between two poses of the same heading on one line is that line). The DSL runtime's smooth
/// paths and the engine's [`Shape::SmoothFromActor`] are built with it.
pub fn hermite_controls(from: (f64, f64, f64), to: (f64, f64, f64)) -> [[f64; 2]; 4] {
    let ((x0, y0, h0), (x1, y1, h1)) = (from, to);
    let k = (x1 - x0).hypot(y1 - y0) / 3.0;
    [
        [x0, y0],
        [x0 + k * h0.cos(), y0 + k * h0.sin()],
        [x1 - k * h1.cos(), y1 - k * h1.sin()],
        [x1, y1],
    ]
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
