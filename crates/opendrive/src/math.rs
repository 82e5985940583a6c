//! Scalar type, pose type and the named tolerances of oscsim.
//!
//! Angles follow the OpenDRIVE 1.8 inertial frame (§8, coordinate systems): x east, y north,
//! z up, right-handed; heading counter-clockwise from +x about z, pitch about the rotated y axis
//! (positive = nose down), roll about the rotated x axis (positive = right side down). Every
//! other module and crate takes its epsilon from here, never its own.

/// The scalar used throughout oscsim: IEEE 754 double precision.
pub type Real = f64;

/// Lengths closer than this are the same length (m); used for s-range checks and section
/// boundaries.
pub const LENGTH_EPSILON: Real = 1e-9;

/// s may lie this far beyond a road's end and still be clamped onto it (m). OpenDRIVE files
/// write lengths with finite decimals, so the sum of geometry lengths and `road/@length` may
/// differ in the last digits.
pub const S_TOLERANCE: Real = 1e-6;

/// Convergence tolerance of the numeric inversions (arc length → curve parameter, world →
/// road projection), in metres.
pub const SOLVER_TOLERANCE: Real = 1e-10;

/// Largest gap between the end of one plan-view geometry and the start of the next before the
/// loader warns (m). Not an error: each geometry is placed by its own start.
pub const GEOMETRY_GAP_TOLERANCE: Real = 1e-3;

/// Vehicle pose in the OpenDRIVE inertial frame: position (m) and heading, pitch, roll (rad).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose {
    /// x (m), east.
    pub x: Real,
    /// y (m), north.
    pub y: Real,
    /// z (m), up.
    pub z: Real,
    /// Heading (rad), counter-clockwise from +x, in (−π, π].
    pub h: Real,
    /// Pitch (rad), positive nose down.
    pub p: Real,
    /// Roll (rad), positive right side down.
    pub r: Real,
}

impl approx::AbsDiffEq for Pose {
    type Epsilon = Real;

    fn default_epsilon() -> Real {
        LENGTH_EPSILON
    }

    /// Positions compare component-wise; angles compare modulo 2π.
    fn abs_diff_eq(&self, other: &Self, epsilon: Real) -> bool {
        (self.x - other.x).abs() <= epsilon
            && (self.y - other.y).abs() <= epsilon
            && (self.z - other.z).abs() <= epsilon
            && angle_difference(self.h, other.h).abs() <= epsilon
            && angle_difference(self.p, other.p).abs() <= epsilon
            && angle_difference(self.r, other.r).abs() <= epsilon
    }
}

/// Wraps an angle into (−π, π].
///
/// The common case, |a| < π, returns a as it is in one comparison of |a| (the sign bit
/// cleared); a = π, which is in the interval too, takes the wrap, where π mod 2π is π again
/// (`rem_euclid` is exact, and π < 2π), so π is returned as it is; −π, NaN and every other a
/// take the wrap as before.
#[inline]
pub fn normalize_angle(a: Real) -> Real {
    use std::f64::consts::{PI, TAU};
    if a.abs() < PI {
        return a; // the common case, without a division
    }
    let mut w = a.rem_euclid(TAU);
    if w > PI {
        w -= TAU;
    }
    w
}

/// Signed smallest difference `a − b`, in (−π, π].
pub fn angle_difference(a: Real, b: Real) -> Real {
    normalize_angle(a - b)
}

/// A cubic polynomial `a + b·ds + c·ds² + d·ds³` starting at `start` along its axis: the
/// record type of OpenDRIVE's elevation, superelevation, laneOffset and lane width/border
/// elements (OpenDRIVE 1.8 §9, §11).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cubic {
    /// Where the record starts (s or sOffset, m).
    pub start: Real,
    /// Constant term.
    pub a: Real,
    /// Linear coefficient.
    pub b: Real,
    /// Quadratic coefficient.
    pub c: Real,
    /// Cubic coefficient.
    pub d: Real,
}

impl Cubic {
    /// Value and first derivative at `x` (the record's own start is subtracted here).
    #[inline]
    pub fn eval(&self, x: Real) -> (Real, Real) {
        let ds = x - self.start;
        let v = self.a + ds * (self.b + ds * (self.c + ds * self.d));
        let dv = self.b + ds * (2.0 * self.c + ds * 3.0 * self.d);
        (v, dv)
    }
}

