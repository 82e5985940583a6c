//! Routes of `along(…)` against the plan (ASAM OpenSCENARIO DSL 2.1 §8.9 movement modifiers,
//! `along`; §8.12 road abstraction): the road the named routes are on, and each actor on its
//! route at the phase start and end as the plan knows them (see `crate::resolve` for the forms
//! a route takes). For an actor driving against s (a lane of the left side, `plan::against`)
//! the route's interval and the actor's place are in u along its direction of travel, on the
//! road view it is planned on; where the engine's controller moves the actor (a gap action,
//! `avoid_collisions(true)`) the plan does not know its place at the end, which is not checked.

use std::collections::HashMap;

use super::map_crossings::{crossing, MapCrossing};
use super::types::POSITION_TOLERANCE;
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Along, At, Kind, MapRoad, ModKind, Modifier, Phase, Route};
use crate::road::PlanRoad;

/// How far an actor may be outside a route's interval (m): the position tolerance of the plan.
const ROUTE_TOLERANCE: f64 = POSITION_TOLERANCE;

/// Where one actor is during a phase, as the plan knows it.
pub(crate) struct OnRoute<'f> {
    /// The actor.
    pub actor: &'f str,
    /// The phase's start (s), when the plan knows it.
    pub t0: Option<f64>,
    /// The phase's end (s), when the plan knows it.
    pub te: Option<f64>,
    /// Its lane at a time.
    pub lane: &'f dyn Fn(f64) -> i32,
    /// Its s on the plan road at a time.
    pub s: &'f dyn Fn(f64) -> f64,
    /// Road fields the map bound to one road of the plan: the plan's s of its start and end,
    /// and what bound it (`map_lanes`).
    pub roads: &'f HashMap<String, (i32, (f64, f64), String)>,
}

/// Where an actor must be when a phase that starts at run time starts, for the engine to
/// check: the route's lane and its interval of s on the plan road (m, tolerance included).
pub(crate) struct StartOnRoute {
    /// The route's lane.
    pub lane: i32,
    /// The least and the greatest s.
    pub s: (f64, f64),
}

