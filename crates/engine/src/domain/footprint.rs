//! The ground-plane outline of a bounding_box (OpenSCENARIO 2.0 §8.7.9): an oriented
//! rectangle, the shape that time_to_collision (§8.7.5.1.1) and space_gap (§8.7.5.1.3) work on.
//!
//! Pitch and roll are ignored for the outline: a box pitched by p has a footprint shorter by
//! the factor cos p (0.05 % at 2°), which oscsim accepts for road vehicles; the centre still
//! follows the full pose.

use opendrive::Real;

/// An oriented rectangle in the world x/y plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Footprint {
    /// Centre (x, y), m.
    pub(crate) center: [Real; 2],
    /// Unit vector of the object's x axis (cos h, sin h).
    pub(crate) axis_x: [Real; 2],
    /// Half the length along `axis_x`, m.
    pub(crate) half_length: Real,
    /// Half the width along the axis to the left of `axis_x`, m.
    pub(crate) half_width: Real,
}

impl Footprint {
    /// The rectangle with `center`, heading `h` (rad) and the given half extents.
    pub(crate) fn new(center: [Real; 2], h: Real, half_length: Real, half_width: Real) -> Self {
        let (s, c) = h.sin_cos();
        Self {
            center,
            axis_x: [c, s],
            half_length,
            half_width,
        }
    }

    /// Unit vector of the object's y axis (to the left).
    pub(crate) fn axis_y(&self) -> [Real; 2] {
        [-self.axis_x[1], self.axis_x[0]]
    }

    /// The interval `(min, max)` that the rectangle covers along the unit vector `n`.
    pub(crate) fn project(&self, n: [Real; 2]) -> (Real, Real) {
        let c = dot(self.center, n);
        let ay = self.axis_y();
        let r = self.half_length * dot(self.axis_x, n).abs() + self.half_width * dot(ay, n).abs();
        (c - r, c + r)
    }

    /// The four corners, counter-clockwise from rear right.
    pub(crate) fn corners(&self) -> [[Real; 2]; 4] {
        let [cx, cy] = self.center;
        let [ux, uy] = self.axis_x;
        let [vx, vy] = self.axis_y();
        let (l, w) = (self.half_length, self.half_width);
        [(-l, -w), (l, -w), (l, w), (-l, w)]
            .map(|(a, b)| [cx + a * ux + b * vx, cy + a * uy + b * vy])
    }
}

/// Dot product of two plane vectors.
pub(crate) fn dot(a: [Real; 2], b: [Real; 2]) -> Real {
    a[0] * b[0] + a[1] * b[1]
}
