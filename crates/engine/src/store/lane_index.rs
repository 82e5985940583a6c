//! A per-lane index of the entities on the road, built once per step, for the gap searches of
//! the driver models: "the nearest entity ahead (or behind) whose bounding box overlaps the
//! lane, along the lane the entity will take" (issue 13; OpenDRIVE 1.8 §11 lanes, §11.4 lane
//! linkage, §12 junctions).
//!
//! **Footprints.** Each placed entity that stands on a road and is visible to traffic
//! (VisibilityAction `traffic`, OpenSCENARIO 1.3 §7.7.2.3) gets the footprint of its bounding
//! box in its road's reference-line frame: the box corners turned by the heading relative to
//! the road, giving an s-range and a t-range (the local linearisation at the reference point;
//! on a curve of radius R the box's length is off by a factor 1 ± t/R, under 1 % for a
//! highway's R ≥ 1 km). The entity is entered in every lane of that lane section whose borders
//! its t-range overlaps, so a vehicle changing lanes is in both lanes (and in its new lane only
//! once its box reaches it: until then controller/one_gap.rs weighs the change under way by the
//! entity's lane track, a driver model's or a storyboard LaneChangeAction's alike, against a
//! driver model's change into the same lane). An entity on a road of a
//! junction is entered as well on the other roads of that junction whose surface holds the
//! centre of its box, in the lanes its box overlaps there: crossing traffic inside a junction
//! is seen from the connecting road taken.
//!
//! **Queries.** [`LaneIndex::nearest`] walks from an s on a lane in a direction of travel,
//! section by section and through lane links and junctions (the successor the caller's choice
//! picks, else the first in the road model's order, as the default controller drives), and
//! returns the first entity whose footprint reaches past the start point, with the gap between
//! the start point and the near end of its footprint (0 when they overlap). The distances are
//! reference-line distances (Δs), which is the distance along a lane up to the factor
//! 1 − κ·t of a curved road.
//!
//! **Cost.** Building is O(n log n) for n entities (one sort per lane); a query is a binary
//! search per lane visited plus a short scan bounded by the longest footprint in that lane, so
//! a step of n queries is O(n log n), not the O(n²) of comparing every pair. The index is
//! brought up to date in place each step ([`LaneIndex::rebuild`]): its lanes are a vector by
//! dense lane number and the lane borders are kept where the road's lanes are constant
//! (store/lane_slots.rs), no road id is hashed, and the step allocates nothing once the
//! vectors have grown (issue 31). An entity whose road, lane section, box t-range and kept
//! borders did not change keeps its entries and lane handle of the last step, only their
//! s-range new (and only its footprint's s, s-range and speed written), and each lane's order
//! is checked and repaired by insertion (store/lane_kept.rs, which says why the answers are a
//! full build's, and checks it in debug builds).
//!
//! **Hints.** A search starts with the index of the first entry not before its start point
//! (`partition_point`). The driver models ask the same questions of the same entity every
//! step, and the lists change little between steps, so each kind of question keeps, per
//! entity, the index it found the last time, and the next search walks from there ([`WALK`]
//! entries, then halves the rest). The index is the same as `partition_point`'s: the list is
//! sorted by lo, so "lo < from" holds on a prefix of it and fails on the rest, and the walk
//! stops where the prefix ends, wherever it starts. Where a lo is NaN that is not so, and the
//! search is `partition_point` alone, as it was.
//!
//! **The last answer re-validated.** The questions a driver model asks each step are its
//! leader (the nearest ahead from its front bumper in its own lane), whether a lane beside is
//! occupied alongside (any entry overlapping its own s-range), and the leader and follower
//! there. Each step the answer is usually where the hint points: the nearest ahead is the
//! entry at the hint (the entity itself, or an entry starting well before, the one before
//! it), the nearest behind the entry just before the hint, an occupant the entry just before
//! the hint. Where the entries there prove that the search would give that answer
//! ([`ahead_at_hint`], [`behind_at_hint`], [`occupied_at_hint`]: a few comparisons whose
//! proof is the lane's order), it is returned without the search; where they do not, the
//! search runs as before. The same answers bit for bit (the proofs at the functions;
//! `store::lane_search_tests`).

use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::Arc;

use opendrive::{Direction, LaneHandle, Real, Road, RoadHandle, RoadNetwork, RoadPosition};

use super::driver_inputs::DriverInput;
pub use super::lane_kept::Footprint;
use super::lane_kept::{bounds, entry_order, order_and_bounds, shifted, BoxKept, Entry, Kept};
use super::lane_slots::{LaneBorders, LaneSlots};
use crate::world::entity::{Entity, EntityId};
use crate::world::lanes::{next_lane, section_end};
use crate::world::zero_angle;

/// Overlap (m) of a box's t-range with a lane's borders below which the box is not in the lane
/// (a box touching the lane marking is not in the next lane).
const LANE_OVERLAP: Real = 1e-3;
/// A located point farther than this (m) from every lane is off the road (store/world.rs
/// uses the same for lane tracks).
const ON_ROAD: Real = 0.5;
/// Most lane sections a query walks through (short junction roads, loops).
pub(super) const MAX_HOPS: usize = 64;

/// The entries of one lane section's lane, sorted by (lo, id).
#[derive(Debug, Clone, Default)]
pub(super) struct LaneEntries {
    pub entries: Vec<Entry>,
    /// Longest footprint (hi − lo) in the lane: bounds the backward scans.
    pub max_len: Real,
    /// Some entry's lo is NaN: "lo < x" is then not monotone along the list, and searches
    /// take the binary search alone (its answer is the one there is only when it is).
    pub unordered: bool,
    /// The lane is in `LaneIndex::touched`.
    listed: bool,
}

/// Query kinds per entity whose last answers are kept as hints ([`LaneIndex::hint`]).
pub const HINTS: usize = 9;
/// Entries a hinted search walks from its hint before it searches the rest by halves.
const WALK: usize = 4;

/// The first index of `entries` whose `lo` is not below `from` (`partition_point`), found
/// from the position `hint` gave the last time, which is stored back (module doc "Hints").
fn position(lane: &LaneEntries, from: Real, hint: Option<&AtomicU32>) -> usize {
    let entries = &lane.entries[..];
    let below = |e: &Entry| e.lo < from;
    let Some(hint) = hint.filter(|_| !lane.unordered && !from.is_nan()) else {
        return entries.partition_point(below);
    };
    let n = entries.len();
    let mut g = (hint.load(Ordering::Relaxed) as usize).min(n);
    let mut found = None;
    for _ in 0..WALK {
        if g < n && below(&entries[g]) {
            g += 1;
        } else if g > 0 && !below(&entries[g - 1]) {
            g -= 1;
        } else {
            found = Some(g);
            break;
        }
    }
    let p = found.unwrap_or_else(|| {
        if g < n && below(&entries[g]) {
            g + 1 + entries[g + 1..].partition_point(below)
        } else {
            entries[..g].partition_point(below)
        }
    });
    hint.store(p as u32, Ordering::Relaxed);
    p
}

/// What a query found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Neighbour {
    /// The entity.
    pub id: EntityId,
    /// Gap from the query's start point to the near end of its footprint (m of s, ≥ 0).
    pub gap: Real,
    /// The query's direction of travel on the lane where the entity was found.
    pub direction: Direction,
}

/// `found` after `walked` m of the walk: its gap from the walk's start, if within `horizon`.
#[inline]
pub(super) fn within(found: Neighbour, walked: Real, horizon: Real) -> Option<Neighbour> {
    let gap = walked + found.gap;
    (gap <= horizon).then_some(Neighbour { gap, ..found })
}

/// The lane look-up [`LaneIndex::enter_with_input`] made for an entity's footprint: road, lane, s and the
/// lane's handle.
type LookedUp = (RoadHandle, i32, Real, LaneHandle);

