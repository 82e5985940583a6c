//! Composite Gauss–Legendre quadrature, used for the clothoid's Fresnel-type integrals and
//! for poly3 arc lengths.
//!
//! Written by hand: the integrands are smooth (cos/sin of a quadratic phase, √(1 + p(u)²)
//! with p a polynomial), so an 8-point Gauss–Legendre rule on panels short enough that the
//! integrand varies little reaches f64 round-off; no quadrature crate offers a fixed,
//! allocation-free rule with this control, and the code is 40 lines.
//!
//! Accuracy: the 8-point rule is exact for polynomials of degree 15. For cos/sin of a phase
//! that changes by at most Δ over a panel of length h, the error is below
//! h·Δ¹⁶/(2¹⁶·16!) ≈ h·7·10⁻¹⁹ for Δ = 0.5, i.e. at round-off level.

/// Nodes (positive half) of the 8-point Gauss–Legendre rule on [−1, 1].
const NODES: [f64; 4] = [
    0.183_434_642_495_649_8,
    0.525_532_409_916_329,
    0.796_666_477_413_626_7,
    0.960_289_856_497_536_3,
];
/// Weights matching [`NODES`].
const WEIGHTS: [f64; 4] = [
    0.362_683_783_378_362,
    0.313_706_645_877_887_3,
    0.222_381_034_453_374_5,
    0.101_228_536_290_376_3,
];

/// ∫ f over [a, b] with the 8-point rule on one panel.
#[inline]
pub(crate) fn gauss8(a: f64, b: f64, mut f: impl FnMut(f64) -> f64) -> f64 {
    let half = 0.5 * (b - a);
    let mid = 0.5 * (a + b);
    let mut sum = 0.0;
    for (x, w) in NODES.iter().zip(WEIGHTS) {
        sum += w * (f(mid - half * x) + f(mid + half * x));
    }
    sum * half
}

/// ∫ (f, g) over [a, b] (two integrands sharing the nodes) on `panels` equal panels.
#[inline]
pub(crate) fn gauss8_pair(
    a: f64,
    b: f64,
    panels: usize,
    mut f: impl FnMut(f64) -> (f64, f64),
) -> (f64, f64) {
    let n = panels.max(1);
    let h = (b - a) / n as f64;
    let (mut sf, mut sg) = (0.0, 0.0);
    for k in 0..n {
        let lo = a + h * k as f64;
        let mid = lo + 0.5 * h;
        let half = 0.5 * h;
        let (mut pf, mut pg) = (0.0, 0.0);
        for (x, w) in NODES.iter().zip(WEIGHTS) {
            let (f1, g1) = f(mid - half * x);
            let (f2, g2) = f(mid + half * x);
            pf += w * (f1 + f2);
            pg += w * (g1 + g2);
        }
        sf += pf * half;
        sg += pg * half;
    }
    (sf, sg)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_for_degree_15_polynomials() {
        // ∫₀² x¹⁵ dx = 2¹⁶/16 = 4096.
        let v = gauss8(0.0, 2.0, |x| x.powi(15));
        assert!((v - 4096.0).abs() < 1e-9, "{v}");
    }

    #[test]
    fn integrates_cosine_to_round_off() {
        // ∫₀^π cos = 0, ∫₀^π sin = 2 (4 panels of π/4).
        let (c, s) = gauss8_pair(0.0, std::f64::consts::PI, 4, |x| (x.cos(), x.sin()));
        assert!(c.abs() < 1e-14 && (s - 2.0).abs() < 1e-14, "{c} {s}");
    }
}
