//! Steering along a trajectory in TrajectoryFollowingMode `follow` (OpenSCENARIO 1.3 XSD
//! `FollowingMode`: "follow: Follow the lateral and/or longitudinal target value as good as
//! possible by observing the dynamic constraints of the entity") for a vehicle whose axles
//! bound its curvature.
//!
//! Dynamic constraint: a vehicle with front axle steering angle δ ≤ maxSteering and wheelbase
//! b (XSD `Axles`: FrontAxle/@positionX − RearAxle/@positionX) drives, about its rear axle (its
//! reference point), curvatures |κ| ≤ tan(maxSteering)/b (the kinematic bicycle model,
//! Rajamani, "Vehicle Dynamics and Control", 2nd ed., §2.2): the minimum turning radius is
//! R = b/tan(maxSteering).
//!
//! Controller: pure pursuit (R. C. Coulter, "Implementation of the Pure Pursuit Path Tracking
//! Algorithm", CMU-RI-TR-92-01, 1992). The goal G is the trajectory point a look-ahead L
//! beyond the point nearest to the vehicle; the arc through the vehicle, tangent to its
//! heading, through G has curvature κ = 2·sin α / ℓ (α the bearing of G from the heading, ℓ
//! the distance to G), clamped to ±1/R, and the vehicle drives that arc for the step's
//! distance. On a circle of radius ≥ R the arc to a goal on the circle is the circle itself,
//! so such a trajectory is followed exactly. L = R: from a lateral offset e of a straight
//! trajectory the pursuit arc is 2e/(L² + e²) ≤ 1/L = 1/R for every e, so the command never
//! needs more than the steering limit to return to the trajectory.

use opendrive::{normalize_angle, Real};
use scenario::Axles;

use super::Trajectory;
use crate::models::single_track::arc_step;

/// Pure pursuit of one vehicle along an open trajectory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pursuit {
    max_curvature: Real,
}

impl Pursuit {
    /// The pursuit of a vehicle that drives curvatures up to `max_curvature` (1/m, finite and
    /// > 0, else `None`).
    pub fn new(max_curvature: Real) -> Option<Self> {
        (max_curvature.is_finite() && max_curvature > 0.0).then_some(Self { max_curvature })
    }

    /// The look-ahead L (m): the minimum turning radius 1/κ_max (see the module doc).
    pub fn look_ahead(&self) -> Real {
        1.0 / self.max_curvature
    }

    /// From `pose` ([x, y, h]) with progress `s` (the arc length of the trajectory point
    /// nearest to it), drives `distance` m on the pursuit arc: the new pose and progress
    /// (never less than `s`).
    pub fn advance(
        &self,
        trajectory: &Trajectory,
        pose: [Real; 3],
        s: Real,
        distance: Real,
    ) -> ([Real; 3], Real) {
        let look = self.look_ahead();
        let goal = trajectory.eval((s + look).min(trajectory.length()));
        let k = pursuit_curvature(pose, [goal.x, goal.y], self.max_curvature);
        let next = drive_arc(pose, k, distance);
        let near = trajectory.closest_near(next[0], next[1], s + distance, distance + look);
        (next, near.point.s.max(s))
    }
}

/// The largest curvature (1/m) the reference point of a vehicle with `axles` can drive
/// (rigid body, wheels rolling without slip: every wheel's axis points at the instantaneous
/// centre of rotation, which lies on the line across the vehicle through its non-steering
/// axles).
///
/// * The RearAxle is taken as non-steering: OpenSCENARIO puts the reference point at its
///   centre and every other element (positions, trajectories) moves that point. (Catalogs,
///   esmini's among them, often give it the front's maxSteering; read literally that would
///   make every such car a four-wheel-steering one.) AdditionalAxle entries with
///   maxSteering 0 are non-steering too; several non-steering axles (a tandem) put the
///   centre's line at their mean position x_c, the usual approximation (their tyres scrub).
/// * Each steering axle (the FrontAxle, AdditionalAxle entries with maxSteering in
///   (0, π/2)) at x_i bounds the curvature on the centre's line to tan(δ_i) / |x_i − x_c|;
///   the tightest bound holds.
/// * The reference point (x = 0) runs on a circle of radius √(R² + x_c²), R the radius on the
///   centre's line: κ = κ_c / √(1 + (x_c·κ_c)²). Two axles with the rear one at 0 give
///   tan(δ_front) / wheelbase.
///
/// `None` when no axle steers within (0, π/2) or a steering axle lies on the centre's line
/// (no usable constraint).
pub fn max_curvature(axles: &Axles) -> Option<Real> {
    let steers = |a: &scenario::Axle| {
        let d = a.max_steering.abs();
        d.is_finite() && d > 0.0 && d < std::f64::consts::FRAC_PI_2
    };
    let mut fixed = vec![axles.rear_axle.position_x];
    fixed.extend(
        axles
            .additional_axles
            .iter()
            .filter(|a| a.max_steering == 0.0)
            .map(|a| a.position_x),
    );
    let x_c = fixed.iter().sum::<Real>() / fixed.len() as Real;
    let steering = axles
        .front_axle
        .iter()
        .chain(axles.additional_axles.iter())
        .filter(|a| steers(a));
    let mut kappa: Option<Real> = None;
    for a in steering {
        let arm = (a.position_x - x_c).abs();
        if !(arm.is_finite() && arm > 0.0) {
            return None;
        }
        let k = a.max_steering.abs().tan() / arm;
        kappa = Some(kappa.map_or(k, |old: Real| old.min(k)));
    }
    let kappa = kappa?;
    Some(if x_c == 0.0 {
        kappa
    } else {
        kappa / (1.0 + (x_c * kappa).powi(2)).sqrt()
    })
}

