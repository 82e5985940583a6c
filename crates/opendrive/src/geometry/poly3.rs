//! `<poly3 a b c d>` (OpenDRIVE 1.8 §9.7, deprecated but still read): a cubic v(u) in the
//! geometry's local u/v frame, traversed by arc length.
//!
//! s is arc length, so u(s) inverts s(u) = ∫₀ᵘ √(1 + v′(τ)²) dτ exactly: the integral is
//! tabulated once per geometry at panel boundaries (8-point Gauss–Legendre per panel), and
//! each query runs Newton's method inside its panel (derivative ds/du = √(1 + v′²)) to
//! [`SOLVER_TOLERANCE`](crate::math::SOLVER_TOLERANCE). No chord stepping (esmini's chord
//! stepping is off by up to 2.6 cm on `poly3_road.xodr`).

use super::quadrature::gauss8;
use super::LocalPoint;
use crate::math::SOLVER_TOLERANCE;

/// Newton iterations allowed per query; convergence is quadratic from the panel start.
const MAX_NEWTON: usize = 30;

/// `<poly3>`: v(u) = a + b·u + c·u² + d·u³.
#[derive(Debug, Clone, PartialEq)]
pub struct Poly3 {
    /// `a` (m).
    pub a: f64,
    /// `b`.
    pub b: f64,
    /// `c` (1/m).
    pub c: f64,
    /// `d` (1/m²).
    pub d: f64,
    /// Panel width in u (m).
    du: f64,
    /// Arc length from u = 0 to each panel boundary k·du.
    table: Vec<f64>,
}

impl Poly3 {
    /// Builds the arc-length table for a geometry of `length` metres (> 0, finite).
    pub fn new(a: f64, b: f64, c: f64, d: f64, length: f64) -> Self {
        // s(u) ≥ u, so u never exceeds the length: panels over [0, length] suffice.
        let panels = ((length / 2.0).ceil() as usize).clamp(16, 4096);
        let du = length / panels as f64;
        let mut me = Self {
            a,
            b,
            c,
            d,
            du,
            table: Vec::with_capacity(panels + 1),
        };
        let mut acc = 0.0;
        me.table.push(0.0);
        for k in 0..panels {
            let lo = du * k as f64;
            acc += gauss8(lo, lo + du, |u| me.speed(u));
            me.table.push(acc);
        }
        me
    }

    #[inline]
    fn slope(&self, u: f64) -> f64 {
        self.b + u * (2.0 * self.c + 3.0 * self.d * u)
    }

    #[inline]
    fn speed(&self, u: f64) -> f64 {
        let m = self.slope(u);
        (1.0 + m * m).sqrt()
    }

    /// The u at arc length `s` from the start.
    pub fn u_at(&self, s: f64) -> f64 {
        // Invariant: `table` has at least 17 entries (≥ 16 panels).
        let last = self.table.len() - 1;
        let i = self
            .table
            .partition_point(|&x| x <= s)
            .saturating_sub(1)
            .min(last - 1);
        let u0 = self.du * i as f64;
        let s0 = self.table[i];
        // Start from linear interpolation of s(u) inside the panel: two or three Newton steps.
        let s1 = self.table[i + 1];
        let mut u = if s1 > s0 && s <= s1 {
            u0 + (s - s0) / (s1 - s0) * self.du
        } else {
            u0 + (s - s0) / self.speed(u0)
        };
        for _ in 0..MAX_NEWTON {
            let f = s0 + gauss8(u0, u, |x| self.speed(x)) - s;
            let step = f / self.speed(u);
            u -= step;
            if step.abs() < SOLVER_TOLERANCE {
                break;
            }
        }
        u
    }

    /// Point at arc length `ds` from the start.
    pub(crate) fn eval(&self, ds: f64) -> LocalPoint {
        let u = self.u_at(ds);
        let v = self.a + u * (self.b + u * (self.c + u * self.d));
        let m = self.slope(u);
        let m2 = 2.0 * self.c + 6.0 * self.d * u;
        let curvature = m2 / (1.0 + m * m).powf(1.5);
        LocalPoint {
            u,
            v,
            hdg: m.atan(),
            curvature,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parabola_arc_length_is_inverted_exactly() {
        // v = 0.1·u². Arc length to u: s(u) = u·√(1 + 4k²u²)/2 + asinh(2ku)/(4k), k = 0.1.
        // At u = 10: s = 5·√5 + asinh(2)/0.4 ≈ 14.7894286; the point is (10, 10), heading
        // atan(v′(10)) = atan(2), curvature 2k/(1 + 4)^1.5 = 0.2/11.1803.
        let k: f64 = 0.1;
        let s = 10.0 * (1.0 + 4.0 * k * k * 100.0_f64).sqrt() / 2.0
            + (2.0 * k * 10.0).asinh() / (4.0 * k);
        let g = Poly3::new(0.0, 0.0, k, 0.0, 20.0);
        let p = g.eval(s);
        assert!(
            (p.u - 10.0).abs() < 1e-10 && (p.v - 10.0).abs() < 1e-9,
            "{p:?}"
        );
        assert!((p.hdg - 2.0_f64.atan()).abs() < 1e-11);
        assert!((p.curvature - 0.2 / 5.0_f64.powf(1.5)).abs() < 1e-11);
    }

    #[test]
    fn offset_and_slope_coefficients_shift_and_tilt_the_start() {
        // v = 1 + 0.5·u: a straight line starting at (0, 1) with slope 0.5; after arc length
        // s, u = s/√1.25 and v = 1 + 0.5·u.
        let g = Poly3::new(1.0, 0.5, 0.0, 0.0, 30.0);
        let p = g.eval(25.0);
        let u = 25.0 / 1.25_f64.sqrt();
        assert!(
            (p.u - u).abs() < 1e-10 && (p.v - (1.0 + 0.5 * u)).abs() < 1e-10,
            "{p:?}"
        );
        assert!((p.hdg - 0.5_f64.atan()).abs() < 1e-14 && p.curvature.abs() < 1e-15);
    }
}
