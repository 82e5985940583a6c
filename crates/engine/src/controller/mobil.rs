//! The `mobil` controller (OpenSCENARIO 1.3 §6.6, both motion domains): the IDM drives the
//! longitudinal domain ([`super::car_following::IdmController`]) and MOBIL
//! ([`crate::models::mobil`]) decides each step whether to change to the lane on the left or
//! the right.
//!
//! A candidate lane is one the view offers ([`ControllerView::neighbour_lane`]: drivable, on
//! the entity's road at its s, driven the same way) with no entity alongside the entity in it,
//! behind a road mark that may be crossed towards it where the entity is (OpenDRIVE 1.8 §11.8:
//! `laneChange`, else the paint; a solid line is not crossed, [`opendrive::RoadMark::permits_lane_change`]).
//! The accelerations MOBIL weighs are the IDM's, with this controller's parameters for the
//! changer and for both followers (the model's usual reading: the others' behaviour is not
//! known, MOBIL evaluates them with the same car-following model):
//!
//! - own: a_c behind the present leader, ã_c behind the target lane's leader;
//! - old follower o (behind in the present lane): a_o behind the changer, ã_o behind the
//!   changer's leader at gap g_o + length + g_c;
//! - new follower n (behind in the target lane): a_n behind the target lane's leader at gap
//!   g_n + length + g_l, ã_n behind the changer at gap g_n.
//!
//! Of the lanes where a change is safe and worth it, the one with the larger margin is taken;
//! the change has the lateral shape of the route's lane changes (cubic over the distance that
//! keeps the peak lateral acceleration at 1 m/s², controller/lane_change.rs). A change into a gap
//! that a change from the lane's other side takes in the same step, or is under way into,
//! yields when the two would fail MOBIL's safety criterion side by side: the one further
//! downstream goes first, as in SUMO (controller/one_gap.rs). Further
//! decisions wait while a lateral transition runs, for [`MIN_CHANGE_INTERVAL`] after a change,
//! and below [`MIN_CHANGE_SPEED`] (a change at rest would be a sideways jump). A
//! LaneChangeAction of the scenario on the lateral domain is carried out the same way, to the
//! lane it names.
//!
//! **A lane that ends.** Neither MOBIL nor a mandatory lane starts a change into a lane beside
//! that ends within the change: where less of it lies ahead of the entity's s than the
//! change's length (its speed × the change's duration, √(6·Δ/1 m/s²) for a sideways move Δ,
//! world/lane_change.rs) plus the entity's length, and less than of its own lane, the change
//! is not made (MOBIL weighs the other side; a mandatory lane waits, without falling back). A
//! lane ends where its lane section ends and no lane follows it, or where it has narrowed to
//! nothing (OpenDRIVE 1.8 §11.5 lane linkage, §11.6 lane width; followed through lane
//! sections, road links and junctions as the gap searches follow it:
//! world/lane_change.rs `ends_within_change`, world/lanes.rs `lane_left`). Lanes that end
//! together with the own lane (the end of the network) are not refused. A human driver does
//! not change into an acceleration lane or a merging lane that ends before the change is
//! done, nor does SUMO's LC2013, which weighs each lane by the length of its continuation
//! (its strategic "bestLanes") and avoids one whose remaining length is too short. The test
//! is asked only of a change about to be decided, never of the lanes beside that are not
//! weighed: ordinary traffic on roads without ending lanes is unchanged bit for bit.
//!
//! **A mandatory lane** (oscsim's `scenario::LateralAction::MandatoryLane`, which the DSL
//! runtime gives the members of random traffic for `lane(…)` at: all, ASAM OpenSCENARIO DSL
//! 2.1 §8.7.18.1) is a separate path that ordinary MOBIL traffic never takes: MOBIL with its
//! incentive replaced by "must reach lane L" and its safety criterion kept (Kesting, Treiber,
//! Helbing, "General lane-changing model MOBIL for car-following models", TRR 1999 (2007),
//! eq. (2): the new follower's ã_n ≥ −b_safe; here, as for the discretionary changes, the
//! changer's own ã_c ≥ −b_safe too and no box alongside). While it holds, the controller
//! makes no change of its own: each step with no lateral transition under way, at
//! [`MIN_CHANGE_SPEED`] or more (no [`MIN_CHANGE_INTERVAL`]: the change is owed), it changes
//! one lane towards L when the road mark lets it cross and the gap passes that test, so a
//! change two lanes over is two changes, each into an accepted gap. While the gap fails, it
//! waits in its lane; and when what blocks it in the lane beside (a box alongside its own
//! length, else the leader there too close for ã_c) is not slower than it, it falls back at
//! its comfortable deceleration b (its command is at most −b), so that a vehicle level with it
//! at its own speed, or one just ahead that it would never pass, leaves a gap behind (SUMO's
//! LC2013 slows so for a strategic change); one that is slower it passes at its own speed. A
//! new follower too close it waits out where its own speed advantage opens the gap the
//! criterion needs within [`GAP_OPENING_TIME`]; else it falls back at b too and lets the
//! follower past, then changes in behind it (SUMO's LC2013 so: `MSLCM_LC2013::informFollower`
//! slows the changer "to allow this" follower "to overtake us" where its speed advantage does
//! not open the secure gap in the time left); before, one at about its own speed kept the gap
//! as it was, and the change waited for ever. During each change its IDM follows the nearer of the
//! leaders in the lane it leaves and the lane it enters ([`ControllerView::leader`]). Reached,
//! L is kept until an action releases it; released before, the entity keeps the lane it is
//! in and the controller's event record says that L was not reached.
//!
//! **Across roads.** L is a lane id of the entity's road where it is asked for. Where the
//! entity passes into another lane section or onto the next road, the lane to reach is the one
//! L's lane links lead to there (OpenDRIVE 1.8 §11.5 lane linkage; [`Mandatory`]'s
//! `target_here`), not the lane of the same id: on a road whose lanes are numbered otherwise
//! (a lane added on the inside), L's continuation keeps the change going or keeps it reached.
//! Where L's links do not lead onto the entity's road, it makes no change there, and the event
//! log says so once for that road and lane section (a `controller` record at the step, at the
//! action that gave the lane: "mandatory lane L lost: its lane links lead onto no lane of road
//! …"; [`Controller::note`], taken after each controllers stage for the controllers that were
//! handed a mandatory lane).
//!
//! The `idm` model, which holds no lateral domain, runs the same path ([`Mandatory`], one
//! piece of state and code; the engine runs the `idm` as [`IdmDriver`], the IDM with the
//! mandatory lane it may hold): where no user controller holds the entity's lateral domain, the mandatory lane is
//! handed to the `idm` holding its longitudinal one (controller/strategy.rs), which judges
//! each change by MOBIL's safety criterion at the default b_safe (it has no MOBIL
//! parameters); the controllers stage starts each change it decides on the default
//! controller's lane track, as the route's lane changes (controller/stage.rs). Without a
//! mandatory lane the `idm`'s step is the IDM's acceleration alone, as before.

