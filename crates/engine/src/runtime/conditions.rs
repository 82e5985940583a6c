//! The storyboard's [`ConditionSource`] over the world: the raw value of each condition
//! (OpenSCENARIO 1.3 §7.6), before the edge and delay the storyboard applies.
//!
//! Interim evaluation until the `condition` module's evaluator lands: SimulationTimeCondition,
//! StoryboardElementStateCondition, ParameterCondition and VariableCondition are answered here;
//! every other condition reads false and is reported once in the event log as unsupported.

use std::cell::RefCell;

use scenario::expr::Value;
use scenario::{
    ByValueCondition, ConditionKind, Rule, StoryboardElementState, StoryboardElementType,
};

use super::world::{ConditionWorld, World};
use crate::condition::{ConditionContext, ConditionStates};
use crate::output::EventRecord;
use crate::storyboard::{
    ConditionId, ConditionSource, ElementKind, ElementState, StateView, Transition,
};

/// Compares `a` with `b` under `rule` (equalTo within 1e-9 relative, as floats compare).
pub(crate) fn compare(a: f64, rule: Rule, b: f64) -> bool {
    let eq = (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1.0);
    match rule {
        Rule::EqualTo => eq,
        Rule::NotEqualTo => !eq,
        Rule::GreaterThan => a > b && !eq,
        Rule::LessThan => a < b && !eq,
        Rule::GreaterOrEqual => a > b || eq,
        Rule::LessOrEqual => a < b || eq,
        _ => false,
    }
}

/// Compares a runtime value with the condition's text value.
fn compare_value(current: &Value, rule: Rule, text: &str) -> bool {
    match (current.as_f64(), text.trim().parse::<f64>()) {
        (Some(a), Ok(b)) => compare(a, rule, b),
        _ => {
            let a = match current {
                Value::String(s) | Value::DateTime(s) => s.clone(),
                Value::Bool(b) => b.to_string(),
                other => format!("{other:?}"),
            };
            match rule {
                Rule::EqualTo => a == text,
                Rule::NotEqualTo => a != text,
                _ => false,
            }
        }
    }
}

fn element_kind(t: StoryboardElementType) -> ElementKind {
    match t {
        StoryboardElementType::Act => ElementKind::Act,
        StoryboardElementType::Action => ElementKind::Action,
        StoryboardElementType::Event => ElementKind::Event,
        StoryboardElementType::Maneuver => ElementKind::Maneuver,
        StoryboardElementType::ManeuverGroup => ElementKind::ManeuverGroup,
        _ => ElementKind::Story,
    }
}

fn element_state(
    view: &StateView<'_>,
    kind: StoryboardElementType,
    name: &str,
    state: StoryboardElementState,
) -> bool {
    let Some(id) = view
        .find_kind(element_kind(kind), name)
        .or_else(|| view.find(name))
    else {
        return false;
    };
    let transition = |t| view.transition_happened(id, t);
    match state {
        StoryboardElementState::StandbyState => view.state(id) == ElementState::Standby,
        StoryboardElementState::RunningState => view.state(id) == ElementState::Running,
        StoryboardElementState::CompleteState => view.state(id) == ElementState::Complete,
        StoryboardElementState::StartTransition => transition(Transition::Start),
        StoryboardElementState::EndTransition => transition(Transition::End),
        StoryboardElementState::StopTransition => transition(Transition::Stop),
        StoryboardElementState::SkipTransition => transition(Transition::Skip),
        _ => false,
    }
}

/// Evaluates one condition in `ctx`; `None` when this evaluator does not handle it.
pub(crate) fn evaluate(condition: &scenario::Condition, ctx: &ConditionWorld<'_>) -> Option<bool> {
    let ConditionKind::ByValue(v) = &condition.kind else {
        return None;
    };
    Some(match v {
        ByValueCondition::SimulationTime { value, rule } => {
            compare(ctx.simulation_time(), *rule, *value)
        }
        ByValueCondition::StoryboardElementState {
            storyboard_element_type,
            storyboard_element_ref,
            state,
        } => element_state(
            &ctx.storyboard(),
            *storyboard_element_type,
            storyboard_element_ref,
            *state,
        ),
        ByValueCondition::Parameter {
            parameter_ref,
            rule,
            value,
        } => ctx
            .parameter(parameter_ref)
            .is_some_and(|p| compare_value(&p, *rule, value)),
        ByValueCondition::Variable {
            variable_ref,
            rule,
            value,
        } => ctx
            .variable(variable_ref)
            .is_some_and(|p| compare_value(&p, *rule, value)),
        _ => return None,
    })
}

/// The [`ConditionSource`] of one step.
pub(crate) struct Conditions<'a> {
    pub world: &'a RefCell<World>,
    pub conditions: &'a [scenario::Condition],
    pub states: &'a mut ConditionStates,
    pub reported: &'a mut Vec<bool>,
    pub log: &'a RefCell<Vec<EventRecord>>,
}

impl ConditionSource for Conditions<'_> {
    fn value(&mut self, id: ConditionId, time: f64, storyboard: &StateView<'_>) -> bool {
        let index = id.0 as usize;
        let Some(condition) = self.conditions.get(index) else {
            return false;
        };
        let world = self.world.borrow();
        let ctx = ConditionWorld {
            world: &world,
            storyboard: *storyboard,
        };
        let _ = self.states.get_mut(id);
        match evaluate(condition, &ctx) {
            Some(v) => v,
            None => {
                if !self.reported[index] {
                    self.reported[index] = true;
                    self.log.borrow_mut().push(EventRecord::unsupported(
                        time,
                        &condition.name,
                        "this condition (reads false)",
                        &condition.pos,
                    ));
                }
                false
            }
        }
    }
}
