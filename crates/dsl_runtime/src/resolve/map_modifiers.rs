//! The map's modifiers applied in the scenario's body (ASAM OpenSCENARIO DSL 2.1 §8.12.2.2:
//! `m.number_of_lanes(…)`, `m.start_lane(l)`, `m.end_lane(l)`, `m.lane_side(…)`,
//! `m.compound_lane_side(…)`, `m.routes_overlap(…)`, `m.roads_follow_in_junction(…)`;
//! `m.routes_are_in_sequence(…)`; `m.routes_are_opposite(…)`), read as plain data
//! for the planner, which binds the lane fields they name to lanes of the loaded road network
//! or checks the network against them (`crate::plan`'s `map_lanes`).
//!
//! The standard calls them constraints on the abstract road network. oscsim generates no
//! maps: with an OpenDRIVE network loaded, a modifier over lane fields is a **binding** of
//! those fields to lanes of the network that satisfy it, one over route fields a **check**
//! that the network (the roads the plan drives on, which every free route field is) does. The
//! exceptions are `roads_follow_in_junction`, whose junction and road fields are bound through
//! two lanes (`in_lane`/`out_lane`, or two of the modifier's own) with the way through on the
//! plan's roads, and `routes_are_in_sequence` on route fields, each bound to a road (a
//! `lane_section` field to a lane section) of the plan through a lane of the modifier's own
//! (`SeqEnd`), or on two routes the map makes, a check of their points, or on a route the map
//! makes and a field, the field bound beside it as beside a road (`EndKind::Made`); `roads_follow_in_junction`'s `junction_route` is bound to the connecting road of the way through;
//! `crossing_connects` binds its crossing field to a crosswalk of the map and its lanes to
//! the lanes the crosswalk joins. `routes_are_opposite` on route fields binds `route2` to the
//! plan's roads driven against s (`OppositeRoutes`);
//! `set_map_file` names the network (`crate::map_file`), `set_traffic_lights_control_file` the
//! traffic signal controllers (`crate::traffic_lights`).

use dsl::semantics::hir::ModifierApp;
use dsl::Value;

use super::eval::{bind, Eval as Ctx};
use super::route::Route;
use super::value::{arg, Arg, Args, Val};
use crate::error::{Error, ErrorKind as K, Site};

/// One map modifier, read.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct MapModifier {
    /// What it constrains.
    pub kind: MapKind,
    /// Its name (`lane_side`).
    pub name: String,
    /// The application.
    pub site: Site,
}

