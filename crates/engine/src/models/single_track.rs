//! A vehicle driven by pedals, gear and steering wheel: the driver inputs of OpenSCENARIO 1.3
//! `OverrideControllerValueAction` (§7.7.2.5; XSD `OverrideThrottleAction`,
//! `OverrideBrakeAction`, `OverrideClutchAction`, `OverrideParkingBrakeAction`,
//! `OverrideSteeringWheelAction`, `OverrideGearAction`) turned into motion.
//!
//! **Actuators.** Each input moves towards the value asked for, at most at its `maxRate`
//! (pedals 1/s, brake force N/s, steering wheel rad/s); without a rate it takes the value at
//! once. The steering wheel with a `maxTorque` is a driven inertia J (`steeringWheelInertia`,
//! default [`DEFAULT_STEERING_INERTIA`]): its angular acceleration is at most maxTorque / J,
//! and it approaches the target time-optimally, at the angular speed √(2·α·|error|) that still
//! stops there (bounded by maxRate).
//!
//! **Longitudinal.** No engine or brake map: the Performance limits of the vehicle are the
//! model. Drive: throttle × (1 − clutch) × `maxAcceleration`, forwards in a forward gear
//! (ManualGear n > 0, AutomaticGear `d`), backwards in reverse (n < 0, `r`), none in neutral
//! (n = 0, `n`) or park (`p`). Brakes: BrakePercent p decelerates by p × `maxDeceleration`,
//! BrakeForce F by F / mass (the vehicle's `mass`); service and parking brake add; park holds
//! the vehicle as a full parking brake. Brakes oppose the motion and never reverse it: a
//! braked vehicle stops and stays, unless the drive is stronger than the brakes. The sum is
//! bounded by `maxAcceleration` / `maxDeceleration` and, where the Performance gives them, its
//! change per second by `maxAccelerationRate` / `maxDecelerationRate`; the speed by
//! `maxSpeed`. No rolling or air resistance: with no input the vehicle coasts at its speed.
//!
//! **Lateral.** The kinematic single-track (bicycle) model about the rear axle (R. Rajamani,
//! "Vehicle Dynamics and Control", 2nd ed., Springer 2012, §2.2, slip angles zero at low lateral
//! acceleration): the front wheel angle δ = steering wheel angle / `steeringRatio`, bounded by
//! the front axle's `maxSteering`; the path curvature κ = tan δ / L with L the wheelbase (front
//! axle `positionX` − rear axle `positionX`); the reference point (the rear-axle centre in
//! OpenSCENARIO) moves along a circular arc of that curvature over the step ([`arc_step`]).

use opendrive::Real;

use super::idm::ballistic_step;

/// Steering ratio (steering wheel angle / front wheel angle) when none is given: a typical
/// passenger car's 15:1.
pub const DEFAULT_STEERING_RATIO: Real = 15.0;
/// Moment of inertia of steering wheel and column (kg·m²) when none is given, for
/// `maxTorque`: the order of a passenger car's (0.03–0.05 kg·m²).
pub const DEFAULT_STEERING_INERTIA: Real = 0.04;

/// The gear selected (XSD `ManualGear` / `AutomaticGear`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum GearSelection {
    /// ManualGear `number`: > 0 forward, < 0 reverse, 0 neutral.
    Manual(i32),
    /// AutomaticGear `p`.
    Park,
    /// AutomaticGear `r`.
    Reverse,
    /// AutomaticGear `n`.
    Neutral,
    /// AutomaticGear `d`.
    #[default]
    Drive,
}

impl GearSelection {
    /// +1 forward, −1 reverse, 0 no drive.
    fn direction(self) -> Real {
        match self {
            GearSelection::Manual(n) if n > 0 => 1.0,
            GearSelection::Manual(n) if n < 0 => -1.0,
            GearSelection::Drive => 1.0,
            GearSelection::Reverse => -1.0,
            _ => 0.0,
        }
    }
}

/// A brake input (XSD group `BrakeInput`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Brake {
    /// BrakePercent, 0..1.
    Percent(Real),
    /// BrakeForce, N.
    Force(Real),
}

impl Default for Brake {
    fn default() -> Self {
        Brake::Percent(0.0)
    }
}

