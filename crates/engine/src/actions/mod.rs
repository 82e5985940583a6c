//! Actions at runtime (OpenSCENARIO 1.3 §7.7 "Actions", §8.4.1 action execution): the table
//! of every action of the storyboard, the [`ActionHost`] the storyboard drives, and one file
//! per action kind.
//!
//! Each private action runs once per actor. An instantaneous action (TeleportAction, a
//! SpeedAction with `step` shape, the global actions) takes effect in `start` and reports
//! ended; the others keep a per-actor [`Part`] that stage 2 of the step advances (where one may
//! also fail: `ActionTable::step_all` returns the failures, which stop the run). A new action
//! in the control domain (longitudinal, lateral) of an actor stops the one running there
//! (§7.5.1, semantics-pitfalls #7).

mod acceleration;
mod appearance;
mod check;
mod check_heading;
mod check_held;
mod custom;
mod distance;
mod entity;
mod environment;
mod follow_trajectory;
mod lane_change;
mod lane_follow;
mod lane_offset;
mod lateral_follow;
mod override_controller;
pub(crate) mod parameter;
mod random_traffic;
mod relative_acceleration;
mod routing;
mod speed;
mod speed_profile;
mod synchronize;
mod teleport;
mod trailer;
mod travel;
mod variable;
mod visibility;

use scenario::{
    Action, ActionKind, ControllerAction, GlobalAction, LaneChangeTarget, LateralAction,
    LongitudinalAction, PrivateAction, RoutingAction, SourcePos,
};

pub(crate) use appearance::Appearances;

use crate::condition::MarkIds;
use crate::controller::ControllerTable;
use crate::error::Error;
use crate::output::EventRecord;
use crate::store::World;
use crate::storyboard::{ActionId, ActionStatus};
use crate::traffic::Traffic;
use crate::world::entity::{Entity, EntityId};

/// The control domain an action occupies on its actor.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Domain {
    Longitudinal,
    Lateral,
}

/// The running state of one action on one actor.
#[derive(Debug, Clone)]
pub(crate) enum Part {
    Speed(speed::SpeedState),
    Acceleration(acceleration::AccelerationState),
    RelativeAcceleration(relative_acceleration::RelativeAccelerationState),
    Profile(speed_profile::ProfileState),
    Lateral(lane_change::LateralState),
    LateralFollow(lateral_follow::FollowState),
    LaneFollow(lane_follow::LaneFollowState),
    LongitudinalDistance(distance::LongitudinalState),
    LateralDistance(distance::LateralState),
    Trajectory(follow_trajectory::TrajectoryState),
    Synchronize(synchronize::SyncState),
    Appearance(appearance::Transition),
    Held(check_held::HeldCheck),
    Done(ActionStatus),
}

impl Part {
    fn status(&self) -> ActionStatus {
        match self {
            Part::Done(s) => *s,
            _ => ActionStatus::Running,
        }
    }
}

/// One action of the storyboard with its actors and per-actor state.
#[derive(Debug, Clone)]
pub(crate) struct ActionSlot {
    /// The name used in logs.
    pub name: String,
    /// The model.
    pub action: Action,
    /// The entities it acts on (private actions), in order.
    pub actors: Vec<EntityId>,
    /// Per actor, once started.
    pub parts: Vec<Part>,
    /// Simulation time of the start.
    pub started_at: f64,
    /// The entities a state check (`PrivateAction::Check`) names, by id, resolved as the
    /// table is built (none for the other actions).
    pub check_refs: check::CheckRefs,
}

/// Every action of the storyboard, indexed by [`ActionId`].
#[derive(Debug, Clone, Default)]
pub(crate) struct ActionTable {
    pub slots: Vec<ActionSlot>,
    /// The animations AppearanceActions set, per entity (appearance.rs).
    pub appearance: Appearances,
    /// The slots that may have a running part, ascending: stage 2 visits these only (a slot
    /// whose parts are all done does nothing there; 1,000 Init actions that ended at t = 0
    /// would otherwise be walked every step). A start with parts adds its slot; stage 2 drops
    /// the slots it finds done.
    live: Vec<u32>,
    /// The entities a lateral action held as stage 2 last ended, ascending (`order_domains`).
    lateral_held: Vec<EntityId>,
    /// The buffer `order_domains` fills next (kept: the stage allocates nothing once grown).
    lateral_held_next: Vec<EntityId>,
    /// The transitions of RelativeAccelerationActions that completed at their target in the
    /// last stage 2: actor, time (the step's end) and the acceleration reached, which an
    /// AccelerationAction keeping the acceleration and started next starts from
    /// (relative_acceleration.rs).
    reached: Vec<(EntityId, f64, f64)>,
    /// Whether a held state check may be running (`Part::Held`): set where one starts, and
    /// by each stage 2 to whether it found one still running; stage 2 steps them in a pass of
    /// their own before every other part only then.
    checks_held: bool,
    /// The followings of lanes (slot, part, actor) the following pass of stage 2 sets aside
    /// to step last, in chain order (`step_lane_follows`); empty between stages.
    lane_follows: Vec<(u32, usize, EntityId)>,
}

