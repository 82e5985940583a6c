//! Where the lane borders do not change along s (OpenDRIVE 1.8 §11.4 lane offset, §11.6 lane
//! width): the s-range around a point, inside one lane section, one `<laneOffset>` record and
//! one `<width>` record per lane, in which every record is a constant (b = c = d = 0). There
//! every lane's span ([`Road::lane_span`], [`Road::lane_spans`]) is the same number, bit for
//! bit, at every s, so a caller that asks at each step (the engine's default controller) can
//! keep the answer while it stays inside the range.
//!
//! Why bit for bit: a record evaluates as a + ds·(b + ds·(c + ds·d)) with ds = x − start; with
//! b, c and d zero (of either sign) and ds > 0 the bracket is a zero whose sign does not depend
//! on ds, and so is the value. The range is kept [`CONSTANT_MARGIN`] inside the records' and
//! the section's ends: there ds > 0 and the tolerant record look-up (`LENGTH_EPSILON`) cannot
//! pick a neighbour.

use crate::math::{Cubic, Real, LENGTH_EPSILON};
use crate::model::Road;

/// Distance (m) kept from each record's and section's ends: more than the tolerance within
/// which a look-up at a section's start takes a lane ending there from the section before
/// (`S_TOLERANCE`, [`Road::lane_section_holding`]).
pub const CONSTANT_MARGIN: Real = 1e-5;
const _: () = assert!(CONSTANT_MARGIN > crate::math::S_TOLERANCE);

impl Road {
    /// The s-range `(lo, hi)` holding `s` over which the lane section and every lane border of
    /// it stay the same numbers (module doc); `None` where the lane offset or a lane's width
    /// varies with s there, a lane is given by `<border>` records, or `s` is off the road or
    /// within [`CONSTANT_MARGIN`] of a record's or section's end.
    pub fn constant_lanes(&self, s: Real) -> Option<(Real, Real)> {
        if !(s.is_finite() && (0.0..=self.length).contains(&s)) {
            return None;
        }
        let k = self.lane_section_index(s);
        let section = &self.lane_sections[k];
        let mut range = (
            section.s.max(0.0) + CONSTANT_MARGIN,
            self.lane_section_end(k).min(self.length) - CONSTANT_MARGIN,
        );
        narrow(&self.lane_offsets, 0.0, s, &mut range)?;
        for lane in section.left.iter().chain(&section.right) {
            if lane.widths.is_empty() && !lane.borders.is_empty() {
                return None;
            }
            // No records at all: width 0 everywhere.
            narrow(&lane.widths, section.s, s, &mut range)?;
        }
        let (lo, hi) = range;
        (lo <= s && s <= hi).then_some(range)
    }
}

/// Narrows `range` to the record of `records` (starts relative to `origin`) that applies at
/// `s`; `None` if that record varies or `s` lies before the first record (extrapolated with
/// ds < 0).
fn narrow(records: &[Cubic], origin: Real, s: Real, range: &mut (Real, Real)) -> Option<()> {
    let record = narrow_to_record(records, origin, s, range)?;
    record.is_none_or(is_constant).then_some(())
}

/// Whether `record` is a constant: b = c = d = 0 (of either sign).
pub(super) fn is_constant(record: &Cubic) -> bool {
    record.b == 0.0 && record.c == 0.0 && record.d == 0.0
}

