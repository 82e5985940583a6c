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

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_6};

    /// Object axes in world coordinates for single rotations, from the conventions in the
    /// module doc: heading π/2 turns x to +y; pitch π/6 (nose down) turns x to
    /// (cos, 0, −sin); roll π/6 (right side down) lifts the left-pointing y axis to
    /// (0, cos, sin).
    #[test]
    fn single_rotations_follow_the_documented_conventions() {
        let x = Vector3::new(1.0, 0.0, 0.0);
        let y = Vector3::new(0.0, 1.0, 0.0);
        let (s, c) = FRAC_PI_6.sin_cos();
        let cases = [
            (
                Pose {
                    h: FRAC_PI_2,
                    ..Pose::default()
                },
                x,
                [0.0, 1.0, 0.0],
            ),
            (
                Pose {
                    p: FRAC_PI_6,
                    ..Pose::default()
                },
                x,
                [c, 0.0, -s],
            ),
            (
                Pose {
                    r: FRAC_PI_6,
                    ..Pose::default()
                },
                y,
                [0.0, c, s],
            ),
        ];
        for (pose, v, expected) in cases {
            let w = Frame::new(&pose).rotate(v);
            for (got, e) in [w.x, w.y, w.z].into_iter().zip(expected) {
                assert!((got - e).abs() < 1e-15, "{pose:?}: {w:?}");
            }
        }
    }

    /// `local_point` undoes `world_point` (the rotation is orthonormal) for a pose turned
    /// about all three axes.
    #[test]
    fn local_point_inverts_world_point() {
        let pose = Pose {
            x: 3.0,
            y: -4.0,
            z: 1.0,
            h: 2.0,
            p: -0.3,
            r: 0.7,
        };
        let f = Frame::new(&pose);
        let p = Vector3::new(1.5, -0.25, 0.75);
        let back = f.local_point(f.world_point(p));
        assert!((back.x - p.x).abs() < 1e-12 && (back.y - p.y).abs() < 1e-12);
        assert!((back.z - p.z).abs() < 1e-12, "{back:?}");
    }
}
