//! OpenSCENARIO 2.0 §8.7.9 struct bounding_box: a box given by its centre in object
//! coordinates and its length (x), width (y) and height (z), axis-aligned in the object frame.
//!
//! The seed: the box does not include side mirrors, and its height includes the ground
//! clearance, so it always reaches down to the ground.

use opendrive::{Pose, Real};

use super::footprint::Footprint;
use super::frame::Frame;
use super::{DomainError, Position3d, Vector3};

/// §8.7.9 bounding_box: simplified three-dimensional shape enclosing a physical_object.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundingBox {
    center: Position3d,
    length: Real,
    width: Real,
    height: Real,
}

impl BoundingBox {
    /// A box with geometrical `center` in object coordinates and the dimensions along the
    /// object's x (`length`), y (`width`) and z (`height`), all in m.
    ///
    /// Errors with `InvalidParameter` when a dimension is negative or not finite, or a
    /// centre coordinate is not finite.
    pub fn new(
        center: Position3d,
        length: Real,
        width: Real,
        height: Real,
    ) -> Result<Self, DomainError> {
        for (name, v) in [
            ("bounding_box.length", length),
            ("bounding_box.width", width),
            ("bounding_box.height", height),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(DomainError::parameter(name, "a finite length >= 0 m", v));
            }
        }
        for (name, v) in [
            ("bounding_box.center.x", center.x),
            ("bounding_box.center.y", center.y),
            ("bounding_box.center.z", center.z),
        ] {
            if !v.is_finite() {
                return Err(DomainError::parameter(name, "a finite coordinate", v));
            }
        }
        Ok(Self {
            center,
            length,
            width,
            height,
        })
    }

    /// Geometrical centre in object coordinates (§8.7.9 `center`), m.
    pub fn center(&self) -> Position3d {
        self.center
    }

    /// Dimension along the object's x axis (§8.7.9 `length`), m.
    pub fn length(&self) -> Real {
        self.length
    }

    /// Dimension along the object's y axis (§8.7.9 `width`), m.
    pub fn width(&self) -> Real {
        self.width
    }

    /// Dimension along the object's z axis (§8.7.9 `height`), m.
    pub fn height(&self) -> Real {
        self.height
    }

    /// Lower and upper bound of the box along object axis `axis` (0 = x, 1 = y, 2 = z).
    pub(crate) fn extent(&self, axis: usize) -> (Real, Real) {
        let (c, d) = match axis {
            0 => (self.center.x, self.length),
            1 => (self.center.y, self.width),
            _ => (self.center.z, self.height),
        };
        (c - 0.5 * d, c + 0.5 * d)
    }

    /// The eight corners in object coordinates.
    pub(crate) fn corners(&self) -> [Vector3; 8] {
        let (x0, x1) = self.extent(0);
        let (y0, y1) = self.extent(1);
        let (z0, z1) = self.extent(2);
        let mut out = [Vector3::ZERO; 8];
        for (i, c) in out.iter_mut().enumerate() {
            *c = Vector3::new(
                if i & 1 == 0 { x0 } else { x1 },
                if i & 2 == 0 { y0 } else { y1 },
                if i & 4 == 0 { z0 } else { z1 },
            );
        }
        out
    }

    /// The box's footprint on the ground plane when its object is at `pose`: the centre
    /// moves with the full pose, the rectangle turns with the heading only (pitch and roll
    /// are ignored for the outline, see `Footprint`).
    pub(crate) fn footprint(&self, pose: &Pose) -> Footprint {
        self.placed(&Frame::new(pose), pose.h).0
    }

    /// The footprint and the world z range `(bottom, top)` of the box when its object's frame
    /// is `frame` with heading `h` (pitch and roll ignored for both, as in `footprint`).
    pub(crate) fn placed(&self, frame: &Frame, h: Real) -> (Footprint, (Real, Real)) {
        let c = frame.world_point(self.center);
        let footprint = Footprint::new([c.x, c.y], h, 0.5 * self.length, 0.5 * self.width);
        (
            footprint,
            (c.z - 0.5 * self.height, c.z + 0.5 * self.height),
        )
    }
}
