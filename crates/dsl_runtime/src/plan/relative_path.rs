//! Relative trajectories and paths (ASAM OpenSCENARIO DSL 2.1 §8.8.2.16-17 `follow_path` /
//! `follow_trajectory` with `relative:`, `reference` and `transform`; §8.12
//! `relative_trajectory_pose_3d`, `relative_trajectory_st`, `relative_path_pose_3d`,
//! `relative_path_st`, enum `relative_transform`), turned into world points against the
//! reference's pose at the action's start, which the plan knows:
//!
//! A point is a pose_3d (x, y, yaw; `relative_*_pose_3d`, §8.12.32, §8.12.39), a route_point
//! (`relative_*_st`, §8.12.33, §8.12.40) or an odr_point (`relative_*_odr`, §8.12.34,
//! §8.12.41). Route and odr points are route elements the solver leaves to the runtime: the
//! program gives them by keeps of the field's declaration (`keep(it.points == [p0, p1])`,
//! `keep(it.points[i] == p)`, `resolve::position`), each `map.create_route_point(route, s,
//! t)` or `map.create_odr_point(road_id, lane_id, s, t)`. The library's declarations give
//! these structs their points' types only (`points: list of route_point`, `list of
//! odr_point`, `osc/standard/map.osc`); the standard's text of §8.12.33-34 and §8.12.40-41 was
//! not found in the public pages searched (they stop at §8.12.2.1), so the placing is oscsim's
//! choice, as the struct names say ("st": s and t; "odr": OpenDRIVE's road, lane, s and t) and
//! as 1.x places a RelativeRoadPosition or a RelativeLanePosition against its entity:
//! - a route point's s and t are road coordinates from the reference's at the action's start,
//!   placed as a pose_3d point (x = s, y = t, yaw 0) under `road_relative` (the default for
//!   these points) or `lane_relative` (t from the centre of the reference's lane) below, along
//!   the plan's roads: the route given to `create_route_point` is one the runtime chooses (a
//!   route the map makes is refused at the argument, `resolve::position`), its s and t along
//!   it and to its left: on a field `routes_are_opposite` binds against s, −s and −t of the
//!   road; on a road field `routes_are_in_sequence` binds, along the sequence of roads (the
//!   plan's roads in +s: s continuing from one road onto the next). `world_relative` and
//!   `object_relative` (frames of x and y, not of s and t) are errors at the argument;
//! - an odr point names its road and lane (OpenDRIVE ids, not relative); its s is from the
//!   reference's s along the plan's roads, its t from its lane's centre, heading the road's,
//!   in OpenDRIVE's axes (s along the road's s-axis, t to its left) also for a reference
//!   driving against s;
//!   the road found there must be the one it names (else an error at the path). `transform`
//!   as for route points (both read the same: the lane is the point's own).
//!
//! | `transform` | a point (x, y, yaw) becomes |
//! | --- | --- |
//! | `object_relative` (the default) | in the reference's frame: x_r + x·cos h_r − y·sin h_r, y_r + x·sin h_r + y·cos h_r, heading h_r + yaw |
//! | `world_relative` | the world's axes from the reference: x_r + x, y_r + y, heading yaw |
//! | `road_relative` | road coordinates from the reference's: s_r + x along the road, t_r + y across it, heading the road's there + yaw |
//! | `lane_relative` | along the road from the reference, across from the centre of its lane: s_r + x, (that lane's centre at s_r + x) + y, heading the road's + yaw |
//!
//! h_r is the heading of the road at the reference (the plan's actors drive along their
//! lanes). For a reference driving against s (`crate::road`) the plan's frame is its view, so
//! h_r is its heading (the road's + π) and `lane_relative` runs along its lane's driving
//! direction; `road_relative` keeps the road's own s-axis and t (x along +s, y to the road's
//! left, heading the road's + yaw), as yaw relative to the road is "relative to road s-axis"
//! (§8.9.9). The points are fixed at the action's start (the trajectory does not move with the
//! reference afterwards, as 1.x resolves a trajectory's relative positions when its action
//! starts). A relative trajectory without a `reference`, `reference`/`transform` beside an
//! absolute one, and a start the plan does not know are errors.

use super::planner::Planner;
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{arg, Invoke, Phase, Place, PlaceArg, RelativePoints, Val};

