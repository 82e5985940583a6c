//! The sideways moves a route through points asks of an actor along it (ASAM OpenSCENARIO DSL
//! 2.1 §8.9 `along`, §8.12.2.1 `map.create_route`, `map.create_odr_point`): between two
//! points in other lanes, or at other offsets from their lanes' centres (`t`), the actor
//! changes lanes (its offset) so as to pass each point where it is.
//!
//! The standard says the route goes through its points and leaves the way between them to
//! `connect_points_by`; it does not say where a lane change between two points happens.
//! oscsim's choice: **over the whole stretch between the two points**, the actor in the first
//! point's lane and offset there and in the second's at the second, so each point holds
//! exactly and the points alone say where and over what length the change runs (a shorter
//! change is written as points closer together). It is oscsim's lane change to a place along
//! the road (`LateralAction::LaneChangeAt`, the engine's LaneChangeAction to the second
//! point's lane with its offset as targetLaneOffset, OpenSCENARIO 1.3 §7.4.3, one action for
//! a lane, an offset, or both), sinusoidal over the distance along the actor's lane from
//! where it is when the change starts to the second point, which it arrives at whatever its
//! speed does on the way. It starts when the plan has the actor at the first point (with the
//! phase, when the phase starts past it: over what is left of the stretch), or, on the
//! stretch right after another change, when that change ends (seen by the engine's triggers
//! in the step after: the next change starts up to one step's travel past its point).

//! In a phase that starts on a run-time condition the plan does not know where the actor is
//! then, so not which stretch it is on: each change starts when the engine has the actor at
//! its first point (oscsim's PlaceReached on the actor's s in the plan's measure), after the
//! change before it is complete, so it runs wherever the actor is when the phase starts. The
//! engine's check at the start holds it in the route's first lane (`route::check`); one past
//! the end of the first change then fails that change (its place is not ahead: an error
//! record and a failed run).
//!
//! The route decides the actor's lateral motion over the phase: a `lateral(…)` or lane change
//! beside it is an error at that modifier, as is a phase that ends before a change it has
//! begun is done (the actor would stop between two lanes; known only at a start the plan
//! knows).

use scenario::{
    ConditionEdge, ConditionGroup, ConditionKind, DynamicsShape, EntityCondition, LaneChangeAt,
    LaneChangeTarget, LateralAction, PrivateAction, StoryboardElementState, Trigger,
};

use super::planner::Planner;
use super::route::plan_points;
use super::types::{Planned, When, POSITION_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Along, At, ModKind, Modifier, Route};
use crate::trigger::action_state;

/// How close in time (s) two moments of the plan are taken as one.
const TIME_EPS: f64 = 1e-9;

/// How far short of a point (m) the plan takes the actor as there (round-off of its s).
const S_EPS: f64 = 1e-6;

/// How long past a phase start without an end the plan looks for the actor reaching a point
/// (s): a bound for the search, far beyond any scenario's run.
const SEARCH_HORIZON: f64 = 1e6;