use opendrive::{LaneHandle, Real, RoadNetwork};

use super::car_following::{nearer, IdmController};
use super::command::{Command, Controller, Lateral, Longitudinal, Strategy};
use super::lane_beside::KeptBeside;
use super::view::{Beside, Besides, ControllerView, Gap, OwnLane, Side};
use crate::models::idm::{IdmParameters, Leader};
use crate::models::mobil::{FollowerChange, LaneChangeCandidate, MobilParameters};
use crate::store::driver_inputs::TrackInput;

/// Least time between two lane changes of one entity (s).
pub const MIN_CHANGE_INTERVAL: Real = 3.0;
/// Least speed at which the controller changes lanes (m/s).
pub const MIN_CHANGE_SPEED: Real = 1.0;
/// The time (s) within which a changer to a mandatory lane waits for the gap to a new follower
/// too close to open by its own speed advantage; where it would take longer, it falls back to
/// let the follower past (module doc): the duration of a change across a 3.5 m lane,
/// √(6·3.5/1) = 4.58 s (world/lane_change.rs), standing in for SUMO LC2013's remaining time
/// to the end of the lane (`MSLCM_LC2013::informFollower`), which a mandatory lane without an
/// end does not have.
pub const GAP_OPENING_TIME: Real = 4.58;

/// The `mobil` controller.
#[derive(Debug, Clone)]
pub struct MobilController {
    idm: IdmController,
    /// The MOBIL parameters.
    pub mobil: MobilParameters,
    /// A lane a LaneChangeAction asked for, not yet started.
    pending: Option<i32>,
    /// Time of the last change started (s).
    last_change: Real,
    /// The lanes beside as the road decides them, kept over the stretch they hold
    /// (controller/lane_beside.rs).
    kept: KeptBeside,
    /// The mandatory lane held (module doc), if any.
    mandatory: Option<Box<Mandatory>>,
    /// The change decided last, when MOBIL or the mandatory lane judged it (not a
    /// LaneChangeAction's): the time of the change before it, put back if it yields
    /// ([`Self::yield_change`], controller/one_gap.rs).
    judged: Option<Real>,
}

impl MobilController {
    /// A controller with `idm` and `mobil` parameters.
    pub fn new(idm: IdmParameters, desired_given: bool, mobil: MobilParameters) -> Self {
        MobilController {
            idm: IdmController::new(idm, desired_given),
            mobil,
            pending: None,
            last_change: Real::NEG_INFINITY,
            kept: KeptBeside::default(),
            mandatory: None,
            judged: None,
        }
    }