/// Checks that an actor follows `along` in its phase (`at`: when the modifier holds), with
/// the invocation's other modifiers `mods`. `shared` records, per free one-lane route, the
/// lane and what bound it (the first actor found along it, or an earlier use of the field). A named route at a phase start the plan does not
/// know is returned, for the engine to check there.
pub(crate) fn check(
    road: &PlanRoad<'_>,
    along: &Along,
    at: At,
    mods: &[Modifier],
    on: &OnRoute<'_>,
    shared: &mut HashMap<String, (i32, String)>,
) -> Result<Option<StartOnRoute>, Error> {
    let actor = on.actor;
    let one_lane = match &along.route {
        Route::Free { one_lane, .. } => *one_lane,
        Route::Lane { .. } => true,
        // The walk across is planned from the crossing's start to its end (`crossings`).
        Route::Crossing { .. } => return Ok(None),
    };
    let bound = match &along.route {
        Route::Free { field, .. } => on.roads.get(field),
        Route::Lane { .. } | Route::Crossing { .. } => None,
    };
    let describe = match (&along.route, bound) {
        (Route::Free { field, .. }, Some((_, _, why))) => format!("route `{field}` ({why})"),
        (Route::Free { field, .. } | Route::Crossing { field, .. }, _) => format!("route `{field}`"),
        (
            Route::Lane {
                road,
                lane,
                s,
                then,
                ..
            },
            _,
        ) => match then.last() {
            None => format!("the route along lane {lane} of road {road} from s = {s} m"),
            Some(p) if p.lane == *lane => format!(
                "the route in lane {lane} from road {road} at s = {s} m to road {} at s = {} m",
                p.road, p.s
            ),
            Some(p) => format!(
                "the route from lane {lane} of road {road} at s = {s} m to lane {} of road {} at s = {} m",
                p.lane, p.road, p.s
            ),
        },
    };
    if one_lane && at == At::All {
        if let Some(c) = mods
            .iter()
            .find(|m| m.kind == ModKind::ChangeLane || (m.kind == ModKind::Lane && m.at == At::End))
        {
            return Err(c.site.err(
                K::Unsatisfiable,
                format!(
                    "expected no lane change along {describe} (one lane, along(…) at {}), found `{}(…)`",
                    along.site.at(),
                    c.name
                ),
            ));
        }
    }
    let (lo, hi) = match &along.route {
        // A road field's span is in +s; on the view of an actor driving against s, in u.
        Route::Free { .. } | Route::Crossing { .. } => match bound {
            None => (0.0, road.length()),
            Some((_, (a, b), _)) if road.is_against() => (road.length() - b, road.length() - a),
            Some((_, span, _)) => *span,
        },
        Route::Lane {
            road: id, s, then, ..
        } => (
            // On roads of the plan (`on_plan_road`).
            road.plan_s(id, *s).unwrap_or(*s) + along.start_offset,
            match then.last() {
                Some(p) => road.plan_s(&p.road, p.s).unwrap_or(p.s),
                None => road.length(),
            } - along.end_offset,
        ),
    };
    let mut moments = Vec::new();
    let mut at_run_time = None;
    if at != At::End {
        match (on.t0, &along.route) {
            (Some(t), _) => moments.push(("start", t)),
            (None, Route::Lane { lane, .. }) => {
                at_run_time = Some(StartOnRoute {
                    lane: *lane,
                    s: (lo - ROUTE_TOLERANCE, hi + ROUTE_TOLERANCE),
                })
            }
            (None, Route::Free { .. } | Route::Crossing { .. }) => {}
        }
        if let Route::Free {
            field,
            one_lane: true,
            ..
        } = &along.route
        {
            // After a run-time start: the lane the actor was last planned in.
            let lane = (on.lane)(on.t0.unwrap_or(f64::MAX));
            match shared.get(field) {
                Some((l, why)) if *l != lane => {
                    return Err(along.site.err(
                        K::Unsatisfiable,
                        format!("expected `{actor}` in the lane of {describe} (lane {l}, {why}), found lane {lane}"),
                    ))
                }
                Some(_) => {}
                None => {
                    shared.insert(
                        field.clone(),
                        (lane, format!("where `{actor}` drives along it")),
                    );
                }
            }
        }
    }
    if at != At::Start {
        match on.te {
            Some(t) => moments.push(("end", t)),
            None if along.end_offset > 0.0 => {
                return Err(along.site.err(
                    K::Unsatisfiable,
                    "expected a phase end the plan knows for along(…, end_offset: …), found none (give the phase a duration; under avoid_collisions(true) or a gap action the engine's controller sets where the actor is then)",
                ))
            }
            None => {}
        }
    }
    let points = plan_points(road, &along.route);
    for (when, t) in moments {
        let s = (on.s)(t);
        if let Route::Lane { .. } = &along.route {
            let l = (on.lane)(t);
            let lanes = lanes_at(&points, s);
            if !lanes.contains(&l) {
                return Err(along.site.err(
                    K::Unsatisfiable,
                    format!("expected `{actor}` on {describe} (lane {} there) at the phase {when}, found it in lane {l}", lanes.first().copied().unwrap_or(l)),
                ));
            }
        }
        if s < lo - ROUTE_TOLERANCE || s > hi + ROUTE_TOLERANCE {
            // On the view of an actor driving against s: u, along its direction of travel.
            let (name, frame) = if road.is_against() {
                (
                    "u",
                    " (u along its direction of travel on the plan's roads driven against s)",
                )
            } else {
                ("s", "")
            };
            return Err(along.site.err(
                K::Unsatisfiable,
                format!("expected `{actor}` on {describe} between {name} = {lo:.2} m and {hi:.2} m at the phase {when}, found it at {name} = {s:.2} m{frame}"),
            ));
        }
    }
    Ok(at_run_time)
}

/// What the plan binds an element of the lists to (`map_route`).
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Bound {
    /// A road or lane section: the lane an actor along it without one of its own starts in,
    /// the plan's s of its start and end, and why.
    Road(i32, (f64, f64), String),
    /// A lane: its id, its road's id, the plan's s of its lane section's start and end, and
    /// why.
    Lane(i32, String, (f64, f64), String),
    /// A lane section flowing in -s (`s_negative`): driven against s as the `route2` of
    /// `routes_are_opposite` bound to one road (`against::bind_routes`): the lane an actor
    /// along it without one of its own starts in (the first driving lane in its direction),
    /// the plan's s of its start and end (in +s), and why.
    Against(i32, (f64, f64), String),
}

