//! x⁴ with the bits of the platform's `pow(x, 4)`, without calling it in seven cases of eight:
//! the IDM's free-road term (v/v0)^δ at its default δ = 4 ([`super::idm`]), which a `mobil`
//! step evaluates up to four times (issue 31: `pow` was 14 % of the samples of the 1,000
//! `mobil` vehicles, 10 points of it the changer's own term, which is also its command).
//!
//! **Why by hand.** No crate computes a power with a given libm's bits, and x·x·x·x is not
//! `pow`'s result bit for bit (three roundings, up to 1.5 ulp off the exact x⁴, where `pow`
//! is within 0.54 ulp). The power is worked out exactly in integers instead: x = m·2^e with a
//! 53-bit m, so x⁴ = m⁴·2^(4e) and m⁴ (212 bits) is three 64 × 64 → 128-bit products.
//!
//! **Why the same bits.** glibc's `pow` (since 2.28; musl has the same code, from Arm's
//! optimized-routines) documents a worst-case error of 0.54 ulp ("Worst-case error: 0.54 ULP",
//! `sysdeps/ieee754/dbl-64/e_pow.c`); earlier glibc's `pow` was correctly rounded (0.5 ulp).
//! Let t = x⁴ exactly and r the double nearest it, t at d ulp from r (d ≤ ½): the other double
//! next to t is 1 − d ulp away, so when d < 0.46 the only double within 0.54 ulp of t is r,
//! and `pow` returns r. The fraction of t's significand below its 53 bits tells d: outside
//! [7/16, 9/16) it is below 7/16 (round down) or above 9/16 (round up), d ≤ 7/16 < 0.46, and r
//! is returned; inside (one case in eight) `pow` is called. So is it where r is a power of two
//! (the ulp below it is half the ulp above, and the argument above needs one ulp on both
//! sides), for x outside [2^−255, 2^256) (t or r not a normal double), for zero, negatives,
//! infinities and NaN. The shortcut is compiled on Linux only, where the libm is glibc or
//! musl; elsewhere [`fourth_power`] is `powf(4.0)`. Test: the shortcut against `powf` on 24
//! million x, the midpoint and power-of-two cases and the edges of the range.

use opendrive::Real;

/// x⁴ as `x.powf(4.0)` gives it (module doc).
#[inline]
pub(crate) fn fourth_power(x: Real) -> Real {
    if cfg!(target_os = "linux") {
        exact(x).unwrap_or_else(|| x.powf(4.0))
    } else {
        x.powf(4.0)
    }
}

