//! Lateral extent of lanes at s (OpenDRIVE 1.8 §11.4 lane offset, §11.6 lane width and
//! border): the centre lane lies at laneOffset; lane n's inner border is lane n−1's outer
//! border, its outer border the inner one plus (left) or minus (right) its width.

use crate::math::{eval_piecewise, Real};
use crate::model::{Lane, LaneSection, Road};

/// Inner and outer border of a lane at some s, as t from the reference line (positive left),
/// with their derivatives along s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaneSpan {
    /// t of the border nearer the centre lane (m).
    pub inner: Real,
    /// t of the border farther from the centre lane (m).
    pub outer: Real,
    /// d(inner)/ds.
    pub d_inner: Real,
    /// d(outer)/ds.
    pub d_outer: Real,
}

impl LaneSpan {
    /// t of the lane centre (m).
    #[inline]
    pub fn center(&self) -> Real {
        0.5 * (self.inner + self.outer)
    }

    /// d(centre t)/ds.
    #[inline]
    pub fn d_center(&self) -> Real {
        0.5 * (self.d_inner + self.d_outer)
    }

    /// Lane width (m), ≥ 0 for well-formed files.
    #[inline]
    pub fn width(&self) -> Real {
        (self.outer - self.inner).abs()
    }
}

/// Width of `lane` and its derivative at `ds` from the section start; from `<border>` records
/// when the lane has no `<width>` (OpenDRIVE 1.8 §11.6.2: the border gives the lane's outer
/// limit independent of its inner border; read here as the distance of the outer border from
/// the centre lane, so width = border − inner distance).
#[inline]
fn width(lane: &Lane, ds: Real, inner_abs: Real, d_inner_abs: Real) -> (Real, Real) {
    if !lane.widths.is_empty() || lane.borders.is_empty() {
        eval_piecewise(&lane.widths, ds)
    } else {
        let (b, db) = eval_piecewise(&lane.borders, ds);
        (b - inner_abs, db - d_inner_abs)
    }
}

/// laneOffset and its derivative at s.
#[inline]
pub(crate) fn lane_offset(road: &Road, s: Real) -> (Real, Real) {
    eval_piecewise(&road.lane_offsets, s)
}

/// The span of lane `id` of `section` at road coordinate `s`; `None` if the section does not
/// hold the lane. Lane 0 has inner = outer = laneOffset.
pub(crate) fn lane_span(road: &Road, section: &LaneSection, id: i32, s: Real) -> Option<LaneSpan> {
    let (off, d_off) = lane_offset(road, s);
    let ds = s - section.s;
    let (lanes, sign) = if id >= 0 {
        (&section.left, 1.0)
    } else {
        (&section.right, -1.0)
    };
    let n = id.unsigned_abs() as usize;
    if n > lanes.len() {
        return None;
    }
    // Distances from the centre lane (positive outwards) and their derivatives.
    let (mut inner, mut d_inner) = (0.0, 0.0);
    for lane in &lanes[..n.saturating_sub(1)] {
        let (w, dw) = width(lane, ds, inner, d_inner);
        inner += w;
        d_inner += dw;
    }
    let (w, dw) = if n == 0 {
        (0.0, 0.0)
    } else {
        width(&lanes[n - 1], ds, inner, d_inner)
    };
    Some(LaneSpan {
        inner: off + sign * inner,
        outer: off + sign * (inner + w),
        d_inner: d_off + sign * d_inner,
        d_outer: d_off + sign * (d_inner + dw),
    })
}

/// The lanes of one side of a lane section with their spans at some s, from the centre
/// outwards: each lane's inner border is the previous lane's outer one, so walking a side
/// costs what its outermost lane's [`lane_span`] alone does; each span equals [`lane_span`]'s
/// bit for bit (the same sums in the same order).
pub(crate) struct SideSpans<'a> {
    lanes: std::slice::Iter<'a, Lane>,
    off: Real,
    d_off: Real,
    ds: Real,
    sign: Real,
    inner: Real,
    d_inner: Real,
}

