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
//! This module holds the plan's types and walks the scenario's phases; `schedule` schedules one
//! phase and its members, `events` turns conditions and events into triggers, `invoke` plans
//! one invocation's actions, `motion` holds the speed profiles, modifier values, lane targets
//! and limits they use.

use std::collections::HashMap;

use dsl::semantics::hir::{Expr, Span};
use scenario::{ConditionGroup, PrivateAction, StoryboardElementState, Trigger, Vehicle};

use crate::actors::{self, ActorKind};
use crate::condition::{act_state, sim_time};
use crate::error::{Error, ErrorKind as K};
use crate::modifier::{read, At, Mod, ModKind};
use crate::phase::{Kind, Phase};
use crate::place::{place, ToPlace};
use crate::road::PlanRoad;
use crate::route::{self, Along};
use crate::track::Track;
use crate::value::Ctx;

mod events;
mod invoke;
mod motion;
mod schedule;

use events::EventCtx;

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
}
