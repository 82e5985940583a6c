//! The position and orientation arguments of the §8.8.2 actions that place an actor (ASAM
//! OpenSCENARIO DSL 2.1 §8.8.2.4 `assign_position`, §8.8.2.5 `assign_orientation`, §8.8.2.11
//! `change_position`), read into plain data: a `position_3d` or `xyz_point` (world x, y, z), an
//! `odr_point` (OpenDRIVE road, lane, s and t from the lane's centre), a `route_point` (s and t
//! on the route, which the runtime binds to the plan road), an `orientation_3d`, a
//! `trajectory` or a `path` (§8.8.2.16-17: points, time stamps, interpolation). Each is a
//! struct field the solver resolved or a call of the map's `create_xyz_point`,
//! `create_odr_point`, `create_route_point`, `create_trajectory` or `create_path` (§8.12.2.1:
//! a path is a route, which the solver leaves to the runtime, so `map.create_path(points:
//! [p0, p1, …], interpolation: …)` with resolved `pose_3d` fields is how a program gives one).
//! A relative path or trajectory of route or odr points (`relative_path_st`,
//! `relative_path_odr`, `relative_trajectory_st`, `relative_trajectory_odr`, §8.12.33-34,
//! §8.12.40-41) has its points read from the keeps of its field's declaration
//! (`keep(it.points == [p0, p1, …])`, `keep(it.points[i] == p)`), which the solver leaves to
//! the runtime; the plan places them against the reference (`crate::plan`'s `relative_path`).

use dsl::semantics::hir::{Arg as HirArg, Expr, ExprKind};
use dsl::Value;

use super::action::Action;
use super::eval::{bind, bound_to, Eval};
use super::route::{map_call, odr_point, route_of, Route};
use super::value::{Args, Val};
use crate::error::{Error, ErrorKind as K, Site};

/// A place or orientation an action is given.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Place {
    /// World coordinates (m).
    World { x: f64, y: f64, z: f64 },
    /// Lane `lane` of OpenDRIVE road `road` at `s`, `t` m left of the lane's centre.
    Lane {
        road: String,
        lane: i32,
        s: f64,
        t: f64,
    },
    /// s and t (m) on the route: the plan road's reference line, or, for a route field the
    /// map binds to the plan's roads driven against s, along that direction and to its left.
    Route {
        s: f64,
        t: f64,
        /// The route field the point is on (`map.create_route_point(r, …)`), if it is one.
        route: Option<String>,
    },
    /// Yaw, pitch and roll (rad).
    Orientation { yaw: f64, pitch: f64, roll: f64 },
    /// A `path` (`map.create_path(points, interpolation)`): world x, y (m) and yaw (rad) of
    /// its points, and whether it is interpolated `smooth`.
    Path {
        points: Vec<(f64, f64, f64)>,
        smooth: bool,
    },
    /// A path or trajectory through points of the road network
    /// (`map.create_path_odr_points(points, interpolation, on_road_network)`,
    /// `map.create_path_route_points(…)`, §8.12.2.1.11-12; with `times`,
    /// `map.create_trajectory_odr_points(points, time_stamps, …)`,
    /// `map.create_trajectory_route_points(…)`, §8.12.2.1.14-15): each point a route from one
    /// point (an odr point, a route point), kept as the resolver reads it; the plan stage,
    /// which has the network, turns it into a [`Place::Path`] (a [`Place::Trajectory`]) of
    /// world points (`crate::plan`'s `locate_paths`). `on_road_network`: "the points of the
    /// path must be joined while keeping the whole path on the road network".
    RoadPath {
        points: Vec<Route>,
        times: Option<Vec<f64>>,
        smooth: bool,
        on_road_network: bool,
    },
    /// A `relative_trajectory` or `relative_path` (§8.12.31-34, §8.12.38-41, relative to a
    /// reference the action names): x, y (m) and yaw (rad) of its pose_3d points, or s, t
    /// (m) and 0 of its route or odr points (`of` says which); its time stamps (s; none for a
    /// path); `smooth`.
    Relative {
        points: Vec<(f64, f64, f64)>,
        times: Vec<f64>,
        smooth: bool,
        of: RelativePoints,
    },
    /// A `trajectory`: world x, y (m) and yaw (rad) of its points, their time stamps (s), and
    /// whether it is interpolated `smooth`.
    Trajectory {
        points: Vec<(f64, f64, f64)>,
        times: Vec<f64>,
        smooth: bool,
    },
}