/// The per-lane index of one step (module doc).
#[derive(Debug, Default)]
pub struct LaneIndex {
    /// The network's lane numbering (made at the first build on a network).
    slots: Option<LaneSlots>,
    /// By slot; only the slots in `touched` have entries.
    pub(super) lanes: Vec<LaneEntries>,
    /// The lanes with entries, each once.
    pub(super) touched: Vec<usize>,
    borders: LaneBorders,
    /// [`HINTS`] per entity: where each kind of search found its answer the last time.
    hints: Vec<AtomicU32>,
    /// The driver models' inputs, by entity index (store/driver_inputs.rs).
    pub(super) inputs: Vec<Option<DriverInput>>,
    /// By entity index: its footprint and what this step keeps for the next
    /// (store/lane_kept.rs).
    pub(super) kept: Vec<Kept>,
    /// By entity index: its box's s-offsets from its last entry in full (store/lane_kept.rs
    /// "The box's s-range").
    boxes: Vec<BoxKept>,
    /// The entries made anew in this step's walk, by slot, before they join their lanes.
    pub(super) pending: Vec<(usize, Entry)>,
    /// The entities the last moves' walk entered (the first `moved`; 0 where it entered none),
    /// whose entries stand until they are written (store/lane_refresh.rs).
    pub(super) moved: usize,
    /// The index of the same step built in full, to check this one against (debug builds).
    #[cfg(debug_assertions)]
    full: Option<Box<LaneIndex>>,
}

/// Where `e` stands to be entered (module doc "Footprints"): its road position, where it is
/// placed, visible to traffic and within [`ON_ROAD`] of a road of `net`; that road, taken by
/// the handle the position carries (the world's network made it), not by its id: no look-up,
/// no read of the id string; and the handle (road, the lane section at s, the position's lane).
#[inline(always)]
fn standing<'a>(
    net: &'a RoadNetwork,
    e: &'a Entity,
) -> Option<(&'a RoadPosition, &'a Road, LaneHandle)> {
    if !e.placed || !e.visibility.traffic {
        return None;
    }
    let rp = e
        .road_position
        .as_ref()
        .filter(|rp| rp.distance <= ON_ROAD)?;
    let road = net.roads().get(rp.road.index())?;
    let handle = LaneHandle {
        road: rp.road.0,
        section: road.lane_section_index(rp.s) as u32,
        lane: rp.lane_id,
    };
    Some((rp, road, handle))
}

/// The velocity component of `e` along +s (m/s) where its heading relative to the road's +s is
/// `rel`: its speed signed by its lane track's direction, else projected.
#[inline(always)]
fn speed_along_s(e: &Entity, rel: Real) -> Real {
    match &e.track {
        Some(track) if track.direction == Direction::Forward => e.speed,
        Some(_) => -e.speed,
        None => e.speed * rel.cos(),
    }
}

/// The bits of what `e`'s box ranges at the road position `rp` are worked out from but its s
/// ([`BoxKept::key`]).
#[inline(always)]
fn box_key(e: &Entity, rp: &RoadPosition) -> [u64; 6] {
    let b = &e.bounding_box;
    let c = b.center();
    [rp.t, rp.relative_heading, c.x, c.y, b.length(), b.width()].map(Real::to_bits)
}

/// The s- and t-ranges of `e`'s box on a road where its reference point is at (s, t) and its
/// heading relative to the road's +s is `rel`, folded from its four corners, and the range of
/// the corners' s-offsets (store/lane_kept.rs "The box's s-range").
fn box_ranges(
    e: &Entity,
    s: Real,
    t: Real,
    rel: Real,
) -> ((Real, Real), (Real, Real), (Real, Real)) {
    let b = &e.bounding_box;
    let c = b.center();
    let (hl, hw) = (0.5 * b.length(), 0.5 * b.width());
    // Exactly 0 for a vehicle following its lane (world/zero_angle.rs: libm's bits).
    let (sin, cos) = zero_angle::sin_cos(rel);
    let mut s_range = (Real::INFINITY, Real::NEG_INFINITY);
    let mut t_range = s_range;
    let mut ds_range = s_range;
    for (dx, dy) in [(hl, hw), (hl, -hw), (-hl, hw), (-hl, -hw)] {
        let (x, y) = (c.x + dx, c.y + dy);
        let ds = x * cos - y * sin;
        let dt = x * sin + y * cos;
        s_range = (s_range.0.min(s + ds), s_range.1.max(s + ds));
        t_range = (t_range.0.min(t + dt), t_range.1.max(t + dt));
        ds_range = (ds_range.0.min(ds), ds_range.1.max(ds));
    }
    (s_range, t_range, ds_range)
}

impl LaneIndex {
    /// The index of `entities` on `net` (module doc), built in full.
    #[cfg(test)]
    pub fn build(net: &Arc<RoadNetwork>, entities: &[Entity]) -> Self {
        let mut index = LaneIndex::default();
        index.walk(net, entities, false);
        index
    }

    /// Makes this the index of `entities` on `net` (their ids are their indices), reusing its
    /// storage and keeping what did not change since the last call (module doc,
    /// store/lane_kept.rs). In debug builds it is checked against a full build.
    /// `written`: by entity index, written since the last moves' walk entered it
    /// (store/lane_refresh.rs: only those are entered anew when that walk entered the rest).
    pub fn rebuild(&mut self, net: &Arc<RoadNetwork>, entities: &[Entity], written: &[bool]) {
        if !self.refresh(net, entities, written) {
            self.walk(net, entities, true);
        }
        self.moved = 0;
        #[cfg(debug_assertions)]
        {
            let mut full = self.full.take().unwrap_or_default();
            full.walk(net, entities, false);
            self.assert_same_as(&full);
            self.full = Some(full);
        }
    }

    /// Builds the index of `entities` on `net` in this storage: every entry made anew
    /// (`keep` false), or kept where it may be (store/lane_kept.rs).
    fn walk(&mut self, net: &Arc<RoadNetwork>, entities: &[Entity], keep: bool) {
        if !self.numbers(net) {
            let slots = LaneSlots::new(net);
            self.lanes.clear();
            self.lanes.resize_with(slots.len(), LaneEntries::default);
            self.touched.clear();
            self.borders.clear();
            self.kept.clear();
            self.boxes.clear();
            // The rows' own lane slots are of the numbering (store/driver_inputs.rs).
            self.inputs.clear();
            self.slots = Some(slots);
        }
        if !keep {
            for slot in self.touched.drain(..) {
                let lane = &mut self.lanes[slot];
                lane.entries.clear();
                lane.listed = false;
            }
        }
        self.fit(entities.len());
        // From the last entity to the first: the moves' walk (controller/stage.rs) that
        // ended the step before went from the first to the last, so the entities it touched
        // last are the ones still in the core's cache, and this walk meets them first and
        // ends at the entities the next moves' walk starts with (at 4,000 vehicles the store,
        // 5 MB, does not stay in the 2 MB cache from one walk to the next, issue 31). The
        // index is the same in any order: the rows are per entity, and each lane's entries
        // are put in their one (lo, id) order at the end (`settle`).
        for e in entities.iter().rev() {
            self.enter_with_input(net, e, keep);
        }
        self.settle(keep, None);
    }

    /// Whether the lane numbering is `net`'s (made at the first build on it).
    pub(super) fn numbers(&self, net: &Arc<RoadNetwork>) -> bool {
        self.slots.as_ref().is_some_and(|s| s.numbers(net))
    }

    /// Sizes the per-entity rows for `n` entities and empties the pending entries.
    pub(super) fn fit(&mut self, n: usize) {
        if self.kept.len() != n {
            self.kept.resize(n, Kept::NONE);
        }
        if self.boxes.len() != n {
            self.boxes.resize(n, BoxKept::NONE);
        }
        if self.hints.len() != n * HINTS {
            self.hints.resize_with(n * HINTS, || AtomicU32::new(0));
        }
        if self.inputs.len() != n {
            self.inputs.resize(n, None);
        }
        self.pending.clear();
    }

