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
//!   ends it; an action that ends on its own ends its invocation then, unless the invocation
//!   gives its own `duration:` argument (§8.8 `osc_action.duration`, the action's duration),
//!   which it then lasts (`schedule`); an invocation without either ends with its composition, or when the engine
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
//! constraint is unsatisfiable, an error naming the modifier. A modifier relative to another
//! actor x reads x's planned track; with `track: projected` (§8.9.1.1.3) x as projected from
//! its state at the phase start (its lane, offset and speed then, held): `motion::reference_s`,
//! `speed_value` read at the start, `lane_target`, `lateral_end`.
//!
//! Modifiers that constrain the motion without adding to it are checked against the plan:
//! `along(r)` (the `route` module: the actor on its route at the phase start and end),
//! `keep_lane`, `keep_speed`, `physical_movement(must_be_physical)` (no contradicting change;
//! `checks::check_keeps`) and `movement_mode: monotonous` on `position(…, at: end)`.
//!
//! Stage 2 of the pipeline, **plan**: it reads the resolved scenario (`crate::resolve`) and the
//! road, and hands a `Plan` (`types`) to `crate::lower`. Modules, each using only those above
//! it:
//!
//! | module | plans |
//! | --- | --- |
//! | `types` | the plan's data, limits and tolerances |
//! | `map_crossings` | the way across a crosswalk of the map joining two lanes (`crossing_connects`) |
//! | `lateral` | `lateral(…)` as an offset in the lane or beside another actor |
//! | `against` | what runs for actors driving against s, and relations between actors of opposite directions |
//! | `place` | initial placement from `at: start`/`all` constraints |
//! | `route` | `along(…)` routes against the planned motion; the road named routes are on |
//! | `checks` | `keep_*`, `physical_movement`, `yaw`/`orientation` against the planned motion |
//! | `heading` | yaws measured in the world or from another object, checked against the finished plan's headings |
//! | `planner` | the planner's state: entities, tracks, phases planned so far; where an event is used (its event context) |
//! | `motion` | speed profiles, modifier values, lane targets |
//! | `events` | conditions and events as triggers in their event context |
//! | `car_following` | `avoid_collisions(true)`: the engine's IDM car following for the phase |
//! | `action_args` | a §8.8 action's `rate_profile`, `rate_peak`, `duration` and the dynamics they give |
//! | `path_shape` | the shape a path or trajectory is lowered to: a polyline, or the smooth curve through the points' headings |
//! | `path_part` | the part of a path an action follows between its offsets, and points along it with their times |
//! | `road_path` | paths through points of the road network (`create_path_odr_points`, `create_path_route_points`) as the paths of their world points, before the plan |
//! | `speed_actions` | the §8.8 actions that control the speed or the acceleration |
//! | `speed_follow` | `speed(…, faster_than/slower_than/same_as: x)` at: all: the actor's planned speed follows x's over the phase (the engine's continuous relative SpeedAction, in a first phase too) |
//! | `lateral_actions` | the §8.8 actions that control the lateral position (`change_lane`, `follow_lane`) |
//! | `position_shape` | `position(…, at: end)` and `distance(…)` with a `common_position_shape`: the speed profile that covers the distance |
//! | `shapes` | modifiers with a `shape:`, planned as the action whose dynamics the shape is |
//! | `shape_relative` | a shaped modifier relative to another actor: its target from that actor's value |
//! | `gap_actions` | the §8.8.3 actions that control the gap or headway to another object |
//! | `position_actions` | the §8.8 actions that put an actor somewhere or turn it (`assign_position`, `assign_orientation`, `change_position`) |
//! | `group_path` | the group forms of the path and trajectory actions: a column following the path in file, a group over several lanes the path moved to each member's place in the road frame |
//! | `group_path_runtime` | the same after a run-time condition: a block's paths as positions relative to each member, a column's untimed path from its checked offset |
//! | `trajectory_actions` | the §8.8 actions along given points (`follow_trajectory`, `follow_path`) |
//! | `relative_path` | relative trajectories and paths as world points against their reference at the action's start |
//! | `map_checks` | the map's modifiers over route fields checked against the plan's roads |
//! | `map_junctions` | ways through a junction: the connecting lane, the turn, the roads meeting there counted clockwise (`roads_follow_in_junction`) |
//! | `map_roads` | the route fields the map's modifiers bind whole: roads and lane sections in sequence, a junction's connecting road |
//! | `map_lanes` | the map's modifiers against the loaded network: lane fields bound, the plan's roads checked |
//! | `lane_fields` | the lane a `lane` field names for `change_lane`/`follow_lane(target: l)`: bound or drawn once |
//! | `relative_over_distance` | a speed relative to another actor at the end of a phase `distance(d)` ends: x's speed where the plan ends it, or the engine's x |
//! | `runtime_end` | what the engine measures from a run-time start (a mark) and checks at such a phase's end |
//! | `runtime` | the engine's checks of `at: start` constraints after a run-time start |
//! | `runtime_rate` | speed changes at a rate relative to another actor after a run-time start (the engine's change and its checks) |
//! | `runtime_kept` | the engine's checks after a run-time start of what the plan keeps by construction (yaw relative to the road, `keep_position`) |
//! | `acceleration_follow` | `acceleration(…)` relative to another actor that the engine follows step by step |
//! | `held_relation` | `position(…, ahead_of/behind: x)` and `lane(…: x)` at: all held throughout the phase: the engine's hold, the plan's check at every step, or the engine's held check |
//! | `lateral_follow` | `lateral(…)` at: all beside another actor that moves sideways: the engine follows it |
//! | `lateral_end` | `lateral(…, at: end)` beside another actor: a lateral target where the plan has it at the phase end |
//! | `crossing_walk` | `walk()` along a crossing the map bound: a person across the crosswalk |
//! | `crossing_beside` | `lateral(…)` beside another actor beside a walk along a crossing: across the crossing's line from x's place |
//! | `crossing_speed` | an action on the speed or acceleration along a crossing: its line the path, the action's speed along it |
//! | `random_traffic` | a `random_traffic_vehicle_group`'s drive: members placed from the seed over the driving lanes, each driven by the engine's `mobil` model |
//! | `route_moves` | the lane (offset) changes between the points of a route in other lanes or at other offsets |
//! | `random_traffic_relations` | another actor placed at its start relative to a member of random traffic as drawn |
//! | `random_traffic_late` | random traffic created after the run's start, among the other actors' places then |
//! | `random_traffic_actions` | a `random_traffic_vehicle_group`'s later actions: each member's model given a desired speed; a member's own acceleration its model's free-road acceleration |
//! | `invoke` | one invocation's action and modifiers |
//! | `schedule` | one phase and its members |
//! | `overlap` | a parallel's members aligned to its `overlap:` argument (§7.3.9) |
use std::cell::RefCell;
use std::collections::{HashMap, HashSet};

