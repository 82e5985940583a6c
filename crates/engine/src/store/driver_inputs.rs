//! The driver models' per-step inputs (issue 31): for each entity, the few numbers of its
//! state the built-in controllers' commands read (OpenSCENARIO 1.3 §6.6 user-defined
//! controllers; the world view of controller/view.rs), copied from the [`Entity`] in the walk
//! that builds the step's lane index (store/lane_index.rs).
//!
//! **Why a table of its own.** An `Entity` is 1.3 kB; what an `idm` or `mobil` command reads of
//! it (its speed, its lane track's road, lane, s, direction and lateral transition, whether an
//! action holds its lateral domain) lies on several of its cache lines. At 4,000 vehicles the
//! entities (5 MB) do not stay in the core's cache from one walk over them to the next, so the
//! commands, worked out after the index is built, loaded those lines a second time per step.
//! A row here is 64 bytes; the rows of 4,000 entities (256 kB) are read in the order they were
//! written, right after. The lane handle of the entity's own lane is worked out in the same
//! walk: the index looks up the handle of the lane its road position names, which is the
//! track's lane at the same s wherever the two agree (the look-up is then not repeated).
//!
//! The rows are copies: the same numbers as the entity's at the step's start, which no
//! command changes (every command is worked out before any entity moves, controller/stage.rs),
//! so a command gives the same bits whether it reads the row or the entity.
//!
//! **The own lane's slot.** Beside the own lane's handle the row keeps that lane's slot in the
//! index (store/lane_slots.rs: where the lane's entries are), so that the leader's answer at
//! the hint reads the lane without looking the slot up (controller/view.rs `leader`; the
//! look-up was about 20 instructions per `idm` or `mobil` entity-step, issue 31). A lane's
//! slot is a function of its handle and the network alone, so the slot is worked out only
//! where the row's handle changes (a vehicle following its lane keeps its handle for the
//! length of the lane section) and kept otherwise; the index empties its rows when it numbers
//! another network's lanes (`LaneIndex::walk`), so a kept slot is always of the numbering the
//! index reads with. Debug builds compare every row with a full build's, slot included
//! (`LaneIndex::assert_same_as`).
//!
//! **The question's number.** The `mobil` controller keeps the road's answer on the lanes
//! beside (controller/lane_beside.rs) for as long as the track's road, lane, direction of
//! travel and own lane (the question) and a range of s hold. The row gives the question as one
//! number, [`TrackInput::question`]: the own lane's slot and one bit for the direction, so the
//! kept answer is tested by one comparison of it (issue 31: the four fields packed into three
//! words and compared were 26 instructions per `mobil` entity-step). One-to-one among the
//! rows whose own lane has a slot: the own lane's handle is the one of the track's road and
//! lane ([`DriverInput::write`] and [`DriverInput::with_own`] take it from a look-up of that
//! road and lane, or of the same road, lane and s), so it holds the road's index and the lane
//! id, and two handles of one network have the same slot only where they are the same
//! (store/lane_slots.rs: a section's slots are a range of their own, a lane's position in it
//! its id's). So two such rows have the same number exactly where the four fields are the
//! same, and a change of any of them changes the number. A row whose own lane has no slot
//! (no own lane, a row made outside an index) has no number: the kept answer is then never
//! used ([`NO_QUESTION`]).

use opendrive::{Direction, LaneHandle, Real, RoadHandle, RoadNetwork};

use super::lane_slots::LaneSlots;
use crate::world::entity::{Entity, EntityId};

/// [`TrackInput::own_slot`] where the own lane has no slot: no handle, the centre lane, or a
/// row made outside an index ([`DriverInput::of`]). Never a lane's slot: a slot is below the
/// number of slots, itself a `u32` (store/lane_slots.rs), so the index's lane at this slot is
/// none, as for a handle without a slot.
pub const NO_SLOT: u32 = u32::MAX;

/// A number [`TrackInput::question`] never gives (it is below 2³³): the question of a track
/// whose own lane has no slot, under which a kept answer matches no track (module doc "The
/// question's number").
pub const NO_QUESTION: u64 = u64::MAX;