/// The double nearest x⁴ where it is the only one within 0.54 ulp of x⁴ and x is in range
/// (module doc); `None` elsewhere.
#[inline]
fn exact(x: Real) -> Option<Real> {
    const FRACTION: u64 = (1 << 52) - 1;
    let bits = x.to_bits();
    // The biased exponent, with the sign bit above it: a negative x is out of range.
    let e = bits >> 52;
    if !(1023 - 255..=1023 + 255).contains(&e) {
        return None;
    }
    // x = m·2^(e − 1075), m in [2^52, 2^53).
    let m = (bits & FRACTION) | (1 << 52);
    let m2 = u128::from(m) * u128::from(m); // < 2^106
                                            // m² = h·2^64 + l, h < 2^42; m⁴ = h²·2^128 + 2hl·2^64 + l²: its top 128 bits (bits 128
                                            // and up), exactly.
    let (h, l) = ((m2 >> 64) as u64, m2 as u64);
    let low = u128::from(l) * u128::from(l);
    let mid = (u128::from(h) * u128::from(l)) << 1; // < 2^107
    let (_, carry) = low.overflowing_add(mid << 64);
    let top = u128::from(h) * u128::from(h) + (mid >> 64) + u128::from(carry);
    // m⁴ is in [2^208, 2^212): top's leading bit is bit k of 80..=83; its 53 bits from there
    // are t's significand, the `shift` bits below the start of the fraction d measures.
    let k = 127 - top.leading_zeros();
    let shift = k - 52; // 28..=31
    let significand = (top >> shift) as u64;
    let sixteenths = ((top as u64) & ((1 << shift) - 1)) >> (shift - 4);
    if sixteenths == 7 || sixteenths == 8 {
        return None;
    }
    let r = significand + u64::from(sixteenths > 8);
    if r == 1 << 52 || r == 1 << 53 {
        return None; // a power of two
    }
    // t = significand·2^(shift + 128 + 4(e − 1075)): a biased exponent of
    // 4e + shift − 3097, in 3..=2046 for e in range.
    let biased = 4 * e + u64::from(shift) - 3097;
    Some(Real::from_bits((biased << 52) | (r & FRACTION)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `fourth_power` and `powf(4.0)` as bits (NaN as one pattern class).
    fn same(x: Real) -> bool {
        let (a, b) = (fourth_power(x), x.powf(4.0));
        a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
    }

    /// A xorshift stream (no dependency for a test's numbers).
    fn stream(mut s: u64) -> impl FnMut() -> u64 {
        move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        }
    }

    /// 8 million speed ratios in [0, 1.5) (the IDM's v/v0), 8 million doubles of every
    /// exponent, 8 million in [2^−256, 2^257) around the range's edges: `powf`'s bits each,
    /// and the shortcut (not `pow`) answers about seven in eight of those in range.
    #[test]
    fn the_fourth_power_is_pows_bit_for_bit() {
        let mut next = stream(0x9E37_79B9_7F4A_7C15);
        let (mut in_range, mut shortcut) = (0u32, 0u32);
        for i in 0..24_000_000u32 {
            let r = next();
            let x = match i % 3 {
                0 => (r >> 11) as Real / (1u64 << 53) as Real * 1.5,
                1 => Real::from_bits(r),
                _ => {
                    Real::from_bits(((1023 - 256 + (r >> 55) % 513) << 52) | (r & ((1 << 52) - 1)))
                }
            };
            assert!(same(x), "x = {x:e} ({:#x})", x.to_bits());
            if x.to_bits() >> 52 >= 1023 - 255 && x.to_bits() >> 52 <= 1023 + 255 {
                in_range += 1;
                shortcut += u32::from(exact(x).is_some());
            }
        }
        // 1/8 to the fallback, within a few hundredths.
        let share = Real::from(shortcut) / Real::from(in_range);
        assert!((share - 0.875).abs() < 0.01, "{shortcut} of {in_range}");
    }

    /// The cases the shortcut leaves to `pow` and the edges: zeros, negatives, infinities,
    /// NaN, subnormals, powers of two and their neighbours, the range's ends, and x whose x⁴
    /// falls in every sixteenth of the ulp, midpoints included (x = 1 + k·2^−39 for k below
    /// 2^20: x⁴ = 1 + 4k·2^−39 + 6k²·2^−78 + …, whose fraction of the ulp 2^−52 is
    /// 6k²·2^−26 mod 1 plus less than 1/8).
    #[test]
    fn the_fourth_power_is_pows_at_the_edges() {
        let mut xs = vec![
            0.0,
            -0.0,
            -1.0,
            -0.5,
            Real::INFINITY,
            Real::NEG_INFINITY,
            Real::NAN,
            Real::MIN_POSITIVE,
            Real::from_bits(1),
            Real::MAX,
            1.0,
        ];
        for p in -300..300 {
            let two = (2.0 as Real).powi(p);
            xs.extend([two, two.next_up(), two.next_down()]);
        }
        for k in 0..(1u64 << 20) {
            xs.push(Real::from_bits((1.0 as Real).to_bits() + (k << 13)));
            xs.push(Real::from_bits((0.75 as Real).to_bits() + (k << 13)));
        }
        for x in xs {
            assert!(same(x), "x = {x:e} ({:#x})", x.to_bits());
        }
        // By hand: 1.5⁴ = 5.0625 and 0.75⁴ = 0.31640625, exact.
        let bits = |x: Option<Real>| x.map(Real::to_bits);
        assert_eq!(bits(exact(1.5)), bits(Some(5.0625)));
        assert_eq!(bits(exact(0.75)), bits(Some(0.316_406_25)));
    }
}
