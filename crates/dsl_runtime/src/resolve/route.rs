//! Routes of the `along(route, start_offset, end_offset)` modifier (ASAM OpenSCENARIO DSL 2.1
//! §8.9 movement modifiers, `along`; §8.12 road abstraction: `route`, `road`, `lane`, the map's
//! `create_odr_point`) resolved on the plan's road.
//!
//! The constraint solver leaves every road-network value to the runtime (a constraint over a
//! route is a check error), so a route reaches the planner in one of these forms:
//!
//! - **a route field given a value** at its declaration (`r: route = m.create_route(…)`,
//!   `var r: route = m.create_odr_point(…)`, or another route field): that value's route (the
//!   solver leaves the value to the runtime, as the field).
//! - **a route field nothing defines** (`r: route`, `r: road`, `r: lane`): the scenario leaves
//!   the route to the runtime. The planner binds it to the plan road, driven in +s: a `route`,
//!   `road`, `lane_section` or `compound_route` is the whole road (actors along it may change
//!   lanes), a `lane` or `compound_lane` one lane of it (actors along it keep that lane, and all
//!   actors along the same field share it). Its ends are where the actors drive, so offsets from
//!   them are not defined: a non-zero `start_offset`/`end_offset` is an error.
//! - **`m.create_odr_point(road_id, lane_id, s, t)`** (or `m.odr_to_route_point(…)`, the
//!   same point as a route point, §8.12.2.1.1) on a `map` field: lane `lane_id` of
//!   OpenDRIVE road `road_id` from `s` to the road's end, `t` from the lane's centre line
//!   (§8.12.2.1: "measured from the ASAM OpenDRIVE lane centerline of the lane"). The plan
//!   drives on that road; an actor along it is placed (its first phase, without
//!   `position`/`lane` at start) at `s + start_offset` in that lane, `t` off its centre, and
//!   must be in that lane between `s + start_offset` and the road's end minus `end_offset` at
//!   the phase start and at its end.
//!
//! - **`m.create_xyz_point(x, y, z)`**, **`m.xyz_to_route_point(x, y, z)`**: a point in world
//!   coordinates, placed on the network's roads before the plan (`crate::plan`'s
//!   `locate_points`), then as the odr point there.
//!
//! - **`m.create_route([p, q, …])`** of odr points (`m.create_odr_point(…)`, in lanes driven
//!   one way) and routes made the same way: from the first point to the last, over the roads
//!   of the network's shortest lane path through the points (`crate::road::route_roads`), so
//!   through a junction by the connection the points say; between two points in other lanes
//!   or at other `t` the actor changes lanes (its offset), `crate::plan`'s `route_moves`.
//!   Placement and checks as for one point, the end being the last point.
//!
//! - **`m.create_route_point(route, s, t)`** of a route made as above: the part of that route
//!   from its point s m along it (from its first point) and t m from its line (its lanes'
//!   centres), placed on the network before the plan (`crate::plan`'s `locate_points`); a
//!   route's **`start_point()`** (the route) and **`end_point()`** (the route from its last
//!   point), and **`m.route_point_to_xyz(p)`** (p's route): a point as a route is the route
//!   from it on.
//!
//! - **`m.routes[i]`**, **`m.junctions[i].roads[j]`**: on an OpenDRIVE map one route per road
//!   of the file, in its order, so the road at index i; a junction's roads its connecting
//!   roads (`MapRoad`); the plan binds it as a road the map's modifiers bind.
//!
//! - **`cr.route_elements[i]`**, **`rd.s_positive[i]`**, **`rd.s_negative[i]`**,
//!   **`ls.lanes[i]`** (§8.12's lists): a compound route's element i is the route given to
//!   `create_route` at i (of one the runtime chooses, the plan's road i); a road's lane section
//!   i in +s (in -s, driven against s) and a lane section's lane i (those flowing its way, from
//!   the centre out) are bound by the plan (`MapRoute`) as a lane section and a lane the map's
//!   modifiers bind. **`cl.lanes[i]`** of a compound lane nothing defines: the library
//!   declares `lanes: list of lane` in no order the runtime could bind, so oscsim's choice is
//!   the one of `ls.lanes[i]`, the lanes of the lane section where `cl`'s road starts (the
//!   road the map's modifiers bind `cl` to, else the plan's roads), flowing in +s from the
//!   centre out.
//!
//! - **a `crossing` field** the map's `crossing_connects` binds to a crosswalk of the map: a
//!   person walking along it crosses from its start lane to its end lane (`crate::plan`),
//!   from `start_offset` m after the crossing's start to `end_offset` m before its end; and
//!   **`m.create_route([a, b], connect_points_by: crossing)`**, two odr points in two lanes
//!   of one road joined across the crosswalk that holds the line between them, crossed the
//!   same way.
//!
//! A path (`map.create_path(…)`, `map.create_path_odr_points(…)`,
//! `map.create_path_route_points(…)`) is followed as `follow_path` follows one (`along_path`;
//! a path through points of the network is placed by the plan stage, `crate::plan`'s
//! `road_path`). Everything else (other list elements, other map methods) is an error naming
//! the argument.

use dsl::semantics::hir::{Expr, ExprKind};
use dsl::Value;

use super::eval::{bind, bound_to, Eval as Ctx};
use super::value::{arg, Args};
use crate::error::{Error, ErrorKind as K, Site};

