//! Fixed-point decimal formatting of `f64` without allocation: the exact bytes of Rust's
//! `format!("{:.N}", x)` (the correctly rounded decimal of the binary value, ties to even; the
//! sign of negative zero and of negatives that round to zero kept; `NaN`, `inf`, `-inf`), for
//! the CSV writer's hot loop.
//!
//! Written by hand because the float crates made for speed (`ryu`, `dtoa`) print the shortest
//! round-trip form, not a fixed number of decimals, and the trajectory CSV's layout (3 and 6
//! decimals) is fixed by the files already written: every byte must stay as it was. The value
//! is scaled exactly in 128-bit integers (mantissa · 10^N / 2^k); values of 10^15 and more, and
//! the non-finite ones, go to `core::fmt`, which gives the same bytes more slowly.

use std::io::Write;

/// Values at or above this go to `core::fmt` (their scaled mantissa would not fit the
/// 128-bit arithmetic below for every N ≤ 9).
const FAST_LIMIT: f64 = 1e15;

/// Powers of ten up to 10^9.
const POW10: [u64; 10] = [
    1,
    10,
    100,
    1_000,
    10_000,
    100_000,
    1_000_000,
    10_000_000,
    100_000_000,
    1_000_000_000,
];

/// Appends `x` with `decimals` digits after the point (at most 9) to `out`, byte for byte as
/// `write!(out, "{:.decimals$}", x)` would.
#[inline]
pub fn push_fixed(out: &mut Vec<u8>, x: f64, decimals: usize) {
    let a = x.abs();
    if decimals >= POW10.len() || a.is_nan() || a >= FAST_LIMIT {
        // Not finite, huge, or more decimals than the table: the standard formatter (writing
        // to a Vec cannot fail).
        let _ = write!(out, "{x:.decimals$}");
        return;
    }
    if x.is_sign_negative() {
        out.push(b'-');
    }
    if a == 0.0 {
        // Zero (most of z, pitch and roll on flat roads): "0", the point and the zeros.
        out.extend_from_slice(&ZEROS[..decimals + usize::from(decimals > 0) + 1]);
        return;
    }
    let scale = POW10[decimals];
    let n = scaled_round(a, u128::from(scale));
    // Integer and fraction digits in 64 bits where the value fits (every value below 1.8e13
    // at 6 decimals): 128-bit division is several times slower.
    match u64::try_from(n) {
        Ok(n) => push_number(out, n / scale, n % scale, decimals),
        Err(_) => {
            // n ≥ 2^64 with a < 10^15 needs scale > 10^4: decimals ≥ 5 here.
            let wide = u128::from(scale);
            let mut digits = itoa::Buffer::new();
            out.extend_from_slice(digits.format(n / wide).as_bytes());
            out.push(b'.');
            // Below scale ≤ 10^9: fits in u64.
            let mut frac = [b'0'; 9];
            write_digits(&mut frac[..decimals], (n % wide) as u64);
            out.extend_from_slice(&frac[..decimals]);
        }
    }
}

/// "0.000000000": zero with up to 9 decimals is a prefix of it.
const ZEROS: &[u8; 11] = b"0.000000000";

/// "00", "01", … "99": two digits per table look-up.
const PAIRS: &[u8; 200] = b"0001020304050607080910111213141516171819\
2021222324252627282930313233343536373839\
4041424344454647484950515253545556575859\
6061626364656667686970717273747576777879\
8081828384858687888990919293949596979899";

/// Appends `int`, then (when `decimals` > 0) the point and `frac` as exactly `decimals`
/// digits. The text is put together in a 32-byte block appended whole and cut back to its
/// length: one fixed-size copy instead of a call to `memcpy` per piece.
#[inline]
fn push_number(out: &mut Vec<u8>, int: u64, frac: u64, decimals: usize) {
    // int ≤ 10^15 (a < FAST_LIMIT rounds to at most 10^15): at most 16 digits, and with the
    // point and at most 9 decimals the text fits the block.
    let width = int.checked_ilog10().map_or(1, |l| l as usize + 1);
    let mut block = [b'0'; 32];
    write_digits(&mut block[..width], int);
    let len = if decimals > 0 {
        block[width] = b'.';
        write_digits(&mut block[width + 1..width + 1 + decimals], frac);
        width + 1 + decimals
    } else {
        width
    };
    let start = out.len();
    out.extend_from_slice(&block);
    out.truncate(start + len);
}