    /// [`consider`](Self::consider)'s verdict on a lane beside that may be crossed into and
    /// is not occupied alongside: out of line, so that the common verdict (occupied: 96 % of
    /// the lanes beside asked about on the scale highway, issue 31) costs no set-up of the
    /// weighing. Inlined, its loop-invariant parameter arithmetic (the desired gap's 2√(ab),
    /// the negated b_safe) was hoisted before `decide`'s loop and paid at every step.
    #[inline(never)]
    fn weigh(
        p: &IdmParameters,
        mobil: &MobilParameters,
        view: &ControllerView<'_>,
        own: &mut Own,
        b: Beside<'_>,
    ) -> Option<Real> {
        // `b` by value: the lane beside is copied where it is weighed, not before every
        // occupancy test (issue 31).
        let b = &b;
        let (v, len) = (own.v, own.len);
        let lane_leader = view.leader_beside(b);
        let own_after = own.after(p, lane_leader);
        if !mobil.safe_for_changer(own_after) {
            return None;
        }
        let new_follower = view
            .follower_beside(b)
            .map(|n| Weighed::new_follower(p, n, v, len, lane_leader));
        let own_change = FollowerChange {
            before: own.a_c,
            after: own_after,
        };
        if settled_without_powers(mobil, p, view, own, own_change, new_follower, b) {
            return None;
        }
        let new_follower = new_follower.map(|n| n.change(p));
        if new_follower.is_some_and(|n| !mobil.safe_for_follower(n.after)) {
            return None;
        }
        let old_follower = own.old_follower(p, view).map(|o| o.change(p));
        let verdict = mobil.judge(&LaneChangeCandidate {
            own: own_change,
            old_follower,
            new_follower,
            toward_keep_side: b.toward_keep_side,
        });
        // A lane that ends within the change is refused last: asked only of a change MOBIL
        // would make (module doc "A lane that ends").
        if !verdict.change() || view.lane_ends_within_change(b, v, len) {
            return None;
        }
        Some(verdict.margin)
    }

    /// Whether the controller may decide a lane change now, and a lane a LaneChangeAction
    /// asked for: `Err(lane)` to take it, `Ok(false)` no decision this step.
    fn may_decide(&mut self, view: &ControllerView<'_>) -> Result<bool, Option<i32>> {
        // The entity's inputs at the step's start (store/driver_inputs.rs), not the entity.
        let e = view.input();
        let Some(track) = e.track.as_ref() else {
            return Ok(false);
        };
        if track.blend_from.is_some() || e.lateral_action {
            return Ok(false);
        }
        if let Some(lane) = self.pending.take() {
            return Err((lane != track.lane_id).then_some(lane));
        }
        if e.speed < MIN_CHANGE_SPEED || view.time() - self.last_change < MIN_CHANGE_INTERVAL {
            return Ok(false);
        }
        Ok(true)
    }

    /// The lane to change to now, if any.
    fn decide(&mut self, view: &ControllerView<'_>, own: &mut Own) -> Option<i32> {
        if let Some(m) = self.mandatory.as_deref_mut() {
            return m.decide(view, own, &self.idm.params, &self.mobil);
        }
        match self.may_decide(view) {
            Err(pending) => return pending,
            Ok(false) => return None,
            Ok(true) => {}
        }
        let mut best: Option<(Real, i32)> = None;
        let (p, mobil) = (&self.idm.params, &self.mobil);
        let s = view.besides(&mut self.kept.0, own.range)?;
        // Each side in turn, not a loop over the pair: the pair then stays in registers
        // (looped over, it was stored and read back; issue 31).
        Self::consider(p, mobil, view, own, &s, Side::Left, &mut best);
        Self::consider(p, mobil, view, own, &s, Side::Right, &mut best);
        best.map(|(_, lane)| lane)
    }

    /// The MOBIL verdict on changing into the lane beside on `side` of `s` (module doc), if
    /// there is one, kept in `best` (margin, lane) where the change is safe and worth it and
    /// its margin is larger. The accelerations are those of the straightforward rule
    /// ([`Self::judge_each`] in the tests), computed in an order that stops early: a lane
    /// behind a mark not to be crossed costs no occupancy search, an occupied one no gap
    /// search, a change unsafe for the changer no search of the new follower (each leaves the
    /// verdict "no change"); the free-road term of a speed is evaluated once for all the
    /// leaders weighed at that speed; and the followers are weighed first with bounds of their
    /// free-road terms instead of the terms ([`settled_without_powers`]), which settle almost
    /// every candidate. The lane beside is made into a [`Beside`] only for the weighing
    /// ([`ControllerView::open_beside`] tests the mark and the occupancy without it).
    #[inline(always)]
    fn consider(
        p: &IdmParameters,
        mobil: &MobilParameters,
        view: &ControllerView<'_>,
        own: &mut Own,
        s: &Besides<'_, '_>,
        side: Side,
        best: &mut Option<(Real, i32)>,
    ) {
        // The mark first: a lane behind a mark not to be crossed costs no occupancy search
        // (either leaves the verdict "no change").
        if !view.open_beside(s, side) {
            return;
        }
        let Some(b) = view.beside_of(s, side) else {
            return;
        };
        if let Some(margin) = Self::weigh(p, mobil, view, own, b) {
            if best.is_none_or(|(m, _)| margin > m) {
                *best = Some((margin, b.lane));
            }
        }
    }
}

