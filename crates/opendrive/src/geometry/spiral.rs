//! `<spiral curvStart curvEnd>` (OpenDRIVE 1.8 §9.4): a clothoid, curvature linear in arc
//! length, including spirals that start at non-zero curvature and the degenerate
//! `curvStart == curvEnd` (an arc, or a line when both are 0).
//!
//! With κ(σ) = κ₀ + c·σ and c = (κ₁ − κ₀)/length, the tangent angle is θ(σ) = κ₀σ + cσ²/2 and
//! the point is (∫cos θ, ∫sin θ) from 0 to ds: the Fresnel integrals, shifted. The shift
//! (σ₀ = κ₀/c) makes the closed Fresnel form lose digits when c is small, so the integrals are
//! evaluated directly by composite 8-point Gauss–Legendre quadrature (see `quadrature`), on
//! panels over which θ changes by at most 0.5 rad, tabulated once per spiral (a Fresnel
//! function from a special-functions crate would have the same cancellation problem): error at f64 round-off (< 1e-12 m for
//! any spiral in the corpus; checked against tabulated Fresnel values in the tests).

use super::quadrature::gauss8_pair;
use super::{arc, LocalPoint};

/// Largest change of the tangent angle on one quadrature panel (rad).
const MAX_PHASE_PER_PANEL: f64 = 0.5;
/// Upper bound on panels, reached only by absurd curvatures (> 5000 rad of turning).
const MAX_PANELS: usize = 10_000;

/// `<spiral>`: curvature from `curv_start` to `curv_end` over the geometry's length.
///
/// The integrals are tabulated at construction on a grid of step ≤ 0.5 rad of turning, so a
/// query integrates only one panel (8 nodes) from the grid point below it.
#[derive(Debug, Clone, PartialEq)]
pub struct Spiral {
    /// `curvStart` (1/m).
    pub curv_start: f64,
    /// `curvEnd` (1/m).
    pub curv_end: f64,
    /// Curvature rate c = (curvEnd − curvStart)/length (1/m²).
    pub(crate) rate: f64,
    /// Grid step along the spiral (m).
    step: f64,
    /// (u, v) at s = k·step, k = 0, 1, ….
    table: Vec<(f64, f64)>,
}

impl Spiral {
    /// A spiral of `length` metres (length > 0, checked by the parser).
    pub fn new(curv_start: f64, curv_end: f64, length: f64) -> Self {
        let rate = (curv_end - curv_start) / length;
        let max_k = curv_start.abs().max(curv_end.abs());
        let panels = ((max_k * length / MAX_PHASE_PER_PANEL).ceil() as usize).clamp(1, MAX_PANELS);
        let step = length / panels as f64;
        let mut me = Self {
            curv_start,
            curv_end,
            rate,
            step,
            table: Vec::with_capacity(panels + 1),
        };
        let mut acc = (0.0, 0.0);
        me.table.push(acc);
        for k in 0..panels {
            let (du, dv) = me.integrate(step * k as f64, step * (k + 1) as f64);
            acc = (acc.0 + du, acc.1 + dv);
            me.table.push(acc);
        }
        me
    }

    /// (∫cos θ, ∫sin θ) over [a, b], one 8-point panel.
    #[inline]
    fn integrate(&self, a: f64, b: f64) -> (f64, f64) {
        let (k0, c) = (self.curv_start, self.rate);
        gauss8_pair(a, b, 1, |s| {
            let (sn, cs) = (s * (k0 + 0.5 * c * s)).sin_cos();
            (cs, sn)
        })
    }

    /// Point at arc length `ds` from the spiral's start.
    pub(crate) fn eval(&self, ds: f64) -> LocalPoint {
        let (k0, c) = (self.curv_start, self.rate);
        if c == 0.0 {
            return arc::eval_constant_curvature(k0, ds);
        }
        let k = ((ds / self.step).floor().max(0.0) as usize).min(self.table.len() - 1);
        let s0 = self.step * k as f64;
        let (u0, v0) = self.table[k];
        let (du, dv) = self.integrate(s0, ds);
        LocalPoint {
            u: u0 + du,
            v: v0 + dv,
            hdg: ds * (k0 + 0.5 * c * ds),
            curvature: k0 + c * ds,
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
