//! The plan: when each phase starts and ends, and what each actor does in it (ASAM OpenSCENARIO
//! DSL 2.1 §7.3.9 composition semantics, §8.9 movement modifiers).
//!
//! # When phases start and end
//!
//! - `serial`: a member starts when the one before it ends; the composition ends with its last
//!   member. `parallel`: members start together; it ends with its own `duration`/`until`, else
//!   when the last member that has an end of its own ends, and members without one end with it.
//!   `one_of`: the member drawn from the seed, as a one-member serial.
//! - A phase's `duration` (a range is drawn from the seed) or `until` (whichever comes first)
//!   ends it; an invocation without either ends with its composition, or when the engine
//!   measures its `position(…, at: end)` gap reached. A composition's own end also stops its
//!   running members (and a serial's later members never start). `emit e` is an instant.
//! - A phase that nothing ends is an error before the run, unless it is the last thing the
//!   scenario does and the run is bounded (`--duration`).
//!
//! Times the plan knows are absolute (a SimulationTimeCondition); after an `until` or a `wait`
//! on a condition, the next phase starts on the state of the one that ended (same step), and a
//! `duration` there counts from the phase's own start. Actors are planned in lane lengths
//! (the engine moves along lane centres) converted to s of the road.
//!
//! # What actors do
//!
//! `speed(v)` (`at: all`/`start`): the actor's speed from the phase start (a step: `at: all`
//! cannot hold otherwise); in its first phase, its initial speed. `speed(v, at: end)` and
//! `change_speed(v)`: a linear change over the phase. `position(d, ahead_of|behind: x, at:
//! end)`: a speed profile of two linear halves, v0 → vm over T/2 and vm → ve over T/2, with vm =
//! (4·Δs/T − v0 − ve)/2 so that the distance covered is Δs (ve is the phase's end speed: its
//! `speed(…)`, else v0). `lane(…, at: end)` and `change_lane(n, side)`: a sinusoidal lane change
//! over the phase. Limits: speeds 0 to 70 m/s, accelerations up to 10 m/s²; beyond them the
//! constraint is unsatisfiable, an error naming the modifier.
//!
//! Modifiers that constrain the motion without adding to it are checked against the plan:
//! `along(r)` (the `route` module: the actor on its route at the phase start and end),
//! `keep_lane`, `keep_speed`, `physical_movement(must_be_physical)` (no contradicting change;
//! `modifier::check_keeps`) and `movement_mode: monotonous` on `position(…, at: end)`.
//!
//! This module schedules the phases; `invoke` plans one invocation's actions, `motion` holds
//! the speed profiles, modifier values, lane targets and limits they use.

use std::collections::HashMap;

use dsl::semantics::hir::{Expr, Span};
use scenario::{ConditionGroup, PrivateAction, StoryboardElementState, Trigger, Vehicle};

use crate::actors::{self, ActorKind};
use crate::condition::{act_state, every_from_start, sim_time, trigger, Names, Timed};
use crate::error::{Error, ErrorKind as K};
use crate::modifier::{read, At, Mod, ModKind};
use crate::phase::{Kind, Phase};
use crate::place::{place, ToPlace};
use crate::road::PlanRoad;
use crate::route::{self, Along};
use crate::track::Track;
use crate::value::Ctx;

mod invoke;
mod motion;

/// How far from a constraint's value the plan may end (m), for `position(…, at: end)` checked
/// against a constant speed.
pub const POSITION_TOLERANCE: f64 = 0.5;

/// How far from a `lateral(…)` offset a later phase may start (m).
const LATERAL_TOLERANCE: f64 = 0.01;

/// A moment of the plan.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum When {
    /// At this simulation time (s).
    At(f64),
    /// When this trigger fires.
    Dyn(Trigger),
    /// Never (the run's bound ends it).
    Never,
    /// With the enclosing parallel (filled in once it is known).
    Pending,
}

impl When {
    /// The earlier of two ends.
    fn or(self, other: When) -> When {
        match (self, other) {
            (When::Pending, x) | (x, When::Pending) => x,
            (When::Never, x) | (x, When::Never) => x,
            (When::At(a), When::At(b)) => When::At(a.min(b)),
            (a, b) => {
                let mut groups = a.groups();
                groups.extend(b.groups());
                When::Dyn(Trigger {
                    condition_groups: groups,
                })
            }
        }
    }

