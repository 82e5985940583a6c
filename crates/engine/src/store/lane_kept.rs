//! What the per-lane index (store/lane_index.rs) keeps of each entity's entries from one step
//! to the next (issue 31), so that a step does not look up, test and sort again what has not
//! changed (OpenDRIVE 1.8 §11 lanes: a lane of one lane section).
//!
//! **Which entries stay.** An entity's entries in the lanes of its own road are a function of
//! its road, the lane section at its s, the t-range of its box and the lanes' borders there
//! (`LaneIndex::insert`). Where the borders come from a list the index keeps for a stretch of
//! the road (store/lane_slots.rs: every border the same number over the stretch), an entity
//! whose road, section and t-range (its bits) are those of the last step, and whose s is still
//! in the stretch of the same kept list (its generation), is in the same lanes: its entries
//! stay, and only their s-range is set to the new footprint's. Any other entity (a new road,
//! section or t-range, borders made anew at each call, a road of a junction, whose entries on
//! the junction's other roads depend on its x and y) has its entries of the last step dropped
//! and made anew, as a full build makes them.
//!
//! **The lane handle.** The handle of the lane the road position names
//! (`RoadNetwork::lane_handle_on`) is (road, the section at s holding the lane, lane). Where the
//! last step's handle was of the same road and lane and of section k, and the section at s is
//! k now, the section at s holds the lane (the last look-up found it there), so the look-up
//! gives that handle again: it is kept.
//!
//! **What is written.** The kept row holds the entity's footprint too (one row per entity,
//! read by the step's end and by the questions). An entity whose entries stay has the same
//! handle, t-range bits, section and borders as the last step, so only its footprint's s,
//! s-range and speed and the row's `stays` are written (`LaneIndex::stay`, the common case, in
//! line); any other entity takes the full way out of line (`LaneIndex::enter_anew`), which
//! writes the whole row once.
//!
//! **The box's s-range.** The box's ranges are folded from its four corners: the s-range as
//! the least and greatest of s + dsᵢ, the t-range of t + dtᵢ, where the corners' offsets
//! (dsᵢ, dtᵢ) are a function of the box (its centre's x and y, its length and width) and the
//! heading relative to the road alone. An entity entered in full keeps beside its row the
//! least and greatest dsᵢ (`BoxKept`) with the bits of that box, heading and t. Where they are
//! the same bits in a later step, the corners' offsets are the same numbers, so the t-range is
//! the one its row holds (written in the same entry: no other write of the row changes it)
//! and the s-range is (s + min dsᵢ, s + max dsᵢ) wherever both ends are finite and not zero
//! ([`shifted`]): rounding to nearest is monotone, so s + min dsᵢ rounds to a value no greater
//! than any s + dsᵢ and is one of them, the least; a finite number other than zero has one bit
//! pattern, so the fold's `min`, which returns one of its operands (a NaN operand is skipped,
//! and s + dsᵢ is NaN only where dsᵢ is, which the fold of min dsᵢ skips alike), gives those
//! bits; the same for the greatest. Where an end is zero (its sign could depend on the
//! fold) or not finite the ranges are folded from the corners as before, and so they are
//! where any of the six differs. On a lane followed at a steady t this replaces the eight
//! products and sixteen sums and bounds of the fold by six comparisons and two sums (issue 31).
//!
//! **The order.** The entries of a lane are sorted by (lo, id), a total order (`total_cmp`,
//! an entity once per lane), so any correct sort gives the one order there is. Vehicles in a
//! lane keep their order from step to step but for the few that change lanes or pass through,
//! so the list is checked in one pass that folds the lane's bounds as it goes, each pair by
//! the plain `<` of their lo first ([`order_and_bounds`]), and where it is out of order
//! repaired by insertion from the first entry out of place and sorted in full when the repair
//! would move more than a few entries per entry ([`repair_order`]).
//!
//! **Checked.** In debug builds (every `cargo test`) each kept index is compared, after every
//! step, with a full build of the same step kept beside it (`LaneIndex::assert_same_as`): the
//! lanes' entries in order, their bounds and flags, every footprint and driver input, bit for
//! bit (and store/lane_kept_tests.rs in random traffic).

use std::cmp::Ordering;

use opendrive::{Direction, LaneHandle, Real};

use crate::world::entity::EntityId;