    /// Enters `e` in the index and keeps its footprint (module doc), when it is placed, visible
    /// to traffic and on a road, and writes its driver inputs' row. With `keep`, its entries
    /// and handle of the last step stay where they are the same (store/lane_kept.rs):
    /// [`stay`](Self::stay) first, else [`enter_anew`](Self::enter_anew). The row is written
    /// in each of the two ways, so that where `e` stays (the common case) the lane look-up
    /// reaches the row's write in registers (issue 31: returned from either way, it went
    /// through memory, five values stored and loaded back per entity-step).
    #[inline]
    pub(super) fn enter_with_input(&mut self, net: &Arc<RoadNetwork>, e: &Entity, keep: bool) {
        if keep {
            if let Some(looked_up) = self.stay(net, e) {
                self.write_input(net, e, Some(looked_up));
                return;
            }
        }
        self.enter_anew_with_input(net, e, keep);
    }

    /// [`enter_anew`](Self::enter_anew) and the driver inputs' row: `enter_with_input` where
    /// `e` does not stay. Out of line, as `enter_anew`.
    #[inline(never)]
    fn enter_anew_with_input(&mut self, net: &Arc<RoadNetwork>, e: &Entity, keep: bool) {
        let looked_up = self.enter_anew(net, e, keep);
        self.write_input(net, e, looked_up);
    }

    /// Writes `e`'s driver inputs' row, `looked_up` the lane look-up made for its footprint
    /// (road, lane, s and the handle found; `None` where it was not entered): the track's
    /// lane at the track's s is the lane the road position names wherever the two agree (the
    /// common case), and its handle is the one just looked up.
    #[inline(always)]
    fn write_input(&mut self, net: &RoadNetwork, e: &Entity, looked_up: Option<LookedUp>) {
        DriverInput::write(
            &mut self.inputs[e.id.index()],
            e,
            net,
            &self.slots,
            looked_up,
        );
    }

    /// Ends a step's build: the entries of the last step that stay take their entity's new
    /// s-range and the others leave, the new entries join their lanes, and each lane is put in
    /// order (repaired where kept, else sorted) with its bounds. `entered`: where only some
    /// entities were entered in this build (store/lane_refresh.rs), whether entity i was;
    /// the entries of the others stand as they are.
    pub(super) fn settle(&mut self, keep: bool, entered: Option<&dyn Fn(usize) -> bool>) {
        let kept = &self.kept;
        for &slot in &self.touched {
            self.lanes[slot].entries.retain_mut(|e| {
                let i = e.id.index();
                if entered.is_some_and(|entered| !entered(i)) {
                    return true;
                }
                match kept.get(i) {
                    Some(k) if k.stays => {
                        (e.lo, e.hi) = k.footprint.s_range;
                        true
                    }
                    _ => false,
                }
            });
        }
        for &(slot, entry) in &self.pending {
            let lane = &mut self.lanes[slot];
            if !lane.listed {
                lane.listed = true;
                self.touched.push(slot);
            }
            lane.entries.push(entry);
        }
        let lanes = &mut self.lanes;
        self.touched.retain(|&slot| {
            let lane = &mut lanes[slot];
            if lane.entries.is_empty() {
                lane.listed = false;
                return false;
            }
            (lane.max_len, lane.unordered) = if keep {
                order_and_bounds(&mut lane.entries)
            } else {
                // (lo, id) orders the entries of a lane totally (an entity is entered in a
                // lane once), so the unstable sort gives the one order there is.
                lane.entries.sort_unstable_by(entry_order);
                bounds(&lane.entries)
            };
            true
        });
    }

    /// The common case of [`enter_with_input`](Self::enter_with_input) with `keep`: `e`'s entries of the last step
    /// stay, its handle and lanes are the last step's, and only its footprint's s, s-range
    /// and speed and the row's `stays` are written (the row's other fields hold the values
    /// [`enter_anew`](Self::enter_anew) would write again: the same handle, t-range bits,
    /// section and borders, `entered` and `lanes`). `None`, writing nothing, where that is
    /// not so. The tests are `enter_anew`'s, in the order the row makes cheapest: `lanes` was
    /// set only on a road of no junction (`plain`), and the road is the one of the row's
    /// handle on the same network (another network empties the rows), so that road is still
    /// plain; the row's handle equal to (road, the section at s, lane) is `enter_anew`'s
    /// condition for keeping it, and its section the section of the row's lanes.
    #[inline(always)]
    fn stay(&mut self, net: &Arc<RoadNetwork>, e: &Entity) -> Option<LookedUp> {
        let i = e.id.index();
        let row = self.kept.get(i).filter(|row| row.lanes)?;
        let (rp, _, handle) = standing(net, e)?;
        let (road_handle, section) = (rp.road, handle.section);
        if row.footprint.handle != handle || row.section != section {
            return None;
        }
        // The box's s-range from its kept s-offsets where its key holds: then its t-range is
        // the row's (store/lane_kept.rs "The box's s-range"); else both folded anew.
        let kept_box = self.boxes.get(i)?;
        let s_range = match kept_box
            .holds(&box_key(e, rp))
            .then(|| shifted(rp.s, kept_box.ds))
            .flatten()
        {
            Some(s_range) => s_range,
            None => {
                let (s_range, t_range, _) = box_ranges(e, rp.s, rp.t, rp.relative_heading);
                let t_was = row.footprint.t_range;
                if (t_was.0.to_bits(), t_was.1.to_bits())
                    != (t_range.0.to_bits(), t_range.1.to_bits())
                {
                    return None;
                }
                s_range
            }
        };
        if self.borders.holds(road_handle, section, rp.s) != Some(row.borders) {
            return None;
        }
        let speed_s = speed_along_s(e, rp.relative_heading);
        let row = &mut self.kept[i];
        row.footprint.s = rp.s;
        row.footprint.s_range = s_range;
        row.footprint.speed_s = speed_s;
        row.stays = true;
        Some((road_handle, rp.lane_id, rp.s, handle))
    }

    /// The entering of [`enter_with_input`](Self::enter_with_input) in full: each row written
    /// once, the new one, or nothing kept where `e` is not entered; returns the lane look-up
    /// made for its footprint. Out of line (in `enter_anew_with_input`): the entities that
    /// take it are few in a step (those changing lanes, entered anew, or off the road), and
    /// [`stay`](Self::stay), with fewer values live, is what the moves' walk runs.
    #[inline(always)]
    fn enter_anew(&mut self, net: &Arc<RoadNetwork>, e: &Entity, keep: bool) -> Option<LookedUp> {
        let i = e.id.index();
        let was = if keep { self.kept[i] } else { Kept::NONE };
        match self.entered(net, e, was) {
            Some((now, looked_up, kept_box)) => {
                self.kept[i] = now;
                self.boxes[i] = kept_box;
                Some(looked_up)
            }
            None => {
                self.kept[i] = Kept::NONE;
                None
            }
        }
    }

