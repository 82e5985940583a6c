//! Bounds of `n = trunc(x)`, the whole part of `x` rounded toward zero: how a `float` converts to
//! `int` or `uint` (`x.as(int)`, ASAM OpenSCENARIO DSL 2.1 §7.4.2.6; the rounding is oscsim's
//! choice, docs/dsl.md). `trunc` is monotone, so the bounds of one side give the other's:
//!
//! - image: `x ∈ [a, b]` gives `n ∈ [trunc(a), trunc(b)]`, one less at an open whole end away
//!   from zero (`x < 3` gives `n ≤ 2`; `x > -3` gives `n ≥ -2`);
//! - preimage: `n ≥ L` holds exactly for `x ≥ L` when `L > 0` and for `x > L − 1` when `L ≤ 0`;
//!   `n ≤ H` exactly for `x < H + 1` when `H ≥ 0` and for `x ≤ H` when `H < 0`.

use super::domain::Interval;

/// The bounds of `trunc(x)` over `x`'s interval (`None`: unbounded on that side).
pub fn image(x: &Interval) -> (Option<f64>, Option<f64>) {
    let lo = x.lo.value.is_finite().then(|| {
        let t = x.lo.value.trunc();
        let whole = x.lo.value.fract() == 0.0;
        if x.lo.open && whole && x.lo.value < 0.0 {
            t + 1.0
        } else {
            t
        }
    });
    let hi = x.hi.value.is_finite().then(|| {
        let t = x.hi.value.trunc();
        let whole = x.hi.value.fract() == 0.0;
        if x.hi.open && whole && x.hi.value > 0.0 {
            t - 1.0
        } else {
            t
        }
    });
    (lo, hi)
}

/// The bounds `x` must keep for `trunc(x)` to lie in `n`'s interval: `((lo, open), (hi, open))`,
/// infinite where `n` is unbounded.
pub fn preimage(n: &Interval) -> ((f64, bool), (f64, bool)) {
    let (l, h) = (n.lo.value, n.hi.value);
    let lo = if !l.is_finite() {
        (f64::NEG_INFINITY, false)
    } else if l > 0.0 {
        (l, false)
    } else {
        (l - 1.0, true)
    };
    let hi = if !h.is_finite() {
        (f64::INFINITY, false)
    } else if h >= 0.0 {
        (h + 1.0, true)
    } else {
        (h, false)
    };
    (lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn interval(lo: f64, lo_open: bool, hi: f64, hi_open: bool, integer: bool) -> Interval {
        let mut i = Interval::new(integer, None, None);
        i.raise(lo, lo_open, vec![]);
        i.lower(hi, hi_open, vec![]);
        i
    }

    #[test]
    fn image_rounds_toward_zero_and_steps_over_open_whole_ends() {
        // trunc over [2.5, 7.9] is [2, 7]; over [-7.9, -2.5] it is [-7, -2].
        assert_eq!(
            image(&interval(2.5, false, 7.9, false, false)),
            (Some(2.0), Some(7.0))
        );
        assert_eq!(
            image(&interval(-7.9, false, -2.5, false, false)),
            (Some(-7.0), Some(-2.0))
        );
        // x in (-3, 3): trunc reaches neither -3 nor 3.
        assert_eq!(
            image(&interval(-3.0, true, 3.0, true, false)),
            (Some(-2.0), Some(2.0))
        );
        // x in [-3, 3] closed: both ends are reached.
        assert_eq!(
            image(&interval(-3.0, false, 3.0, false, false)),
            (Some(-3.0), Some(3.0))
        );
    }

    #[test]
    fn preimage_is_exact_on_each_side_of_zero() {
        // n = 2: x in [2, 3); n = -2: x in (-3, -2]; n = 0: x in (-1, 1).
        assert_eq!(
            preimage(&interval(2.0, false, 2.0, false, true)),
            ((2.0, false), (3.0, true))
        );
        assert_eq!(
            preimage(&interval(-2.0, false, -2.0, false, true)),
            ((-3.0, true), (-2.0, false))
        );
        assert_eq!(
            preimage(&interval(0.0, false, 0.0, false, true)),
            ((-1.0, true), (1.0, true))
        );
    }
}
