//! What a controller sees in a step (issue 13 "the step's world view for its entity"): its
//! entity's state (pose, road position, lane track, speed, performance, route, the driver
//! inputs overridden by OverrideControllerValueAction), the road network, and the entities
//! around it with their gaps along the lanes, from the step's [`LaneIndex`]
//! (store/lane_index.rs).
//!
//! Gaps are bumper to bumper along the lane (reference-line distance), to the nearest entity
//! whose bounding box overlaps the lane, through lane sections, road links and junctions along
//! the lane the entity will take: the successor its route picks where its road ends, else the
//! first in the road model's order, as the default controller drives. The speed of an entity
//! found is its speed along the searching entity's direction of travel (negative when it comes
//! the other way). All views of one step are taken before any entity moves, so the order in
//! which controllers run does not matter.

use std::sync::atomic::AtomicU32;

use opendrive::{Direction, LaneHandle, Real, RoadNetwork};

use super::external_input::ExternalInput;
use super::lane_beside::KeptRoad;
pub use super::lane_beside::Side;
use crate::signals::Signals;
use crate::store::driver_inputs::DriverInput;
use crate::store::lane_index::{Footprint, LaneIndex, Neighbour, HINTS};
use crate::world::{Entity, EntityId};

/// Base distance (m) a gap search looks ahead or behind; it adds [`HORIZON_TIME`] seconds of
/// the entity's speed. At 33 m/s that is 483 m, more than the IDM's desired gap when closing
/// in on a standing vehicle from that speed (s* = 2 + 53 + 33²·1/2.21 ≈ 460 m, idm module).
pub const HORIZON_BASE: Real = 150.0;
/// Seconds of travel added to [`HORIZON_BASE`].
pub const HORIZON_TIME: Real = 10.0;

/// Another entity seen from the controller's entity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gap {
    /// The entity.
    pub id: EntityId,
    /// Bumper-to-bumper distance along the lane (m, ≥ 0).
    pub gap: Real,
    /// Its speed along the controller's entity's direction of travel (m/s).
    pub speed: Real,
}

/// A lane beside the entity's, as a lane change would find it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NeighbourLane {
    /// The lane id on the entity's road.
    pub lane: i32,
    /// The nearest entity ahead in it, from the entity's front bumper.
    pub leader: Option<Gap>,
    /// The nearest entity behind in it, from the entity's rear bumper.
    pub follower: Option<Gap>,
    /// An entity's box overlaps the entity's own length in that lane (a change now would
    /// collide).
    pub occupied: bool,
    /// The lane lies towards the keep side of the road's traffic rule (right under right-hand
    /// traffic).
    pub toward_keep_side: bool,
    /// The road mark between the entity's lane and this one, where the entity is, lets it
    /// cross (OpenDRIVE 1.8 §11.8 `laneChange`, else the paint:
    /// [`opendrive::RoadMark::permits_lane_change`]).
    pub crossing_permitted: bool,
}

/// A lane beside the entity's as [`ControllerView::beside`] finds it: a
/// [`NeighbourLane`] whose leader, follower and occupancy are not searched yet.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Beside<'a> {
    /// As [`NeighbourLane::lane`].
    pub lane: i32,
    /// Its handle at the entity's s and the entity's direction of travel (the searches of
    /// [`leader_beside`](ControllerView::leader_beside),
    /// [`follower_beside`](ControllerView::follower_beside) and
    /// [`occupied_beside`](ControllerView::occupied_beside) start there).
    pub at: (LaneHandle, Direction),
    /// As [`NeighbourLane::toward_keep_side`].
    pub toward_keep_side: bool,
    /// As [`NeighbourLane::crossing_permitted`].
    pub crossing_permitted: bool,
    /// The lane index's slot of the lane ([`LaneIndex::slot`] of `at`'s handle), when known:
    /// kept with the lanes beside (controller/lane_beside.rs), so that the occupancy's answer
    /// at the hint costs no slot look-up (issue 31).
    pub slot: Option<usize>,
    /// The s-range of the entity's box (its footprint's in the lane index), which the
    /// occupancy's questions ask about: looked up once for both sides (issue 31).
    pub range: (Real, Real),
    /// The hint of the entity's searches alongside in this lane (kind 2 of the lane's
    /// hints, [`ControllerView::hint`]'s): worked out once for both sides from the entity's
    /// hints (issue 31).
    pub alongside: Option<&'a AtomicU32>,
}

