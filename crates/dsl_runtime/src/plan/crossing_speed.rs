//! An action on the speed or acceleration along a crossing the map bound (ASAM OpenSCENARIO
//! DSL 2.1 §8.8.2 `change_speed`, `keep_speed`, `assign_speed`, `remain_stationary`,
//! `change_acceleration`, `keep_acceleration`, `assign_acceleration`, with §8.9 `along` and
//! §8.12.2.2.9 `crossing_connects`): the crossing's line is the path (`along`: "the actor
//! moves along the route"), the action's the speed profile along it — the walker's speed
//! changes as the action says while it follows the crossing's line.
//!
//! | part | lowered to |
//! | --- | --- |
//! | the path | FollowTrajectoryAction along the walked part's straight line (`crossing_walk`) without a time reference: the lateral domain only, so the actor moves along it at its own speed |
//! | the speed | the action's own SpeedActions (`speed_actions`), as without `along` |
//!
//! The phase ends as the action's does: where the action ends on its own (a speed reached),
//! at the phase's own end, or else where the actor reaches the walked part's end (the line
//! ends the walk, as `walk()`'s). Reaching the line's end before the phase ends is an error at
//! `along` (the actor would leave the crossing mid-phase), as is never reaching it in a phase
//! with no other end (an actor standing on it). The plan has the actor at the point of the
//! line it reaches when the phase ends (its distance along the line is the planned speed's
//! integral), from where a later phase's `along(c, start_offset: …)` goes on.

use scenario::FollowingMode;

use super::crossing_walk::{point_at, Walk};
use super::path_shape::along as trajectory;
use super::planner::Planner;
use super::speed_actions::Slot;
use super::types::{CrossingLine, Planned, When};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Invoke, Phase};

/// How far past the line's end (m) the planned distance may reach at the phase's end: float
/// round-off of the speed's integral.
const LINE_END_TOLERANCE: f64 = 1e-6;
/// How long (s) the plan waits for an actor to reach the line's end in a phase with no other.
const REACH_HORIZON: f64 = 3600.0;
/// Halvings of the bracket of that moment: below f64's resolution of it.
const BISECTIONS: usize = 60;

impl Planner<'_> {
    /// Plans `inv`, an action on the speed or acceleration, along `field`'s walked part
    /// (`part`: its start, where the actor is at the phase start, and its end); returns when
    /// the phase ends by it (module doc).
    pub(super) fn speed_along_crossing(
        &mut self,
        p: &Phase,
        (inv, field): (&Invoke, &str),
        walk: &Walk<'_>,
        slot: Slot<'_>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let (target, len, t, along) = (slot.target, slot.len, walk.t, walk.along);
        let again = Slot {
            out: &mut *slot.out,
            persist: &mut *slot.persist,
            ..slot
        };
        let own_end = self.plan_speed_action(p, inv, again, name)?;
        let s_start = self.track(target).at(t).0;
        let walked = |planner: &Self, span: f64| planner.track(target).at(t + span).0 - s_start;
        let reaches = |planner: &Self, length: f64| -> Option<f64> {
            let mut hi = 1.0;
            while walked(planner, hi) < length {
                hi *= 2.0;
                if hi > REACH_HORIZON {
                    return None;
                }
            }
            let (mut a, mut b) = (0.0, hi);
            for _ in 0..BISECTIONS {
                let mid = (a + b) / 2.0;
                if walked(planner, mid) < length {
                    a = mid;
                } else {
                    b = mid;
                }
            }
            Some(b)
        };
        let own = match (&own_end, len) {
            (Some(When::At(te)), _) => Some(te - t),
            (_, Some(l)) => Some(l),
            _ => None,
        };
        let settled = self.settle_walk(walk, target, &|pl, length| {
            own.or_else(|| reaches(pl, length))
        })?;
        let Some((span, (start, end))) = settled else {
            return Err(along.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` to reach the end of crossing `{field}` under {}(), its phase's only end, found it stopping short of it within {REACH_HORIZON} s", inv.action),
            ));
        };
        let phase_end = match own {
            Some(_) => own_end,
            None => Some(When::At(t + span)),
        };
        let ends = [start, end].map(|(_, s, w)| self.road.world_pose(s, w));
        // Both ends lie on a road of the plan (`map_lanes` binds crossings there).
        let [Some((x0, y0, _)), Some((x1, y1, _))] = ends else {
            return Ok(None);
        };
        let length = (x1 - x0).hypot(y1 - y0);
        let d = walked(self, span);
        if d > length + LINE_END_TOLERANCE {
            let at = reaches(self, length).map_or(f64::NAN, |r| t + r);
            return Err(along.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` on crossing `{field}` until its phase ends at {:.2} s, found it at the crossing's end ({length:.2} m along its line) at {at:.2} s under {}() (give the phase an end by then, or go on in a phase along another route)", t + span, inv.action),
            ));
        }
        let n = name("crossing");
        let h = (y1 - y0).atan2(x1 - x0);
        let action = trajectory(
            &n,
            &[(x0, y0, h), (x1, y1, h)],
            None,
            false,
            FollowingMode::Position,
            &along.site,
        );
        slot.out
            .push(Planned::with_phase(target, n, action, &p.site));
        let f = d / length;
        let (s, w) = (
            start.1 + f * (end.1 - start.1),
            start.2 + f * (end.2 - start.2),
        );
        let reached = point_at(&self.road, field, (s, w), along)?;
        let (lane, s, w) = reached;
        let offset = w - self.road.lane_center(lane, s);
        self.arrive(target, t, span, (lane, s, offset));
        let line = CrossingLine {
            uniform: false,
            ..CrossingLine::new(target, (t, t + span), start, reached)
        };
        self.crossing_lines.push(line);
        Ok(phase_end)
    }
}