/// Narrows `range` to a [`CONSTANT_MARGIN`] inside the ends of the record of `records` (starts
/// relative to `origin`) that `eval_piecewise` evaluates at `s`, and returns that record
/// (`Some(None)` where there are none: every s has the value 0); `None` if `s` lies before
/// the first record (extrapolated with ds < 0). Inside the narrowed range `eval_piecewise`
/// evaluates the same record, with ds ≥ the margin: the record starting at or before
/// s − origin + `LENGTH_EPSILON` is that one wherever s lies a margin inside its ends.
pub(super) fn narrow_to_record<'a>(
    records: &'a [Cubic],
    origin: Real,
    s: Real,
    range: &mut (Real, Real),
) -> Option<Option<&'a Cubic>> {
    if records.is_empty() {
        return Some(None);
    }
    // The look-up of `eval_piecewise`.
    let i = records.partition_point(|r| r.start <= s - origin + LENGTH_EPSILON);
    let r = &records[i.checked_sub(1)?];
    range.0 = range.0.max(origin + r.start + CONSTANT_MARGIN);
    if let Some(next) = records.get(i) {
        range.1 = range.1.min(origin + next.start - CONSTANT_MARGIN);
    }
    Some(Some(r))
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::math::Cubic;
    use crate::model::{Lane, LaneSection};
    use crate::road::frame::tests::straight_road;
    use crate::road::lane_span::tests::lane;

    /// A record of value `a` and slope `b` from `start` (c = −0, d = 0).
    pub(crate) fn cubic(start: Real, a: Real, b: Real) -> Cubic {
        Cubic {
            start,
            a,
            b,
            c: -0.0,
            d: 0.0,
        }
    }

    fn section(s: Real, right: Vec<Lane>) -> LaneSection {
        LaneSection {
            s,
            single_side: false,
            left: Vec::new(),
            center: lane(0, Vec::new()),
            right,
        }
    }

    /// A 100 m road: section 0 (lane −1 3.5 m wide, lane −2 3 m up to sOffset 30 then
    /// 3 + 0.01·ds), section 60 (lane −1 3.5 m). Section 0 is constant on [0, 30] and varies
    /// after; section 60 is constant to the road's end. Margins of 10 µm at each end.
    fn road() -> Road {
        let s0 = section(
            0.0,
            vec![
                lane(-1, vec![cubic(0.0, 3.5, 0.0)]),
                lane(-2, vec![cubic(0.0, 3.0, 0.0), cubic(30.0, 3.0, 0.01)]),
            ],
        );
        let s60 = section(60.0, vec![lane(-1, vec![cubic(0.0, 3.5, 0.0)])]);
        straight_road(100.0, Vec::new(), vec![s0, s60])
    }

    #[test]
    fn constant_ranges_end_a_margin_inside_records_and_sections() {
        let r = road();
        let (lo, hi) = r.constant_lanes(10.0).expect("constant at 10");
        assert_eq!((lo, hi), (CONSTANT_MARGIN, 30.0 - CONSTANT_MARGIN));
        assert!(r.constant_lanes(40.0).is_none(), "lane −2 widens after 30");
        let (lo, hi) = r.constant_lanes(70.0).expect("constant at 70");
        assert_eq!((lo, hi), (60.0 + CONSTANT_MARGIN, 100.0 - CONSTANT_MARGIN));
        // Within the margin, off the road, not finite: no range.
        for s in [0.0, 30.0, 60.0, 100.0, -1.0, 101.0, f64::NAN] {
            assert!(r.constant_lanes(s).is_none(), "{s}");
        }
    }

    /// Inside a range every span is the same bits at every s (the module doc's argument), with
    /// a negative zero coefficient in every record and a varying laneOffset elsewhere.
    #[test]
    fn spans_are_bitwise_constant_inside_the_range() {
        let mut r = road();
        r.lane_offsets = vec![cubic(0.0, 0.25, 0.0), cubic(50.0, 0.25, 0.002)];
        let (lo, hi) = r.constant_lanes(5.0).expect("constant at 5");
        assert_eq!(hi, 30.0 - CONSTANT_MARGIN);
        let at = |s: Real| {
            let mut spans = Vec::new();
            r.lane_spans(s, |l, sp| spans.push((l.id, sp)))
                .expect("on road");
            spans
        };
        let first = at(lo);
        for i in 0..=1000 {
            let s = lo + (hi - lo) * Real::from(i) / 1000.0;
            assert_eq!(at(s), first, "s = {s}");
        }
        // Lane −1 at the range: inner 0.25, outer 0.25 − 3.5 (hand sums).
        assert_eq!(first[1].1.inner, 0.25);
        assert_eq!(first[1].1.outer, 0.25 - 3.5);
        // Where the laneOffset varies (s ≥ 50 in section 0): none.
        assert!(r.constant_lanes(55.0).is_none());
    }
}