/// Value and derivative of a piecewise cubic (records sorted by `start`) at `x`: the last record
/// starting at or before `x` applies; before the first record, the first one is extrapolated.
/// Returns `(0, 0)` for an empty list, the OpenDRIVE default for absent profiles.
#[inline]
pub fn eval_piecewise(records: &[Cubic], x: Real) -> (Real, Real) {
    if records.is_empty() {
        return (0.0, 0.0);
    }
    let i = records.partition_point(|r| r.start <= x + LENGTH_EPSILON);
    records[i.saturating_sub(1)].eval(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalize_angle_wraps_into_half_open_interval() {
        use std::f64::consts::PI;
        // 3π wraps to π (upper end included), −π wraps to π as well.
        assert!((normalize_angle(3.0 * PI) - PI).abs() < 1e-12);
        assert!((normalize_angle(-PI) - PI).abs() < 1e-12);
        assert!((normalize_angle(0.5) - 0.5).abs() < 1e-15);
        assert!((angle_difference(0.1, 2.0 * PI - 0.1) - 0.2).abs() < 1e-12);
    }

    /// The one-comparison test of the common case against the interval's two bounds, bit
    /// for bit: every a with |a| < π returned as it is, π and −π (both to π, by hand: π mod
    /// 2π = π, −π mod 2π = 2π − π = π exactly), their neighbours an ulp either side, ±0,
    /// ±∞ and NaN (NaN out), and angles from −10π to 10π every 0.001 rad.
    #[test]
    fn normalize_angle_is_the_interval_test_bit_for_bit() {
        use std::f64::consts::{PI, TAU};
        let reference = |a: Real| {
            if a > -PI && a <= PI {
                return a;
            }
            let mut w = a.rem_euclid(TAU);
            if w > PI {
                w -= TAU;
            }
            w
        };
        let mut xs = vec![
            0.0,
            -0.0,
            Real::INFINITY,
            Real::NEG_INFINITY,
            Real::NAN,
            TAU,
        ];
        for a in [PI, -PI, TAU, -TAU, 3.0 * PI] {
            xs.extend([a, a.next_up(), a.next_down()]);
        }
        xs.extend((-31_416..=31_416).map(|i| Real::from(i) * 0.001));
        for a in xs {
            let (got, want) = (normalize_angle(a), reference(a));
            assert!(
                got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                "{a}: {got} against {want}"
            );
        }
        assert_eq!(normalize_angle(PI).to_bits(), PI.to_bits());
        assert_eq!(normalize_angle(-PI).to_bits(), PI.to_bits());
    }

    #[test]
    fn poses_compare_angles_modulo_two_pi() {
        use approx::AbsDiffEq;
        let a = Pose {
            x: 1.0,
            y: 2.0,
            z: 3.0,
            h: std::f64::consts::PI - 1e-12,
            p: 0.0,
            r: 0.0,
        };
        let b = Pose {
            h: -std::f64::consts::PI + 1e-12,
            ..a
        };
        assert!(a.abs_diff_eq(&b, 1e-9));
        assert!(!a.abs_diff_eq(&Pose { x: 1.1, ..a }, 1e-9));
    }

    #[test]
    fn piecewise_cubic_picks_the_last_record_started() {
        // Records at 0 (v = 1 + ds) and 10 (v = 5 + 2·ds²): at x = 12, ds = 2 → 5 + 8 = 13,
        // dv = 4·ds = 8; at x = 9 the first record gives 10, slope 1.
        let r = [
            Cubic {
                start: 0.0,
                a: 1.0,
                b: 1.0,
                c: 0.0,
                d: 0.0,
            },
            Cubic {
                start: 10.0,
                a: 5.0,
                b: 0.0,
                c: 2.0,
                d: 0.0,
            },
        ];
        let (v, dv) = eval_piecewise(&r, 12.0);
        assert!((v - 13.0).abs() < 1e-12 && (dv - 8.0).abs() < 1e-12);
        let (v, dv) = eval_piecewise(&r, 9.0);
        assert!((v - 10.0).abs() < 1e-12 && (dv - 1.0).abs() < 1e-12);
        assert_eq!(eval_piecewise(&[], 3.0), (0.0, 0.0));
    }
}
