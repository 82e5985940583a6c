//! The Intelligent Driver Model, IDM (M. Treiber, A. Hennecke, D. Helbing, "Congested traffic
//! states in empirical observations and microscopic simulations", Phys. Rev. E 62, 1805 (2000),
//! eq. (2) and (3)): the longitudinal acceleration of a driver who wants to drive at a desired
//! speed v0 and keep a safe time headway T to the vehicle ahead,
//!
//! ```text
//! dv/dt = a · [1 − (v/v0)^δ − (s*(v, Δv)/s)²],   s*(v, Δv) = s0 + max(0, v·T + v·Δv / (2√(a·b)))
//! ```
//!
//! with s the gap to the leader (bumper to bumper), Δv = v − v_leader the approach rate, a the
//! maximum acceleration, b the comfortable deceleration, s0 the minimum gap at standstill and δ
//! the acceleration exponent. On a free road the interaction term vanishes:
//! dv/dt = a·(1 − (v/v0)^δ). The max(0, ·) in s* is the usual guard against a negative desired
//! gap when the leader is much faster (Treiber & Kesting, "Traffic Flow Dynamics", Springer
//! 2013, §11.3.4).
//!
//! The defaults are the paper's highway parameter set: v0 = 120 km/h, T = 1.6 s, s0 = 2 m,
//! a = 0.73 m/s², b = 1.67 m/s², δ = 4.
//!
//! Integration is the ballistic update of Treiber & Kanagaraj ("Comparing numerical
//! integration schemes for time-continuous car-following models", Physica A 419, 2015): the
//! acceleration is held over the step, the speed never becomes negative, and the distance is
//! that of the constant acceleration up to the stop.

use opendrive::Real;

use super::fourth_power::fourth_power;

/// Smallest gap the interaction term is evaluated at (m): a gap at or below zero (boxes that
/// touch or overlap) is read as this, so the model asks for a large but finite deceleration
/// that the caller bounds by the vehicle's performance.
pub const GAP_FLOOR: Real = 0.01;

/// The IDM parameters (SI units), named as the `Property` names of an `idm` controller.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IdmParameters {
    /// `desiredSpeed` v0 (m/s).
    pub desired_speed: Real,
    /// `timeHeadway` T (s).
    pub time_headway: Real,
    /// `minimumGap` s0 (m).
    pub minimum_gap: Real,
    /// `maxAcceleration` a (m/s²).
    pub max_acceleration: Real,
    /// `comfortableDeceleration` b (m/s², positive).
    pub comfortable_deceleration: Real,
    /// `accelerationExponent` δ.
    pub acceleration_exponent: Real,
}

impl Default for IdmParameters {
    /// The highway set of Treiber, Hennecke and Helbing (2000).
    fn default() -> Self {
        IdmParameters {
            desired_speed: 120.0 / 3.6,
            time_headway: 1.6,
            minimum_gap: 2.0,
            max_acceleration: 0.73,
            comfortable_deceleration: 1.67,
            acceleration_exponent: 4.0,
        }
    }
}

/// The vehicle ahead as the follower sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Leader {
    /// Gap, bumper to bumper along the lane (m).
    pub gap: Real,
    /// The leader's speed along the follower's direction of travel (m/s).
    pub speed: Real,
}

impl IdmParameters {
    /// The desired gap s*(v, Δv) (m) at speed `v` and approach rate `dv` = v − v_leader.
    pub fn desired_gap(&self, v: Real, dv: Real) -> Real {
        let ab = (self.max_acceleration * self.comfortable_deceleration).sqrt();
        let dynamic = v * self.time_headway + v * dv / (2.0 * ab);
        self.minimum_gap + dynamic.max(0.0)
    }

    /// The free-road term a·(1 − (v/v0)^δ) (m/s²). A desired speed of 0 asks to stop: the term
    /// is then −b for a moving vehicle and 0 at rest.
    pub fn free_acceleration(&self, v: Real) -> Real {
        if self.desired_speed <= 0.0 {
            return if v > 0.0 {
                -self.comfortable_deceleration
            } else {
                0.0
            };
        }
        let x = v.max(0.0) / self.desired_speed;
        // δ = 4 (the default) exactly: x⁴ with pow's bits without calling it in 57 cases of
        // 64 (models/fourth_power.rs).
        let ratio = if self.acceleration_exponent == 4.0 {
            fourth_power(x)
        } else {
            x.powf(self.acceleration_exponent)
        };
        self.max_acceleration * (1.0 - ratio)
    }