/// What an `along(…)` route is.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Route {
    /// A route field the scenario leaves to the runtime: the plan road.
    Free {
        /// The field's path (`r`): actors along the same field share the route.
        field: String,
        /// A `lane`/`compound_lane`: one lane, kept.
        one_lane: bool,
        /// A road of the map's lists (`m.routes[i]`, `m.junctions[i].roads[j]`), or an element
        /// of the library's lists (`cr.route_elements[i]`, `rd.s_positive[i]`,
        /// `ls.lanes[i]`), bound by the plan (`crate::plan`) as a road (lane) the map's
        /// modifiers bind.
        map_route: Option<MapRoute>,
    },
    /// Lane `lane` of road `road` from s = `s`, `t` from the lane's centre: to the end of the
    /// plan's roads, or with `then`, over the roads of the network's shortest lane path
    /// through those points to the last one (`map.create_route`), changing lanes (or its
    /// offset in the lane) between two points in other lanes (at other offsets).
    Lane {
        /// OpenDRIVE road id.
        road: String,
        /// OpenDRIVE lane id.
        lane: i32,
        /// Where the route starts (m of s).
        s: f64,
        /// The start's offset from the lane's centre (m, OpenDRIVE t: + left of +s).
        t: f64,
        /// A start given in world coordinates (`create_xyz_point`, `xyz_to_route_point`):
        /// (x, y), placed on the network before the plan (`crate::plan`'s
        /// `locate_points`), which fills in `road`, `lane`, `s` and `t`.
        xyz: Option<(f64, f64)>,
        /// The route's later points in order (empty: a route from one point,
        /// `create_odr_point`).
        then: Vec<Waypoint>,
        /// A point on this route (`map.create_route_point(route, s, t)`): s m along it from
        /// its first point and t m from its line (its lane's centre, + left of +s); the route
        /// is then the part from that point on, placed on the network before the plan
        /// (`crate::plan`'s `locate_points`), which fills in `road`, `lane`, `s` and `t`.
        on: Option<(f64, f64)>,
    },
    /// A `crossing` field the map's `crossing_connects` binds to a crosswalk of the map: a
    /// person walks it from its start lane to its end lane.
    Crossing {
        /// The field's path (for a route the map makes across a crossing, its place).
        field: String,
        /// The route's two points, for `map.create_route([a, b], connect_points_by:
        /// crossing)` (`None`: a field `crossing_connects` binds).
        points: Option<Box<CrossingPoints>>,
    },
}

/// A road of the map's lists (§8.12 `map.routes: list of route`, `map.junctions: list of
/// junction`, `junction.roads: list of road`), on an OpenDRIVE map (oscsim's choice, the
/// standard saying nothing of a map loaded from a file): one route per road of the file in
/// its order, one junction per junction of the file in its order, and a junction's roads its
/// connecting roads in the order its connections first name them; or a road of the plan (the
/// elements of a compound route the runtime chooses).
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum MapRoad {
    /// `m.routes[i]`: the road at index i of the file.
    Route(usize),
    /// `m.junctions[i].roads[j]`: connecting road j of junction i.
    Junction(usize, usize),
    /// `cr.route_elements[i]` of a compound route field nothing defines (the plan's roads):
    /// the plan's road i.
    Plan(usize),
    /// A route field nothing defines (`rd: road`, `ls: lane_section`) whose list elements are
    /// read: the road (lane section) the map's modifiers bind it to, else the plan's roads.
    Field(String),
}

/// An element of the library's lists as `along`'s route (§8.12 `road.s_positive: list of
/// lane_section`, "elements that flow in the positive direction of the road s-axis",
/// `road.s_negative`, those "that flow in the negative direction"; `lane_section.lanes: list
/// of lane`, "lanes that compose the lane_section"): a road (`road`), its lane section
/// `section` in +s (its lane sections in order along s) or, `against`, in -s (in the order a
/// driver against s meets them, from the road's end), and the lane `lane` of that section
/// (oscsim's choice: the lanes that flow its way, under right-hand traffic the right side in +s
/// and the left side in -s, from the centre out: `lanes[0]` is lane -1, or lane 1).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct MapRoute {
    /// The road.
    pub road: MapRoad,
    /// `s_positive[i]` (`s_negative[i]`): the road's lane section i in +s (in -s).
    pub section: Option<usize>,
    /// The section flows in -s (`s_negative`): driven against s.
    pub against: bool,
    /// `lanes[i]`: the section's lane i from the centre out; of a compound lane
    /// (`compound`), its lane i along it.
    pub lane: Option<usize>,
    /// `cl.lanes[i]` of a compound lane nothing defines: the lanes it is made of, one per lane
    /// section of the plan's roads in order along s, each the compound lane's own lane there
    /// (`crate::plan`'s `route::map_route`).
    pub compound: bool,
}

/// The two points of a route the map makes across a crossing (`create_route([a, b],
/// connect_points_by: crossing)`): one road, a start and an end lane, each with its s.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct CrossingPoints {
    /// OpenDRIVE road id.
    pub road: String,
    /// The start: lane id and s (m).
    pub start: (i32, f64),
    /// The end: lane id and s (m).
    pub end: (i32, f64),
}

/// A later point of a route through points (`map.create_route`): an odr point.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Waypoint {
    /// OpenDRIVE road id.
    pub road: String,
    /// OpenDRIVE lane id.
    pub lane: i32,
    /// s (m).
    pub s: f64,
    /// Offset from the lane's centre (m, OpenDRIVE t: + left of +s).
    pub t: f64,
    /// Given in world coordinates: (x, y), placed on the network before the plan.
    pub xyz: Option<(f64, f64)>,
}

/// An `along(…)` application, read.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Along {
    /// The route.
    pub route: Route,
    /// Distance from the route's start where the movement starts (m).
    pub start_offset: f64,
    /// Distance before the route's end the movement stays within (m).
    pub end_offset: f64,
    /// The application.
    pub site: Site,
}

/// Route types bound to the whole plan road.
pub(crate) const WHOLE_ROAD: [&str; 5] = [
    "route",
    "route_element",
    "road",
    "lane_section",
    "compound_route",
];
/// Route types bound to one lane.
pub(crate) const ONE_LANE: [&str; 2] = ["lane", "compound_lane"];

/// Reads the route and offsets of an `along(…)` modifier (its evaluated arguments `args`, the
/// route expression and where the application is written).
pub(crate) fn read(
    ctx: &Ctx<'_>,
    args: &Args,
    route: Option<&Expr>,
    site: &Site,
) -> Result<Along, Error> {
    let offset = |name: &str| -> Result<f64, Error> {
        match arg(args, name) {
            None => Ok(0.0),
            Some(e) => {
                let x = e.number()?;
                if x < 0.0 {
                    return Err(e.site.err(
                        K::Value,
                        format!("expected a {name} of 0 m or more, found {x} m"),
                    ));
                }
                Ok(x)
            }
        }
    };
    let start_offset = offset("start_offset")?;
    let end_offset = offset("end_offset")?;
    let Some(e) = route else {
        return Err(site.err(K::Modifier, "expected a route in along(…), found none"));
    };
    let route = route_of(ctx, e)?;
    let fixed_ends = match &route {
        Route::Free { field, map_route: None, .. } => Some((field, "a route the runtime chooses (its ends are where the actors drive)", "; name the route with map.create_odr_point(road_id, lane_id, s, t) to drive from a given place")),
        Route::Free { field, .. } => Some((field, "a road of the map (the actors drive it from its start, or where they are on it)", "; name a point on it with map.create_odr_point(road_id, lane_id, s, t) to drive from a given place")),
        // A crossing's offsets trim the walk along it (`plan::crossing_walk`).
        Route::Crossing { .. } | Route::Lane { .. } => None,
    };
    if let Some((field, what, hint)) = fixed_ends {
        for (name, x) in [("start_offset", start_offset), ("end_offset", end_offset)] {
            if x != 0.0 {
                let at = arg(args, name).map_or(site, |a| &a.site);
                return Err(at.err(
                    K::Unsatisfiable,
                    format!("expected no {name} on `{field}`, {what}, found {x} m{hint}"),
                ));
            }
        }
    }
    Ok(Along {
        route,
        start_offset,
        end_offset,
        site: site.clone(),
    })
}

