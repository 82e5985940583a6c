//! The lane a `lane` field names where `change_lane(target: l)` or `follow_lane(target: l)`
//! uses it (ASAM OpenSCENARIO DSL 2.1 §8.8.3.2, §8.8.3.3 `target: lane`; §8.12 `lane`).
//!
//! The constraint solver leaves road-network values to the runtime, so a lane field gets its
//! lane here, once for the run, and every use of the field is that lane:
//!
//! - **bound by the map's modifiers** (`map.start_lane(l)`, `map.end_lane(l)`,
//!   `map.lane_side(l, side, k, count)`; `map_lanes`) before anything is planned;
//! - **bound by `along(l)`**: the lane of the first actor planned along `l`
//!   (`route::check`);
//! - **drawn at its first use** otherwise: §7 (constraint semantics) gives an attribute that
//!   nothing constrains any legal value, randomized. For `change_lane(target: l)` the legal
//!   values are the driving lanes of the plan road at the action's start in the actor's
//!   direction of travel other than its own lane; for `follow_lane(target: l)`, which follows
//!   the lane the actor is in (its semantic clarification is `keep_lane()`), that lane.
//!
//! A bound lane that the use cannot take is an error at the argument, naming what bound it:
//! a lane of a road the plan does not drive on, a lane running against the actor's direction,
//! the actor's own lane as a lane change's target, another lane than the actor's for
//! `follow_lane`. `target:` beside `num_of_lanes`, `side` or `reference` (which name the
//! target relative to an actor) is an error at the latter.

use super::planner::Planner;
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{arg, Invoke, LaneField};

impl Planner<'_> {
    /// The lane `change_lane(target: f)` of `inv` moves `actor` into, from its lane `own` at
    /// the plan's s `s` where the action starts.
    pub(super) fn change_lane_field(
        &mut self,
        inv: &Invoke,
        f: &LaneField,
        actor: &str,
        own: i32,
        s: f64,
    ) -> Result<i32, Error> {
        for name in ["num_of_lanes", "side", "reference"] {
            if let Some(a) = arg(&inv.args, name) {
                return Err(a.site.err(
                    K::Argument,
                    format!("expected either target: or {name}: in change_lane(…) (target: names the lane itself, {name}: one relative to an actor), found both"),
                ));
            }
        }
        let lanes = self.road.driving_lanes(s);
        // The road's own s, for messages (against s the plan's s is u, `crate::road`).
        let road_s = self.road.road_at(s).1;
        let (lane, why) = match self.route_lanes.get(&f.path) {
            Some((l, why)) => (*l, why.clone()),
            None => {
                let choices: Vec<i32> = lanes.iter().copied().filter(|l| *l != own).collect();
                if choices.is_empty() {
                    return Err(f.site.err(
                        K::Unsatisfiable,
                        format!(
                            "expected a driving lane other than `{actor}`'s own (lane {own}) on road {} at s = {road_s:.2} m to draw `{}` from, found none",
                            self.road.road_at(s).0.id,
                            f.path
                        ),
                    ));
                }
                let l = choices[self.choose(choices.len())];
                let why = format!("drawn for `{}` at {}", f.path, f.site.at());
                self.route_lanes.insert(f.path.clone(), (l, why.clone()));
                (l, why)
            }
        };
        self.on_plan_roads(f, lane, &why, s)?;
        if !lanes.contains(&lane) {
            let road = &self.road.road_at(s).0.id;
            let against = if (lane > 0) != self.road.is_against() {
                ", which runs against it"
            } else {
                ""
            };
            return Err(f.site.err(
                K::Unsatisfiable,
                format!("expected a driving lane of road {road} in the direction `{actor}` drives (right-hand traffic: lanes {lanes:?}) at s = {road_s:.2} m for `{}`, found lane {lane} ({why}){against}", f.path),
            ));
        }
        if lane == own {
            return Err(f.site.err(
                K::Unsatisfiable,
                format!("expected a lane other than `{actor}`'s own as the target of change_lane(…), found `{}` = lane {lane} ({why}), the lane it is in at the action's start", f.path),
            ));
        }
        Ok(lane)
    }

    /// Checks `follow_lane(target: f)` for `actor` in lane `own` at the action's start: `f` is
    /// that lane (bound to it when nothing bound it before).
    pub(super) fn follow_lane_field(
        &mut self,
        f: &LaneField,
        actor: &str,
        own: i32,
        s: f64,
    ) -> Result<(), Error> {
        let Some((lane, why)) = self.route_lanes.get(&f.path).cloned() else {
            self.route_lanes.insert(
                f.path.clone(),
                (
                    own,
                    format!("the lane `{actor}` follows at {}", f.site.at()),
                ),
            );
            return Ok(());
        };
        self.on_plan_roads(f, lane, &why, s)?;
        if lane != own {
            return Err(f.site.err(
                K::Unsatisfiable,
                format!("expected `{actor}` in lane {lane} (`{}`, {why}) at the start of follow_lane(target: {}), which follows the lane the actor is in (its semantic clarification is keep_lane(); change_lane(target: {}) moves into it), found lane {own}", f.path, f.path, f.path),
            ));
        }
        Ok(())
    }

    /// A lane the map's modifiers bound `f` to lies on a road of the plan, and the action's
    /// start (the plan's s `s`) in its lane section.
    fn on_plan_roads(&self, f: &LaneField, lane: i32, why: &str, s: f64) -> Result<(), Error> {
        match self.lane_roads.get(&f.path) {
            Some((road, None)) => Err(f.site.err(
                K::Road,
                format!(
                    "expected a lane of the roads the plan drives on ({}) for `{}`, found lane {lane} of road {road} ({why})",
                    self.road.ids().join(", "),
                    f.path
                ),
            )),
            // The span is in +s; against s (`crate::road`) the action's s is u = L − s.
            Some((road, Some((a, b))))
                if self.road.forward_s(s) < *a || self.road.forward_s(s) > *b =>
            {
                Err(f.site.err(
                K::Road,
                format!(
                    "expected the action to start in the lane section of `{}` (lane {lane} of road {road}, {why}: s from {a:.2} m to {b:.2} m), found it at s = {:.2} m",
                    f.path,
                    self.road.forward_s(s)
                ),
            ))
            }
            _ => Ok(()),
        }
    }
}