    /// The IDM acceleration (m/s²) at speed `v` behind `leader` (none: free road).
    pub fn acceleration(&self, v: Real, leader: Option<Leader>) -> Real {
        self.acceleration_with_free(self.free_acceleration(v), v, leader)
    }

    /// [`acceleration`](Self::acceleration) given its free-road term `free` =
    /// [`free_acceleration`](Self::free_acceleration)`(v)`: a caller weighing several leaders
    /// for one speed (MOBIL) evaluates the power (v/v0)^δ once.
    pub fn acceleration_with_free(&self, free: Real, v: Real, leader: Option<Leader>) -> Real {
        match leader {
            None => free,
            Some(l) => free - self.interaction(v, l),
        }
    }

    /// The interaction term a·(s*(v, Δv)/s)² (m/s², ≥ 0 unless a parameter is NaN) behind
    /// `leader`: the IDM acceleration behind it is the free-road term less this, as
    /// [`acceleration_with_free`](Self::acceleration_with_free) subtracts it.
    #[inline]
    pub fn interaction(&self, v: Real, leader: Leader) -> Real {
        let ratio = self.desired_gap(v, v - leader.speed) / leader.gap.max(GAP_FLOOR);
        self.max_acceleration * ratio * ratio
    }

    /// Bounds (lo, hi) of [`free_acceleration`](Self::free_acceleration)`(v)` as it computes
    /// it, bit for bit: lo ≤ free_acceleration(v) ≤ hi, without the power where δ = 4 (a
    /// caller that needs only a bound of an acceleration, as MOBIL weighing the followers of a
    /// change that cannot pass, controller/mobil.rs). Elsewhere both are the term itself.
    ///
    /// Why they bound it: with x = v/v0 as the term computes it, z = (x·x)·(x·x) is within
    /// (1 + u)³ − 1 < 3.1·u of x⁴ (u = 2⁻⁵³, three roundings) and `pow(x, 4)` within 60 ulp ≤
    /// 120·u of x⁴ (glibc documents 0.54 ulp), so within 124·u·z of z, inside
    /// z·(1 ± 2⁻⁴⁶) = z·(1 ± 128·u) rounded outwards; for x in [2⁻²⁰⁰, 2²⁰⁰] every one of
    /// these numbers is a normal double, and z·2⁻⁴⁶ is exact. Rounding to nearest is monotone,
    /// so a·(1 − p) with a > 0 is monotone in p: the power's bounds give the term's, in the
    /// same operations.
    pub fn free_acceleration_bounds(&self, v: Real) -> (Real, Real) {
        /// The power's relative bound 2⁻⁴⁶.
        const SLACK: Real = 1.0 / (1u64 << 46) as Real;
        /// x beyond which z or its slack might leave the normal doubles.
        const RANGE: Real = 1.0e60;
        let a = self.max_acceleration;
        let usable = self.desired_speed > 0.0
            && self.acceleration_exponent == 4.0
            && a > 0.0
            && a.is_finite();
        let x = v.max(0.0) / self.desired_speed;
        if usable && (1.0 / RANGE..=RANGE).contains(&x) {
            let x2 = x * x;
            let z = x2 * x2;
            let w = z * SLACK;
            return (a * (1.0 - (z + w)), a * (1.0 - (z - w)));
        }
        let f = self.free_acceleration(v);
        (f, f)
    }

    /// The equilibrium gap (m) at speed `v` (dv/dt = 0 behind a leader at the same speed):
    /// s_e(v) = (s0 + v·T) / √(1 − (v/v0)^δ). `None` at or above the desired speed, where no
    /// gap holds the speed.
    pub fn equilibrium_gap(&self, v: Real) -> Option<Real> {
        let free = 1.0 - (v / self.desired_speed).powf(self.acceleration_exponent);
        (free > 0.0).then(|| (self.minimum_gap + v * self.time_headway) / free.sqrt())
    }
}

