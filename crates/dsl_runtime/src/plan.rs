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

use std::collections::HashMap;

use dsl::semantics::hir::{Expr, Span};
use scenario::{
    ConditionGroup, DynamicsDimension, DynamicsShape, LaneChangeTarget, LateralAction,
    LongitudinalAction, PrivateAction, SpeedTarget, SpeedTargetValueType, StoryboardElementState,
    TransitionDynamics, Trigger, Vehicle,
};

use crate::actors::{self, ActorKind, MAX_ACCELERATION, MAX_SPEED};
use crate::condition::{act_state, sim_time, trigger, Names};
use crate::error::{Error, ErrorKind as K};
use crate::modifier::{read, At, Mod, ModKind};
use crate::phase::{Invoke, Kind, Phase};
use crate::place::{place, ToPlace};
use crate::road::PlanRoad;
use crate::route::{self, Along, OnRoute};
use crate::track::Track;
use crate::value::{Ctx, Val};

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
    /// those of the `on c: emit e` handlers.
    events: HashMap<String, Vec<&'a Expr>>,
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
/// whether an `on` handler gives it).
pub(crate) fn plan<'a>(
    ctx: &Ctx<'a>,
    road: &PlanRoad<'a>,
    root: &Phase<'_>,
    events: Vec<(String, &'a Expr, bool)>,
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
        p.events.entry(name).or_default().push(spec);
        if handler {
            handlers.push(spec);
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
    // An `on` handler's event is checked even when nothing waits on what it emits.
    for spec in handlers {
        p.condition(spec, 0)?;
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

    /// A DSL condition as a trigger; `depth` counts nested event definitions.
    fn condition(&self, e: &Expr, depth: usize) -> Result<Trigger, Error> {
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
            for spec in specs.into_iter().flatten() {
                if depth > 16 {
                    return Some(Err(self.ctx.files.err(
                        K::Condition,
                        spec.span,
                        "expected events defined without a cycle, found one defined through itself",
                    )));
                }
                match self.condition(spec, depth + 1) {
                    Ok(t) => groups.extend(t.condition_groups),
                    Err(e) => return Some(Err(e)),
                }
            }
            Some(Ok(groups))
        };
        trigger(
            self.ctx,
            e,
            &Names {
                entity: &entity,
                event: &event,
            },
        )
    }

    /// The own end of `p` (duration, until), given its start.
    fn own_end(&self, p: &Phase<'_>, start: &When) -> Result<Option<When>, Error> {
        let mut end = None;
        if let Some(d) = p.duration {
            end = Some(match start {
                When::At(t) => When::At(t + d),
                _ => When::Dyn(Trigger {
                    condition_groups: vec![ConditionGroup {
                        conditions: vec![act_state(
                            &p.path,
                            StoryboardElementState::RunningState,
                            // The Act's stop trigger is first sampled one step after it starts.
                            (d - self.settings.dt).max(0.0),
                            self.ctx.files.pos(p.span),
                        )],
                    }],
                }),
            });
        }
        if let Some(u) = p.until {
            let w = When::Dyn(self.condition(u, 0)?);
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
                });
                return Ok(end);
            }
            Kind::Emit(_) => {
                // An instant: its Act starts and, with nothing to do, completes in its step.
                self.phases.push(PhasePlan {
                    path: p.path.clone(),
                    span: p.span,
                    start: start.clone(),
                    end: When::Never,
                    actions: Vec::new(),
                    hold: false,
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
        });
        Ok(end)
    }

    /// Plans one invocation: its actions, and the time its `position(…, at: end)` is met when
    /// nothing else ends it.
    #[allow(clippy::too_many_arguments)]
    fn plan_invoke(
        &mut self,
        p: &Phase<'_>,
        inv: &Invoke<'_>,
        mods: &[Mod<'_>],
        t0: Option<f64>,
        end: Option<f64>,
        len: Option<f64>,
        out: &mut Vec<Planned>,
    ) -> Result<Option<When>, Error> {
        let ctx = self.ctx;
        if inv.action != "drive" {
            return Err(ctx.files.err(
                K::Unsupported,
                p.span,
                format!(
                    "expected drive() (the movement action the runtime plans), found `{}`",
                    inv.action
                ),
            ));
        }
        let targets: Vec<String> = match self.groups.get(&inv.actor) {
            Some(m) => m.clone(),
            None => vec![inv.actor.clone()],
        };
        let mut derived = None;
        for target in &targets {
            let first = self.first_leaf.get(target) == Some(&p.path);
            let mut n = 0;
            let mut name = |what: &str| {
                n += 1;
                format!("{}/{target}/{n}:{what}", p.path)
            };
            // A step of speed at the phase start (`speed(v)` after the first phase).
            let step = match (t0, first) {
                (Some(t), false) => match mods
                    .iter()
                    .find(|m| m.kind == ModKind::Speed && m.at != At::End)
                {
                    Some(m) => Some((m, self.track(target).at(t).1, self.speed_value(m, t0)?.0)),
                    None => None,
                },
                _ => None,
            };
            crate::modifier::check_keeps(ctx, mods, step)?;
            crate::modifier::check_orientation(ctx, mods)?;
            // Speed first, position at end last: it builds on the phase's speed.
            let mut ordered: Vec<&Mod<'_>> = mods.iter().collect();
            ordered.sort_by_key(|m| {
                ((m.kind == ModKind::Position && m.at == At::End) || m.kind == ModKind::Distance)
                    as u8
            });
            for m in ordered {
                let need_t = |what: &str| -> Result<f64, Error> {
                    t0.ok_or_else(|| {
                        ctx.files.err(
                            K::Unsatisfiable,
                            m.app.span,
                            format!("expected a phase start the plan knows for {what}, found one after a run-time condition"),
                        )
                    })
                };
                // The phase's start (when the plan knows it) and duration.
                let need_len = |what: &str| -> Result<(Option<f64>, f64), Error> {
                    match (t0, end, len) {
                        (Some(a), Some(b), _) if b > a => Ok((Some(a), b - a)),
                        (_, _, Some(l)) if l > 0.0 => Ok((t0, l)),
                        _ => Err(ctx.files.err(
                            K::Unsatisfiable,
                            m.app.span,
                            format!("expected a phase duration the plan knows for {what}, found none (give the phase a duration)"),
                        )),
                    }
                };
                match (m.kind, m.at) {
                    // Checked against the planned motion (see check_keeps, route::check).
                    (
                        ModKind::Along
                        | ModKind::Orientation
                        | ModKind::KeepLane
                        | ModKind::KeepSpeed
                        | ModKind::PhysicalMovement
                        | ModKind::AvoidCollisions,
                        _,
                    ) => {}
                    (ModKind::Speed, At::Start | At::All) => {
                        let (v, relative) = self.speed_value(m, t0)?;
                        if first {
                            continue;
                        }
                        let target_speed = match relative {
                            Some((x, delta)) => SpeedTarget::Relative {
                                entity_ref: x,
                                value: delta,
                                speed_target_value_type: SpeedTargetValueType::Delta,
                                continuous: m.at == At::All,
                            },
                            None => SpeedTarget::Absolute(v),
                        };
                        out.push(Planned {
                            entity: target.clone(),
                            at: None,
                            name: name("speed"),
                            action: speed_action(DynamicsShape::Step, 0.0, target_speed),
                            span: m.app.span,
                        });
                        if let Some(t) = t0 {
                            self.track_mut(target).ramp(t, t, v);
                        }
                        self.last_v.insert(target.clone(), v);
                    }
                    (ModKind::Speed, At::End) | (ModKind::ChangeSpeed, _) => {
                        let (t, len) = need_len("a speed at the phase end")?;
                        let (v1, _) = self.speed_value(m, t.map(|t| t + len))?;
                        let v0 = t.map_or(self.last_v[target], |t| self.track(target).at(t).1);
                        check_speed(ctx, m, v1)?;
                        // With acceleration(a): the change at that rate, done within the phase.
                        let rate = match mods.iter().find(|q| q.kind == ModKind::Acceleration) {
                            Some(q) => Some((q, self.acceleration_value(q)?.abs())),
                            None => None,
                        };
                        let (action, ramp) = match rate {
                            Some((q, a)) => {
                                check_accel(ctx, q, a)?;
                                let needed = (v1 - v0).abs() / a;
                                if needed > len + 1e-9 {
                                    return Err(ctx.files.err(
                                        K::Unsatisfiable,
                                        q.app.span,
                                        format!("expected the speed change from {v0:.2} m/s to {v1:.2} m/s at {a} m/s² within the phase's {len} s, found it needs {needed:.2} s"),
                                    ));
                                }
                                let dynamics = TransitionDynamics {
                                    dynamics_shape: DynamicsShape::Linear,
                                    dynamics_dimension: DynamicsDimension::Rate,
                                    value: a,
                                    following_mode: None,
                                };
                                (
                                    PrivateAction::Longitudinal(LongitudinalAction::Speed {
                                        dynamics,
                                        target: SpeedTarget::Absolute(v1),
                                    }),
                                    needed,
                                )
                            }
                            None => {
                                check_accel(ctx, m, (v1 - v0) / len)?;
                                (
                                    speed_action(
                                        DynamicsShape::Linear,
                                        len,
                                        SpeedTarget::Absolute(v1),
                                    ),
                                    len,
                                )
                            }
                        };
                        out.push(Planned {
                            entity: target.clone(),
                            at: None,
                            name: name("speed"),
                            action,
                            span: m.app.span,
                        });
                        if let Some(t) = t {
                            self.track_mut(target).ramp(t, t + ramp, v1);
                        }
                        self.last_v.insert(target.clone(), v1);
                    }
                    (ModKind::Acceleration, _) => {
                        // Alone: a constant acceleration over the phase.
                        let paired = mods.iter().any(|q| {
                            q.kind == ModKind::ChangeSpeed
                                || (q.kind == ModKind::Speed && q.at == At::End)
                        });
                        if paired {
                            continue;
                        }
                        let (t, len) = need_len("acceleration(…)")?;
                        let a = self.acceleration_value(m)?;
                        check_accel(ctx, m, a)?;
                        let v0 = t.map_or(self.last_v[target], |t| self.track(target).at(t).1);
                        let v1 = v0 + a * len;
                        check_speed(ctx, m, v1)?;
                        out.push(Planned {
                            entity: target.clone(),
                            at: None,
                            name: name("acceleration"),
                            action: speed_action(
                                DynamicsShape::Linear,
                                len,
                                SpeedTarget::Absolute(v1),
                            ),
                            span: m.app.span,
                        });
                        if let Some(t) = t {
                            self.track_mut(target).ramp(t, t + len, v1);
                        }
                        self.last_v.insert(target.clone(), v1);
                    }
                    (ModKind::Position, At::Start | At::All)
                    | (ModKind::Lane, At::Start | At::All) => {
                        if first {
                            continue;
                        }
                        let t = need_t("a constraint at the phase start")?;
                        self.check_start(m, target, t)?;
                    }
                    (ModKind::Position, At::End) => {
                        let t = need_t("position(…, at: end)")?;
                        let (x, sign, d) = self.position_target(m, t)?;
                        let (ve_given, hold) = (end_speed_mod(mods), holds_speed(mods));
                        let v0 = self.track(target).at(t).1;
                        let s_a = self.s_at(target, t);
                        let lane_a = self.track(target).lane(t);
                        match end {
                            None => {
                                // Constant speeds: when does the gap reach its value?
                                let (s_x, v_x) =
                                    x.as_ref().map_or((0.0, 0.0), |x| self.track(x).at(t));
                                let gap = s_x + sign * d - s_a;
                                let closing = v0 - v_x;
                                let tau = gap / closing;
                                if !(tau.is_finite() && tau > 0.0) {
                                    return Err(ctx.files.err(
                                        K::Unsatisfiable,
                                        m.app.span,
                                        format!("expected the actors to close the {gap:.2} m to this position at their speeds ({v0:.2} m/s and {v_x:.2} m/s), found they never do"),
                                    ));
                                }
                                // The phase ends when the engine measures the gap reached
                                // (the same step an XML trigger on it would fire).
                                let w = self.gap_reached(m, target, x.as_deref(), sign, d)?;
                                derived = Some(match derived {
                                    None => w,
                                    Some(When::Dyn(mut a)) => {
                                        // Both gaps reached: one group with every condition.
                                        if let (Some(ga), When::Dyn(b)) =
                                            (a.condition_groups.first_mut(), &w)
                                        {
                                            ga.conditions.extend(
                                                b.condition_groups
                                                    .iter()
                                                    .flat_map(|g| g.conditions.clone()),
                                            );
                                        }
                                        When::Dyn(a)
                                    }
                                    Some(other) => other,
                                });
                            }
                            Some(te) => {
                                let len = te - t;
                                let s_x = x.as_ref().map_or(0.0, |x| self.s_at(x, te));
                                let want = s_x + sign * d;
                                // The distance to cover along the actor's lane.
                                let ds = self.road.lane_distance(lane_a, s_a, want);
                                if hold && ve_given.is_none() {
                                    let got = self.road.s_after(lane_a, s_a, v0 * len);
                                    if (got - want).abs() > POSITION_TOLERANCE {
                                        return Err(ctx.files.err(
                                            K::Unsatisfiable,
                                            m.app.span,
                                            format!("expected position(…, at: end) met at the constant speed {v0:.2} m/s, found it {:.2} m off at the phase end", got - want),
                                        ));
                                    }
                                    continue;
                                }
                                let ve = self.end_speed(ve_given, te, v0)?;
                                let names = (name("position.1"), name("position.2"));
                                self.two_halves(m, target, (t, len), (v0, ds, ve), names, out)?;
                            }
                        }
                    }
                    (ModKind::Distance, at) => {
                        if at == At::Start {
                            return Err(ctx.files.err(
                                K::Modifier,
                                m.app.span,
                                "expected distance(…) over the phase (at: all or end), found at: start",
                            ));
                        }
                        let t = need_t("distance(…)")?;
                        let d =
                            match m.arg("distance").map(|e| ctx.number(e)).transpose()? {
                                Some(d) if d >= 0.0 => d,
                                _ => return Err(ctx.files.err(
                                    K::Value,
                                    m.app.span,
                                    "expected a distance of 0 m or more in distance(…), found none",
                                )),
                            };
                        let v0 = self.track(target).at(t).1;
                        let (ve_given, hold) = (end_speed_mod(mods), holds_speed(mods));
                        if let Some(q) = mods.iter().find(|q| q.kind == ModKind::Acceleration) {
                            return Err(ctx.files.err(
                                K::Unsatisfiable,
                                q.app.span,
                                format!("expected the speed profile of distance(…) at {} planned by the runtime, found acceleration(…) beside it", ctx.files.at(m.app.span)),
                            ));
                        }
                        match end.filter(|te| *te > t) {
                            Some(te) => {
                                let len = te - t;
                                if hold && ve_given.is_none() {
                                    if (v0 * len - d).abs() > POSITION_TOLERANCE {
                                        return Err(ctx.files.err(
                                            K::Unsatisfiable,
                                            m.app.span,
                                            format!("expected distance({d} m) at the constant speed {v0:.2} m/s over {len} s, found {:.2} m", v0 * len),
                                        ));
                                    }
                                    continue;
                                }
                                let ve = self.end_speed(ve_given, te, v0)?;
                                let names = (name("distance.1"), name("distance.2"));
                                self.two_halves(m, target, (t, len), (v0, d, ve), names, out)?;
                            }
                            None => {
                                // No duration: the phase ends when d is travelled at the speed
                                // it starts with.
                                if let Some(q) = ve_given {
                                    return Err(ctx.files.err(
                                        K::Unsatisfiable,
                                        q.app.span,
                                        format!("expected a phase duration for a speed change beside distance(…) at {}, found none", ctx.files.at(m.app.span)),
                                    ));
                                }
                                if v0 <= 0.0 && d > 0.0 {
                                    return Err(ctx.files.err(
                                        K::Unsatisfiable,
                                        m.app.span,
                                        format!("expected `{target}` to move to travel {d} m, found it standing"),
                                    ));
                                }
                                let te = When::At(t + if d > 0.0 { d / v0 } else { 0.0 });
                                derived = Some(match derived {
                                    None => te,
                                    Some(w) => w.or(te),
                                });
                            }
                        }
                    }
                    (ModKind::Lane, At::End) | (ModKind::ChangeLane, _) => {
                        let (t, len) = need_len("a lane change")?;
                        let (target_lane, planned) =
                            self.lane_target(m, target, t.unwrap_or(0.0), len)?;
                        // lateral(…, at: end): the offset in the target lane.
                        let offset = match (lateral_end(mods), planned) {
                            (Some(q), Some(l)) => {
                                let s_end = t.map_or(0.0, |t| self.s_at(target, t + len));
                                let w = self.width(target);
                                Some(crate::lateral::lane_offset(
                                    ctx,
                                    q,
                                    self.road.lane_width(l, s_end),
                                    w,
                                )?)
                            }
                            (Some(q), None) => {
                                return Err(ctx.files.err(
                                    K::Unsatisfiable,
                                    q.app.span,
                                    "expected a target lane the plan knows for lateral(…, at: end) with a lane change, found none",
                                ))
                            }
                            (None, _) => None,
                        };
                        out.push(Planned {
                            entity: target.clone(),
                            at: None,
                            name: name("lane"),
                            action: PrivateAction::Lateral(LateralAction::LaneChange {
                                target_lane_offset: offset,
                                dynamics: TransitionDynamics {
                                    dynamics_shape: DynamicsShape::Sinusoidal,
                                    dynamics_dimension: DynamicsDimension::Time,
                                    value: len,
                                    following_mode: None,
                                },
                                target: target_lane,
                            }),
                            span: m.app.span,
                        });
                        if let (Some(l), Some(t)) = (planned, t) {
                            let tr = self.track_mut(target);
                            tr.set_lane(t + len, l);
                            tr.set_offset(t + len, offset.unwrap_or(0.0));
                            tr.add_move(t, t + len);
                        }
                    }
                    (ModKind::Lateral, At::Start | At::All) => {
                        if m.at == At::All {
                            if let Some(c) = lane_change(mods) {
                                return Err(ctx.files.err(
                                    K::Unsatisfiable,
                                    c.app.span,
                                    format!("expected no lane change while lateral(…) at {} holds throughout the phase, found `{}(…)`", ctx.files.at(m.app.span), c.app.name.text),
                                ));
                            }
                        }
                        if first {
                            // Placed; beside another actor and throughout, both must keep
                            // their lateral positions (checked once everything is planned).
                            if m.at == At::All {
                                if let Some((e, _)) = crate::lateral::reference(ctx, m)? {
                                    let x = self.entity_of(e)?;
                                    self.beside_checks.push((
                                        target.clone(),
                                        x,
                                        t0.unwrap_or(0.0),
                                        end.or(len.and_then(|l| t0.map(|t| t + l))),
                                        m.app.span,
                                    ));
                                }
                            }
                            continue;
                        }
                        let t = need_t("a lateral position at the phase start")?;
                        let tr = self.track(target);
                        let lane = tr.lane(t);
                        let w = self.road.lane_width(lane, self.s_at(target, t));
                        let want = crate::lateral::lane_offset(ctx, m, w, self.width(target))?;
                        let got = tr.offset(t);
                        if (got - want).abs() > LATERAL_TOLERANCE {
                            return Err(ctx.files.err(
                                K::Unsatisfiable,
                                m.app.span,
                                format!("expected this lateral position at the phase start, found `{target}` {:.2} m from it (plan an earlier phase to reach it, with lateral(…, at: end))", got - want),
                            ));
                        }
                    }
                    (ModKind::Lateral, At::End) => {
                        if lane_change(mods).is_some() {
                            // Planned with the lane change.
                            continue;
                        }
                        let (t, len) = need_len("a lateral position at the phase end")?;
                        let t = t.ok_or_else(|| ctx.files.err(
                            K::Unsatisfiable,
                            m.app.span,
                            "expected a phase start the plan knows for lateral(…, at: end), found one after a run-time condition",
                        ))?;
                        let tr = self.track(target);
                        let lane = tr.lane(t);
                        let o0 = tr.offset(t);
                        let w = self.road.lane_width(lane, self.s_at(target, t + len));
                        let o1 = crate::lateral::lane_offset(ctx, m, w, self.width(target))?;
                        // A sinusoidal change of Δ has its peak lateral acceleration
                        // π²Δ/(2T²): given as the action's maximum, the engine's change lasts T.
                        let a = std::f64::consts::PI.powi(2) * (o1 - o0).abs() / (2.0 * len * len);
                        check_accel(ctx, m, a)?;
                        if a > 0.0 {
                            out.push(Planned {
                                entity: target.clone(),
                                at: None,
                                name: name("lateral"),
                                action: PrivateAction::Lateral(LateralAction::LaneOffset {
                                    continuous: false,
                                    dynamics_shape: DynamicsShape::Sinusoidal,
                                    max_lateral_acc: Some(a),
                                    target: scenario::LaneOffsetTarget::Absolute(o1),
                                }),
                                span: m.app.span,
                            });
                        }
                        let tr = self.track_mut(target);
                        tr.set_offset(t + len, o1);
                        if a > 0.0 {
                            tr.add_move(t, t + len);
                        }
                    }
                }
            }
            // The routes, against the motion just planned.
            let te = match (t0, end, len) {
                (Some(a), Some(b), _) if b > a => Some(b),
                (Some(a), _, Some(l)) => Some(a + l),
                _ => None,
            };
            let alongs = self.alongs.get(&p.path).cloned().unwrap_or_default();
            let mut shared = std::mem::take(&mut self.route_lanes);
            let track = self.track(target).clone();
            let lane = |t: f64| track.lane(t);
            let s = |t: f64| self.s_at(target, t);
            let on = OnRoute {
                actor: target,
                t0,
                te,
                lane: &lane,
                s: &s,
            };
            let checked = alongs.iter().try_for_each(|(at, a)| {
                route::check(ctx, &self.road, a, *at, mods, &on, &mut shared)
            });
            self.route_lanes = shared;
            checked?;
        }
        Ok(derived)
    }

    /// The speed at `te` an end-speed modifier asks for, else `v0`.
    fn end_speed(&self, q: Option<&Mod<'_>>, te: f64, v0: f64) -> Result<f64, Error> {
        Ok(match q {
            Some(q) => self.speed_value(q, Some(te))?.0,
            None => v0,
        })
    }

    /// Plans a speed profile of two linear halves over [t, t + len] that covers `ds` (m along
    /// the lane) from speed `v0` to `ve`: v0 → vm over len/2 and vm → ve over len/2, with vm =
    /// (4·ds/len − v0 − ve)/2, within the limits (and monotonous when `m` asks). It replaces
    /// a speed change the phase planned already.
    fn two_halves(
        &mut self,
        m: &Mod<'_>,
        target: &str,
        (t, len): (f64, f64),
        (v0, ds, ve): (f64, f64, f64),
        names: (String, String),
        out: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        let ctx = self.ctx;
        self.last_v.insert(target.to_string(), ve);
        let vm = (4.0 * ds / len - v0 - ve) / 2.0;
        // movement_mode: monotonous: the speed only rises or only falls.
        if m.monotonous && (vm - v0) * (ve - vm) < -1e-9 {
            return Err(ctx.files.err(
                K::Unsatisfiable,
                m.app.span,
                format!("expected a monotonous speed profile (movement_mode: monotonous) from {v0:.2} m/s to {ve:.2} m/s, found it needs {vm:.2} m/s half way"),
            ));
        }
        check_speed(ctx, m, vm)?;
        check_accel(ctx, m, (vm - v0) / (len / 2.0))?;
        check_accel(ctx, m, (ve - vm) / (len / 2.0))?;
        // Drop a speed ramp this phase planned already (change_speed).
        out.retain(|a| !(a.entity == target && a.name.ends_with(":speed")));
        out.push(Planned {
            entity: target.to_string(),
            at: None,
            name: names.0,
            action: speed_action(DynamicsShape::Linear, len / 2.0, SpeedTarget::Absolute(vm)),
            span: m.app.span,
        });
        out.push(Planned {
            entity: target.to_string(),
            at: Some(t + len / 2.0),
            name: names.1,
            action: speed_action(DynamicsShape::Linear, len / 2.0, SpeedTarget::Absolute(ve)),
            span: m.app.span,
        });
        let tr = self.track_mut(target);
        tr.ramp(t, t + len / 2.0, vm);
        tr.ramp(t + len / 2.0, t + len, ve);
        Ok(())
    }

    /// The moment the gap of a `position(d, ahead_of|behind: x)` is reached, as the engine
    /// measures it: a RelativeDistanceCondition (longitudinal, road coordinates, reference
    /// points) of the actor in front over the one behind rising through d. Without a reference: s ≥ d is
    /// not measured by a 1.x condition, so it is an error.
    fn gap_reached(
        &self,
        m: &Mod<'_>,
        target: &str,
        x: Option<&str>,
        sign: f64,
        d: f64,
    ) -> Result<When, Error> {
        let Some(x) = x else {
            return Err(self.ctx.files.err(
                K::Unsatisfiable,
                m.app.span,
                "expected a duration for position(d, at: end) without a reference, found none",
            ));
        };
        let (front, back) = if sign > 0.0 { (target, x) } else { (x, target) };
        Ok(When::Dyn(Trigger {
            condition_groups: vec![ConditionGroup {
                conditions: vec![scenario::Condition {
                    name: format!("{front} {d} m ahead of {back}"),
                    // The engine's longitudinal distance has no sign: the gap is reached when
                    // it grows through d (an actor behind first closes, passes, then opens it).
                    condition_edge: scenario::ConditionEdge::Rising,
                    delay: 0.0,
                    kind: scenario::ConditionKind::ByEntity {
                        triggering_entities: scenario::TriggeringEntities {
                            rule: scenario::TriggeringEntitiesRule::Any,
                            entity_refs: vec![front.to_string()],
                        },
                        entity_condition: scenario::EntityCondition::RelativeDistance {
                            entity_ref: back.to_string(),
                            value: d,
                            rule: scenario::Rule::GreaterOrEqual,
                            measure: scenario::DistanceMeasure {
                                freespace: false,
                                coordinate_system: Some(scenario::CoordinateSystem::Road),
                                relative_distance_type: Some(
                                    scenario::RelativeDistanceType::Longitudinal,
                                ),
                                routing_algorithm: None,
                            },
                        },
                    },
                    pos: self.ctx.files.pos(m.app.span),
                }],
            }],
        }))
    }

    /// The speed a speed-like modifier asks for at time `t`, and its relative form.
    fn speed_value(
        &self,
        m: &Mod<'_>,
        t: Option<f64>,
    ) -> Result<(f64, Option<(String, f64)>), Error> {
        let own = m.arg("speed").map(|e| self.ctx.number(e)).transpose()?;
        for (key, sign) in [
            ("faster_than", 1.0),
            ("slower_than", -1.0),
            ("same_as", 0.0),
        ] {
            if let Some(e) = m.arg(key) {
                let x = self.entity_of(e)?;
                let delta = sign * own.unwrap_or(0.0);
                let vx = t.map_or(0.0, |t| self.track(&x).at(t).1);
                return Ok((vx + delta, Some((x, delta))));
            }
        }
        match own {
            Some(v) => Ok((v, None)),
            None => Err(self.ctx.files.err(
                K::Modifier,
                m.app.span,
                "expected a speed (or faster_than/slower_than/same_as) in this modifier, found none",
            )),
        }
    }

    /// The acceleration of an `acceleration(a)` modifier (m/s²).
    fn acceleration_value(&self, m: &Mod<'_>) -> Result<f64, Error> {
        match m.arg("acceleration") {
            Some(e) => self.ctx.number(e),
            None => Err(self.ctx.files.err(
                K::Modifier,
                m.app.span,
                "expected an acceleration in acceleration(…), found none (relative forms are not planned yet)",
            )),
        }
    }

    fn entity_of(&self, e: &Expr) -> Result<String, Error> {
        self.ctx
            .path_of(e)
            .filter(|p| self.index.contains_key(p))
            .ok_or_else(|| {
                self.ctx.files.err(
                    K::UnknownActor,
                    e.span,
                    "expected a vehicle of the scenario, found another value",
                )
            })
    }

    /// (reference entity, +1 ahead / −1 behind, distance) of a position modifier.
    fn position_target(&self, m: &Mod<'_>, t: f64) -> Result<(Option<String>, f64, f64), Error> {
        let (x, sign) = match (m.arg("ahead_of"), m.arg("behind")) {
            (Some(e), _) => (Some(self.entity_of(e)?), 1.0),
            (None, Some(e)) => (Some(self.entity_of(e)?), -1.0),
            (None, None) => (None, 1.0),
        };
        let d =
            match (m.arg("distance"), m.arg("time"), &x) {
                (Some(e), _, _) => self.ctx.number(e)?,
                (None, Some(e), Some(x)) => self.ctx.number(e)? * self.track(x).at(t).1,
                _ => return Err(self.ctx.files.err(
                    K::Unsatisfiable,
                    m.app.span,
                    "expected a distance (or a time and a reference) in position(…), found neither",
                )),
            };
        Ok((x, sign, d))
    }

    /// Checks a constraint at the start of a phase that is not the actor's first.
    fn check_start(&self, m: &Mod<'_>, target: &str, t: f64) -> Result<(), Error> {
        if m.kind == ModKind::Position {
            let (x, sign, d) = self.position_target(m, t)?;
            let want = x.as_ref().map_or(0.0, |x| self.s_at(x, t)) + sign * d;
            let got = self.s_at(target, t);
            if (got - want).abs() > POSITION_TOLERANCE {
                return Err(self.ctx.files.err(
                    K::Unsatisfiable,
                    m.app.span,
                    format!("expected this position at the phase start, found `{target}` {:.2} m from it (plan an earlier phase to reach it)", got - want),
                ));
            }
        }
        Ok(())
    }

    /// The LaneChangeAction target of a lane modifier at the phase end, and the lane the plan
    /// expects there.
    fn lane_target(
        &self,
        m: &Mod<'_>,
        target: &str,
        t: f64,
        len: f64,
    ) -> Result<(LaneChangeTarget, Option<i32>), Error> {
        let n = m
            .arg("lane")
            .map(|e| self.ctx.number(e))
            .transpose()?
            .map_or(1, |x| x.round() as i32);
        let side = m.arg("side").map(|e| self.ctx.eval(e)).transpose()?;
        let left = !matches!(&side, Some(Val::Enum(s)) if s == "right");
        let shift = if left { n } else { -n };
        if m.kind == ModKind::ChangeLane {
            let now = self.track(target).lane(t);
            let s_now = self.s_at(target, t);
            let exists = |left: bool| self.road.beside(now, left, n.into(), s_now).is_some();
            // change_lane without a side: "the side is randomized" (§8.9 change_lane), drawn
            // once per modifier from the run's seed among the sides that have the lane.
            let left = match side {
                Some(_) => left,
                None => *self
                    .sides
                    .borrow_mut()
                    .entry(format!("{:?}", m.app.span))
                    .or_insert_with(|| match (exists(true), exists(false)) {
                        (true, true) => self.ctx.choose(2) == 0,
                        (l, _) => l,
                    }),
            };
            let shift = if left { n } else { -n };
            if !exists(left) {
                return Err(self.ctx.files.err(
                    K::Unsatisfiable,
                    m.app.span,
                    format!(
                        "expected a driving lane {n} to the {} of `{target}`'s lane {now} at s = {s_now:.2} m, found none",
                        if left { "left" } else { "right" }
                    ),
                ));
            }
            return Ok((
                LaneChangeTarget::Relative {
                    entity_ref: target.to_string(),
                    value: shift,
                },
                self.road.beside(now, left, n.into(), s_now),
            ));
        }
        for (key, value) in [
            ("same_as", 0),
            ("side_of", shift),
            ("left_of", n),
            ("right_of", -n),
        ] {
            if let Some(e) = m.arg(key) {
                let x = self.entity_of(e)?;
                let lx = self.track(&x).lane(t + len);
                let s_end = self.s_at(&x, t + len);
                let lane = match value {
                    0 => Some(lx),
                    v => self.road.beside(lx, v > 0, v.abs().into(), s_end),
                };
                if lane.is_none() {
                    return Err(self.ctx.files.err(
                        K::Unsatisfiable,
                        m.app.span,
                        format!(
                            "expected a driving lane {} to the {} of `{x}`'s lane {lx} at the phase end (s = {s_end:.2} m), found none",
                            value.abs(),
                            if value > 0 { "left" } else { "right" }
                        ),
                    ));
                }
                return Ok((
                    LaneChangeTarget::Relative {
                        entity_ref: x,
                        value,
                    },
                    lane,
                ));
            }
        }
        // A lane number (1 = the rightmost driving lane, or the leftmost with from: left) at
        // the phase end: an absolute target lane.
        let from_left = matches!(m.arg("from").map(|e| self.ctx.eval(e)).transpose()?, Some(Val::Enum(f)) if f == "left");
        let s_end = self.s_at(target, t + len);
        match self.road.numbered(n.into(), from_left, s_end) {
            Some(l) => Ok((LaneChangeTarget::Absolute(l.to_string()), Some(l))),
            None => Err(self.ctx.files.err(
                K::Unsatisfiable,
                m.app.span,
                format!(
                    "expected a driving lane numbered {n} from the {} on road {} at s = {s_end:.2} m, found none",
                    if from_left { "left" } else { "right" },
                    self.road.id()
                ),
            )),
        }
    }
}

/// The `speed(…, at: end)` or `change_speed(…)` of an invocation, if any.
fn end_speed_mod<'m, 'p>(mods: &'m [Mod<'p>]) -> Option<&'m Mod<'p>> {
    mods.iter()
        .find(|q| (q.kind == ModKind::Speed && q.at == At::End) || q.kind == ModKind::ChangeSpeed)
}

