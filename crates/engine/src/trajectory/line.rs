//! One straight piece of a `Polyline` (OpenSCENARIO 1.3 §6.9, XSD `Polyline`: straight
//! lines joining the vertices in order): from one vertex to the next, z interpolated linearly,
//! s measured horizontally.

use opendrive::Real;

use super::TrajectoryPoint;

/// A straight piece from `(x0, y0, z0)` to `(x1, y1, z1)`, of positive horizontal length.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Line {
    start: [Real; 3],
    end: [Real; 3],
    length: Real,
    heading: Real,
}

impl Line {
    /// The piece between two points; `None` when they coincide horizontally.
    pub(crate) fn new(start: [Real; 3], end: [Real; 3]) -> Option<Self> {
        let (dx, dy) = (end[0] - start[0], end[1] - start[1]);
        let length = dx.hypot(dy);
        (length > opendrive::LENGTH_EPSILON).then(|| Self {
            start,
            end,
            length,
            heading: dy.atan2(dx),
        })
    }

    /// Horizontal length (m).
    pub(crate) fn length(&self) -> Real {
        self.length
    }

    /// The point `ds` metres from the start (0 ≤ ds ≤ length).
    pub(crate) fn eval(&self, ds: Real) -> TrajectoryPoint {
        let u = ds / self.length;
        let lerp = |i: usize| self.start[i] + u * (self.end[i] - self.start[i]);
        TrajectoryPoint {
            s: ds,
            x: lerp(0),
            y: lerp(1),
            z: lerp(2),
            heading: self.heading,
            curvature: 0.0,
        }
    }
}