/// What a map modifier constrains. Fields are paths of the scenario's route and lane fields.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum MapKind {
    /// §8.12.2.2.1: `route` has `n` lanes of the type, use and directionality given.
    NumberOfLanes {
        /// The route field.
        route: String,
        /// Whether it is a `lane_section` (one section of the plan's roads: a binding), else
        /// the whole route (every section: a check).
        section: bool,
        /// The number.
        n: u32,
        /// `lane_type`, `lane_use`, `directionality` members, when given.
        lane_type: Option<String>,
        /// See `lane_type`.
        lane_use: Option<String>,
        /// See `lane_type`.
        directionality: Option<String>,
    },
    /// §8.12.2.2.8: the lane starts in its lane section (no predecessor in the previous one).
    StartLane(String),
    /// §8.12.2.2.7: the lane ends in its lane section (no successor in the next one).
    EndLane(String),
    /// §8.12.2.2.5/6: `lane1` is `count` lanes to the `left` (else right) of `lane2`.
    LaneSide {
        /// The first lane field.
        lane1: String,
        /// Left, else right.
        left: bool,
        /// The second lane field.
        lane2: String,
        /// n: n − 1 lanes between them.
        count: u32,
        /// Whether `lane_section:` (`route:` of `compound_lane_side`) was given: a route field,
        /// the plan's roads.
        on_plan_roads: bool,
    },
    /// §8.12.2.2.2 on lane fields: `succeeding` follows `preceding`.
    InSequence {
        /// The first lane field.
        preceding: String,
        /// The lane field that follows it.
        succeeding: String,
        /// Whether `road:` was given (a road field: the plan's roads).
        on_plan_roads: bool,
    },
    /// §8.12.2.2.10 on lane fields: the two run in opposite directions.
    Opposite {
        /// The first lane field.
        route1: String,
        /// The second lane field.
        route2: String,
        /// Whether `containing_road:` was given (a road field: the plan's roads).
        on_plan_roads: bool,
    },
    /// §8.12.2.2.10 on route fields (`route`, `road`, `compound_route`, `lane_section`):
    /// `route1` is the plan's roads (as every free route field), `route2` the same roads
    /// driven the other way, against s.
    OppositeRoutes {
        /// The first route field.
        route1: String,
        /// The route field bound to the plan's roads against s.
        route2: String,
    },
    /// §8.12.2.2.2 on route fields other than two lanes (roads, lane sections, routes, a lane
    /// beside one of them): `succeeding` follows `preceding` in +s, through lanes of the
    /// modifier's own on the ends that are no lane field (`SeqEnd::lane`), which are what is
    /// bound.
    RoutesInSequence {
        /// The first end.
        preceding: SeqEnd,
        /// The end that follows it.
        succeeding: SeqEnd,
    },
    /// §8.12.2.2.2 on two routes the map makes (`m.create_route([…])`,
    /// `m.create_odr_point(…)`): a check that `succeeding` starts where `preceding` ends, on
    /// its road further on or on the road after it (directly or through one connecting road).
    NamedInSequence {
        /// The first route (`Route::Lane`).
        preceding: Route,
        /// The route that follows it (`Route::Lane`).
        succeeding: Route,
    },
    /// §8.12.2.2.3: `out_lane` is reached from `in_lane` through one connecting lane of a
    /// junction, turning the way `direction` names; without `in_lane`/`out_lane` two lanes
    /// of the modifier's own stand for them (`in_road`'s and `out_road`'s).
    Junction {
        /// The lane into the junction (a lane field, or the modifier's own).
        in_lane: String,
        /// The lane out of it (see `in_lane`).
        out_lane: String,
        /// `straight`, `right`, `u_turn`, `left` (none: any).
        direction: Option<String>,
        /// The junction and road arguments.
        roads: JunctionRoads,
    },
    /// §8.12.2.2.9: `crossing` connects `start_lane` to `end_lane`, a straight line from
    /// `start_lane`'s centreline at `start_s` at `start_angle` to its direction to `end_lane`'s
    /// centreline, within a crosswalk of the map; without the lanes, two of the modifier's own.
    Crossing {
        /// The crossing field.
        crossing: String,
        /// The lane it starts in (a lane field, or the modifier's own).
        start_lane: String,
        /// The lane it ends in (see `start_lane`).
        end_lane: String,
        /// `start_s_coord` (m of the start lane's road), when given.
        start_s: Option<f64>,
        /// `start_angle` (rad, in (0, π)), when given.
        start_angle: Option<f64>,
        /// Whether the lanes are the modifier's own (neither lane given).
        own_lanes: bool,
    },
    /// §8.12.2.2.12: the file of traffic light control cycles (resolved against the `.osc`
    /// file's folder; `crate::traffic_lights`).
    TrafficLightControl(std::path::PathBuf),
    /// §8.12.2.2.4: the routes overlap longitudinally in the way `kind` names.
    RoutesOverlap {
        /// The first route field.
        route1: String,
        /// The second route field.
        route2: String,
        /// `equal`, `start`, `end`, `inside`, `any`, `other`.
        kind: String,
    },
}

/// One end of `routes_are_in_sequence` on route fields (§8.12.2.2.2).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SeqEnd {
    /// The field's path.
    pub field: String,
    /// What the field is bound to.
    pub kind: EndKind,
    /// The lane the sequence is bound through: the field itself for a lane field, else the
    /// modifier's own lane on the field's road or lane section (named for messages, unique to
    /// the modifier).
    pub lane: String,
    /// For a route the map makes beside a field (`EndKind::Made`): that route
    /// (`Route::Lane`), whose lane at its end (preceding) or start (succeeding) is the
    /// modifier's own lane.
    pub made: Option<Route>,
}