    /// The body of [`enter_anew`](Self::enter_anew) given the kept row `was` of the last step
    /// (or [`Kept::NONE`]): makes `e`'s entries and returns its new kept row with its
    /// footprint, the look-up and its box's s-offsets with their key, or `None` where it is not
    /// entered. Reads no row of `e`: `enter_anew` writes them once with the outcome.
    #[inline(always)]
    fn entered(
        &mut self,
        net: &Arc<RoadNetwork>,
        e: &Entity,
        was: Kept,
    ) -> Option<(Kept, LookedUp, BoxKept)> {
        let (rp, road, same_handle) = standing(net, e)?;
        let (road_handle, section) = (rp.road, same_handle.section);
        let (s_range, t_range, ds) = box_ranges(e, rp.s, rp.t, rp.relative_heading);
        let speed_s = speed_along_s(e, rp.relative_heading);
        let handle = if was.entered && was.footprint.handle == same_handle {
            was.footprint.handle
        } else {
            net.lane_handle_on(road_handle, rp.lane_id, rp.s)?
        };
        let t_was = was.footprint.t_range;
        let plain = road.junction.is_none();
        let stays = plain
            && was.lanes
            && was.footprint.handle.road == road_handle.0
            && was.section == section
            && (t_was.0.to_bits(), t_was.1.to_bits()) == (t_range.0.to_bits(), t_range.1.to_bits())
            && self.borders.holds(road_handle, section, rp.s) == Some(was.borders);
        let mut now = Kept {
            footprint: Footprint {
                handle,
                s: rp.s,
                s_range,
                t_range,
                speed_s,
            },
            section,
            entered: true,
            stays,
            ..was
        };
        if !stays {
            let borders = self.insert(road_handle, road, section, rp.s, s_range, t_range, e.id);
            if let Some(junction) = road.junction.as_deref().and_then(|j| net.junction(j)) {
                self.insert_in_junction(net, junction, road, e);
            }
            now.lanes = plain && borders.is_some();
            now.borders = borders.unwrap_or(0);
        }
        let kept_box = BoxKept {
            key: box_key(e, rp),
            ds,
        };
        Some((now, (road_handle, rp.lane_id, rp.s, handle), kept_box))
    }

    /// Enters `id` with footprint `s_range` × `t_range` in every lane of `road`'s section
    /// `section` (the section at `s`) whose borders at `s` its t-range overlaps: the entries
    /// wait in `pending` for the step's end. Returns the generation of the kept borders used
    /// (store/lane_slots.rs), `None` where they were made for this call.
    #[allow(clippy::too_many_arguments)]
    fn insert(
        &mut self,
        road_handle: RoadHandle,
        road: &Road,
        section: u32,
        s: Real,
        s_range: (Real, Real),
        t_range: (Real, Real),
        id: EntityId,
    ) -> Option<u32> {
        let slots = self.slots.as_ref()?;
        let (lanes, generation) = self.borders.at(road_handle, section, road, s);
        for &(lane, lo, hi) in lanes {
            if t_range.1.min(hi) - t_range.0.max(lo) <= LANE_OVERLAP {
                continue;
            }
            // The section `lane_handle` finds for a lane of the section at s is that section.
            let h = LaneHandle {
                road: road_handle.0,
                section,
                lane,
            };
            let Some(slot) = slots.slot(h) else {
                continue;
            };
            self.pending.push((
                slot,
                Entry {
                    lo: s_range.0,
                    hi: s_range.1,
                    id,
                },
            ));
        }
        generation
    }

    /// Enters `e` (on `road`, a road of `junction`) on the junction's other roads whose surface
    /// holds its box centre.
    fn insert_in_junction(
        &mut self,
        net: &Arc<RoadNetwork>,
        junction: &opendrive::Junction,
        road: &Road,
        e: &Entity,
    ) {
        let c = e.bounding_box.center();
        let (sin, cos) = e.pose.h.sin_cos();
        let (x, y) = (
            e.pose.x + c.x * cos - c.y * sin,
            e.pose.y + c.x * sin + c.y * cos,
        );
        let mut seen: Vec<&str> = vec![road.id.as_str()];
        for conn in &junction.connections {
            let other = conn.connecting_road.as_str();
            if seen.contains(&other) {
                continue;
            }
            seen.push(other);
            let Some(rp) = net
                .locate_on_road(other, x, y)
                .filter(|rp| rp.distance <= 0.0)
            else {
                continue;
            };
            let (Some(other_handle), Ok(pose)) =
                (net.road_handle(other), net.road_pose(other, rp.s, rp.t))
            else {
                continue;
            };
            let other_road = net.road_at(other_handle);
            // The footprint about the box centre found on the other road: move back to the
            // reference point along the entity's heading relative to that road.
            let rel = e.pose.h - pose.h;
            let (rs, rc) = rel.sin_cos();
            let ref_s = rp.s - (c.x * rc - c.y * rs);
            let ref_t = rp.t - (c.x * rs + c.y * rc);
            let (s_range, t_range, _) = box_ranges(e, ref_s, ref_t, rel);
            let section = other_road.lane_section_index(rp.s) as u32;
            self.insert(
                other_handle,
                other_road,
                section,
                rp.s,
                s_range,
                t_range,
                e.id,
            );
        }
    }