/// Writes the low `digits.len()` decimal digits of `v` into `digits`, zeros in front.
#[inline]
fn write_digits(digits: &mut [u8], mut v: u64) {
    let mut end = digits.len();
    while end >= 2 {
        let pair = (v % 100) as usize * 2;
        v /= 100;
        digits[end - 2..end].copy_from_slice(&PAIRS[pair..pair + 2]);
        end -= 2;
    }
    if end == 1 {
        digits[0] = b'0' + (v % 10) as u8;
    }
}

/// round(a · scale) to the nearest integer, ties to even, computed exactly: a = m · 2^e with
/// an integer mantissa m < 2^53; a < 10^15 and scale ≤ 10^9 keep everything below 2^128.
#[inline]
fn scaled_round(a: f64, scale: u128) -> u128 {
    let bits = a.to_bits();
    let exp_bits = ((bits >> 52) & 0x7ff) as i32;
    let frac_bits = bits & ((1u64 << 52) - 1);
    // Subnormals have no implicit bit and the exponent of the smallest normal.
    let (m, e) = if exp_bits == 0 {
        (frac_bits, -1074)
    } else {
        (frac_bits | (1u64 << 52), exp_bits - 1075)
    };
    let num = u128::from(m) * scale;
    if e >= 0 {
        // a < 10^15 < 2^50 with m ≥ 2^52 means e < 0 for normals; an integer mantissa
        // shifted left stays exact.
        return num << e;
    }
    let k = (-e) as u32;
    if k >= 128 {
        // a · scale < 2^53 · 2^30 / 2^128: far below one half.
        return 0;
    }
    let q = num >> k;
    let r = num & ((1u128 << k) - 1);
    let half = 1u128 << (k - 1);
    let up = r > half || (r == half && q & 1 == 1);
    q + u128::from(up)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn fixed(x: f64, d: usize) -> String {
        let mut v = Vec::new();
        push_fixed(&mut v, x, d);
        String::from_utf8(v).unwrap_or_default()
    }

    #[test]
    fn matches_the_standard_formatter_on_ties_signs_and_edges() {
        // Ties of the binary value: 0.0078125 = 1/128 is 7812.5 millionths (even → 7812);
        // 0.0234375 = 3/128 is 23437.5 (odd → 23438); 0.5 and 2.5 at 0 decimals go to 0 and 2;
        // 1.0005 is not a tie (its binary value lies below), -0.0 and -1e-9 keep the sign.
        let cases = [
            0.0078125,
            0.0234375,
            0.5,
            1.5,
            2.5,
            1.0005,
            -0.0,
            0.0,
            -1e-9,
            1e-300,
            f64::MIN_POSITIVE,
            5e-324,
            123456.789,
            -12.345_678_901_234_5,
            999999.9999995,
            0.9999995,
            9.999_999_999_999e14,
            1e15,
            1e300,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for x in cases {
            for d in [0, 1, 3, 6, 9, 12] {
                assert_eq!(fixed(x, d), format!("{x:.d$}"), "{x:e} at {d} decimals");
            }
        }
        assert_eq!(fixed(0.0078125, 6), "0.007812");
        assert_eq!(fixed(0.0234375, 6), "0.023438");
        assert_eq!(fixed(-1e-9, 6), "-0.000000");
    }

    proptest! {
        #[test]
        fn matches_the_standard_formatter_on_any_finite_value(
            bits in any::<u64>(),
            d in 0usize..10,
        ) {
            let x = f64::from_bits(bits);
            prop_assert_eq!(fixed(x, d), format!("{x:.d$}"));
        }

        #[test]
        fn matches_the_standard_formatter_on_simulation_magnitudes(
            x in -1e7f64..1e7,
            d in prop::sample::select(vec![3usize, 6]),
        ) {
            prop_assert_eq!(fixed(x, d), format!("{x:.d$}"));
        }
    }
}