/// The kind of an entity's search of kind `query` (0 ahead, 1 behind, 2 alongside) in `lane`
/// where its own lane is `own`: `query` in its own lane, 3 + `query` in the one with the
/// larger id, 6 + `query` in the one with the smaller (lane index "Hints").
#[inline(always)]
fn hint_kind(lane: i32, own: i32, query: usize) -> usize {
    let which = match lane.cmp(&own) {
        std::cmp::Ordering::Equal => 0,
        std::cmp::Ordering::Greater => 1,
        std::cmp::Ordering::Less => 2,
    };
    which * 3 + query
}

/// The hints of an entity's searches alongside in the lanes beside it, left and right of its
/// direction of travel `direction`, from its [`HINTS`] hints `hints`: [`hint_kind`] of each
/// lane beside and kind 2, without comparing lane ids (issue 31: the comparison and its table
/// look-up were about 9 instructions a side). Why the same
/// kinds: the lanes beside are the own lane's neighbours `lane_shift(own, ±1, direction)`
/// (controller/lane_beside.rs, world/lanes.rs): travelling +s the left one has the larger id
/// (kind 3 + 2) and the right one the smaller (6 + 2); travelling −s the other way round.
/// (Only a lane id at the end of `i32`'s range, where the shift wraps, could break this;
/// a hint only speeds a search, whose answer does not depend on it, so even there every
/// answer is the same.)
#[inline(always)]
fn alongside_hints(
    hints: Option<&[AtomicU32; HINTS]>,
    direction: Direction,
) -> [Option<&AtomicU32>; 2] {
    let Some(h) = hints else {
        return [None, None];
    };
    let (larger, smaller) = (&h[3 + 2], &h[6 + 2]);
    match direction {
        Direction::Forward => [Some(larger), Some(smaller)],
        Direction::Backward => [Some(smaller), Some(larger)],
    }
}

/// The lanes beside an entity's lane ([`ControllerView::besides`]): the road's kept answer for
/// its track, its direction of travel, its footprint's s-range and its hints of the searches
/// alongside (left, right).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Besides<'k, 'a> {
    road: &'k KeptRoad,
    direction: Direction,
    range: (Real, Real),
    alongside: [Option<&'a AtomicU32>; 2],
}

/// The index of `side` in a left-right pair.
#[inline(always)]
fn side_index(side: Side) -> usize {
    match side {
        Side::Left => 0,
        Side::Right => 1,
    }
}

/// What a driver model's step reads of its entity's own lane
/// ([`ControllerView::own_lane`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct OwnLane {
    /// [`ControllerView::leader`].
    pub leader: Option<Gap>,
    /// [`ControllerView::length`].
    pub length: Real,
    /// The s-range of the entity's footprint in the lane index, `None` where it has none.
    pub range: Option<(Real, Real)>,
}

/// The world of one step as the controller of one entity sees it (module doc).
#[derive(Debug, Clone, Copy)]
pub struct ControllerView<'a> {
    time: Real,
    entity: &'a Entity,
    entities: &'a [Entity],
    network: &'a RoadNetwork,
    index: &'a LaneIndex,
    external: Option<ExternalInput>,
    signals: &'a Signals,
    /// What the driver models read of the entity, copied at the step's start
    /// (store/driver_inputs.rs): the commands of `idm` and `mobil` read it instead of the
    /// entity. Its track's `own` is the handle of the entity's own lane at its s
    /// ([`lane_handle`](Self::lane_handle) of the track's lane): a `mobil` step asks for it up
    /// to five times (its leader, follower, both lanes beside).
    input: &'a DriverInput,
    /// The step's length (s); 0 where the view is not of a step ([`dt`](Self::dt)).
    dt: Real,
}