/// A mandatory lane held (module doc "A mandatory lane"): the one piece of state and code
/// both driver models run it with, the `mobil` controller and the `idm` ([`IdmDriver`]),
/// which is handed it when no user controller holds its entity's lateral domain
/// (controller/strategy.rs).
#[derive(Debug, Clone)]
pub(crate) struct Mandatory {
    /// The lane to reach.
    target: i32,
    /// The entity has been in it since it was asked for.
    reached: bool,
    /// The lanes beside as the road decides them (controller/lane_beside.rs).
    kept: KeptBeside,
    /// The target lane where it was last found, on the entity's road and lane section then
    /// (`None` before the first step): its id there is the lane to reach.
    on: Option<LaneHandle>,
    /// The road and lane section where the target lane was not found along its links, if the
    /// entity is still there (not searched again there).
    lost: Option<(u32, u32)>,
    /// What the event log is still to be told: that the target lane was lost where the entity
    /// is ([`Controller::note`]).
    note: Option<String>,
}

/// Most lane links followed from the target lane to the entity's road and lane section.
const MAX_LINK_HOPS: usize = 8;

impl Mandatory {
    /// The target lane's id on the entity's road and lane section now (module doc "Across
    /// roads"): the lane `target` names on the road where it was asked for, then, where the
    /// entity has passed into another lane section or road, the lane the target lane's links
    /// lead to there (OpenDRIVE 1.8 §11.5 lane linkage: "Lanes may be linked to lanes on the
    /// same or another road"), followed in its driving direction, breadth first, up to
    /// [`MAX_LINK_HOPS`] links (junction roads included). `None` where they lead nowhere there.
    fn target_here(&mut self, net: &RoadNetwork, track: &TrackInput) -> Option<i32> {
        let here = track
            .own
            .or_else(|| net.lane_handle_on(track.road, track.lane_id, track.s))?;
        let at = match self.on {
            Some(h) => h,
            None => {
                let h = net.lane_handle_on(track.road, self.target, track.s)?;
                self.on = Some(h);
                h
            }
        };
        let place = (here.road, here.section);
        if (at.road, at.section) == place {
            return Some(at.lane);
        }
        if self.lost == Some(place) {
            return None;
        }
        let mut frontier = vec![at];
        for _ in 0..MAX_LINK_HOPS {
            let mut next: Vec<LaneHandle> = Vec::new();
            for h in frontier {
                for &n in net.successors(h) {
                    if (n.road, n.section) == place {
                        self.on = Some(n);
                        self.lost = None;
                        return Some(n.lane);
                    }
                    if !next.contains(&n) {
                        next.push(n);
                    }
                }
            }
            if next.is_empty() {
                break;
            }
            frontier = next;
        }
        self.lost = Some(place);
        let road = net.road_at(track.road);
        self.note = Some(format!(
            "mandatory lane {} lost: its lane links lead onto no lane of road \"{}\" (lane section {}) where the entity is; it makes no change towards it there",
            self.target,
            road.id,
            here.section + 1
        ));
        None
    }

    /// Takes mandatory lane `lane` into `held` (`None`: releases the one held, if any);
    /// returns the event note.
    pub(crate) fn take(held: &mut Option<Box<Self>>, lane: Option<i32>) -> String {
        let note = match (lane, held.as_deref()) {
            (Some(l), _) => format!("mandatory lane {l}: changes lane by lane into gaps MOBIL's safety criterion accepts, then keeps it"),
            (None, Some(m)) if m.reached => format!("mandatory lane {} released, reached", m.target),
            (None, Some(m)) => format!("mandatory lane {} released, not reached: no gap MOBIL's safety criterion accepted before (the entity keeps the lane it is in)", m.target),
            (None, None) => "no mandatory lane to release".to_owned(),
        };
        *held = lane.map(|target| {
            Box::new(Mandatory {
                target,
                reached: false,
                kept: KeptBeside::default(),
                on: None,
                lost: None,
                note: None,
            })
        });
        note
    }