impl<'a> Iterator for SideSpans<'a> {
    type Item = (&'a Lane, LaneSpan);

    #[inline]
    fn next(&mut self) -> Option<Self::Item> {
        let lane = self.lanes.next()?;
        let (w, dw) = width(lane, self.ds, self.inner, self.d_inner);
        let span = LaneSpan {
            inner: self.off + self.sign * self.inner,
            outer: self.off + self.sign * (self.inner + w),
            d_inner: self.d_off + self.sign * self.d_inner,
            d_outer: self.d_off + self.sign * (self.d_inner + dw),
        };
        self.inner += w;
        self.d_inner += dw;
        Some((lane, span))
    }
}

/// The left (`left`) or right lanes of `section` with their spans at `s`, centre outwards.
#[inline]
pub(crate) fn side_spans<'a>(
    road: &Road,
    section: &'a LaneSection,
    s: Real,
    left: bool,
) -> SideSpans<'a> {
    let (off, d_off) = lane_offset(road, s);
    let (lanes, sign) = if left {
        (&section.left, 1.0)
    } else {
        (&section.right, -1.0)
    };
    SideSpans {
        lanes: lanes.iter(),
        off,
        d_off,
        ds: s - section.s,
        sign,
        inner: 0.0,
        d_inner: 0.0,
    }
}

/// Calls `f` with every lane of `section` and its span at `s`, from the centre outwards: the
/// centre lane, left lanes 1, 2, …, then right lanes −1, −2, … (see [`SideSpans`]).
pub(crate) fn for_each_span(
    road: &Road,
    section: &LaneSection,
    s: Real,
    mut f: impl FnMut(&Lane, LaneSpan),
) {
    let (off, d_off) = lane_offset(road, s);
    // lane_span's arithmetic for lane 0 (no widths: inner = outer = laneOffset).
    f(
        &section.center,
        LaneSpan {
            inner: off + 0.0,
            outer: off + (0.0 + 0.0),
            d_inner: d_off + 0.0,
            d_outer: d_off + (0.0 + 0.0),
        },
    );
    for left in [true, false] {
        for (lane, span) in side_spans(road, section, s, left) {
            f(lane, span);
        }
    }
}