    /// As OR-ed condition groups.
    pub(crate) fn groups(&self) -> Vec<ConditionGroup> {
        match self {
            When::At(t) => vec![ConditionGroup {
                conditions: vec![sim_time(
                    *t,
                    scenario::Rule::GreaterOrEqual,
                    scenario::SourcePos::start_of(std::sync::Arc::from(std::path::Path::new(""))),
                )],
            }],
            When::Dyn(t) => t.condition_groups.clone(),
            When::Never | When::Pending => Vec::new(),
        }
    }

    fn time(&self) -> Option<f64> {
        match self {
            When::At(t) => Some(*t),
            _ => None,
        }
    }
}

/// One phase of the plan.
#[derive(Debug, Clone)]
pub(crate) struct PhasePlan {
    /// Its path (the Act's name).
    pub path: String,
    /// Where it is written.
    pub span: Span,
    /// Start.
    pub start: When,
    /// End.
    pub end: When,
    /// What the actors do.
    pub actions: Vec<Planned>,
    /// The phase lasts until its end (all but `emit`, an instant).
    pub hold: bool,
    /// The event an `emit` phase emits.
    pub emit: Option<String>,
}

/// An action of a phase.
#[derive(Debug, Clone)]
pub(crate) struct Planned {
    /// The entity.
    pub entity: String,
    /// Absolute start time, when it does not start with the phase.
    pub at: Option<f64>,
    /// Its name.
    pub name: String,
    /// The action.
    pub action: PrivateAction,
    /// The modifier it comes from.
    pub span: Span,
}

/// A vehicle of the plan.
#[derive(Debug, Clone)]
pub(crate) struct Entity {
    /// Its name (the actor's path).
    pub name: String,
    /// The engine's model of it.
    pub vehicle: Vehicle,
    /// Planned motion.
    pub track: Track,
}

/// The whole plan.
#[derive(Debug, Clone)]
pub(crate) struct Plan {
    /// The road everything is placed on.
    pub road: String,
    /// The vehicles, in the order the `do` tree first names them.
    pub entities: Vec<Entity>,
    /// The phases, children before their composition.
    pub phases: Vec<PhasePlan>,
    /// The emissions of the scenario's `on` handlers.
    pub handlers: Vec<HandlerPlan>,
}

/// One `emit e` of an `on` handler: a repeatable 1.x Event that starts at each occurrence of
/// the handler's event, so that each emission is logged.
#[derive(Debug, Clone)]
pub(crate) struct HandlerPlan {
    /// `on.0`: the handler's index among the scenario's `on` directives.
    pub act: String,
    /// The emitted event's name.
    pub event: String,
    /// When the handler's event occurs.
    pub trigger: Trigger,
    /// The `emit` directive.
    pub span: Span,
}

/// An event's condition: (event name, condition, for an `on` handler's emit the handler's index
/// and the emit's span).
pub(crate) type EventSpec<'a> = (String, &'a Expr, Option<(usize, Span)>);

/// Where an event specification is used: what its event context starts with (ASAM
/// OpenSCENARIO DSL 2.1 §7.3.10.4).
#[derive(Debug, Clone, Copy)]
enum EventCtx<'w> {
    /// An `on` handler of the scenario: the start of the run.
    Run,
    /// The `wait` or `until` of a phase: the phase's start.
    Phase {
        path: &'w str,
        span: Span,
        start: &'w When,
        until: bool,
    },
}

/// Options of planning.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Settings {
    /// The engine's step (s).
    pub dt: f64,
    /// A phase may have no end (the run is bounded from outside).
    pub open_end: bool,
}