/// Where an entity's bounding box lies on its road (store/lane_index.rs module doc
/// "Footprints"); kept in its row (`Kept`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Footprint {
    /// The lane holding the reference point.
    pub handle: LaneHandle,
    /// s of the reference point (m).
    pub s: Real,
    /// s-range of the box (m).
    pub s_range: (Real, Real),
    /// t-range of the box (m).
    pub t_range: (Real, Real),
    /// Velocity component along +s (m/s).
    pub speed_s: Real,
}

impl Footprint {
    /// The end of the box reached first travelling `direction` from its inside: the front
    /// bumper of a vehicle driving that way.
    pub fn front(&self, direction: Direction) -> Real {
        match direction {
            Direction::Forward => self.s_range.1,
            Direction::Backward => self.s_range.0,
        }
    }

    /// The other end: the rear bumper.
    pub fn rear(&self, direction: Direction) -> Real {
        self.front(direction.reverse())
    }

    /// The speed along `direction` of travel (m/s).
    pub fn speed_along(&self, direction: Direction) -> Real {
        match direction {
            Direction::Forward => self.speed_s,
            Direction::Backward => -self.speed_s,
        }
    }
}

/// One entity's footprint in one lane: the s-range of its box, by lo.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Entry {
    pub lo: Real,
    pub hi: Real,
    pub id: EntityId,
}

/// What the index keeps of one entity from one step to the next (module doc), with its
/// footprint, in one row of 80 bytes: the step's end reads only this row for each entry (its
/// `stays` and the footprint's `s_range`), and an entity that stays writes only the fields
/// that moved (its footprint's s, s-range and speed, and `stays`; `LaneIndex::stay`).
#[derive(Debug, Clone, Copy)]
pub(super) struct Kept {
    /// The entity's footprint in this step (with `entered`): its s-range is the one its
    /// staying entries take, its t-range the one its lanes were decided for (with `lanes`),
    /// its handle the one the road position's lane look-up found, whose road is the road of
    /// the lanes.
    pub footprint: Footprint,
    /// The section at s the lanes were decided in (with `lanes`).
    pub section: u32,
    /// The generation of the kept borders the lanes were decided by (with `lanes`).
    pub borders: u32,
    /// The entity is entered in this step: `footprint` holds.
    pub entered: bool,
    /// Its entries are in lanes of its own road decided by kept borders: `footprint`'s
    /// t-range, `section` and `borders` hold.
    pub lanes: bool,
    /// Its entries of the last step stay in this step (only their s-range is new).
    pub stays: bool,
}

// The row's size as its doc says.
const _: () = assert!(std::mem::size_of::<Kept>() == 80);

impl Kept {
    /// Nothing kept: an entity not on the road, or a full build.
    pub const NONE: Kept = Kept {
        footprint: Footprint {
            handle: LaneHandle {
                road: 0,
                section: 0,
                lane: 0,
            },
            s: 0.0,
            s_range: (0.0, 0.0),
            t_range: (0.0, 0.0),
            speed_s: 0.0,
        },
        section: 0,
        borders: 0,
        entered: false,
        lanes: false,
        stays: false,
    };
}

/// An entity's box seen from its reference point: the least and the greatest s-offset of its
/// corners, kept with the bits of what they and the footprint's t-range were worked out from
/// (module doc "The box's s-range").
#[derive(Debug, Clone, Copy)]
pub(super) struct BoxKept {
    /// The bits of the reference point's t, the heading relative to the road, and the box's
    /// centre x and y, length and width.
    pub key: [u64; 6],
    /// The least and the greatest s-offset of the box's corners (NaN: none kept).
    pub ds: (Real, Real),
}

impl BoxKept {
    /// Whether `key` is this one's, bit for bit (each word compared, no call to `memcmp`).
    #[inline(always)]
    pub fn holds(&self, key: &[u64; 6]) -> bool {
        let k = &self.key;
        (k[0] ^ key[0])
            | (k[1] ^ key[1])
            | (k[2] ^ key[2])
            | (k[3] ^ key[3])
            | (k[4] ^ key[4])
            | (k[5] ^ key[5])
            == 0
    }

    /// Nothing kept.
    pub const NONE: BoxKept = BoxKept {
        key: [0; 6],
        ds: (Real::NAN, Real::NAN),
    };
}

