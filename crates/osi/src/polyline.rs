//! Sampling a curve of the exact road model into the polylines OSI 3.8 uses for
//! `Lane.Classification.centerline` and `LaneBoundary.boundary_line` (OSI 3.8
//! osi_lane.proto: "the centerline is a polyline… the points shall be placed so that the
//! polyline stays within a small error of the true curve").
//!
//! Written by hand because it is a few lines on top of the opendrive crate's exact
//! evaluation: the interval [s0, s1] is cut into pieces no longer than `max_step`, and a
//! piece is halved while one of its points at 1/4, 1/2 and 3/4 of its s range lies
//! farther than [`CHECK_FACTOR`] · `tolerance` from the chord (at most [`MAX_DEPTH`]
//! times, so a pathological curve cannot make it loop).
//!
//! Why three points and the factor: on a short piece the curve's distance from its
//! chord is, to third order, d(u) = u(1 − u)(α + βu) for u in [0, 1]. For β = 0 (an arc)
//! the maximum is at u = 1/2 and is checked exactly. Over all α, β the true maximum of
//! |d| exceeds the largest of |d(1/4)|, |d(1/2)|, |d(3/4)| by at most a factor 1.09402
//! (found by a dense scan over α : β; the worst case is α = β/4). Checking against
//! 0.914 · tolerance (just under 1/1.09402 = 0.91406) therefore keeps the whole piece
//! within the tolerance for curves that are locally cubic, which lines, arcs, clothoids
//! and (param)poly3 are.

/// Share of the tolerance the three checked points must keep (see the module doc).
pub const CHECK_FACTOR: f64 = 0.914;

/// Limit on the number of halvings of one piece (2¹² pieces of the first cut).
pub const MAX_DEPTH: u32 = 12;

/// How finely to sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sampling {
    /// Longest distance in s between two points (m).
    pub max_step: f64,
    /// Largest allowed distance of a piece's midpoint from its chord (m).
    pub tolerance: f64,
}

impl Default for Sampling {
    /// 10 m steps at most, 1 cm chord error.
    fn default() -> Self {
        Sampling {
            max_step: 10.0,
            tolerance: 0.01,
        }
    }
}

/// A point of the curve with the s it was taken at.
pub type Sample = (f64, [f64; 3]);

/// Points of `curve` on [s0, s1], both ends included, in order of s.
pub fn sample<E>(
    s0: f64,
    s1: f64,
    sampling: &Sampling,
    curve: &mut impl FnMut(f64) -> Result<[f64; 3], E>,
) -> Result<Vec<Sample>, E> {
    let max_step = if sampling.max_step.is_finite() && sampling.max_step > 0.0 {
        sampling.max_step
    } else {
        Sampling::default().max_step
    };
    let length = (s1 - s0).max(0.0);
    // `length / max_step` is finite and ≥ 0 here; the cap keeps a huge road from
    // allocating without bound.
    let pieces = ((length / max_step).ceil() as usize).clamp(1, 100_000);
    let mut out = vec![(s0, curve(s0)?)];
    for i in 0..pieces {
        let a = out[out.len() - 1];
        let sb = if i + 1 == pieces {
            s1
        } else {
            s0 + length * (i + 1) as f64 / pieces as f64
        };
        let b = (sb, curve(sb)?);
        refine(a, b, sampling.tolerance, MAX_DEPTH, curve, &mut out)?;
    }
    Ok(out)
}

/// Appends the points after `a` up to and including `b`, halving while needed.
fn refine<E>(
    a: Sample,
    b: Sample,
    tolerance: f64,
    depth: u32,
    curve: &mut impl FnMut(f64) -> Result<[f64; 3], E>,
    out: &mut Vec<Sample>,
) -> Result<(), E> {
    if depth > 0 {
        let at = |u: f64| a.0 + u * (b.0 - a.0);
        let m = (at(0.5), curve(at(0.5))?);
        let q1 = curve(at(0.25))?;
        let q3 = curve(at(0.75))?;
        let limit = CHECK_FACTOR * tolerance;
        if [m.1, q1, q3]
            .into_iter()
            .any(|p| distance_to_chord(p, a.1, b.1) > limit)
        {
            refine(a, m, tolerance, depth - 1, curve, out)?;
            return refine(m, b, tolerance, depth - 1, curve, out);
        }
    }
    out.push(b);
    Ok(())
}

