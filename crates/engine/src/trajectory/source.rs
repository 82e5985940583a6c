//! Where a shape's points come from (OpenSCENARIO 1.3 §6.9: every Vertex, ControlPoint,
//! Clothoid and ClothoidSplineSegment start is a `Position`, any of the forms of §7.4): the
//! seam through which [`build`](super::build) has them resolved. The engine's position
//! resolver ([`position::resolve`](crate::position::resolve)) is the source for every
//! [`EntityQuery`](crate::position::EntityQuery), so this module never calls it: a
//! TrajectoryPosition is resolved by building its trajectory, whose points are positions.

use opendrive::Pose;
use scenario::Position;

use super::error::TrajectoryError;

/// A shape's `Position` resolved: the world pose of its point, and whether the Position
/// states that heading (an `Orientation` element, or `h` on a WorldPosition).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlacedPoint {
    /// World pose of the point (x, y, z in m; h, p, r in rad).
    pub pose: Pose,
    /// The Position states the heading (a six-dimensional Polyline needs it on every vertex).
    pub oriented: bool,
}

/// Resolves the Positions of a shape. Errors of the shape itself are [`TrajectoryError`]s;
/// the source's own `Error` holds them too, so that a point's error and a shape's error come
/// back as one type.
pub trait PointSource {
    /// The error of resolving a point, and of the build as a whole.
    type Error: From<TrajectoryError>;

    /// Where `position` is now.
    fn place(&self, position: &Position) -> Result<PlacedPoint, Self::Error>;
}
