//! OpenSCENARIO 2.0 §8.7.2.1.1 method object_distance(): the position of the reference
//! entity measured in the coordinate system of the calling physical_object, along its x
//! (longitudinal) or y (lateral) axis.
//!
//! * `reference_points`: the reference's reference point (pose position) in the caller's
//!   frame, component x or y. Positive when the reference is in front of / left of the
//!   caller (§8.7.14).
//! * `bounding_boxes`: the gap between the two boxes' intervals on that axis of the caller's
//!   frame. The caller's box is axis-aligned in its own frame, so its interval is exact; the
//!   reference's interval is the extreme of its eight corners. Positive when the reference's
//!   box lies wholly in front of / left of the caller's, negative when wholly behind / right
//!   of it, and 0 when the two intervals overlap, the freespace rule of OpenSCENARIO 1.3
//!   §6.4.3 (overlapping boxes are at distance 0).
//!
//! Full 3D: pitch and roll of both objects enter through their poses.

use opendrive::Real;

use super::frame::Frame;
use super::{DistanceDirection, DistanceMode, Physical, PhysicalObject, Vector3};

impl PhysicalObject {
    /// §8.7.2.1.1 `object_distance(reference, direction, mode)`: the distance of `reference`
    /// from this object along this object's x (`Longitudinal`) or y (`Lateral`) axis, m; see
    /// the module doc for the sign and the box rule.
    pub fn object_distance(
        &self,
        reference: &impl Physical,
        direction: DistanceDirection,
        mode: DistanceMode,
    ) -> Real {
        let reference = reference.physical_object();
        let frame = Frame::new(&self.pose);
        let axis = match direction {
            DistanceDirection::Longitudinal => 0,
            DistanceDirection::Lateral => 1,
        };
        let component = |v: Vector3| if axis == 0 { v.x } else { v.y };
        match mode {
            DistanceMode::ReferencePoints => {
                let p = &reference.pose;
                component(frame.local_point(Vector3::new(p.x, p.y, p.z)))
            }
            DistanceMode::BoundingBoxes => {
                let (own_min, own_max) = self.bounding_box.extent(axis);
                let reference_frame = Frame::new(&reference.pose);
                let (mut lo, mut hi) = (Real::INFINITY, Real::NEG_INFINITY);
                for corner in reference.bounding_box.corners() {
                    let c = component(frame.local_point(reference_frame.world_point(corner)));
                    lo = lo.min(c);
                    hi = hi.max(c);
                }
                interval_gap((own_min, own_max), (lo, hi))
            }
        }
    }
}

/// Signed gap from interval `own` to interval `other` on one axis: positive when `other`
/// lies wholly above `own`, negative when wholly below, 0 when they overlap or touch.
pub(crate) fn interval_gap(own: (Real, Real), other: (Real, Real)) -> Real {
    if other.0 > own.1 {
        other.0 - own.1
    } else if other.1 < own.0 {
        other.1 - own.0
    } else {
        0.0
    }
}