/// Distance of `p` from the segment a–b.
fn distance_to_chord(p: [f64; 3], a: [f64; 3], b: [f64; 3]) -> f64 {
    let ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let ap = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
    let len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    let u = if len2 > 0.0 {
        ((ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let d = [ap[0] - u * ab[0], ap[1] - u * ab[1], ap[2] - u * ab[2]];
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::convert::Infallible;

    #[test]
    fn straight_line_takes_only_the_step_points() {
        let mut line = |s: f64| Ok::<_, Infallible>([s, 2.0, 0.0]);
        let pts = sample(0.0, 25.0, &Sampling::default(), &mut line).unwrap();
        // 25 m at ≤ 10 m: 3 pieces of 25/3 m, 4 points.
        let s: Vec<f64> = pts.iter().map(|p| p.0).collect();
        assert_eq!(s.len(), 4);
        assert!((s[1] - 25.0 / 3.0).abs() < 1e-12);
        assert_eq!(s[3], 25.0);
    }

    #[test]
    fn arc_meets_the_chord_tolerance() {
        // Circle of radius R = 50 m. A chord over arc length L deviates from the arc by
        // R(1 − cos(L / 2R)) at its middle; every piece must stay within 1 cm, and the
        // pieces must be no shorter than needed: on an arc the midpoint deviates most, so a
        // piece is halved only when longer than L*, where
        // R(1 − cos(L*/2R)) = 2R·sin²(L*/4R) = 0.914 · 0.01, so
        // L* = 4R·asin(sqrt(0.00914 / 2R)) = 200·asin(0.0095603) ≈ 1.9121 m, and halves are
        // ≥ L*/2.
        let r = 50.0;
        let mut arc = |s: f64| Ok::<_, Infallible>([r * (s / r).sin(), r - r * (s / r).cos(), 0.0]);
        let sampling = Sampling::default();
        let pts = sample(0.0, 60.0, &sampling, &mut arc).unwrap();
        let l_star = 4.0 * r * (CHECK_FACTOR * 0.01 / (2.0 * r)).sqrt().asin();
        for w in pts.windows(2) {
            let l = w[1].0 - w[0].0;
            let sag = r * (1.0 - (l / (2.0 * r)).cos());
            assert!(sag <= 0.01 + 1e-12, "piece of {l} m sags {sag} m");
            assert!(
                l >= 0.5 * l_star - 1e-9,
                "piece of {l} m is shorter than needed"
            );
        }
    }

    #[test]
    fn cubic_stays_within_tolerance_everywhere() {
        // y = 1e-3·x³ on [0, 60]: a curve whose deviation from a chord peaks off the
        // middle. Check 200 points inside every piece against the chord.
        let mut cubic = |s: f64| Ok::<_, Infallible>([s, 1e-3 * s * s * s, 0.0]);
        let pts = sample(0.0, 60.0, &Sampling::default(), &mut cubic).unwrap();
        for w in pts.windows(2) {
            for k in 1..200 {
                let s = w[0].0 + (w[1].0 - w[0].0) * f64::from(k) / 200.0;
                let p = [s, 1e-3 * s * s * s, 0.0];
                assert!(distance_to_chord(p, w[0].1, w[1].1) <= 0.01, "at s = {s}");
            }
        }
    }

    #[test]
    fn errors_of_the_curve_come_through() {
        let mut failing = |s: f64| {
            if s > 5.0 {
                Err("off the road")
            } else {
                Ok([s, 0.0, 0.0])
            }
        };
        assert_eq!(
            sample(0.0, 20.0, &Sampling::default(), &mut failing),
            Err("off the road")
        );
    }
}