/// The route `e` names.
pub(super) fn route_of(ctx: &Ctx<'_>, e: &Expr) -> Result<Route, Error> {
    route_within(ctx, e, 0)
}

/// The value a route field is given at its declaration (`r: route = m.create_route(…)`,
/// `var r: route = …`), with the reader of the instance that declares it (whose names the
/// value uses): the field is that route. `None`: a field nothing defines.
pub(crate) fn field_value<'a>(ctx: &Ctx<'a>, path: &str) -> Option<(&'a Expr, Ctx<'a>)> {
    let (field, owner) = field_def(ctx, path)?;
    Some((field.default.as_ref()?, owner))
}

/// The declaration of the field at `path` (its value, its `with:` keeps), with the reader of
/// the instance that declares it (whose names they use); `None` for no field of the program.
pub(crate) fn field_def<'a>(
    ctx: &Ctx<'a>,
    path: &str,
) -> Option<(&'a dsl::semantics::model::FieldDef, Ctx<'a>)> {
    let (owner, name) = match path.rsplit_once('.') {
        Some((o, n)) => (o, n),
        None => ("", path),
    };
    let field = if ctx.res.get(&format!("{}.{path}", ctx.root)).is_some() {
        // A field of the scenario's instance (or of an instance in it).
        let instance = if owner.is_empty() {
            ctx.res.get(&ctx.root)
        } else {
            ctx.lookup(owner).map(|(_, v)| v)
        }?;
        // A scenario's type is no entry of the model's type names: found by its name, the
        // program's own before a library type of the same name (a scenario
        // `relative_path_st`): the library's come first.
        let Value::Compound { ty: name_of, .. } = instance else {
            return None;
        };
        let ty = (0..ctx.model.compounds.len() as u32)
            .map(dsl::semantics::types::CompoundId)
            .rev()
            .find(|c| ctx.model.compound(*c).name == *name_of)?;
        ctx.model
            .all_fields(ty)
            .into_iter()
            .rev()
            .find(|f| f.name == name)?
    } else {
        // A global field (top level).
        ctx.model.globals.iter().find(|g| g.name == path)?
    };
    let prefix = if owner.is_empty() {
        String::new()
    } else {
        format!("{owner}.")
    };
    // The reader's own frame where the field is its own (keeping its parameters' aliases).
    let frame = if prefix == ctx.frame.prefix {
        ctx.frame.clone()
    } else {
        super::eval::Frame {
            prefix,
            ..Default::default()
        }
    };
    Some((field, ctx.enter(frame)))
}

/// The route of the field at `path` when it is given a value at its declaration (`None`: a
/// field nothing defines); a value naming another field is that field's route (a free field
/// stays free: `c: route = b` shares `b`).
pub(crate) fn valued_route(ctx: &Ctx<'_>, path: &str) -> Option<Result<Route, Error>> {
    let (value, owner) = field_value(ctx, path)?;
    Some(route_within(&owner, value, 1))
}

/// Route fields given a value may name one another; deeper than this is a cycle.
const MAX_FIELD_DEPTH: usize = 16;