/// The binding of `along`'s route when it is a road of the map's lists (`m.routes[i]`,
/// `m.junctions[i].roads[j]`, `crate::resolve::MapRoad`) or an element of the library's
/// lists (`cr.route_elements[i]`, `rd.s_positive[i]`, `ls.lanes[i]`,
/// `crate::resolve::MapRoute`): on an OpenDRIVE map oscsim's choice is one route per road of
/// the file in its order, each the whole road (a `road` is a route element), a junction's
/// roads its connecting roads in the order its connections first name them, the elements of a
/// compound route the runtime chooses the plan's roads in order, a road's `s_positive` its
/// lane sections in order along s, and a lane section's `lanes` the lanes that flow in +s
/// (right-hand traffic: the right side) from the centre out. A road or lane section is bound
/// as a road the map's modifiers bind (its field, then the rightmost driving lane in +s at
/// its start, `lane(1)`'s, where an actor along it without a lane of its own starts, its span
/// in the plan's s, and why); a lane as a lane field the map binds (its lane, from its lane
/// section's start). `bound`: the road fields the map's modifiers bound (a route field whose
/// elements are read is that road, else the plan's roads). An index past a list, a road the
/// plan does not drive, and a lane no vehicle drives are errors at `along`.
pub(crate) fn map_route(
    road: &PlanRoad<'_>,
    along: &Along,
    bound: &HashMap<String, (i32, (f64, f64), String)>,
    lanes: &HashMap<String, (i32, String)>,
) -> Result<Option<(String, Bound)>, Error> {
    let Route::Free {
        field,
        map_route: Some(which),
        ..
    } = &along.route
    else {
        return Ok(None);
    };
    let net = road.network();
    let past = |n: usize, what: &str| {
        along.site.err(
            K::Road,
            format!("expected an index below {n} into {what}, found `{field}`"),
        )
    };
    let whole = |id: &str, why: String| -> Result<((f64, f64), String), Error> {
        let length = net.road(id).map_or(0.0, |r| r.length);
        match road.plan_span(id, 0.0, length) {
            Some(span) => Ok((span, why)),
            None => Err(along.site.err(
                K::Road,
                format!(
                    "expected `{field}` on the roads the plan drives on ({}), found {why}",
                    road.ids().join(", ")
                ),
            )),
        }
    };
    let (span, why) = match &which.road {
        MapRoad::Route(i) => {
            let roads = net.roads();
            let r = roads.get(*i).ok_or_else(|| {
                past(
                    roads.len(),
                    "the map's routes (one per road of the OpenDRIVE file, in its order)",
                )
            })?;
            whole(&r.id, format!("road {}, the map's route {i} (one per road of the OpenDRIVE file, in its order)", r.id))?
        }
        MapRoad::Junction(i, j) => {
            let junctions = net.junctions();
            let jn = junctions.get(*i).ok_or_else(|| {
                past(
                    junctions.len(),
                    "the map's junctions (one per junction of the OpenDRIVE file, in its order)",
                )
            })?;
            let mut roads: Vec<&str> = Vec::new();
            for c in &jn.connections {
                if !roads.contains(&c.connecting_road.as_str()) {
                    roads.push(&c.connecting_road);
                }
            }
            let id = roads.get(*j).ok_or_else(|| {
                past(
                    roads.len(),
                    &format!("the roads of junction {} (its connecting roads in the order its connections name them)", jn.id),
                )
            })?;
            whole(id, format!("road {id}, road {j} of junction {} (its connecting roads in the order its connections name them)", jn.id))?
        }
        MapRoad::Plan(i) => {
            let ids = road.ids();
            let id = ids.get(*i).ok_or_else(|| {
                past(
                    ids.len(),
                    "the route elements of a compound route the runtime chooses (the plan's roads, in order)",
                )
            })?;
            whole(id, format!("road {id}, the plan's road {i} (the elements of a compound route the runtime chooses)"))?
        }
        MapRoad::Field(f) => match bound.get(f) {
            Some((_, span, why)) => (*span, format!("`{f}` ({why})")),
            None => (
                (0.0, road.length()),
                format!("`{f}`, the plan's roads (a route the runtime chooses)"),
            ),
        },
    };
    if which.section.is_none() && which.lane.is_none() {
        let lane = road.driving_lanes(span.0).first().copied().unwrap_or(-1);
        return Ok(Some((field.clone(), Bound::Road(lane, span, why))));
    }
    // The lane sections within the span, in order along s (against s, in the order a driver
    // against s meets them): road id, index, plan span.
    let mut sections = Vec::new();
    for id in road.ids() {
        let Some(r) = net.road(&id) else { continue };
        for (k, sec) in r.lane_sections.iter().enumerate() {
            let s1 = r.lane_sections.get(k + 1).map_or(r.length, |n| n.s);
            if let Some(ps) = road.plan_span(&id, sec.s, s1) {
                if ps.0 >= span.0 - ROUTE_TOLERANCE && ps.1 <= span.1 + ROUTE_TOLERANCE {
                    sections.push((id.clone(), k, ps));
                }
            }
        }
    }
    // A compound lane's lanes: its own lane (bound, else lane(1)'s, where an actor along it
    // without a lane of its own drives) in the first lane section, then in each lane section
    // after it in order along s the lane the one before leads into (OpenDRIVE 1.8 §11.5 lane
    // linkage: the lane's <link><successor id=…>, `RoadNetwork::successors`), while that is a
    // driving lane of the plan's roads (issue 27: before, the same lane id in each section,
    // the wrong lane where a section renumbers its lanes; the plan's roads run on to another
    // road only where the ids are kept, `road::chain`).
    if let (true, MapRoad::Field(f), Some(j)) = (which.compound, &which.road, which.lane) {
        let (lane, how) = match lanes.get(f) {
            Some((l, why)) => (*l, why.clone()),
            None => (
                road.driving_lanes(span.0).first().copied().unwrap_or(-1),
                "lane(1)'s where the plan's roads start, where an actor along it without a lane of its own drives".to_string(),
            ),
        };
        let mut own = Vec::new();
        let mut before: Option<opendrive::LaneHandle> = None;
        for (id, k, ps) in &sections {
            let here = match before {
                None => {
                    let mid = net.road(id).map_or(0.0, |r| {
                        let s1 = r.lane_sections.get(k + 1).map_or(r.length, |n| n.s);
                        0.5 * (r.lane_sections[*k].s + s1)
                    });
                    net.lane_handle(id, lane, mid)
                }
                Some(h) => net
                    .successors(h)
                    .iter()
                    .copied()
                    .find(|n| n.section as usize == *k && net.handle_road(*n).id == *id),
            };
            let driving = road.driving_lanes(0.5 * (ps.0 + ps.1));
            let Some(h) = here.filter(|h| driving.contains(&h.lane)) else {
                break;
            };
            own.push((id, k, ps, h.lane));
            before = Some(h);
        }
        let (id, k, ps, l) = own.get(j).ok_or_else(|| {
            past(
                own.len(),
                &format!("the lanes along `{f}` (its lane {lane}, {how}, in the plan's first lane section, then in each after it the lane the one before leads into, while that is a driving lane)"),
            )
        })?;
        let why = format!(
            "lane {l} of the lane section of road {id} from s = {:.2} m, lane {j} along `{f}` ({how}, then its lanes' successor links)",
            net.road(id).map_or(0.0, |r| r.lane_sections[**k].s)
        );
        return Ok(Some((
            field.clone(),
            Bound::Lane(*l, (*id).clone(), **ps, why),
        )));
    }
    if which.against {
        sections.reverse();
    }
    let (way, side) = if which.against {
        ("-s", "lane 1")
    } else {
        ("+s", "lane -1")
    };
    let (id, k, ps) = match which.section {
        Some(k) => sections.get(k).ok_or_else(|| {
            past(
                sections.len(),
                &format!("the lane sections in {way} of {why} (in the order a driver in {way} meets them)"),
            )
        })?,
        // A lane section the runtime chooses: the one where its road starts.
        None => sections.first().ok_or_else(|| past(0, &format!("the lane sections of {why}")))?,
    };
    let why = format!(
        "the lane section of road {id} from s = {:.2} m{}, {why}",
        net.road(id).map_or(0.0, |r| r.lane_sections[*k].s),
        if which.against {
            " driven against s"
        } else {
            ""
        }
    );
    // Against s, the view of the plan's roads driven so: its u = L − s, the section's middle
    // (its ends are its neighbours' too).
    let view = if which.against {
        road.against().map_err(|m| along.site.err(K::Road, m))?
    } else {
        road.clone()
    };
    let at = if which.against {
        road.length() - 0.5 * (ps.0 + ps.1)
    } else {
        ps.0
    };
    let Some(j) = which.lane else {
        let lane = view.driving_lanes(at).first().copied();
        return Ok(Some((
            field.clone(),
            match lane {
                Some(l) if which.against => Bound::Against(l, *ps, why),
                Some(l) => Bound::Road(l, *ps, why),
                None => {
                    return Err(along.site.err(
                        K::Road,
                        format!(
                            "expected a driving lane in {way} in `{field}`, found none in {why}"
                        ),
                    ))
                }
            },
        )));
    };
    // The lanes flowing its way (right-hand traffic: the right side in +s, the left in -s),
    // from the centre out.
    let mut lanes: Vec<i32> = net
        .road(id)
        .map(|r| {
            let sec = &r.lane_sections[*k];
            let side = if which.against { &sec.left } else { &sec.right };
            side.iter().map(|l| l.id).collect()
        })
        .unwrap_or_default();
    lanes.sort_by_key(|l| l.abs());
    let lane = *lanes.get(j).ok_or_else(|| {
        past(
            lanes.len(),
            &format!(
                "the lanes of {why} (those flowing in {way}, from the centre out: {side} first)"
            ),
        )
    })?;
    if !view.driving_lanes(at).contains(&lane) {
        return Err(along.site.err(
            K::Road,
            format!("expected a driving lane as `{field}`, found lane {lane} of {why}, which no vehicle drives"),
        ));
    }
    let why = format!("lane {lane} of {why}");
    Ok(Some((
        field.clone(),
        Bound::Lane(lane, id.clone(), *ps, why),
    )))
}