/// The pure-pursuit curvature (1/m) from (x, y) heading `h` to the goal (gx, gy), clamped to
/// ±`max_curvature`; 0 when the goal coincides with the vehicle.
pub fn pursuit_curvature([x, y, h]: [Real; 3], [gx, gy]: [Real; 2], max_curvature: Real) -> Real {
    let (dx, dy) = (gx - x, gy - y);
    let l = dx.hypot(dy);
    if l <= opendrive::LENGTH_EPSILON {
        return 0.0;
    }
    let alpha = normalize_angle(dy.atan2(dx) - h);
    (2.0 * alpha.sin() / l).clamp(-max_curvature, max_curvature)
}

/// The pose after driving `distance` m on an arc of `curvature` from (x, y) heading `h`: the
/// single-track model's arc ([`arc_step`]) with the heading normalised to (−π, π]; on a
/// straight (a turn below 1e-9 rad, whose sagitta is below 1e-9·distance) the heading is kept.
pub fn drive_arc([x, y, h]: [Real; 3], curvature: Real, distance: Real) -> [Real; 3] {
    let (x1, y1, h1) = arc_step(x, y, h, distance, curvature);
    if (curvature * distance).abs() < crate::tolerance::TURN {
        return [x1, y1, h];
    }
    [x1, y1, normalize_angle(h1)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_6, PI};

    #[test]
    fn a_goal_on_the_circle_gives_the_circle() {
        // On the circle of radius 10 about (0, 10), at the origin heading 0: the goal at arc
        // 5 m further is (10 sin 0.5, 10 − 10 cos 0.5); 2 sin α/ℓ with α = 0.25, ℓ = 20 sin 0.25
        // is 1/10.
        let g = [10.0 * 0.5f64.sin(), 10.0 - 10.0 * 0.5f64.cos()];
        assert!((pursuit_curvature([0.0, 0.0, 0.0], g, 1.0) - 0.1).abs() < 1e-12);
        // Driving 5π m on it reaches the top of the circle, heading π.
        let [x, y, h] = drive_arc([0.0, 0.0, 0.0], 0.1, 5.0 * PI * 2.0);
        assert!(x.abs() < 1e-9 && (y - 20.0).abs() < 1e-9 && (h.abs() - PI).abs() < 1e-9);
        // The limit clamps: a goal straight to the left asks 2/ℓ.
        assert!((pursuit_curvature([0.0, 0.0, 0.0], [0.0, 1.0], 0.5) - 0.5).abs() < 1e-12);
    }

    #[test]
    fn curvature_limit_from_the_axles() {
        // The esmini catalog car: maxSteering 0.523598775598 rad (30°, written so in the
        // catalog), wheelbase 2.98 m: tan 30° / 2.98 = 0.57735/2.98 = 0.19374 1/m.
        let axle = |x: f64, steer: f64| scenario::Axle {
            max_steering: steer,
            wheel_diameter: 0.8,
            track_width: 1.68,
            position_x: x,
            position_z: 0.4,
        };
        let mut axles = Axles {
            front_axle: Some(axle(2.98, FRAC_PI_6)),
            rear_axle: axle(0.0, FRAC_PI_6),
            additional_axles: Vec::new(),
        };
        let k = max_curvature(&axles).unwrap();
        assert!((k - (1.0 / 3f64.sqrt()) / 2.98).abs() < 1e-9);
        axles.front_axle = Some(axle(2.98, FRAC_PI_2));
        assert!(max_curvature(&axles).is_none());
        axles.front_axle = None;
        assert!(max_curvature(&axles).is_none());
    }
}