/// What the driver models read of an entity's lane track (the lane the default controller
/// keeps it in). `own`, where there is one, is a handle of lane `lane_id` of `road` (module
/// doc "The question's number").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrackInput {
    /// The track's road.
    pub road: RoadHandle,
    /// The lane followed.
    pub lane_id: i32,
    /// s along the road (m).
    pub s: Real,
    /// Direction of travel along s.
    pub direction: Direction,
    /// The lane a lateral transition in progress leaves (`Some` exactly while one runs).
    pub blend_from: Option<i32>,
    /// The handle of lane `lane_id` of `road` at `s` ([`RoadNetwork::lane_handle_on`]).
    pub own: Option<LaneHandle>,
    /// The lane index's slot of `own` (`LaneIndex::slot`, module doc "The own lane's slot"),
    /// [`NO_SLOT`] where it has none. In the row's padding: the row stays 64 bytes.
    pub own_slot: u32,
}

impl TrackInput {
    /// The number of the question the road answers on the lanes beside (module doc "The
    /// question's number"): the own lane's slot in the low 32 bits, bit 32 set for travel
    /// towards decreasing s. Where `own_slot` is a slot, one-to-one with (`road`, `lane_id`,
    /// `direction`, `own`); else (`own_slot` is [`NO_SLOT`]) not a number of the question:
    /// see [`numbered`](Self::numbered).
    #[inline(always)]
    pub fn question(&self) -> u64 {
        u64::from(self.own_slot) | u64::from(self.direction == Direction::Backward) << 32
    }

    /// [`question`](Self::question) where the own lane has a slot, else [`NO_QUESTION`],
    /// which no track's `question` is: the number to keep an answer under.
    pub fn numbered(&self) -> u64 {
        if self.own_slot == NO_SLOT {
            NO_QUESTION
        } else {
            self.question()
        }
    }
}

impl TrackInput {
    /// Works out the own lane's slot in `slots` ([`DriverInput::write`], where the own lane
    /// changed).
    #[cold]
    #[inline(never)]
    fn own_slot_anew(&mut self, slots: &Option<LaneSlots>) {
        self.own_slot = slot_of(slots.as_ref(), self.own);
    }

    /// The own lane looked up on `net` at the track's road, lane and s, and its slot worked
    /// out where it is not the row's already ([`DriverInput::write`] where the lane index's
    /// look-up was of another lane or s, or none).
    #[cold]
    #[inline(never)]
    fn own_looked_up(&mut self, net: &RoadNetwork, slots: &Option<LaneSlots>) {
        let now = net.lane_handle_on(self.road, self.lane_id, self.s);
        if self.own != now {
            self.own = now;
            self.own_slot = slot_of(slots.as_ref(), now);
        }
    }
}

/// One entity's row (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DriverInput {
    /// The entity.
    pub id: EntityId,
    /// It is placed in the world.
    pub placed: bool,
    /// An action holds its lateral domain.
    pub lateral_action: bool,
    /// Its speed (m/s).
    pub speed: Real,
    /// Its lane track, if it has one.
    pub track: Option<TrackInput>,
}

impl DriverInput {
    /// The row of `e` on `net`, its own lane's handle looked up; made outside an index, it
    /// has no slot ([`NO_SLOT`]).
    pub fn of(e: &Entity, net: &RoadNetwork) -> Self {
        Self::with_own(e, |road, lane, s| net.lane_handle_on(road, lane, s), None)
    }