/// Checks that a named route lies on a road of the plan, in one of its driving lanes (either
/// direction: an actor along a lane driven in −s drives against s, `crate::road`).
pub(crate) fn on_plan_road(road: &PlanRoad<'_>, along: &Along) -> Result<(), Error> {
    let Route::Lane {
        road: id,
        lane,
        s,
        then,
        ..
    } = &along.route
    else {
        return Ok(());
    };
    if !then.is_empty() {
        return path_on_plan_road(road, along);
    }
    let Some(at) = road.plan_s(id, 0.0) else {
        return Err(along.site.err(
            K::Road,
            format!(
                "expected every named route on the roads the plan drives on ({}: road {} and the roads the engine drives onto after it), found road {id}",
                road.ids().join(", "),
                road.id()
            ),
        ));
    };
    let (own, _) = road.road_at(at);
    if !(0.0..=own.length).contains(s) {
        return Err(along.site.err(
            K::Road,
            format!(
                "expected the route's start on road {id} (0 m to {:.1} m), found s = {s} m",
                own.length
            ),
        ));
    }
    let lanes = road.driving_lanes(at + s);
    // A lane of the left side is driven against s (`crate::road`); its start is on the view
    // of the roads driven so, whose u = L − s holds the same point.
    let back: Vec<i32> = own
        .lane_section_at(*s)
        .left
        .iter()
        .filter(|l| l.lane_type.is_drivable())
        .map(|l| l.id)
        .collect();
    if !lanes.contains(lane) && !back.contains(lane) {
        return Err(along.site.err(
            K::Road,
            format!("expected a driving lane of road {id} (right-hand traffic: lanes {lanes:?} driven in +s, {back:?} in -s) at s = {s} m, found lane {lane}"),
        ));
    }
    Ok(())
}