/// What an end of `routes_are_in_sequence` is bound to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum EndKind {
    /// A lane field (`lane`, `compound_lane`): one lane.
    Lane,
    /// A `lane_section` field: one lane section of the plan's roads.
    Section,
    /// A `road`, `route`, `route_element` or `compound_route` field: one road of the plan.
    Road,
    /// A route the map makes (`m.create_route([…])`, `m.create_odr_point(…)`, or a field given
    /// one) beside a field: no field, its lane fixed where it ends (preceding) or starts
    /// (succeeding); the field is bound as beside a road.
    Made,
}

/// The junction and road arguments of `roads_follow_in_junction` (§8.12.2.2.3).
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct JunctionRoads {
    /// The `junction` field: the junction's id once bound.
    pub junction: Option<String>,
    /// The `in_road` field: the road of the lane into the junction.
    pub in_road: Option<String>,
    /// The `out_road` field: the road of the lane out of it.
    pub out_road: Option<String>,
    /// The `junction_route` field: the connecting road from the lane into the junction to the
    /// lane out of it.
    pub junction_route: Option<String>,
    /// `clockwise_count`: the out-road is the n-th road met going clockwise round the
    /// junction from the in-road.
    pub clockwise_count: Option<u32>,
    /// `number_of_roads`: how many roads outside the junction meet at it.
    pub number_of_roads: Option<u32>,
    /// Whether `in_lane`/`out_lane` were not given (the lanes are the modifier's own).
    pub own_lanes: bool,
    /// Whether any of `junction`, `in_road`, `out_road`, `resulting_route`, `junction_route`
    /// was given: the way through is on the plan's roads.
    pub on_plan_roads: bool,
}

/// The map modifiers of §8.12.2.2 (besides `set_map_file`).
pub(crate) const MAP_MODIFIERS: [&str; 11] = [
    "number_of_lanes",
    "routes_are_in_sequence",
    "roads_follow_in_junction",
    "routes_overlap",
    "lane_side",
    "compound_lane_side",
    "end_lane",
    "start_lane",
    "crossing_connects",
    "routes_are_opposite",
    "set_traffic_lights_control_file",
];

/// Reads `app`, a modifier of the scenario's body, when it is one of the map's (`None` for
/// another modifier).
pub(crate) fn read(ctx: &Ctx<'_>, app: &ModifierApp) -> Option<Result<MapModifier, Error>> {
    let name = app.name.text.as_str();
    MAP_MODIFIERS
        .contains(&name)
        .then(|| read_map(ctx, app, name))
}

