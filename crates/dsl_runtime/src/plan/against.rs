//! Actors that drive against s (ASAM OpenDRIVE 1.8 §11.2: with right-hand traffic the lanes of
//! the left side, positive ids, are driven towards −s; ASAM OpenSCENARIO DSL 2.1 §8.9 movement
//! modifiers): what the planner runs for them, and relations between actors of opposite
//! directions.
//!
//! An actor whose first phase is `along(l)` of a lane driven in −s (a lane field the map's
//! modifiers bind, an odr point, a route through points in such a lane, whose path runs
//! against s and whose roads the plan drives the other way round, `road::route_roads`), or `along(r)` of a route field the map's
//! `routes_are_opposite(route1, route2)` binds as `route2` (§8.12.2.2.10; `bind_routes`: the
//! plan's roads driven the other way, or the one road `routes_are_in_sequence` bound `route1`
//! to, driven so), drives the plan's roads against s: it is placed and planned
//! on the view `PlanRoad::against` gives, in the distance u along its direction of travel
//! (`crate::road`), and the lowering maps its start back to (road, s). The planner's
//! arithmetic is the same in either direction, so what runs is what only reads the actor's
//! own track and its road view: `drive()`/`move()`, `change_speed`, `keep_speed`, the
//! direction-free `assign_speed`, `assign_acceleration`, `change_acceleration`,
//! `keep_acceleration`, `remain_stationary`, `change_lane`, `follow_lane` (and their
//! `offset`), with `speed`, `change_speed`, `acceleration(a)`, `position(d)`, `lane(n)`,
//! `change_lane`, `keep_lane`, `keep_speed`, `keep_position`, `distance`, `along`,
//! `physical_movement`, `lateral(d)` in the lane (offsets to the left of the direction of
//! travel in the plan, turned to the road's t by the lowering), `yaw`/`orientation` relative to
//! the road's s-axis (§8.9.9: π along a lane driven in −s, `checks::check_orientation`), in the
//! world or from another object (`heading`: the view's heading is the road's turned by π),
//! `shape:` (its action's dynamics, `shapes`), and `lateral` and `acceleration` relative to an
//! actor driving against s too (left and right are the drivers': the view's t, which the
//! lowering turns to the road's; an acceleration has no direction), and the position and
//! path actions (`assign_position`, `assign_orientation`, `change_position`, `follow_path`,
//! `follow_trajectory`, `replay_path`, `replay_trajectory`: world places have no direction;
//! the place the actor reaches is put on the view, `position_actions`),
//! `avoid_collisions(true)` (the engine's `idm` finds the leader along the vehicle's direction
//! of travel, `car_following`). What the engine measures
//! for such an actor — its checks at the start of a phase that starts on a run-time condition
//! (`position(…)`, `lateral(…)` in the lane or beside another actor, `lane(…)` by number or
//! relative to another actor, `along` a named route), the marks of `distance(d)` and of a gap
//! without a phase duration, the TravelAction — it measures along the actor's direction of
//! travel, in the numbers the plan writes (u = L − s, t to the actor's left): the plan gives
//! it the direction with the roads (`Planner::chain`, `scenario::PlanRoads`); so do the group
//! forms of the path actions after a run-time condition (`group_path_runtime`: member 0's
//! check at the part's start, a column's offsets; a block's RelativeRoadPositions in the road
//! frame, the view's offsets turned).
//!
//! The gap actions (`change_space_gap`, `keep_space_gap`, `change_time_headway`,
//! `keep_time_headway`) run between two actors driving against s: the engine's
//! LongitudinalDistanceAction and LateralDistanceAction measure in road coordinates turned to
//! the actor's direction of travel (OpenSCENARIO 1.3 §6.4, `condition::road_distance`: the
//! reference ahead of / left of it is positive) and move the actor along and across its lane in
//! that direction, the plan's own view; their checks carry the direction like every other.
//!
//! A vehicle group (§8.7.18) drives its members' direction, one for all of them
//! (`group_direction`): its formation is placed and planned on the view as in +s, front to
//! back along the direction of travel, and each member lowered as an actor driving against s;
//! the gap actions' group form is their chain along that formation; `g.assign_position`,
//! `g.change_position` (`position_actions::formation_place`) and, at a start the plan knows,
//! the path actions' group forms (`group_path`) move it by
//! each member's offset from member 0 in the view (along the direction of travel and to the
//! drivers' left), a column's lead-ins along its lanes in that direction.
//!
//! So every §8.8 action and §8.9 modifier of the standard library runs against s; what is
//! left is an action the program declares with no `do` and no §8.8 action among its
//! ancestors, which runs in neither direction: the planner's one refusal of it
//! (`Planner::plan_invoke`, "expected a `do` in …"), the same for an actor in +s (before,
//! `check_runs` here refused it first with a list of what runs against s, though nothing of
//! the standard library was left off that list).
//!
//! An actor along a free route of the other direction than its own is an error at the
//! `along` (`check_alongs`).
//!
//! Between actors of opposite directions: the speed relations (`speed(…, faster_than /
//! slower_than / same_as: x)`) run, a speed having no direction, and so do the yaws measured
//! from x's axes (`yaw`/`orientation` with `relative_to: x`, an angle in the world frame,
//! `heading`); every other relation
//! (`position(d, ahead_of/behind: x)`, `lane(same_as/side_of/left_of/right_of: x)`, a gap or
//! a lane change relative to x) is an error at the argument: §8.9 places the actor "ahead of"
//! or "behind" x, or in a lane counted from x's, along the direction both travel, and two
//! actors driving opposite ways share none. A stationary object has no direction: an actor
//! driving against s relates to it in its own frame (`turn_stationary` while its phases are
//! planned, `place` at the start: u = L − s, its offset to the left of that direction); a
//! lane or a lateral position counted from the object's lane only where the object stands in
//! a lane of the actor's direction (else an error at the argument).

