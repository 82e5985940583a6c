//! The actions that control a vehicle's gap to another object (ASAM OpenSCENARIO DSL 2.1 §8.8.3
//! actions for vehicle: `change_space_gap`, `keep_space_gap`, `change_time_headway`,
//! `keep_time_headway`), lowered to the engine's LongitudinalDistanceAction (OpenSCENARIO 1.3
//! §7.7.2.1), whose distance controller has the dynamics:
//!
//! | action | LongitudinalDistanceAction | ends |
//! | --- | --- | --- |
//! | `change_space_gap(target, direction, reference)` | `distance` = target, `freespace` (the space gap is between the bounding boxes, §8.7.5.1.3), road coordinates, `continuous="false"` | when the gap is reached (the engine: within 0.1 m) |
//! | `keep_space_gap(reference, direction)` | as above, the gap at its start, `continuous="true"` | with its phase |
//! | `change_time_headway(target, direction, reference)` | `timeGap` = target between the reference points (§8.7.5.1.2 measures the headway "from reference point to reference point"), `continuous="false"` | when the headway is reached |
//! | `keep_time_headway(reference, direction)` | as above, the headway at its start, `continuous="true"` | with its phase |
//!
//! `direction`: `behind` (the actor behind the reference) is `displacement`
//! trailingReferencedEntity, `ahead` leadingReferencedEntity, none `any` (the side the actor is
//! on); `keep_space_gap`'s `longitudinal` is `any`. The lateral directions (`left`, `right`,
//! `inside`, `outside`, `lateral`) are errors (not run yet). The controller's limits are
//! [`GAP_ACCELERATION`] and [`GAP_DECELERATION`] and the vehicle's maximum speed.
//!
//! The gap or headway a `keep_*` action keeps is the one at its start: the target of the gap
//! action the actor ran just before (to the same reference), else the plan's gap between the two
//! tracks at the phase's start. While the engine's controller moves the actor the plan does not
//! know its track: a later phase of the actor must start on a run-time condition (an `until`,
//! a `wait`, or the gap action's own end), else an error.

use scenario::{
    CoordinateSystem, DynamicConstraints, LongitudinalAction, LongitudinalDisplacement,
    PrivateAction, StoryboardElementState,
};

use super::action_args::missing;
use super::planner::{Gap, Planner};
use super::speed_actions::Slot;
use super::types::{Planned, When, MAX_SPEED};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{arg, Action, Invoke, Phase, Val};

/// Largest acceleration of the gap controller (m/s²): the largest average acceleration ISO
/// 15622 allows an adaptive cruise control, the controller these actions describe.
pub(crate) const GAP_ACCELERATION: f64 = 2.0;
/// Largest deceleration of the gap controller (m/s²): ISO 15622's largest average deceleration
/// of an adaptive cruise control.
pub(crate) const GAP_DECELERATION: f64 = 3.5;

