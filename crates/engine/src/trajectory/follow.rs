//! TrajectoryFollowingMode `follow` of a timed trajectory (OpenSCENARIO 1.3 XSD
//! `TrajectoryFollowingMode`, enumeration `FollowingMode`: "follow: Follow the lateral and/or
//! longitudinal target value as good as possible by observing the dynamic constraints of the
//! entity"; "position: … exactly by ignoring the dynamic constraints").
//!
//! The longitudinal target is the arc length s_ref(t) the trajectory's times give, in the
//! speed-continuous reading of the times (`TimeTable::continuous_speeds`: each vertex reached
//! on time, the speed changing linearly between vertices, from the entity's speed at the
//! start), which a vehicle can drive where the linear reading's speed jumps. Each step
//! from t to t + dt the entity wants the reference's own advance, (s_ref(t + dt) − s_ref(t))/dt,
//! plus a correction c of its gap e = s_ref(t) − s, signed as e: the time-optimal approach
//! of a double integrator whose speed changes by at most a·dt per step (a: maxDeceleration
//! when behind, since the approach ends braking back to the reference's speed;
//! maxAcceleration when ahead). Shedding c in steps of a·dt covers dt·c·(c/(a·dt) + 1)/2,
//! which is |e| for c = a·dt·(√(1/4 + 2|e|/(a·dt²)) − 1/2) (the continuous √(2a|e|) less
//! the half step that makes the discrete approach land without undershoot); and c is never
//! more than |e|/dt, which closes the gap in one step. That speed is then limited by its
//! Performance (OpenSCENARIO 1.3 XSD `Performance`): at most maxAcceleration·dt up or
//! maxDeceleration·dt down from its current speed, between 0 and maxSpeed. Where the limits
//! allow, this is exactly the timed motion (as `position`); where they do not, the entity lags
//! or leads and closes the gap at its limits without overshooting. An entity without
//! Performance (a pedestrian, a misc object) has no dynamic constraint to observe and moves as
//! in `position`.
//!
//! Laterally, a vehicle whose axles bound its curvature steers along an open trajectory by
//! pure pursuit (`steer`); other entities (no axles: pedestrians, misc objects) have no lateral
//! constraint to observe and stay on the path.

use opendrive::Real;

/// The dynamic constraints observed in `follow` mode (XSD `Performance`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FollowLimits {
    /// Largest speed gain per second (m/s², > 0).
    pub acceleration: Real,
    /// Largest speed loss per second (m/s², > 0).
    pub deceleration: Real,
    /// Largest speed (m/s, > 0).
    pub max_speed: Real,
}

impl FollowLimits {
    /// Limits from Performance values; `None` unless all three are finite and positive (a
    /// vehicle whose Performance says nothing usable is followed as in `position`).
    pub fn new(acceleration: Real, deceleration: Real, max_speed: Real) -> Option<Self> {
        let ok = |v: Real| v.is_finite() && v > 0.0;
        (ok(acceleration.abs()) && ok(deceleration.abs()) && ok(max_speed)).then_some(Self {
            acceleration: acceleration.abs(),
            deceleration: deceleration.abs(),
            max_speed,
        })
    }

    /// The speed (m/s) for a step of `dt` s from speed `v0` at arc length `s`, the reference
    /// being at `s_ref` now and at `s_ref_next` at the step's end. `dt` ≤ 0 keeps `v0`.
    pub fn tracking_speed(
        &self,
        v0: Real,
        s: Real,
        s_ref: Real,
        s_ref_next: Real,
        dt: Real,
    ) -> Real {
        if dt <= 0.0 {
            return v0;
        }
        let gap = s_ref - s;
        let closing = if gap >= 0.0 {
            self.deceleration
        } else {
            self.acceleration
        };
        let step = closing * dt;
        let braking = step * ((0.25 + 2.0 * gap.abs() / (step * dt)).sqrt() - 0.5);
        let correction = braking.min(gap.abs() / dt);
        let wanted = (s_ref_next - s_ref) / dt + correction.copysign(gap);
        let low = (v0 - self.deceleration * dt).max(0.0);
        let high = (v0 + self.acceleration * dt).min(self.max_speed);
        if low > high {
            // Above maxSpeed already: slow down as fast as allowed.
            low
        } else {
            wanted.clamp(low, high)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_when_the_limits_allow_it() {
        // On the reference, which advances 0.5 m in 0.05 s: 10 m/s, kept.
        let l = FollowLimits::new(5.0, 8.0, 40.0).unwrap();
        assert!((l.tracking_speed(10.0, 0.0, 0.0, 0.5, 0.05) - 10.0).abs() < 1e-12);
        // The reference speeds up to 10.2 m/s: 10 + 5·0.05 = 10.25 allows it.
        assert!((l.tracking_speed(10.0, 0.0, 0.0, 0.51, 0.05) - 10.2).abs() < 1e-12);
    }

    #[test]
    fn limited_changes_and_the_approach_curve() {
        let l = FollowLimits::new(5.0, 8.0, 40.0).unwrap();
        // The reference drops to 2 m/s: 10 − 8·0.05 = 9.6 at most down.
        assert!((l.tracking_speed(10.0, 0.0, 0.0, 0.1, 0.05) - 9.6).abs() < 1e-12);
        // 0.9 m ahead of a reference at 10 m/s (it moves 0.5 m in the step): the gap closes
        // by accelerating back (a·dt = 0.25 m/s per step), so c = 0.25·(√(1/4 + 2·0.9/
        // (0.25·0.05)) − 1/2) = 0.25·(12.01 − 0.5) = 2.8776 m/s below the reference:
        // 7.1224 m/s, which the step from 7 m/s allows (6.6 .. 7.25).
        let c = 0.25 * ((0.25f64 + 2.0 * 0.9 / (0.25 * 0.05)).sqrt() - 0.5);
        assert!((c - 2.8776).abs() < 1e-4);
        assert!((l.tracking_speed(7.0, 0.9, 0.0, 0.5, 0.05) - (10.0 - c)).abs() < 1e-12);
        // Shedding c in steps of 0.25 m/s covers the gap: Σ dt·(c − k·0.25) over k = 0 .. c/0.25.
        let n = c / 0.25;
        assert!((0.05 * c * (n + 1.0) / 2.0 - 0.9).abs() < 1e-12);
        // 2 m behind a reference at 10 m/s: c > 5 m/s above it, limited to 14 + 0.25 from
        // 14 m/s.
        assert!((l.tracking_speed(14.0, 0.0, 2.0, 2.5, 0.05) - 14.25).abs() < 1e-12);
        // 1 mm behind: the braking curve would allow 0.4·(√(1/4 + 0.002/0.02) − 1/2) =
        // 0.0366 m/s extra, the one-step closure only 0.001/0.05 = 0.02.
        assert!((l.tracking_speed(10.0, 0.0, 0.001, 0.501, 0.05) - 10.02).abs() < 1e-12);
        // Never below 0, never above maxSpeed.
        assert!(l.tracking_speed(0.1, 1.0, 0.0, 0.0, 0.05).abs() < 1e-12);
        assert!((l.tracking_speed(39.9, 0.0, 0.0, 10.0, 0.05) - 40.0).abs() < 1e-12);
    }

    #[test]
    fn unusable_performance_gives_no_limits() {
        assert!(FollowLimits::new(0.0, 8.0, 40.0).is_none());
        assert!(FollowLimits::new(5.0, f64::NAN, 40.0).is_none());
    }
}