/// Checks that a route through points runs over the plan's roads: its roads (the network's
/// path through its points) are roads of the plan, one after another.
fn path_on_plan_road(road: &PlanRoad<'_>, along: &Along) -> Result<(), Error> {
    // Called for `Route::Lane` with points only.
    let Some(pts) = points(&along.route) else {
        return Ok(());
    };
    let net = road.network();
    let roads = crate::road::route_roads(net, &pts).map_err(|m| along.site.err(K::Road, m))?;
    let ids: Vec<String> = roads.iter().map(|&i| net.roads()[i].id.clone()).collect();
    let plan = road.ids();
    let consecutive = plan
        .iter()
        .position(|r| *r == ids[0])
        .is_some_and(|i| plan[i..].starts_with(&ids));
    if !consecutive {
        return Err(along.site.err(
            K::Road,
            format!(
                "expected every named route on the roads the plan drives on ({}), found a route over roads {}",
                plan.join(", "),
                ids.join(", ")
            ),
        ));
    }
    for (id, _, s) in &pts {
        let own = road.road_at(road.plan_s(id, 0.0).unwrap_or(0.0)).0;
        if !(0.0..=own.length).contains(s) {
            return Err(along.site.err(
                K::Road,
                format!(
                    "expected the route's point on road {id} (0 m to {:.1} m), found s = {s} m",
                    own.length
                ),
            ));
        }
    }
    Ok(())
}

