//! Relative trajectories and paths (ASAM OpenSCENARIO DSL 2.1 §8.8.2.16-17 `follow_path` /
//! `follow_trajectory` with `relative:`, `reference` and `transform`; §8.12
//! `relative_trajectory_pose_3d`, `relative_trajectory_st`, `relative_path_pose_3d`,
//! `relative_path_st`, enum `relative_transform`), turned into world points against the
//! reference's pose at the action's start, which the plan knows:
//!
//! The points a program can write are pose_3d (x, y, yaw); route_point and odr_point points
//! are route elements, which the solver leaves to the runtime (an error where they are read).
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
use crate::resolve::{arg, Invoke, Phase, Place, PlaceArg, Val};

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
            None => "object_relative".to_string(),
        };
        let t = t0.ok_or_else(|| {
            p.site.err(
                K::Unsatisfiable,
                format!("expected a phase start the plan knows for a relative {} (where `{r}` is then), found one after a run-time condition", if inv.kind.along_path() { "path" } else { "trajectory" }),
            )
        })?;
        let road = &self.road;
        let (s_r, lane_r) = (self.s_at(r, t), self.track(r).lane(t));
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
        let world = points
            .iter()
            .map(|&(x, y, yaw)| match transform.as_str() {
                "world_relative" => Ok((x_r + x, y_r + y, yaw)),
                // The road's coordinates (its s-axis, as yaw relative to the road, §8.9.9): for
                // a reference driving against s, x along −u and y to the right of its travel.
                "road_relative" if road.is_against() => {
                    on_road(s_r - x, t_r - y, yaw).map(|(x, y, h)| (x, y, h - std::f64::consts::PI))
                }
                "road_relative" => on_road(s_r + x, t_r + y, yaw),
                "lane_relative" => on_road(s_r + x, road.lane_center(lane_r, s_r + x) + y, yaw),
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