/// The passes of stage 2 over the running parts (`ActionTable::step_all`), in order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Pass {
    /// The held state checks, reading every entity as the stage starts.
    Checks,
    /// Every other part, in slot order.
    Own,
    /// The parts that read their references at the step's end (relative accelerations,
    /// lateral and lane following).
    Following,
}

impl ActionTable {
    /// Adds an action, returning its id; the entities a state check names are resolved in
    /// `world` now, its marks given their slots in `marks` (`check::CheckRefs`): an entity the
    /// scenario does not declare is an error at the action.
    pub fn push(
        &mut self,
        (world, marks): (&World, &mut MarkIds),
        name: String,
        action: Action,
        actors: Vec<EntityId>,
    ) -> Result<ActionId, Error> {
        let check_refs = match &action.kind {
            ActionKind::Private(PrivateAction::Check(c)) => {
                check::CheckRefs::resolve((world, marks), c, &action.pos)?
            }
            _ => check::CheckRefs::default(),
        };
        self.slots.push(ActionSlot {
            name,
            action,
            actors,
            parts: Vec::new(),
            started_at: 0.0,
            check_refs,
        });
        Ok(ActionId(self.slots.len() as u32 - 1))
    }

    /// Marks slot `id` as possibly running (after its start set its parts).
    fn mark_live(&mut self, id: ActionId) {
        if let Err(at) = self.live.binary_search(&id.0) {
            self.live.insert(at, id.0);
        }
    }

    /// Stage 2: advances every running part by one step from `now` over `dt`, in slot order;
    /// the held state checks first, so that each reads every entity at `now`, as the last
    /// step's moves left it (§8.9.1.1.1 `at: all`, "holds throughout the phase": a relation
    /// between the states at one time; before, a check after a SpeedAction of its reference in
    /// slot order read the reference's speed at the step's end and its actor's at its start,
    /// issue 27); the RelativeAccelerationActions and the lane changes beside a moving entity
    /// last, so that they read their references' speeds and lateral positions at the step's
    /// end (relative_acceleration.rs, lateral_follow.rs), and the followings of lanes after
    /// them, each after those of the actors it follows (`step_lane_follows`). Returns the
    /// actions that failed in the step (their names and errors), which stop the run.
    pub fn step_all(&mut self, world: &mut World, now: f64, dt: f64) -> Vec<(String, Error)> {
        let mut failures = Vec::new();
        self.reached.clear();
        self.note_start_speeds(world);
        self.synchronize_along_trajectories();
        let mut live = std::mem::take(&mut self.live);
        // The checks' pass only where a held check may run, the following pass only where
        // the own pass met a part that follows: most steps have neither, and the stage walks
        // every running action once.
        let (mut deferred, mut held) = (false, false);
        for pass in [Pass::Checks, Pass::Own, Pass::Following] {
            match pass {
                Pass::Checks if !self.checks_held => continue,
                Pass::Following if !deferred => break,
                _ => {}
            }
            for &index in &live {
                let slot = &mut self.slots[index as usize];
                let id = ActionId(index);
                for (j, (part, &actor)) in slot.parts.iter_mut().zip(&slot.actors).enumerate() {
                    let kind = match part {
                        Part::Held(_) => Pass::Checks,
                        Part::RelativeAcceleration(_)
                        | Part::LateralFollow(_)
                        | Part::LaneFollow(_) => Pass::Following,
                        _ => Pass::Own,
                    };
                    deferred |= kind == Pass::Following;
                    held |= kind == Pass::Checks;
                    if pass == Pass::Following && matches!(part, Part::LaneFollow(_)) {
                        self.lane_follows.push((index, j, actor));
                        continue;
                    }
                    if kind == pass {
                        let reached = &mut self.reached;
                        if let Some(e) = step_part(world, (actor, id), part, (now, dt), reached) {
                            failures.push((slot.name.clone(), e));
                        }
                    }
                }
            }
        }
        self.checks_held = held;
        self.step_lane_follows(world, (now, dt), &mut failures);
        // The domains' order over the slots live as the stage started (those that ended in
        // it too), then the slots found done are dropped.
        std::mem::swap(&mut self.live, &mut live);
        self.order_domains(world);
        std::mem::swap(&mut self.live, &mut live);
        live.retain(|&index| {
            self.slots[index as usize]
                .parts
                .iter()
                .any(|p| p.status() == ActionStatus::Running)
        });
        self.live = live;
        failures
    }