impl<'a> ControllerView<'a> {
    /// The view of `entity` at `time`; `input` its driver inputs (the same entity's, at
    /// `time`); `external` is the host's input for an `external` controller; `signals` the
    /// signal states (for [`red_light`](Self::red_light)).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        time: Real,
        entity: &'a Entity,
        input: &'a DriverInput,
        entities: &'a [Entity],
        network: &'a RoadNetwork,
        index: &'a LaneIndex,
        external: Option<ExternalInput>,
        signals: &'a Signals,
    ) -> Self {
        debug_assert_eq!(input.id, entity.id, "the inputs are the entity's");
        ControllerView {
            time,
            entity,
            entities,
            network,
            index,
            external,
            signals,
            input,
            dt: 0.0,
        }
    }

    /// The view of a step of `dt` s (the controllers stage's).
    #[inline]
    pub(crate) fn stepping(mut self, dt: Real) -> Self {
        self.dt = dt;
        self
    }

    /// The same view of another entity, `entity` with its driver inputs `input` (as
    /// [`new`](Self::new)): the controllers stage moves one view along its walk instead of
    /// building one per entity and step (issue 31).
    #[inline]
    pub(crate) fn move_to(&mut self, entity: &'a Entity, input: &'a DriverInput) {
        debug_assert_eq!(input.id, entity.id, "the inputs are the entity's");
        self.entity = entity;
        self.input = input;
    }

    /// The length of the step the view is of (s): the controllers stage's; 0 where the view
    /// is not of a step (at an activation, in a test), where a driver model cuts no step's
    /// free-road term to end at a speed (car_following.rs, "A rate toward a speed").
    pub fn dt(&self) -> Real {
        self.dt
    }

    /// With run option `stop_at_red_lights` on: the distance (m) from the entity's front
    /// bumper to the nearest vehicle light ahead on its road showing red for its direction of
    /// travel, when the entity can still stop before it at its `maxDeceleration` (engine
    /// signals/red_light.rs); `None` when the option is off, there is none, or it is too close
    /// to stop for.
    #[inline]
    pub fn red_light(&self) -> Option<Real> {
        // The option tested here, the search out of line: off (the common case), the question
        // costs a test, not a call (issue 31: 20 instructions per `mobil` entity-step).
        if !self.signals.stops_at_red_lights() {
            return None;
        }
        self.red_light_ahead()
    }

    /// [`red_light`](Self::red_light) with the option on.
    #[inline(never)]
    fn red_light_ahead(&self) -> Option<Real> {
        self.signals.red_light_ahead(self.network, self.entity)
    }

    /// The input the host program gave the entity's `external` controller, if any (module
    /// `external`).
    pub fn external_input(&self) -> Option<ExternalInput> {
        self.external
    }

    /// Simulation time at the step's start (s).
    pub fn time(&self) -> Real {
        self.time
    }

    /// The controller's entity.
    pub fn entity(&self) -> &'a Entity {
        self.entity
    }

    /// The entity's speed (m/s): [`entity`](Self::entity)'s, read from the step's driver
    /// inputs.
    pub fn speed(&self) -> Real {
        self.input.speed
    }

    /// What the driver models read of the entity (store/driver_inputs.rs).
    pub(crate) fn input(&self) -> &'a DriverInput {
        self.input
    }

    /// Another entity.
    pub fn other(&self, id: EntityId) -> &'a Entity {
        &self.entities[id.index()]
    }

    /// The road network.
    pub fn network(&self) -> &'a RoadNetwork {
        self.network
    }

    /// How far gap searches look (m): `HORIZON_BASE` (150 m) + `HORIZON_TIME` (10 s) × speed.
    pub fn horizon(&self) -> Real {
        HORIZON_BASE + HORIZON_TIME * self.input.speed.abs()
    }

    /// The lane handle of the entity's lane `lane` at its s, and its direction of travel.
    fn lane_handle(&self, lane: i32) -> Option<(LaneHandle, Direction)> {
        let track = self.input.track.as_ref()?;
        if lane == track.lane_id {
            // The question the inputs answered when they were copied from the entity at the
            // step's start, which no command changes.
            return track.own.map(|h| (h, track.direction));
        }
        let h = self.network.lane_handle_on(track.road, lane, track.s)?;
        Some((h, track.direction))
    }

    /// A found neighbour as a [`Gap`]; `behind` when found searching backwards.
    fn gap(&self, n: Neighbour, behind: bool) -> Gap {
        let along = self
            .index
            .footprint(n.id)
            .map_or(0.0, |f| f.speed_along(n.direction));
        Gap {
            id: n.id,
            gap: n.gap,
            speed: if behind { -along } else { along },
        }
    }

    /// The hint of the entity's searches of kind `query` (0 ahead, 1 behind, 2 alongside) in
    /// `lane`: its own lane, the one with the larger id or the one with the smaller (lane
    /// index "Hints").
    fn hint(&self, lane: i32, query: usize) -> Option<&'a AtomicU32> {
        let own = self.input.track.as_ref().map_or(lane, |t| t.lane_id);
        self.index.hint(self.input.id, hint_kind(lane, own, query))
    }

    /// The nearest entity ahead in `lane` from the front bumper, along the lane the entity
    /// will take (its route's choice at road ends).
    fn ahead_in(&self, lane: i32) -> Option<Gap> {
        self.ahead_on(lane, self.lane_handle(lane)?)
    }

    /// [`ahead_in`](Self::ahead_in) with the lane's handle and direction of travel known.
    fn ahead_on(&self, lane: i32, (h, dir): (LaneHandle, Direction)) -> Option<Gap> {
        let me = self.index.footprint(self.input.id)?;
        self.ahead_hinted(me, &h, dir, None, self.hint(lane, 0))
    }

    /// [`ahead_on`](Self::ahead_on) with the search's hint known: the answer the entries at
    /// the hint prove taken inline ([`LaneIndex::nearest_ahead_proven`], `nearest`'s answer
    /// where it is proven), the search out of line otherwise (issue 31: the set-up of a
    /// search, its route closure and its call, was paid for the answer at the hint, which the
    /// own leader's question gets 99.7 % of the time on the scale highway). `slot`: the
    /// lane's slot in the index where the caller keeps it (the own lane's, from the driver
    /// inputs: [`TrackInput::own_slot`](crate::store::driver_inputs::TrackInput::own_slot)),
    /// else `None` and it is looked up. The lane's handle `h` by reference: only the search
    /// reads it where the caller keeps the slot, and a copy passed by value was made before
    /// the answer at the hint (issue 31: the own leader's handle is the driver inputs'). `me`:
    /// the entity's footprint, which the caller has looked up.
    #[inline(always)]
    fn ahead_hinted(
        &self,
        me: &Footprint,
        h: &LaneHandle,
        dir: Direction,
        slot: Option<u32>,
        hint: Option<&'a AtomicU32>,
    ) -> Option<Gap> {
        let (from, horizon) = (me.front(dir), self.horizon());
        let id = self.input.id;
        // A match, not a closure: the closure was left out of line (a call per question).
        let proven = match (hint, slot) {
            (Some(hint), Some(k)) => self
                .index
                .nearest_ahead_proven_at(k, from, id, horizon, hint),
            (Some(hint), None) => self.index.nearest_ahead_proven(*h, from, id, horizon, hint),
            (None, _) => None,
        };
        // `gap` in each arm: where the hint proves the answer its direction is `Forward`
        // (`ahead_at_hint`), and the speed's sign is not tested there.
        match proven {
            Some(n) => Some(self.gap(n?, false)),
            None => Some(self.gap(self.ahead_searched(h, from, dir, horizon, hint)?, false)),
        }
    }

    /// [`ahead_hinted`](Self::ahead_hinted)'s search ([`LaneIndex::nearest`]), along the lane
    /// the entity will take (its route's choice at road ends).
    #[inline(never)]
    fn ahead_searched(
        &self,
        h: &LaneHandle,
        from: Real,
        dir: Direction,
        horizon: Real,
        hint: Option<&AtomicU32>,
    ) -> Option<Neighbour> {
        let id = self.input.id;
        let mut choose = self.route_choice();
        self.index
            .nearest(self.network, *h, from, dir, id, horizon, &mut choose, hint)
    }

    /// Where a lane is followed past its road's end: the lane the entity's route takes among
    /// the candidates `c` on leaving road `road`, `None` where it has no route or the route
    /// does not say (the caller then takes the first). The gap searches' choice and the
    /// ending-lane test's. The route is read when a road ends only (it is not one of the
    /// driver inputs).
    fn route_choice(&self) -> impl FnMut(&str, &[LaneHandle]) -> Option<LaneHandle> + 'a {
        let (net, entity) = (self.network, self.entity);
        move |road, c| {
            let route = entity.route_follow.as_ref();
            route.and_then(|r| r.peek(net, road, c))
        }
    }

    /// The nearest entity behind in `lane` from the rear bumper.
    fn behind_in(&self, lane: i32) -> Option<Gap> {
        self.behind_on(lane, self.lane_handle(lane)?)
    }

    /// [`behind_in`](Self::behind_in) with the lane's handle and direction of travel known.
    fn behind_on(&self, lane: i32, (h, dir): (LaneHandle, Direction)) -> Option<Gap> {
        let me = self.index.footprint(self.input.id)?;
        let n = self.index.nearest(
            self.network,
            h,
            me.rear(dir),
            dir.reverse(),
            self.input.id,
            self.horizon(),
            &mut |_, _| None,
            self.hint(lane, 1),
        )?;
        Some(self.gap(n, true))
    }

    /// The vehicle (or any entity) ahead: the nearest in the entity's lane, and during a lane
    /// change also in the lane it leaves.
    ///
    /// Always inlined into the driver models' commands, the lane change's case out of line
    /// (`leader_changing`): as a function of its own, the question answered at the hint
    /// (nearly every one) paid a call's entry and exit, its registers saved and restored, and
    /// its answer returned through memory (issue 31: about 20 instructions per `idm` or
    /// `mobil` entity-step).
    #[inline(always)]
    pub fn leader(&self) -> Option<Gap> {
        self.leader_from(self.index.footprint(self.input.id))
    }

    /// [`leader`](Self::leader) with the entity's footprint `me` looked up.
    #[inline(always)]
    fn leader_from(&self, me: Option<&Footprint>) -> Option<Gap> {
        let track = self.input.track.as_ref()?;
        // Off a lateral transition (nearly always) the own lane's answer is the leader, returned
        // as the search gives it: chosen below between two answers, it was copied through the
        // stack with 16-byte loads of what the search had stored 4 and 8 bytes at a time, a
        // load that waits for the stores to reach the cache (80 % of this function's samples
        // on the scale highway, issue 31). The same answer as `leader_changing`'s choice: with
        // no lane left, `left` is `None` and the choice is `here`.
        match track.blend_from {
            Some(from) if from != track.lane_id => self.leader_changing(from),
            _ => {
                // `ahead_in` of the own lane: its handle is the inputs' (`lane_handle`), its
                // slot too (the slot of that handle, or a slot with no lane where it has none:
                // store/driver_inputs.rs), its hint the own lane's ahead, kind 0 (`hint`).
                let h = track.own.as_ref()?;
                let hint = self.index.hint(self.input.id, 0);
                self.ahead_hinted(me?, h, track.direction, Some(track.own_slot), hint)
            }
        }
    }

    /// [`leader`](Self::leader) during a lane change that leaves lane `from`: the nearer of
    /// the leaders in the own lane and in `from`.
    #[inline(never)]
    fn leader_changing(&self, from: i32) -> Option<Gap> {
        let track = self.input.track.as_ref()?;
        let here = self.ahead_in(track.lane_id);
        let left = self.ahead_in(from);
        match (here, left) {
            (Some(a), Some(b)) => Some(if b.gap < a.gap { b } else { a }),
            (a, b) => a.or(b),
        }
    }

    /// The nearest entity behind in the entity's own lane.
    pub fn follower(&self) -> Option<Gap> {
        let track = self.input.track.as_ref()?;
        self.behind_in(track.lane_id)
    }

    /// The lane on `side` of the entity's lane, when it is a drivable lane of the road at the
    /// entity's s driven the same way; with its leader, follower, occupancy and whether the
    /// road mark between lets the entity cross.
    pub fn neighbour_lane(&self, side: Side) -> Option<NeighbourLane> {
        let b = self.beside(side)?;
        Some(NeighbourLane {
            lane: b.lane,
            leader: self.leader_beside(&b),
            follower: self.follower_beside(&b),
            occupied: self.occupied_beside(&b),
            toward_keep_side: b.toward_keep_side,
            crossing_permitted: b.crossing_permitted,
        })
    }

    /// [`neighbour_lane`](Self::neighbour_lane) without its three searches, which
    /// [`leader_beside`](Self::leader_beside), [`follower_beside`](Self::follower_beside) and
    /// [`occupied_beside`](Self::occupied_beside) make when asked: a lane change that is
    /// ruled out without them (a mark not to be crossed, an occupied lane) costs no search.
    /// The road's part is asked of the road each time (controller/lane_beside.rs).
    pub(crate) fn beside(&self, side: Side) -> Option<Beside<'a>> {
        let [left, right] = self.beside_kept(&mut None);
        match side {
            Side::Left => left,
            Side::Right => right,
        }
    }

    /// [`beside`](Self::beside) on the left and on the right, with the road's part taken from
    /// `kept` while it holds for the entity's track, else asked and kept there
    /// (controller/lane_beside.rs: the same answer bit for bit). Whether it holds is tested
    /// once for both sides (issue 31: the test per side was 2.7 % of the instructions of
    /// `mobil` at 1,000 vehicles); a second test right after the first, of the same track,
    /// could only give the same answer. The entity's box's s-range and its hints are looked
    /// up here once for both sides and kept with each ([`Beside::range`],
    /// [`Beside::alongside`]): the occupancy's questions looked them up again per side (about
    /// 15 instructions a side, issue 31); the index does not change within a step's commands,
    /// so they are the same numbers. The hints' kinds follow from the direction of travel
    /// ([`alongside_hints`]; debug builds compare them with [`hint`](Self::hint)'s).
    #[inline(always)]
    pub(crate) fn beside_kept(&self, kept: &mut Option<KeptRoad>) -> [Option<Beside<'a>>; 2] {
        let range = self.index.footprint(self.input.id).map(|f| f.s_range);
        self.beside_kept_with(kept, range)
    }

    /// [`beside_kept`](Self::beside_kept) with the entity's footprint's s-range `range`
    /// looked up ([`own_lane`](Self::own_lane)'s; `None` where it has no footprint).
    #[inline(always)]
    pub(crate) fn beside_kept_with(
        &self,
        kept: &mut Option<KeptRoad>,
        range: Option<(Real, Real)>,
    ) -> [Option<Beside<'a>>; 2] {
        match self.besides(kept, range) {
            Some(s) => [
                self.beside_of(&s, Side::Left),
                self.beside_of(&s, Side::Right),
            ],
            None => [None, None],
        }
    }

    /// The lanes beside as [`beside_kept_with`](Self::beside_kept_with) finds them, each side
    /// not made into a [`Beside`] yet ([`beside_of`](Self::beside_of) makes it,
    /// [`open_beside`](Self::open_beside) tests it without): `None` where the entity has no
    /// lane track or `range` is `None`.
    #[inline(always)]
    pub(crate) fn besides<'k>(
        &self,
        kept: &'k mut Option<KeptRoad>,
        range: Option<(Real, Real)>,
    ) -> Option<Besides<'k, 'a>> {
        let (Some(track), Some(range)) = (self.input.track.as_ref(), range) else {
            return None;
        };
        let road = KeptRoad::for_track(kept, self.network, self.index, track);
        let alongside = alongside_hints(self.index.hints(self.input.id), track.direction);
        Some(Besides {
            road,
            direction: track.direction,
            range,
            alongside,
        })
    }

    /// The lane beside on `side` of `s`, if there is one.
    #[inline(always)]
    pub(crate) fn beside_of(&self, s: &Besides<'_, 'a>, side: Side) -> Option<Beside<'a>> {
        let beside = s.road.side(side)?;
        let b = Beside {
            lane: beside.lane,
            at: (beside.handle, s.direction),
            toward_keep_side: beside.toward_keep_side,
            crossing_permitted: beside.crossing_permitted,
            slot: s.road.slot(side),
            range: s.range,
            alongside: s.alongside[side_index(side)],
        };
        debug_assert!(
            std::ptr::eq(
                b.alongside.map_or(std::ptr::null(), |h| h),
                self.hint(b.lane, 2).map_or(std::ptr::null(), |h| h)
            ),
            "the alongside hints are `hint_kind`'s"
        );
        Some(b)
    }

    /// Whether there is a lane beside on `side` of `s` that the mark lets the entity cross
    /// into and that is not occupied alongside: `b.crossing_permitted &&
    /// !self.occupied_beside(&b)` of the [`beside_of`](Self::beside_of) `b` (`false` where there
    /// is none), from the kept answer's mark, slot and handle alone. For the `mobil` step,
    /// which weighs a lane beside only where this holds (4 % of them on the scale highway) and
    /// makes its `Beside` only then (issue 31: made for every lane beside, the `Beside`'s
    /// fields were read and kept on the stack for the weighing, about 12 instructions per
    /// entity-step). The same answer: the same fields of the same kept answer, the same
    /// s-range and hint, the same occupancy questions in the same order.
    #[inline(always)]
    pub(crate) fn open_beside(&self, s: &Besides<'_, 'a>, side: Side) -> bool {
        let Some(beside) = s.road.side(side) else {
            return false;
        };
        if !beside.crossing_permitted {
            return false;
        }
        // `occupied_beside`, its search out of line: the lane's handle, which only the
        // search reads, is read there (inline, it was read and kept on the stack before the
        // answer at the hint).
        let hint = s.alongside[side_index(side)];
        !self.occupied_at_hint(s.road.slot(side), s.range, hint) && !self.occupied_searched(s, side)
    }

    /// [`open_beside`](Self::open_beside)'s occupancy where the entries at the hint do not
    /// prove it: [`LaneIndex::occupied`] of the lane beside on `side`.
    #[inline(never)]
    fn occupied_searched(&self, s: &Besides<'_, 'a>, side: Side) -> bool {
        let hint = s.alongside[side_index(side)];
        s.road
            .side(side)
            .is_some_and(|b| self.index.occupied(b.handle, s.range, self.input.id, hint))
    }

    /// Whether an entity's box overlaps the entity's own length in the lane beside (a change
    /// now would collide): [`NeighbourLane::occupied`].
    #[inline(always)]
    pub(crate) fn occupied_beside(&self, b: &Beside<'_>) -> bool {
        // The answer the entries at the hint prove inline, in the lane at the kept slot, the
        // index's question otherwise (issue 31: `occupied`'s own test at the hint was left
        // out of line, and its slot look-up cost about 25 instructions a question). The
        // entity's s-range and hint are the lane beside's, taken once for both sides
        // (`besides`): a `Beside` is made only where the entity has a footprint.
        self.occupied_at_hint(b.slot, b.range, b.alongside)
            || self
                .index
                .occupied(b.at.0, b.range, self.input.id, b.alongside)
    }

    /// Whether the entries of the lane at `slot` (its slot in the index, where known) at
    /// `hint` prove that an entity other than this one overlaps the s-range `range` there
    /// ([`LaneIndex::occupied_proven`]); `false` where they do not (then the index's
    /// question answers).
    #[inline(always)]
    fn occupied_at_hint(
        &self,
        slot: Option<usize>,
        range: (Real, Real),
        hint: Option<&AtomicU32>,
    ) -> bool {
        match (hint, slot) {
            (Some(hint), Some(slot)) => {
                self.index.occupied_proven(slot, range, self.input.id, hint)
            }
            _ => false,
        }
    }

    /// The largest speed along the entity's direction of travel (m/s) of the entities whose
    /// boxes overlap the entity's own length in the lane beside (those
    /// [`occupied_beside`](Self::occupied_beside) finds); `None` when there is none.
    pub(crate) fn fastest_alongside(&self, b: &Beside<'_>) -> Option<Real> {
        self.index
            .overlapping(b.at.0, b.range, self.input.id, b.alongside)
            .filter_map(|id| self.index.footprint(id).map(|f| f.speed_along(b.at.1)))
            .reduce(Real::max)
    }

    /// The nearest entity ahead in the lane beside, from the entity's front bumper.
    pub(crate) fn leader_beside(&self, b: &Beside<'_>) -> Option<Gap> {
        self.ahead_on(b.lane, b.at)
    }

    /// The nearest entity behind in the lane beside, from the entity's rear bumper.
    pub(crate) fn follower_beside(&self, b: &Beside<'_>) -> Option<Gap> {
        self.behind_on(b.lane, b.at)
    }

    /// Whether the entity, at speed `speed` and `length` m long, must not start a change into
    /// the lane beside `b` because that lane ends within the change and before its own lane
    /// does ([`crate::world::lane_change::ends_within_change`]; the `mobil` module doc "A
    /// lane that ends"), the lanes followed at a road's end as the gap searches follow them
    /// (its route's choice, else the first). Asked only of a change about to be decided: cold
    /// and out of line, so that the driver models' steps that do not ask it are compiled as
    /// before (issue 31).
    #[cold]
    #[inline(never)]
    pub(crate) fn lane_ends_within_change(
        &self,
        b: &Beside<'_>,
        speed: Real,
        length: Real,
    ) -> bool {
        let (Some(track), Some(own)) = (
            self.entity.track.as_ref(),
            self.input.track.as_ref().and_then(|t| t.own),
        ) else {
            return false;
        };
        let mut choose = self.route_choice();
        crate::world::lane_change::ends_within_change(
            self.network,
            track,
            own,
            b.at,
            speed,
            length,
            &mut choose,
        )
    }

    /// The entity's length along its direction of travel (m): its box's s-range.
    pub fn length(&self) -> Real {
        self.length_from(self.index.footprint(self.input.id))
    }

    /// [`length`](Self::length) with the entity's footprint `me` looked up.
    #[inline(always)]
    fn length_from(&self, me: Option<&Footprint>) -> Real {
        me.map_or_else(
            || self.entity.bounding_box.length(),
            |f| f.s_range.1 - f.s_range.0,
        )
    }

    /// What a driver model's step reads of the entity's own lane, its footprint looked up once
    /// for all of it (issue 31: the leader, the length and the lanes beside's s-range looked
    /// it up each, about 10 instructions a time): [`leader`](Self::leader),
    /// [`length`](Self::length) and the footprint's s-range, which
    /// [`beside_kept_with`](Self::beside_kept_with) takes. The same numbers as asked one by
    /// one: the index does not change within a step's commands.
    #[inline(always)]
    pub(crate) fn own_lane(&self) -> OwnLane {
        let me = self.index.footprint(self.input.id);
        OwnLane {
            leader: self.leader_from(me),
            length: self.length_from(me),
            range: me.map(|f| f.s_range),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::world::lanes::lane_shift;

    /// The hints of the searches alongside, taken from the direction of travel, are the
    /// straightforward ones, [`hint_kind`] of the lane beside against the own lane, for every
    /// own lane id from −12 to 12 (the lanes ±1 beside the centre lane, where the shift skips
    /// 0, among them), both directions and both sides, the lanes beside numbered as
    /// controller/lane_beside.rs numbers them (`lane_shift` by +1 on the left, −1 on the
    /// right). By hand: lane −2 travelling +s has −1 on its left (larger: kind 3 + 2 = 5) and
    /// −3 on its right (smaller: 6 + 2 = 8); lane 1 travelling −s has −1 on its left (the
    /// shift skips 0; smaller: 8) and 2 on its right (larger: 5). Without hints, none.
    #[test]
    fn the_alongside_hints_are_hint_kinds() {
        let hints: [AtomicU32; HINTS] = std::array::from_fn(|k| AtomicU32::new(k as u32));
        let kind = |h: Option<&AtomicU32>| h.map(|h| h.load(std::sync::atomic::Ordering::Relaxed));
        let by_hand = [
            (-2, Direction::Forward, [-1, -3], [5, 8]),
            (1, Direction::Backward, [-1, 2], [8, 5]),
        ];
        for (own, direction, lanes, [left, right]) in by_hand {
            let shifted = [
                lane_shift(own, 1, direction),
                lane_shift(own, -1, direction),
            ];
            assert_eq!(shifted, lanes, "{own}");
            let [l, r] = alongside_hints(Some(&hints), direction);
            assert_eq!((kind(l), kind(r)), (Some(left), Some(right)), "{own}");
        }
        let mut checked = 0;
        for own in (-12..=12).filter(|&l| l != 0) {
            for direction in [Direction::Forward, Direction::Backward] {
                let found = alongside_hints(Some(&hints), direction);
                for (side, n) in [(0, 1), (1, -1)] {
                    let lane = lane_shift(own, n, direction);
                    let want = hint_kind(lane, own, 2);
                    let got = found[side].expect("hints given");
                    assert!(
                        std::ptr::eq(got, &hints[want]),
                        "own {own} {direction:?} side {side}: lane {lane}, kind {want}"
                    );
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 24 * 2 * 2);
        for direction in [Direction::Forward, Direction::Backward] {
            assert!(alongside_hints(None, direction).iter().all(Option::is_none));
        }
    }
}