impl Brake {
    fn value(self) -> Real {
        match self {
            Brake::Percent(v) | Brake::Force(v) => v,
        }
    }

    fn with_value(self, v: Real) -> Brake {
        match self {
            Brake::Percent(_) => Brake::Percent(v),
            Brake::Force(_) => Brake::Force(v),
        }
    }
}

/// What the driver (or an override) asks of the vehicle.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DriverInputs {
    /// Throttle pedal, 0..1.
    pub throttle: Real,
    /// Service brake.
    pub brake: Brake,
    /// Clutch pedal, 0..1 (1: disengaged).
    pub clutch: Real,
    /// Parking brake.
    pub parking_brake: Brake,
    /// Steering wheel angle (rad, positive left).
    pub steering_wheel: Real,
    /// Gear.
    pub gear: GearSelection,
}

/// Rate limits of the inputs (`maxRate`, `maxTorque`); `None`: unbounded.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct InputLimits {
    /// Throttle, 1/s.
    pub throttle_rate: Option<Real>,
    /// Service brake, 1/s or N/s.
    pub brake_rate: Option<Real>,
    /// Clutch, 1/s.
    pub clutch_rate: Option<Real>,
    /// Parking brake, 1/s or N/s.
    pub parking_brake_rate: Option<Real>,
    /// Steering wheel angular speed, rad/s.
    pub steering_rate: Option<Real>,
    /// Steering torque, N·m.
    pub steering_torque: Option<Real>,
}

/// The vehicle's constants, from its Performance, Axles, mass and controller properties.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VehicleParameters {
    /// Wheelbase L (m).
    pub wheelbase: Real,
    /// Largest front wheel angle (rad).
    pub max_steering: Real,
    /// Steering wheel angle / front wheel angle.
    pub steering_ratio: Real,
    /// Steering wheel and column inertia (kg·m²).
    pub steering_inertia: Real,
    /// Mass (kg).
    pub mass: Real,
    /// Performance `maxSpeed` (m/s).
    pub max_speed: Real,
    /// Performance `maxAcceleration` (m/s²).
    pub max_acceleration: Real,
    /// Performance `maxDeceleration` (m/s², positive).
    pub max_deceleration: Real,
    /// Performance `maxAccelerationRate` (m/s³).
    pub max_acceleration_rate: Option<Real>,
    /// Performance `maxDecelerationRate` (m/s³).
    pub max_deceleration_rate: Option<Real>,
}

/// The actuators' state: where each input stands now.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct VehicleState {
    /// Inputs as applied (after the rate limits).
    pub applied: DriverInputs,
    /// Steering wheel angular speed (rad/s).
    pub steering_speed: Real,
    /// Longitudinal acceleration of the last step (m/s²).
    pub acceleration: Real,
}

/// The motion of one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepMotion {
    /// Speed at the end of the step (m/s, signed: negative backwards).
    pub speed: Real,
    /// Signed distance travelled (m).
    pub distance: Real,
    /// Path curvature (1/m, positive left).
    pub curvature: Real,
    /// Acceleration over the step (m/s²).
    pub acceleration: Real,
}

/// Moves `value` towards `target` by at most `rate`·dt.
fn approach(value: Real, target: Real, rate: Option<Real>, dt: Real) -> Real {
    match rate {
        Some(r) if r >= 0.0 => value + (target - value).clamp(-r * dt, r * dt),
        _ => target,
    }
}

impl VehicleParameters {
    /// The path curvature (1/m) at steering wheel angle `wheel` (rad).
    pub fn curvature(&self, wheel: Real) -> Real {
        let delta = (wheel / self.steering_ratio).clamp(-self.max_steering, self.max_steering);
        if self.wheelbase > 0.0 {
            delta.tan() / self.wheelbase
        } else {
            0.0
        }
    }

    /// Brake deceleration (m/s², positive) of one brake input.
    fn brake_deceleration(&self, b: Brake) -> Real {
        match b {
            Brake::Percent(p) => p.clamp(0.0, 1.0) * self.max_deceleration,
            Brake::Force(f) if self.mass > 0.0 => f.max(0.0) / self.mass,
            Brake::Force(_) => 0.0,
        }
    }