    /// Steps the followings of lanes the second pass of stage 2 set aside (`lane_follows`),
    /// last in the stage, each after those of the actors it follows (lane_follow.rs): in slot
    /// order, except that one whose references include the actor of another still to step
    /// waits for it (a cycle, each following the other, steps in slot order). So in a chain
    /// (car follows ego, who follows npc) car reads ego's new lane and weight of the same
    /// step, whatever their order in the storyboard.
    fn step_lane_follows(
        &mut self,
        world: &mut World,
        (now, dt): (f64, f64),
        failures: &mut Vec<(String, Error)>,
    ) {
        let mut pending = std::mem::take(&mut self.lane_follows);
        while !pending.is_empty() {
            let waits = |&(index, j, _): &(u32, usize, EntityId)| match &self.slots[index as usize]
                .parts[j]
            {
                Part::LaneFollow(s) => s.references().any(|x| {
                    pending
                        .iter()
                        .any(|&(i, k, a)| a == x && (i, k) != (index, j))
                }),
                _ => false,
            };
            let next = pending.iter().position(|p| !waits(p)).unwrap_or(0);
            let (index, j, actor) = pending.remove(next);
            let slot = &mut self.slots[index as usize];
            let (id, reached) = (ActionId(index), &mut self.reached);
            if let Some(e) = step_part(world, (actor, id), &mut slot.parts[j], (now, dt), reached) {
                failures.push((slot.name.clone(), e));
            }
        }
        // Kept: the stage allocates nothing once grown.
        self.lane_follows = pending;
    }

    /// The speed as stage 2 starts (`Entity::start_speed`), before any part changes it, of
    /// each entity that can read it: the controller's move and a lane change's step read it
    /// where the lateral action goes first (`order_domains`), which only an entity a lateral
    /// action holds can be. So the stage notes it for the candidates of `order_domains`
    /// instead of walking every entity (issue 31: that walk, a cache line of each of 4,000
    /// entities per step, was 2–3 % of a driver-model run).
    fn note_start_speeds(&self, world: &mut World) {
        for actor in self.ordered_candidates() {
            let e = world.entity_mut(actor);
            e.start_speed = e.speed;
        }
    }

    /// The entities whose lateral action can go first (see `order_domains`): those a lateral
    /// action held at the last stage, and the actors of the slots that may be running. A
    /// lateral domain is claimed only by the start of an action with parts, whose slot is
    /// then live until a stage has seen it (an action may end and keep its domain: the
    /// corpus test has a LaneChangeAction `Ended` with its actor's lateral domain naming it).
    fn ordered_candidates(&self) -> impl Iterator<Item = EntityId> + '_ {
        let actors = self
            .live
            .iter()
            .flat_map(|&index| self.slots[index as usize].actors.iter().copied());
        self.lateral_held.iter().copied().chain(actors)
    }

    /// Which domain's action comes first in the storyboard, for the controller's choice of
    /// speed (`Entity::lateral_first`): action ids number the actions in document order
    /// (runtime/build.rs). The lateral one goes first only where a lateral action holds the
    /// domain, so the stage sets it over `ordered_candidates` and keeps those a lateral action
    /// holds for the next stage, instead of walking every entity (issue 31). Called before
    /// the stage drops the slots it found done from `live`. In debug builds (every
    /// `cargo test`) the result is checked against the rule over every entity.
    fn order_domains(&mut self, world: &mut World) {
        let mut held = std::mem::take(&mut self.lateral_held_next);
        held.clear();
        for id in self.ordered_candidates() {
            let e = world.entity_mut(id);
            e.lateral_first = lateral_goes_first(e);
            if e.lateral_action.is_some() {
                held.push(id);
            }
        }
        // An entity can be both held and an actor, or the actor of several slots.
        held.sort_unstable();
        held.dedup();
        self.lateral_held_next = std::mem::replace(&mut self.lateral_held, held);
        debug_assert!(
            world
                .entities()
                .iter()
                .all(|e| e.lateral_first == lateral_goes_first(e)),
            "lateral_first set for the candidates only is the rule over every entity"
        );
    }
}

/// Whether `e`'s lateral action comes before its longitudinal one in the storyboard, or it
/// has a lateral action only (`Entity::lateral_first`).
fn lateral_goes_first(e: &Entity) -> bool {
    let order = |id: Option<ActionId>| id.map(|id| id.0);
    match (order(e.lateral_action), order(e.longitudinal_action)) {
        (Some(lat), Some(lon)) => lat < lon,
        (Some(_), None) => true,
        _ => false,
    }
}

