//! x⁴ with the bits of the platform's `pow(x, 4)`, without calling it in 57 cases of 64:
//! the IDM's free-road term (v/v0)^δ at its default δ = 4 ([`super::idm`]), which a `mobil`
//! step evaluates up to four times (issue 31: `pow` was 14 % of the samples of the 1,000
//! `mobil` vehicles, 10 points of it the changer's own term, which is also its command).
//!
//! **Why by hand.** No crate computes a power with a given libm's bits, and x·x·x·x is not
//! `pow`'s result bit for bit (three roundings, up to 1.5 ulp off the exact x⁴, where `pow`
//! is within 0.54 ulp). The power is worked out in integers instead: x = m·2^e with a 53-bit
//! m, so x⁴ = m⁴·2^(4e), and m⁴'s top 64 bits, from two 64 × 64 → 128-bit products, are
//! within 7/256 of an ulp below it (`exact`); the 212 bits of m⁴ exactly took four products
//! and the 128-bit sums of their parts.
//!
//! **Why the same bits.** glibc's `pow` (since 2.28; musl has the same code, from Arm's
//! optimized-routines) documents a worst-case error of 0.54 ulp ("Worst-case error: 0.54 ULP",
//! `sysdeps/ieee754/dbl-64/e_pow.c`); earlier glibc's `pow` was correctly rounded (0.5 ulp).
//! Let t = x⁴ exactly and r the double nearest it, t at d ulp from r (d ≤ ½): the other double
//! next to t is 1 − d ulp away, so when d < 0.46 the only double within 0.54 ulp of t is r,
//! and `pow` returns r. The fraction g of t's significand below its 53 bits tells d, and its
//! estimate q/64 from below (g in [q/64, q/64 + 7/256)) tells enough of g: for q ≤ 27,
//! g < 115/256 < 0.46 (round down, d = g); for q ≥ 35, g ≥ 35/64 (round up, d ≤ 29/64 <
//! 0.46), and r is returned; in between (7 cases in 64) `pow` is called. So is it where r is a
//! power of two (the ulp below it is half the ulp above, and the argument above needs one ulp on both
//! sides), for x outside [2^−255, 2^256) (t or r not a normal double), for zero, negatives,
//! infinities and NaN. The shortcut is compiled on Linux only, where the libm is glibc or
//! musl; elsewhere [`fourth_power`] is `powf(4.0)`. Tests: the shortcut against `powf` on 24
//! million x, the midpoint and power-of-two cases and the edges of the range; and against
//! x⁴'s exact 212 bits (whatever the libm: the double it returns is the nearest, at d < 0.46
//! ulp, on 6 million x and around every q's edges).

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
///
/// x⁴ is known here to 1/64 of an ulp from below, from two 64 × 64-bit products, not to the
/// last bit: with x = m·2^(e − 1075), m in [2^52, 2^53), m² = a·2^42 + ρ (a the top 64 bits,
/// 0 ≤ ρ < 2^42) and a² = p·2^64 + p₀, T = m⁴/2^84 = a² + 2aρ/2^42 + ρ²/2^84 lies in
/// [p·2^64, p·2^64 + 3·2^64) (p₀ < 2^64, 2aρ/2^42 + ρ²/2^84 < 2a + 1 ≤ 2^65). p is in [2^60,
/// 2^64), its top 53 bits the significand s′ and its next six the 64ths q of the fraction
/// below it; the ulp is 2^(64 + sh) with sh = 8..=11 the bits below s′, so T's fraction g
/// above s′ (T = (s′ + g)·ulp) lies in [q/64, q/64 + 1/64 + 3/256) = [q/64, q/64 + 7/256).
/// For q ≤ 27, g < 115/256 < 0.46 and s′ is the nearest double (at d = g ulp); for q ≥ 35,
/// g ≥ 35/64, so s′ + 1 is the nearest (d = 1 − g ≤ 29/64 < 0.46 below 1, d = g − 1 < 7/256
/// from 1 on). In between (7 cases in 64) `pow` is asked.
#[inline]
fn exact(x: Real) -> Option<Real> {
    const FRACTION: u64 = (1 << 52) - 1;
    let bits = x.to_bits();
    // The biased exponent, with the sign bit above it: a negative x is out of range.
    let e = bits >> 52;
    if !(1023 - 255..=1023 + 255).contains(&e) {
        return None;
    }
    // x = m·2^(e − 1075), m in [2^52, 2^53); m² in [2^104, 2^106), a in [2^62, 2^64).
    let m = (bits & FRACTION) | (1 << 52);
    let a = ((u128::from(m) * u128::from(m)) >> 42) as u64;
    let p = ((u128::from(a) * u128::from(a)) >> 64) as u64;
    // p in [2^60, 2^64): its leading bit is bit 60..=63, the significand the 53 bits from
    // there, `sh` the bits below them.
    let sh = 11 - p.leading_zeros();
    let significand = p >> sh;
    let q = (p >> (sh - 6)) & 63;
    if (28..=34).contains(&q) {
        return None;
    }
    let r = significand + u64::from(q >= 35);
    // r is in [2^52, 2^53]: a power of two where its fraction bits are all 0.
    let fraction = r & FRACTION;
    if fraction == 0 {
        return None;
    }
    // x⁴ = r·2^(64 + sh + 84 + 4(e − 1075)): a biased exponent of 4e + sh − 3077, in
    // 3..=2046 for e in range.
    let biased = 4 * e + u64::from(sh) - 3077;
    Some(Real::from_bits((biased << 52) | fraction))
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
    /// and the shortcut (not `pow`) answers about 57 in 64 of those in range (`pow` is asked
    /// for q in 28..=34 of the 64ths, 7 of them, where the fraction is spread evenly).
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
        // 7/64 to the fallback, within a few thousandths.
        let share = Real::from(shortcut) / Real::from(in_range);
        assert!(
            (share - 57.0 / 64.0).abs() < 0.005,
            "{shortcut} of {in_range}"
        );
    }

    /// x⁴ from m⁴'s 212 bits exactly (three products and their 128-bit sums, the computation
    /// before the 64-bit estimate): the biased exponent, the 53-bit significand of x⁴
    /// truncated, the fraction below it as 64 bits (truncated) and whether anything is left
    /// below those. For x in range.
    fn exact_parts(x: Real) -> (u64, u64, u64, bool) {
        let bits = x.to_bits();
        let e = bits >> 52;
        let m = (bits & ((1 << 52) - 1)) | (1 << 52);
        let m2 = u128::from(m) * u128::from(m);
        let (h, l) = ((m2 >> 64) as u64, m2 as u64);
        let low = u128::from(l) * u128::from(l);
        let mid = (u128::from(h) * u128::from(l)) << 1;
        let (low, carry) = low.overflowing_add(mid << 64);
        let top = u128::from(h) * u128::from(h) + (mid >> 64) + u128::from(carry);
        // m⁴ = top·2^128 + low, top's leading bit 80..=83.
        let shift = 127 - top.leading_zeros() - 52;
        let significand = (top >> shift) as u64;
        let above = (top as u64) & ((1 << shift) - 1);
        let fraction = (above << (64 - shift)) | (low >> (64 + shift)) as u64;
        let rest = low & ((1u128 << (64 + shift)) - 1) != 0;
        (4 * e + u64::from(shift) - 3097, significand, fraction, rest)
    }

    /// Whatever the libm: where the shortcut answers, its answer is the double nearest the
    /// exact x⁴ (from [`exact_parts`]) and x⁴ lies less than 0.46 ulp from it, the bound the
    /// module doc's argument needs; it leaves to `pow` only x out of range, powers of two and
    /// fractions in the 64ths 28..=34 widened by the estimate's 7/256 (so in [28/64,
    /// 143/256)). On 6 million x: speed ratios in [0, 1.5), doubles of the range's every
    /// exponent, and x = 1 + k·2^−39 (fractions in every sixteenth, midpoints included).
    #[test]
    fn the_shortcut_is_the_nearest_double_to_the_exact_power() {
        let mut next = stream(0xD1B5_4A32_D192_ED03);
        let (mut asked, mut in_range) = (0u32, 0u32);
        for i in 0..6_000_000u64 {
            let r = next();
            let x = match i % 3 {
                0 => (r >> 11) as Real / (1u64 << 53) as Real * 1.5,
                1 => {
                    Real::from_bits(((1023 - 255 + (r >> 55) % 511) << 52) | (r & ((1 << 52) - 1)))
                }
                _ => Real::from_bits((1.0 as Real).to_bits() + ((i / 3) << 13)),
            };
            if !(1023 - 255..=1023 + 255).contains(&(x.to_bits() >> 52)) {
                continue;
            }
            in_range += 1;
            let (biased, significand, fraction, rest) = exact_parts(x);
            let g = fraction as Real / 2.0_f64.powi(64);
            let Some(y) = exact(x) else {
                asked += 1;
                let power_of_two = (significand == 1 << 52 && g < 0.5)
                    || (significand == (1 << 53) - 1 && g > 0.5);
                assert!(
                    power_of_two || (28.0 / 64.0..143.0 / 256.0).contains(&g),
                    "x = {x:e}: g = {g}"
                );
                continue;
            };
            let half = 1u64 << 63;
            assert!(fraction != half || rest, "x = {x:e}: a tie answered");
            let up = fraction > half || (fraction == half && rest);
            let nearest = (biased << 52) + (significand & ((1 << 52) - 1)) + u64::from(up);
            let d = if up { 1.0 - g } else { g };
            assert_eq!(y.to_bits(), nearest, "x = {x:e}");
            assert!(d < 0.46, "x = {x:e}: d = {d}");
        }
        // 7/64 of the fractions asked, within a few thousandths.
        let share = Real::from(asked) / Real::from(in_range);
        assert!((share - 7.0 / 64.0).abs() < 0.005, "{asked} of {in_range}");
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