impl Planner<'_> {
    /// Plans the lane changes `along` (holding `at`) asks of `target` in a phase from `t0` to `te` (when the
    /// plan knows them), beside the invocation's modifiers `mods`, into `out`, naming each
    /// action with `name`.
    pub(super) fn plan_route_moves(
        &mut self,
        (at, along): &(At, Along),
        mods: &[Modifier],
        target: &str,
        (t0, te): (Option<f64>, Option<f64>),
        name: &mut dyn FnMut(&str) -> String,
        out: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        // Only a route followed throughout (at: all, the default) moves the actor; at: start
        // or end the route only says where it is then.
        if *at != At::All || !matches!(along.route, Route::Lane { .. }) {
            return Ok(());
        }
        let points = plan_points(&self.road, &along.route);
        let moves = points
            .windows(2)
            .any(|w| w[0].1 != w[1].1 || (w[0].2 - w[1].2).abs() > f64::EPSILON);
        if !moves {
            return Ok(());
        }
        if let Some(m) = mods.iter().find(|m| {
            matches!(m.kind, ModKind::ChangeLane | ModKind::Lateral)
                || (m.kind == ModKind::Lane && m.at == At::End)
        }) {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!(
                    "expected no `{}(…)` beside {} (a route through points in other lanes or at other offsets moves the actor across between them), found one",
                    m.name,
                    along.site.at()
                ),
            ));
        }
        let Some(t0) = t0 else {
            self.route_moves_at_run_time(along, target, &points, name, out);
            return Ok(());
        };
        let s_start = self.s_at(target, t0);
        let horizon = te.unwrap_or(t0 + SEARCH_HORIZON);
        // The change before: its action's name and the time the plan ends it.
        let mut before: Option<(String, f64)> = None;
        for w in points.windows(2) {
            let ((sa, _, oa), (sb, lb, ob)) = (w[0], w[1]);
            if w[0].1 == lb && (oa - ob).abs() <= f64::EPSILON {
                continue;
            }
            // Passed before the phase.
            if sb <= s_start + POSITION_TOLERANCE {
                continue;
            }
            let (ta, from) = if sa <= s_start {
                (t0, s_start)
            } else {
                match self.time_reaching(target, sa, t0, horizon) {
                    Some(t) => (t, sa),
                    // Not at the stretch within the phase: nothing more to change.
                    None => break,
                }
            };
            let Some(tb) = self.time_reaching(target, sb, ta, horizon) else {
                let (road, s_end) = (self.road.road_at(sb), self.s_at(target, horizon));
                return Err(along.site.err(
                    K::Unsatisfiable,
                    format!(
                        "expected `{target}` to reach the route's point in lane {lb} (road {} at s = {:.2} m) within the phase, to end the change it begins at s = {from:.2} m, found it at s = {s_end:.2} m when the phase ends (the plan's s)",
                        road.0.id, road.1
                    ),
                ));
            };
            // Right after the change before: when it ends (the engine's actor is then at the
            // point, a little later than the plan has it: its speed runs along the change's
            // longer path); else at the time the plan has the actor at the first point.
            let start = match &before {
                Some((prev, end)) if (end - ta).abs() <= TIME_EPS => Some(When::Dyn(Trigger {
                    condition_groups: vec![ConditionGroup {
                        conditions: vec![action_state(
                            prev,
                            StoryboardElementState::EndTransition,
                            along.site.pos.clone(),
                        )],
                    }],
                })),
                _ => (ta > t0 + TIME_EPS).then_some(When::At(ta)),
            };
            let action = name("route");
            before = Some((action.clone(), tb));
            out.push(Planned {
                entity: target.to_string(),
                at: start,
                name: action,
                action: self.change_to_point(along, (sb, lb, ob)),
                site: along.site.clone(),
            });
            let tr = self.track_mut(target);
            tr.set_lane(tb, lb);
            tr.set_offset(tb, ob);
            tr.add_move(ta, tb);
        }
        Ok(())
    }

    /// The lane changes of `along` through `points` (`plan_points`) in a phase of `target`
    /// that starts on a run-time condition, into `out`: the plan does not know where the actor
    /// is then, so each change starts when the engine has the actor at its first point
    /// (oscsim's PlaceReached on the point's place in the plan's measure, at once when the
    /// actor is past it as the phase starts), and a change right after another once that one
    /// is complete too. The engine's check at the phase start holds the actor in the route's
    /// first lane on it (`route::check`); an actor past the end of the first change then is
    /// that change's failure (LaneChangeAt's place not ahead of it: an error record and a
    /// failed run), as the route's lane there is not the one it is in.
    fn route_moves_at_run_time(
        &self,
        along: &Along,
        target: &str,
        points: &[(f64, i32, f64)],
        name: &mut dyn FnMut(&str) -> String,
        out: &mut Vec<Planned>,
    ) {
        let mut before: Option<String> = None;
        for w in points.windows(2) {
            let ((sa, la, oa), (sb, lb, ob)) = (w[0], w[1]);
            if la == lb && (oa - ob).abs() <= f64::EPSILON {
                continue;
            }
            let mut conditions = vec![scenario::Condition {
                name: format!("{target} at the route's point s = {sa} m"),
                condition_edge: ConditionEdge::None,
                delay: 0.0,
                kind: ConditionKind::by_entity(
                    target,
                    EntityCondition::PlaceReached {
                        value: sa - S_EPS,
                        roads: self.chain(),
                    },
                ),
                pos: along.site.pos.clone(),
            }];
            if let Some(prev) = &before {
                conditions.push(action_state(
                    prev,
                    StoryboardElementState::CompleteState,
                    along.site.pos.clone(),
                ));
            }
            let action = name("route");
            before = Some(action.clone());
            out.push(Planned {
                entity: target.to_string(),
                at: Some(When::Dyn(Trigger {
                    condition_groups: vec![ConditionGroup { conditions }],
                })),
                name: action,
                action: self.change_to_point(along, (sb, lb, ob)),
                site: along.site.clone(),
            });
        }
    }

    /// oscsim's lane change of `along`'s route to its point at the plan's s `sb` in lane `lb`,
    /// offset `ob` from its centre (`LateralAction::LaneChangeAt`, sinusoidal): on a plan over
    /// several roads the engine measures the way in the plan's s, across the roads' joints; on
    /// one road in the road's own s.
    fn change_to_point(&self, along: &Along, (sb, lb, ob): (f64, i32, f64)) -> PrivateAction {
        let roads = self.chain();
        let s = match roads.chain.is_empty() {
            true => self.road.road_at(sb).1,
            false => sb,
        };
        PrivateAction::Lateral(LateralAction::LaneChangeAt(Box::new(LaneChangeAt {
            target: LaneChangeTarget::Absolute(lb.to_string()),
            target_lane_offset: (ob != 0.0).then_some(ob),
            shape: DynamicsShape::Sinusoidal,
            s,
            roads,
            what: format!("the route of along(…) at {}", along.site.at()),
        })))
    }

    /// The first time from `from` to `until` at which `target`'s planned s reaches `s`, if it
    /// does (its s never decreases: speeds are 0 or more).
    fn time_reaching(&self, target: &str, s: f64, from: f64, until: f64) -> Option<f64> {
        let s = s - S_EPS;
        if self.s_at(target, from) >= s {
            return Some(from);
        }
        if self.s_at(target, until) < s {
            return None;
        }
        let (mut lo, mut hi) = (from, until);
        // Bisection to well below the engine's step.
        while hi - lo > TIME_EPS {
            let mid = 0.5 * (lo + hi);
            if self.s_at(target, mid) >= s {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        Some(hi)
    }
}