/// Advances `part` of action `id` on `actor` by one step from `now` over `dt`; a part that
/// stops running frees the actor's domain and becomes `Done` (a RelativeAccelerationAction's
/// transition that reached its target noted in `reached`). Returns why it failed, if it did.
fn step_part(
    world: &mut World,
    (actor, id): (EntityId, ActionId),
    part: &mut Part,
    (now, dt): (f64, f64),
    reached: &mut Vec<(EntityId, f64, f64)>,
) -> Option<Error> {
    let next = match part {
        Part::Done(_) => return None,
        Part::Speed(s) => speed::step(world, actor, s, now, dt),
        Part::Acceleration(s) => acceleration::step(world, actor, s, now, dt),
        Part::RelativeAcceleration(s) => relative_acceleration::step(world, actor, s, now, dt),
        Part::Profile(s) => speed_profile::step(world, actor, s, now, dt),
        Part::Lateral(s) => lane_change::step(world, actor, s, now, dt),
        Part::LateralFollow(s) => lateral_follow::step(world, actor, s, now, dt),
        Part::LaneFollow(s) => lane_follow::step(world, actor, s),
        Part::LongitudinalDistance(s) => distance::step_longitudinal(world, actor, s, dt),
        Part::LateralDistance(s) => distance::step_lateral(world, actor, s, dt),
        Part::Trajectory(s) => follow_trajectory::step(world, actor, s, now, dt),
        Part::Synchronize(s) => synchronize::step(world, actor, s, dt),
        Part::Appearance(s) => s.step(now, dt),
        Part::Held(s) => check_held::step(world, actor, s, now),
    };
    if next == ActionStatus::Running {
        return None;
    }
    let failure = match part {
        Part::RelativeAcceleration(s) => {
            reached.extend(s.reached().map(|(at, a)| (actor, at, a)));
            s.failure.take()
        }
        Part::Held(s) => s.failure.take(),
        _ => None,
    };
    release(world, actor, id);
    *part = Part::Done(next);
    failure
}

impl ActionTable {
    /// Gives every running SynchronizeAction its actor's remaining distance along the
    /// trajectory the actor follows, if it follows one (synchronize.rs).
    fn synchronize_along_trajectories(&mut self) {
        // Synchronize and Trajectory parts run: only the live slots can hold them (in slot
        // order, so the first trajectory found is the same).
        let mut syncs = Vec::new();
        for &i in &self.live {
            let (i, slot) = (i as usize, &self.slots[i as usize]);
            for (j, (part, &actor)) in slot.parts.iter().zip(&slot.actors).enumerate() {
                if let Part::Synchronize(s) = part {
                    syncs.push((i, j, actor, s.target_point()));
                }
            }
        }
        for (i, j, actor, (x, y)) in syncs {
            let along = self
                .live
                .iter()
                .map(|&k| &self.slots[k as usize])
                .flat_map(|slot| slot.parts.iter().zip(&slot.actors))
                .find_map(|(part, &a)| match part {
                    Part::Trajectory(t) if a == actor => Some(t.remaining_to(x, y)),
                    _ => None,
                });
            if let Part::Synchronize(s) = &mut self.slots[i].parts[j] {
                s.set_along_path(along);
            }
        }
    }
}

/// Stops a running part midway: a lateral transition keeps the lateral position reached, a
/// trajectory hands the actor back to the default controller where it stands.
fn interrupt(world: &mut World, actor: EntityId, part: &mut Part) {
    match part {
        Part::Lateral(_)
        | Part::LateralFollow(_)
        | Part::LaneFollow(_)
        | Part::LateralDistance(_) => world.keep_lateral_position(actor),
        Part::Trajectory(_) => world.release_to_road(actor, false),
        _ => {}
    }
    *part = Part::Done(ActionStatus::Stopped);
}

/// Frees the control domains `actor` gave to action `id`.
fn release(world: &mut World, actor: EntityId, id: ActionId) {
    let e = world.entity_mut(actor);
    if e.longitudinal_action == Some(id) {
        e.longitudinal_action = None;
    }
    if e.lateral_action == Some(id) {
        e.lateral_action = None;
    }
}

/// Stops the action of `table` running in `domain` of `actor`, if any, and frees the domain
/// (a user controller took it).
pub(crate) fn stop_domain(
    table: &mut ActionTable,
    world: &mut World,
    actor: EntityId,
    domain: Domain,
) {
    let e = world.entity_mut(actor);
    let held = match domain {
        Domain::Longitudinal => e.longitudinal_action.take(),
        Domain::Lateral => e.lateral_action.take(),
    };
    let Some(old) = held else {
        return;
    };
    if let Some(slot) = table.slots.get_mut(old.0 as usize) {
        for (part, &a) in slot.parts.iter_mut().zip(&slot.actors) {
            if a == actor && part.status() == ActionStatus::Running {
                interrupt(world, actor, part);
            }
        }
    }
    release(world, actor, old);
}

/// The storyboard's [`ActionHost`] over the table and the world for one step.
pub(crate) struct Host<'a> {
    pub table: &'a mut ActionTable,
    pub world: &'a mut World,
    /// The user controllers (engine module `controller`): a ControllerAction changes them, a
    /// motion action on a domain one holds goes to it.
    pub controllers: &'a mut ControllerTable,
    /// The traffic actions at work (engine module `traffic`).
    pub traffic: &'a mut Traffic,
    pub events: &'a mut Vec<EventRecord>,
    pub errors: &'a mut Vec<Error>,
    /// The Init actions have started: this action belongs to a Story.
    pub story: bool,
    pub time: f64,
}

