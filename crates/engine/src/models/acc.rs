//! Adaptive cruise control, ACC: a set speed and a constant time gap to the vehicle ahead,
//! with the acceleration and its rate of change bounded.
//!
//! Control law (V. Milanés, S. E. Shladover, "Modeling cooperative and autonomous adaptive
//! cruise control dynamic responses using experimental data", Transportation Research Part C
//! 48, 285–300, 2014, §3): the speed mode a = k_v·(v_set − v) with k_v = 0.4 s⁻¹; the gap mode
//! a = k₁·(s − s0 − T·v) + k₂·(v_leader − v) with k₁ = 0.23 s⁻², k₂ = 0.07 s⁻¹; with a vehicle
//! ahead the smaller of the two commands acts (the gap mode takes over as soon as it asks for
//! less).
//!
//! Limits (ISO 15622:2018 "Intelligent transport systems — Adaptive cruise control systems",
//! §6.4 operational limits), used as defaults where the controller's properties give none, as
//! functions of the speed, linear between 5 m/s and 20 m/s:
//!
//! | quantity | v ≤ 5 m/s | v ≥ 20 m/s |
//! | --- | --- | --- |
//! | automatic acceleration | 4.0 m/s² | 2.0 m/s² |
//! | automatic deceleration | 5.0 m/s² | 3.5 m/s² |
//! | rate of change of the deceleration (jerk) | 5.0 m/s³ | 2.5 m/s³ |
//!
//! The standard states the deceleration and jerk limits as averages (over 2 s and 1 s);
//! oscsim bounds every step by them, which keeps each average within the limit. The time gap
//! default, 1.5 s, is the lower end of the range 1.5 s to 2.2 s of which ISO 15622 requires
//! one selectable setting (§6.2.3; its smallest allowed gap is 0.8 s).

use opendrive::Real;

use super::idm::Leader;

/// Speed gain of the speed mode k_v (1/s).
pub const SPEED_GAIN: Real = 0.4;
/// Gap gain k₁ (1/s²).
pub const GAP_GAIN: Real = 0.23;
/// Speed-difference gain k₂ (1/s).
pub const SPEED_DIFFERENCE_GAIN: Real = 0.07;

/// ISO 15622 limits at speeds up to 5 m/s and from 20 m/s on: (acceleration, deceleration,
/// jerk), m/s², m/s², m/s³.
const ISO_LOW_SPEED: (Real, Real, Real) = (4.0, 5.0, 5.0);
const ISO_HIGH_SPEED: (Real, Real, Real) = (2.0, 3.5, 2.5);

/// The ISO 15622 limits at speed `v` (m/s): (acceleration, deceleration, jerk), interpolated
/// linearly between 5 and 20 m/s (module doc).
pub fn iso_15622_limits(v: Real) -> (Real, Real, Real) {
    let w = ((v.abs() - 5.0) / 15.0).clamp(0.0, 1.0);
    let lerp = |lo: Real, hi: Real| lo + (hi - lo) * w;
    (
        lerp(ISO_LOW_SPEED.0, ISO_HIGH_SPEED.0),
        lerp(ISO_LOW_SPEED.1, ISO_HIGH_SPEED.1),
        lerp(ISO_LOW_SPEED.2, ISO_HIGH_SPEED.2),
    )
}

/// The ACC settings (SI units), named as the `Property` names of an `acc` controller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AccParameters {
    /// `setSpeed` (m/s).
    pub set_speed: Real,
    /// `timeGap` T (s).
    pub time_gap: Real,
    /// `minimumGap` s0, the gap kept at standstill (m).
    pub minimum_gap: Real,
    /// `maxAcceleration` (m/s²); `None`: the ISO 15622 limit at the speed.
    pub max_acceleration: Option<Real>,
    /// `maxDeceleration` (m/s², positive); `None`: the ISO 15622 limit at the speed.
    pub max_deceleration: Option<Real>,
    /// `maxJerk` (m/s³); `None`: the ISO 15622 limit at the speed.
    pub max_jerk: Option<Real>,
}

impl AccParameters {
    /// Settings for `set_speed` with the defaults: time gap 1.5 s, 2 m at standstill, ISO
    /// 15622 limits.
    pub fn new(set_speed: Real) -> Self {
        AccParameters {
            set_speed,
            time_gap: 1.5,
            minimum_gap: 2.0,
            max_acceleration: None,
            max_deceleration: None,
            max_jerk: None,
        }
    }

