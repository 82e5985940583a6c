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
//!
//! The geometry and the elevation and superelevation records valid at s are looked up from
//! [`Hints`]: the indices valid on the piece being projected onto, checked first, then the
//! binary search of `PlanView::eval_trig` and `eval_piecewise`. The parser sorts geometries
//! and records by their start (finite numbers), so "the last one starting at or before s"
//! holds for the hint exactly when the binary search would find it.

use super::frame::cross_section;
use crate::math::{Cubic, Real, LENGTH_EPSILON};
use crate::model::Road;

/// Indices of the geometry, elevation record and superelevation record valid somewhere on a
/// piece of road (usually all of it), tried first by [`plan_frame`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Hints {
    geometry: u32,
    elevation: u32,
    superelevation: u32,
}

impl Hints {
    /// The indices valid at `s` on `road`.
    pub(crate) fn at(road: &Road, s: Real) -> Self {
        let index = |i: usize| u32::try_from(i).unwrap_or(u32::MAX);
        Self {
            geometry: index(road.plan_view.index_at(s)),
            elevation: index(record_index(&road.elevation, s, u32::MAX)),
            superelevation: index(record_index(&road.superelevation, s, u32::MAX)),
        }
    }
}

/// `items.partition_point(pred).saturating_sub(1)` (the last item for which the ascending
/// predicate holds, or 0), trying `hint` first.
#[inline]
fn last_holding<T>(items: &[T], hint: u32, pred: impl Fn(&T) -> bool) -> usize {
    let h = hint as usize;
    if let Some(item) = items.get(h) {
        if pred(item) && items.get(h + 1).is_none_or(|next| !pred(next)) {
            return h;
        }
    }
    items.partition_point(pred).saturating_sub(1)
}

/// The record of `records` that `eval_piecewise` evaluates at `x`.
#[inline]
fn record_index(records: &[Cubic], x: Real, hint: u32) -> usize {
    let bound = x + LENGTH_EPSILON;
    last_holding(records, hint, |r| r.start <= bound)
}

/// `eval_piecewise(records, x)`, the record looked up from `hint` first.
#[inline]
fn eval_hinted(records: &[Cubic], x: Real, hint: u32) -> (Real, Real) {
    if records.is_empty() {
        return (0.0, 0.0);
    }
    records[record_index(records, x, hint)].eval(x)
}

/// The horizontal placement of a road's cross-section at some s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PlanFrame {
    x: Real,
    y: Real,
    /// Heading of the reference line (rad).
    pub(crate) hdg: Real,
    /// Curvature of the reference line (1/m).
    pub(crate) curvature: Real,
    sin_h: Real,
    cos_h: Real,
    /// sin p, or on unbanked roads a number with its sign (see the module doc).
    sin_p: Real,
    sin_r: Real,
    cos_r: Real,
}

/// The horizontal frame of `road` at `s` (s already within [0, length]), its geometry and
/// records looked up from `hints` first.
#[inline]
pub(crate) fn plan_frame(road: &Road, s: Real, hints: Hints) -> PlanFrame {
    let geometries = road.plan_view.geometries();
    let g = last_holding(geometries, hints.geometry, |g| g.s <= s);
    let (rp, sin_h, cos_h) = geometries[g].eval_trig(s);
    let (_, dz) = eval_hinted(&road.elevation, s, hints.elevation);
    let (roll, _) = eval_hinted(&road.superelevation, s, hints.superelevation);
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
        cross_section(
            t,
            0.0,
            [self.x, self.y],
            [self.sin_h, self.cos_h],
            self.sin_p,
            [self.sin_r, self.cos_r],
        )
        .0
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
    use crate::road::frame::tests::straight_road;
    use crate::road::frame::{road_frame, RoadFrame};
    use crate::road::lane_span::tests::centre_only_section;

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
                let f = road_frame(road, s);
                // Right hints, and hints of another s (the binary search then).
                let p = plan_frame(road, s, Hints::at(road, s));
                let other = plan_frame(road, s, Hints::at(road, 100.0 - s));
                assert_eq!(p, other);
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
    #[test]
    fn hints_give_the_binary_search_answer() {
        // Three geometries (a line to s = 10, an arc to 25, a line to 40), an elevation record
        // every 5 m and two superelevation records: at every s on a 0.25 m grid and just
        // around each start, the frame from any piece's hints is the full frame's, bit for bit.
        let mut road = straight_road(40.0, vec![], vec![centre_only_section()]);
        let arc_end = Arc { curvature: 0.02 }.eval(15.0);
        road.plan_view = PlanView::new(vec![
            Geometry::new(0.0, 0.0, 0.0, 0.0, 10.0, GeometryKind::Line),
            Geometry::new(
                10.0,
                10.0,
                0.0,
                0.0,
                15.0,
                GeometryKind::Arc(Arc { curvature: 0.02 }),
            ),
            Geometry::new(
                25.0,
                10.0 + arc_end.u,
                arc_end.v,
                arc_end.hdg,
                15.0,
                GeometryKind::Line,
            ),
        ]);
        road.elevation = (0..8)
            .map(|k| cubic(5.0 * k as f64, 0.1 * k as f64, 0.01 * (k as f64 - 3.0)))
            .collect();
        road.superelevation = vec![cubic(0.0, 0.0, 0.0), cubic(20.0, 0.05, 0.0)];
        let mut samples: Vec<f64> = (0..=160).map(|k| 0.25 * k as f64).collect();
        for start in [5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0] {
            samples.extend([start - 1e-9, start - 1e-12, start + 1e-12, start + 1e-9]);
        }
        let hints: Vec<Hints> = [0.0, 7.5, 12.0, 20.0, 24.9, 33.0, 40.0]
            .iter()
            .map(|&s| Hints::at(&road, s))
            .collect();
        for &s in &samples {
            let f = road_frame(&road, s);
            for &h in &hints {
                let p = plan_frame(&road, s, h);
                assert_eq!(p.hdg.to_bits(), f.hdg.to_bits(), "s {s}");
                for t in [0.0, -2.5, 3.75] {
                    let (xy, _) = full(&f, t);
                    assert_eq!(
                        p.place(t).map(Real::to_bits),
                        xy.map(Real::to_bits),
                        "s {s}"
                    );
                }
            }
        }
    }
}
