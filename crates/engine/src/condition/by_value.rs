//! ByValueCondition (OpenSCENARIO 1.3 §7.6.2, XSD `ByValueCondition`): conditions on the
//! simulation's values rather than on entities.
//!
//! * SimulationTimeCondition: simulation time `rule` value (s).
//! * ParameterCondition, VariableCondition, UserDefinedValueCondition: the current value
//!   `rule` the condition's value read as the same type (`rule::compare_value`). An
//!   undeclared parameter or variable is an error; a user-defined value nothing has
//!   registered reads false (it may appear later, from outside).
//! * StoryboardElementStateCondition: the reference designates exactly one element of its
//!   type, by name or by `::`-qualified name (`StateView::find_ref`); a state (standby, running, complete) holds while the
//!   element is in it; a transition (start, end, stop, skip) holds in the step it happens and
//!   the next (`StateView::transition_happened`: the second step lets elements earlier in
//!   document order see it).
//! * TimeOfDayCondition: the scenario's time of day `rule` the condition's dateTime; false
//!   while no TimeOfDay has been set.
//! * TrafficSignalCondition, TrafficSignalControllerCondition: the signal's state / the
//!   controller's phase equals the one named (whitespace around it ignored); false for an
//!   unknown signal or controller.
//! * SimulationTimeEvery (oscsim extension for the DSL's `every(…)`, no XML form): true in the
//!   step whose interval (t − step, t] reaches offset + k·period, k ≥ 0; t the simulation time,
//!   or with `since` the time since the step in which that Act last started (steps × step).
//! * ElapsedSinceStart (oscsim extension for the DSL's `elapsed(d)` counted from an Act's start,
//!   no XML form): the time since the step in which that Act last started is d or more.

use scenario::{ByValueCondition, Rule, SourcePos, StoryboardElementState, StoryboardElementType};

use super::rule::{compare, compare_value};
use super::{ConditionContext, ConditionError, ConditionErrorKind};
use crate::storyboard::{ElementId, ElementKind, ElementState, StateView, Transition};
use crate::world::date_time::parse_date_time;

/// The raw value of a ByValueCondition.
pub(crate) fn evaluate<C: ConditionContext + ?Sized>(
    condition: &ByValueCondition,
    ctx: &C,
    pos: &SourcePos,
) -> Result<bool, ConditionError> {
    let err = |kind| ConditionError::new(kind, pos);
    match condition {
        ByValueCondition::SimulationTime { value, rule } => {
            Ok(compare(ctx.simulation_time(), *rule, *value))
        }
        ByValueCondition::Parameter {
            parameter_ref,
            rule,
            value,
        } => {
            let current = ctx
                .parameter(parameter_ref)
                .ok_or_else(|| err(ConditionErrorKind::UnknownParameter(parameter_ref.clone())))?;
            compare_value(&current, *rule, value).map_err(err)
        }
        ByValueCondition::Variable {
            variable_ref,
            rule,
            value,
        } => {
            let current = ctx
                .variable(variable_ref)
                .ok_or_else(|| err(ConditionErrorKind::UnknownVariable(variable_ref.clone())))?;
            compare_value(&current, *rule, value).map_err(err)
        }
        ByValueCondition::UserDefinedValue { name, rule, value } => {
            match ctx.user_defined_value(name) {
                Some(current) => compare_value(&current, *rule, value).map_err(err),
                None => Ok(false),
            }
        }
        ByValueCondition::StoryboardElementState {
            storyboard_element_type,
            storyboard_element_ref,
            state,
        } => element_state(
            ctx,
            *storyboard_element_type,
            storyboard_element_ref,
            *state,
        )
        .map_err(err),
        ByValueCondition::TimeOfDay { rule, date_time } => {
            let wanted = parse_date_time(date_time)
                .ok_or_else(|| err(ConditionErrorKind::InvalidDateTime(date_time.clone())))?;
            // Compared as a difference: the rule's relative tolerance on two epoch times
            // (~1.8e9 s) would be almost two seconds wide.
            Ok(ctx
                .time_of_day()
                .is_some_and(|now| compare(now - wanted, *rule, 0.0)))
        }
        ByValueCondition::TrafficSignal { name, state } => Ok(ctx
            .traffic_signal_state(name)
            .is_some_and(|s| s.trim() == state.trim())),
        ByValueCondition::TrafficSignalController {
            traffic_signal_controller_ref,
            phase,
        } => Ok(ctx
            .traffic_signal_controller_phase(traffic_signal_controller_ref)
            .is_some_and(|p| p.trim() == phase.trim())),
        ByValueCondition::SimulationTimeEvery {
            period,
            offset,
            step,
            since,
        } => {
            let t = match since {
                None => Some(ctx.simulation_time()),
                Some(act) => since_start(ctx, act, *step).map_err(err)?,
            };
            Ok(t.is_some_and(|t| every_reached(t, *period, *offset, *step)))
        }
        ByValueCondition::ElapsedSinceStart { act, value, step } => {
            Ok(since_start(ctx, act, *step)
                .map_err(err)?
                .is_some_and(|t| compare(t, Rule::GreaterOrEqual, *value)))
        }
        _ => Err(err(ConditionErrorKind::Unsupported {
            expected: "a ByValueCondition of OpenSCENARIO 1.3",
            found: "another kind",
        })),
    }
}

