//! `<paramPoly3>` (OpenDRIVE 1.8 §9.6): u(p), v(p) cubic in a parameter p.
//!
//! p ↔ s: OpenDRIVE 1.8 gives the range of p, "arcLength: p in [0, @length of `<geometry>`];
//! normalized: p in [0, 1]", and nothing else, so p runs linearly with s over the geometry:
//! p = ds for `arcLength`, p = ds/length for `normalized`. This is the reading of pyxodr and
//! the direct evaluation in the corpus README; esmini instead maps s to p by the curve's arc
//! length rescaled to the declared length, which differs by up to 6.6 cm on
//! `mixed_geometry.xodr` (see the reference test there).

use super::LocalPoint;

/// `paramPoly3/@pRange`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamRange {
    /// `arcLength`: p ∈ [0, length].
    ArcLength,
    /// `normalized`: p ∈ [0, 1].
    Normalized,
}

/// `<paramPoly3>`: u(p) = aU + bU·p + cU·p² + dU·p³, v(p) likewise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamPoly3 {
    /// aU, bU, cU, dU.
    pub u: [f64; 4],
    /// aV, bV, cV, dV.
    pub v: [f64; 4],
    /// `pRange`.
    pub range: ParamRange,
    /// The geometry's length (m), for the normalized range.
    pub(crate) length: f64,
}

#[inline]
fn cubic(c: &[f64; 4], p: f64) -> (f64, f64, f64) {
    let v = c[0] + p * (c[1] + p * (c[2] + p * c[3]));
    let d1 = c[1] + p * (2.0 * c[2] + 3.0 * c[3] * p);
    let d2 = 2.0 * c[2] + 6.0 * c[3] * p;
    (v, d1, d2)
}

impl ParamPoly3 {
    /// A paramPoly3 on a geometry of `length` metres.
    pub fn new(u: [f64; 4], v: [f64; 4], range: ParamRange, length: f64) -> Self {
        Self {
            u,
            v,
            range,
            length,
        }
    }

    /// Point at `ds` from the geometry's start.
    pub(crate) fn eval(&self, ds: f64) -> LocalPoint {
        let p = match self.range {
            ParamRange::ArcLength => ds,
            ParamRange::Normalized => ds / self.length,
        };
        let (u, du, ddu) = cubic(&self.u, p);
        let (v, dv, ddv) = cubic(&self.v, p);
        let sp2 = du * du + dv * dv;
        let curvature = if sp2 > 0.0 {
            (du * ddv - dv * ddu) / (sp2 * sp2.sqrt())
        } else {
            0.0
        };
        LocalPoint {
            u,
            v,
            hdg: dv.atan2(du),
            curvature,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arc_length_range_uses_p_equal_to_ds() {
        // mixed_geometry's second paramPoly3: u = p, v = 0.01p² − 0.0002p³. At ds = p = 10:
        // (10, 1 − 0.2) = (10, 0.8), heading atan(0.2 − 0.06) = atan(0.14), curvature
        // v″/(1 + v′²)^1.5 = (0.02 − 0.012)/(1.0196)^1.5.
        let g = ParamPoly3::new(
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 0.01, -0.0002],
            ParamRange::ArcLength,
            30.0,
        );
        let p = g.eval(10.0);
        assert!(
            (p.u - 10.0).abs() < 1e-12 && (p.v - 0.8).abs() < 1e-12,
            "{p:?}"
        );
        assert!((p.hdg - 0.14_f64.atan()).abs() < 1e-14);
        assert!((p.curvature - 0.008 / 1.0196_f64.powf(1.5)).abs() < 1e-14);
    }

    #[test]
    fn normalized_range_divides_by_length() {
        // mixed_geometry's first paramPoly3: u = 40p, v = 4p² − 2p³, length 40. At ds = 20,
        // p = 0.5: (20, 1 − 0.25) = (20, 0.75); du/dp = 40, dv/dp = 8p − 6p² = 2.5.
        let g = ParamPoly3::new(
            [0.0, 40.0, 0.0, 0.0],
            [0.0, 0.0, 4.0, -2.0],
            ParamRange::Normalized,
            40.0,
        );
        let p = g.eval(20.0);
        assert!(
            (p.u - 20.0).abs() < 1e-12 && (p.v - 0.75).abs() < 1e-12,
            "{p:?}"
        );
        assert!((p.hdg - 2.5_f64.atan2(40.0)).abs() < 1e-14);
    }
}