/// Whether an invocation holds its speed throughout (`speed(v)`, at: all).
fn holds_speed(mods: &[Mod<'_>]) -> bool {
    mods.iter()
        .any(|q| q.kind == ModKind::Speed && q.at == At::All)
}

/// The lane change of an invocation (`change_lane`, `lane(…, at: end)`), if any.
fn lane_change<'m, 'p>(mods: &'m [Mod<'p>]) -> Option<&'m Mod<'p>> {
    mods.iter()
        .find(|m| m.kind == ModKind::ChangeLane || (m.kind == ModKind::Lane && m.at == At::End))
}

/// The `lateral(…, at: end)` of an invocation, if any.
fn lateral_end<'m, 'p>(mods: &'m [Mod<'p>]) -> Option<&'m Mod<'p>> {
    mods.iter()
        .find(|m| m.kind == ModKind::Lateral && m.at == At::End)
}

/// 1 for an invocation with a `position(…, at: end)` relative to another actor, else 0: the
/// order in which a parallel plans its members.
fn relative_end(p: &Phase<'_>, mods: &HashMap<String, &Vec<Mod<'_>>>) -> u8 {
    mods.get(&p.path).is_some_and(|ms| {
        ms.iter()
            .any(|m| m.kind == ModKind::Position && m.at == At::End)
    }) as u8
}

fn speed_action(shape: DynamicsShape, time: f64, target: SpeedTarget) -> PrivateAction {
    PrivateAction::Longitudinal(LongitudinalAction::Speed {
        dynamics: TransitionDynamics {
            dynamics_shape: shape,
            dynamics_dimension: DynamicsDimension::Time,
            value: time,
            following_mode: None,
        },
        target,
    })
}

fn check_speed(ctx: &Ctx<'_>, m: &Mod<'_>, v: f64) -> Result<(), Error> {
    if !(0.0..=MAX_SPEED).contains(&v) {
        return Err(ctx.files.err(
            K::Unsatisfiable,
            m.app.span,
            format!("expected a plan within 0 to {MAX_SPEED} m/s, found it needs {v:.2} m/s"),
        ));
    }
    Ok(())
}

fn check_accel(ctx: &Ctx<'_>, m: &Mod<'_>, a: f64) -> Result<(), Error> {
    if a.abs() > MAX_ACCELERATION + 1e-9 {
        return Err(ctx.files.err(
            K::Unsatisfiable,
            m.app.span,
            format!("expected a plan within ±{MAX_ACCELERATION} m/s², found it needs {a:.2} m/s²"),
        ));
    }
    Ok(())
}