use std::collections::HashMap;

use super::place::ToPlace;
use super::types::Entity;
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{
    ActorKind, Along, Kind, MapKind, MapModifier, ModKind, Modifier, Phase, Route,
};
use crate::road::PlanRoad;
use crate::track::Track;

/// The speed relations, which hold between actors of any directions.
const SPEED_REFERENCES: [&str; 3] = ["faster_than", "slower_than", "same_as"];

/// Whether the argument `key` of modifier `m` relates the actor to another without a
/// direction, so that it holds between actors driving opposite ways: a speed relation (a
/// speed has no direction), or the angle between two objects' axes (`yaw`/`orientation`
/// `relative_to: x`, measured in the world frame: `heading`).
fn directionless(m: Option<&Modifier>, key: &str) -> bool {
    m.is_some_and(|m| match m.kind {
        ModKind::Speed => SPEED_REFERENCES.contains(&key),
        ModKind::Orientation => key == "relative_to",
        _ => false,
    })
}

/// Checks, before any actor is placed, that every invocation runs for the direction its
/// actors drive and relates no two actors of opposite directions (see the module doc).
/// `all`: every actor to place, with its direction; `index`: the entities by name.
pub(crate) fn check_references(
    leaves: &[&Phase],
    all: &[ToPlace<'_>],
    index: &HashMap<String, usize>,
    random: &dyn Fn(&str) -> bool,
) -> Result<(), Error> {
    let against: HashMap<&str, bool> = all.iter().map(|p| (p.name.as_str(), p.against)).collect();
    let fixed = |name: &str| all.iter().find(|p| p.name == name).and_then(|p| p.fixed);
    if !against.values().any(|a| *a) {
        return Ok(());
    }
    let dir = |name: &str| against.get(name).copied().unwrap_or(false);
    for leaf in leaves {
        let Kind::Invoke(inv) = &leaf.kind else {
            continue;
        };
        // The invocation's actor: an entity, or a group, which drives its members' direction
        // (they share the group's first phase, so its route).
        let actor_against = if index.contains_key(&inv.actor) {
            dir(&inv.actor)
        } else {
            let against = group_direction(&inv.actor, all, &leaf.site)?;
            // The group forms of the position and path actions run on the view: `assign_position`,
            // `change_position` (`position_actions::formation_place`) and the path actions at a
            // start the plan knows (`group_path`) move the formation by its offsets from member 0
            // taken in the view (along the direction of travel, to the drivers' left), after a
            // run-time condition too (`group_path_runtime`);
            // `assign_orientation` turns each standing member where it is to a world yaw.
            against
        };
        for (m, key, a) in inv.all_args() {
            let Some(x) = a.path.as_deref().filter(|x| index.contains_key(*x)) else {
                continue;
            };
            let what = m.map_or_else(
                || format!("{}(…)", inv.action),
                |m| format!("{}(…)", m.name),
            );
            // A stationary object has no direction: its place is turned into the actor's
            // frame (`turn_stationary`, `place`). A relation along the lane (a position, a
            // speed) holds with it in any lane; one that counts lanes from its lane (`lane`,
            // a lane change relative to it) needs a lane the actor drives in its direction.
            if let Some(f) = fixed(x) {
                let along = m.is_some_and(|m| matches!(m.kind, ModKind::Position | ModKind::Speed));
                if !along && actor_against && f.lane < 0 {
                    return Err(a.site.err(
                        K::Unsatisfiable,
                        format!("expected `{key}:` of {what} to name an object in a lane `{}` drives in its direction (against s, a lane of the left side), found `{x}` in lane {}, driven in +s", inv.actor, f.lane),
                    ));
                }
                continue;
            }
            if dir(x) == actor_against || x == inv.actor {
                continue;
            }
            // Random traffic has no direction of its own: `lane(…: x)` deals its members to
            // x's lane or one beside it in x's direction (`random_traffic_creation`).
            if random(&inv.actor) && m.is_some_and(|m| m.kind == ModKind::Lane) {
                continue;
            }
            if directionless(m, key) {
                continue;
            }
            let how = |a: bool| if a { "against s" } else { "in +s" };
            return Err(a.site.err(
                K::Unsatisfiable,
                format!(
                    "expected `{key}:` of {what} to name an actor driving in the direction of `{}` ({}), found `{x}`, which drives {}: §8.9 relates an actor to x along the direction both travel (ahead of, behind, the lanes counted from x's), and two actors driving opposite ways share none (speed relations alone hold across directions)",
                    inv.actor,
                    how(actor_against),
                    how(dir(x))
                ),
            ));
        }
    }
    Ok(())
}

/// The direction of group `group`'s members among `all` (true: against s), or an error at
/// `site` when they drive both ways (a member whose own first phase comes before the group's
/// set its direction apart): a formation is placed and planned along one direction of travel.
pub(crate) fn group_direction(
    group: &str,
    all: &[ToPlace<'_>],
    site: &crate::error::Site,
) -> Result<bool, Error> {
    let prefix = format!("{group}.");
    let mut members = all.iter().filter(|p| p.name.starts_with(&prefix));
    let Some(first) = members.next() else {
        return Ok(false);
    };
    if let Some(other) = members.find(|p| p.against != first.against) {
        let how = |a: bool| if a { "against s" } else { "in +s" };
        return Err(site.err(
            K::Unsatisfiable,
            format!(
                "expected the members of group `{group}` to drive one direction (its formation is placed along one direction of travel), found `{}` {} and `{}` {}",
                first.name,
                how(first.against),
                other.name,
                how(other.against)
            ),
        ));
    }
    Ok(first.against)
}

/// The route fields `routes_are_opposite(route1, route2)` on route fields binds to roads
/// driven against s (`route2`), each with what bound it: `route1` is the plan's roads, as
/// every free route field, and `route2` those roads against s; or `route1` is one road of the
/// plan that `routes_are_in_sequence` bound (`road_fields`: its lane, the plan's s of its start
/// and end, what bound it), and `route2` that road driven against s, returned also as a road
/// field of its own (the first driving lane in its direction, its span in +s), which an actor
/// along it drives from its start (u = L − its end) and must stay on (`route::check`).
/// Errors at the modifier: a field opposite to itself, a `route2` bound in +s to one road, a
/// field both ways, a road with no lane driven against s.
pub(crate) fn bind_routes(
    mods: &[MapModifier],
    road: &PlanRoad<'_>,
    road_fields: &HashMap<String, (i32, (f64, f64), String)>,
) -> Result<(HashMap<String, String>, BoundRoads), Error> {
    let mut out: HashMap<String, String> = HashMap::new();
    let mut one_road = Vec::new();
    let mut forward: Vec<&str> = Vec::new();
    for m in mods {
        let MapKind::OppositeRoutes { route1, route2 } = &m.kind else {
            continue;
        };
        if route1 == route2 {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected two routes in opposite directions, found `{route1}` twice"),
            ));
        }
        if let Some((_, _, why)) = road_fields.get(route2) {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected route2 driven against s, opposite to route1, found `{route2}`, one road driven in +s ({why}: its lanes lead on in the plan's direction)"),
            ));
        }
        if out.contains_key(route1) || forward.contains(&route2.as_str()) {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected `{route1}` in +s and `{route2}` against s, found a route field bound both ways by the map's routes_are_opposite(…)"),
            ));
        }
        forward.push(route1);
        let why = format!(
            "the plan's roads against s, bound by map.{}(…) at {}",
            m.name,
            m.site.at()
        );
        // route1 one road of the plan: route2 that road against s, in its first driving lane
        // in that direction (lane 1 counted from the drivers' right), from its start.
        if let Some((_, (a, b), by)) = road_fields.get(route1) {
            let view = road.against().map_err(|e| m.site.err(K::Road, e))?;
            let (id, _) = road.road_at(0.5 * (a + b));
            let Some(lane) = view.numbered(1, false, road.length() - b, false) else {
                return Err(m.site.err(
                    K::Road,
                    format!("expected a driving lane of road {} driven against s for `{route2}`, opposite to `{route1}` ({by}), found none", id.id),
                ));
            };
            let why = format!(
                "road {} against s, opposite to `{route1}` ({by}), bound by map.{}(…) at {}",
                id.id,
                m.name,
                m.site.at()
            );
            one_road.push((route2.clone(), (lane, (*a, *b), why.clone())));
            out.insert(route2.clone(), why);
            continue;
        }
        out.insert(route2.clone(), why);
    }
    Ok((out, one_road))
}