    /// Makes `row` the row of `e` on `net`, where the lane index looked up the handle of lane
    /// `looked_up` (road, lane, s, handle) for the entity's footprint: the track's own lane's
    /// handle is that one where the track names the same road, lane and s (the common case),
    /// else it is looked up; its slot is `slots`' (module doc), worked out only where the
    /// handle is not the row's already. The fields are written one by one where the row is,
    /// not a row built aside and copied in: the copy loaded 8 or 16 bytes at a time what had
    /// just been stored 4 bytes at a time and waited for the stores (a third of the index
    /// walk's samples, issue 31). Inline in each of the lane index's two ways of entering an
    /// entity (store/lane_index.rs `enter_with_input`): out of line, the look-up went to it
    /// through memory. The common case inline, the rest out of line and given nothing the
    /// common case would have to keep in memory for them (a row or track not there before:
    /// [`start`](Self::start); none now; the own lane's slot anew; the own lane looked up
    /// anew). The id is not written again: a row is the one at its entity's index, whose id
    /// is that index.
    #[inline(always)]
    pub(crate) fn write(
        row: &mut Option<DriverInput>,
        e: &Entity,
        net: &RoadNetwork,
        slots: &Option<LaneSlots>,
        looked_up: Option<(RoadHandle, i32, Real, LaneHandle)>,
    ) {
        let Some(t) = e.track.as_ref() else {
            *row = Some(Self::without_track(e));
            return;
        };
        let r = match row {
            Some(r) if r.track.is_some() => r,
            _ => Self::start(row, e),
        };
        let Some(rt) = r.track.as_mut() else {
            return;
        };
        rt.road = t.road;
        rt.lane_id = t.lane_id;
        rt.s = t.s;
        rt.direction = t.direction;
        rt.blend_from = t.blend.as_ref().map(|b| b.from_lane);
        match looked_up {
            // The look-up of the track's road, lane and s: its handle is the own lane's.
            Some((road, lane, s, h))
                if (road, lane) == (t.road, t.lane_id) && s.to_bits() == t.s.to_bits() =>
            {
                if rt.own != Some(h) {
                    rt.own = Some(h);
                    rt.own_slot_anew(slots);
                }
            }
            _ => rt.own_looked_up(net, slots),
        }
        debug_assert_eq!(r.id, e.id, "the row at an entity's index is the entity's");
        r.placed = e.placed;
        r.lateral_action = e.lateral_action.is_some();
        r.speed = e.speed;
    }

    /// The row of `e`, which has no lane track ([`write`](Self::write)).
    #[cold]
    #[inline(never)]
    fn without_track(e: &Entity) -> Self {
        Self::with_own(e, |_, _, _| None, None)
    }

    /// [`write`](Self::write) where `row` or its track is none: a row with `e`'s id and a
    /// track without an own lane (`None`, [`NO_SLOT`]), which `write` then fills as any row.
    #[cold]
    #[inline(never)]
    fn start<'r>(row: &'r mut Option<DriverInput>, e: &Entity) -> &'r mut DriverInput {
        row.insert(Self::with_own(e, |_, _, _| None, None))
    }

    /// The row of `e`, its own lane's handle from `own(road, lane, s)` and that lane's slot
    /// from `slots`.
    pub(crate) fn with_own(
        e: &Entity,
        own: impl FnOnce(RoadHandle, i32, Real) -> Option<LaneHandle>,
        slots: Option<&LaneSlots>,
    ) -> Self {
        DriverInput {
            id: e.id,
            placed: e.placed,
            lateral_action: e.lateral_action.is_some(),
            speed: e.speed,
            track: e.track.as_ref().map(|t| {
                let own = own(t.road, t.lane_id, t.s);
                TrackInput {
                    road: t.road,
                    lane_id: t.lane_id,
                    s: t.s,
                    direction: t.direction,
                    blend_from: t.blend.as_ref().map(|b| b.from_lane),
                    own,
                    own_slot: slot_of(slots, own),
                }
            }),
        }
    }
}

/// The slot of lane `own` in the numbering `slots` ([`TrackInput::own_slot`]): [`NO_SLOT`]
/// where there is no lane, no numbering or no slot of the lane.
#[inline(never)]
fn slot_of(slots: Option<&LaneSlots>, own: Option<LaneHandle>) -> u32 {
    match (slots, own) {
        (Some(slots), Some(h)) => slots
            .slot(h)
            .and_then(|k| u32::try_from(k).ok())
            .unwrap_or(NO_SLOT),
        _ => NO_SLOT,
    }
}

// The own lane's slot sits in the row's padding (module doc).
const _: () = assert!(std::mem::size_of::<Option<DriverInput>>() == 64);
