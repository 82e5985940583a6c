//! Where an entity's bounding box is and how it moves, for `MovingObject.base`.
//!
//! OpenSCENARIO 1.3 places a vehicle by its reference point (rear axle centre on the
//! ground) and gives the bounding-box centre relative to it (`BoundingBox/Center`, in the
//! entity's frame); ASAM OSI 3.8 places an object by its bounding-box centre
//! (`BaseMoving.position`) with velocity and acceleration of that point, in the world
//! frame. Both use Tait-Bryan angles z-y'-x'' (yaw, pitch, roll), so the rotation from
//! the entity frame to the world is R = Rz(yaw) · Ry(pitch) · Rx(roll).
//!
//! For a point fixed in the body at world offset r from the reference point, rigid-body
//! kinematics give v = v_ref + ω × r and a = a_ref + α × r + ω × (ω × r).

use crate::osi3::{BaseMoving, Dimension3d, Orientation3d, Vector3d};

/// A 3D vector as `[x, y, z]`.
pub type Vec3 = [f64; 3];

/// State of an entity, as the engine knows it, in the world frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RigidBodyState {
    /// Reference point (OpenSCENARIO: rear axle centre on the ground), m.
    pub reference_point: Vec3,
    /// Yaw, pitch, roll (rad).
    pub orientation: Vec3,
    /// Time derivative of yaw, pitch, roll (rad/s).
    pub orientation_rate: Vec3,
    /// Angular acceleration in the world frame (rad/s²).
    pub angular_acceleration: Vec3,
    /// Velocity of the reference point (m/s).
    pub velocity: Vec3,
    /// Acceleration of the reference point (m/s²).
    pub acceleration: Vec3,
    /// Bounding-box centre relative to the reference point, entity frame (m).
    pub bbox_centre: Vec3,
    /// Bounding-box length, width, height (m).
    pub dimension: Vec3,
}

/// `v` turned from the entity frame into the world frame (R · v, see the module doc).
pub fn body_to_world(orientation: Vec3, v: Vec3) -> Vec3 {
    let [yaw, pitch, roll] = orientation;
    let (sy, cy) = yaw.sin_cos();
    let (sp, cp) = pitch.sin_cos();
    let (sr, cr) = roll.sin_cos();
    [
        cy * cp * v[0] + (cy * sp * sr - sy * cr) * v[1] + (cy * sp * cr + sy * sr) * v[2],
        sy * cp * v[0] + (sy * sp * sr + cy * cr) * v[1] + (sy * sp * cr - cy * sr) * v[2],
        -sp * v[0] + cp * sr * v[1] + cp * cr * v[2],
    ]
}

/// Angular velocity in the world frame from yaw, pitch, roll and their rates: yaw turns
/// about world z, pitch about the once-turned y axis, roll about the body x axis.
pub fn angular_velocity(orientation: Vec3, orientation_rate: Vec3) -> Vec3 {
    let [yaw, pitch, _] = orientation;
    let [yaw_rate, pitch_rate, roll_rate] = orientation_rate;
    let (sy, cy) = yaw.sin_cos();
    let (sp, cp) = pitch.sin_cos();
    [
        -sy * pitch_rate + cy * cp * roll_rate,
        cy * pitch_rate + sy * cp * roll_rate,
        yaw_rate - sp * roll_rate,
    ]
}