use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{
    ActorData, ActorKind, At, EventSpec, Kind, ModKind, Modifier, Object, Phase, Resolved, Route,
};
use crate::road::PlanRoad;
use crate::track::Track;

mod acceleration_follow;
mod action_args;
mod against;
mod car_following;
mod checks;
mod crossing_beside;
mod crossing_speed;
mod crossing_walk;
mod events;
mod gap_actions;
mod group_path;
mod group_path_runtime;
mod heading;
mod held_relation;
mod invoke;
mod lane_fields;
mod lateral;
mod lateral_actions;
mod lateral_end;
mod lateral_follow;
mod map_checks;
mod map_crossings;
mod map_junctions;
mod map_lanes;
mod map_roads;
mod motion;
mod overlap;
mod path_part;
mod path_shape;
mod place;
mod planner;
mod position_actions;
mod position_shape;
mod random_traffic;
mod random_traffic_actions;
mod random_traffic_creation;
mod random_traffic_late;
mod random_traffic_relations;
mod relative_over_distance;
mod relative_path;
mod road_path;
mod route;
mod route_moves;
mod runtime;
mod runtime_end;
mod runtime_kept;
mod runtime_rate;
mod schedule;
mod shape_relative;
mod shapes;
mod speed_actions;
mod speed_follow;
mod trajectory_actions;
mod types;