/// What the points of a relative path or trajectory are (§8.12.32-34, §8.12.39-41).
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum RelativePoints {
    /// `pose_3d` (`relative_path_pose_3d`, `relative_trajectory_pose_3d`).
    Pose,
    /// `route_point` (`relative_path_st`, `relative_trajectory_st`): s and t, and the route
    /// field each is on (`map.create_route_point(r, …)`), whose direction the plan reads from
    /// the map's bindings (a field `routes_are_opposite` binds against s).
    St(Vec<Option<String>>),
    /// `odr_point` (`relative_path_odr`, `relative_trajectory_odr`): s and t, and the
    /// OpenDRIVE road and lane each names.
    Odr(Vec<(String, i32)>),
}

/// A place argument of an invocation.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PlaceArg {
    /// The parameter (`position`, `odr_point`, `route_point`, `target`).
    pub param: String,
    /// Its value.
    pub place: Place,
    /// Where it is written.
    pub site: Site,
}

/// The place arguments of an invocation of `action` (its arguments `args` bound to `params`).
pub(crate) fn read(
    ev: &Eval<'_>,
    action: Action,
    args: &[HirArg],
    params: &[String],
) -> Result<Vec<PlaceArg>, Error> {
    let wanted: &[&str] = match action {
        Action::AssignPosition => &["position", "odr_point", "route_point"],
        Action::ChangePosition | Action::AssignOrientation => &["target"],
        Action::FollowTrajectory
        | Action::FollowPath
        | Action::ReplayTrajectory
        | Action::ReplayPath => &["absolute", "relative"],
        _ => return Ok(Vec::new()),
    };
    bind(args, params)
        .into_iter()
        .filter(|(n, _)| wanted.contains(&n.as_str()))
        .map(|(param, e)| {
            Ok(PlaceArg {
                place: place(ev, e)?,
                param,
                site: ev.site(e.span),
            })
        })
        .collect()
}

/// The path `e` gives as the route of an `along(…)` (§8.12: a `path` inherits `route`, "a
/// polyline of points"), with the arguments that place it: `map.create_path(points,
/// interpolation)`, `map.create_path_odr_points(…)`, `map.create_path_route_points(…)` (none),
/// `map.resolve_relative_path(relative_path, reference, transform)`
/// (§8.12.2.1: the relative path placed against `reference` in the frame `transform` says,
/// as `follow_path(relative: …, reference, transform)` places one: its `reference` and
/// `transform`), or a field given one at its declaration; `None` for anything else (the route
/// module reads the other routes).
pub(crate) fn path_route(ev: &Eval<'_>, e: &Expr) -> Result<Option<(Place, Args)>, Error> {
    let value = match ev.path_of(e).and_then(|p| ev.lookup(&p)) {
        Some((p, _)) => match super::route::field_value(ev, &p) {
            Some((value, owner)) => return path_route(&owner, value),
            None => return Ok(None),
        },
        None => e,
    };
    match map_call(ev, value) {
        Some(("create_path" | "create_path_odr_points" | "create_path_route_points", _)) => {
            Ok(Some((place(ev, value)?, Args::new())))
        }
        Some(("resolve_relative_path", args)) => {
            let names = ["relative_path", "reference", "transform"].map(String::from);
            let bound = bind(args, &names);
            let Some((_, rp)) = bound.iter().find(|(n, _)| n == "relative_path") else {
                return Err(ev.files.err(
                    K::Value,
                    value.span,
                    "expected `relative_path` in resolve_relative_path(…), found none",
                ));
            };
            let place = place(ev, rp)?;
            if !matches!(&place, Place::Relative { times, .. } if times.is_empty()) {
                return Err(ev.files.err(
                    K::Value,
                    rp.span,
                    "expected a relative path (relative_path_pose_3d, relative_path_st, relative_path_odr) in resolve_relative_path(…), found another value",
                ));
            }
            let placing = bound
                .iter()
                .filter(|(n, _)| n != "relative_path")
                .map(|(n, a)| (n.clone(), ev.arg(a)))
                .collect();
            Ok(Some((place, placing)))
        }
        _ => Ok(None),
    }
}

