//! A speed relative to another actor x at `at: all` (ASAM OpenSCENARIO DSL 2.1 §8.9 `speed(v,
//! faster_than/slower_than/same_as: x)`; §8.9.1.1.1: a constraint at `all` "holds throughout
//! the phase"; §8.9.1.1.3 `track: actual`, the default: x as it actually moves).
//!
//! The actor's speed is x's ± v at every step of the phase: the engine's continuous
//! SpeedAction to the RelativeTargetSpeed on x (lowered in `invoke`, in the actor's first phase
//! too, where the Init gives its start speed). The plan's track of the actor follows x's
//! planned speed profile over the phase (`Track::follow`, offset by ± v), so what the plan
//! derives from the actor later (its place at a later phase's start, relations to it) is
//! where the engine has it. Before, a first phase kept the speed x had at its start while x
//! changed speed (and a later phase's track did), and the run passed (issue 27, found in
//! review: ego `speed(same_as: lead)` at 10 m/s while lead accelerated to 16 m/s).
//!
//! Where x is moved by the engine (a gap action's or a driver model's controller, a member
//! of random traffic), the plan has no track of x: the actor's speed is the engine's from
//! the phase start, as an actor held to such an x by `position(…)` (`held_relation`).
//! `track: projected` (x's speed at the phase start, held) and `at: start` are a step at the
//! start and need none of this.

use super::planner::Planner;
use crate::error::{Error, ErrorKind as K};
use crate::resolve::Modifier;

impl Planner<'_> {
    /// Holds `target`'s speed at x's + `delta` over the phase from `t0` to `end` on the
    /// plan's track (module doc), or hands `target` to the engine where x is the engine's.
    pub(super) fn hold_speed(
        &mut self,
        target: &str,
        m: &Modifier,
        (x, delta): (&str, f64),
        t0: Option<f64>,
        end: Option<f64>,
    ) -> Result<(), Error> {
        if let Some(since) = self.engine_moved.get(x).copied() {
            // x's speed is the engine's from `since`: so is the actor's that follows it.
            let from = t0.or(since);
            self.engine_moves(target, from);
            return Ok(());
        }
        let Some(t0) = t0 else {
            // After a run-time start the engine's action alone: the plan's track of the
            // actor is not read from then on (`plan::runtime`).
            return Ok(());
        };
        let xs = self.track(x).clone();
        let te = end.unwrap_or(f64::INFINITY);
        self.track_mut(target)
            .follow(&xs, (t0, te), delta)
            .map_err(|t| {
                m.site.err(
                    K::Unsatisfiable,
                    format!("expected `{x}`'s speed profile one `{target}` can take from {t0:.2} s ({}(…) at: all), found a sinusoidal change of `{x}`'s under way then, from {t:.2} s", m.name),
                )
            })?;
        // x's speed where the hold ends (an end the plan does not know: at the start).
        let v = xs.at(end.unwrap_or(t0)).1 + delta;
        self.last_v.insert(target.to_string(), v);
        Ok(())
    }
}
