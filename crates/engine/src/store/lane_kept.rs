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
//! step, with a full build of the same step kept beside it ([`assert_same`]): the lanes' entries
//! in order, their bounds and flags, every footprint and driver input, bit for bit.

use std::cmp::Ordering;

use opendrive::{LaneHandle, Real};

#[cfg(any(test, debug_assertions))]
use super::driver_inputs::DriverInput;
use super::lane_index::Entry;
#[cfg(any(test, debug_assertions))]
use super::lane_index::{Footprint, LaneIndex};

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

/// Panics unless `kept` (the index kept from step to step) and `full` (built anew for the same
/// step) give the same answers: the same non-empty lanes with the same entries in the same
/// order, bounds and flags, the same footprints and driver inputs, bit for bit. Allocates
/// nothing (the step's allocation test runs it).
#[cfg(any(test, debug_assertions))]
pub(super) fn assert_same(kept: &LaneIndex, full: &LaneIndex) {
    let entry = |e: &Entry| (e.lo.to_bits(), e.hi.to_bits(), e.id);
    assert_eq!(kept.touched.len(), full.touched.len(), "lanes with entries");
    for &slot in &full.touched {
        let (k, f) = (&kept.lanes[slot], &full.lanes[slot]);
        assert!(
            k.entries.len() == f.entries.len()
                && k.entries
                    .iter()
                    .zip(&f.entries)
                    .all(|(a, b)| entry(a) == entry(b))
                && k.max_len.to_bits() == f.max_len.to_bits()
                && k.unordered == f.unordered,
            "the kept lane {slot} is not the full build's: {k:?} against {f:?}"
        );
    }
    let footprint = |f: &Footprint| {
        (
            f.handle,
            [
                f.s,
                f.s_range.0,
                f.s_range.1,
                f.t_range.0,
                f.t_range.1,
                f.speed_s,
            ]
            .map(f64::to_bits),
        )
    };
    assert_eq!(kept.footprints.len(), full.footprints.len(), "footprints");
    for (i, (k, f)) in kept.footprints.iter().zip(&full.footprints).enumerate() {
        assert!(
            k.as_ref().map(footprint) == f.as_ref().map(footprint),
            "entity {i}'s kept footprint {k:?} is not the full build's {f:?}"
        );
    }
    let input = |d: &DriverInput| {
        (
            d.id,
            d.placed,
            d.lateral_action,
            d.speed.to_bits(),
            d.track.map(|t| {
                (
                    t.road,
                    t.lane_id,
                    t.s.to_bits(),
                    t.direction,
                    t.blend_from,
                    t.own,
                )
            }),
        )
    };
    assert_eq!(kept.inputs.len(), full.inputs.len(), "driver inputs");
    for (i, (k, f)) in kept.inputs.iter().zip(&full.inputs).enumerate() {
        assert!(
            k.as_ref().map(input) == f.as_ref().map(input),
            "entity {i}'s driver input {k:?} is not the full build's {f:?}"
        );
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::domain::{BoundingBox, Vector3};
    use crate::position::lane_at;
    use crate::store::World;
    use crate::world::entity::{Entity, EntityId, EntityKind};
    use opendrive::{Direction, RoadNetwork};
    use std::sync::Arc;

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

    /// A car of `length` × 2 m whose box centre is 1.4 m ahead of its reference point.
    fn car(i: u32, length: Real) -> Entity {
        let b = BoundingBox::new(Vector3::new(1.4, 0.0, 0.75), length, 2.0, 1.5).expect("box");
        Entity::new(EntityId(i), &format!("c{i}"), EntityKind::Vehicle, b)
    }

    /// Places car `id` at a random s of a random road, in the middle of a random lane there
    /// (driving along the lane's direction under right-hand traffic), or off its centre.
    fn place_randomly(w: &mut World, id: EntityId, next: &mut impl FnMut() -> f64) {
        let net = Arc::clone(&w.network);
        for _ in 0..20 {
            let road = &net.roads()[(next() * net.roads().len() as f64) as usize];
            let s = next() * road.length;
            let lanes: Vec<i32> = road
                .lane_section_at(s)
                .lanes()
                .filter(|l| l.id != 0)
                .map(|l| l.id)
                .collect();
            if lanes.is_empty() {
                continue;
            }
            let lane = lanes[(next() * lanes.len() as f64) as usize];
            let Ok(span) = road.lane_span(lane, s) else {
                continue;
            };
            let off = if next() < 0.8 { 0.0 } else { next() - 0.5 };
            let t = 0.5 * (span.inner + span.outer) + off;
            let Ok(mut pose) = road.pose(s, t) else {
                continue;
            };
            if lane > 0 {
                pose.h += std::f64::consts::PI;
            }
            let found = net.locate(pose.x, pose.y, Some(pose.h));
            w.place_resolved(id, pose, found);
            return;
        }
    }

    /// Moves car `i` `ds` along its direction of travel on its road, its t and heading relative
    /// to the road kept (as a vehicle following a lane), or shifted by `dt` (a lane change);
    /// off the road's ends it is placed anew.
    fn drive(w: &mut World, i: usize, ds: Real, dt: Real, next: &mut impl FnMut() -> f64) {
        let net = Arc::clone(&w.network);
        let e = &mut w.entities[i];
        let (Some(rp), Some(track)) = (e.road_position.as_mut(), e.track.as_mut()) else {
            return place_randomly(w, EntityId(i as u32), next);
        };
        let road = net.road_at(rp.road);
        let s = match track.direction {
            Direction::Forward => rp.s + ds,
            Direction::Backward => rp.s - ds,
        };
        let t = rp.t + dt;
        let (Some((lane, offset)), Ok(pose)) = (lane_at(road, s, t), road.pose(s, t)) else {
            return place_randomly(w, EntityId(i as u32), next);
        };
        (rp.s, rp.t, rp.lane_id, rp.offset) = (s, t, lane, offset);
        (track.s, track.t) = (s, t);
        if dt != 0.0 {
            track.lane_id = lane;
        }
        e.pose.x = pose.x;
        e.pose.y = pose.y;
        e.pose.h = pose.h + rp.relative_heading;
        e.speed = ds / 0.05;
    }

    /// The kept index gives a full build's answers, step after step, in random traffic on
    /// corpus roads with junctions (fabriksgatan), lane sections and lanes that widen
    /// (two_plus_one) and a highway (e6mini): cars following their lane at various speeds in
    /// both directions (their entries stay), drifting across lane borders, jumping elsewhere,
    /// hidden from traffic, taken off the road and put back, their boxes and headings changed,
    /// a car spawned midway. Each step the kept index is compared with the step's full build
    /// (the lanes' entries in order, bounds and flags, footprints, driver inputs, bit for bit);
    /// most entries stay, and every kind of change happens.
    #[test]
    fn a_kept_index_gives_the_full_builds_answers_in_random_traffic() {
        let corpus = |name: &str| {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../../../shared/corpus/esmini/xodr")
                .join(name);
            Arc::new(RoadNetwork::from_file(&path).unwrap_or_else(|e| panic!("{e}")))
        };
        let mut next = generator(0x5851_f42d_4c95_7f2d);
        let mut steps = 0;
        let mut shares = Vec::new();
        for name in ["fabriksgatan.xodr", "two_plus_one.xodr", "e6mini.xodr"] {
            let (mut stayed, mut entered) = (0usize, 0usize);
            let net = corpus(name);
            let cars = 80;
            let entities = (0..cars).map(|i| car(i, 4.0 + (i % 4) as Real)).collect();
            let mut w = World::new(Arc::clone(&net), entities);
            for i in 0..cars {
                place_randomly(&mut w, EntityId(i), &mut next);
            }
            let mut kept = LaneIndex::default();
            for step in 0..200 {
                if step == 100 {
                    let id = w.spawn(car(0, 5.0));
                    place_randomly(&mut w, id, &mut next);
                }
                for i in 0..w.entities.len() {
                    let ds = 0.05 * 30.0 * next();
                    match next() {
                        x if x < 0.85 => drive(&mut w, i, ds, 0.0, &mut next),
                        x if x < 0.90 => drive(&mut w, i, ds, 0.7 * (next() - 0.5), &mut next),
                        x if x < 0.92 => place_randomly(&mut w, EntityId(i as u32), &mut next),
                        x if x < 0.94 => {
                            let v = &mut w.entities[i].visibility.traffic;
                            *v = !*v;
                        }
                        x if x < 0.95 => {
                            let p = &mut w.entities[i].placed;
                            *p = !*p;
                        }
                        x if x < 0.97 => {
                            let length = 3.0 + 10.0 * next();
                            w.entities[i].bounding_box = car(0, length).bounding_box;
                        }
                        x if x < 0.98 => {
                            if let Some(rp) = w.entities[i].road_position.as_mut() {
                                rp.relative_heading += 0.2 * (next() - 0.5);
                            }
                        }
                        _ => {}
                    }
                }
                kept.rebuild(&net, w.entities());
                let full = LaneIndex::build(&net, w.entities());
                assert_same(&kept, &full);
                stayed += kept.kept.iter().filter(|k| k.stays).count();
                entered += kept.footprints.iter().flatten().count();
                steps += 1;
            }
            shares.push(stayed as f64 / entered as f64);
        }
        assert_eq!(steps, 600);
        // About 85 % of the cars follow their lane in a step; their entries stay but where a
        // junction's road, a new section or borders made at each s (a lane widening,
        // store/lane_slots.rs) are under them: measured 37 % of the entered cars in the town,
        // 68 % on two_plus_one, 88 % on the highway.
        assert!(shares.iter().all(|&f| f > 0.3), "{shares:?}");
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