    /// The step of the mandatory lane (module doc) for a driver with IDM parameters `p` and
    /// MOBIL's safety criterion `mobil`: the lane beside to change to now, one lane towards
    /// the target, when the gap passes the criterion; else none, with `own`'s command lowered
    /// to −b where what blocks the change is not slower.
    fn decide(
        &mut self,
        view: &ControllerView<'_>,
        own: &mut Own,
        p: &IdmParameters,
        mobil: &MobilParameters,
    ) -> Option<i32> {
        let e = view.input();
        let track = e.track.as_ref()?;
        let target = self.target_here(view.network(), track)?;
        if track.lane_id == target {
            self.reached = true;
            return None;
        }
        if track.blend_from.is_some() || e.lateral_action || e.speed < MIN_CHANGE_SPEED {
            return None;
        }
        let toward = (target - track.lane_id).signum();
        let b = view
            .beside_kept(&mut self.kept.0)
            .into_iter()
            .flatten()
            .find(|b| (b.lane - track.lane_id).signum() == toward)?;
        // Not into a lane that ends within the change (module doc "A lane that ends"): it
        // waits, without falling back.
        if !b.crossing_permitted || view.lane_ends_within_change(&b, own.v, own.len) {
            return None;
        }
        // Whether to fall back: what blocks the change alongside or ahead is not slower, or
        // the gap to the new follower too close would not open in time.
        let fall_back = match view.fastest_alongside(&b) {
            Some(v) => v >= own.v,
            None => {
                let lane_leader = view.leader_beside(&b);
                if mobil.safe_for_changer(own.after(p, lane_leader)) {
                    let found = view.follower_beside(&b);
                    let new_follower = found.map(|n| {
                        Weighed::new_follower(p, n, own.v, own.len, lane_leader).change(p)
                    });
                    if new_follower.is_none_or(|n| mobil.safe_for_follower(n.after)) {
                        return Some(b.lane);
                    }
                    // A new follower too close: waited out where the changer's speed
                    // advantage opens the gap in time, else let past.
                    found.is_some_and(|n| !opens_in_time(p, mobil, own, n))
                } else {
                    lane_leader.is_some_and(|l| l.speed >= own.v)
                }
            }
        };
        if fall_back {
            own.a_c = own.a_c.min(-p.comfortable_deceleration);
        }
        None
    }
}

/// Whether the gap to `n`, a new follower too close behind the changer `own` in the lane beside,
/// opens by the changer's speed advantage within [`GAP_OPENING_TIME`] (module doc): the gap
/// g* at which n, weighed at the changer's parameters `p` as MOBIL weighs it, needs exactly
/// b_safe, ã_n = f(v_n) − a(s*/g*)² = −b_safe, so g* = s*·√(a/(b_safe + f(v_n))) with s* at
/// the speeds now, reached at the rate v − v_n. A follower not slower, or one that would brake
/// harder than b_safe at any gap, never lets the gap open.
fn opens_in_time(p: &IdmParameters, mobil: &MobilParameters, own: &Own, n: Gap) -> bool {
    let vn = n.speed.max(0.0);
    let closing = own.v - vn;
    let room = mobil.safe_deceleration + p.free_acceleration(vn);
    if !(closing > 0.0 && room > 0.0) {
        return false;
    }
    let needed = p.desired_gap(vn, vn - own.v) * (p.max_acceleration / room).sqrt();
    (needed - n.gap) / closing <= GAP_OPENING_TIME
}

/// The `idm` model as the engine runs it (module doc): the IDM ([`IdmController`]) and the
/// mandatory lane it may be handed where no user controller holds its entity's lateral domain.
#[derive(Debug, Clone)]
pub(crate) struct IdmDriver {
    /// The IDM.
    pub idm: IdmController,
    /// The mandatory lane held, if any.
    mandatory: Option<Box<Mandatory>>,
}

impl IdmDriver {
    /// The `idm` model driving by `idm`, with no mandatory lane.
    pub fn new(idm: IdmController) -> Self {
        IdmDriver {
            idm,
            mandatory: None,
        }
    }

    /// The step's command as numbers (controller/drivers.rs): without a mandatory lane the
    /// IDM's acceleration alone, as [`IdmController::acceleration`] gives it; with one, the
    /// same acceleration computed as the `mobil` controller computes it (the same
    /// operations) and the lane to change to, judged by MOBIL's safety criterion at the
    /// engine's default b_safe ([`MobilParameters::default`]: the `idm` has no MOBIL
    /// parameters).
    #[inline]
    pub fn command(&mut self, view: &ControllerView<'_>) -> (Real, Option<i32>) {
        self.idm.settle(view);
        match self.mandatory.as_deref_mut() {
            None => (self.idm.acceleration(view), None),
            Some(m) => Self::with_mandatory(&self.idm, m, view),
        }
    }

    /// [`command`](Self::command) with a mandatory lane held: out of line, so that the
    /// common step of an `idm` without one is the IDM's alone (issue 31, step 30: with
    /// [`Own::new`] always inlined, this keeps it out of the `idm`'s step).
    #[inline(never)]
    fn with_mandatory(
        idm: &IdmController,
        m: &mut Mandatory,
        view: &ControllerView<'_>,
    ) -> (Real, Option<i32>) {
        let mut own = Own::new(idm, view);
        let p = &idm.params;
        let lane = m.decide(view, &mut own, p, &MobilParameters::default());
        (own.a_c, lane)
    }
}