struct Planner<'c, 'a> {
    ctx: &'c Ctx<'a>,
    road: PlanRoad<'a>,
    settings: Settings,
    entities: Vec<Entity>,
    index: HashMap<String, usize>,
    groups: HashMap<String, Vec<String>>,
    /// The groups whose formation spreads over the lanes (common route, not single-lane).
    across: std::collections::HashSet<String>,
    first_leaf: HashMap<String, String>,
    phases: Vec<PhasePlan>,
    /// The speed each actor's last planned speed change ends at (known also when the times
    /// are not).
    last_v: HashMap<String, f64>,
    /// Event name → the paths of the phases that emit it.
    emits: HashMap<String, Vec<(String, Span)>>,
    /// Event name → the conditions that make it occur: its declared one (`event e is c`) and
    /// those of the `on c: emit e` handlers (true: a handler's, whose event context is the run).
    events: HashMap<String, Vec<(&'a Expr, bool)>>,
    /// Leaf path → its `along(…)` routes, with when each holds.
    alongs: HashMap<String, Vec<(At, Along)>>,
    /// Free one-lane route → its lane and the first actor along it.
    route_lanes: HashMap<String, (i32, String)>,
    /// `lateral(…, x)` at: all of a first phase: (actor, x, phase start, phase end if known,
    /// the modifier), checked once every phase is planned.
    beside_checks: Vec<(String, String, f64, Option<f64>, Span)>,
    /// The side drawn for each `change_lane(…)` without one (by the modifier's span).
    sides: std::cell::RefCell<HashMap<String, bool>>,
}

/// Plans `root` on `road`; `events` are the scenario's event conditions (name, condition,
/// and for an `on` handler's emit the handler's index and the emit's span).
pub(crate) fn plan<'a>(
    ctx: &Ctx<'a>,
    road: &PlanRoad<'a>,
    root: &Phase<'_>,
    events: Vec<EventSpec<'a>>,
    settings: Settings,
) -> Result<Plan, Error> {
    let mut p = Planner {
        ctx,
        road: *road,
        settings,
        entities: Vec::new(),
        index: HashMap::new(),
        groups: HashMap::new(),
        across: std::collections::HashSet::new(),
        first_leaf: HashMap::new(),
        phases: Vec::new(),
        last_v: HashMap::new(),
        emits: HashMap::new(),
        events: HashMap::new(),
        alongs: HashMap::new(),
        route_lanes: HashMap::new(),
        sides: std::cell::RefCell::new(HashMap::new()),
        beside_checks: Vec::new(),
    };
    root.walk(&mut |ph| {
        if let Kind::Emit(e) = &ph.kind {
            p.emits
                .entry(e.clone())
                .or_default()
                .push((ph.path.clone(), ph.span));
        }
    });
    let mut handlers = Vec::new();
    for (name, spec, handler) in events {
        p.events
            .entry(name.clone())
            .or_default()
            .push((spec, handler.is_some()));
        if let Some((i, span)) = handler {
            handlers.push((format!("on.{i}"), name, spec, span));
        }
    }
    // Actors, in the order the tree names them, and each one's first phase.
    let mut leaves_mods: Vec<(&Phase<'_>, Vec<Mod<'_>>)> = Vec::new();
    for leaf in root.leaves() {
        let Kind::Invoke(inv) = &leaf.kind else {
            continue;
        };
        let names = p.register(&inv.actor, inv.actor_expr.span)?;
        let mut mods = Vec::new();
        for m in &inv.modifiers {
            let m = read(ctx, m)?;
            for key in [
                "ahead_of",
                "behind",
                "same_as",
                "side_of",
                "left_of",
                "right_of",
                "faster_than",
                "slower_than",
            ] {
                if let Some(e) = m.arg(key) {
                    let path = ctx.path_of(e).ok_or_else(|| {
                        ctx.files.err(
                            K::UnknownActor,
                            e.span,
                            format!("expected a vehicle for `{key}:`, found an expression"),
                        )
                    })?;
                    p.register(&path, e.span)?;
                }
            }
            if m.kind == ModKind::Along {
                let a = route::read(ctx, &m)?;
                route::on_plan_road(ctx, road, &a)?;
                p.alongs
                    .entry(leaf.path.clone())
                    .or_default()
                    .push((m.at, a));
            }
            mods.push(m);
        }
        for n in names {
            p.first_leaf.entry(n).or_insert_with(|| leaf.path.clone());
        }
        leaves_mods.push((leaf, mods));
    }
    // Initial placement from each actor's first phase.
    let mut to_place = Vec::new();
    for e in &p.entities {
        let first = p.first_leaf.get(&e.name);
        let (mods, span, actor): (Vec<&Mod<'_>>, Span, Option<&str>) =
            match leaves_mods.iter().find(|(l, _)| Some(&l.path) == first) {
                Some((l, m)) => (
                    m.iter().filter(|m| m.at != At::End).collect(),
                    l.span,
                    match &l.kind {
                        Kind::Invoke(i) => Some(i.actor.as_str()),
                        _ => None,
                    },
                ),
                None => (Vec::new(), root.span, None),
            };
        let member_after = actor.and_then(|a| p.groups.get(a)).map(|members| {
            let i = members.iter().position(|m| *m == e.name).unwrap_or(0);
            (i > 0).then(|| members[i - 1].clone())
        });
        // A common-route group over several lanes: the members and this one's index.
        let across = actor
            .filter(|a| p.across.contains(*a))
            .and_then(|a| p.groups.get(a))
            .and_then(|members| {
                let i = members.iter().position(|m| *m == e.name)?;
                (i > 0).then(|| (members.clone(), i))
            });
        let bb = e.vehicle.bounding_box;
        // A named route of the first phase places the actor at its start.
        let route = first
            .and_then(|f| p.alongs.get(f))
            .into_iter()
            .flatten()
            .find_map(|(at, a)| match (&a.route, at) {
                (route::Route::Lane { lane, s, .. }, At::Start | At::All) => {
                    Some((*lane, s + a.start_offset))
                }
                _ => None,
            });
        to_place.push(ToPlace {
            route,
            name: e.name.clone(),
            mods,
            member_after,
            across,
            front: bb.center[0] + bb.length / 2.0,
            rear: bb.length / 2.0 - bb.center[0],
            width: bb.width,
            span,
        });
    }
    let entity = |path: &str| p.index.contains_key(path).then(|| path.to_string());
    let starts = place(ctx, road, &to_place, &entity)?;
    for e in &mut p.entities {
        let s = starts[&e.name];
        e.track = Track::new(s.s, s.v, s.lane);
        e.track.set_offset(0.0, s.offset);
        p.last_v.insert(e.name.clone(), s.v);
    }
    let mods: HashMap<String, &Vec<Mod<'_>>> = leaves_mods
        .iter()
        .map(|(l, m)| (l.path.clone(), m))
        .collect();
    // An `on` handler's event context starts with the run (the scenario's start); its event
    // is translated (so checked) even when nothing waits on what it emits.
    let mut handler_plans = Vec::new();
    for (act, event, spec, span) in handlers {
        handler_plans.push(HandlerPlan {
            act,
            event,
            trigger: p.condition(spec, 0, EventCtx::Run)?,
            span,
        });
    }
    let end = p.schedule(root, When::At(0.0), None, None, None, &mods)?;
    if end == When::Never && !settings.open_end {
        return Err(no_end(ctx, root));
    }
    for (a, x, t0, te, span) in &p.beside_checks {
        for who in [a, x] {
            if let Some(t) = p.track(who).moving_in(*t0, te.unwrap_or(f64::INFINITY)) {
                return Err(ctx.files.err(
                    K::Unsatisfiable,
                    *span,
                    format!("expected `{a}` and `{x}` to keep their lateral positions while this lateral(…) holds (at: all), found `{who}` moving sideways from {t:.2} s; write at: start"),
                ));
            }
        }
    }
    Ok(Plan {
        road: road.id().to_string(),
        entities: p.entities,
        phases: p.phases,
        handlers: handler_plans,
    })
}

fn no_end(ctx: &Ctx<'_>, p: &Phase<'_>) -> Error {
    ctx.files.err(
        K::NoEnd,
        p.span,
        format!(
            "expected a way for phase `{}` to end (a duration, an until, or a member that ends), found none; give it one or bound the run with --duration",
            p.path
        ),
    )
}

impl Planner<'_, '_> {
    /// Registers the vehicle(s) `path` names; returns the entity names.
    fn register(&mut self, path: &str, span: Span) -> Result<Vec<String>, Error> {
        let names = match actors::classify(self.ctx, path) {
            Some(ActorKind::Vehicle) => vec![path.to_string()],
            Some(ActorKind::Group(members, lanes)) => {
                self.groups.insert(path.to_string(), members.clone());
                if lanes {
                    self.across.insert(path.to_string());
                }
                members
            }
            Some(ActorKind::RandomTraffic) => {
                return Err(self.ctx.files.err(
                    K::Unsupported,
                    span,
                    format!("expected a vehicle, or a vehicle group with a formation (single-lane or common-route), found `{path}`, a random_traffic_vehicle_group (random traffic is not planned)"),
                ))
            }
            None => {
                return Err(self.ctx.files.err(
                    K::UnknownActor,
                    span,
                    format!("expected a vehicle or vehicle group of the scenario, found `{path}`"),
                ))
            }
        };
        for n in &names {
            if !self.index.contains_key(n) {
                self.index.insert(n.clone(), self.entities.len());
                self.entities.push(Entity {
                    name: n.clone(),
                    vehicle: actors::vehicle(self.ctx, n),
                    track: Track::new(0.0, 0.0, -1),
                });
            }
        }
        Ok(names)
    }

    fn track(&self, name: &str) -> &Track {
        &self.entities[self.index[name]].track
    }

    /// s of `name` at time `t`: its track's distance along its lane's centre line from its
    /// start, as s of the road (the engine moves vehicles along lane centres).
    fn s_at(&self, name: &str, t: f64) -> f64 {
        let tr = self.track(name);
        let s0 = tr.at(0.0).0;
        self.road.s_after(tr.lane(0.0), s0, tr.at(t).0 - s0)
    }

    /// The width of `name`'s bounding box (m).
    fn width(&self, name: &str) -> f64 {
        self.entities[self.index[name]].vehicle.bounding_box.width
    }

    fn track_mut(&mut self, name: &str) -> &mut Track {
        let i = self.index[name];
        &mut self.entities[i].track
    }

    /// The moment `d` s after phase `path` (written at `span`) starts at `start`.
    fn after(&self, path: &str, span: Span, start: &When, d: f64) -> When {
        match start {
            When::At(t) => When::At(t + d),
            _ => When::Dyn(Trigger {
                condition_groups: vec![ConditionGroup {
                    conditions: vec![act_state(
                        path,
                        StoryboardElementState::RunningState,
                        // The Act's stop trigger is first sampled one step after it starts.
                        (d - self.settings.dt).max(0.0),
                        self.ctx.files.pos(span),
                    )],
                }],
            }),
        }
    }

    /// A DSL condition as a trigger, used in event context `ectx`; `depth` counts nested event
    /// definitions (a declared event's context is that of the place it is used).
    fn condition(&self, e: &Expr, depth: usize, ectx: EventCtx<'_>) -> Result<Trigger, Error> {
        let index = &self.index;
        let entity = |path: &str| index.contains_key(path).then(|| path.to_string());
        let event = |name: &str| -> Option<Result<Vec<ConditionGroup>, Error>> {
            let emits = self.emits.get(name);
            let specs = self.events.get(name);
            if emits.is_none() && specs.is_none() {
                return None;
            }
            // The event occurs when a phase emits it or one of its conditions holds.
            let mut groups: Vec<ConditionGroup> = emits
                .into_iter()
                .flatten()
                .map(|(path, span)| ConditionGroup {
                    conditions: vec![act_state(
                        path,
                        StoryboardElementState::StartTransition,
                        0.0,
                        self.ctx.files.pos(*span),
                    )],
                })
                .collect();
            for (spec, handler) in specs.into_iter().flatten() {
                if depth > 16 {
                    return Some(Err(self.ctx.files.err(
                        K::Condition,
                        spec.span,
                        "expected events defined without a cycle, found one defined through itself",
                    )));
                }
                // A handler's event counts from the run's start wherever it is waited on; a
                // declared event takes the context of the place it is used.
                let ectx = if *handler { EventCtx::Run } else { ectx };
                match self.condition(spec, depth + 1, ectx) {
                    Ok(t) => groups.extend(t.condition_groups),
                    Err(e) => return Some(Err(e)),
                }
            }
            Some(Ok(groups))
        };
        let timed = |tm: Timed, span: Span| -> Result<Vec<ConditionGroup>, Error> {
            // The first moment the event occurs, after the context's start.
            let first = match tm {
                Timed::Every(ev) => ev.offset,
                Timed::Elapsed(d) => d,
            };
            match ectx {
                EventCtx::Run => Ok(vec![ConditionGroup {
                    conditions: vec![match tm {
                        Timed::Every(ev) => {
                            every_from_start(ev, self.settings.dt, self.ctx.files.pos(span))
                        }
                        // True from d on (§7.3.10.4), so a handler on it emits at every step.
                        Timed::Elapsed(d) => sim_time(
                            d,
                            scenario::Rule::GreaterOrEqual,
                            self.ctx.files.pos(span),
                        ),
                    }],
                }]),
                // Only the first occurrence can end a wait or an until.
                EventCtx::Phase { until: true, .. } if first <= 0.0 => Err(self.ctx.files.err(
                    K::Value,
                    span,
                    "expected a time above 0 s in the event of an until, found 0 s (its first occurrence is the start of the phase, which would end it at once)",
                )),
                EventCtx::Phase {
                    path,
                    span: at,
                    start,
                    ..
                } => Ok(self.after(path, at, start, first).groups()),
            }
        };
        trigger(
            self.ctx,
            e,
            &Names {
                entity: &entity,
                event: &event,
                timed: &timed,
            },
        )
    }

    /// The own end of `p` (duration, until), given its start.
    fn own_end(&self, p: &Phase<'_>, start: &When) -> Result<Option<When>, Error> {
        let mut end = None;
        if let Some(d) = p.duration {
            end = Some(self.after(&p.path, p.span, start, d));
        }
        if let Some(u) = p.until {
            let ectx = EventCtx::Phase {
                path: &p.path,
                span: p.span,
                start,
                until: !matches!(p.kind, Kind::Wait),
            };
            let w = When::Dyn(self.condition(u, 0, ectx)?);
            end = Some(match end {
                Some(e) => e.or(w),
                None => w,
            });
        }
        Ok(end)
    }

    fn schedule(
        &mut self,
        p: &Phase<'_>,
        start: When,
        inherit: Option<When>,
        cap: Option<When>,
        len_hint: Option<f64>,
        mods: &HashMap<String, &Vec<Mod<'_>>>,
    ) -> Result<When, Error> {
        let own = self.own_end(p, &start)?;
        // The latest end: an enclosing composition's own end (duration, until) stops its
        // running member too.
        let capped = |w: When| match (&cap, w) {
            // Filled in with the enclosing parallel's end, which is capped itself.
            (_, When::Pending) => When::Pending,
            (Some(c), w) => w.or(c.clone()),
            (None, w) => w,
        };
        let first_index = self.phases.len();
        let end = match &p.kind {
            Kind::Invoke(_) | Kind::Wait => {
                let mut actions = Vec::new();
                let mut derived = None;
                if let Kind::Invoke(inv) = &p.kind {
                    let cap = own.as_ref().or(inherit.as_ref()).and_then(When::time);
                    let empty = Vec::new();
                    let ms = mods.get(&p.path).copied().unwrap_or(&empty);
                    let len = p.duration.or(len_hint);
                    derived = self.plan_invoke(p, inv, ms, start.time(), cap, len, &mut actions)?;
                }
                let end = match (own, derived, inherit) {
                    (Some(o), _, i) => o.or(i.unwrap_or(When::Pending)),
                    (None, Some(d), i) => d.or(i.unwrap_or(When::Pending)),
                    (None, None, Some(i)) => i,
                    (None, None, None) if self.settings.open_end => When::Never,
                    (None, None, None) => return Err(no_end(self.ctx, p)),
                };
                let end = capped(end);
                self.phases.push(PhasePlan {
                    path: p.path.clone(),
                    span: p.span,
                    start,
                    end: end.clone(),
                    actions,
                    hold: true,
                    emit: None,
                });
                return Ok(end);
            }
            Kind::Emit(event) => {
                // An instant: its Act starts and, with nothing to do, completes in its step.
                self.phases.push(PhasePlan {
                    path: p.path.clone(),
                    span: p.span,
                    start: start.clone(),
                    end: When::Never,
                    actions: Vec::new(),
                    hold: false,
                    emit: Some(event.clone()),
                });
                return Ok(start);
            }
            Kind::Serial | Kind::OneOf(_) => {
                let mut cur = start.clone();
                let n = p.children.len();
                let own_cap = match (&own, &cap) {
                    (Some(o), Some(c)) => Some(o.clone().or(c.clone())),
                    (o, c) => o.clone().or(c.clone()),
                };
                for (i, c) in p.children.iter().enumerate() {
                    // Members that would start when the serial has ended never run.
                    if let (When::At(t), Some(When::At(end))) = (&cur, &own_cap) {
                        if i > 0 && *t >= *end {
                            break;
                        }
                    }
                    let inh = if i + 1 == n {
                        match (&own, &inherit) {
                            (Some(o), Some(i)) => Some(o.clone().or(i.clone())),
                            (Some(o), None) => Some(o.clone()),
                            (None, i) => i.clone(),
                        }
                    } else {
                        None
                    };
                    let hint = match p.kind {
                        Kind::OneOf(_) => p.duration.or(len_hint),
                        _ => None,
                    };
                    cur = self.schedule(c, cur.clone(), inh, own_cap.clone(), hint, mods)?;
                    // After a run-time end, the next member starts on the state of the one that
                    // ended (and only while this serial runs, which its own end may stop).
                    let mut ended = vec![act_state(
                        &c.path,
                        StoryboardElementState::CompleteState,
                        0.0,
                        self.ctx.files.pos(c.span),
                    )];
                    if i + 1 < n {
                        if matches!(own_cap, Some(When::Dyn(_))) {
                            ended.push(act_state(
                                &p.path,
                                StoryboardElementState::RunningState,
                                0.0,
                                self.ctx.files.pos(p.span),
                            ));
                        }
                        cur = match cur {
                            When::At(t) => When::At(t),
                            When::Dyn(_) => When::Dyn(Trigger {
                                condition_groups: vec![ConditionGroup { conditions: ended }],
                            }),
                            When::Never | When::Pending => return Err(no_end(self.ctx, c)),
                        };
                    } else if matches!(cur, When::Dyn(_)) {
                        // Ends with its last member: on that member's state (its condition
                        // could hold before the member runs).
                        ended.truncate(1);
                        cur = When::Dyn(Trigger {
                            condition_groups: vec![ConditionGroup { conditions: ended }],
                        });
                    }
                }
                capped(match own {
                    Some(o) => o,
                    None => cur,
                })
            }
            Kind::Parallel => {
                // Members planned (and written) first: those whose motion others refer to, and
                // those that end on their own, so that members ending with the parallel see
                // their end in the same step.
                let mut order: Vec<&Phase<'_>> = p.children.iter().collect();
                order.sort_by_key(|c| {
                    (
                        relative_end(c, mods),
                        c.duration.is_none() && c.until.is_none(),
                    )
                });
                let inh = match (&own, &inherit) {
                    (Some(o), Some(i)) => Some(o.clone().or(i.clone())),
                    (Some(o), None) => Some(o.clone()),
                    (None, _) => Some(When::Pending),
                };
                let own_cap = match (&own, &cap) {
                    (Some(o), Some(c)) => Some(o.clone().or(c.clone())),
                    (o, c) => o.clone().or(c.clone()),
                };
                let mut ends = Vec::new();
                for c in order {
                    let e = self.schedule(
                        c,
                        start.clone(),
                        inh.clone(),
                        own_cap.clone(),
                        p.duration.or(len_hint),
                        mods,
                    )?;
                    ends.push((c, e));
                }
                capped(match own {
                    Some(o) => o,
                    None => {
                        let with_end: Vec<&(&Phase<'_>, When)> =
                            ends.iter().filter(|(_, e)| *e != When::Pending).collect();
                        if with_end.iter().any(|(_, e)| *e == When::Never) {
                            When::Never
                        } else if with_end.is_empty() {
                            match inherit {
                                Some(i) => i,
                                None if self.settings.open_end => When::Never,
                                None => return Err(no_end(self.ctx, p)),
                            }
                        } else if with_end.iter().all(|(_, e)| matches!(e, When::At(_))) {
                            When::At(
                                with_end
                                    .iter()
                                    .filter_map(|(_, e)| e.time())
                                    .fold(f64::NEG_INFINITY, f64::max),
                            )
                        } else {
                            When::Dyn(Trigger {
                                condition_groups: vec![ConditionGroup {
                                    conditions: with_end
                                        .iter()
                                        .map(|(c, _)| {
                                            act_state(
                                                &c.path,
                                                StoryboardElementState::CompleteState,
                                                0.0,
                                                self.ctx.files.pos(c.span),
                                            )
                                        })
                                        .collect(),
                                }],
                            })
                        }
                    }
                })
            }
        };
        // Members that end with this composition.
        if end != When::Pending {
            for ph in &mut self.phases[first_index..] {
                if ph.end == When::Pending {
                    ph.end = end.clone();
                }
            }
        }
        self.phases.push(PhasePlan {
            path: p.path.clone(),
            span: p.span,
            start,
            end: end.clone(),
            actions: Vec::new(),
            hold: true,
            emit: None,
        });
        Ok(end)
    }
}

/// 1 for an invocation with a `position(…, at: end)` relative to another actor, else 0: the
/// order in which a parallel plans its members.
fn relative_end(p: &Phase<'_>, mods: &HashMap<String, &Vec<Mod<'_>>>) -> u8 {
    mods.get(&p.path).is_some_and(|ms| {
        ms.iter()
            .any(|m| m.kind == ModKind::Position && m.at == At::End)
    }) as u8
}