impl Host<'_> {
    /// Claims `domain` of `actor` for `id`, stopping the action that held it.
    fn claim(&mut self, actor: EntityId, domain: Domain, id: ActionId) {
        let e = self.world.entity_mut(actor);
        let held = match domain {
            Domain::Longitudinal => e.longitudinal_action.replace(id),
            Domain::Lateral => e.lateral_action.replace(id),
        };
        if let Some(old) = held.filter(|&old| old != id) {
            if let Some(slot) = self.table.slots.get_mut(old.0 as usize) {
                for (part, &a) in slot.parts.iter_mut().zip(&slot.actors) {
                    if a == actor && part.status() == ActionStatus::Running {
                        interrupt(self.world, actor, part);
                    }
                }
            }
        }
    }

    /// The first acceleration of the AccelerationAction holding `actor`'s longitudinal domain,
    /// if it started in this step (it has not acted yet).
    fn acceleration_started_now(&self, actor: EntityId) -> Option<f64> {
        let held = self.world.entity(actor).longitudinal_action?;
        let slot = self.table.slots.get(held.0 as usize)?;
        slot.parts
            .iter()
            .zip(&slot.actors)
            .find_map(|(part, &a)| match part {
                Part::Acceleration(s) if a == actor => s.first_if_started_at(self.time),
                _ => None,
            })
    }

    /// The acceleration a RelativeAccelerationAction's transition to its target reached for
    /// `actor` at the end of the last step, if one completed then (a hold starts from it).
    fn transition_reached(&self, actor: EntityId) -> Option<f64> {
        self.table
            .reached
            .iter()
            .find(|(a, at, _)| *a == actor && (at - self.time).abs() <= crate::tolerance::TIME)
            .map(|r| r.2)
    }

    /// Stops the action running in `domain` of `actor`, if any, and frees the domain.
    fn stop_domain(&mut self, actor: EntityId, domain: Domain) {
        stop_domain(self.table, self.world, actor, domain);
    }

    /// Starts a private action on one actor.
    fn start_private(
        &mut self,
        id: ActionId,
        action: &PrivateAction,
        actor: EntityId,
    ) -> Result<Part, Error> {
        let pos = &self.table.slots[id.0 as usize].action.pos.clone();
        let time = self.time;
        // A motion action on a domain a user controller holds goes to that controller and
        // completes at once (engine module `controller`).
        let name = self.table.slots[id.0 as usize].name.clone();
        let origin = crate::controller::Origin {
            element: &name,
            time,
            pos,
        };
        if crate::controller::hand_over(
            self.world,
            self.controllers,
            actor,
            action,
            !self.story,
            &origin,
            self.events,
        )? {
            return Ok(Part::Done(ActionStatus::Ended));
        }
        match action {
            PrivateAction::Teleport(position) => {
                teleport::start(self.world, actor, position, self.story)?;
                Ok(Part::Done(ActionStatus::Ended))
            }
            PrivateAction::CreateRandomTraffic(c) => {
                random_traffic::start(self.world, c, pos)?;
                Ok(Part::Done(ActionStatus::Ended))
            }
            PrivateAction::Check(check) => {
                let refs = self.table.slots[id.0 as usize].check_refs;
                check::start(self.world, actor, (check, &refs), (time, pos))?;
                self.table.checks_held |= check.throughout;
                Ok(match check.throughout {
                    true => Part::Held(check_held::HeldCheck::new(
                        self.world,
                        (check, &refs),
                        (time, pos),
                    )?),
                    false => Part::Done(ActionStatus::Ended),
                })
            }
            PrivateAction::Longitudinal(l) => {
                let replaced = match l {
                    LongitudinalAction::Acceleration { .. } => self
                        .acceleration_started_now(actor)
                        .or_else(|| self.transition_reached(actor)),
                    _ => None,
                };
                self.claim(actor, Domain::Longitudinal, id);
                match l {
                    LongitudinalAction::Speed { dynamics, target } => {
                        speed::start(self.world, actor, dynamics, target, time, pos)
                    }
                    LongitudinalAction::SpeedProfile { .. } => {
                        speed_profile::start(self.world, actor, l, time, pos)
                    }
                    LongitudinalAction::LongitudinalDistance { .. } => {
                        distance::start_longitudinal(self.world, actor, l, pos)
                    }
                    LongitudinalAction::Acceleration {
                        target,
                        dynamics,
                        ends_at_target,
                    } => Ok(acceleration::start(
                        self.world,
                        actor,
                        (*target, replaced),
                        (dynamics, *ends_at_target),
                        time,
                    )),
                    LongitudinalAction::RelativeAcceleration {
                        entity_ref,
                        value,
                        continuous,
                        to_speed,
                        transition,
                        ends_at_target,
                    } => relative_acceleration::start(
                        self.world,
                        actor,
                        entity_ref,
                        (*value, *continuous, to_speed.as_deref()),
                        (transition.as_ref(), *ends_at_target),
                        (time, pos),
                    ),
                    LongitudinalAction::Travel(travel) => {
                        travel::start(self.world, actor, travel, time, pos)
                    }
                    // Only a driver model takes it (handed over above).
                    LongitudinalAction::ModelAcceleration { .. } => Err(Error::at(
                        "a driver model to take the free-road acceleration (idm or mobil holding the longitudinal domain)",
                        "none",
                        pos,
                    )),
                    _ => Err(Error::unsupported("this LongitudinalAction", pos)),
                }
            }
            PrivateAction::Lateral(l) => {
                self.claim(actor, Domain::Lateral, id);
                match l {
                    // oscsim's lane change beside a moving entity (lateral_follow.rs).
                    LateralAction::LaneChange {
                        target:
                            LaneChangeTarget::Beside {
                                entity_ref,
                                t,
                                what,
                                follow: true,
                                roads,
                            },
                        dynamics,
                        ..
                    } => lateral_follow::start(
                        self.world,
                        actor,
                        (entity_ref, *t, what, roads),
                        dynamics,
                        time,
                        pos,
                    ),
                    LateralAction::LaneChange { .. } => {
                        lane_change::start(self.world, actor, l, time, pos)
                    }
                    LateralAction::LaneChangeAt(at) => {
                        lane_change::start_at(self.world, actor, at, time, pos)
                    }
                    LateralAction::OffsetInWidth(w) => {
                        lane_offset::start_in_width(self.world, actor, w, time, pos)
                    }
                    LateralAction::LaneOffset { .. } => {
                        lane_offset::start(self.world, actor, l, time, pos)
                    }
                    LateralAction::LateralDistance { .. } => {
                        distance::start_lateral(self.world, actor, l, pos)
                    }
                    LateralAction::FollowLanes(followed) => {
                        lane_follow::start(self.world, followed, pos)
                    }
                    // Only a driver model takes it (handed over above).
                    LateralAction::MandatoryLane { .. } => Err(Error::at(
                        "a driver model to take the mandatory lane (mobil holding the lateral domain, or idm the longitudinal one)",
                        "none",
                        pos,
                    )),
                    _ => Err(Error::unsupported("this LateralAction", pos)),
                }
            }
            PrivateAction::Visibility(v) => {
                let name = self.table.slots[id.0 as usize].name.clone();
                visibility::start(self.world, actor, v, &name, time, self.events);
                Ok(Part::Done(ActionStatus::Ended))
            }
            PrivateAction::Synchronize(s) => {
                self.claim(actor, Domain::Longitudinal, id);
                synchronize::start(self.world, s, pos)
            }
            PrivateAction::Controller(c) => {
                let name = self.table.slots[id.0 as usize].name.clone();
                let origin = crate::controller::Origin {
                    element: &name,
                    time,
                    pos,
                };
                let taken = match &**c {
                    ControllerAction::OverrideValues(o) => {
                        override_controller::start(self.world, actor, o, &name, time, self.events);
                        crate::controller::Taken::default()
                    }
                    ControllerAction::Assign {
                        controller,
                        object_controller_name,
                        activate,
                    } => crate::controller::assign(
                        self.world,
                        self.controllers,
                        actor,
                        controller,
                        object_controller_name.as_deref(),
                        activate,
                        &origin,
                        self.events,
                    )?,
                    ControllerAction::Activate {
                        object_controller_ref,
                        domains,
                    } => crate::controller::activate(
                        self.world,
                        self.controllers,
                        actor,
                        object_controller_ref.as_deref(),
                        domains,
                        &origin,
                        self.events,
                    )?,
                    _ => return Err(Error::unsupported("this ControllerAction", pos)),
                };
                // A user controller that takes a domain ends the action running there.
                if taken.longitudinal {
                    self.stop_domain(actor, Domain::Longitudinal);
                }
                if taken.lateral {
                    self.stop_domain(actor, Domain::Lateral);
                }
                Ok(Part::Done(ActionStatus::Ended))
            }
            PrivateAction::Routing(r) => self.start_routing(id, r, actor),
            PrivateAction::Appearance(a) => {
                let name = self.table.slots[id.0 as usize].name.clone();
                let transition = appearance::start(
                    self.world,
                    &mut self.table.appearance,
                    actor,
                    a,
                    &name,
                    time,
                    self.events,
                );
                Ok(transition.map_or(Part::Done(ActionStatus::Ended), Part::Appearance))
            }
            PrivateAction::Trailer(t) => {
                trailer::start(self.world, actor, t, pos)?;
                Ok(Part::Done(ActionStatus::Ended))
            }
            other => {
                let name = self.table.slots[id.0 as usize].name.clone();
                self.events
                    .push(EventRecord::unsupported(time, &name, kind_name(other), pos));
                Ok(Part::Done(ActionStatus::Ended))
            }
        }
    }

    /// Starts a RoutingAction on one actor.
    fn start_routing(
        &mut self,
        id: ActionId,
        action: &RoutingAction,
        actor: EntityId,
    ) -> Result<Part, Error> {
        let slot = &self.table.slots[id.0 as usize];
        let (pos, name, time) = (slot.action.pos.clone(), slot.name.clone(), self.time);
        match action {
            RoutingAction::AssignRoute(route) => {
                routing::assign(self.world, actor, route, &pos, &name, time, self.events);
                Ok(Part::Done(ActionStatus::Ended))
            }
            RoutingAction::AcquirePosition(target) => {
                routing::acquire(self.world, actor, target, &name, time, self.events);
                Ok(Part::Done(ActionStatus::Ended))
            }
            RoutingAction::FollowTrajectory {
                trajectory,
                time_reference,
                following_mode,
                initial_distance_offset,
            } => {
                let request = follow_trajectory::Request {
                    trajectory,
                    timing: time_reference.as_ref(),
                    following_mode: *following_mode,
                    initial_distance_offset: *initial_distance_offset,
                };
                Ok(self.start_trajectory(id, actor, request, (&pos, &name)))
            }
            RoutingAction::FollowTrajectoryAtSpeed(a) => {
                let trajectory = follow_trajectory::at_speed(self.world, a, time)?;
                let request = follow_trajectory::Request {
                    trajectory: &trajectory,
                    timing: Some(&a.time_reference),
                    following_mode: a.following_mode,
                    initial_distance_offset: None,
                };
                Ok(self.start_trajectory(id, actor, request, (&pos, &name)))
            }
            RoutingAction::RandomRoute => {
                routing::random(self.world, actor, &pos, &name, time, self.events);
                Ok(Part::Done(ActionStatus::Ended))
            }
            _ => {
                self.events.push(EventRecord::unsupported(
                    time,
                    &name,
                    "this RoutingAction",
                    &pos,
                ));
                Ok(Part::Done(ActionStatus::Ended))
            }
        }
    }

    /// Starts a FollowTrajectoryAction on `actor`, claiming the lateral domain (and with a
    /// time reference the longitudinal one). A trajectory that cannot be built skips the
    /// action (recorded in the event log); the actor drives on under the default controller.
    fn start_trajectory(
        &mut self,
        id: ActionId,
        actor: EntityId,
        request: follow_trajectory::Request<'_>,
        (pos, name): (&SourcePos, &str),
    ) -> Part {
        let time = self.time;
        self.claim(actor, Domain::Lateral, id);
        if request.timing.is_some() {
            self.claim(actor, Domain::Longitudinal, id);
        }
        let started = follow_trajectory::start(self.world, actor, request, time, pos);
        started.unwrap_or_else(|e| {
            self.events.push(EventRecord::error(time, name, &e));
            release(self.world, actor, id);
            Part::Done(ActionStatus::Stopped)
        })
    }

    fn start_global(&mut self, id: ActionId, action: &GlobalAction) -> Result<(), Error> {
        let slot = &self.table.slots[id.0 as usize];
        let (pos, name) = (slot.action.pos.clone(), slot.name.clone());
        match action {
            GlobalAction::Parameter {
                parameter_ref,
                rule,
            } => parameter::apply(self.world, parameter_ref, rule, &pos),
            GlobalAction::Variable { variable_ref, rule } => {
                variable::apply(self.world, variable_ref, rule, &pos)
            }
            GlobalAction::Environment(environment) => {
                environment::start(self.world, environment, self.time);
                Ok(())
            }
            GlobalAction::Entity { entity_ref, add_at } => {
                entity::apply(self.world, entity_ref, add_at.as_ref(), &pos)?;
                let change = if add_at.is_some() { "added" } else { "deleted" };
                self.events.push(EventRecord::Entity {
                    time: self.time,
                    element: name,
                    entity: entity_ref.clone(),
                    change: change.to_owned(),
                });
                Ok(())
            }
            GlobalAction::Traffic {
                traffic_name,
                action,
            } if crate::traffic::supports(action) => crate::traffic::start(
                self.world,
                self.traffic,
                &name,
                traffic_name.as_deref(),
                action,
                &pos,
            ),
            GlobalAction::TrafficSignal(scenario::TrafficSignalAction::State { name, state }) => {
                self.world
                    .signals
                    .set_state(name, state, self.time, self.events);
                Ok(())
            }
            GlobalAction::TrafficSignal(scenario::TrafficSignalAction::Controller {
                traffic_signal_controller_ref,
                phase,
            }) => self.world.signals.set_phase(
                traffic_signal_controller_ref,
                phase,
                self.time,
                &pos,
                self.events,
            ),
            GlobalAction::SetMonitor { monitor_ref, value } => {
                // The reader checks that monitorRef names a MonitorDeclaration.
                let old = self.world.monitors.insert(monitor_ref.clone(), *value);
                if old != Some(*value) {
                    self.events.push(EventRecord::Monitor {
                        time: self.time,
                        element: monitor_ref.clone(),
                        value: *value,
                    });
                }
                Ok(())
            }
            _ => {
                self.events.push(EventRecord::unsupported(
                    self.time,
                    &name,
                    "this GlobalAction",
                    &pos,
                ));
                Ok(())
            }
        }
    }

    fn try_start(&mut self, id: ActionId) -> Result<(), Error> {
        let slot = &mut self.table.slots[id.0 as usize];
        slot.started_at = self.time;
        slot.parts.clear();
        // Selection actors (ByType, spawned vehicles) are the members at the start.
        if let Some(now) = self.world.selections.actors_now(id, self.world) {
            slot.actors = now;
        }
        let action = slot.action.clone();
        let actors = slot.actors.clone();
        match &action.kind {
            ActionKind::Private(p) => {
                let mut parts = Vec::with_capacity(actors.len());
                for &actor in &actors {
                    parts.push(self.start_private(id, p, actor)?);
                }
                self.table.slots[id.0 as usize].parts = parts;
                self.table.mark_live(id);
            }
            ActionKind::Global(g) => {
                self.start_global(id, g)?;
                self.table.slots[id.0 as usize].parts = vec![Part::Done(ActionStatus::Ended)];
            }
            ActionKind::UserDefined(u) => {
                let name = self.table.slots[id.0 as usize].name.clone();
                custom::record(u, &name, self.time, self.events);
                self.table.slots[id.0 as usize].parts = vec![Part::Done(ActionStatus::Ended)];
            }
            // Read with a warning at load; it ends in the step it starts.
            ActionKind::Empty => {
                self.table.slots[id.0 as usize].parts = vec![Part::Done(ActionStatus::Ended)];
            }
            _ => {
                let name = self.table.slots[id.0 as usize].name.clone();
                self.events.push(EventRecord::unsupported(
                    self.time,
                    &name,
                    "this action",
                    &action.pos,
                ));
                self.table.slots[id.0 as usize].parts = vec![Part::Done(ActionStatus::Ended)];
            }
        }
        Ok(())
    }
}