/// The route `e` names, `depth` fields deep.
fn route_within(ctx: &Ctx<'_>, e: &Expr, depth: usize) -> Result<Route, Error> {
    let unsupported = |what: &str| {
        ctx.files.err(
            K::Unsupported,
            e.span,
            format!("expected a route field nothing constrains (r: route, road or lane), map.create_odr_point(road_id, lane_id, s, t), map.odr_to_route_point(…) or map.create_route(…) in along(…), found {what}"),
        )
    };
    // A road of the map's lists, an element of the library's other lists.
    if let ExprKind::Index(list, at) = &e.kind {
        if let Some(junction) = map_road(ctx, list) {
            return map_road_route(ctx, e, junction, at);
        }
        if let ExprKind::Field(base, name) = &list.kind {
            if let Some(r) = list_element(ctx, e, (base, &name.text), at, depth) {
                return r;
            }
        }
    }
    match &e.kind {
        ExprKind::Call(callee, args) => {
            let ExprKind::Field(obj, method) = &callee.kind else {
                return Err(unsupported("a call of a function"));
            };
            let on_map = ctx
                .path_of(obj)
                .and_then(|p| ctx.lookup(&p))
                .is_some_and(|(_, v)| matches!(v, Value::RunTime(t) if is_a(ctx, t, "map")));
            if !on_map {
                if let "start_point" | "end_point" = method.text.as_str() {
                    return end_point(ctx, obj, method.text == "end_point", depth);
                }
                return Err(unsupported(&format!(
                    "`{}` called on something other than a map field",
                    method.text
                )));
            }
            let mut points = Vec::new();
            match method.text.as_str() {
                // The world position of a route point (§8.12.2.1): the same place.
                "route_point_to_xyz" => {
                    let params = ["route_point".to_string()];
                    let Some((_, p)) = bind(args, &params).into_iter().next() else {
                        return Err(ctx.files.err(
                            K::Value,
                            e.span,
                            "expected `route_point` in route_point_to_xyz(…), found none",
                        ));
                    };
                    return route_within(ctx, p, depth + 1);
                }
                // odr_to_route_point (§8.12.2.1.1) names the same point as a route point.
                "create_odr_point" => points.push(route_start(ctx, e, args, false)?),
                "odr_to_route_point" => points.push(route_start(ctx, e, args, true)?),
                "create_xyz_point" | "xyz_to_route_point" => points.push(xyz_point(ctx, e, args)?),
                "create_route" => {
                    if route_points(ctx, e, args, &mut points, depth)? {
                        return crossing_route(ctx, e, points);
                    }
                }
                "create_route_point" => return route_point(ctx, e, args, depth),
                other => return Err(unsupported(&format!("map.{other}(…)"))),
            }
            // Both calls give at least one point.
            let first = points.remove(0);
            // A route's points are on lanes driven one way (points in world coordinates are
            // checked once placed on the network, `crate::plan`'s `locate_points`).
            let placed = |p: &RoutePoint| p.xyz.is_none() && p.lane != 0;
            if placed(&first) {
                if let Some(p) = points
                    .iter()
                    .find(|p| placed(p) && (p.lane > 0) != (first.lane > 0))
                {
                    return Err(ctx.files.err(K::Road, p.span, one_way(first.lane, p.lane)));
                }
            }
            Ok(Route::Lane {
                road: first.road,
                lane: first.lane,
                s: first.s,
                t: first.t,
                xyz: first.xyz,
                then: points
                    .into_iter()
                    .map(|p| Waypoint {
                        road: p.road,
                        lane: p.lane,
                        s: p.s,
                        t: p.t,
                        xyz: p.xyz,
                    })
                    .collect(),
                on: None,
            })
        }
        ExprKind::Name(_) | ExprKind::Field(..) | ExprKind::Index(..) => {
            let path = ctx.path_of(e).ok_or_else(|| unsupported("an expression"))?;
            // A field given a value at its declaration is that value's route.
            if let Some((value, owner)) = ctx.lookup(&path).and_then(|(p, _)| field_value(ctx, &p))
            {
                if depth >= MAX_FIELD_DEPTH {
                    return Err(ctx.files.err(
                        K::Value,
                        e.span,
                        format!("expected route fields whose values end in a route the map makes, found `{path}` defined through itself"),
                    ));
                }
                return route_within(&owner, value, depth + 1);
            }
            match ctx.lookup(&path) {
                Some((_, Value::RunTime(ty))) => {
                    if is_a(ctx, ty, "crossing") {
                        Ok(Route::Crossing {
                            field: path,
                            points: None,
                        })
                    } else if WHOLE_ROAD.iter().any(|t| is_exactly_or_user(ctx, ty, t)) {
                        Ok(Route::Free {
                            field: path,
                            one_lane: false,
                            map_route: None,
                        })
                    } else if ONE_LANE.iter().any(|t| is_a(ctx, ty, t)) {
                        Ok(Route::Free {
                            field: path,
                            one_lane: true,
                            map_route: None,
                        })
                    } else if is_a(ctx, ty, "path") {
                        // A path given by the map is followed (`along_path`); one nothing
                        // defines has no points: bad input.
                        Err(ctx.files.err(
                            K::Value,
                            e.span,
                            format!("expected a path with points in along(…) (`{path}: path = map.create_path(points: [...], interpolation: ...)`), found `{path}`, a path nothing defines (no points to follow)"),
                        ))
                    } else {
                        Err(unsupported(&format!(
                            "`{path}`, a {ty} (not run as a route)"
                        )))
                    }
                }
                _ => Err(unsupported(&format!("`{path}`"))),
            }
        }
        _ => Err(unsupported("an expression")),
    }
}

/// The route of `r.start_point()` or `r.end_point()` (§8.12 `route`: "start_point() ->
/// route_point", "end_point() -> route_point") as `along`'s route, `r` written at `obj`,
/// `depth` fields deep: a point as a route is the route from it on (`create_route_point`), so
/// the start point of a route the map makes is that route, its end point the route from its
/// last point (over the roads the engine drives onto after it). A route the runtime chooses, a
/// crossing, and the end of a route from one point are not known before the plan: errors at
/// `r`.
fn end_point(ctx: &Ctx<'_>, obj: &Expr, end: bool, depth: usize) -> Result<Route, Error> {
    let which = if end { "end_point" } else { "start_point" };
    let wrong = |found: &str| {
        ctx.files.err(
            K::Value,
            obj.span,
            format!("expected a route the map makes through points (map.create_route(…), …) before .{which}() in along(…), found {found}"),
        )
    };
    match route_within(ctx, obj, depth + 1)? {
        // The start of a route, and either end of a point, is where the route already starts.
        r @ Route::Lane { on: Some(_), .. } => Ok(r),
        r @ Route::Lane { .. } if !end => Ok(r),
        Route::Lane { mut then, .. } => match then.pop() {
            Some(last) => Ok(Route::Lane {
                road: last.road,
                lane: last.lane,
                s: last.s,
                t: last.t,
                xyz: last.xyz,
                then: Vec::new(),
                on: None,
            }),
            None => Err(wrong("a route from one point (it runs on over the roads the engine drives onto: its end is not known before the plan)")),
        },
        _ => Err(wrong("a route the runtime chooses or a crossing (its ends are not known before the plan)")),
    }
}

/// The route of `map.create_route_point(route, s, t)` (its call `e`, arguments `args`, `depth`
/// fields deep) as `along`'s route (§8.12 `route_point`, a route element: "s" along the route,
/// "t" across it): the part of `route` from its point s m along it from its first point, t m
/// from its line, a route the map makes (`create_odr_point`, `create_route`, …; oscsim's
/// choice: its line is its lanes' centres, as an odr point's t is measured from its lane's
/// centre). A route the runtime chooses (`r: route` nothing defines) has no first point to
/// measure s from before the plan (its roads are the plan's): an error at the argument, as are
/// a negative s and a point on a point already (`create_route_point` of a route point).
fn route_point(
    ctx: &Ctx<'_>,
    e: &Expr,
    args: &[dsl::semantics::hir::Arg],
    depth: usize,
) -> Result<Route, Error> {
    let params = ["route", "s", "t"].map(String::from);
    let bound = bind(args, &params);
    let get = |n: &str| bound_to(&bound, n);
    let Some(r) = get("route") else {
        return Err(ctx.files.err(
            K::Value,
            e.span,
            "expected `route` in create_route_point(route, s, t), found none",
        ));
    };
    let s = get("s").map(|a| ctx.number(a)).transpose()?.unwrap_or(0.0);
    if s < 0.0 {
        return Err(ctx.files.err(
            K::Value,
            get("s").map_or(e.span, |a| a.span),
            format!("expected an s of 0 m or more along the route in create_route_point(…), found {s} m"),
        ));
    }
    let t = get("t").map(|a| ctx.number(a)).transpose()?.unwrap_or(0.0);
    match route_within(ctx, r, depth + 1)? {
        Route::Lane {
            road,
            lane,
            s: s0,
            t: t0,
            xyz,
            then,
            on: None,
        } => Ok(Route::Lane {
            road,
            lane,
            s: s0,
            t: t0,
            xyz,
            then,
            on: Some((s, t)),
        }),
        Route::Lane { .. } => Err(ctx.files.err(
            K::Value,
            r.span,
            "expected a route in create_route_point(route, s, t), found a route point (a point has no length to measure s along)",
        )),
        Route::Free { field, .. } => Err(ctx.files.err(
            K::Value,
            r.span,
            format!("expected a route the map makes (map.create_odr_point(…), map.create_route(…), …) in create_route_point(route, s, t) as along's route, found `{field}`, a route the runtime chooses (its start, which s is measured from, is where the actors drive: give its point as map.create_odr_point(road_id, lane_id, s, t))"),
        )),
        Route::Crossing { .. } => Err(ctx.files.err(
            K::Value,
            r.span,
            "expected a route over the lanes in create_route_point(route, s, t) as along's route, found a crossing (walked from its start lane to its end lane; along(c, start_offset: s) walks from s on)",
        )),
    }
}