fn read_map(ctx: &Ctx<'_>, app: &ModifierApp, name: &str) -> Result<MapModifier, Error> {
    let site = ctx.site(app.span);
    let on_map = app
        .target
        .as_ref()
        .and_then(|t| ctx.path_of(t))
        .and_then(|p| ctx.lookup(&p))
        .is_some_and(|(_, v)| matches!(v, Value::RunTime(t) if super::route::is_a(ctx, t, "map")));
    if !on_map {
        return Err(site.err(
            K::Modifier,
            format!("expected {name}(…) applied to a map field (m: map; m.{name}(…)), found it applied to something else"),
        ));
    }
    if name == "set_traffic_lights_control_file" {
        use dsl::semantics::hir::ExprKind;
        let file = app
            .args
            .iter()
            .find_map(|a| match (&a.name, &a.value.kind) {
                (None, ExprKind::Str(f)) => Some(f.clone()),
                (Some(n), ExprKind::Str(f)) if n.text == "file" => Some(f.clone()),
                _ => None,
            });
        let Some(file) = file else {
            return Err(site.err(
                K::Argument,
                "expected the control file as a string (set_traffic_lights_control_file(\"signals.xosc\")), found none".to_string(),
            ));
        };
        let dir = site.pos.file.parent().unwrap_or(std::path::Path::new(""));
        return Ok(MapModifier {
            kind: MapKind::TrafficLightControl(dir.join(file)),
            name: name.to_string(),
            site,
        });
    }
    let params = super::modifier::params(ctx, name);
    let exprs = bind(&app.args, &params);
    let args: Args = exprs.iter().map(|(n, e)| (n.clone(), ctx.arg(e))).collect();
    // An argument that calls a method (a route the map makes: `m.create_route(…)`), or names
    // a route field given such a value at its declaration (`r: route = m.create_route(…)`).
    let call = |p: &str| {
        exprs
            .iter()
            .find(|(n, e)| {
                n == p
                    && (matches!(e.kind, dsl::semantics::hir::ExprKind::Call(..))
                        || ctx
                            .path_of(e)
                            .and_then(|f| ctx.lookup(&f))
                            .and_then(|(f, _)| super::route::valued_route(ctx, &f))
                            .is_some_and(|r| matches!(r, Ok(Route::Lane { .. }))))
            })
            .map(|(_, e)| *e)
    };
    let need = |p: &str| {
        arg(&args, p).ok_or_else(|| {
            site.err(
                K::Argument,
                format!("expected `{p}` in {name}(…) (a mandatory argument), found none"),
            )
        })
    };
    let lane = |p: &str| -> Result<String, Error> { field(ctx, need(p)?, true) };
    let route = |p: &str| -> Result<String, Error> { field(ctx, need(p)?, false) };
    let member = |p: &str| -> Result<Option<String>, Error> {
        arg(&args, p)
            .map(|a| match a.eval()? {
                Val::Enum(m) => Ok(m),
                _ => Err(a.site.err(
                    K::Value,
                    format!("expected a member of {p}, found another value"),
                )),
            })
            .transpose()
    };
    let count = |p: &str, default: Option<u32>| -> Result<u32, Error> {
        match (arg(&args, p), default) {
            (None, Some(d)) => Ok(d),
            (None, None) => Err(site.err(
                K::Argument,
                format!("expected `{p}` in {name}(…) (a mandatory argument), found none"),
            )),
            (Some(a), _) => match a.number()? {
                x if x >= 0.0 && x.fract() == 0.0 && x <= f64::from(u32::MAX) => Ok(x as u32),
                x => Err(a.site.err(
                    K::Value,
                    format!("expected a whole number of 0 or more, found {x}"),
                )),
            },
        }
    };
    let kind = match name {
        "number_of_lanes" => {
            let r = need("route")?;
            let path = field(ctx, r, false)?;
            MapKind::NumberOfLanes {
                section: is_type(ctx, &path, "lane_section"),
                route: path,
                n: count("num_of_lanes", None)?,
                lane_type: member("lane_type")?,
                lane_use: member("lane_use")?,
                directionality: member("directionality")?,
            }
        }
        "start_lane" => MapKind::StartLane(lane("lane")?),
        "end_lane" => MapKind::EndLane(lane("lane")?),
        "lane_side" | "compound_lane_side" => {
            let left = match member("side")?.as_deref() {
                Some("left") => true,
                Some("right") => false,
                _ => {
                    return Err(site.err(
                        K::Argument,
                        format!("expected side: left or right in {name}(…), found none"),
                    ))
                }
            };
            let within = if name == "lane_side" {
                "lane_section"
            } else {
                "route"
            };
            MapKind::LaneSide {
                lane1: lane("lane1")?,
                left,
                lane2: lane("lane2")?,
                count: count("count", Some(1))?,
                on_plan_roads: arg(&args, within)
                    .map(|a| field(ctx, a, false))
                    .transpose()?
                    .is_some(),
            }
        }
        "routes_overlap" => MapKind::RoutesOverlap {
            route1: route("route1")?,
            route2: route("route2")?,
            kind: member("overlap_kind")?.unwrap_or_else(|| "any".to_string()),
        },
        "routes_are_opposite" => {
            if let Some(k) = member("lateral_overlap")?.filter(|k| k != "never") {
                let at = arg(&args, "lateral_overlap").map_or(&site, |a| &a.site);
                return Err(at.err(
                    K::Unsatisfiable,
                    format!("expected lateral_overlap: never for two routes driven in opposite directions (each lane of an OpenDRIVE road has one driving direction, so two never share their width), found {k}"),
                ));
            }
            if arg(&args, "route1").is_none_or(|a| field(ctx, a, true).is_err()) {
                // Route fields: containing_road, when given, is a road field, the plan's
                // roads, which hold both.
                if let Some(a) = arg(&args, "containing_road") {
                    field(ctx, a, false)?;
                }
                return Ok(MapModifier {
                    kind: MapKind::OppositeRoutes {
                        route1: route("route1")?,
                        route2: route("route2")?,
                    },
                    name: name.to_string(),
                    site,
                });
            }
            MapKind::Opposite {
                route1: lane("route1")?,
                route2: lane("route2")?,
                on_plan_roads: arg(&args, "containing_road")
                    .map(|a| field(ctx, a, false))
                    .transpose()?
                    .is_some(),
            }
        }
        "routes_are_in_sequence" => {
            // A field end: a lane field is itself, a road or lane section field is bound
            // through a lane of the modifier's own on it.
            let field_end = |p: &str| -> Result<SeqEnd, Error> {
                let a = need(p)?;
                if let Ok(f) = field(ctx, a, true) {
                    return Ok(SeqEnd {
                        lane: f.clone(),
                        field: f,
                        kind: EndKind::Lane,
                        made: None,
                    });
                }
                let f = field(ctx, a, false)?;
                Ok(SeqEnd {
                    lane: format!("{f}'s lane ({name} at {}:{})", site.pos.line, site.pos.col),
                    kind: if is_type(ctx, &f, "lane_section") {
                        EndKind::Section
                    } else {
                        EndKind::Road
                    },
                    field: f,
                    made: None,
                })
            };
            let made = |p: &str| call(p).map(|e| super::route::route_of(ctx, e)).transpose();
            // `road:` is a road field nothing else defines, the plan's roads as every free
            // route field (`crate::road`), which hold both ends: the ends are bound to (or,
            // made by the map, checked on) the plan's roads. An end itself holds no other
            // route that follows it.
            let road = arg(&args, "road")
                .map(|a| field(ctx, a, false).map(|f| (f, a)))
                .transpose()?;
            if let Some((f, a)) = &road {
                let end = |p: &str| {
                    arg(&args, p)
                        .and_then(|e| e.path.as_ref())
                        .and_then(|e| ctx.lookup(e))
                        .map(|(e, _)| e)
                };
                if let Some(which) = ["preceding", "succeeding"]
                    .into_iter()
                    .find(|p| end(p).as_deref() == Some(f.as_str()))
                {
                    return Err(a.site.err(
                        K::Unsatisfiable,
                        format!("expected a road holding both routes in road: (\"one route follows another in successive order\": the succeeding one after the preceding one's end), found `{f}`, the {which} route itself"),
                    ));
                }
            }
            match (made("preceding")?, made("succeeding")?) {
                (Some(preceding), Some(succeeding)) => MapKind::NamedInSequence {
                    preceding,
                    succeeding,
                },
                (None, None) => {
                    let (preceding, succeeding) =
                        (field_end("preceding")?, field_end("succeeding")?);
                    if preceding.kind == EndKind::Lane && succeeding.kind == EndKind::Lane {
                        MapKind::InSequence {
                            preceding: preceding.field,
                            succeeding: succeeding.field,
                            on_plan_roads: road.is_some(),
                        }
                    } else {
                        MapKind::RoutesInSequence {
                            preceding,
                            succeeding,
                        }
                    }
                }
                // A route the map makes beside a field: the field is bound to the element
                // after (before) it, as beside a road.
                (Some(route), None) | (None, Some(route)) => {
                    let first = call("preceding").is_some();
                    let which = if first { "preceding" } else { "succeeding" };
                    // A route through one point (no later points) has no end.
                    if first && matches!(&route, Route::Lane { then, .. } if then.is_empty()) {
                        return Err(need(which)?.site.err(
                            K::Road,
                            "expected a preceding route with an end (map.create_route([…]) through two or more points), found one from a single point, which runs on over the roads after it",
                        ));
                    }
                    let made_end = SeqEnd {
                        field: format!("the route the map makes at {}", need(which)?.site.at()),
                        kind: EndKind::Made,
                        lane: format!(
                            "the {which} route's lane ({name} at {}:{})",
                            site.pos.line, site.pos.col
                        ),
                        made: Some(route),
                    };
                    let (preceding, succeeding) = if first {
                        (made_end, field_end("succeeding")?)
                    } else {
                        (field_end("preceding")?, made_end)
                    };
                    MapKind::RoutesInSequence {
                        preceding,
                        succeeding,
                    }
                }
            }
        }
        "crossing_connects" => {
            let crossing = typed_field(ctx, need("crossing")?, "crossing")?;
            let own_lanes = arg(&args, "start_lane").is_none() && arg(&args, "end_lane").is_none();
            let (start_lane, end_lane) = if own_lanes {
                let of = |which: &str| {
                    format!(
                        "{crossing}'s {which} lane ({name} at {}:{})",
                        site.pos.line, site.pos.col
                    )
                };
                (of("start"), of("end"))
            } else {
                (lane("start_lane")?, lane("end_lane")?)
            };
            let start_angle = match arg(&args, "start_angle") {
                None => None,
                Some(a) => match a.number()? {
                    x if x > 0.0 && x < std::f64::consts::PI => Some(x),
                    x => {
                        return Err(a.site.err(
                            K::Value,
                            format!("expected a start_angle between 0 and 180 deg (the crossing's angle to start_lane's direction, towards end_lane), found {:.2} deg", x.to_degrees()),
                        ))
                    }
                },
            };
            MapKind::Crossing {
                crossing,
                start_lane,
                end_lane,
                start_s: arg(&args, "start_s_coord")
                    .map(|a| a.number())
                    .transpose()?,
                start_angle,
                own_lanes,
            }
        }
        "roads_follow_in_junction" => {
            let direction = member("direction")?;
            if let (Some(d), Some(a)) = (&direction, arg(&args, "direction")) {
                // §8.12 junction_direction's `other` is a way none of the four names; the
                // headings put every way through in one of them (`plan::map_junctions::Turn`).
                if !["straight", "right", "u_turn", "left"].contains(&d.as_str()) {
                    return Err(a.site.err(
                        K::Unsatisfiable,
                        format!("expected direction straight, right, u_turn or left, found {d}: every way through a junction is one of those four, read from the change of heading between the lane in and the lane out (within ±45° straight, 45° to 150° left or right, beyond 150° a U-turn), so no way is another"),
                    ));
                }
            }
            let road_arg = |p: &str| -> Result<Option<String>, Error> {
                arg(&args, p).map(|a| field(ctx, a, false)).transpose()
            };
            let junction = arg(&args, "junction")
                .map(|a| typed_field(ctx, a, "junction"))
                .transpose()?;
            let in_road = road_arg("in_road")?;
            let out_road = road_arg("out_road")?;
            let resulting = road_arg("resulting_route")?;
            let junction_route = road_arg("junction_route")?;
            let given = |p: &str| arg(&args, p).is_some();
            let own_lanes = !given("in_lane") && !given("out_lane");
            let mut roads = JunctionRoads {
                on_plan_roads: junction.is_some()
                    || in_road.is_some()
                    || out_road.is_some()
                    || resulting.is_some()
                    || junction_route.is_some(),
                junction,
                in_road,
                out_road,
                junction_route,
                clockwise_count: given("clockwise_count")
                    .then(|| count("clockwise_count", None))
                    .transpose()?,
                number_of_roads: given("number_of_roads")
                    .then(|| count("number_of_roads", None))
                    .transpose()?,
                own_lanes,
            };
            let (in_lane, out_lane) = if own_lanes {
                // The modifier's own lanes, named for messages and unique to it.
                let of = |r: &Option<String>, what: &str| {
                    format!(
                        "{}'s lane {what} ({name} at {}:{})",
                        r.as_deref().unwrap_or("the road"),
                        site.pos.line,
                        site.pos.col
                    )
                };
                roads.on_plan_roads = true;
                (
                    of(&roads.in_road, "into the junction"),
                    of(&roads.out_road, "out of the junction"),
                )
            } else {
                (lane("in_lane")?, lane("out_lane")?)
            };
            MapKind::Junction {
                in_lane,
                out_lane,
                direction,
                roads,
            }
        }
        // `read` reads only the names of MAP_MODIFIERS, each matched above: every map
        // modifier of the standard library (§8.12.2.2) but set_map_file, read where the map
        // file is named (`crate::map_file`).
        other => {
            return Err(site.err(
                K::Modifier,
                format!("expected a map modifier of §8.12.2.2 (number_of_lanes, start_lane, end_lane, lane_side, compound_lane_side, routes_overlap, routes_are_in_sequence, routes_are_opposite, roads_follow_in_junction, crossing_connects, set_traffic_lights_control_file), found {other}(…)"),
            ));
        }
    };
    Ok(MapModifier {
        kind,
        name: name.to_string(),
        site,
    })
}