fn kind_name(a: &PrivateAction) -> &'static str {
    match a {
        PrivateAction::Synchronize(_) => "SynchronizeAction",
        PrivateAction::Routing(_) => "RoutingAction",
        PrivateAction::Appearance(_) => "AppearanceAction",
        PrivateAction::Trailer(_) => "TrailerAction",
        _ => "this PrivateAction",
    }
}

impl Host<'_> {
    /// Starts action `id` ([`crate::storyboard::ActionHost::start`]); a failure stops it and is
    /// recorded.
    pub fn start(&mut self, id: ActionId) {
        if let Err(e) = self.try_start(id) {
            let slot = &mut self.table.slots[id.0 as usize];
            slot.parts = vec![Part::Done(ActionStatus::Stopped)];
            self.events
                .push(EventRecord::error(self.time, &slot.name, &e));
            // Live until stage 2 has seen it: a private action may have claimed a domain of
            // an actor before failing, and stage 2 orders the domains of live slots' actors
            // (`order_domains`), should the host step on after the error.
            self.table.mark_live(id);
            self.errors.push(e);
        }
    }

    /// Stops action `id` on every actor.
    pub fn stop(&mut self, id: ActionId) {
        let Some(slot) = self.table.slots.get_mut(id.0 as usize) else {
            return;
        };
        for (part, &actor) in slot.parts.iter_mut().zip(&slot.actors) {
            if part.status() == ActionStatus::Running {
                interrupt(self.world, actor, part);
            }
        }
        for &actor in &slot.actors {
            release(self.world, actor, id);
        }
    }
}