/// A `lane` field named by the `target:` of `change_lane`/`follow_lane` (§8.8.3.2, §8.8.3.3):
/// the solver leaves it to the runtime, which binds it to a lane of the road network (by the
/// map's modifiers, by `along(…)`, or by a draw at its first use; `crate::plan`).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LaneField {
    /// The field's path (`l`): every use of one field is one lane.
    pub path: String,
    /// Where the argument is written.
    pub site: Site,
}

/// The lane field the argument `a` names (`target: l` with `l: lane`).
pub(crate) fn lane_field(ctx: &Ctx<'_>, a: &super::value::Arg) -> Result<LaneField, Error> {
    let ty = a
        .path
        .as_ref()
        .and_then(|p| ctx.lookup(p))
        .and_then(|(p, v)| match v {
            Value::RunTime(t) => Some((p, t.clone())),
            _ => None,
        });
    // A lane field whose value is another lane field is that field.
    let ty = match ty.as_ref().and_then(|(p, _)| valued_route(ctx, p)) {
        None => ty,
        Some(Ok(Route::Free {
            field,
            one_lane: true,
            ..
        })) => Some((field, "lane".to_string())),
        // No method of the map gives a lane (create_odr_point an odr_point, create_route a
        // compound_route): the checker refuses such a value for a lane field, so this is a
        // value it let through, an error at the argument.
        Some(Ok(_)) => {
            return Err(a.site.err(
                K::Argument,
                "expected a lane field nothing defines in target: (bound by the map's modifiers, along(…) or drawn at its first use), found a field given a route the map makes at its declaration (driven with along(…), not changed into)",
            ))
        }
        Some(Err(e)) => return Err(e),
    };
    match ty {
        Some((path, t)) if is_a(ctx, &t, "lane") => Ok(LaneField {
            path,
            site: a.site.clone(),
        }),
        _ => Err(a.site.err(
            K::Argument,
            "expected a lane field (l: lane, bound by the map's modifiers, along(l) or drawn at its first use) in target:, found another expression",
        )),
    }
}

/// What is wrong with a route from a point in lane `first` through one in lane `other`, driven
/// the other way: from a lane driven in +s into one driven in −s (right-hand traffic: the sign
/// of the id) the route turns about (the rest of a sentence "expected …").
pub(crate) fn one_way(first: i32, other: i32) -> String {
    format!("expected every point of a route in a lane driven the way lane {first} is (a legal route, §8.12.2.1 legal_route; right-hand traffic: {}), found lane {other}, driven the other way (a route from it would turn about, which no lane change does)", if first > 0 { "lanes of positive id driven in -s" } else { "lanes of negative id driven in +s" })
}

/// A point of a route, read, and where it is written.
struct RoutePoint {
    road: String,
    lane: i32,
    s: f64,
    t: f64,
    xyz: Option<(f64, f64)>,
    span: dsl::semantics::hir::Span,
}

/// The point of `map.create_xyz_point(x, y, z)` or `map.xyz_to_route_point(x, y, z)` (§8.12.2.1:
/// "takes a position in world coordinates and returns the corresponding ASAM OpenSCENARIO
/// route-coordinates"), as a route's point: where it is, placed on the network's roads before
/// the plan (`crate::plan`'s `locate_points`); z is not read (the roads give the height).
fn xyz_point(
    ctx: &Ctx<'_>,
    e: &Expr,
    args: &[dsl::semantics::hir::Arg],
) -> Result<RoutePoint, Error> {
    let params: Vec<String> = ["x", "y", "z"].iter().map(|s| s.to_string()).collect();
    let bound = bind(args, &params);
    let coord = |n: &str| -> Result<f64, Error> {
        match bound_to(&bound, n) {
            Some(a) => ctx.number(a),
            None => Err(ctx.files.err(
                K::Value,
                e.span,
                format!("expected `{n}` in the point's world coordinates, found none"),
            )),
        }
    };
    Ok(RoutePoint {
        road: String::new(),
        lane: 0,
        s: 0.0,
        t: 0.0,
        xyz: Some((coord("x")?, coord("y")?)),
        span: e.span,
    })
}

/// The point of `map.create_odr_point(…)` (its call `e`, arguments `args`) as a route's
/// point: `t` from the lane's centre line (§8.12.2.1: "the t-coordinate is measured from the
/// ASAM OpenDRIVE lane centerline of the lane"), which the route passes there.
fn route_start(
    ctx: &Ctx<'_>,
    e: &Expr,
    args: &[dsl::semantics::hir::Arg],
    lane_optional: bool,
) -> Result<RoutePoint, Error> {
    // odr_to_route_point's lane_id: "Optional. If omitted, the t-coordinate is measured from
    // the ASAM OpenDRIVE road reference line" (§8.12.2.1.1): lane 0 (the centre lane, on the
    // reference line), the lane that holds t found on the network before the plan
    // (`crate::plan`'s `locate_points`).
    let params = ["road_id", "lane_id", "s", "t"].map(String::from);
    let bound = bind(args, &params);
    let get = |n: &str| bound_to(&bound, n);
    // Not given, or given as the declaration's default "".
    let omitted = match get("lane_id") {
        None => true,
        Some(a) => matches!(&a.kind, ExprKind::Str(s) if s.is_empty()),
    };
    if lane_optional && omitted {
        let road = match get("road_id") {
            Some(a) => string(ctx, a)?,
            None => {
                return Err(ctx.files.err(
                    K::Value,
                    e.span,
                    "expected `road_id` in odr_to_route_point(…), found none",
                ))
            }
        };
        let number = |n: &str| get(n).map(|a| ctx.number(a)).transpose();
        return Ok(RoutePoint {
            road,
            lane: 0,
            s: number("s")?.unwrap_or(0.0),
            t: number("t")?.unwrap_or(0.0),
            xyz: None,
            span: e.span,
        });
    }
    let p = odr_point(ctx, e, args)?;
    Ok(RoutePoint {
        road: p.road,
        lane: p.lane,
        s: p.s,
        t: p.t,
        xyz: None,
        span: e.span,
    })
}