/// The named routes of the tree (its `along(…)` modifiers on `Route::Lane`), in the order
/// they are written, each once.
pub(crate) fn named_routes(root: &Phase) -> Vec<Along> {
    let mut found: Vec<Along> = Vec::new();
    root.walk(&mut |p| {
        if let Kind::Invoke(inv) = &p.kind {
            for m in &inv.modifiers {
                if let (ModKind::Along, Some(a)) = (m.kind, &m.along) {
                    if matches!(a.route, Route::Lane { .. })
                        && !found.iter().any(|f| f.route == a.route)
                    {
                        found.push(a.clone());
                    }
                }
            }
        }
    });
    found
}

/// The points of a named route, its start first: road id, lane id and s of each.
pub(crate) fn points(route: &Route) -> Option<Vec<(String, i32, f64)>> {
    let Route::Lane {
        road,
        lane,
        s,
        then,
        ..
    } = route
    else {
        return None;
    };
    let mut all = vec![(road.clone(), *lane, *s)];
    all.extend(then.iter().map(|p| (p.road.clone(), p.lane, p.s)));
    Some(all)
}

/// A named route's points in the plan's s on the road view `road` (u along the direction of
/// travel on a view driven against s): each point's s, lane and offset from the lane's
/// centre to the left of the direction of travel (OpenDRIVE's t, turned on a view driven
/// against s). Points off the plan's roads are left out (`on_plan_road` refuses them).
pub(crate) fn plan_points(road: &PlanRoad<'_>, route: &Route) -> Vec<(f64, i32, f64)> {
    let Route::Lane {
        road: id,
        lane,
        s,
        t,
        then,
        ..
    } = route
    else {
        return Vec::new();
    };
    let turn = if road.is_against() { -1.0 } else { 1.0 };
    std::iter::once((id, *lane, *s, *t))
        .chain(then.iter().map(|p| (&p.road, p.lane, p.s, p.t)))
        .filter_map(|(id, lane, s, t)| road.plan_s(id, s).map(|at| (at, lane, turn * t)))
        .collect()
}

/// The lanes a route through `points` (`plan_points`) allows at the plan's s `s`: the lane of
/// the stretch between two points that holds s, both lanes where they differ (the actor
/// changes lanes there), within `ROUTE_TOLERANCE` of each end.
fn lanes_at(points: &[(f64, i32, f64)], s: f64) -> Vec<i32> {
    let (Some(first), Some(last)) = (points.first(), points.last()) else {
        return Vec::new();
    };
    let mut lanes = Vec::new();
    if s <= first.0 + ROUTE_TOLERANCE {
        lanes.push(first.1);
    }
    if s >= last.0 - ROUTE_TOLERANCE {
        lanes.push(last.1);
    }
    for w in points.windows(2) {
        if (w[0].0 - ROUTE_TOLERANCE..=w[1].0 + ROUTE_TOLERANCE).contains(&s) {
            lanes.push(w[0].1);
            lanes.push(w[1].1);
        }
    }
    lanes
}