/// t of the outermost left and right borders at s: (right t, left t), i.e. (min, max) of the
/// road surface across all lanes of the section.
pub(crate) fn road_extent(road: &Road, section: &LaneSection, s: Real) -> (Real, Real) {
    let left = lane_span(road, section, section.left.len() as i32, s).map_or(0.0, |sp| sp.outer);
    let right =
        lane_span(road, section, -(section.right.len() as i32), s).map_or(0.0, |sp| sp.outer);
    let (off, _) = lane_offset(road, s);
    (right.min(off), left.max(off))
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::math::Cubic;
    use crate::model::LaneType;

    /// A driving lane with the given id and width entries (no marks, links or heights).
    pub(crate) fn lane(id: i32, widths: Vec<Cubic>) -> Lane {
        Lane {
            id,
            lane_type: LaneType::Driving,
            level: false,
            predecessor: None,
            successor: None,
            widths,
            borders: Vec::new(),
            road_marks: Vec::new(),
            heights: Vec::new(),
            speed_limit: None,
        }
    }

    /// A lane section at s = 0 with the centre lane only (the road surface is the reference
    /// line).
    pub(crate) fn centre_only_section() -> LaneSection {
        LaneSection {
            s: 0.0,
            single_side: false,
            left: vec![],
            center: lane(0, vec![]),
            right: vec![],
        }
    }

    fn cubic(start: f64, a: f64, b: f64, c: f64, d: f64) -> Cubic {
        Cubic { start, a, b, c, d }
    }

    #[test]
    fn widths_stack_outwards_from_the_lane_offset() {
        // Section at s = 10; laneOffset 0.5 + 0.01·s. Lane 1: 3 + 0.1·ds; lane 2: 2 (from
        // sOffset 0) then 1 + 0.5·(ds − 4)² (from sOffset 4). Lane −1: 3.5 − 0.002·ds³.
        // At s = 16 (ds = 6): offset 0.66 (slope 0.01); lane 1 width 3.6 (slope 0.1);
        // lane 2 width 1 + 0.5·4 = 3 (slope 2); lane −1 width 3.5 − 0.432 = 3.068
        // (slope −0.006·36 = −0.216).
        let road_offsets = vec![cubic(0.0, 0.5, 0.01, 0.0, 0.0)];
        let section = LaneSection {
            s: 10.0,
            single_side: false,
            left: vec![
                lane(1, vec![cubic(0.0, 3.0, 0.1, 0.0, 0.0)]),
                lane(
                    2,
                    vec![
                        cubic(0.0, 2.0, 0.0, 0.0, 0.0),
                        cubic(4.0, 1.0, 0.0, 0.5, 0.0),
                    ],
                ),
            ],
            center: lane(0, vec![]),
            right: vec![lane(-1, vec![cubic(0.0, 3.5, 0.0, 0.0, -0.002)])],
        };
        let road =
            crate::road::frame::tests::straight_road(100.0, road_offsets, vec![section.clone()]);
        let tol = 1e-12;
        let c = lane_span(&road, &section, 0, 16.0).unwrap();
        assert!((c.inner - 0.66).abs() < tol && (c.outer - 0.66).abs() < tol);
        let l2 = lane_span(&road, &section, 2, 16.0).unwrap();
        assert!((l2.inner - (0.66 + 3.6)).abs() < tol, "{l2:?}");
        assert!((l2.outer - (0.66 + 3.6 + 3.0)).abs() < tol, "{l2:?}");
        assert!((l2.d_outer - (0.01 + 0.1 + 2.0)).abs() < tol, "{l2:?}");
        let r1 = lane_span(&road, &section, -1, 16.0).unwrap();
        assert!((r1.outer - (0.66 - 3.068)).abs() < tol, "{r1:?}");
        assert!((r1.d_outer - (0.01 + 0.216)).abs() < tol, "{r1:?}");
        assert!((r1.center() - (0.66 - 1.534)).abs() < tol);
        assert!(lane_span(&road, &section, 3, 16.0).is_none());
        // Borders instead of widths: lane −1 outer border 4 + 0.1·ds, lane −2 outer border 7.
        // At ds = 6: lane −1 spans [0.66, 0.66 − 4.6], lane −2 [0.66 − 4.6, 0.66 − 7], width 2.4.
        let mut bordered = section.clone();
        bordered.right = vec![lane(-1, vec![]), lane(-2, vec![])];
        bordered.right[0].borders = vec![cubic(0.0, 4.0, 0.1, 0.0, 0.0)];
        bordered.right[1].borders = vec![cubic(0.0, 7.0, 0.0, 0.0, 0.0)];
        let b2 = lane_span(&road, &bordered, -2, 16.0).unwrap();
        assert!(
            (b2.inner - (0.66 - 4.6)).abs() < tol && (b2.outer - (0.66 - 7.0)).abs() < tol,
            "{b2:?}"
        );
        assert!(
            (b2.width() - 2.4).abs() < tol && (b2.d_outer - 0.01).abs() < tol,
            "{b2:?}"
        );
        assert!(lane_span(&road, &section, -2, 16.0).is_none());
        // The one-pass walk gives every lane, centre outwards, with lane_span's span bit for
        // bit (borders included).
        for sec in [&section, &bordered] {
            let mut seen = Vec::new();
            for_each_span(&road, sec, 16.0, |lane, span| {
                assert_eq!(
                    Some(span),
                    lane_span(&road, sec, lane.id, 16.0),
                    "{}",
                    lane.id
                );
                seen.push(lane.id);
            });
            let expected: Vec<i32> = std::iter::once(0)
                .chain(sec.left.iter().map(|l| l.id))
                .chain(sec.right.iter().map(|l| l.id))
                .collect();
            assert_eq!(seen, expected);
        }
    }
}