    /// Advances the actuators towards `asked` and the vehicle by `dt` s from speed `v`.
    pub fn step(
        &self,
        state: &mut VehicleState,
        asked: &DriverInputs,
        limits: &InputLimits,
        v: Real,
        dt: Real,
    ) -> StepMotion {
        let now = &mut state.applied;
        now.throttle = approach(now.throttle, asked.throttle, limits.throttle_rate, dt);
        now.clutch = approach(now.clutch, asked.clutch, limits.clutch_rate, dt);
        now.brake = approach_brake(now.brake, asked.brake, limits.brake_rate, dt);
        now.parking_brake = approach_brake(
            now.parking_brake,
            asked.parking_brake,
            limits.parking_brake_rate,
            dt,
        );
        now.gear = asked.gear;
        self.steer(state, asked.steering_wheel, limits, dt);
        let now = state.applied;

        let drive = now.gear.direction()
            * now.throttle.clamp(0.0, 1.0)
            * (1.0 - now.clutch.clamp(0.0, 1.0))
            * self.max_acceleration;
        let parking = if now.gear == GearSelection::Park {
            self.max_deceleration
        } else {
            self.brake_deceleration(now.parking_brake)
        };
        let braking = (self.brake_deceleration(now.brake) + parking).min(self.max_deceleration);
        let mut a = if v > 0.0 {
            drive - braking
        } else if v < 0.0 {
            drive + braking
        } else {
            // At rest the brakes hold against the drive up to their deceleration.
            drive.signum() * (drive.abs() - braking).max(0.0)
        };
        a = a.clamp(-self.max_deceleration, self.max_acceleration);
        // The Performance's rates bound the change of the acceleration.
        let rising = a > state.acceleration;
        let rate = if rising == (v >= 0.0) {
            self.max_acceleration_rate
        } else {
            self.max_deceleration_rate
        };
        a = approach(state.acceleration, a, rate, dt);
        state.acceleration = a;

        let (speed, distance) = signed_ballistic(v, a, drive, dt);
        let speed = speed.clamp(-self.max_speed, self.max_speed);
        StepMotion {
            speed,
            distance,
            curvature: self.curvature(now.steering_wheel),
            acceleration: a,
        }
    }

    /// The steering wheel towards `target` (module doc).
    fn steer(&self, state: &mut VehicleState, target: Real, limits: &InputLimits, dt: Real) {
        let angle = state.applied.steering_wheel;
        let rate = limits.steering_rate.filter(|r| *r >= 0.0);
        let Some(torque) = limits.steering_torque.filter(|t| *t > 0.0) else {
            let next = approach(angle, target, rate, dt);
            state.steering_speed = (next - angle) / dt;
            state.applied.steering_wheel = next;
            return;
        };
        let alpha = torque / self.steering_inertia.max(Real::EPSILON);
        let error = target - angle;
        let stopping = (2.0 * alpha * error.abs()).sqrt();
        let wanted = error.signum() * rate.map_or(stopping, |r| stopping.min(r));
        let omega = approach(state.steering_speed, wanted, Some(alpha), dt);
        let mut next = angle + omega * dt;
        // Never pass the target within a step.
        if (target - next).signum() != error.signum() {
            next = target;
        }
        state.steering_speed = (next - angle) / dt;
        state.applied.steering_wheel = next;
    }
}

fn approach_brake(now: Brake, asked: Brake, rate: Option<Real>, dt: Real) -> Brake {
    // A change of kind (percent ↔ force) starts the new kind from zero.
    let from = match (now, asked) {
        (Brake::Percent(v), Brake::Percent(_)) | (Brake::Force(v), Brake::Force(_)) => v,
        _ => 0.0,
    };
    asked.with_value(approach(from, asked.value(), rate, dt))
}

/// The speed and signed distance of a step at acceleration `a` from `v`: brakes stop the
/// vehicle at zero and never reverse it; from rest it moves only where the drive points.
fn signed_ballistic(v: Real, a: Real, drive: Real, dt: Real) -> (Real, Real) {
    if v == 0.0 && (drive == 0.0 || drive.signum() != a.signum()) {
        return (0.0, 0.0);
    }
    if v > 0.0 || (v == 0.0 && a > 0.0) {
        ballistic_step(v, a, dt)
    } else {
        let (s, d) = ballistic_step(-v, -a, dt);
        (-s, -d)
    }
}