/// The s-range of a box whose corners' s-offsets range over `ds` at the reference point `s`,
/// where both ends of (s + ds.0, s + ds.1) are finite and not zero: there it is the s-range
/// `LaneIndex`'s `box_ranges` folds from the corners, bit for bit (module doc "The box's
/// s-range"); `None` elsewhere.
#[inline(always)]
pub(super) fn shifted(s: Real, ds: (Real, Real)) -> Option<(Real, Real)> {
    let (lo, hi) = (s + ds.0, s + ds.1);
    // Finite and not zero: false for NaN, ±0 and ±∞ (two comparisons of |x|).
    let usable = |x: Real| 0.0 < x.abs() && x.abs() < Real::INFINITY;
    (usable(lo) && usable(hi)).then_some((lo, hi))
}

/// The order of a lane's entries (module doc "The order").
#[inline]
pub(super) fn entry_order(a: &Entry, b: &Entry) -> Ordering {
    a.lo.total_cmp(&b.lo).then(a.id.cmp(&b.id))
}

/// Entry moves an insertion pass may make per entry (plus a few) before the list is sorted in
/// full instead.
const MOVES_PER_ENTRY: usize = 4;

/// Whether `a` comes after `b` in [`entry_order`], with the plain comparison first: where
/// `a.lo < b.lo` (false when either is NaN) the two are numbers in increasing order, and
/// `total_cmp` orders numbers as `<` does (it only adds −0 before +0, which `<` calls equal,
/// and places NaN), so `entry_order` is `Less`; only where it fails is the full order asked.
/// On a lane in order (nearly every lane at nearly every step) that is one comparison per entry
/// where `entry_order` took a dozen instructions (issue 31).
#[inline(always)]
fn after(a: &Entry, b: &Entry) -> bool {
    if a.lo < b.lo {
        return false;
    }
    entry_order(a, b) == Ordering::Greater
}

/// Sorts `entries` by [`entry_order`], repairing by insertion the list as it is (the last
/// step's order with the new s-ranges, the new entries at the end), and returns the lane's
/// bounds ([`bounds`] of the sorted list). A list already in order is checked and its bounds
/// folded in one pass: the fold meets the entries in the order they stay in, so its bits are
/// those of [`bounds`] after the sort. Elsewhere the list is repaired from the first entry out
/// of order ([`repair_order`]) and the bounds are folded anew.
pub(super) fn order_and_bounds(entries: &mut [Entry]) -> (Real, bool) {
    let (mut max_len, mut unordered) = (0.0, false);
    for i in 0..entries.len() {
        if i > 0 && after(&entries[i - 1], &entries[i]) {
            repair_order(entries, i);
            return bounds(entries);
        }
        let e = &entries[i];
        max_len = Real::max(max_len, e.hi - e.lo);
        unordered |= e.lo.is_nan();
    }
    (max_len, unordered)
}

/// A lane's bounds: its longest footprint (hi − lo, folded from 0 in the list's order) and
/// whether some lo is NaN (`LaneEntries::max_len`, `LaneEntries::unordered`).
pub(super) fn bounds(entries: &[Entry]) -> (Real, bool) {
    let (mut max_len, mut unordered) = (0.0, false);
    for e in entries {
        max_len = Real::max(max_len, e.hi - e.lo);
        unordered |= e.lo.is_nan();
    }
    (max_len, unordered)
}

