//! `walk()` along a crossing the map bound (ASAM OpenSCENARIO DSL 2.1 §8.8.4.1 `walk`, §8.9
//! `along`, §8.12.2.2.9 `crossing_connects`): a person (or an animal, §8.7.8: the standard's
//! `crossing_use` has `animal`) crosses the road from the crossing's start lane to its end lane.
//!
//! | form | lowered to | ends |
//! | --- | --- | --- |
//! | `p.walk() with: along(c)` | FollowTrajectoryAction in following mode `position` along the straight line from the start lane's centre to the end lane's (`map_crossings`), timed from the phase start at the walker's speed: `speed(v)` of the phase, else the speed it has | when it reaches the end lane's centre, the line's length over the speed |
//!
//! The walker must be at the crossing's start when the walk starts (a first phase places it
//! there; a later one checks it, 0.5 m), moving, and the phase's start known to the plan; the
//! crossing walked whole (`start_offset`/`end_offset` are errors, `crate::resolve`). A vehicle
//! or another action along a crossing is an error at `along`. The plan has the walker at the
//! end lane's centre from the end on; in between it keeps the walker's track along its lane
//! (as for `follow_trajectory`), since the engine moves it.

use scenario::FollowingMode;

use super::path_shape::along as trajectory;
use super::planner::Planner;
use super::speed_actions::Slot;
use super::types::{Planned, When, POSITION_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Action, ActorKind, Along, At, Invoke, ModKind, Modifier, Phase, Route};

impl Planner<'_> {
    /// Plans `inv`, a walk along the crossing `along` names, for one walker.
    pub(super) fn plan_crossing_walk(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        mods: &[Modifier],
        along: &Along,
        Slot {
            target, t0, out, ..
        }: Slot<'_>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Route::Crossing { field } = &along.route else {
            return Ok(None);
        };
        let walker = matches!(
            self.entities[self.index[target]].data.kind,
            ActorKind::Walker(_)
        );
        if inv.kind != Action::Move || !walker {
            return Err(along.site.err(
                K::Unsupported,
                format!("expected a person's walk() along crossing `{field}` (a person crosses the road on it), found `{target}`'s {}()", inv.action),
            ));
        }
        let Some(c) = self.crossings.get(field).cloned() else {
            return Err(along.site.err(
                K::Road,
                format!("expected crossing `{field}` bound to a crosswalk of the map by map.crossing_connects(crossing: {field}, …), found no such modifier"),
            ));
        };
        let Some(t) = t0 else {
            return Err(along.site.err(
                K::Unsatisfiable,
                format!("expected a phase start the plan knows for a walk along crossing `{field}`, found one after a run-time condition"),
            ));
        };
        let (lane0, s0, w0) = c.crossing.start;
        let (lane1, s1, w1) = c.crossing.end;
        let (s0, s1) = (c.road_start + s0, c.road_start + s1);
        let (lane, s, w) = (
            self.track(target).lane(t),
            self.s_at(target, t),
            self.t_at(target, t),
        );
        if lane != lane0
            || (s - s0).abs() > POSITION_TOLERANCE
            || (w - w0).abs() > POSITION_TOLERANCE
        {
            return Err(along.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` at the start of crossing `{field}` ({}: lane {lane0} at s = {s0:.2} m, t = {w0:.2} m) when its walk starts, found it in lane {lane} at s = {s:.2} m, t = {w:.2} m", c.why),
            ));
        }
        let v = match mods
            .iter()
            .find(|m| m.kind == ModKind::Speed && m.at != At::End)
        {
            Some(m) => self.speed_value(m, t0)?.0,
            None => self.track(target).at(t).1,
        };
        if v <= 0.0 {
            return Err(along.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` walking at the start of its walk along crossing `{field}` (speed(…) in the phase), found it standing"),
            ));
        }
        let ends = self
            .road
            .world_pose(s0, w0)
            .zip(self.road.world_pose(s1, w1));
        // Both ends lie on a road of the plan (`map_lanes` binds crossings there).
        let Some(((x0, y0, _), (x1, y1, _))) = ends else {
            return Ok(None);
        };
        let h = (y1 - y0).atan2(x1 - x0);
        let span = (x1 - x0).hypot(y1 - y0) / v;
        let n = name("crossing");
        let action = trajectory(
            &n,
            &[(x0, y0, h), (x1, y1, h)],
            Some(&[0.0, span]),
            false,
            FollowingMode::Position,
            &along.site,
        );
        out.push(Planned::with_phase(target, n.clone(), action, &p.site));
        self.arrive(target, t, span, (lane1, s1, 0.0));
        Ok(Some(self.ends(t0, span, &n, p)))
    }
}
