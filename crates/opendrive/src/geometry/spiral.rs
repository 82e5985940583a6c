//! `<spiral curvStart curvEnd>` (OpenDRIVE 1.8 §9.4): a clothoid, curvature linear in arc
//! length, including spirals that start at non-zero curvature and the degenerate
//! `curvStart == curvEnd` (an arc, or a line when both are 0).
//!
//! With κ(σ) = κ₀ + c·σ and c = (κ₁ − κ₀)/length, the tangent angle is θ(σ) = κ₀σ + cσ²/2 and
//! the point is (∫cos θ, ∫sin θ) from 0 to ds: the Fresnel integrals, shifted. The shift
//! (σ₀ = κ₀/c) makes the closed Fresnel form lose digits when c is small, so the integrals are
//! evaluated directly by composite 8-point Gauss–Legendre quadrature (see `quadrature`), on
//! panels over which θ changes by at most 0.5 rad: error at f64 round-off (< 1e-12 m for
//! any spiral in the corpus; checked against tabulated Fresnel values in the tests).

use super::quadrature::gauss8_pair;
use super::{arc, LocalPoint};

/// Largest change of the tangent angle on one quadrature panel (rad).
const MAX_PHASE_PER_PANEL: f64 = 0.5;
/// Upper bound on panels, reached only by absurd curvatures (> 5000 rad of turning).
const MAX_PANELS: usize = 10_000;

/// `<spiral>`: curvature from `curv_start` to `curv_end` over the geometry's length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spiral {
    /// `curvStart` (1/m).
    pub curv_start: f64,
    /// `curvEnd` (1/m).
    pub curv_end: f64,
    /// Curvature rate c = (curvEnd − curvStart)/length (1/m²).
    pub(crate) rate: f64,
}

impl Spiral {
    /// A spiral of `length` metres (length > 0, checked by the parser).
    pub fn new(curv_start: f64, curv_end: f64, length: f64) -> Self {
        Self {
            curv_start,
            curv_end,
            rate: (curv_end - curv_start) / length,
        }
    }

    /// Point at arc length `ds` from the spiral's start.
    pub(crate) fn eval(&self, ds: f64) -> LocalPoint {
        let (k0, c) = (self.curv_start, self.rate);
        if c == 0.0 {
            return arc::eval_constant_curvature(k0, ds);
        }
        let k_end = k0 + c * ds;
        // Bound on |θ'| over [0, ds]: the curvature is linear, so its extremes are at the ends.
        let max_k = k0.abs().max(k_end.abs());
        let panels =
            ((max_k * ds.abs() / MAX_PHASE_PER_PANEL).ceil() as usize).clamp(1, MAX_PANELS);
        let (u, v) = gauss8_pair(0.0, ds, panels, |s| {
            let th = s * (k0 + 0.5 * c * s);
            let (sn, cs) = th.sin_cos();
            (cs, sn)
        });
        LocalPoint {
            u,
            v,
            hdg: ds * (k0 + 0.5 * c * ds),
            curvature: k_end,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    // Fresnel integrals C(x) = ∫₀ˣ cos(πτ²/2) dτ, S(x) likewise with sin (Abramowitz &
    // Stegun, table 7.7): C(1) = 0.7798934003768228, S(1) = 0.4382591473903548,
    // C(2) = 0.4882534060753408, S(2) = 0.3434156783636982.
    const C1: f64 = 0.779_893_400_376_822_8;
    const S1: f64 = 0.438_259_147_390_354_8;
    const C2: f64 = 0.488_253_406_075_340_8;
    const S2: f64 = 0.343_415_678_363_698_2;

    #[test]
    fn clothoid_from_zero_curvature_matches_fresnel() {
        // κ(σ) = π·σ over length 1 → θ = πσ²/2, so the end point is (C(1), S(1)).
        let p = Spiral::new(0.0, PI, 1.0).eval(1.0);
        assert!(
            (p.u - C1).abs() < 1e-14 && (p.v - S1).abs() < 1e-14,
            "{p:?}"
        );
        assert!((p.hdg - PI / 2.0).abs() < 1e-15);
        assert!((p.curvature - PI).abs() < 1e-15);
    }

    #[test]
    fn clothoid_from_nonzero_curvature_matches_shifted_fresnel() {
        // κ from π to 2π over length 1 is the piece σ ∈ [1, 2] of the clothoid above. Its end
        // point, in the frame of its start (rotated by θ(1) = π/2), is
        // R(−π/2)·(C(2) − C(1), S(2) − S(1)) = (S(2) − S(1), −(C(2) − C(1))).
        let p = Spiral::new(PI, 2.0 * PI, 1.0).eval(1.0);
        assert!((p.u - (S2 - S1)).abs() < 1e-14, "{p:?}");
        assert!((p.v + (C2 - C1)).abs() < 1e-14, "{p:?}");
        // θ(1) = π·1 + π/2·1² = 3π/2.
        assert!((p.hdg - 1.5 * PI).abs() < 1e-14);
    }

    #[test]
    fn degenerate_spiral_is_an_arc() {
        // curvStart == curvEnd == 0.02: a circle of radius 50; after 50·π/2 m, (50, 50).
        let p = Spiral::new(0.02, 0.02, 100.0).eval(25.0 * PI);
        assert!(
            (p.u - 50.0).abs() < 1e-9 && (p.v - 50.0).abs() < 1e-9,
            "{p:?}"
        );
        // curvStart == curvEnd == 0: a line.
        let p = Spiral::new(0.0, 0.0, 10.0).eval(7.0);
        assert!((p.u - 7.0).abs() < 1e-15 && p.v.abs() < 1e-15);
    }

    #[test]
    fn decreasing_curvature_mirrors_the_fresnel_clothoid() {
        // κ from 0 to −π over length 1 is the mirror image: (C(1), −S(1)).
        let p = Spiral::new(0.0, -PI, 1.0).eval(1.0);
        assert!(
            (p.u - C1).abs() < 1e-14 && (p.v + S1).abs() < 1e-14,
            "{p:?}"
        );
    }
}