/// The place `e` gives.
fn place(ev: &Eval<'_>, e: &Expr) -> Result<Place, Error> {
    let bad = |what: &str| {
        ev.files.err(
            K::Value,
            e.span,
            format!("expected a position_3d, xyz_point, odr_point, route_point, orientation_3d, trajectory or path (a field, or map.create_xyz_point/create_odr_point/create_route_point/create_trajectory/create_path(…)), found {what}"),
        )
    };
    if let Some((method, args)) = map_call(ev, e) {
        let params = |ps: &[&str]| ps.iter().map(|p| p.to_string()).collect::<Vec<_>>();
        let number = |ps: &[&str], n: &str| -> Result<f64, Error> {
            let names = params(ps);
            bind(args, &names)
                .into_iter()
                .find(|(p, _)| p == n)
                .map_or(Ok(0.0), |(_, a)| ev.number(a))
        };
        return match method {
            "create_odr_point" => {
                let p = odr_point(ev, e, args)?;
                Ok(Place::Lane {
                    road: p.road,
                    lane: p.lane,
                    s: p.s,
                    t: p.t,
                })
            }
            "create_route_point" => {
                let ps = ["route", "s", "t"];
                let route = bind(args, &params(&ps))
                    .into_iter()
                    .find(|(p, _)| p == "route")
                    .and_then(|(_, r)| ev.path_of(r));
                Ok(Place::Route {
                    s: number(&ps, "s")?,
                    t: number(&ps, "t")?,
                    route,
                })
            }
            "create_xyz_point" => {
                let ps = ["x", "y", "z"];
                Ok(Place::World {
                    x: number(&ps, "x")?,
                    y: number(&ps, "y")?,
                    z: number(&ps, "z")?,
                })
            }
            "create_path" | "create_trajectory" => {
                let trajectory = method == "create_trajectory";
                let ps: &[&str] = if trajectory {
                    &["points", "time_stamps", "interpolation"]
                } else {
                    &["points", "interpolation"]
                };
                let names = params(ps);
                let bound = bind(args, &names);
                let given = |n: &str| bound_to(&bound, n);
                let list = |n: &str| match given(n).map(|e| &e.kind) {
                    Some(ExprKind::List(items)) => Ok(items.as_slice()),
                    _ => Err(bad(&format!(
                        "map.{method}(…) without a list of {n} (a list literal, `[a, b, …]`)"
                    ))),
                };
                let points = list("points")?
                    .iter()
                    .map(|item| {
                        ev.path_of(item)
                            .and_then(|p| ev.lookup(&p))
                            .and_then(|(_, v)| pose_of(v))
                            .ok_or_else(|| {
                                ev.files.err(
                                    K::Value,
                                    item.span,
                                    "expected a pose_3d the solver resolved as a point of the path, found another value",
                                )
                            })
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                let times = if trajectory {
                    list("time_stamps")?
                        .iter()
                        .map(|t| ev.number(t))
                        .collect::<Result<Vec<_>, _>>()?
                } else {
                    Vec::new()
                };
                let smooth = smooth(ev, given("interpolation"))?;
                Ok(if trajectory {
                    Place::Trajectory {
                        points,
                        times,
                        smooth,
                    }
                } else {
                    Place::Path { points, smooth }
                })
            }
            "create_path_odr_points"
            | "create_path_route_points"
            | "create_trajectory_odr_points"
            | "create_trajectory_route_points" => road_path(ev, e, method, args),
            m => Err(bad(&format!("map.{m}(…)"))),
        };
    }
    let path = ev.path_of(e).ok_or_else(|| bad("an expression"))?;
    let found = ev.lookup(&path);
    let Some((_, v @ Value::Compound { fields, .. })) = found else {
        let hint = match found {
            Some((_, Value::RunTime(t))) if t == "path" => {
                " (a path is made by map.create_path(points: [...], interpolation: ...))"
            }
            _ => "",
        };
        return Err(bad(&format!(
            "`{path}`, which is no struct the solver resolved{hint}"
        )));
    };
    let text = |n: &str| match fields.iter().find(|(f, _)| f == n) {
        Some((_, Value::Str(s))) => Ok(s.clone()),
        _ => Err(bad(&format!("`{path}` without a {n}"))),
    };
    if ev.is_a(v, "position_3d") {
        Ok(Place::World {
            x: num(fields, "x"),
            y: num(fields, "y"),
            z: num(fields, "z"),
        })
    } else if ev.is_a(v, "xyz_point") {
        match fields.iter().find(|(f, _)| f == "position") {
            Some((_, Value::Compound { fields: p, .. })) => Ok(Place::World {
                x: num(p, "x"),
                y: num(p, "y"),
                z: num(p, "z"),
            }),
            _ => Err(bad(&format!("`{path}` without a position"))),
        }
    } else if ev.is_a(v, "odr_point") {
        let lane_text = text("lane_id")?;
        let lane = lane_text.trim().parse().map_err(|_| {
            bad(&format!(
                "`{path}` with lane_id {lane_text:?} (an OpenDRIVE lane id is an integer)"
            ))
        })?;
        Ok(Place::Lane {
            road: text("road_id")?,
            lane,
            s: num(fields, "s"),
            t: num(fields, "t"),
        })
    } else if ev.is_a(v, "route_point") {
        Ok(Place::Route {
            s: num(fields, "s"),
            t: num(fields, "t"),
            route: None,
        })
    } else if ["trajectory", "relative_trajectory", "relative_path"]
        .iter()
        .any(|t| ev.is_a(v, t))
    {
        let relative = !ev.is_a(v, "trajectory");
        let list = |n: &str| match fields.iter().find(|(f, _)| f == n) {
            Some((_, Value::List(items))) => Ok(items.as_slice()),
            _ => Err(bad(&format!("`{path}` without a list of {n}"))),
        };
        let items = list("points")?;
        let (points, of) = if relative && items.iter().any(|p| matches!(p, Value::RunTime(_))) {
            road_points(ev, e, &path, items.len())?
        } else {
            let points = items
                .iter()
                .map(|p| {
                    pose_of(p)
                        .ok_or_else(|| bad(&format!("a point of `{path}` that is no pose_3d")))
                })
                .collect::<Result<Vec<_>, _>>()?;
            (points, RelativePoints::Pose)
        };
        let times = if ev.is_a(v, "relative_path") {
            Vec::new()
        } else {
            list("time_stamps")?
                .iter()
                .map(|t| match t {
                    Value::Quantity { si, .. } | Value::Float(si) => Ok(*si),
                    _ => Err(bad(&format!("a time stamp of `{path}` that is no time"))),
                })
                .collect::<Result<Vec<_>, _>>()?
        };
        let smooth = matches!(
            fields.iter().find(|(f, _)| f == "interpolation"),
            Some((_, Value::Enum { member, .. })) if member == "smooth"
        );
        Ok(if relative {
            Place::Relative {
                points,
                times,
                smooth,
                of,
            }
        } else {
            Place::Trajectory {
                points,
                times,
                smooth,
            }
        })
    } else if ev.is_a(v, "orientation_3d") {
        Ok(Place::Orientation {
            yaw: num(fields, "yaw"),
            pitch: num(fields, "pitch"),
            roll: num(fields, "roll"),
        })
    } else {
        Err(bad(&format!("`{path}`")))
    }
}

/// x, y (m) and yaw (rad) of a point, or s, t (m) and 0.
type Pose = (f64, f64, f64);

/// The points of the relative path or trajectory field `path` (read at `e`) whose `count`
/// points are route elements the solver leaves to the runtime (`relative_path_st`,
/// `relative_path_odr`, `relative_trajectory_st`, `relative_trajectory_odr`; §8.12.33-34,
/// §8.12.40-41): each given by a `keep` of the field's `with:` block, `keep(it.points ==
/// [p0, p1, …])` or `keep(it.points[i] == p)`, a `map.create_route_point(route, s, t)`
/// (its s and t) or a `map.create_odr_point(road_id, lane_id, s, t)` (its s and t, road and
/// lane). Every point given once; another value, a point given twice or none is an error.
fn road_points(
    ev: &Eval<'_>,
    e: &Expr,
    path: &str,
    count: usize,
) -> Result<(Vec<Pose>, RelativePoints), Error> {
    let mut given: Vec<Option<&Expr>> = vec![None; count];
    let mut pairs: Vec<(usize, &Expr)> = Vec::new();
    let def = super::route::field_def(ev, path);
    let (keeps, owner): (&[dsl::semantics::hir::Keep], &Eval<'_>) = match &def {
        Some((field, owner)) => (&field.keeps, owner),
        None => (&[], ev),
    };
    let points_of = |x: &Expr| match &x.kind {
        ExprKind::Field(it, f) if matches!(it.kind, ExprKind::It) && f.text == "points" => {
            Some(None)
        }
        ExprKind::Index(list, i) => match (&list.kind, &i.kind) {
            (ExprKind::Field(it, f), ExprKind::Int(i))
                if matches!(it.kind, ExprKind::It) && f.text == "points" =>
            {
                usize::try_from(*i).ok().map(Some)
            }
            _ => None,
        },
        _ => None,
    };
    for k in keeps.iter().filter(|k| !k.default) {
        let ExprKind::Binary(dsl::semantics::hir::BinOp::Eq, a, b) = &k.expr.kind else {
            continue;
        };
        let (at, value) = match (points_of(a), points_of(b)) {
            (Some(at), _) => (at, &**b),
            (None, Some(at)) => (at, &**a),
            (None, None) => continue,
        };
        match (at, &value.kind) {
            (None, ExprKind::List(items)) => pairs.extend(items.iter().enumerate()),
            (Some(i), _) => pairs.push((i, value)),
            (None, _) => {
                return Err(owner.files.err(
                    K::Value,
                    value.span,
                    format!("expected the points of `{path}` as a list literal (`keep(it.points == [p0, p1, …])`), found another expression"),
                ))
            }
        }
    }
    for (i, p) in pairs {
        match given.get_mut(i) {
            Some(slot @ None) => *slot = Some(p),
            _ => {
                return Err(owner.files.err(
                    K::Value,
                    p.span,
                    format!("expected each of the {count} points of `{path}` given once, found point {i} given again or past the list's end"),
                ))
            }
        }
    }
    let mut points = Vec::with_capacity(count);
    let mut lanes = Vec::new();
    let mut routes = Vec::new();
    for (i, p) in given.into_iter().enumerate() {
        let Some(p) = p else {
            return Err(ev.files.err(
                K::Value,
                e.span,
                format!("expected point {i} of `{path}` (a route element, left to the runtime) given by a keep of its declaration, `keep(it.points == [p0, p1, …])` or `keep(it.points[{i}] == p)`, found none"),
            ));
        };
        match place(owner, p) {
            Ok(Place::Route { s, t, route }) => {
                relative_route(owner, p, i, path)?;
                points.push((s, t, 0.0));
                routes.push(route);
            }
            Ok(Place::Lane { road, lane, s, t }) => {
                points.push((s, t, 0.0));
                lanes.push((road, lane));
            }
            _ => {
                return Err(owner.files.err(
                    K::Value,
                    p.span,
                    format!("expected map.create_route_point(route, s, t) or map.create_odr_point(road_id, lane_id, s, t) as point {i} of `{path}`, found another value"),
                ))
            }
        }
    }
    let of = match lanes.len() {
        0 => RelativePoints::St(routes),
        n if n == points.len() => RelativePoints::Odr(lanes),
        _ => {
            return Err(ev.files.err(
                K::Value,
                e.span,
                format!(
                "expected the points of `{path}` all route points or all odr points, found both"
            ),
            ))
        }
    };
    Ok((points, of))
}

/// Checks the `route` of `map.create_route_point(route, s, t)`, point `i` of the relative path
/// or trajectory `path` (the call `p`): a relative point's s and t are road coordinates from
/// the reference's, along the plan's roads (`crate::plan`'s `relative_path`), so its route is
/// a route the runtime chooses (a `route` field nothing defines: the plan's roads, in the
/// direction the map's modifiers bind it, which the plan reads); a route the
/// map makes (an odr point, `create_route`, a road of the map's lists, …) would be measured
/// along nowhere, an error at the argument (issue 27: before, it was not read).
fn relative_route(ev: &Eval<'_>, p: &Expr, i: usize, path: &str) -> Result<(), Error> {
    let Some((_, args)) = map_call(ev, p) else {
        return Ok(());
    };
    let params = ["route", "s", "t"].map(String::from);
    let bound = bind(args, &params);
    let Some(r) = bound_to(&bound, "route") else {
        return Ok(());
    };
    match route_of(ev, r)? {
        Route::Free {
            map_route: None, ..
        } => Ok(()),
        other => {
            let what = match other {
                Route::Free { field, .. } => format!("`{field}`, a road of the map's lists"),
                Route::Crossing { field, .. } => format!("`{field}`, a crossing"),
                Route::Lane { .. } => "a route the map makes".to_string(),
            };
            Err(ev.files.err(
                K::Value,
                r.span,
                format!("expected a route the runtime chooses (a `route` field nothing defines: the plan's roads) as the `route` of create_route_point(route, s, t), point {i} of the relative `{path}`, found {what}: a relative route point's s and t are road coordinates from the reference's along the plan's roads, not along its route (give the point as map.create_odr_point(road_id, lane_id, s, t) to name its road)"),
            ))
        }
    }
}

/// Whether a path's `interpolation` argument `e` is `smooth` (`straight_line`, or none given:
/// the polyline).
fn smooth(ev: &Eval<'_>, e: Option<&Expr>) -> Result<bool, Error> {
    let Some(e) = e else {
        return Ok(false);
    };
    match ev.eval(e)? {
        Val::Enum(m) if m == "smooth" => Ok(true),
        Val::Enum(m) if m == "straight_line" => Ok(false),
        _ => Err(ev.files.err(
            K::Value,
            e.span,
            "expected an interpolation (straight_line, smooth), found another value",
        )),
    }
}

/// The path of `map.create_path_odr_points(points, interpolation, on_road_network)` or
/// `map.create_path_route_points(…)` (`method`, its call `e`, its arguments `args`;
/// §8.12.2.1.11-12: "Sequence of odr_point (route_point) that will be converted to world
/// x-y-z-coordinates to create a path"), or the trajectory of
/// `map.create_trajectory_odr_points(points, time_stamps, …)` /
/// `map.create_trajectory_route_points(…)` (§8.12.2.1.14-15): each point read as the route
/// from it (`route`), which the plan stage places on the network. A point that is a route of more than one point (no point of its own) is an error
/// at it.
fn road_path(ev: &Eval<'_>, e: &Expr, method: &str, args: &[HirArg]) -> Result<Place, Error> {
    let trajectory = method.starts_with("create_trajectory");
    let names: &[&str] = if trajectory {
        &["points", "time_stamps", "interpolation", "on_road_network"]
    } else {
        &["points", "interpolation", "on_road_network"]
    };
    let names: Vec<String> = names.iter().map(|n| n.to_string()).collect();
    let bound = bind(args, &names);
    let given = |n: &str| bound_to(&bound, n);
    let kind = if method.ends_with("odr_points") {
        "odr_point"
    } else {
        "route_point"
    };
    // A trajectory's time stamps: checked against its points by the plan, as create_trajectory's.
    let times = match (trajectory, given("time_stamps").map(|t| (t, &t.kind))) {
        (false, _) => None,
        (true, Some((_, ExprKind::List(items)))) => Some(
            items
                .iter()
                .map(|t| ev.number(t))
                .collect::<Result<Vec<_>, _>>()?,
        ),
        // A field given the list (`time_stamps: list of time = [0s, 2s, 5s]`, §8.12.2.1.14's
        // example), resolved by the solver.
        (true, Some((t, _))) if ev.path_of(t).and_then(|p| ev.lookup(&p)).is_some() => {
            match ev.path_of(t).and_then(|p| ev.lookup(&p)) {
                Some((_, Value::List(items))) => Some(
                    items
                        .iter()
                        .map(|v| match v {
                            Value::Quantity { si, .. } | Value::Float(si) => Ok(*si),
                            _ => Err(ev.files.err(
                                K::Value,
                                t.span,
                                "expected time stamps (times) in the list, found another value",
                            )),
                        })
                        .collect::<Result<Vec<_>, _>>()?,
                ),
                _ => {
                    return Err(ev.files.err(
                        K::Value,
                        t.span,
                        format!("expected a list of time stamps in map.{method}(…), found another value"),
                    ))
                }
            }
        }
        (true, found) => {
            return Err(ev.files.err(
                K::Value,
                found.map_or(e.span, |(t, _)| t.span),
                format!("expected a list of time stamps (a list literal, `[t0, t1, …]`) in map.{method}(…), found {}", if found.is_some() { "another expression" } else { "none" }),
            ))
        }
    };
    let items = match given("points").map(|e| (e, &e.kind)) {
        Some((_, ExprKind::List(items))) if items.len() >= 2 => items,
        found => {
            let (span, what) = match found {
                Some((e, ExprKind::List(items))) => (
                    e.span,
                    format!(
                        "{} point{}",
                        items.len(),
                        if items.len() == 1 { "" } else { "s" }
                    ),
                ),
                Some((e, _)) => (e.span, "another expression".to_string()),
                None => (e.span, "none".to_string()),
            };
            return Err(ev.files.err(
                K::Value,
                span,
                format!("expected a list of two or more {kind}s (a list literal, `[a, b, …]`) as the points of map.{method}(…), found {what}"),
            ));
        }
    };
    let points = items
        .iter()
        .map(|item| match route_of(ev, item)? {
            // A point on a route (its later points are dropped once it is placed), or a route
            // from one point.
            r @ Route::Lane { .. } if one_point(&r) => Ok(r),
            _ => Err(ev.files.err(
                K::Value,
                item.span,
                format!("expected a {kind} (one point on the road network) as a point of map.{method}(…), found a route of its own (no one point to place)"),
            )),
        })
        .collect::<Result<Vec<_>, _>>()?;
    let on_road_network = match given("on_road_network") {
        None => false,
        Some(e) => match ev.eval(e)? {
            Val::Bool(b) => b,
            _ => {
                return Err(ev.files.err(
                    K::Value,
                    e.span,
                    "expected on_road_network true or false, found another value",
                ))
            }
        },
    };
    Ok(Place::RoadPath {
        points,
        times,
        smooth: smooth(ev, given("interpolation"))?,
        on_road_network,
    })
}

/// Whether route `r` stands for one point: a route from one point, or a point on a route.
fn one_point(r: &Route) -> bool {
    matches!(r, Route::Lane { on: Some(_), .. })
        || matches!(r, Route::Lane { then, .. } if then.is_empty())
}

/// The number field `n` of a struct's `fields` (0 when it has none).
fn num(fields: &[(String, Value)], n: &str) -> f64 {
    fields
        .iter()
        .find(|(f, _)| f == n)
        .and_then(|(_, v)| match v {
            Value::Quantity { si, .. } | Value::Float(si) => Some(*si),
            Value::Int(i) => Some(*i as f64),
            _ => None,
        })
        .unwrap_or(0.0)
}

/// World x, y (m) and yaw (rad) of a `pose_3d` value.
fn pose_of(v: &Value) -> Option<(f64, f64, f64)> {
    let Value::Compound { fields, .. } = v else {
        return None;
    };
    let yaw = match fields.iter().find(|(f, _)| f == "orientation") {
        Some((_, Value::Compound { fields: o, .. })) => num(o, "yaw"),
        _ => 0.0,
    };
    match fields.iter().find(|(f, _)| f == "position") {
        Some((_, Value::Compound { fields: q, .. })) => Some((num(q, "x"), num(q, "y"), yaw)),
        _ => None,
    }
}
