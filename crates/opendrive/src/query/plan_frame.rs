//! The horizontal part of the road's local frame (OpenDRIVE 1.8 §8.3 reference-line
//! coordinates, §10.5 superelevation), for the world → road projection of `locate`: where
//! the cross-section point (t, height 0) lies in x and y, and the derivatives of that
//! placement. Bit for bit what [`RoadFrame::place`](super::frame::RoadFrame::place) and
//! [`RoadFrame::jacobian`](super::frame::RoadFrame::jacobian) give, without the pitch's
//! trigonometry (an `atan` and a `sin_cos` per evaluation) on unbanked roads.
//!
//! Why that is exact: with roll 0 the frame has sin r = +0 and cos r = 1, so the cross-section
//! point (0, t, 0) rotates to a = t and b = t·0 + 0·1, which is +0 for a finite t and NaN
//! otherwise; the pitch enters x and y only through fwd = b·sin p: a zero with the sign of
//! sin p, or NaN. sin p = sin(−atan(dz)) is +0 for dz = 0 (the frame skips the trigonometry
//! there) and otherwise has the sign of −dz (±∞ included) or is NaN with dz, which is what
//! −signum(dz) has; so b·(−signum(dz)) is the same fwd, signed zero and NaN included. A
//! signed zero matters where the reference point itself has x or y = ±0. Banked roads
//! (roll ≠ 0) compute the pitch as the full frame does.

use crate::math::{eval_piecewise, Real};
use crate::model::Road;

/// The horizontal placement of a road's cross-section at some s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PlanFrame {
    x: Real,
    y: Real,
    /// Heading of the reference line (rad).
    pub(crate) hdg: Real,
    curvature: Real,
    sin_h: Real,
    cos_h: Real,
    /// sin p, or on unbanked roads a number with its sign (see the module doc).
    sin_p: Real,
    sin_r: Real,
    cos_r: Real,
}

/// The horizontal frame of `road` at `s` (s already within [0, length]).
#[inline]
pub(crate) fn plan_frame(road: &Road, s: Real) -> PlanFrame {
    let (rp, sin_h, cos_h) = road.plan_view.eval_trig(s);
    let (_, dz) = eval_piecewise(&road.elevation, s);
    let (roll, _) = eval_piecewise(&road.superelevation, s);
    let (sin_p, sin_r, cos_r) = if roll == 0.0 {
        (if dz == 0.0 { 0.0 } else { -dz.signum() }, 0.0, 1.0)
    } else {
        // RoadFrame's own arithmetic (`road_frame`).
        let sin_p = if dz == 0.0 {
            0.0
        } else {
            (-dz.atan()).sin_cos().0
        };
        let (sin_r, cos_r) = roll.sin_cos();
        (sin_p, sin_r, cos_r)
    };
    PlanFrame {
        x: rp.x,
        y: rp.y,
        hdg: rp.hdg,
        curvature: rp.curvature,
        sin_h,
        cos_h,
        sin_p,
        sin_r,
        cos_r,
    }
}

impl PlanFrame {
    /// x and y of the cross-section point (t, height 0): [`RoadFrame::place`]'s first two.
    #[inline]
    pub(crate) fn place(&self, t: Real) -> [Real; 2] {
        let height: Real = 0.0;
        let a = t * self.cos_r - height * self.sin_r;
        let b = t * self.sin_r + height * self.cos_r;
        let fwd = b * self.sin_p;
        [
            self.x + fwd * self.cos_h - a * self.sin_h,
            self.y + fwd * self.sin_h + a * self.cos_h,
        ]
    }

    /// [`RoadFrame::jacobian`]: (∂xy/∂s, ∂xy/∂t) at t.
    #[inline]
    pub(crate) fn jacobian(&self, t: Real) -> [[Real; 2]; 2] {
        let along = 1.0 - self.curvature * t * self.cos_r;
        [
            [along * self.cos_h, -self.cos_r * self.sin_h],
            [along * self.sin_h, self.cos_r * self.cos_h],
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Arc, Geometry, GeometryKind, PlanView};
    use crate::math::Cubic;
    use crate::query::frame::tests::straight_road;
    use crate::query::frame::{road_frame, RoadFrame};
    use crate::query::lane_span::tests::centre_only_section;

    /// The full frame's horizontal part.
    fn full(f: &RoadFrame, t: Real) -> ([Real; 2], [[Real; 2]; 2]) {
        let [x, y, _] = f.place(t, 0.0);
        ([x, y], f.jacobian(t))
    }

    fn cubic(start: f64, a: f64, b: f64) -> Cubic {
        Cubic {
            start,
            a,
            b,
            c: 0.0,
            d: 0.0,
        }
    }

    #[test]
    fn same_bits_as_the_full_frame() {
        // Roads through the origin (reference points with x or y = ±0, where fwd's signed
        // zero shows), climbing, falling, flat, banked, and an arc; t of either sign and ±0.
        let section = centre_only_section();
        let mut roads = Vec::new();
        for (elevation, superelevation) in [
            (vec![], vec![]),
            (vec![cubic(0.0, 1.0, 0.1)], vec![]),
            (vec![cubic(0.0, 1.0, -0.1)], vec![cubic(0.0, 0.0, 0.0)]),
            (vec![cubic(0.0, 0.0, 0.05)], vec![cubic(0.0, 0.2, 0.0)]),
            (vec![cubic(0.0, 0.0, -0.05)], vec![cubic(0.0, -0.1, 0.001)]),
            (vec![cubic(0.0, 2.0, 0.0)], vec![cubic(0.0, 0.0, 0.002)]),
        ] {
            let mut road = straight_road(100.0, vec![], vec![section.clone()]);
            road.elevation = elevation;
            road.superelevation = superelevation;
            roads.push(road.clone());
            // The same profiles on a left arc starting at (-0, 0) heading π/2 (so x is -0 at
            // s = 0) and on a line along -x.
            road.plan_view = PlanView::new(vec![Geometry::new(
                0.0,
                -0.0,
                0.0,
                std::f64::consts::FRAC_PI_2,
                100.0,
                GeometryKind::Arc(Arc { curvature: 0.01 }),
            )]);
            roads.push(road.clone());
            road.plan_view = PlanView::new(vec![Geometry::new(
                0.0,
                0.0,
                -0.0,
                std::f64::consts::PI,
                100.0,
                GeometryKind::Line,
            )]);
            roads.push(road);
        }
        let mut compared = 0;
        for road in &roads {
            for s in [0.0, 0.5, 33.3, 100.0] {
                let (f, p) = (road_frame(road, s), plan_frame(road, s));
                assert_eq!(f.hdg.to_bits(), p.hdg.to_bits());
                for t in [0.0, -0.0, 1.5, -3.25, 1e-300, -7e5] {
                    let (xy, j) = full(&f, t);
                    let bits = |v: [Real; 2]| v.map(Real::to_bits);
                    assert_eq!(bits(p.place(t)), bits(xy), "s {s}, t {t}");
                    assert_eq!(bits(p.jacobian(t)[0]), bits(j[0]), "s {s}, t {t}");
                    assert_eq!(bits(p.jacobian(t)[1]), bits(j[1]), "s {s}, t {t}");
                    compared += 1;
                }
            }
        }
        assert_eq!(compared, 18 * 4 * 6);
    }
}
