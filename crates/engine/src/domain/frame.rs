//! The object coordinate system of OpenSCENARIO 2.0 §8.7.2 (x forward, y left, z up, origin at
//! the reference point) placed in the world by a pose_3d, and its inverse.
//!
//! The rotation is the one `opendrive` documents for `Pose` (OpenDRIVE 1.8 §8, ISO 8855): heading
//! about z, then pitch about the rotated y (positive nose down), then roll about the rotated
//! x (positive right side down), i.e. `R = Rz(h) · Ry(p) · Rx(r)`.

use opendrive::{Pose, Real};

use super::Vector3;

/// A pose_3d (§8.7.2 `pose`) as an origin and a rotation matrix, computed once so that many points can be
/// moved between the object and the world frame without repeated trigonometry.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Frame {
    origin: Vector3,
    /// Rows of R: `m[i][j]` is world component i of object axis j.
    m: [[Real; 3]; 3],
}

impl Frame {
    /// The object frame placed at `pose`.
    pub(crate) fn new(pose: &Pose) -> Self {
        let (sh, ch) = pose.h.sin_cos();
        let (sp, cp) = pose.p.sin_cos();
        let (sr, cr) = pose.r.sin_cos();
        let m = [
            [ch * cp, ch * sp * sr - sh * cr, ch * sp * cr + sh * sr],
            [sh * cp, sh * sp * sr + ch * cr, sh * sp * cr - ch * sr],
            [-sp, cp * sr, cp * cr],
        ];
        Self {
            origin: Vector3::new(pose.x, pose.y, pose.z),
            m,
        }
    }

    /// A vector given in object axes, expressed in world axes (`R · v`).
    pub(crate) fn rotate(&self, v: Vector3) -> Vector3 {
        let m = &self.m;
        Vector3::new(
            m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z,
        )
    }

    /// A point given in object coordinates, in world coordinates (`o + R · p`).
    pub(crate) fn world_point(&self, p: Vector3) -> Vector3 {
        let r = self.rotate(p);
        Vector3::new(
            self.origin.x + r.x,
            self.origin.y + r.y,
            self.origin.z + r.z,
        )
    }

    /// A world point in object coordinates (`Rᵀ · (w − o)`).
    pub(crate) fn local_point(&self, w: Vector3) -> Vector3 {
        let d = Vector3::new(
            w.x - self.origin.x,
            w.y - self.origin.y,
            w.z - self.origin.z,
        );
        let m = &self.m;
        Vector3::new(
            m[0][0] * d.x + m[1][0] * d.y + m[2][0] * d.z,
            m[0][1] * d.x + m[1][1] * d.y + m[2][1] * d.z,
            m[0][2] * d.x + m[1][2] * d.y + m[2][2] * d.z,
        )
    }
}