/// The crossing of a route the map makes across one (`create_route([a, b], connect_points_by:
/// crossing)`, §8.12 `connect_route_points`): the crosswalk of the map that holds the straight
/// line from a's lane centre at its s to b's at its s (`map_crossings::crossing`, starting at
/// a's s at the angle that line makes with the lane's direction), as `crossing_connects`
/// binds one; `None` for another route. Errors at `along`: a road off the plan, lanes not in
/// one lane section, no crosswalk holding the line.
pub(crate) fn made_crossing(
    road: &PlanRoad<'_>,
    along: &Along,
) -> Result<Option<MapCrossing>, Error> {
    let Route::Crossing {
        field,
        points: Some(pts),
    } = &along.route
    else {
        return Ok(None);
    };
    let net = road.network();
    let describe = format!(
        "lane {} at s = {} m to lane {} at s = {} m of road {}",
        pts.start.0, pts.start.1, pts.end.0, pts.end.1, pts.road
    );
    let (Some(index), Some(road_start)) = (
        net.roads().iter().position(|r| r.id == pts.road),
        road.plan_s(&pts.road, 0.0),
    ) else {
        return Err(along.site.err(
            K::Road,
            format!(
                "expected the route across a crossing on a road the plan drives on ({}), found road {}",
                road.ids().join(", "),
                pts.road
            ),
        ));
    };
    let own = &net.roads()[index];
    let handle = |(lane, s): (i32, f64)| opendrive::LaneHandle {
        road: index as u32,
        section: own.lane_section_index(s) as u32,
        lane,
    };
    // The line's angle to the lane's direction, from the lanes' centres at the start.
    let centre = |lane: i32, s: f64| own.lane_span(lane, s).ok().map(|sp| sp.center());
    let dt = match (
        centre(pts.start.0, pts.start.1),
        centre(pts.end.0, pts.start.1),
    ) {
        (Some(a), Some(b)) => (b - a).abs(),
        _ => 0.0,
    };
    let angle = dt.atan2(pts.end.1 - pts.start.1);
    let found = crossing(
        net,
        handle(pts.start),
        handle(pts.end),
        Some(pts.start.1),
        (angle > 0.0).then_some(angle),
    )
    .filter(|c| (c.end.1 - pts.end.1).abs() <= POSITION_TOLERANCE);
    let Some(c) = found else {
        return Err(along.site.err(
            K::Road,
            format!("expected a crosswalk of the map holding the straight line from {describe} in one lane section (connect_points_by: crossing), found none"),
        ));
    };
    Ok(Some(MapCrossing {
        field: field.clone(),
        why: format!(
            "crosswalk {} of road {} the route crosses by",
            c.object, pts.road
        ),
        road_start,
        crossing: c,
    }))
}

/// Places the route points given in world coordinates (`create_xyz_point`,
/// `xyz_to_route_point`), or by t from a road's reference line (`odr_to_route_point` without
/// `lane_id`), of `resolved`'s routes (its `along(…)` modifiers and the map's
/// modifiers) on the network `net`, before anything is planned: the road, lane, s and offset
/// from the lane's centre of the road surface that holds (x, y) (`RoadNetwork::locate`), so
/// the route is that of the odr points there. A point on no road, and a route whose points so
/// placed are in lanes driven opposite ways, are errors at `along` (at the map's modifier).
pub(crate) fn locate_points(
    resolved: &mut crate::resolve::Resolved,
    net: &opendrive::RoadNetwork,
) -> Result<(), Error> {
    fn walk(p: &mut Phase, net: &opendrive::RoadNetwork) -> Result<(), Error> {
        if let Kind::Invoke(inv) = &mut p.kind {
            for m in &mut inv.modifiers {
                if let Some(a) = &mut m.along {
                    locate_route(&mut a.route, net, &a.site)?;
                }
            }
        }
        for c in &mut p.children {
            walk(c, net)?;
        }
        Ok(())
    }
    walk(&mut resolved.root, net)?;
    for m in &mut resolved.map {
        let site = m.site.clone();
        match &mut m.kind {
            crate::resolve::MapKind::NamedInSequence {
                preceding,
                succeeding,
            } => {
                locate_route(preceding, net, &site)?;
                locate_route(succeeding, net, &site)?;
            }
            crate::resolve::MapKind::RoutesInSequence {
                preceding,
                succeeding,
            } => {
                for end in [preceding, succeeding] {
                    if let Some(r) = &mut end.made {
                        locate_route(r, net, &site)?;
                    }
                }
            }
            _ => {}
        }
    }
    Ok(())
}