/// The path of the free field `a` names: a lane (`lane`, `compound_lane`) with `lane`, else a
/// route bound to the plan's roads (`route`, `road`, `lane_section`, `compound_route`).
fn field(ctx: &Ctx<'_>, a: &Arg, lane: bool) -> Result<String, Error> {
    let found = a.path.as_ref().and_then(|p| {
        ctx.lookup(p).and_then(|(p, v)| match v {
            Value::RunTime(t) => Some((p, t.clone())),
            _ => None,
        })
    });
    // A field whose value is another free field is that field (`route::valued_route`); one
    // whose value is a route the map makes is no field to bind.
    let found = match found
        .as_ref()
        .and_then(|(p, _)| super::route::valued_route(ctx, p))
    {
        None => found,
        Some(Ok(Route::Free { field, .. })) => ctx.lookup(&field).and_then(|(p, v)| match v {
            Value::RunTime(t) => Some((p, t.clone())),
            _ => None,
        }),
        Some(Ok(_)) => {
            return Err(a.site.err(
                K::Argument,
                format!(
                    "expected a {} field nothing defines, found `{}`, given a route the map makes at its declaration (its roads are named, not bound or checked as the plan's)",
                    if lane { "lane" } else { "route" },
                    a.path.as_deref().unwrap_or_default()
                ),
            ))
        }
        Some(Err(e)) => return Err(e),
    };
    let fits = |t: &str| {
        if lane {
            super::route::ONE_LANE
                .iter()
                .any(|k| super::route::is_a(ctx, t, k))
        } else {
            super::route::WHOLE_ROAD
                .iter()
                .any(|k| super::route::is_exactly_or_user(ctx, t, k))
        }
    };
    match found {
        Some((p, t)) if fits(&t) => Ok(p),
        _ => Err(a.site.err(
            K::Argument,
            format!(
                "expected a {} field nothing defines, found another expression",
                if lane {
                    "lane (or compound_lane)"
                } else {
                    "route (route, road, lane_section or compound_route)"
                }
            ),
        )),
    }
}

/// The path of the free field `a` names, of type `ty` (`junction`, `crossing`) or one
/// inheriting it.
fn typed_field(ctx: &Ctx<'_>, a: &Arg, ty: &str) -> Result<String, Error> {
    match a.path.as_ref().and_then(|p| ctx.lookup(p)) {
        Some((p, Value::RunTime(t))) if super::route::is_a(ctx, t, ty) => Ok(p),
        _ => Err(a.site.err(
            K::Argument,
            format!("expected a {ty} field nothing defines, found another expression"),
        )),
    }
}

/// Whether the field at `path` is of type `ty` (or inherits it).
fn is_type(ctx: &Ctx<'_>, path: &str, ty: &str) -> bool {
    ctx.lookup(path)
        .is_some_and(|(_, v)| matches!(v, Value::RunTime(t) if super::route::is_a(ctx, t, ty)))
}