/// Moves a pose (x, y, heading h) `distance` m along an arc of curvature `curvature`:
/// h' = h + κ·d; x' = x + (sin h' − sin h)/κ, y' = y − (cos h' − cos h)/κ; a straight line
/// when κ·d is below 1e-9 rad.
pub fn arc_step(x: Real, y: Real, h: Real, distance: Real, curvature: Real) -> (Real, Real, Real) {
    let turn = curvature * distance;
    if turn.abs() < crate::tolerance::TURN {
        return (x + distance * h.cos(), y + distance * h.sin(), h + turn);
    }
    let h2 = h + turn;
    (
        x + (h2.sin() - h.sin()) / curvature,
        y - (h2.cos() - h.cos()) / curvature,
        h2,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const DT: Real = 0.05;
    /// Issue 13: the stopping distance within 5 % of the closed form.
    const STOP_REL_TOLERANCE: Real = 0.05;

    fn car() -> VehicleParameters {
        VehicleParameters {
            wheelbase: 2.98,
            max_steering: 0.5,
            steering_ratio: DEFAULT_STEERING_RATIO,
            steering_inertia: DEFAULT_STEERING_INERTIA,
            mass: 1500.0,
            max_speed: 70.0,
            max_acceleration: 10.0,
            max_deceleration: 10.0,
            max_acceleration_rate: None,
            max_deceleration_rate: None,
        }
    }

    /// Drives from `v0` with `asked` until the vehicle stands (or 60 s); the distance.
    fn stopping_distance(
        p: &VehicleParameters,
        asked: &DriverInputs,
        limits: &InputLimits,
    ) -> Real {
        let mut state = VehicleState::default();
        let (mut v, mut x) = (30.0, 0.0);
        for _ in 0..1200 {
            let m = p.step(&mut state, asked, limits, v, DT);
            v = m.speed;
            x += m.distance;
            if v == 0.0 {
                break;
            }
        }
        assert_eq!(v, 0.0, "stands");
        x
    }

    fn full_brake() -> DriverInputs {
        DriverInputs {
            brake: Brake::Percent(1.0),
            ..DriverInputs::default()
        }
    }

    /// Issue 13: a full brake from 30 m/s with maxDeceleration 10 m/s² stops in
    /// v²/(2·d) = 900/20 = 45 m.
    #[test]
    fn full_brake_stops_within_the_closed_form() {
        let d = stopping_distance(&car(), &full_brake(), &InputLimits::default());
        assert!((d - 45.0).abs() <= STOP_REL_TOLERANCE * 45.0, "{d}");
    }

    /// With maxRate 2/s the pedal takes τ = 0.5 s to reach 1, the deceleration rising linearly:
    /// over the ramp x(τ) = v0·τ − d·τ²/6 = 15 − 0.41667 = 14.58333 m and v(τ) = v0 − d·τ/2
    /// = 27.5 m/s; then v(τ)²/(2d) = 756.25/20 = 37.8125 m; in all 52.39583 m.
    #[test]
    fn rate_limited_brake_adds_the_ramp() {
        let limits = InputLimits {
            brake_rate: Some(2.0),
            ..InputLimits::default()
        };
        let d = stopping_distance(&car(), &full_brake(), &limits);
        let expected: Real = 15.0 - 10.0 * 0.25 / 6.0 + 27.5 * 27.5 / 20.0;
        assert!((expected - 52.395_83).abs() < 1e-4);
        assert!((d - expected).abs() <= STOP_REL_TOLERANCE * expected, "{d}");
    }

    /// BrakeForce 7500 N on 1500 kg is 5 m/s²: 900/10 = 90 m; park holds a standing car.
    #[test]
    fn brake_force_uses_the_mass_and_park_holds() {
        let asked = DriverInputs {
            brake: Brake::Force(7500.0),
            ..DriverInputs::default()
        };
        let d = stopping_distance(&car(), &asked, &InputLimits::default());
        assert!((d - 90.0).abs() <= STOP_REL_TOLERANCE * 90.0, "{d}");
        let mut state = VehicleState::default();
        let parked = DriverInputs {
            throttle: 0.5,
            gear: GearSelection::Park,
            ..DriverInputs::default()
        };
        let m = car().step(&mut state, &parked, &InputLimits::default(), 0.0, DT);
        assert_eq!((m.speed, m.distance), (0.0, 0.0));
    }

    /// Throttle 0.5 in reverse from rest: −0.5·10 = −5 m/s²; after 1 s −5 m/s and −2.5 m.
    /// Neutral gives no drive.
    #[test]
    fn gears_set_the_direction() {
        let p = car();
        let mut state = VehicleState::default();
        let asked = DriverInputs {
            throttle: 0.5,
            gear: GearSelection::Manual(-1),
            ..DriverInputs::default()
        };
        let (mut v, mut x) = (0.0, 0.0);
        for _ in 0..20 {
            let m = p.step(&mut state, &asked, &InputLimits::default(), v, DT);
            v = m.speed;
            x += m.distance;
        }
        assert!((v + 5.0).abs() < 1e-9 && (x + 2.5).abs() < 1e-9, "{v} {x}");
        let neutral = DriverInputs {
            gear: GearSelection::Neutral,
            ..asked
        };
        let m = p.step(
            &mut VehicleState::default(),
            &neutral,
            &InputLimits::default(),
            0.0,
            DT,
        );
        assert_eq!(m.speed, 0.0);
    }

    /// Steering wheel 1.5 rad at ratio 15: δ = 0.1 rad, κ = tan 0.1 / 2.98 = 0.0336178 1/m.
    /// With maxRate 1 rad/s the wheel reaches 0.5 rad after 0.5 s.
    #[test]
    fn steering_curvature_and_rate() {
        let p = car();
        assert!((p.curvature(1.5) - 0.1_f64.tan() / 2.98).abs() < 1e-12);
        // Bounded by maxSteering: 15 rad of wheel is δ = 1 rad → 0.5 rad.
        assert!((p.curvature(15.0) - 0.5_f64.tan() / 2.98).abs() < 1e-12);
        let mut state = VehicleState::default();
        let asked = DriverInputs {
            steering_wheel: 1.5,
            ..DriverInputs::default()
        };
        let limits = InputLimits {
            steering_rate: Some(1.0),
            ..InputLimits::default()
        };
        for _ in 0..10 {
            p.step(&mut state, &asked, &limits, 10.0, DT);
        }
        assert!((state.applied.steering_wheel - 0.5).abs() < 1e-9);
    }

    /// maxTorque 0.4 N·m on J = 0.04 kg·m²: α = 10 rad/s². To turn 1 rad time-optimally
    /// takes 2·√(1/α) = 0.632 s (accelerate half-way, brake half-way); the wheel arrives
    /// within 0.1 s of that and never overshoots.
    #[test]
    fn steering_torque_limits_the_angular_acceleration() {
        let p = car();
        let mut state = VehicleState::default();
        let asked = DriverInputs {
            steering_wheel: 1.0,
            ..DriverInputs::default()
        };
        let limits = InputLimits {
            steering_torque: Some(0.4),
            ..InputLimits::default()
        };
        let mut arrived = None;
        for k in 1..=40 {
            p.step(&mut state, &asked, &limits, 10.0, DT);
            assert!(state.applied.steering_wheel <= 1.0 + 1e-12);
            if arrived.is_none() && (state.applied.steering_wheel - 1.0).abs() < 1e-3 {
                arrived = Some(k as Real * DT);
            }
        }
        let t = arrived.expect("the wheel reaches its target");
        assert!((t - 2.0 * 0.1_f64.sqrt()).abs() < 0.1, "{t}");
    }

    /// A quarter circle: κ = 0.01, d = 50π m from (0, 0) heading 0 ends at (100, 100),
    /// heading π/2.
    #[test]
    fn arc_step_quarter_circle() {
        let (x, y, h) = arc_step(0.0, 0.0, 0.0, 50.0 * std::f64::consts::PI, 0.01);
        assert!((x - 100.0).abs() < 1e-9 && (y - 100.0).abs() < 1e-9);
        assert!((h - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    }
}