/// The points of `map.create_route(routes, connect_points_by, legal_route)` (ASAM OpenSCENARIO
/// DSL 2.1 §8.12.2.1), appended to `out` in order: each element of `routes` an odr point
/// (`map.create_odr_point(…)`) or a route made the same way (its points). The points are
/// joined by the network's shortest lane path in the driving direction (the `road` module):
/// `connect_points_by` `waypoint` (the default), `lane`, `lane_section` and `road` all give
/// that path (it runs in the points' lane over whole lane sections and roads); with `crossing`
/// the points are joined across a crossing of the map (`crossing_route`): `true`. A path in
/// the lanes' driving direction is a legal route, so `legal_route` holds either way.
fn route_points(
    ctx: &Ctx<'_>,
    e: &Expr,
    args: &[dsl::semantics::hir::Arg],
    out: &mut Vec<RoutePoint>,
    depth: usize,
) -> Result<bool, Error> {
    let params: Vec<String> = ["routes", "connect_points_by", "legal_route"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let bound = bind(args, &params);
    let arg = |n: &str| bound_to(&bound, n);
    if let Some(c) = arg("connect_points_by") {
        let member = match &c.kind {
            ExprKind::EnumValue(_, m) => Some(m.text.as_str()),
            ExprKind::Name(m) => Some(m.as_str()),
            _ => None,
        };
        if !matches!(
            member,
            Some("waypoint" | "lane" | "lane_section" | "road" | "crossing")
        ) {
            return Err(ctx.files.err(
                K::Value,
                c.span,
                "expected connect_points_by waypoint, lane, lane_section, road or crossing (§8.12 connect_route_points), found another value",
            ));
        }
    }
    let crossing = arg("connect_points_by").is_some_and(|c| match &c.kind {
        ExprKind::EnumValue(_, m) => m.text == "crossing",
        ExprKind::Name(m) => m == "crossing",
        _ => false,
    });
    let Some(list) = arg("routes") else {
        return Err(ctx.files.err(
            K::Value,
            e.span,
            "expected `routes` in create_route(…), found none",
        ));
    };
    let ExprKind::List(items) = &list.kind else {
        return Err(ctx.files.err(
            K::Value,
            list.span,
            "expected a list of odr points and routes ([m.create_odr_point(…), …]) in create_route(…), found another expression",
        ));
    };
    if items.is_empty() {
        return Err(ctx.files.err(
            K::Value,
            list.span,
            "expected at least one point in create_route(…), found an empty list",
        ));
    }
    for item in items {
        match map_call(ctx, item) {
            Some(("create_odr_point", a)) => out.push(route_start(ctx, item, a, false)?),
            Some(("odr_to_route_point", a)) => out.push(route_start(ctx, item, a, true)?),
            Some(("create_xyz_point" | "xyz_to_route_point", a)) => {
                out.push(xyz_point(ctx, item, a)?)
            }
            Some(("create_route", a)) => {
                if route_points(ctx, item, a, out, depth)? {
                    return Err(ctx.files.err(
                        K::Value,
                        item.span,
                        "expected odr points and routes over the lanes in create_route(…), found a route across a crossing (a crossing joins two points of its own)",
                    ));
                }
            }
            // Any other route made of points (a route field given one, a route's end point):
            // its points.
            _ => match route_within(ctx, item, depth + 1)? {
                Route::Lane {
                    road,
                    lane,
                    s,
                    t,
                    xyz,
                    then,
                    on: None,
                } => {
                    let span = item.span;
                    out.push(RoutePoint {
                        road,
                        lane,
                        s,
                        t,
                        xyz,
                        span,
                    });
                    out.extend(then.into_iter().map(|w| RoutePoint {
                        road: w.road,
                        lane: w.lane,
                        s: w.s,
                        t: w.t,
                        xyz: w.xyz,
                        span,
                    }));
                }
                _ => {
                    return Err(ctx.files.err(
                        K::Value,
                        item.span,
                        "expected an odr point (m.create_odr_point(…), m.odr_to_route_point(…)), a point in world coordinates (m.create_xyz_point(…), m.xyz_to_route_point(…)) or a route the map makes of such points (m.create_route(…), a field given one) in create_route(…), found a route the runtime chooses, a crossing, a path or a point on a route (no points of its own to join)",
                    ))
                }
            },
        }
    }
    Ok(crossing)
}

/// The route of `map.create_route([a, b], connect_points_by: crossing)` (its call `e`, its
/// points): §8.12's `connect_route_points` member `crossing` joins the points across a
/// crossing, so the two points must be on one road, in two lanes, at its lanes' centres (the
/// crossing runs "a straight line" from one lane's centre to the other's, as
/// `crossing_connects` says); the crosswalk of the map that holds the line is found by the
/// plan (`crate::plan`'s `map_crossings`).
fn crossing_route(ctx: &Ctx<'_>, e: &Expr, points: Vec<RoutePoint>) -> Result<Route, Error> {
    let wrong = |span, found: String| {
        ctx.files.err(
            K::Value,
            span,
            format!("expected two odr points on one road, in two lanes at their centres (t = 0 m), joined across a crossing (connect_points_by: crossing), found {found}"),
        )
    };
    let [a, b] = points.as_slice() else {
        return Err(wrong(e.span, format!("{} points", points.len())));
    };
    if b.road != a.road {
        return Err(wrong(b.span, format!("roads {} and {}", a.road, b.road)));
    }
    if b.lane == a.lane {
        return Err(wrong(b.span, format!("both in lane {}", a.lane)));
    }
    if let Some(p) = [a, b].into_iter().find(|p| p.t != 0.0) {
        return Err(wrong(p.span, format!("t = {} m", p.t)));
    }
    Ok(Route::Crossing {
        field: format!("the route across a crossing at {}", ctx.site(e.span).at()),
        points: Some(Box::new(CrossingPoints {
            road: a.road.clone(),
            start: (a.lane, a.s),
            end: (b.lane, b.s),
        })),
    })
}

/// A `map.create_odr_point(road_id, lane_id, s, t)` call, read.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct OdrPoint {
    /// OpenDRIVE road id.
    pub road: String,
    /// OpenDRIVE lane id.
    pub lane: i32,
    /// s (m).
    pub s: f64,
    /// t (m), from the lane's centre.
    pub t: f64,
    /// Where `t` is written (the call without one).
    pub t_span: dsl::semantics::hir::Span,
}