/// `locate_points` for one route, its errors at `site`.
pub(super) fn locate_route(
    route: &mut Route,
    net: &opendrive::RoadNetwork,
    site: &crate::error::Site,
) -> Result<(), Error> {
    let Route::Lane {
        road,
        lane,
        s,
        t,
        xyz,
        then,
        on,
    } = route
    else {
        return Ok(());
    };
    let place = |(x, y): (f64, f64)| {
        net.locate(x, y, None)
            .filter(|p| on_surface(net, p))
            .ok_or_else(|| {
                site.err(
                    K::Road,
                    format!("expected a point on a road of the network for the route's point at x = {x} m, y = {y} m (§8.12.2.1: \"if the point is not on a route, returns with an error\"), found none"),
                )
            })
    };
    // A point whose t is from the reference line (odr_to_route_point without lane_id, lane
    // 0): the lane of its road whose borders hold t there, t then from that lane's centre.
    let lane_of = |id: &str, s: f64, t: f64| -> Result<(i32, f64), Error> {
        let mut found = None;
        if let Some(r) = net.roads().iter().find(|r| r.id == id) {
            let _ = r.lane_spans(s, |l, sp| {
                let (lo, hi) = (sp.inner.min(sp.outer), sp.inner.max(sp.outer));
                if l.id != 0 && found.is_none() && (lo..=hi).contains(&t) && hi > lo {
                    found = Some((l.id, t - sp.center()));
                }
            });
        }
        found.ok_or_else(|| {
            site.err(
                K::Road,
                format!("expected a lane of road {id} holding t = {t} m (from its reference line) at s = {s} m for the route's point, found none"),
            )
        })
    };
    if let Some(at) = xyz.take() {
        let p = place(at)?;
        (*road, *lane, *s, *t) = (p.road_id, p.lane_id, p.s, p.offset);
    } else if *lane == 0 {
        (*lane, *t) = lane_of(road, *s, *t)?;
    }
    for w in then.iter_mut() {
        if let Some(at) = w.xyz.take() {
            let p = place(at)?;
            (w.road, w.lane, w.s, w.t) = (p.road_id, p.lane_id, p.s, p.offset);
        } else if w.lane == 0 {
            (w.lane, w.t) = lane_of(&w.road, w.s, w.t)?;
        }
    }
    if let Some(w) = then.iter().find(|w| (w.lane > 0) != (*lane > 0)) {
        return Err(site.err(K::Road, crate::resolve::one_way(*lane, w.lane)));
    }
    if let Some((d, dt)) = on.take() {
        let length = net.roads().iter().find(|r| r.id == *road).map(|r| r.length);
        (*s, *lane, *t) = point_on_route((road, *lane, *s), then, (d, dt), length, site)?;
    }
    Ok(())
}

/// Whether the network's look-up `p` is on its road's surface: within its lane's borders
/// (the network gives the outermost lane of the nearest road for a point beside every road).
pub(super) fn on_surface(net: &opendrive::RoadNetwork, p: &opendrive::RoadPosition) -> bool {
    net.road(&p.road_id)
        .and_then(|r| r.lane_span(p.lane_id, p.s).ok())
        .is_some_and(|sp| {
            let (lo, hi) = (sp.inner.min(sp.outer), sp.inner.max(sp.outer));
            (lo - POSITION_TOLERANCE..=hi + POSITION_TOLERANCE).contains(&p.t)
        })
}

/// The point `d` m along a route from its first point (`road`, `lane`, `s0`; its later points
/// `then`) and `dt` m from its line (`create_route_point(route, d, dt)`): on the first point's
/// road, in its lane's driving direction (right-hand traffic: +s for a negative id), in the
/// lane of the route's last point at or before it there (the points before it are dropped from
/// `then`, the route running from the point on): its s, lane and t. oscsim's choice: the
/// point is placed on the route's first road (`length` m long, `None` for a road the network
/// lacks); a point beyond it, or beyond the route's last point, is an error at `along`.
fn point_on_route(
    (road, lane, s0): (&str, i32, f64),
    then: &mut Vec<crate::resolve::Waypoint>,
    (d, dt): (f64, f64),
    length: Option<f64>,
    site: &crate::error::Site,
) -> Result<(f64, i32, f64), Error> {
    let dir = if lane > 0 { -1.0 } else { 1.0 };
    let at = s0 + dir * d;
    if !length.is_some_and(|l| (0.0..=l).contains(&at)) {
        return Err(site.err(
            K::Road,
            format!("expected the route point {d} m along the route on its first road (road {road}, from s = {s0} m in lane {lane}), found s = {at} m, off that road (oscsim places a route point on the route's first road)"),
        ));
    }
    let passed = |w: &crate::resolve::Waypoint| w.road == road && dir * (w.s - at) <= 0.0;
    if let Some(last) = then.last().filter(|w| passed(w) && dir * (w.s - at) < 0.0) {
        return Err(site.err(
            K::Road,
            format!("expected the route point {d} m along the route before its last point (road {}, s = {} m), found s = {at} m, past it", last.road, last.s),
        ));
    }
    let lane_here = then
        .iter()
        .take_while(|w| passed(w))
        .last()
        .map_or(lane, |w| w.lane);
    then.retain(|w| !passed(w));
    Ok((at, lane_here, dt))
}