/// The status of action `id` as the storyboard sees it in the step that ends at `step_end`:
/// running while any actor's part runs, else stopped if any part was stopped, else ended.
///
/// A transition over a fixed time that reaches its goal by `step_end` reports ended in this
/// step: its last stretch of motion is this step's (stage 2 still applies it). This is how
/// esmini's logs time the end of such actions (e.g. a 3 s lane change started at 6.500 ends at
/// 9.450, the step whose motion completes it), and an Event that ends so can restart in the
/// next step instead of being overridden there.
pub(crate) fn status(table: &ActionTable, id: ActionId, step_end: f64) -> ActionStatus {
    let Some(slot) = table.slots.get(id.0 as usize) else {
        return ActionStatus::Ended;
    };
    let mut status = ActionStatus::Ended;
    for part in &slot.parts {
        let finishing = match part {
            Part::Speed(s) => s.completes_by(step_end),
            Part::Acceleration(s) => s.completes_by(step_end),
            Part::RelativeAcceleration(s) => s.completes_by(step_end),
            Part::Profile(s) => s.completes_by(step_end),
            Part::Lateral(s) => s.completes_by(step_end),
            Part::LateralFollow(s) => s.completes_by(step_end),
            Part::Trajectory(s) => s.completes_by(step_end),
            Part::Appearance(s) => s.completes_by(step_end),
            _ => false,
        };
        if finishing {
            continue;
        }
        match part.status() {
            ActionStatus::Running => return ActionStatus::Running,
            ActionStatus::Stopped => status = ActionStatus::Stopped,
            ActionStatus::Ended => {}
        }
    }
    status
}