impl Controller for IdmDriver {
    fn model(&self) -> &'static str {
        "idm"
    }

    fn activate(&mut self, view: &ControllerView<'_>) {
        self.idm.on_activate(view);
    }

    fn strategy(&mut self, strategy: Strategy) -> Option<String> {
        match strategy {
            Strategy::MandatoryLane(lane) => Some(Mandatory::take(&mut self.mandatory, lane)),
            other => self.idm.on_strategy(other),
        }
    }

    fn note(&mut self) -> Option<String> {
        self.mandatory.as_mut()?.note.take()
    }

    fn step(&mut self, view: &ControllerView<'_>, _dt: Real) -> Command {
        motion(self.command(view))
    }
}

/// A driver model's step as a [`Command`]: the acceleration and the lane to change to, if any.
fn motion((a, lane): (Real, Option<i32>)) -> Command {
    Command::Motion {
        longitudinal: Some(Longitudinal::Acceleration(a)),
        lateral: lane.map(Lateral::ChangeLane),
    }
}

/// What one step of a `mobil` controller knows of its entity's own lane: worked out once for
/// both lanes beside it and for the longitudinal command.
struct Own {
    /// The entity's speed (≥ 0).
    v: Real,
    /// The free-road term at `v`.
    free: Real,
    /// Its length along the lane.
    len: Real,
    /// The leader in its lane, as the IDM reads it (its gap and speed). Not the [`Gap`]: kept
    /// here whole, the gap and speed were read back from the stack as one 16-byte load of what
    /// the search had stored 8 bytes at a time (and the id's 4 bytes as 8), loads that store
    /// forwarding cannot serve and that wait for the stores to reach the cache (issue 31: 16 %
    /// of `command`'s samples on one instruction; 4 % of the `mobil` step's time).
    leader: Option<Leader>,
    /// The s-range of its footprint in the lane index, if it has one (the lanes beside's
    /// occupancy asks about it: [`ControllerView::beside_kept_with`]).
    range: Option<(Real, Real)>,
    /// The red light ahead, if any (run option stop_at_red_lights).
    light: Option<Real>,
    /// a_c: the IDM acceleration behind the leader (or the light): also the command.
    a_c: Real,
    /// The old follower's interaction terms, once searched.
    old_follower: Option<Option<Weighed>>,
}

impl Own {
    /// `idm`'s free-road term (its own, or one handed to it: car_following.rs) at the entity's
    /// speed, weighed in every lane. Always inlined: called from the `mobil` step and the
    /// `idm`'s mandatory lane, it was left out of line once the second caller came, a call
    /// that cost `mobil` 22 instructions per entity-step (issue 31, step 30).
    #[inline(always)]
    fn new(idm: &IdmController, view: &ControllerView<'_>) -> Self {
        let p = &idm.params;
        let v = view.speed().max(0.0);
        let free = idm.free_term(view, v);
        // The leader, the length and the footprint's s-range with one look-up of the
        // footprint (issue 31).
        let OwnLane {
            leader,
            length,
            range,
        } = view.own_lane();
        let light = view.red_light();
        let leader = leader.map(to);
        Own {
            v,
            free,
            len: length,
            leader,
            range,
            light,
            a_c: p.acceleration_with_free(free, v, nearer(leader, light)),
            old_follower: None,
        }
    }
}

/// A gap as the IDM's leader.
fn to(g: Gap) -> Leader {
    Leader {
        gap: g.gap,
        speed: g.speed,
    }
}

impl Own {
    /// ã_c: the changer's IDM acceleration behind `lane_leader`, the leader in the lane beside
    /// (or the red light ahead, run option stop_at_red_lights: it stands across both lanes, no
    /// incentive to change for it).
    fn after(&self, p: &IdmParameters, lane_leader: Option<Gap>) -> Real {
        p.acceleration_with_free(self.free, self.v, nearer(lane_leader.map(to), self.light))
    }

    /// The old follower o (module doc), searched once a step: behind the changer now, behind
    /// the changer's leader at gap g_o + length + g_c after the change.
    fn old_follower(&mut self, p: &IdmParameters, view: &ControllerView<'_>) -> Option<Weighed> {
        if let Some(searched) = self.old_follower {
            return searched;
        }
        let (v, len, leader) = (self.v, self.len, self.leader);
        let found = view.follower().map(|o| {
            let vo = o.speed.max(0.0);
            let behind_me = Leader {
                gap: o.gap,
                speed: v,
            };
            let behind_leader = leader.map(|l| Leader {
                gap: o.gap + len + l.gap,
                speed: l.speed,
            });
            Weighed {
                v: vo,
                before: Some(p.interaction(vo, behind_me)),
                after: behind_leader.map(|l| p.interaction(vo, l)),
            }
        });
        // Kept, and returned as computed: read back from where it was kept, it was loaded 16
        // bytes at a time just after being stored 8 at a time, loads that store forwarding
        // cannot serve (issue 31).
        self.old_follower = Some(found);
        found
    }
}