impl Planner<'_> {
    /// Plans `inv`'s gap or headway action for one actor; returns when the action ends on its
    /// own (`None`: with its phase).
    pub(super) fn plan_gap_action(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        slot: Slot<'_>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Slot {
            target,
            t0,
            first,
            out,
            ..
        } = slot;
        super::speed_actions::check_speed_modifiers(inv, first)?;
        let reference = self.gap_reference(p, inv)?;
        let headway = matches!(
            inv.kind,
            Action::ChangeTimeHeadway | Action::KeepTimeHeadway
        );
        let change = matches!(inv.kind, Action::ChangeSpaceGap | Action::ChangeTimeHeadway);
        let displacement = displacement(inv)?;
        let wanted = if change {
            let a = arg(&inv.args, "target").ok_or_else(|| missing(p, inv, "target"))?;
            let x = a.number()?;
            if x < 0.0 || (headway && x <= 0.0) {
                return Err(a.site.err(
                    K::Argument,
                    format!(
                        "expected a target {} {}, found {x}",
                        if headway { "headway" } else { "gap" },
                        if headway {
                            "above 0 s"
                        } else {
                            "of 0 m or more"
                        }
                    ),
                ));
            }
            if headway {
                Gap::Headway(x)
            } else {
                Gap::Space(x)
            }
        } else {
            self.gap_at_start(p, inv, target, &reference, t0, headway)?
        };
        let (distance, time_gap) = match wanted {
            Gap::Space(d) => (Some(d), None),
            Gap::Headway(t) => (None, Some(t)),
        };
        let n = name(&inv.action);
        out.push(Planned::with_phase(
            target,
            n.clone(),
            PrivateAction::Longitudinal(LongitudinalAction::LongitudinalDistance {
                entity_ref: reference.clone(),
                continuous: !change,
                distance,
                time_gap,
                freespace: !headway,
                displacement: Some(displacement),
                coordinate_system: Some(CoordinateSystem::Road),
                dynamic_constraints: Some(DynamicConstraints {
                    max_acceleration: Some(GAP_ACCELERATION),
                    max_acceleration_rate: None,
                    max_deceleration: Some(GAP_DECELERATION),
                    max_deceleration_rate: None,
                    max_speed: Some(MAX_SPEED),
                }),
            }),
            &p.site,
        ));
        // From here the engine's controller moves the actor; once it holds the gap, at the
        // reference's speed.
        self.engine_moved.insert(target.to_string(), t0);
        self.gaps
            .insert(target.to_string(), (reference.clone(), wanted));
        let v_ref = self.last_v.get(&reference).copied().unwrap_or(0.0);
        self.last_v.insert(target.to_string(), v_ref);
        Ok(change.then(|| {
            When::Dyn(scenario::Trigger {
                condition_groups: vec![scenario::ConditionGroup {
                    conditions: vec![crate::trigger::event_state(
                        &n,
                        StoryboardElementState::CompleteState,
                        p.site.pos.clone(),
                    )],
                }],
            })
        }))
    }

    /// The `reference` of a gap action: mandatory, an entity of the plan.
    fn gap_reference(&self, p: &Phase, inv: &Invoke) -> Result<String, Error> {
        let a = arg(&inv.args, "reference").ok_or_else(|| missing(p, inv, "reference"))?;
        a.path
            .as_ref()
            .filter(|x| self.index.contains_key(*x))
            .cloned()
            .ok_or_else(|| {
                a.site.err(
                    K::UnknownActor,
                    "expected a physical object of the scenario as the reference, found another value",
                )
            })
    }

    /// The gap (or headway) between `target` and `reference` at the start of a `keep_*` action.
    fn gap_at_start(
        &self,
        p: &Phase,
        inv: &Invoke,
        target: &str,
        reference: &str,
        t0: Option<f64>,
        headway: bool,
    ) -> Result<Gap, Error> {
        // The target of the gap action just before, when it kept the same measure.
        if let Some((r, g)) = self.gaps.get(target) {
            if r == reference {
                match (g, headway) {
                    (Gap::Space(_), false) | (Gap::Headway(_), true) => return Ok(*g),
                    _ => {}
                }
            }
        }
        let unknown = |why: &str| {
            p.site.err(
                K::Unsatisfiable,
                format!(
                    "expected the {} at the start of {}(…) known to the plan, found {why}; change it first (change_space_gap / change_time_headway to the same reference)",
                    if headway { "headway" } else { "gap" },
                    inv.action
                ),
            )
        };
        let t = t0.ok_or_else(|| unknown("a phase that starts on a run-time condition"))?;
        if self.engine_moved.contains_key(target) || self.engine_moved.contains_key(reference) {
            return Err(unknown("an actor the engine's gap controller moves"));
        }
        let (s_a, s_r) = (self.s_at(target, t), self.s_at(reference, t));
        let between = (s_r - s_a).abs();
        if headway {
            let v = self.track(reference).at(t).1;
            if v <= 0.0 {
                return Err(unknown(
                    "the reference standing (no headway to a standing object)",
                ));
            }
            return Ok(Gap::Headway(between / v));
        }
        let overhangs = self.facing_overhangs(target, reference, s_r >= s_a);
        Ok(Gap::Space((between - overhangs).max(0.0)))
    }
}

/// The LongitudinalDisplacement of a gap action's `direction`.
fn displacement(inv: &Invoke) -> Result<LongitudinalDisplacement, Error> {
    let Some(a) = arg(&inv.args, "direction") else {
        return Ok(LongitudinalDisplacement::Any);
    };
    match a.eval()? {
        Val::Enum(d) if d == "behind" => Ok(LongitudinalDisplacement::TrailingReferencedEntity),
        Val::Enum(d) if d == "ahead" => Ok(LongitudinalDisplacement::LeadingReferencedEntity),
        Val::Enum(d) if d == "longitudinal" => Ok(LongitudinalDisplacement::Any),
        Val::Enum(d) => Err(a.site.err(
            K::Unsupported,
            format!("expected a longitudinal direction (ahead, behind, longitudinal) in {}(…), found `{d}` (lateral gaps are not run yet)", inv.action),
        )),
        _ => Err(a.site.err(K::Argument, "expected a direction, found another value")),
    }
}