use place::{place, ToPlace};
use planner::{no_end, EventCtx, Planner};

pub(crate) use map_lanes::junction_roads;
pub(crate) use random_traffic::driver_domains;
pub(crate) use road_path::locate_paths;
pub(crate) use route::{locate_points, named_routes, points as route_points};
pub use types::POSITION_TOLERANCE;
pub(crate) use types::{
    Entity, HandlerPlan, Plan, Planned, Settings, When, MAX_ACCELERATION, MAX_SPEED,
};

/// The Act of the `index`th `on` handler of the behavior invoked at phase `within` (`None`:
/// the entry scenario's): `do.round_two.on.0`, `on.0`.
fn handler_act(within: Option<&str>, index: usize) -> String {
    match within {
        Some(path) => format!("{path}.on.{index}"),
        None => format!("on.{index}"),
    }
}

/// Plans the resolved scenario on `road`.
pub(crate) fn plan(res: &Resolved, road: &PlanRoad<'_>, settings: Settings) -> Result<Plan, Error> {
    let root = &res.root;
    let mut p = Planner {
        road: road.clone(),
        settings,
        objects: &res.objects,
        entities: Vec::new(),
        index: HashMap::new(),
        groups: HashMap::new(),
        across: HashSet::new(),
        random: HashMap::new(),
        first_leaf: HashMap::new(),
        phases: Vec::new(),
        last_v: HashMap::new(),
        emits: HashMap::new(),
        events: HashMap::new(),
        alongs: HashMap::new(),
        route_lanes: HashMap::new(),
        lane_roads: HashMap::new(),
        route_roads: HashMap::new(),
        crossings: HashMap::new(),
        crossing_lines: Vec::new(),
        sides: RefCell::new(HashMap::new()),
        beside_checks: Vec::new(),
        beside_follows: Vec::new(),
        held_relations: Vec::new(),
        heading_asks: Vec::new(),
        draws: RefCell::new(res.draws.clone()),
        engine_moved: HashMap::new(),
        lane_only: HashMap::new(),
        lane_blind: RefCell::new(std::collections::BTreeMap::new()),
        gaps: HashMap::new(),
        serial_before: HashMap::new(),
        against_road: None,
        against_routes: HashMap::new(),
        late_random: Vec::new(),
        unplaced_random: HashMap::new(),
    };
    root.walk(&mut |ph| {
        if let Kind::Emit(e) = &ph.kind {
            p.emits
                .entry(e.clone())
                .or_default()
                .push((ph.path.clone(), ph.site.clone()));
        }
    });
    let mut handlers = Vec::new();
    for spec in &res.events {
        // An `on` handler's event context: the run's, or its invocation's (§7.3.10).
        let ectx = spec.handler.as_ref().map(|_| match &spec.within {
            Some(within) => EventCtx::Invocation(within),
            None => EventCtx::Run,
        });
        // A handler's `call` is no event of the scenario.
        if spec.call.is_none() {
            p.events
                .entry(spec.name.clone())
                .or_default()
                .push((&spec.cond, &spec.site, ectx));
        }
        if let (Some((i, site)), Some(ectx)) = (&spec.handler, ectx) {
            handlers.push((handler_act(spec.within.as_deref(), *i), spec, site, ectx));
        }
    }
    // The map's modifiers: the plan's roads checked, lane fields bound (before any use).
    let (bound, crossings) = map_lanes::bind(road, &res.map, &mut |n| p.choose(n))?;
    for c in crossings {
        p.crossings.insert(c.field.clone(), c);
    }
    for b in bound {
        if b.whole_road {
            if let Some(span) = b.span {
                p.route_roads.insert(b.field, (b.lane, span, b.why));
            }
            continue;
        }
        p.route_lanes.insert(b.field.clone(), (b.lane, b.why));
        p.lane_roads.insert(b.field, (b.road, b.span));
    }
    let (against_routes, against_roads) = against::bind_routes(&res.map, road, &p.route_roads)?;
    p.against_routes = against_routes;
    p.route_roads.extend(against_roads);
    // Actors, in the order the tree names them, and each one's first phase.
    let mut leaves: Vec<&Phase> = Vec::new();
    for leaf in root.leaves() {
        let Kind::Invoke(inv) = &leaf.kind else {
            continue;
        };
        let names = p.register(&inv.actor, &inv.actor_site)?;
        for m in &inv.modifiers {
            for key in crate::resolve::REFERENCES {
                if let Some(e) = m.arg(key) {
                    let path = e.path.as_ref().ok_or_else(|| {
                        e.site.err(
                            K::UnknownActor,
                            format!("expected a vehicle for `{key}:`, found an expression"),
                        )
                    })?;
                    p.register(path, &e.site)?;
                }
            }
            if let (ModKind::Along, Some(a)) = (m.kind, &m.along) {
                route::on_plan_road(road, a)?;
                match route::map_route(road, a, &p.route_roads, &p.route_lanes)? {
                    Some((field, route::Bound::Road(lane, span, why))) => {
                        p.route_roads.entry(field).or_insert((lane, span, why));
                    }
                    // A lane of a lane section: bound as a lane field the map binds, within
                    // its section.
                    Some((field, route::Bound::Lane(lane, id, span, why))) => {
                        // A compound lane's element binds the compound lane to its lane
                        // too: `cl` alone is the lane its elements are made of.
                        if let Route::Free {
                            map_route:
                                Some(crate::resolve::MapRoute {
                                    compound: true,
                                    road: crate::resolve::MapRoad::Field(cl),
                                    ..
                                }),
                            ..
                        } = &a.route
                        {
                            p.route_lanes
                                .entry(cl.clone())
                                .or_insert((lane, why.clone()));
                        }
                        p.route_lanes
                            .entry(field.clone())
                            .or_insert((lane, why.clone()));
                        p.lane_roads
                            .entry(field.clone())
                            .or_insert((id, Some(span)));
                        p.route_roads.entry(field).or_insert((lane, span, why));
                    }
                    // A lane section in -s: driven against s, as route2 of routes_are_opposite
                    // bound to one road.
                    Some((field, route::Bound::Against(lane, span, why))) => {
                        p.against_routes.entry(field.clone()).or_insert(why.clone());
                        p.route_roads.entry(field).or_insert((lane, span, why));
                    }
                    None => {}
                }
                // A route the map makes across a crossing: walked (crossed) as a crossing
                // field the map binds.
                if let Some(c) = route::made_crossing(road, a)? {
                    p.crossings.entry(c.field.clone()).or_insert(c);
                }
                if let Route::Free { field, .. } = &a.route {
                    if let (Some((other, None)), Some((lane, why))) =
                        (p.lane_roads.get(field), p.route_lanes.get(field))
                    {
                        return Err(a.site.err(
                            K::Road,
                            format!("expected a lane of the roads the plan drives on ({}) for `{field}`, found lane {lane} of road {other} ({why})", road.ids().join(", ")),
                        ));
                    }
                }
                p.alongs
                    .entry(leaf.path.clone())
                    .or_default()
                    .push((m.at, a.clone()));
            }
        }
        for n in names {
            p.first_leaf.entry(n).or_insert_with(|| leaf.path.clone());
        }
        leaves.push(leaf);
    }
    // Stationary objects stand where their location(…) puts them, named or not.
    for (path, o) in res.objects.iter() {
        if let Some(Object::Actor(ActorData {
            kind: ActorKind::Stationary(_),
            ..
        })) = o
        {
            p.register(path, &res.site)?;
        }
    }
    // Initial placement from each actor's first phase.
    let mut to_place = Vec::new();
    // Walkers placed at a crossing's walked part, actors at a route's start off its lane's
    // centre: the lane, s and offset from the lane centre.
    let mut crossing_offsets = HashMap::new();
    for e in &p.entities {
        let first = p.first_leaf.get(&e.name);
        let (mods, site, actor): (Vec<&Modifier>, &Site, Option<&str>) =
            match leaves.iter().find(|l| Some(&l.path) == first) {
                Some(l) => match &l.kind {
                    Kind::Invoke(i) => (
                        i.modifiers.iter().filter(|m| m.at != At::End).collect(),
                        &l.site,
                        Some(i.actor.as_str()),
                    ),
                    _ => (Vec::new(), &l.site, None),
                },
                None => (Vec::new(), &root.site, None),
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
        let bb = e.data.bounding_box;
        // A member of random traffic is placed from the seed once the others are placed
        // (`random_traffic`): nothing else places it.
        let random = p.random_member(&e.name);
        let (member_after, across) = if random {
            (None, None)
        } else {
            (member_after, across)
        };
        let fixed = match e.data.kind {
            _ if random => Some(random_traffic::UNPLACED),
            ActorKind::Stationary(at) => {
                let [x, y, _] = at.position;
                let (lane, s, offset) = road.locate(x, y).unwrap_or((-1, 0.0, 0.0));
                Some(place::Start {
                    lane,
                    s,
                    v: 0.0,
                    offset,
                })
            }
            _ => None,
        };
        // A crossing of the first phase: at the start of the part walked (`crossing_walk`).
        let crossing_start = first
            .and_then(|f| p.alongs.get(f))
            .into_iter()
            .flatten()
            .find_map(|(at, a)| match (&a.route, at) {
                (Route::Crossing { field, .. }, At::Start | At::All) => {
                    p.crossings.get(field).map(|c| (c, a))
                }
                _ => None,
            })
            .map(|(c, a)| {
                let shift =
                    crossing_walk::crossing_shift(road, c, &mods, e.data.bounding_box.width)?;
                crossing_walk::walked_part(road, c, a, shift).map(|(start, _)| start)
            })
            .transpose()?;
        if let Some((lane, s, t)) = crossing_start {
            crossing_offsets.insert(e.name.clone(), (lane, s, t - road.lane_center(lane, s)));
        }
        // Beside another actor across a crossing: not beside it in a lane (`crossing_beside`
        // moves the walker once x is placed).
        let mods: Vec<&Modifier> = if crossing_start.is_some() {
            mods.into_iter()
                .filter(|m| {
                    m.kind != ModKind::Lateral || !matches!(lateral::reference(m), Ok(Some(_)))
                })
                .collect()
        } else {
            mods
        };
        // A named route of the first phase places the actor at its start; a lane driven in
        // −s (right-hand traffic: a positive id) puts the actor against s, at the distance u
        // = L − s along its direction of travel (`crate::road`), from where its lane starts in
        // that direction (a lane section's end in s).
        let route = first
            .and_then(|f| p.alongs.get(f))
            .into_iter()
            .flatten()
            .find_map(|(at, a)| {
                let (lane, s, against) = match (&a.route, at) {
                    (
                        Route::Lane {
                            road: id, lane, s, ..
                        },
                        At::Start | At::All,
                    ) => {
                        // On a road of the plan (`route::on_plan_road`, checked above).
                        let s0 = road.plan_s(id, *s).unwrap_or(*s);
                        let from = if *lane > 0 { road.length() - s0 } else { s0 };
                        (*lane, from + a.start_offset, *lane > 0)
                    }
                    // A lane field the map bound: from its lane section's start; a road field:
                    // from the road's start, in the lane the modifier bound there.
                    // A crossing: at the start of the part walked (its start lane's centre
                    // without a start_offset or lateral).
                    (Route::Crossing { .. }, At::Start | At::All) => {
                        crossing_start.map(|(lane, s, _)| (lane, s, false))?
                    }
                    // A route field `routes_are_opposite` binds to the plan's roads against
                    // s: no start of its own (the actor floats, in u); to one road of the
                    // plan against s: from its start in u = L − its end.
                    (Route::Free { field, .. }, At::Start | At::All)
                        if p.against_routes.contains_key(field) =>
                    {
                        let Some((lane, (_, to), _)) = p.route_roads.get(field) else {
                            return Some((None, Some(a.site.clone())));
                        };
                        (*lane, road.length() - to, true)
                    }
                    (Route::Free { field, .. }, At::Start | At::All) => {
                        match (p.lane_roads.get(field), p.route_lanes.get(field)) {
                            (Some((_, Some((_, to)))), Some((lane, _))) if *lane > 0 => {
                                (*lane, road.length() - to, true)
                            }
                            (Some((_, Some((from, _)))), Some((lane, _))) => (*lane, *from, false),
                            _ => p
                                .route_roads
                                .get(field)
                                .map(|(lane, (from, _), _)| (*lane, *from, false))?,
                        }
                    }
                    _ => return None,
                };
                Some((Some((lane, s)), against.then(|| a.site.clone())))
            });
        let (route, against) = route.unwrap_or((None, None));
        // A route whose start is off its lane's centre (t ≠ 0): placed there, the offset to
        // the left of its direction of travel (OpenDRIVE's t turned against s).
        let route_t = first
            .and_then(|f| p.alongs.get(f))
            .into_iter()
            .flatten()
            .find_map(|(at, a)| match (&a.route, at) {
                (Route::Lane { lane, t, .. }, At::Start | At::All) if *t != 0.0 => {
                    Some(if *lane > 0 { -*t } else { *t })
                }
                _ => None,
            });
        if let (Some(offset), Some((lane, s))) = (route_t, route) {
            crossing_offsets.insert(e.name.clone(), (lane, s, offset));
        }
        if let Some(site) = &against {
            if p.against_road.is_none() {
                p.against_road = Some(road.against().map_err(|m| site.err(K::Road, m))?);
            }
        }
        to_place.push(ToPlace {
            route,
            name: e.name.clone(),
            mods,
            member_after,
            across,
            front: bb.center[0] + bb.length / 2.0,
            rear: bb.length / 2.0 - bb.center[0],
            width: bb.width,
            site: site.clone(),
            walker: matches!(
                e.data.kind,
                ActorKind::Walker(scenario::PedestrianCategory::Pedestrian)
            ),
            fixed,
            against: against.is_some(),
        });
    }
    against::check_references(&leaves, &to_place, &p.index, &|g| p.random.contains_key(g))?;
    let to_members = p.random_traffic_relations(&leaves)?;
    let dependents = p.hold_dependents(&mut to_place, to_members);
    let index = p.index.clone();
    let entity = |path: &str| index.contains_key(path).then(|| path.to_string());
    let mut starts = place(road, p.against_road.as_ref(), &to_place, &entity)?;
    let placed_against: HashSet<String> = to_place
        .iter()
        .filter(|q| q.against)
        .map(|q| q.name.clone())
        .collect();
    let oncoming =
        p.place_random_traffic(&leaves, &mut starts, &placed_against, &dependents.held)?;
    p.place_relative_to_members(
        road,
        &mut to_place,
        &mut starts,
        &oncoming,
        &dependents,
        &entity,
    )?;
    for (e, q) in p.entities.iter_mut().zip(&to_place) {
        let mut s = starts[&e.name];
        e.against = q.against || oncoming.contains(&e.name);
        // Placed by its crossing or its route (no lane or position of its own): off its
        // lane's centre where the walked part (the route) starts there.
        if let Some((lane, at, offset)) = crossing_offsets.get(&e.name) {
            if s.lane == *lane && (s.s - at).abs() < POSITION_TOLERANCE {
                s.offset = *offset;
            }
        }
        e.track = Track::new(s.s, s.v, s.lane);
        e.track.set_offset(0.0, s.offset);
        p.last_v.insert(e.name.clone(), s.v);
    }
    // An `on` handler's event context starts with the run (the scenario's start) or with its
    // invocation; its event is translated (so checked) even when nothing waits on what it
    // emits: the run's handlers before the phases are planned, an invoked behavior's once its
    // invocation's phase has its start (`every`/`elapsed` count from it, `EventCtx`).
    let mut handler_plans = vec![None; handlers.len()];
    plan_handlers(&p, &handlers, false, &mut handler_plans)?;
    let end = p.schedule(root, When::At(0.0), None, None, None)?;
    p.create_late_random_traffic()?;
    plan_handlers(&p, &handlers, true, &mut handler_plans)?;
    let handler_plans: Vec<HandlerPlan> = handler_plans.into_iter().flatten().collect();
    if end == When::Never && !settings.open_end {
        return Err(no_end(root));
    }
    lateral_follow::check_beside_follows(&p, &p.beside_follows)?;
    p.check_held_relations(&p.held_relations)?;
    for (a, x, t0, te, site) in &p.beside_checks {
        for who in [a, x] {
            if let Some(t) = p.track(who).moving_in(*t0, te.unwrap_or(f64::INFINITY)) {
                return Err(site.err(
                    K::Unsatisfiable,
                    format!("expected `{a}` and `{x}` to keep their lateral positions while this lateral(…) holds (at: all), found `{who}` moving sideways from {t:.2} s; write at: start"),
                ));
            }
        }
    }
    let asks = std::mem::take(&mut p.heading_asks);
    heading::check_headings(&mut p, &asks)?;
    // A read of a lane the engine sets by a check once every phase is planned (`lane_only`).
    p.lane_blind_error()?;
    // A yaw other than 0 relative to the road is kept physically only by an actor that
    // stands; one that moves keeps it crabwise along its lane where every invocation of it
    // allows a non-physical movement (`checks::crabwise`).
    for e in &p.entities {
        if let Some((y, site)) = &e.yaw {
            if !e.track.stands() || p.engine_moved.contains_key(&e.name) {
                checks::crabwise(
                    root,
                    &e.name,
                    *y,
                    site,
                    &e.track,
                    p.engine_moved.contains_key(&e.name),
                )?;
            }
        }
    }
    Ok(Plan {
        roads: road.starts(),
        end: road.length(),
        routed: road.routed(),
        entities: p.entities,
        phases: p.phases,
        handlers: handler_plans,
    })
}

/// An `on` handler to plan: its Act, its event, the directive and its event context.
type Handler<'a> = (String, &'a EventSpec, &'a Site, EventCtx<'a>);