/// A follower MOBIL weighs: its speed (≥ 0) and the IDM's interaction terms before and after
/// the change, at the changer's parameters (`None`: no leader, the free road).
#[derive(Debug, Clone, Copy)]
struct Weighed {
    v: Real,
    before: Option<Real>,
    after: Option<Real>,
}

impl Weighed {
    /// The new follower n (module doc), `n` behind the changer in the target lane: behind the
    /// lane's leader `leader` at gap g_n + length + g_l now, behind the changer (at speed `v`,
    /// `len` long) at gap g_n after the change.
    fn new_follower(p: &IdmParameters, n: Gap, v: Real, len: Real, leader: Option<Gap>) -> Self {
        let vn = n.speed.max(0.0);
        let behind_leader = leader.map(|l| Leader {
            gap: n.gap + len + l.gap,
            speed: l.speed,
        });
        let behind_me = Leader {
            gap: n.gap,
            speed: v,
        };
        Weighed {
            v: vn,
            before: behind_leader.map(|l| p.interaction(vn, l)),
            after: Some(p.interaction(vn, behind_me)),
        }
    }

    /// Its accelerations, as [`IdmParameters::acceleration_with_free`] gives them.
    fn change(&self, p: &IdmParameters) -> FollowerChange {
        let free = p.free_acceleration(self.v);
        FollowerChange {
            before: self.before.map_or(free, |x| free - x),
            after: self.after.map_or(free, |x| free - x),
        }
    }

    /// Bounds of them in the same operations ([`IdmParameters::free_acceleration_bounds`]):
    /// `before` at most the acceleration before, `after` at least the one after, so that
    /// after − before is at least the follower's gain, as the rule computes it.
    fn gain_bound(&self, p: &IdmParameters) -> FollowerChange {
        let (lo, hi) = p.free_acceleration_bounds(self.v);
        FollowerChange {
            before: self.before.map_or(lo, |x| lo - x),
            after: self.after.map_or(hi, |x| hi - x),
        }
    }
}

/// Whether the verdict on a candidate whose changer passed its safety criterion is "no
/// change" for a reason known from the followers' interaction terms alone, without their
/// free-road powers: the new follower unsafe by its bound, or the margin of MOBIL's own
/// arithmetic ([`MobilParameters::judge`]) on the followers' bounds at most 0.
///
/// Why it settles only what the rule settles. Every operation of the rule is rounded to
/// nearest, which is monotone: x ≤ x' gives fl(x − y) ≤ fl(x' − y), fl(y − x) ≥ fl(y − x'),
/// fl(x + y) ≤ fl(x' + y), and fl(p·x) ≤ fl(p·x') for p ≥ 0 (NaN aside). A follower's
/// accelerations are its free-road term f less its interaction terms, and
/// [`Weighed::gain_bound`] computes them from f's bounds lo ≤ f ≤ hi in the same operations,
/// so ã_n ≤ its bound's `after`, and ã − a ≤ the bound's after − before for both followers;
/// the margin, ((ã_c − a_c) + p·(gain_n + gain_o)) − threshold, is then at most the same
/// arithmetic on the bounds when the politeness p ≥ 0. Where the rule changes lanes, its
/// numbers are not NaN (a NaN margin or acceleration fails its tests), so the chain holds:
/// the new follower's ã_n ≥ −b_safe, so its bound is too, and the bounds' margin ≥ the
/// rule's > 0, so neither test here settles the candidate. A bound that is NaN settles
/// nothing ("<" and "≤" are false). Test: controller::mobil::tests::the_shortcut_gives_the_full_rule_bit_for_bit
/// and the_bounds_settle_only_what_the_rule_refuses.
fn settled_without_powers(
    mobil: &MobilParameters,
    p: &IdmParameters,
    view: &ControllerView<'_>,
    own: &mut Own,
    own_change: FollowerChange,
    new_follower: Option<Weighed>,
    b: &Beside<'_>,
) -> bool {
    let new_follower = new_follower.map(|n| n.gain_bound(p));
    if new_follower.is_some_and(|n| n.after < -mobil.safe_deceleration) {
        return true;
    }
    // politeness NaN or negative: not monotone, nothing settled.
    if mobil.politeness.is_nan() || mobil.politeness < 0.0 {
        return false;
    }
    let old_follower = own.old_follower(p, view).map(|o| o.gain_bound(p));
    let bound = mobil.judge(&LaneChangeCandidate {
        own: own_change,
        old_follower,
        new_follower,
        toward_keep_side: b.toward_keep_side,
    });
    bound.margin <= 0.0
}

