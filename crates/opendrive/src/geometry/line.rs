//! `<line>` (OpenDRIVE 1.8 §9.3): a straight reference line.

use super::LocalPoint;
use crate::math::Real;

/// Point at arc length `ds` along a line.
#[inline]
pub(crate) fn eval(ds: f64) -> LocalPoint {
    LocalPoint {
        u: ds,
        v: 0.0,
        hdg: 0.0,
        curvature: 0.0,
    }
}

/// The point `ds` along a line from `start` whose heading has the sine and cosine given:
/// (x + ds·cos h, y + ds·sin h), the reference point of `Geometry::eval_trig` and of a
/// straight `FrameStretch` (road/frame_stretch.rs), one formula for both.
#[inline(always)]
pub(crate) fn along([x, y]: [Real; 2], ds: Real, [sin_h, cos_h]: [Real; 2]) -> [Real; 2] {
    [x + ds * cos_h, y + ds * sin_h]
}

#[cfg(test)]
mod tests {
    #[test]
    fn line_advances_along_its_heading() {
        // A line is (ds, 0) in its own frame with zero heading and curvature.
        let p = super::eval(12.5);
        assert!((p.u - 12.5).abs() < 1e-15 && p.v.abs() < 1e-15 && p.hdg.abs() < 1e-15);
    }
}
