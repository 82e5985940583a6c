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
//! **The order.** The entries of a lane are sorted by (lo, id), a total order (`total_cmp`,
//! an entity once per lane), so any correct sort gives the one order there is. Vehicles in a
//! lane keep their order from step to step but for the few that change lanes or pass through,
//! so the list is repaired by insertion (linear on a sorted list) and sorted in full when the
//! repair would move more than a few entries per entry ([`repair_order`]).
//!
//! **Checked.** In debug builds (every `cargo test`) each kept index is compared, after every
//! step, with a full build of the same step kept beside it (`LaneIndex::assert_same_as`): the
//! lanes' entries in order, their bounds and flags, every footprint and driver input, bit for
//! bit (and store/lane_kept_tests.rs in random traffic).

use std::cmp::Ordering;

use opendrive::{LaneHandle, Real};

use crate::world::entity::EntityId;

/// One entity's footprint in one lane: the s-range of its box, by lo.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Entry {
    pub lo: Real,
    pub hi: Real,
    pub id: EntityId,
}

/// What the index keeps of one entity from one step to the next (module doc), in one row of
/// 56 bytes: the step's end reads only this row for each entry (its `stays` and `s_range`).
#[derive(Debug, Clone, Copy)]
pub(super) struct Kept {
    /// The s-range of the entity's box in this step: its staying entries take it.
    pub s_range: (Real, Real),
    /// The bits of the t-range of the box its lanes were decided for (with `lanes`).
    pub t_range: (u64, u64),
    /// The handle the road position's lane look-up found (with `has_handle`); its road is the
    /// road of the lanes.
    pub handle: LaneHandle,
    /// The section at s the lanes were decided in (with `lanes`).
    pub section: u32,
    /// The generation of the kept borders the lanes were decided by (with `lanes`).
    pub borders: u32,
    /// `handle` holds.
    pub has_handle: bool,
    /// Its entries are in lanes of its own road decided by kept borders: `t_range`,
    /// `section` and `borders` hold.
    pub lanes: bool,
    /// Its entries of the last step stay in this step (only their s-range is new).
    pub stays: bool,
}

// The row's size as its doc says.
const _: () = assert!(std::mem::size_of::<Kept>() == 56);

impl Kept {
    /// Nothing kept: an entity not on the road, or a full build.
    pub const NONE: Kept = Kept {
        s_range: (0.0, 0.0),
        t_range: (0, 0),
        handle: LaneHandle {
            road: 0,
            section: 0,
            lane: 0,
        },
        section: 0,
        borders: 0,
        has_handle: false,
        lanes: false,
        stays: false,
    };
}

/// The order of a lane's entries (module doc "The order").
#[inline]
pub(super) fn entry_order(a: &Entry, b: &Entry) -> Ordering {
    a.lo.total_cmp(&b.lo).then(a.id.cmp(&b.id))
}

/// Entry moves an insertion pass may make per entry (plus a few) before the list is sorted in
/// full instead.
const MOVES_PER_ENTRY: usize = 4;

/// Sorts `entries` by [`entry_order`]: by insertion from the list as it is (the last step's
/// order with the new s-ranges, the new entries at the end), and in full when that would move
/// entries more than [`MOVES_PER_ENTRY`] places each on the whole.
pub(super) fn repair_order(entries: &mut [Entry]) {
    let mut budget = MOVES_PER_ENTRY * entries.len() + 16;
    for i in 1..entries.len() {
        let mut j = i;
        while j > 0 && entry_order(&entries[j - 1], &entries[j]) == Ordering::Greater {
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
pub(super) mod tests {
    use super::*;

    /// A small deterministic generator in [0, 1) (64-bit LCG, Knuth's constants).
    pub(in crate::store) fn generator(seed: u64) -> impl FnMut() -> f64 {
        let mut state = seed;
        move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 33) as f64 / (1u64 << 31) as f64
        }
    }

    /// The repair gives the order of a full sort, from nearly sorted lists (a few entries out
    /// of place, new ones at the end) and from lists in no order at all (the fallback), with
    /// repeated lo, −0 and +0, NaN and infinities.
    #[test]
    fn the_repaired_order_is_the_sorted_order() {
        let mut next = generator(0x9e37_79b9_7f4a_7c15);
        let specials = [0.0, -0.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
        let mut checked = 0;
        for n in [0usize, 1, 2, 3, 10, 64, 500] {
            for disorder in [0usize, 1, 3, n / 2, n] {
                let mut entries: Vec<Entry> = (0..n)
                    .map(|i| Entry {
                        lo: (next() * 50.0).round() * 0.5,
                        hi: 0.0,
                        id: EntityId(i as u32),
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
                }
                let mut expected = entries.clone();
                expected.sort_unstable_by(entry_order);
                repair_order(&mut entries);
                let bits = |v: &[Entry]| -> Vec<(u64, u32)> {
                    v.iter().map(|e| (e.lo.to_bits(), e.id.0)).collect()
                };
                assert_eq!(bits(&entries), bits(&expected), "n {n} disorder {disorder}");
                checked += 1;
            }
        }
        assert_eq!(checked, 35);
    }
}
