//! A point of a trajectory (OpenSCENARIO 1.3 §6.9): where the trajectory is at arc length s.
//! Coordinates are the world frame of OpenSCENARIO 1.3 §6.3.1 (the OpenDRIVE inertial frame).

use opendrive::Real;

/// Position, heading and curvature of a trajectory at one arc length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrajectoryPoint {
    /// Arc length from the trajectory's start (m), measured horizontally.
    pub s: Real,
    /// x (m), world frame.
    pub x: Real,
    /// y (m), world frame.
    pub y: Real,
    /// z (m), world frame.
    pub z: Real,
    /// Heading of the tangent (rad), counter-clockwise from +x, in (−π, π].
    pub heading: Real,
    /// Signed horizontal curvature (1/m), positive turning left.
    pub curvature: Real,
}