/// Plans the handlers of invoked behaviors (`invoked`, once the phases are planned: each runs
/// while its invocation's phase does) or those of the scenario that runs into `out`, at the
/// handlers' indices.
fn plan_handlers(
    p: &Planner<'_>,
    handlers: &[Handler<'_>],
    invoked: bool,
    out: &mut [Option<HandlerPlan>],
) -> Result<(), Error> {
    for (slot, (act, spec, site, ectx)) in out.iter_mut().zip(handlers) {
        if spec.within.is_some() != invoked {
            continue;
        }
        let span = match &spec.within {
            Some(within) => {
                // An invocation the plan never starts (a member of a serial that its own end
                // stops before it, `serial(duration: d)`) has no instance: §7.3.10 ties an `on`
                // directive to its scenario's instance, which lives from the invocation's start
                // to its end (§7.3.6), so its handlers never run and have no Act.
                let Some(phase) = p.phases.iter().find(|ph| &ph.path == within) else {
                    continue;
                };
                Some((phase.start.clone(), phase.end.clone()))
            }
            None => None,
        };
        *slot = Some(HandlerPlan {
            act: act.clone(),
            command_type: if spec.call.is_some() { "call" } else { "emit" },
            event: spec.name.clone(),
            trigger: p.condition(&spec.cond, 0, *ectx)?,
            site: (*site).clone(),
            span,
        });
    }
    Ok(())
}

/// Roads for the unit tests of the plan's modules.
#[cfg(test)]
pub(crate) mod test_roads {
    use opendrive::RoadNetwork;

    /// A bundled road of `tests/roads`.
    pub(crate) fn net(file: &str) -> RoadNetwork {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/roads")
            .join(file);
        // A test fixture the crate ships: failing to read it is a broken checkout.
        RoadNetwork::from_file(&path).expect("reads")
    }
}