impl Controller for MobilController {
    fn model(&self) -> &'static str {
        "mobil"
    }

    fn activate(&mut self, view: &ControllerView<'_>) {
        self.idm.on_activate(view);
    }

    fn strategy(&mut self, strategy: Strategy) -> Option<String> {
        match strategy {
            Strategy::Lane(lane) => {
                self.pending = Some(lane);
                Some(format!("lane change to lane {lane}"))
            }
            Strategy::MandatoryLane(lane) => Some(Mandatory::take(&mut self.mandatory, lane)),
            other => self.idm.on_strategy(other),
        }
    }

    fn note(&mut self) -> Option<String> {
        self.mandatory.as_mut()?.note.take()
    }

    fn step(&mut self, view: &ControllerView<'_>, _dt: Real) -> Command {
        motion(self.command(view))
    }
}

impl MobilController {
    /// The step's command as numbers (the controllers stage's walk of the driver models,
    /// controller/drivers.rs, takes them so): the acceleration and the lane to change to, if
    /// any. [`Controller::step`] is this as a [`Command`].
    pub(crate) fn command(&mut self, view: &ControllerView<'_>) -> (Real, Option<i32>) {
        self.idm.settle(view);
        let mut own = Own::new(&self.idm, view);
        // A lane change decided with a pending lane and no mandatory one is the
        // LaneChangeAction's (may_decide takes the pending lane before any judgement).
        let ordered = self.mandatory.is_none() && self.pending.is_some();
        let lane = self.decide(view, &mut own);
        if lane.is_some() {
            self.judged = (!ordered).then_some(self.last_change);
            self.last_change = view.time();
        }
        // a_c is the IDM controller's acceleration in this view (the same leader, light,
        // speed and parameters).
        (own.a_c, lane)
    }
}

impl MobilController {
    /// The change this step's command gave yields to another change into the same gap
    /// (controller/one_gap.rs): `true` when MOBIL or the mandatory lane judged it, and the
    /// controller is then as if it had decided none (its last change's time put back, so
    /// that it decides again in the next step); `false` for a LaneChangeAction's change,
    /// which is carried out as ordered.
    pub(crate) fn yield_change(&mut self) -> bool {
        match self.judged.take() {
            Some(before) => {
                self.last_change = before;
                true
            }
            None => false,
        }
    }

    /// MOBIL's safety criterion, at this controller's parameters, for its entity changing
    /// into a lane where `other` would be next to it ([`gap_safe`]).
    pub(crate) fn gap_safe(&self, view: &ControllerView<'_>, other: Next) -> bool {
        gap_safe(&self.idm, &self.mobil, view, other)
    }
}

impl IdmDriver {
    /// MOBIL's safety criterion at the default b_safe (the `idm` has no MOBIL parameters), for
    /// its entity changing into a lane where `other` would be next to it ([`gap_safe`]). A
    /// change of an `idm` is always its mandatory lane's, judged: it may always yield.
    pub(crate) fn gap_safe(&self, view: &ControllerView<'_>, other: Next) -> bool {
        gap_safe(&self.idm, &MobilParameters::default(), view, other)
    }
}

/// Another vehicle as it would be next to a changer in the lane it changes into
/// (controller/one_gap.rs): ahead of it (its new leader) or behind it (its new follower).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Next {
    /// The other vehicle.
    pub id: crate::world::EntityId,
    /// It is ahead.
    pub ahead: bool,
    /// Bumper-to-bumper distance along the lane (m); 0 or less where the boxes overlap along it.
    pub gap: Real,
    /// Its speed along the changer's direction of travel (m/s).
    pub speed: Real,
}

/// MOBIL's safety criterion (module doc; Kesting, Treiber, Helbing 2007, eq. (2)) for the
/// entity of `view`, driving by `idm`, changing into a lane where `other` would
/// be next to it: ahead, the changer's own ã_c behind it ≥ −b_safe, as [`Own::after`] weighs
/// a lane's leader; behind, its ã_n behind the changer ≥ −b_safe, weighed as MOBIL weighs a
/// new follower ([`Weighed::new_follower`]: at the changer's parameters). Boxes that overlap
/// along the lane (gap ≤ 0) fail it, as a box alongside fails a change.
fn gap_safe(
    idm: &IdmController,
    mobil: &MobilParameters,
    view: &ControllerView<'_>,
    other: Next,
) -> bool {
    if other.gap.is_nan() || other.gap <= 0.0 {
        return false;
    }
    let p = &idm.params;
    let own = Own::new(idm, view);
    let other_gap = Gap {
        id: other.id,
        gap: other.gap,
        speed: other.speed,
    };
    if other.ahead {
        mobil.safe_for_changer(own.after(p, Some(other_gap)))
    } else {
        let n = Weighed::new_follower(p, other_gap, own.v, own.len, None).change(p);
        mobil.safe_for_follower(n.after)
    }
}

#[cfg(test)]
#[path = "mobil_tests.rs"]
mod tests;
