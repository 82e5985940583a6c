//! The actions that move an actor along given points (ASAM OpenSCENARIO DSL 2.1 §8.8.2.17
//! `follow_trajectory`, §8.8.2.16 `follow_path`), as the standard's tables say when each starts
//! and ends:
//!
//! | action | lowered to | ends |
//! | --- | --- | --- |
//! | `follow_trajectory(absolute: trajectory)` | FollowTrajectoryAction along the polyline of the points (world x, y), each reached at its time stamp (a relative time reference from the action's start, offset by the first stamp), following mode `position` | at the last time stamp |
//! | `follow_path(…)` | an error: a `path` is a `route`, whose values the constraint solver leaves to the runtime, so no program can give its points | |
//!
//! A trajectory's points must be at least two, as many as its time stamps, the stamps rising;
//! `interpolation: smooth`, `relative:` trajectories and `start_offset`/`end_offset` are errors
//! (not run). The points' orientations are not read: the heading is the polyline's. The actor
//! is where the first point is at the start (the engine's FollowTrajectoryAction in `position`
//! mode puts it on the trajectory); the plan puts it in the lane and at the s of the last point.

use super::planner::Planner;
use super::position_actions::polyline;
use super::speed_actions::Slot;
use super::types::{Planned, When};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{arg, Action, Invoke, Phase, Place, PlaceArg};

impl Planner<'_> {
    /// Plans `inv`'s `follow_trajectory` or `follow_path` for one actor; returns when it ends.
    pub(super) fn plan_trajectory_action(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        slot: Slot<'_>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Slot {
            target, t0, out, ..
        } = slot;
        for param in [
            "relative",
            "reference",
            "transform",
            "start_offset",
            "end_offset",
        ] {
            if let Some(a) = arg(&inv.args, param) {
                return Err(a.site.err(
                    K::Unsupported,
                    format!("expected an absolute {} in {}(…), found `{param}:` (relative ones and offsets along them are not run)", if inv.kind == Action::FollowPath { "path" } else { "trajectory" }, inv.action),
                ));
            }
        }
        if inv.kind == Action::FollowPath {
            let site = arg(&inv.args, "absolute").map_or(&p.site, |a| &a.site);
            return Err(site.err(
                K::Unsupported,
                "expected a path the runtime can follow, found follow_path(…): a path is a route, whose values the constraint solver leaves to the runtime, so no program gives its points (use follow_trajectory with a trajectory, or change_position)",
            ));
        }
        let Some(
            place @ PlaceArg {
                place:
                    Place::Trajectory {
                        points,
                        times,
                        smooth,
                    },
                site,
                ..
            },
        ) = inv.places.first()
        else {
            return Err(p.site.err(
                K::Argument,
                "expected an absolute trajectory in follow_trajectory(…) (one of absolute and relative is mandatory), found none",
            ));
        };
        if *smooth {
            return Err(site.err(
                K::Unsupported,
                "expected a trajectory with interpolation: straight_line, found smooth (not run)",
            ));
        }
        let rising = times.windows(2).all(|w| w[1] > w[0]);
        if points.len() < 2 || points.len() != times.len() || !rising {
            return Err(site.err(
                K::Argument,
                format!(
                    "expected two or more points with as many rising time stamps, found {} points and {} time stamps{}",
                    points.len(),
                    times.len(),
                    if rising { "" } else { " not rising" }
                ),
            ));
        }
        let span = times[times.len() - 1] - times[0];
        let (x1, y1) = points[points.len() - 1];
        let (lane, s1, offset) = self.lane_position(&PlaceArg {
            place: Place::World {
                x: x1,
                y: y1,
                z: 0.0,
            },
            ..place.clone()
        })?;
        let n = name("follow_trajectory");
        out.push(Planned::with_phase(
            target,
            n.clone(),
            polyline(&n, points, Some(times), site),
            &p.site,
        ));
        if let Some(t) = t0 {
            // At the end: the last point, at the last segment's speed.
            let k = points.len() - 1;
            let (xa, ya) = points[k - 1];
            let v = (x1 - xa).hypot(y1 - ya) / (times[k] - times[k - 1]);
            let s_plan = self.s_at(target, t + span);
            let tr = self.track_mut(target);
            tr.ramp(t + span, t + span, v);
            tr.jump(t + span, s1 - s_plan);
            tr.set_lane(t + span, lane);
            tr.set_offset(t + span, offset);
            tr.add_move(t, t + span);
        }
        Ok(Some(self.ends(t0, span, &n, p)))
    }
}
