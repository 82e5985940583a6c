//! `sin_cos` of an angle and `atan2` of a slope where the angle (the slope's rise) is zero,
//! without calling libm (issue 31): a vehicle that follows its lane on a road without lane
//! offset changes has a heading relative to the road of exactly 0 and a lateral slope of
//! exactly 0, and each move and each lane-index entry called `sincos` and `atan2` for them
//! (2.3 % and 1.9 % of the samples of 1,000 `idm` vehicles).
//!
//! **Why the same bits.** ISO C (C99 and later) Annex F, F.10.1.4 and F.10.1.6–7 (IEC 60559
//! floating-point arithmetic): `sin(±0)` returns ±0, `cos(±0)` returns 1, and `atan2(±0, x)`
//! returns ±0 for x > 0, exactly. glibc and musl follow Annex F (and every correctly rounded
//! result is these values: sin 0 = 0, cos 0 = 1 and atan2(0, x > 0) = 0 are exact), so the
//! values returned here are libm's bit for bit, the sign of zero included. Any other input
//! (a NaN, an infinity, a non-zero angle, x ≤ 0 or NaN for `atan2`) calls libm as before.
//! Test: both against libm at ±0 and at the values around them.

use opendrive::Real;

/// `x.sin_cos()`, with (x, 1) where x is ±0 (module doc).
#[inline]
pub(crate) fn sin_cos(x: Real) -> (Real, Real) {
    if x == 0.0 {
        (x, 1.0)
    } else {
        x.sin_cos()
    }
}

/// `y.atan2(x)`, with y where y is ±0 and x > 0 (module doc).
#[inline]
pub(crate) fn atan2(y: Real, x: Real) -> Real {
    if y == 0.0 && x > 0.0 {
        y
    } else {
        y.atan2(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The shortcuts give libm's bits: at ±0 (the shortcut) and at the values next to them,
    /// the smallest subnormals, ordinary angles, the infinities and NaN (libm itself);
    /// `atan2` over denominators ±0, subnormal, ordinary, huge, infinite and NaN.
    #[test]
    fn the_shortcuts_at_zero_give_libms_bits() {
        let tiny = Real::from_bits(1);
        let xs = [
            0.0,
            -0.0,
            tiny,
            -tiny,
            Real::MIN_POSITIVE,
            1e-300,
            -1e-300,
            1e-17,
            0.5,
            -3.0,
            std::f64::consts::PI,
            1e300,
            Real::INFINITY,
            Real::NEG_INFINITY,
            Real::NAN,
        ];
        let bits = |(a, b): (Real, Real)| (a.to_bits(), b.to_bits());
        let mut checked = 0;
        for &x in &xs {
            let libm = (x.sin(), x.cos());
            assert_eq!(bits(sin_cos(x)), bits(libm), "sin_cos({x:e})");
            for &d in &xs {
                assert_eq!(
                    atan2(x, d).to_bits(),
                    x.atan2(d).to_bits(),
                    "atan2({x:e}, {d:e})"
                );
                checked += 1;
            }
        }
        assert_eq!(checked, 225);
        // At ±0 the values Annex F fixes, not only libm's agreement with itself.
        assert_eq!(bits(sin_cos(-0.0)), ((-0.0f64).to_bits(), 1.0f64.to_bits()));
        assert_eq!(atan2(-0.0, 2.0).to_bits(), (-0.0f64).to_bits());
    }
}
