//! The lane at a lateral offset (OpenDRIVE 1.8 §11 lanes, §11.4–§11.6 lane offset and widths):
//! which lane of a road holds a point given in road coordinates (s, t), the look-up behind
//! every entity's lane (module `world`) and behind positions placed beyond a road's end.

use opendrive::{Real, Road};

/// The drivable lane of `road` whose borders enclose `t` at `s`, with the offset from its
/// centre; beyond the drivable lanes, the nearest one (so an entity on the shoulder keeps its
/// driving lane, with a large offset). Roads without drivable lanes use every lane. Lane 0
/// (the centre lane, zero width) is never chosen. Where two lanes are equally near (`t` on
/// the marking between them) the first in the section's order (left lanes outermost first,
/// then right lanes innermost first, [`LaneSection::lanes`](opendrive::LaneSection::lanes))
/// wins.
///
/// One pass over the section's spans ([`Road::lane_spans`]: each lane's inner border is its
/// neighbour's outer one), every step for every entity: the per-lane look-up it replaces
/// summed the inner lanes' widths again for each lane.
pub fn lane_at(road: &Road, s: Real, t: Real) -> Option<(i32, Real)> {
    let left = road.lane_section_at(s).left.len() as i64;
    // (gap, place in the section's order, id, offset) of the nearest drivable lane and of the
    // nearest lane of any type.
    type Best = Option<(Real, i64, i32, Real)>;
    let (mut drivable, mut any): (Best, Best) = (None, None);
    let keep = |best: &mut Best, candidate: (Real, i64, i32, Real)| {
        if best.is_none_or(|(g, order, _, _)| {
            candidate.0 < g || (candidate.0 == g && candidate.1 < order)
        }) {
            *best = Some(candidate);
        }
    };
    road.lane_spans(s, |lane, span| {
        if lane.id == 0 {
            return;
        }
        let (lo, hi) = if span.inner <= span.outer {
            (span.inner, span.outer)
        } else {
            (span.outer, span.inner)
        };
        let gap = (lo - t).max(t - hi).max(0.0);
        // Place in LaneSection::lanes order: left lanes from the outermost (id = left, place
        // 0) inwards, the centre lane (place `left`), then the right lanes outwards.
        let order = left - i64::from(lane.id);
        let candidate = (gap, order, lane.id, t - span.center());
        if lane.lane_type.is_drivable() {
            keep(&mut drivable, candidate);
        }
        keep(&mut any, candidate);
    })
    .ok()?;
    drivable.or(any).map(|(_, _, id, offset)| (id, offset))
}