/// The arguments `args` of the call `e` of `map.create_odr_point(road_id, lane_id, s, t)`.
pub(crate) fn odr_point(
    ctx: &Ctx<'_>,
    e: &Expr,
    args: &[dsl::semantics::hir::Arg],
) -> Result<OdrPoint, Error> {
    let params: Vec<String> = ["road_id", "lane_id", "s", "t"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let bound = bind(args, &params);
    let arg = |n: &str| bound_to(&bound, n);
    let text = |n: &str| -> Result<String, Error> {
        let a = arg(n).ok_or_else(|| {
            ctx.files.err(
                K::Value,
                e.span,
                format!("expected `{n}` in create_odr_point(…), found none"),
            )
        })?;
        string(ctx, a)
    };
    let road = text("road_id")?;
    let lane_text = text("lane_id")?;
    let lane: i32 = lane_text.trim().parse().map_err(|_| {
        ctx.files.err(
            K::Value,
            arg("lane_id").map_or(e.span, |a| a.span),
            format!("expected an OpenDRIVE lane id (an integer) in lane_id, found {lane_text:?}"),
        )
    })?;
    let s = arg("s").map(|a| ctx.number(a)).transpose()?.unwrap_or(0.0);
    let t = arg("t").map(|a| ctx.number(a)).transpose()?.unwrap_or(0.0);
    Ok(OdrPoint {
        road,
        lane,
        s,
        t,
        t_span: arg("t").map_or(e.span, |a| a.span),
    })
}

/// Whether `e` is a call of a method of a `map` field: the method's name and arguments.
pub(crate) fn map_call<'e>(
    ctx: &Ctx<'_>,
    e: &'e Expr,
) -> Option<(&'e str, &'e [dsl::semantics::hir::Arg])> {
    let ExprKind::Call(callee, args) = &e.kind else {
        return None;
    };
    let ExprKind::Field(obj, method) = &callee.kind else {
        return None;
    };
    ctx.path_of(obj)
        .and_then(|p| ctx.lookup(&p))
        .is_some_and(|(_, v)| matches!(v, Value::RunTime(t) if is_a(ctx, t, "map")))
        .then_some((method.text.as_str(), args.as_slice()))
}

/// The route of `e`, an element of a list of the map's roads at index `at` (`m.routes[at]`, or
/// with `junction` `m.junctions[junction].roads[at]`).
fn map_road_route(
    ctx: &Ctx<'_>,
    e: &Expr,
    junction: Option<&Expr>,
    at: &Expr,
) -> Result<Route, Error> {
    let index = |at: &Expr, what: &str| index(ctx, at, what);
    let road = match junction {
        None => MapRoad::Route(index(at, "the map's routes")?),
        Some(j) => MapRoad::Junction(
            index(j, "the map's junctions")?,
            index(at, "a junction's roads")?,
        ),
    };
    Ok(Route::Free {
        field: ctx
            .path_of(e)
            .unwrap_or_else(|| "the map's road".to_string()),
        one_lane: false,
        map_route: Some(MapRoute {
            road,
            section: None,
            against: false,
            lane: None,
            compound: false,
        }),
    })
}

/// The index `at` into `what`: a whole number of 0 or more, else an error at it.
fn index(ctx: &Ctx<'_>, at: &Expr, what: &str) -> Result<usize, Error> {
    let i = ctx.number(at)?;
    if i < 0.0 || i.fract() != 0.0 {
        return Err(ctx.files.err(
            K::Value,
            at.span,
            format!("expected an index of 0 or more (a whole number) into {what}, found {i}"),
        ));
    }
    Ok(i as usize)
}

/// The route of `e`, element `at` of the library's list `name` of the route `base`
/// (`cr.route_elements[i]`, `rd.s_positive[i]`, `ls.lanes[i]`, §8.12), `depth` fields deep;
/// `None` when `name` is no such list. The elements of a compound route the map makes
/// (`create_route(routes, …)`, "contains all the provided route instances, in the same
/// sequential order as the input list") are the routes given to it; those of one the runtime
/// chooses, the plan's roads in order. A road's lane sections in +s and a lane section's lanes
/// are bound by the plan (`crate::plan`'s `route::map_route`), an index past them an error
/// there.
fn list_element(
    ctx: &Ctx<'_>,
    e: &Expr,
    (base, name): (&Expr, &str),
    at: &Expr,
    depth: usize,
) -> Option<Result<Route, Error>> {
    if !matches!(
        name,
        "route_elements" | "s_positive" | "s_negative" | "lanes"
    ) {
        return None;
    }
    Some((|| {
        let i = index(ctx, at, &format!("`{name}`"))?;
        let field = ctx
            .path_of(e)
            .unwrap_or_else(|| format!("the element at {}", ctx.site(e.span).at()));
        let wrong = |found: &str| {
            ctx.files.err(
                K::Unsupported,
                base.span,
                format!("expected a compound route before .route_elements, a road before .s_positive or .s_negative, or a lane section before .lanes (a route field, a road of the map's lists or an element of these lists), found {found}"),
            )
        };
        // The routes given to create_route, where the compound route is a field given one or
        // the call itself.
        if name == "route_elements" {
            if let Some(r) = made_element(ctx, base, (i, at), depth) {
                return r;
            }
        }
        let against = name == "s_negative";
        let part = |road: MapRoad, section: Option<usize>, lane: Option<usize>, against: bool| {
            Route::Free {
                field: field.clone(),
                one_lane: lane.is_some(),
                map_route: Some(MapRoute {
                    road,
                    section,
                    against,
                    lane,
                    compound: false,
                }),
            }
        };
        match (name, route_within(ctx, base, depth + 1)?) {
            (
                "route_elements",
                Route::Free {
                    one_lane: false,
                    map_route: None,
                    ..
                },
            ) => Ok(part(MapRoad::Plan(i), None, None, false)),
            (
                "s_positive" | "s_negative" | "lanes",
                Route::Free {
                    field: f,
                    one_lane: false,
                    map_route: None,
                },
            ) => Ok(if name == "lanes" {
                part(MapRoad::Field(f), None, Some(i), false)
            } else {
                part(MapRoad::Field(f), Some(i), None, against)
            }),
            (
                "s_positive" | "s_negative",
                Route::Free {
                    one_lane: false,
                    map_route:
                        Some(MapRoute {
                            road,
                            section: None,
                            lane: None,
                            ..
                        }),
                    ..
                },
            ) => Ok(part(road, Some(i), None, against)),
            (
                "lanes",
                Route::Free {
                    one_lane: false,
                    map_route:
                        Some(MapRoute {
                            road,
                            section: Some(k),
                            against,
                            lane: None,
                            ..
                        }),
                    ..
                },
            ) => Ok(part(road, Some(k), Some(i), against)),
            // A compound lane nothing defines: the lanes it is made of, its own lane in each
            // lane section of the plan's roads in order along s (`crate::plan`'s
            // `route::map_route`; issue 27: before, the lanes side by side of the first
            // section, of which `cl` alone is one).
            (
                "lanes",
                Route::Free {
                    field: f,
                    one_lane: true,
                    map_route: None,
                },
            ) => Ok(Route::Free {
                field: field.clone(),
                one_lane: true,
                map_route: Some(MapRoute {
                    road: MapRoad::Field(f),
                    section: None,
                    against: false,
                    lane: Some(i),
                    compound: true,
                }),
            }),
            (_, Route::Free { one_lane: true, .. }) => Err(wrong("a lane or compound lane element")),
            (_, Route::Free { .. }) => Err(wrong("an element of another kind")),
            (_, Route::Lane { .. }) => Err(wrong("a route through points (its elements are its points: give them as routes of their own)")),
            (_, Route::Crossing { .. }) => Err(wrong("a crossing")),
        }
    })())
}

