//! `<arc curvature>` (OpenDRIVE 1.8 §9.5): a circular arc of constant curvature, in closed form.

use super::LocalPoint;

/// `<arc>`: constant curvature (1/m), positive turning left.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arc {
    /// `curvature` (1/m).
    pub curvature: f64,
}

impl Arc {
    /// Point at arc length `ds`: u = sin(κ·ds)/κ, v = (1 − cos(κ·ds))/κ, written as
    /// 2·sin²(κ·ds/2)/κ to avoid cancellation for small κ·ds; a line when κ = 0.
    #[inline]
    pub(crate) fn eval(&self, ds: f64) -> LocalPoint {
        eval_constant_curvature(self.curvature, ds)
    }
}

/// Constant-curvature curve from the origin with heading 0 (shared with the degenerate spiral).
#[inline]
pub(crate) fn eval_constant_curvature(k: f64, ds: f64) -> LocalPoint {
    if k == 0.0 {
        return super::line::eval(ds);
    }
    let phi = k * ds;
    let half = 0.5 * phi;
    let sh = half.sin();
    LocalPoint {
        u: phi.sin() / k,
        v: 2.0 * sh * sh / k,
        hdg: phi,
        curvature: k,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn quarter_circle_of_radius_100() {
        // κ = 0.01, ds = π/2·100: a quarter circle turning left ends at (R, R) = (100, 100)
        // with heading π/2.
        let p = Arc { curvature: 0.01 }.eval(50.0 * PI);
        assert!((p.u - 100.0).abs() < 1e-9, "u = {}", p.u);
        assert!((p.v - 100.0).abs() < 1e-9, "v = {}", p.v);
        assert!((p.hdg - PI / 2.0).abs() < 1e-12);
    }

    #[test]
    fn right_turning_half_circle() {
        // κ = −0.05 (R = 20), ds = π·20: half circle to the right ends at (0, −40), heading −π.
        let p = Arc { curvature: -0.05 }.eval(20.0 * PI);
        assert!(p.u.abs() < 1e-9 && (p.v + 40.0).abs() < 1e-9, "{p:?}");
        assert!((p.hdg + PI).abs() < 1e-12);
    }
}