    /// The limits at speed `v`: given ones, else ISO 15622's.
    pub fn limits(&self, v: Real) -> (Real, Real, Real) {
        let iso = iso_15622_limits(v);
        (
            self.max_acceleration.unwrap_or(iso.0),
            self.max_deceleration.unwrap_or(iso.1),
            self.max_jerk.unwrap_or(iso.2),
        )
    }

    /// The unbounded command (m/s²) at speed `v` behind `leader` (module doc).
    pub fn demand(&self, v: Real, leader: Option<Leader>) -> Real {
        let speed_mode = SPEED_GAIN * (self.set_speed - v);
        match leader {
            None => speed_mode,
            Some(l) => {
                let error = l.gap - self.minimum_gap - self.time_gap * v;
                let gap_mode = GAP_GAIN * error + SPEED_DIFFERENCE_GAIN * (l.speed - v);
                speed_mode.min(gap_mode)
            }
        }
    }

    /// The command for a step of `dt` s at speed `v` behind `leader`, after the last command
    /// `previous`: the demand bounded by the acceleration and deceleration limits, then by the
    /// jerk limit from `previous`.
    pub fn command(&self, v: Real, leader: Option<Leader>, previous: Real, dt: Real) -> Real {
        let (up, down, jerk) = self.limits(v);
        let bounded = self.demand(v, leader).clamp(-down, up);
        let step = jerk * dt;
        bounded.clamp(previous - step, previous + step)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::idm::ballistic_step;

    const EPS: Real = 1e-12;
    const DT: Real = 0.05;

    #[test]
    fn iso_limits_interpolate_between_5_and_20_m_per_s() {
        assert_eq!(iso_15622_limits(0.0), (4.0, 5.0, 5.0));
        assert_eq!(iso_15622_limits(30.0), (2.0, 3.5, 2.5));
        // 12.5 m/s is half-way: 4 − 2·0.5 = 3.0; 5 − 1.5·0.5 = 4.25; 5 − 2.5·0.5 = 3.75.
        let (a, d, j) = iso_15622_limits(12.5);
        assert!((a - 3.0).abs() < EPS && (d - 4.25).abs() < EPS && (j - 3.75).abs() < EPS);
    }

    #[test]
    fn demand_by_hand() {
        let p = AccParameters::new(30.0);
        // Free: 0.4·(30 − 25) = 2.0.
        assert!((p.demand(25.0, None) - 2.0).abs() < EPS);
        // Leader 40 m ahead at 20 m/s, own 25 m/s: 0.23·(40 − 2 − 37.5) + 0.07·(−5)
        // = 0.115 − 0.35 = −0.235, below the speed mode's 2.0.
        let l = Leader {
            gap: 40.0,
            speed: 20.0,
        };
        assert!((p.demand(25.0, Some(l)) + 0.235).abs() < EPS);
    }

    /// A sudden demand for a hard brake at 25 m/s ramps at the jerk limit 2.5 m/s³ to the
    /// deceleration limit 3.5 m/s²: −2.5 after 1 s, −3.5 from 1.4 s on.
    #[test]
    fn hard_brake_ramps_at_the_jerk_limit() {
        let p = AccParameters::new(30.0);
        let wall = Leader {
            gap: 5.0,
            speed: 0.0,
        };
        let mut a = 0.0;
        for step in 1..=40 {
            a = p.command(25.0, Some(wall), a, DT);
            let t = step as Real * DT;
            let expected = (-2.5 * t).max(-3.5);
            assert!((a - expected).abs() < 1e-9, "t = {t}: {a}");
        }
    }

    /// Behind a leader at a constant 20 m/s the ACC settles at the constant-time-gap spacing
    /// s0 + T·v = 2 + 1.5·20 = 32 m and at the leader's speed.
    #[test]
    fn settles_at_the_time_gap() {
        let p = AccParameters::new(30.0);
        let (mut gap, mut v, mut a) = (80.0, 28.0, 0.0);
        for _ in 0..(300.0 / DT) as usize {
            a = p.command(v, Some(Leader { gap, speed: 20.0 }), a, DT);
            let (next, d) = ballistic_step(v, a, DT);
            gap += 20.0 * DT - d;
            v = next;
            assert!(gap > 0.0);
        }
        assert!((gap - 32.0).abs() < 0.3, "gap {gap}");
        assert!((v - 20.0).abs() < 0.05, "speed {v}");
    }
}
