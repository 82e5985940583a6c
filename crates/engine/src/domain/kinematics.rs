//! The basic physical types the §8.7 actors use: position_3d, velocity_6d and
//! acceleration_6d (OpenSCENARIO 2.0 §7, physical types; used by §8.7.2, §8.7.4, §8.7.9).
//!
//! The pose (pose_3d) is `opendrive::Pose`, so the runtime, the road model and the
//! domain share one pose type; that module has no vector type, so the three-component vector
//! these structs are made of is defined here.

use opendrive::Real;

/// A vector of three `f64` components along x, y, z of some frame (m, m/s, rad/s, … as its
/// use says): OpenSCENARIO 2.0 position_3d (§8.7.2, §8.7.9) and the halves of velocity_6d
/// and acceleration_6d (§8.7.4).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Vector3 {
    /// x component.
    pub x: Real,
    /// y component.
    pub y: Real,
    /// z component.
    pub z: Real,
}

/// OpenSCENARIO 2.0 position_3d (used for bounding_box.center and center_of_gravity, §8.7.2,
/// §8.7.9): a point in the coordinates of the physical_object, m.
pub type Position3d = Vector3;

impl Vector3 {
    /// The zero vector.
    pub const ZERO: Vector3 = Vector3 {
        x: 0.0,
        y: 0.0,
        z: 0.0,
    };

    /// The vector (`x`, `y`, `z`).
    pub const fn new(x: Real, y: Real, z: Real) -> Self {
        Self { x, y, z }
    }
}

/// OpenSCENARIO 2.0 velocity_6d (§8.7.4 movable_object.velocity): translational (m/s) and
/// rotational (rad/s) velocity measured in object coordinates with the world as reference.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Velocity6d {
    /// Translational velocity along the object's x (forward), y (left), z (up), m/s.
    pub translational: Vector3,
    /// Rotational velocity about the object's x (roll rate), y (pitch rate), z (yaw rate),
    /// rad/s.
    pub rotational: Vector3,
}

impl Velocity6d {
    /// At rest.
    pub const ZERO: Velocity6d = Velocity6d {
        translational: Vector3::ZERO,
        rotational: Vector3::ZERO,
    };
}

/// OpenSCENARIO 2.0 acceleration_6d (§8.7.4 movable_object.acceleration): translational
/// (m/s²) and rotational (rad/s²) acceleration in object coordinates, world as reference.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Acceleration6d {
    /// Translational acceleration along the object's x, y, z, m/s².
    pub translational: Vector3,
    /// Rotational acceleration about the object's x, y, z, rad/s².
    pub rotational: Vector3,
}

impl Acceleration6d {
    /// No acceleration.
    pub const ZERO: Acceleration6d = Acceleration6d {
        translational: Vector3::ZERO,
        rotational: Vector3::ZERO,
    };
}