    /// Panics unless this index (kept from step to step, store/lane_kept.rs) and `full` (built anew for the same
    /// step) give the same answers: the same non-empty lanes with the same entries in the same
    /// order, bounds and flags, the same footprints and driver inputs, bit for bit. Allocates
    /// nothing (the step's allocation test runs it).
    #[cfg(any(test, debug_assertions))]
    pub(super) fn assert_same_as(&self, full: &LaneIndex) {
        let kept = self;
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
        assert_eq!(kept.kept.len(), full.kept.len(), "footprints");
        for i in 0..full.kept.len() {
            let (k, f) = (
                kept.footprint(EntityId(i as u32)),
                full.footprint(EntityId(i as u32)),
            );
            assert!(
                k.map(footprint) == f.map(footprint),
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
                        t.own_slot,
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

    /// The hint of entity `id`'s searches of kind `kind` (< [`HINTS`]): a caller that asks
    /// the same kind of question for an entity each step (its leader, say) passes it to
    /// [`nearest`](Self::nearest) and [`overlapping`](Self::overlapping).
    pub fn hint(&self, id: EntityId, kind: usize) -> Option<&AtomicU32> {
        self.hints.get(id.index() * HINTS + kind)
    }

    /// All [`HINTS`] hints of entity `id` ([`hint`](Self::hint) of each kind), for a caller
    /// that takes several of them (controller/view.rs, the lanes beside).
    #[inline]
    pub(crate) fn hints(&self, id: EntityId) -> Option<&[AtomicU32; HINTS]> {
        let at = id.index() * HINTS;
        self.hints.get(at..at + HINTS)?.try_into().ok()
    }

    /// The entries of lane `h` (empty where no entity is in it).
    #[inline]
    pub(super) fn lane(&self, h: LaneHandle) -> Option<&LaneEntries> {
        let slot = self.slots.as_ref()?.slot(h)?;
        self.lanes.get(slot)
    }

    /// The driver models' inputs of entity `index` in this step (store/driver_inputs.rs).
    pub fn input(&self, index: usize) -> Option<&DriverInput> {
        self.inputs.get(index)?.as_ref()
    }

    /// The footprint of entity `id` in this step, if it stands on a road.
    #[inline]
    pub fn footprint(&self, id: EntityId) -> Option<&Footprint> {
        let row = self.kept.get(id.index())?;
        row.entered.then_some(&row.footprint)
    }

    /// Whether some entity other than `exclude` has a footprint in lane `h` overlapping the
    /// s-range `lo..hi`: [`overlapping`](Self::overlapping) finds one, answered from the hint
    /// where the entry there proves it ([`occupied_at_hint`]).
    #[inline]
    pub fn occupied(
        &self,
        h: LaneHandle,
        range: (Real, Real),
        exclude: EntityId,
        hint: Option<&AtomicU32>,
    ) -> bool {
        let at_hint = || occupied_at_hint(self.lane(h)?, range, exclude, hint?).then_some(());
        at_hint().is_some() || self.occupied_searched(h, range, exclude, hint)
    }

    /// [`occupied`](Self::occupied) by the search: out of line, as [`searched`].
    #[inline(never)]
    fn occupied_searched(
        &self,
        h: LaneHandle,
        range: (Real, Real),
        exclude: EntityId,
        hint: Option<&AtomicU32>,
    ) -> bool {
        self.overlapping(h, range, exclude, hint).next().is_some()
    }

    /// The entities whose footprint lies in lane `h` and overlaps the s-range `lo..hi`, other
    /// than `exclude`.
    pub fn overlapping(
        &self,
        h: LaneHandle,
        (lo, hi): (Real, Real),
        exclude: EntityId,
        hint: Option<&AtomicU32>,
    ) -> impl Iterator<Item = EntityId> + '_ {
        let lane = self.lane(h);
        let entries = lane.map_or(&[][..], |l| &l.entries[..]);
        let max_len = lane.map_or(0.0, |l| l.max_len);
        let end = lane.map_or(0, |l| position(l, hi, hint));
        entries[..end]
            .iter()
            .rev()
            .take_while(move |e| e.lo >= lo - max_len)
            .filter(move |e| e.hi > lo && e.id != exclude)
            .map(|e| e.id)
    }

    /// The nearest entity other than `exclude` whose footprint reaches past `from` travelling
    /// `direction` from s `from` on lane `start`, within `horizon` m (module doc). `choose`
    /// picks the successor where the road whose id it is given ends (`None`: the first).
    /// `hint` ([`hint`](Self::hint)) speeds the search in `start`.
    ///
    /// The search in `start` is made here, inline in the caller; the walk on from there, which
    /// few searches need, is [`nearest_beyond`](Self::nearest_beyond), out of line (issue 31:
    /// the walk's registers saved and restored around every search were a quarter of the
    /// search's instructions). The same answers as the one loop it was, bit for bit
    /// (`store::lane_search_tests::the_split_search_gives_the_walks_answers_bit_for_bit`).
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub fn nearest(
        &self,
        net: &RoadNetwork,
        start: LaneHandle,
        from: Real,
        direction: Direction,
        exclude: EntityId,
        horizon: Real,
        choose: &mut dyn FnMut(&str, &[LaneHandle]) -> Option<LaneHandle>,
        hint: Option<&AtomicU32>,
    ) -> Option<Neighbour> {
        if let Some(found) = self.in_lane(start, from, direction, exclude, hint) {
            // Walked 0 m so far, added as the walk adds it (0 + −0 is +0: the same bits).
            return within(found, 0.0, horizon);
        }
        self.nearest_beyond(net, start, from, direction, exclude, horizon, choose)
    }

    /// [`nearest`](Self::nearest) past its first lane `start`, searched and found empty: the
    /// walk through the following lane sections, links and junctions (module doc).
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    fn nearest_beyond(
        &self,
        net: &RoadNetwork,
        start: LaneHandle,
        from: Real,
        direction: Direction,
        exclude: EntityId,
        horizon: Real,
        choose: &mut dyn FnMut(&str, &[LaneHandle]) -> Option<LaneHandle>,
    ) -> Option<Neighbour> {
        let (mut h, mut at, mut direction) = (start, from, direction);
        // Distance travelled to `at`.
        let mut walked = 0.0;
        // Lane `h` was searched (the first by `nearest`): on to the next, up to MAX_HOPS lanes
        // searched in all.
        for hop in 0..MAX_HOPS {
            if hop > 0 {
                if let Some(found) = self.in_lane(h, at, direction, exclude, None) {
                    return within(found, walked, horizon);
                }
            }
            let end = section_end(net.handle_road(h), h.section as usize, direction);
            walked += (end - at).abs();
            if walked > horizon {
                return None;
            }
            // The next section of the same road, else the caller's choice at the road's end.
            (h, direction, at) = next_lane(net, h, direction, choose)?;
        }
        None
    }

    /// The nearest entry of lane `h` reaching past `from` in `direction`, with its gap.
    pub(super) fn in_lane(
        &self,
        h: LaneHandle,
        from: Real,
        direction: Direction,
        exclude: EntityId,
        hint: Option<&AtomicU32>,
    ) -> Option<Neighbour> {
        let lane = self.lane(h)?;
        let at_hint = hint.and_then(|hint| match direction {
            Direction::Forward => ahead_at_hint(lane, from, exclude, hint),
            Direction::Backward => behind_at_hint(lane, from, exclude, hint),
        });
        at_hint.or_else(|| searched(lane, from, direction, exclude, hint))
    }
}

impl LaneIndex {
    /// [`nearest`](Self::nearest)'s answer travelling forward from `from` on lane `h` within
    /// `horizon`, where the entries of `h` at `hint` prove its first lane's answer
    /// ([`ahead_at_hint`]): `Some` of it, as `nearest` takes that answer; `None` where they do
    /// not (then `nearest` answers). For a caller that takes the proven answer inline and
    /// asks `nearest` out of line otherwise (controller/view.rs, the driver models' leader;
    /// issue 31).
    #[inline(always)]
    pub(crate) fn nearest_ahead_proven(
        &self,
        h: LaneHandle,
        from: Real,
        exclude: EntityId,
        horizon: Real,
        hint: &AtomicU32,
    ) -> Option<Option<Neighbour>> {
        proven_ahead_in(self.lane(h)?, from, exclude, horizon, hint)
    }

    /// [`nearest_ahead_proven`](Self::nearest_ahead_proven) of the lane at `slot`
    /// ([`slot`](Self::slot) of its handle; a slot the index has no lane at, as
    /// `driver_inputs::NO_SLOT`, for a handle without one): the driver models' own lane, whose
    /// slot their inputs keep (store/driver_inputs.rs; issue 31).
    #[inline(always)]
    pub(crate) fn nearest_ahead_proven_at(
        &self,
        slot: u32,
        from: Real,
        exclude: EntityId,
        horizon: Real,
        hint: &AtomicU32,
    ) -> Option<Option<Neighbour>> {
        proven_ahead_in(self.lanes.get(slot as usize)?, from, exclude, horizon, hint)
    }

    /// The slot of lane `h` (store/lane_slots.rs), where its entries are: a function of the
    /// handle and the network alone, the same in every index built on that network, so a
    /// caller that keeps a lane's handle from step to step may keep its slot beside it (the
    /// driver models' lanes beside, controller/lane_beside.rs; issue 31). `None` for the
    /// centre lane, a lane the network does not have, or an index never built.
    #[inline]
    pub(crate) fn slot(&self, h: LaneHandle) -> Option<usize> {
        self.slots.as_ref()?.slot(h)
    }

    /// Whether the entries of the lane at `slot` ([`slot`](Self::slot) of its handle) at
    /// `hint` prove that [`occupied`](Self::occupied) is true for that lane, the s-range
    /// `range` and `exclude` ([`occupied_at_hint`]); `false` where they do not (then `occupied`
    /// answers). Inline for the driver models' lanes beside, whose slots are kept
    /// (controller/view.rs; issue 31), as [`nearest_ahead_proven`](Self::nearest_ahead_proven).
    #[inline(always)]
    pub(crate) fn occupied_proven(
        &self,
        slot: usize,
        range: (Real, Real),
        exclude: EntityId,
        hint: &AtomicU32,
    ) -> bool {
        self.lanes
            .get(slot)
            .is_some_and(|lane| occupied_at_hint(lane, range, exclude, hint))
    }
}

/// [`LaneIndex::nearest_ahead_proven`] in the entries `lane`.
#[inline(always)]
fn proven_ahead_in(
    lane: &LaneEntries,
    from: Real,
    exclude: EntityId,
    horizon: Real,
    hint: &AtomicU32,
) -> Option<Option<Neighbour>> {
    let found = ahead_at_hint(lane, from, exclude, hint)?;
    Some(within(found, 0.0, horizon))
}

/// [`LaneIndex::in_lane`] in `lane` by the search: out of line, so that the answer the hint
/// proves costs no saving of the search's registers.
#[inline(never)]
pub(super) fn searched(
    lane: &LaneEntries,
    from: Real,
    direction: Direction,
    exclude: EntityId,
    hint: Option<&AtomicU32>,
) -> Option<Neighbour> {
    let entries = &lane.entries;
    let p = position(lane, from, hint);
    match direction {
        Direction::Forward => {
            // An entry starting before `from` but reaching past it overlaps: gap 0.
            let overlapping = entries[..p]
                .iter()
                .rev()
                .take_while(|e| e.lo >= from - lane.max_len)
                .find(|e| e.hi > from && e.id != exclude);
            if let Some(e) = overlapping {
                return Some(Neighbour {
                    id: e.id,
                    gap: 0.0,
                    direction,
                });
            }
            entries[p..]
                .iter()
                .find(|e| e.id != exclude)
                .map(|e| Neighbour {
                    id: e.id,
                    gap: e.lo - from,
                    direction,
                })
        }
        Direction::Backward => {
            // Entries starting before `from`: the one whose far end hi is largest.
            let mut best: Option<&Entry> = None;
            for e in entries[..p].iter().rev() {
                if best.is_some_and(|b| e.lo + lane.max_len < b.hi) {
                    break;
                }
                if e.id != exclude && best.is_none_or(|b| e.hi > b.hi) {
                    best = Some(e);
                }
            }
            best.map(|e| Neighbour {
                id: e.id,
                gap: (from - e.hi).max(0.0),
                direction,
            })
        }
    }
}

/// [`LaneIndex::in_lane`]'s answer travelling forward from `from` in `lane`, other than
/// `exclude`, where the entries at the `hint` prove it (module doc "The last answer
/// re-validated"); `None` where they do not (then the search gives it).
///
/// Why it is the search's answer. Let p be the hint and `next` = entries[p]. The lane holds no
/// NaN lo (`unordered` false), so its order by `total_cmp` of lo is the numeric order (−0
/// before +0, which compare equal). The entry before p (if any) has lo < from, so every entry
/// before p has; next.lo ≥ from, so no entry from p on has: p is the search's
/// `partition_point` (and `from` is not NaN). Its backward scan for an entry overlapping
/// `from` goes on while lo ≥ from − max_len and takes an entry with hi > from and an id other
/// than `exclude`: it stops at entries[p − 1] where that starts below from − max_len, or,
/// where entries[p − 1] is `exclude` (the asking entity itself, which it does not take), at
/// entries[p − 2] where that starts below, or where there is no entry before: no overlap. Its
/// forward look then takes the first entry from p whose id is not `exclude`: `next`, at gap
/// next.lo − from. The hint is left as it is: p is where the search would store it.
#[inline(always)]
pub(super) fn ahead_at_hint(
    lane: &LaneEntries,
    from: Real,
    exclude: EntityId,
    hint: &AtomicU32,
) -> Option<Neighbour> {
    if lane.unordered {
        return None;
    }
    let p = hint.load(Ordering::Relaxed) as usize;
    let entries = &lane.entries[..];
    let next = entries.get(p)?;
    // "lo < bound" stops the scan, which goes on while "lo >= bound" (a NaN bound, which
    // stops it too, is left to the search).
    let bound = from - lane.max_len;
    let stops_at = |k: Option<usize>| k.is_none_or(|k| entries[k].lo < bound);
    let (below, no_overlap) = match p.checked_sub(1) {
        None => (true, true),
        Some(k) => {
            let e = &entries[k];
            let passed = e.id == exclude && stops_at(k.checked_sub(1));
            (e.lo < from, e.lo < bound || passed)
        }
    };
    (below && next.lo >= from && no_overlap && next.id != exclude).then_some(Neighbour {
        id: next.id,
        gap: next.lo - from,
        direction: Direction::Forward,
    })
}

/// [`LaneIndex::in_lane`]'s answer travelling backward from `from` in `lane`, other than
/// `exclude`, where the entries at the `hint` prove it (module doc "The last answer
/// re-validated"); `None` where they do not.
///
/// Why it is the search's answer. Let p be the hint and `e` = entries[p − 1]. As for
/// [`ahead_at_hint`], e.lo < from and (where there is one) entries[p].lo ≥ from make p the
/// search's `partition_point`. Its scan back from p − 1 keeps the entry with the largest hi
/// (ids other than `exclude`), the first met kept first, and stops at an entry whose
/// lo + max_len is below the kept hi: it keeps e (not `exclude`), then stops at entries[p − 2]
/// where that is below e.hi, or ends there is none: the answer is e, at gap
/// max(from − e.hi, 0).
#[inline(always)]
pub(super) fn behind_at_hint(
    lane: &LaneEntries,
    from: Real,
    exclude: EntityId,
    hint: &AtomicU32,
) -> Option<Neighbour> {
    if lane.unordered {
        return None;
    }
    let p = hint.load(Ordering::Relaxed) as usize;
    let entries = &lane.entries[..];
    let e = entries.get(p.checked_sub(1)?)?;
    let at_end = entries.get(p).is_none_or(|next| next.lo >= from);
    let stops = p
        .checked_sub(2)
        .is_none_or(|k| entries[k].lo + lane.max_len < e.hi);
    (e.lo < from && at_end && stops && e.id != exclude).then_some(Neighbour {
        id: e.id,
        gap: (from - e.hi).max(0.0),
        direction: Direction::Backward,
    })
}

/// Whether the entry just before the `hint` proves that [`LaneIndex::overlapping`] finds an
/// entity in `lane` for the s-range `lo..hi` other than `exclude` (module doc "The last answer
/// re-validated"); `false` where it does not (then the search answers).
///
/// Why. Let e = entries[p − 1] for the hint p. The lane holds no NaN lo, so its order is the
/// numeric order of lo. e.lo < hi, so p − 1 is before the search's end (`position` of hi:
/// every entry before the end has lo < hi, none after). The search scans back from the end
/// while lo ≥ hi's bound lo − max_len: every entry from p − 1 to the end has lo ≥ e.lo ≥ that
/// bound, so the scan reaches e unless it has found an entity before; and e, with e.hi > lo and
/// an id other than `exclude`, is one it finds. Either way it finds one.
#[inline(always)]
pub(super) fn occupied_at_hint(
    lane: &LaneEntries,
    (lo, hi): (Real, Real),
    exclude: EntityId,
    hint: &AtomicU32,
) -> bool {
    let p = hint.load(Ordering::Relaxed) as usize;
    let Some(e) = p.checked_sub(1).and_then(|k| lane.entries.get(k)) else {
        return false;
    };
    !lane.unordered && e.lo < hi && e.lo >= lo - lane.max_len && e.hi > lo && e.id != exclude
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::domain::{BoundingBox, Vector3};
    use crate::store::World;
    use crate::world::entity::EntityKind;

    const EPS: Real = 1e-9;

    /// Road "A": 100 m along +x, lanes −1 (t −3.5..0) and −2 (t −7..−3.5) towards +s, lane 1
    /// towards −s; its successor road "B" (200 m, same lanes) continues at x = 100.
    fn network() -> RoadNetwork {
        let lanes = r#"<lanes><laneSection s="0"><left><lane id="1" type="driving"><link><predecessor id="1"/><successor id="1"/></link><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><link><predecessor id="-1"/><successor id="-1"/></link><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane><lane id="-2" type="driving"><link><predecessor id="-2"/><successor id="-2"/></link><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes>"#;
        let xodr = format!(
            r#"<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="A" junction="-1" length="100"><link><successor elementType="road" elementId="B" contactPoint="start"/></link><planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView>{lanes}</road>
<road id="B" junction="-1" length="200"><link><predecessor elementType="road" elementId="A" contactPoint="end"/></link><planView><geometry s="0" x="100" y="0" hdg="0" length="200"><line/></geometry></planView>{lanes}</road>
</OpenDRIVE>"#
        );
        RoadNetwork::from_str(&xodr, std::path::Path::new("index_test.xodr")).expect("road")
    }

    /// A 5 m × 2 m car whose box centre is 1.4 m ahead of its reference point.
    fn car(i: u32) -> Entity {
        let b = BoundingBox::new(Vector3::new(1.4, 0.0, 0.75), 5.0, 2.0, 1.5).expect("box");
        Entity::new(EntityId(i), &format!("c{i}"), EntityKind::Vehicle, b)
    }

    /// A world with one car per (road, s, t, heading).
    fn world(cars: &[(&str, Real, Real, Real)]) -> World {
        let net = network();
        let entities = (0..cars.len() as u32).map(car).collect();
        let mut w = World::new(std::sync::Arc::new(net), entities);
        for (i, &(road, s, t, h)) in cars.iter().enumerate() {
            let mut pose = w.network.road_pose(road, s, t).expect("on road");
            pose.h += h;
            let found = w.network.locate(pose.x, pose.y, Some(pose.h));
            w.place_resolved(EntityId(i as u32), pose, found);
        }
        w
    }

    fn ahead(w: &World, index: &LaneIndex, me: u32) -> Option<Neighbour> {
        let f = index.footprint(EntityId(me)).expect("on road");
        let dir = w
            .entity(EntityId(me))
            .track
            .as_ref()
            .expect("track")
            .direction;
        index.nearest(
            &w.network,
            f.handle,
            f.front(dir),
            dir,
            EntityId(me),
            500.0,
            &mut |_, _| None,
            None,
        )
    }

    /// Car 0 on A lane −1 at s 10 (box s 8.9..13.9), car 1 at s 40 (box 38.9..43.9): gap
    /// 38.9 − 13.9 = 25 m. Car 2 in lane −2 at s 20 is not in lane −1.
    #[test]
    fn leader_in_the_same_lane() {
        let w = world(&[
            ("A", 10.0, -1.75, 0.0),
            ("A", 40.0, -1.75, 0.0),
            ("A", 20.0, -5.25, 0.0),
        ]);
        let index = LaneIndex::build(&w.network, w.entities());
        let f = index.footprint(EntityId(0)).expect("on road");
        assert!((f.s_range.0 - 8.9).abs() < EPS && (f.s_range.1 - 13.9).abs() < EPS);
        let n = ahead(&w, &index, 0).expect("a leader");
        assert_eq!(n.id, EntityId(1));
        assert!((n.gap - 25.0).abs() < EPS, "{}", n.gap);
        // Car 2's leader in lane −2: none.
        assert!(ahead(&w, &index, 2).is_none());
        // Car 1 has nobody ahead.
        assert!(ahead(&w, &index, 1).is_none());
    }

    /// A car on the marking between lanes −1 and −2 (t = −3.5, box t −4.5..−2.5) is in both
    /// lanes: the leader of a car in either lane.
    #[test]
    fn a_box_across_the_marking_is_in_both_lanes() {
        let w = world(&[
            ("A", 10.0, -1.75, 0.0),
            ("A", 10.0, -5.25, 0.0),
            ("A", 30.0, -3.5, 0.0),
        ]);
        let index = LaneIndex::build(&w.network, w.entities());
        for me in [0, 1] {
            let n = ahead(&w, &index, me).expect("a leader");
            assert_eq!(n.id, EntityId(2));
            assert!((n.gap - 15.0).abs() < EPS);
        }
    }

    /// Through the road link: car 0 on A at s 90 (front 93.9), car 1 on B at s 20 (rear 18.9):
    /// gap 6.1 + 18.9 = 25 m.
    #[test]
    fn leader_across_a_road_link() {
        let w = world(&[("A", 90.0, -1.75, 0.0), ("B", 20.0, -1.75, 0.0)]);
        let index = LaneIndex::build(&w.network, w.entities());
        let n = ahead(&w, &index, 0).expect("a leader");
        assert_eq!(n.id, EntityId(1));
        assert!((n.gap - 25.0).abs() < EPS, "{}", n.gap);
        // Within a 20 m horizon there is none.
        let f = index.footprint(EntityId(0)).expect("on road");
        let near = index.nearest(
            &w.network,
            f.handle,
            f.front(Direction::Forward),
            Direction::Forward,
            EntityId(0),
            20.0,
            &mut |_, _| None,
            None,
        );
        assert!(near.is_none());
    }

    /// Behind: from car 1's rear on B (s 18.9) travelling backwards the nearest is car 0 on A
    /// with front 93.9: 18.9 + 6.1 = 25 m. A box reaching past the start point overlaps: gap 0.
    #[test]
    fn follower_behind_and_overlap() {
        let w = world(&[
            ("A", 90.0, -1.75, 0.0),
            ("B", 20.0, -1.75, 0.0),
            ("B", 23.0, -1.75, 0.0),
        ]);
        let index = LaneIndex::build(&w.network, w.entities());
        let f = index.footprint(EntityId(1)).expect("on road");
        let back = index
            .nearest(
                &w.network,
                f.handle,
                f.rear(Direction::Forward),
                Direction::Backward,
                EntityId(1),
                500.0,
                &mut |_, _| None,
                None,
            )
            .expect("a follower");
        assert_eq!(back.id, EntityId(0));
        assert!((back.gap - 25.0).abs() < EPS, "{}", back.gap);
        // Car 2 (box 21.9..26.9) overlaps car 1 (18.9..23.9): ahead at gap 0.
        let n = ahead(&w, &index, 1).expect("a leader");
        assert_eq!((n.id, n.gap), (EntityId(2), 0.0));
        assert_eq!(back.direction, Direction::Backward);
        let beside: Vec<_> = index
            .overlapping(f.handle, f.s_range, EntityId(1), None)
            .collect();
        assert_eq!(beside, vec![EntityId(2)]);
    }

    /// Boxes that touch end to end do not occupy each other's length, whether the answer is
    /// taken at the hint or searched: cars of 5 m whose box centre is 1.5 m ahead of the
    /// reference point (box s − 1 .. s + 4, exact in binary), car 0 in lane −1 at s 10 (9..14),
    /// car 1 in lane −2 at s 15 (14..19, its lo car 0's hi), car 2 in lane −2 at s 5 (4..9,
    /// its hi car 0's lo); car 3 in lane −2 at s 12 (11..16) overlaps. From every hint.
    #[test]
    fn boxes_end_to_end_are_not_alongside() {
        let b = BoundingBox::new(Vector3::new(1.5, 0.0, 0.75), 5.0, 2.0, 1.5).expect("box");
        let cars = [(10.0, -1.75), (15.0, -5.25), (5.0, -5.25), (12.0, -5.25)];
        let entities = (0..4)
            .map(|i| Entity::new(EntityId(i), &format!("c{i}"), EntityKind::Vehicle, b))
            .collect();
        let mut w = World::new(std::sync::Arc::new(network()), entities);
        for (i, &(s, t)) in cars.iter().enumerate() {
            let pose = w.network.road_pose("A", s, t).expect("on road");
            let found = w.network.locate(pose.x, pose.y, Some(pose.h));
            w.place_resolved(EntityId(i as u32), pose, found);
        }
        let w3 = World::new(
            std::sync::Arc::clone(&w.network),
            w.entities()[..3].to_vec(),
        );
        for (world, expected) in [(&w3, false), (&w, true)] {
            let index = LaneIndex::build(&world.network, world.entities());
            let me = *index.footprint(EntityId(0)).expect("on road");
            assert_eq!((me.s_range.0, me.s_range.1), (9.0, 14.0));
            let beside = LaneHandle {
                lane: -2,
                ..me.handle
            };
            for at in 0..5 {
                let hint = AtomicU32::new(at);
                let occupied = index.occupied(beside, me.s_range, EntityId(0), Some(&hint));
                assert_eq!(occupied, expected, "hint {at}");
            }
        }
    }

    /// The hinted search is `partition_point` (module doc "Hints"): on lists with repeated
    /// values, −0 and +0, and lists short and long, from every hint (in range or past the end)
    /// and for start points on, between and beyond the entries, the index is the same and is
    /// stored back as the next hint; with a NaN lo in the list, or a NaN start point, the
    /// search is `partition_point` alone.
    #[test]
    fn the_hinted_search_is_partition_point() {
        let mut next = crate::store::lane_kept::tests::generator(0x2545_f491_4f6c_dd1d);
        let mut checked = 0;
        for n in [0usize, 1, 2, 5, 17, 120] {
            let mut los: Vec<Real> = (0..n)
                .map(|_| (next() * 40.0).round() * 0.5 - 5.0)
                .collect();
            if n > 3 {
                los[1] = -0.0;
                los[2] = 0.0;
            }
            los.sort_by(|a, b| a.total_cmp(b));
            let lane = LaneEntries {
                entries: los
                    .iter()
                    .enumerate()
                    .map(|(i, &lo)| Entry {
                        lo,
                        hi: lo + 4.5,
                        id: EntityId(i as u32),
                    })
                    .collect(),
                max_len: 4.5,
                unordered: false,
                listed: true,
            };
            let mut froms: Vec<Real> = los.iter().flat_map(|&l| [l, l + 0.25, l - 0.25]).collect();
            froms.extend([-100.0, 100.0, -0.0, 0.0, Real::INFINITY, Real::NEG_INFINITY]);
            for &from in &froms {
                let expected = lane.entries.partition_point(|e| e.lo < from);
                for start in 0..=n + 3 {
                    let hint = AtomicU32::new(start as u32);
                    assert_eq!(
                        position(&lane, from, Some(&hint)),
                        expected,
                        "n {n} from {from} hint {start}"
                    );
                    assert_eq!(hint.load(Ordering::Relaxed) as usize, expected);
                    checked += 1;
                }
            }
            // A NaN start point: no hint is used or stored.
            let hint = AtomicU32::new(7);
            // "lo < NaN" fails for every lo: index 0.
            assert_eq!(position(&lane, Real::NAN, Some(&hint)), 0);
            assert_eq!(hint.load(Ordering::Relaxed), 7);
        }
        assert!(checked > 5_000, "{checked}");
        // A NaN lo: "lo < from" holds after it again, the walk could stop at it; the binary
        // search alone answers.
        let nan = LaneEntries {
            entries: [1.0, Real::NAN, 3.0]
                .iter()
                .enumerate()
                .map(|(i, &lo)| Entry {
                    lo,
                    hi: 9.0,
                    id: EntityId(i as u32),
                })
                .collect(),
            max_len: 8.0,
            unordered: true,
            listed: true,
        };
        let hint = AtomicU32::new(2);
        let expected = nan.entries.partition_point(|e| e.lo < 5.0);
        assert_eq!(position(&nan, 5.0, Some(&hint)), expected);
        assert_eq!(hint.load(Ordering::Relaxed), 2);
    }

    /// The box's s-range from its kept s-offsets ([`shifted`], store/lane_kept.rs "The box's
    /// s-range") is the one `box_ranges` folds from the corners, bit for bit, wherever it is
    /// given: boxes with centres ahead, behind, beside and at 0, of zero length or width;
    /// headings relative to the road of ±0, one ulp, small, ±π/2, π and NaN; reference points
    /// at ±0, at −dsᵢ of each corner (an end exactly 0: `None`), a subnormal, around 1e16
    /// (the offsets absorbed), ±∞, NaN and ordinary values. It is given in most cases and
    /// refused exactly where an end is 0 or not finite.
    #[test]
    fn the_kept_s_offsets_give_the_folded_s_range_bit_for_bit() {
        let mut next = crate::store::lane_kept::tests::generator(0x9e37_79b9_7f4a_7c15);
        let (mut given, mut refused, mut zero_ends) = (0, 0, 0);
        let centres = [(1.4, 0.0), (-2.0, 0.5), (0.0, 0.0), (0.0, -1.0), (3.3, 1.1)];
        let sizes = [(5.0, 2.0), (0.0, 2.0), (4.5, 0.0), (12.0, 2.55), (0.1, 0.1)];
        let pi = std::f64::consts::PI;
        let headings = [
            0.0,
            -0.0,
            0.0_f64.next_up(),
            0.0_f64.next_down(),
            1e-9,
            -0.03,
            pi / 2.0,
            -pi / 2.0,
            pi,
            Real::NAN,
        ];
        for &(cx, cy) in &centres {
            for &(length, width) in &sizes {
                let b =
                    BoundingBox::new(Vector3::new(cx, cy, 0.75), length, width, 1.5).expect("box");
                let e = Entity::new(EntityId(0), "c", EntityKind::Vehicle, b);
                for &rel in &headings {
                    let (_, _, ds) = box_ranges(&e, 0.0, 0.0, rel);
                    let mut ss = vec![
                        0.0,
                        -0.0,
                        -ds.0,
                        -ds.1,
                        1e-310,
                        -1e-310,
                        1e16,
                        -1e16 + 0.5,
                        Real::INFINITY,
                        Real::NEG_INFINITY,
                        Real::NAN,
                    ];
                    // The other corners' −dsᵢ: an end of the fold may be 0 at any of them.
                    let (sin, cos) = zero_angle::sin_cos(rel);
                    for (dx, dy) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
                        let (x, y) = (cx + dx * 0.5 * length, cy + dy * 0.5 * width);
                        ss.push(-(x * cos - y * sin));
                    }
                    ss.extend((0..20).map(|_| (next() - 0.5) * 400.0));
                    for &s in &ss {
                        let t = (next() - 0.5) * 10.0;
                        let (s_range, _, _) = box_ranges(&e, s, t, rel);
                        let ends = (s + ds.0, s + ds.1);
                        zero_ends += usize::from(ends.0 == 0.0 || ends.1 == 0.0);
                        match shifted(s, ds) {
                            Some(r) => {
                                given += 1;
                                assert_eq!(
                                    (r.0.to_bits(), r.1.to_bits()),
                                    (s_range.0.to_bits(), s_range.1.to_bits()),
                                    "s {s} rel {rel} box {cx} {cy} {length} {width}"
                                );
                            }
                            None => {
                                refused += 1;
                                let usable = |x: Real| x.is_finite() && x != 0.0;
                                assert!(!(usable(ends.0) && usable(ends.1)));
                            }
                        }
                    }
                }
            }
        }
        // 5 × 5 × 10 boxes and headings, 35 s each: 8,750 cases.
        assert_eq!(given + refused, 8_750);
        // Measured: 5,942 given, 2,808 refused (1,258 with an end 0; the rest NaN headings,
        // infinite and NaN s).
        assert!(
            given > 5_500 && refused > 2_000 && zero_ends > 1_000,
            "{given} {refused} {zero_ends}"
        );
    }

    /// A car driving lane 1 (towards −s) at s 60 sees the car at s 20 of the same lane ahead:
    /// its front is 60 − 1.4 − 2.5 = 56.1, the other's far end 20 − 1.4 + 2.5 = 21.1 → 35 m.
    /// Invisible entities are not indexed.
    #[test]
    fn oncoming_lane_and_invisible_entities() {
        let pi = std::f64::consts::PI;
        let mut w = world(&[
            ("A", 60.0, 1.75, pi),
            ("A", 20.0, 1.75, pi),
            ("A", 40.0, 1.75, pi),
        ]);
        w.entity_mut(EntityId(2)).visibility.traffic = false;
        let index = LaneIndex::build(&w.network, w.entities());
        assert!(index.footprint(EntityId(2)).is_none());
        let n = ahead(&w, &index, 0).expect("a leader");
        assert_eq!(n.id, EntityId(1));
        assert!((n.gap - 35.0).abs() < 1e-6, "{}", n.gap);
        let f = index.footprint(EntityId(1)).expect("on road");
        assert!(f.speed_along(Direction::Backward) == 0.0 && f.speed_s == 0.0);
    }
}