/// One ballistic step (module doc): from speed `v` with acceleration `a` held for `dt` s.
/// Returns the speed at the end and the distance travelled; a braking vehicle stops at
/// v = 0 after −v²/(2a) metres and stays there.
pub fn ballistic_step(v: Real, a: Real, dt: Real) -> (Real, Real) {
    let next = v + a * dt;
    if next < 0.0 && a < 0.0 {
        (0.0, -v * v / (2.0 * a))
    } else {
        (next.max(0.0), 0.5 * (v + next.max(0.0)) * dt)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Relative tolerance of a simulated speed against the closed form (issue 13: 1 %).
    const SPEED_REL_TOLERANCE: Real = 0.01;
    /// Equilibrium gap tolerance (issue 13: 0.3 m) and speed tolerance (0.05 m/s).
    const GAP_TOLERANCE: Real = 0.3;
    const SPEED_TOLERANCE: Real = 0.05;
    const DT: Real = 0.05;

    /// Time to reach speed v from rest on a free road with δ = 4:
    /// dv/dt = a(1 − u⁴), u = v/v0, so t = (v0/a)∫₀^u du/(1 − u⁴); with
    /// 1/(1 − u⁴) = ½[1/(1 − u²) + 1/(1 + u²)] the integral is ½(artanh u + arctan u).
    fn free_road_time(p: &IdmParameters, v: Real) -> Real {
        let u = v / p.desired_speed;
        p.desired_speed / (2.0 * p.max_acceleration) * (u.atanh() + u.atan())
    }

    /// The closed-form speed at time t: the inverse of [`free_road_time`] by bisection (t(v)
    /// rises strictly from 0 to ∞ on [0, v0)).
    fn free_road_speed(p: &IdmParameters, t: Real) -> Real {
        let (mut lo, mut hi) = (0.0, p.desired_speed * (1.0 - 1e-15));
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if free_road_time(p, mid) < t {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    #[test]
    fn desired_gap_and_terms_at_hand_values() {
        let p = IdmParameters::default();
        // s*(20, 0) = 2 + 20·1.6 = 34 m; s*(20, 5) = 34 + 20·5/(2√(0.73·1.67)) with
        // √1.2191 = 1.104129 → 100/2.208258 = 45.28457 → 79.28457 m.
        assert!((p.desired_gap(20.0, 0.0) - 34.0).abs() < 1e-12);
        assert!((p.desired_gap(20.0, 5.0) - 79.284_57).abs() < 1e-4);
        // A much faster leader: the dynamic part is negative and clamped, s* = s0.
        assert!((p.desired_gap(10.0, -30.0) - 2.0).abs() < 1e-12);
        // Free road at v0/2: 0.73·(1 − 1/16) = 0.684375 m/s².
        assert!((p.acceleration(p.desired_speed / 2.0, None) - 0.684_375).abs() < 1e-12);
        // Standing behind a standing leader at exactly s0: 0.73·(1 − 0 − 1) = 0.
        let at_s0 = Leader {
            gap: 2.0,
            speed: 0.0,
        };
        assert!(p.acceleration(0.0, Some(at_s0)).abs() < 1e-12);
    }

    #[test]
    fn ballistic_step_stops_at_zero() {
        // 1 m/s braking at 4 m/s² over 0.5 s: stops after 0.25 s, 1/(2·4) = 0.125 m.
        let (v, d) = ballistic_step(1.0, -4.0, 0.5);
        assert_eq!(v, 0.0);
        assert!((d - 0.125).abs() < 1e-12);
        // 10 m/s at +1 m/s² over 1 s: 11 m/s, 10.5 m.
        let (v, d) = ballistic_step(10.0, 1.0, 1.0);
        assert!((v - 11.0).abs() < 1e-12 && (d - 10.5).abs() < 1e-12);
    }

    /// Issue 13: IDM on a free road from rest follows dv/dt = a(1 − (v/v0)^δ) within 1 %
    /// (closed form in [`free_road_time`]), at dt = 0.05 s.
    #[test]
    fn free_road_from_rest_follows_the_closed_form() {
        let p = IdmParameters::default();
        let mut v = 0.0;
        let mut t = 0.0;
        for check in [2.0, 5.0, 10.0, 20.0, 40.0, 80.0] {
            while t < check - 1e-9 {
                v = ballistic_step(v, p.acceleration(v, None), DT).0;
                t += DT;
            }
            let exact = free_road_speed(&p, check);
            assert!(
                (v - exact).abs() <= SPEED_REL_TOLERANCE * exact,
                "t = {check}: {v} against {exact}"
            );
        }
    }

    /// Issue 13: behind a leader at a constant 20 m/s, the follower settles at the equilibrium
    /// gap s_e = (s0 + vT)/√(1 − (v/v0)^δ) = (2 + 32)/√(1 − 0.6⁴) = 34/√0.8704 = 36.4434 m
    /// (v/v0 = 20/33.333 = 0.6) and at the leader's speed.
    #[test]
    fn follower_converges_to_the_equilibrium_gap() {
        let p = IdmParameters::default();
        let expected = p.equilibrium_gap(20.0).expect("below v0");
        assert!((expected - 36.443_4).abs() < 1e-3, "{expected}");
        let (mut gap, mut v) = (80.0, 28.0);
        for _ in 0..(300.0 / DT) as usize {
            let a = p.acceleration(v, Some(Leader { gap, speed: 20.0 }));
            let (next, d) = ballistic_step(v, a, DT);
            gap += 20.0 * DT - d;
            v = next;
            assert!(gap > 0.0);
        }
        assert!((gap - expected).abs() < GAP_TOLERANCE, "gap {gap}");
        assert!((v - 20.0).abs() < SPEED_TOLERANCE, "speed {v}");
    }

    /// Issue 13: approaching a standing obstacle from 25 m/s, 300 m away, the vehicle stops at
    /// the gap s0 = 2 m (at v = 0 the acceleration a(1 − (s0/s)²) vanishes exactly at s = s0),
    /// and the gap never reaches zero.
    #[test]
    fn stops_behind_a_standing_obstacle_at_the_minimum_gap() {
        let p = IdmParameters::default();
        let (mut gap, mut v) = (300.0, 25.0);
        let mut smallest = gap;
        for _ in 0..(200.0 / DT) as usize {
            let a = p.acceleration(v, Some(Leader { gap, speed: 0.0 }));
            let (next, d) = ballistic_step(v, a, DT);
            gap -= d;
            v = next;
            smallest = smallest.min(gap);
        }
        assert!(smallest > 0.0);
        assert!((gap - p.minimum_gap).abs() < GAP_TOLERANCE, "gap {gap}");
        assert!(v < SPEED_TOLERANCE, "speed {v}");
    }

    #[test]
    fn zero_desired_speed_brakes_to_rest() {
        let p = IdmParameters {
            desired_speed: 0.0,
            ..IdmParameters::default()
        };
        assert!((p.free_acceleration(5.0) + 1.67).abs() < 1e-12);
        assert_eq!(p.free_acceleration(0.0), 0.0);
        assert!(p.equilibrium_gap(1.0).is_none());
    }

    /// `free_acceleration_bounds` holds the term as computed, bit for bit, between its
    /// bounds: at δ = 4 for 3 million speeds from 0 to 2·v0 (v0 from 1 to 70 m/s, a from 0.1
    /// to 5 m/s²), their bounds within 2⁻⁴⁴·a·(1 + x⁴) of each other (x = v/v0; a width of
    /// 2·2⁻⁴⁶·a·x⁴ by hand, and the roundings of 1 − p and a·(…), each half an ulp of a; below
    /// x = 2⁻⁶ both round to the term's bits);
    /// elsewhere (δ = 2.5,
    /// v0 = 0, a negative or NaN speed, a speed of 1e200) both bounds are the term's bits.
    #[test]
    fn the_free_road_bounds_hold_the_term() {
        const REL_WIDTH: Real = 1.0 / (1u64 << 44) as Real;
        let mut s: u64 = 0x2545_F491_4F6C_DD1D;
        let mut next = move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as Real / (1u64 << 53) as Real
        };
        for _ in 0..3_000_000 {
            let p = IdmParameters {
                desired_speed: 1.0 + 69.0 * next(),
                max_acceleration: 0.1 + 4.9 * next(),
                ..IdmParameters::default()
            };
            let v = 2.0 * p.desired_speed * next();
            let f = p.free_acceleration(v);
            let (lo, hi) = p.free_acceleration_bounds(v);
            assert!(
                lo <= f
                    && f <= hi
                    && hi - lo
                        <= REL_WIDTH * p.max_acceleration * (1.0 + (v / p.desired_speed).powi(4)),
                "{p:?} v {v}: {lo} {f} {hi}"
            );
        }
        let odd = [
            IdmParameters {
                acceleration_exponent: 2.5,
                ..IdmParameters::default()
            },
            IdmParameters {
                desired_speed: 0.0,
                ..IdmParameters::default()
            },
            IdmParameters::default(),
        ];
        for (k, p) in odd.iter().enumerate() {
            for v in [-3.0, 0.0, Real::NAN, 1e200, 17.0] {
                // At δ = 4, v0 > 0 and 17 m/s the power is bounded, not evaluated.
                if k == 2 && v == 17.0 {
                    continue;
                }
                let (lo, hi) = p.free_acceleration_bounds(v);
                let f = p.free_acceleration(v).to_bits();
                assert_eq!((lo.to_bits(), hi.to_bits()), (f, f), "{p:?} v {v}");
            }
        }
    }
}