impl Planner<'_> {
    /// The absolute trajectory or path of `inv`'s `relative:` argument at the action's start
    /// `t0`, or `None` when it has none.
    pub(super) fn absolute_place(
        &self,
        p: &Phase,
        inv: &Invoke,
        t0: Option<f64>,
    ) -> Result<Option<PlaceArg>, Error> {
        let Some(
            given @ PlaceArg {
                place:
                    Place::Relative {
                        points,
                        times,
                        smooth,
                        of,
                    },
                site,
                ..
            },
        ) = inv.places.iter().find(|a| a.param == "relative")
        else {
            for param in ["reference", "transform"] {
                if let Some(a) = arg(&inv.args, param) {
                    return Err(a.site.err(
                        K::Argument,
                        format!("expected `{param}:` only with a relative path or trajectory in {}(…), found it beside an absolute one", inv.action),
                    ));
                }
            }
            return Ok(None);
        };
        let reference = arg(&inv.args, "reference")
            .ok_or_else(|| super::action_args::missing(p, inv, "reference"))?;
        let r = reference
            .path
            .as_ref()
            .filter(|x| self.index.contains_key(*x))
            .ok_or_else(|| {
                reference.site.err(
                    K::UnknownActor,
                    "expected a physical object of the scenario as the reference, found another value",
                )
            })?;
        let transform = match arg(&inv.args, "transform") {
            Some(a) => match a.eval()? {
                Val::Enum(m) => m,
                _ => {
                    return Err(a.site.err(
                        K::Argument,
                        "expected a relative_transform, found another value",
                    ))
                }
            },
            // Route and odr points are road coordinates (module doc).
            None if *of == RelativePoints::Pose => "object_relative".to_string(),
            None => "road_relative".to_string(),
        };
        if *of != RelativePoints::Pose
            && !matches!(transform.as_str(), "road_relative" | "lane_relative")
        {
            return Err(arg(&inv.args, "transform").map_or(site, |a| &a.site).err(
                K::Argument,
                format!("expected road_relative or lane_relative for a relative {} of route or odr points (their s and t are road coordinates), found {transform}", if inv.kind.along_path() { "path" } else { "trajectory" }),
            ));
        }
        let t = t0.ok_or_else(|| {
            p.site.err(
                K::Unsatisfiable,
                format!("expected a phase start the plan knows for a relative {} (where `{r}` is then), found one after a run-time condition", if inv.kind.along_path() { "path" } else { "trajectory" }),
            )
        })?;
        let road = &self.road;
        let (s_r, lane_r) = (self.s_at(r, t), self.lane_now(r, t));
        let t_r = self.t_at(r, t);
        let off_road = |s: f64| {
            site.err(
                K::Unsatisfiable,
                format!("expected the relative points on the plan road, found s = {s:.2} m off it"),
            )
        };
        let (x_r, y_r, h_r) = road.world_pose(s_r, t_r).ok_or_else(|| off_road(s_r))?;
        let on_road = |s: f64, t: f64, yaw: f64| {
            road.world_pose(s, t)
                .map(|(x, y, h)| (x, y, h + yaw))
                .ok_or_else(|| off_road(s))
        };
        let odr_elsewhere = |i: usize, id: &str, x: f64, here: &str| {
            site.err(
                K::Unsatisfiable,
                format!("expected odr point {i} of the relative path on its road {id}, {x:.2} m along the road's s from `{r}`, found road {here} there"),
            )
        };
        let lane_of = |i: usize| match of {
            RelativePoints::Odr(lanes) => lanes.get(i),
            _ => None,
        };
        // A route point's s and t run along its route and to its left (§8.12 route_point): on
        // a route field `routes_are_opposite` binds to the plan's roads driven against s
        // (`against::bind_routes`) they are −s and −t of the road (as an absolute route
        // point's, `position_actions`) under `road_relative`, and of the reference's lane
        // where it drives in +s under `lane_relative` (a lane driven against s has the route's
        // direction already) (issue 27: before, the binding was ignored). On a road field
        // `routes_are_in_sequence` binds to a road of the plan (`route_roads`) they run along
        // the sequence of roads, which are the plan's roads in +s in that order: s from the
        // reference's continuing from one road onto the next, as on a free route.
        let mut along = Vec::with_capacity(points.len());
        for (i, &(x, y, yaw)) in points.iter().enumerate() {
            let field = match of {
                RelativePoints::St(routes) => routes.get(i).and_then(Option::as_ref),
                _ => None,
            };
            let back = field.is_some_and(|f| self.against_routes.contains_key(f));
            let turn = back && (transform == "road_relative" || !road.is_against());
            along.push(match turn {
                true => (-x, -y, yaw),
                false => (x, y, yaw),
            });
        }
        let world = along
            .iter()
            .enumerate()
            .map(|(i, &(x, y, yaw))| match (lane_of(i), transform.as_str()) {
                // An odr point's lane is its own, t from that lane's centre, in OpenDRIVE's
                // axes (s along the road's reference line, t to its left, heading the road's):
                // for a reference driving against s, x along −u and y to the right of its
                // travel, as `road_relative` (issue 27: before, along its travel and to its
                // left, so an oncoming actor's points of smaller s lay behind it).
                (Some((id, lane)), _) if road.is_against() => {
                    match road.road_at(s_r - x).0.id.as_str() {
                        here if here == id => {
                            on_road(s_r - x, road.lane_center(*lane, s_r - x) - y, yaw)
                                .map(|(x, y, h)| (x, y, h - std::f64::consts::PI))
                        }
                        here => Err(odr_elsewhere(i, id, x, here)),
                    }
                }
                (Some((id, lane)), _) => match road.road_at(s_r + x).0.id.as_str() {
                    here if here == id => {
                        on_road(s_r + x, road.lane_center(*lane, s_r + x) + y, yaw)
                    }
                    here => Err(odr_elsewhere(i, id, x, here)),
                },
                (None, "world_relative") => Ok((x_r + x, y_r + y, yaw)),
                // The road's coordinates (its s-axis, as yaw relative to the road, §8.9.9): for
                // a reference driving against s, x along −u and y to the right of its travel.
                (None, "road_relative") if road.is_against() => {
                    on_road(s_r - x, t_r - y, yaw).map(|(x, y, h)| (x, y, h - std::f64::consts::PI))
                }
                (None, "road_relative") => on_road(s_r + x, t_r + y, yaw),
                (None, "lane_relative") => {
                    on_road(s_r + x, road.lane_center(lane_r, s_r + x) + y, yaw)
                }
                _ => {
                    let (sin, cos) = h_r.sin_cos();
                    Ok((x_r + x * cos - y * sin, y_r + x * sin + y * cos, h_r + yaw))
                }
            })
            .collect::<Result<Vec<_>, _>>()?;
        let place = if inv.kind.along_path() {
            Place::Path {
                points: world,
                smooth: *smooth,
            }
        } else {
            Place::Trajectory {
                points: world,
                times: times.clone(),
                smooth: *smooth,
            }
        };
        Ok(Some(PlaceArg {
            place,
            ..given.clone()
        }))
    }
}