fn cross(a: Vec3, b: Vec3) -> Vec3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn add(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn vector3d(v: Vec3) -> Vector3d {
    Vector3d {
        x: Some(v[0]),
        y: Some(v[1]),
        z: Some(v[2]),
    }
}

fn orientation3d(o: Vec3) -> Orientation3d {
    Orientation3d {
        yaw: Some(o[0]),
        pitch: Some(o[1]),
        roll: Some(o[2]),
    }
}

impl RigidBodyState {
    /// World position of the bounding-box centre.
    pub fn bbox_centre_position(&self) -> Vec3 {
        add(
            self.reference_point,
            body_to_world(self.orientation, self.bbox_centre),
        )
    }

    /// World velocity of the bounding-box centre.
    pub fn bbox_centre_velocity(&self) -> Vec3 {
        let r = body_to_world(self.orientation, self.bbox_centre);
        let w = angular_velocity(self.orientation, self.orientation_rate);
        add(self.velocity, cross(w, r))
    }

    /// World acceleration of the bounding-box centre.
    pub fn bbox_centre_acceleration(&self) -> Vec3 {
        let r = body_to_world(self.orientation, self.bbox_centre);
        let w = angular_velocity(self.orientation, self.orientation_rate);
        add(
            add(self.acceleration, cross(self.angular_acceleration, r)),
            cross(w, cross(w, r)),
        )
    }

    /// `MovingObject.base`: position, velocity and acceleration of the bounding-box
    /// centre, orientation, orientation_rate and dimension.
    pub fn base_moving(&self) -> BaseMoving {
        BaseMoving {
            dimension: Some(Dimension3d {
                length: Some(self.dimension[0]),
                width: Some(self.dimension[1]),
                height: Some(self.dimension[2]),
            }),
            position: Some(vector3d(self.bbox_centre_position())),
            orientation: Some(orientation3d(self.orientation)),
            velocity: Some(vector3d(self.bbox_centre_velocity())),
            acceleration: Some(vector3d(self.bbox_centre_acceleration())),
            orientation_rate: Some(orientation3d(self.orientation_rate)),
            ..Default::default()
        }
    }

    /// `VehicleAttributes.bbcenter_to_rear`: from the bounding-box centre to the rear
    /// axle (the reference point), entity frame.
    pub fn bbcenter_to_rear(&self) -> Vector3d {
        vector3d([
            -self.bbox_centre[0],
            -self.bbox_centre[1],
            -self.bbox_centre[2],
        ])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use std::f64::consts::FRAC_PI_2;

    const TOL: f64 = 1e-12;

    fn car_heading_north() -> RigidBodyState {
        RigidBodyState {
            reference_point: [10.0, 20.0, 0.0],
            orientation: [FRAC_PI_2, 0.0, 0.0],
            orientation_rate: [0.5, 0.0, 0.0],
            velocity: [0.0, 10.0, 0.0],
            bbox_centre: [1.4, 0.0, 0.75],
            dimension: [4.5, 1.8, 1.5],
            ..Default::default()
        }
    }

    #[test]
    fn centre_is_ahead_of_the_rear_axle_along_the_heading() {
        // Heading +y (yaw 90°): the centre 1.4 m ahead and 0.75 m up is (10, 21.4, 0.75).
        let p = car_heading_north().bbox_centre_position();
        assert_relative_eq!(p[0], 10.0, epsilon = TOL);
        assert_relative_eq!(p[1], 21.4, epsilon = TOL);
        assert_relative_eq!(p[2], 0.75, epsilon = TOL);
    }

    #[test]
    fn centre_velocity_adds_the_turn() {
        // ω = (0, 0, 0.5), r = (0, 1.4, 0.75): ω × r = (0·0.75 − 0.5·1.4, 0.5·0 − 0·0.75, 0)
        // = (−0.7, 0, 0), so v = (−0.7, 10, 0).
        let v = car_heading_north().bbox_centre_velocity();
        assert_relative_eq!(v[0], -0.7, epsilon = TOL);
        assert_relative_eq!(v[1], 10.0, epsilon = TOL);
        assert_relative_eq!(v[2], 0.0, epsilon = TOL);
        // Centripetal: ω × (ω × r) = (0,0,0.5) × (−0.7, 0, 0) = (0, −0.35, 0).
        let a = car_heading_north().bbox_centre_acceleration();
        assert_relative_eq!(a[1], -0.35, epsilon = TOL);
    }

    #[test]
    fn pitch_and_roll_follow_z_y_x() {
        // Pitch +90° turns body x onto world −z (Ry: x → (cos p, 0, −sin p)).
        let x = body_to_world([0.0, FRAC_PI_2, 0.0], [1.0, 0.0, 0.0]);
        assert_relative_eq!(x[2], -1.0, epsilon = TOL);
        // Roll +90° turns body y onto world +z (Rx: y → (0, cos r, sin r)).
        let y = body_to_world([0.0, 0.0, FRAC_PI_2], [0.0, 1.0, 0.0]);
        assert_relative_eq!(y[2], 1.0, epsilon = TOL);
        // Rotations keep lengths: |R v| = |v| for v = (1, 2, 3) under arbitrary angles.
        let v = body_to_world([0.3, -0.2, 0.7], [1.0, 2.0, 3.0]);
        let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        assert_relative_eq!(len, 14f64.sqrt(), epsilon = TOL);
    }
}