/// Route fields bound to one road of the plan: the field, its lane, the plan's s of the road's
/// start and end (in +s), and what bound it.
pub(crate) type BoundRoads = Vec<(String, (i32, (f64, f64), String))>;

/// Checks that each free route `actor` drives `along` in `mods` runs in its direction:
/// a route field bound against s (`against_routes`) for an actor driving so, any other free
/// route field (the plan's roads in +s) for one in +s.
pub(crate) fn check_alongs(
    actor: &str,
    against: bool,
    mods: &[Modifier],
    against_routes: &HashMap<String, String>,
) -> Result<(), Error> {
    for m in mods {
        let Some(Along {
            route:
                Route::Free {
                    field,
                    one_lane: false,
                    ..
                },
            site,
            ..
        }) = &m.along
        else {
            continue;
        };
        let back = against_routes.get(field);
        if back.is_some() != against {
            let how = |a: bool| if a { "against s" } else { "in +s" };
            let what = back.map_or_else(|| "the plan's roads in +s".to_string(), |why| why.clone());
            return Err(site.err(
                K::Unsatisfiable,
                format!("expected `{actor}`, which drives {}, along a route in its direction, found `{field}` ({what}); an actor's direction is its first phase's route's", how(against)),
            ));
        }
    }
    Ok(())
}