/// Sorts `entries`, whose first `from` are in [`entry_order`], by insertion from entry `from`
/// on, and in full when that would move entries more than [`MOVES_PER_ENTRY`] places each on
/// the whole. (lo, id) is a total order, so either way the list is the one sorted list.
pub(super) fn repair_order(entries: &mut [Entry], from: usize) {
    let mut budget = MOVES_PER_ENTRY * entries.len() + 16;
    for i in from.max(1)..entries.len() {
        let mut j = i;
        while j > 0 && after(&entries[j - 1], &entries[j]) {
            if budget == 0 {
                entries.sort_unstable_by(entry_order);
                return;
            }
            budget -= 1;
            entries.swap(j - 1, j);
            j -= 1;
        }
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A small deterministic generator in [0, 1) (64-bit LCG, Knuth's constants): the
    /// engine's tests' one (controller/test_world.rs re-exports it).
    pub(crate) fn generator(seed: u64) -> impl FnMut() -> f64 {
        let mut state = seed;
        move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 33) as f64 / (1u64 << 31) as f64
        }
    }

    /// The repair gives the order of a full sort and the bounds folded over it, bit for bit,
    /// from nearly sorted lists (a few entries out of place, new ones at the end) and from
    /// lists in no order at all (the fallback), with repeated lo, −0 and +0, NaN and
    /// infinities, and lengths of +0 and −0 (hi −0 over lo +0: `max` of ±0 depends on the
    /// fold's order, so the bounds must be folded in the sorted order).
    #[test]
    fn the_repaired_order_is_the_sorted_order() {
        let mut next = generator(0x9e37_79b9_7f4a_7c15);
        let specials = [
            0.0,
            -0.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            -f64::NAN,
        ];
        let mut checked = 0;
        for n in [0usize, 1, 2, 3, 10, 64, 500] {
            for disorder in [0usize, 1, 3, n / 2, n] {
                let mut entries: Vec<Entry> = (0..n)
                    .map(|i| {
                        let lo = (next() * 50.0).round() * 0.5;
                        Entry {
                            lo,
                            hi: lo + [4.5, 0.0, 12.0][i % 3],
                            id: EntityId(i as u32),
                        }
                    })
                    .collect();
                entries.sort_unstable_by(entry_order);
                for k in 0..if n == 0 { 0 } else { disorder } {
                    let i = (next() * n as f64) as usize % n;
                    entries[i].lo = if k % 7 == 3 {
                        specials[k % specials.len()]
                    } else {
                        entries[i].lo + (next() - 0.5) * 20.0
                    };
                    if k % 5 == 2 {
                        (entries[i].lo, entries[i].hi) = (0.0, -0.0);
                    }
                }
                checked += check(entries);
            }
        }
        assert_eq!(checked, 35);
        // Neighbours the plain comparison cannot order: −0 before +0 and after it, equal lo
        // with ids in and out of order, NaN of either sign, infinities; lengths −0 and +0 in
        // both orders (max(+0, −0) and max(−0, +0)).
        let e = |lo: Real, hi: Real, id: u32| Entry {
            lo,
            hi,
            id: EntityId(id),
        };
        let nan = f64::NAN;
        let lists = [
            vec![e(-0.0, 4.0, 1), e(0.0, 4.0, 0)],
            vec![e(0.0, 4.0, 0), e(-0.0, 4.0, 1)],
            vec![e(1.0, 5.0, 2), e(1.0, 5.0, 1), e(1.0, 5.0, 3)],
            vec![e(1.0, 5.0, 0), e(nan, 5.0, 1), e(2.0, 5.0, 2)],
            vec![e(-nan, 5.0, 0), e(1.0, 5.0, 1), e(nan, 5.0, 2)],
            vec![e(1.0, 5.0, 1), e(-nan, 5.0, 0)],
            vec![e(f64::NEG_INFINITY, 0.0, 0), e(0.0, f64::INFINITY, 1)],
            vec![e(0.0, -0.0, 0), e(0.0, 0.0, 1)],
            vec![e(0.0, 0.0, 1), e(0.0, -0.0, 0)],
            vec![e(0.0, -0.0, 0), e(1.0, 1.0, 1)],
            vec![e(1.0, 1.0, 1), e(0.0, -0.0, 0)],
        ];
        for list in lists {
            checked += check(list);
        }
        assert_eq!(checked, 46);
    }

    /// `order_and_bounds` of `entries` against the full sort and the bounds folded over it,
    /// bit for bit; 1.
    fn check(mut entries: Vec<Entry>) -> usize {
        let mut expected = entries.clone();
        expected.sort_unstable_by(entry_order);
        let (max_len, unordered) = bounds(&expected);
        let got = order_and_bounds(&mut entries);
        let bits = |v: &[Entry]| -> Vec<(u64, u64, u32)> {
            v.iter()
                .map(|e| (e.lo.to_bits(), e.hi.to_bits(), e.id.0))
                .collect()
        };
        let n = entries.len();
        assert!(
            bits(&entries) == bits(&expected),
            "the order of {n} entries"
        );
        assert!(
            (got.0.to_bits(), got.1) == (max_len.to_bits(), unordered),
            "bounds {got:?} against {:?} of {n} entries",
            (max_len, unordered)
        );
        1
    }
}