/// Whether the step interval (t − step, t] reaches a trigger point offset + k·period, k ≥ 0
/// (`SimulationTimeEvery`). Times within 1e-9 s of a trigger point count as reaching it, so
/// that a step time summed in floating point (2.9999999999) still fires at 3 s and fires once.
fn every_reached(t: f64, period: f64, offset: f64, step: f64) -> bool {
    const EPS: f64 = 1e-9;
    if !(period > 0.0 && step > 0.0 && t.is_finite()) || t + EPS < offset {
        return false;
    }
    // The last trigger point at or before t (within EPS).
    let k = ((t - offset + EPS) / period).floor();
    let last = offset + k * period;
    last > t - step + EPS
}

/// The storyboard's element kind and XSD literal for a `storyboardElementType`.
fn element_kind(t: StoryboardElementType) -> (ElementKind, &'static str) {
    match t {
        StoryboardElementType::Story => (ElementKind::Story, "story"),
        StoryboardElementType::Act => (ElementKind::Act, "act"),
        StoryboardElementType::ManeuverGroup => (ElementKind::ManeuverGroup, "maneuverGroup"),
        StoryboardElementType::Maneuver => (ElementKind::Maneuver, "maneuver"),
        StoryboardElementType::Event => (ElementKind::Event, "event"),
        // Action, and any type a later version adds, name Actions.
        _ => (ElementKind::Action, "action"),
    }
}

/// The one element of type `element_type` that `name` designates.
fn designated(
    view: &StateView<'_>,
    element_type: StoryboardElementType,
    name: &str,
) -> Result<ElementId, ConditionErrorKind> {
    let (kind, literal) = element_kind(element_type);
    match view.find_ref(kind, name).as_slice() {
        [one] => Ok(*one),
        [] => Err(ConditionErrorKind::UnknownElement {
            kind: literal,
            name: name.to_string(),
        }),
        several => Err(ConditionErrorKind::AmbiguousElement {
            kind: literal,
            name: name.to_string(),
            found: several.len(),
        }),
    }
}

/// The time since Act `act` last started (s), counted in steps of `step` s from the step of
/// its startTransition (that step is 0 s); `None` before it ever started.
fn since_start<C: ConditionContext + ?Sized>(
    ctx: &C,
    act: &str,
    step: f64,
) -> Result<Option<f64>, ConditionErrorKind> {
    let view = ctx.storyboard();
    let id = designated(&view, StoryboardElementType::Act, act)?;
    Ok(view
        .last_transition_step(id, Transition::Start)
        .map(|k| view.step().saturating_sub(k) as f64 * step))
}

/// StoryboardElementStateCondition.
fn element_state<C: ConditionContext + ?Sized>(
    ctx: &C,
    element_type: StoryboardElementType,
    name: &str,
    state: StoryboardElementState,
) -> Result<bool, ConditionErrorKind> {
    let view = ctx.storyboard();
    let id = designated(&view, element_type, name)?;
    let in_state = |s| view.state(id) == s;
    let happened = |t| view.transition_happened(id, t);
    Ok(match state {
        StoryboardElementState::StandbyState => in_state(ElementState::Standby),
        StoryboardElementState::RunningState => in_state(ElementState::Running),
        StoryboardElementState::CompleteState => in_state(ElementState::Complete),
        StoryboardElementState::StartTransition => happened(Transition::Start),
        StoryboardElementState::EndTransition => happened(Transition::End),
        StoryboardElementState::StopTransition => happened(Transition::Stop),
        StoryboardElementState::SkipTransition => happened(Transition::Skip),
        _ => false,
    })
}

#[cfg(test)]
mod tests {
    use super::every_reached;

    /// every(2 s, offset: 1 s) at a step of 0.05 s: trigger points 1, 3, 5 s; the steps are
    /// summed as the engine sums them (0.05 is not exact in binary), and exactly the steps at
    /// 1, 3 and 5 s (± rounding) hold.
    #[test]
    fn every_holds_once_per_period_at_the_step_reaching_it() {
        let mut t = 0.0;
        let mut hits = Vec::new();
        for _ in 0..120 {
            if every_reached(t, 2.0, 1.0, 0.05) {
                hits.push(t);
            }
            t += 0.05;
        }
        assert_eq!(hits.len(), 3, "{hits:?}");
        for (h, want) in hits.iter().zip([1.0, 3.0, 5.0]) {
            assert!((h - want).abs() < 1e-9, "{h} vs {want}");
        }
    }

    /// A trigger point between two steps (every 0.3 s at a 0.2 s step: 0, 0.3, 0.6, 0.9, 1.2)
    /// moves to the next step (0, 0.4, 0.6, 1.0, 1.2); without an offset the first is at 0.
    #[test]
    fn a_point_between_steps_fires_at_the_next_step() {
        let hits: Vec<f64> = (0..7)
            .map(|i| f64::from(i) * 0.2)
            .filter(|t| every_reached(*t, 0.3, 0.0, 0.2))
            .collect();
        let want = [0.0, 0.4, 0.6, 1.0, 1.2];
        assert_eq!(hits.len(), want.len(), "{hits:?}");
        for (h, w) in hits.iter().zip(want) {
            assert!((h - w).abs() < 1e-9, "{h} vs {w}");
        }
    }
}