/// Turns the place of every stationary object among `entities` into the frame of an actor
/// driving the plan's roads (of length `length`) against s: s to u = L − s, its offset from its
/// lane's centre to the left of that direction (−offset); returns the tracks it replaced, which
/// [`restore_stationary`] puts back. A stationary object has no direction of travel: an actor
/// related to one (`position(d, behind: cone)`) reads its place in the actor's own frame.
pub(crate) fn turn_stationary(entities: &mut [Entity], length: f64) -> Vec<(usize, Track)> {
    let mut kept = Vec::new();
    for (i, e) in entities.iter_mut().enumerate() {
        if !matches!(e.data.kind, ActorKind::Stationary(_)) {
            continue;
        }
        // A stationary object's track is its place from the start (nothing moves it).
        let (s, _) = e.track.at(0.0);
        let mut turned = Track::new(length - s, 0.0, e.track.start_lane());
        turned.set_offset(0.0, -e.track.offset(0.0));
        kept.push((i, std::mem::replace(&mut e.track, turned)));
    }
    kept
}

/// Puts back the tracks [`turn_stationary`] replaced.
pub(crate) fn restore_stationary(entities: &mut [Entity], kept: Vec<(usize, Track)>) {
    for (i, track) in kept {
        entities[i].track = track;
    }
}