/// Element `i` (written at `at`) of the compound route `e` when the map makes it: the route
/// given to `map.create_route(routes, …)` at i, `e` the call or a field whose value is one
/// (through fields given other fields), `depth` fields deep; `None` for any other compound
/// route.
fn made_element(
    ctx: &Ctx<'_>,
    e: &Expr,
    (i, at): (usize, &Expr),
    depth: usize,
) -> Option<Result<Route, Error>> {
    if let Some(items) = made_routes(ctx, e) {
        return Some(match items.get(i) {
            Some(item) => route_within(ctx, item, depth + 1),
            None => Err(ctx.files.err(
                K::Value,
                at.span,
                format!("expected an index below {} into the route elements of the compound route (the routes given to create_route, in order), found {i}", items.len()),
            )),
        });
    }
    let (path, _) = ctx.path_of(e).and_then(|p| ctx.lookup(&p))?;
    let (value, owner) = field_value(ctx, &path)?;
    if depth >= MAX_FIELD_DEPTH {
        return Some(Err(ctx.files.err(
            K::Value,
            e.span,
            format!("expected route fields whose values end in a route the map makes, found `{path}` defined through itself"),
        )));
    }
    made_element(&owner, value, (i, at), depth + 1)
}

/// The routes given to `map.create_route(routes, …)` when `e` is such a call with a list.
fn made_routes<'e>(ctx: &Ctx<'_>, e: &'e Expr) -> Option<&'e [Expr]> {
    let Some(("create_route", args)) = map_call(ctx, e) else {
        return None;
    };
    let params = ["routes", "connect_points_by", "legal_route"].map(String::from);
    match bound_to(&bind(args, &params), "routes").map(|r| &r.kind) {
        Some(ExprKind::List(items)) => Some(items.as_slice()),
        _ => None,
    }
}

/// Whether `e` is a list of the map's roads: `m.routes` (`Some(None)`) or
/// `m.junctions[i].roads` (`Some(Some(i))`, the junction's index expression).
fn map_road<'e>(ctx: &Ctx<'_>, e: &'e Expr) -> Option<Option<&'e Expr>> {
    if map_list(ctx, e, "routes") {
        return Some(None);
    }
    let ExprKind::Field(junction, f) = &e.kind else {
        return None;
    };
    match &junction.kind {
        ExprKind::Index(list, i) if f.text == "roads" && map_list(ctx, list, "junctions") => {
            Some(Some(&**i))
        }
        _ => None,
    }
}

/// Whether `e` is the list field `name` of a `map` field (`m.routes`).
fn map_list(ctx: &Ctx<'_>, e: &Expr, name: &str) -> bool {
    let ExprKind::Field(obj, f) = &e.kind else {
        return false;
    };
    f.text == name
        && ctx
            .path_of(obj)
            .and_then(|p| ctx.lookup(&p))
            .is_some_and(|(_, v)| matches!(v, Value::RunTime(t) if is_a(ctx, t, "map")))
}

/// Whether type `ty` is `sup` or inherits from it.
pub(crate) fn is_a(ctx: &Ctx<'_>, ty: &str, sup: &str) -> bool {
    use dsl::semantics::model::TypeName;
    match (ctx.model.types.get(ty), ctx.model.types.get(sup)) {
        (Some((TypeName::Compound(a), _)), Some((TypeName::Compound(b), _))) => {
            ctx.model.is_subtype(*a, *b)
        }
        _ => false,
    }
}

/// Whether `ty` is `base` itself, or a user type inheriting from it that is none of the
/// library's more specific route types (a `lane` inherits `route` but is one lane).
pub(crate) fn is_exactly_or_user(ctx: &Ctx<'_>, ty: &str, base: &str) -> bool {
    ty == base
        || (is_a(ctx, ty, base)
            && ![
                "lane",
                "compound_lane",
                "path",
                "crossing",
                "route_point",
                "xyz_point",
                "odr_point",
            ]
            .iter()
            .any(|t| is_a(ctx, ty, t)))
}

/// A string literal or a resolved string field.
fn string(ctx: &Ctx<'_>, e: &Expr) -> Result<String, Error> {
    if let ExprKind::Str(s) = &e.kind {
        return Ok(s.clone());
    }
    if let Some((_, Value::Str(s))) = ctx.path_of(e).and_then(|p| ctx.lookup(&p)) {
        return Ok(s.clone());
    }
    Err(ctx
        .files
        .err(K::Value, e.span, "expected a string, found another value"))
}
