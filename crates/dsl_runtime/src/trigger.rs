//! The OpenSCENARIO 1.x conditions the pipeline builds its triggers from (OpenSCENARIO 1.3
//! §7.5 conditions): a storyboard element's state (an Act's, an Event's, an Action's), the
//! simulation time, and oscsim's periodic SimulationTimeEvery and ElapsedSinceStart (counted
//! from an Act's start).

use scenario::{
    ByValueCondition, Condition, ConditionEdge, ConditionKind, Rule, StoryboardElementState,
    StoryboardElementType,
};

/// A condition on the state of the phase `act` (a storyboard Act), reported `delay` s later.
pub(crate) fn act_state(
    act: &str,
    state: StoryboardElementState,
    delay: f64,
    pos: scenario::SourcePos,
) -> Condition {
    element_state((StoryboardElementType::Act, act), state, delay, pos)
}

/// A condition on the state of the storyboard Event `event` (an action's completion).
pub(crate) fn event_state(
    event: &str,
    state: StoryboardElementState,
    pos: scenario::SourcePos,
) -> Condition {
    element_state((StoryboardElementType::Event, event), state, 0.0, pos)
}

/// A condition on the state of the storyboard Action `action`: its `endTransition` is its own
/// end (a target reached), where its Event also completes when the action is stopped.
pub(crate) fn action_state(
    action: &str,
    state: StoryboardElementState,
    pos: scenario::SourcePos,
) -> Condition {
    element_state((StoryboardElementType::Action, action), state, 0.0, pos)
}

/// A StoryboardElementStateCondition on the element `name` of type `kind`.
fn element_state(
    (kind, name): (StoryboardElementType, &str),
    state: StoryboardElementState,
    delay: f64,
    pos: scenario::SourcePos,
) -> Condition {
    Condition {
        name: format!("{name}:{}", state.as_str()),
        condition_edge: ConditionEdge::None,
        delay,
        kind: ConditionKind::ByValue(ByValueCondition::StoryboardElementState {
            storyboard_element_type: kind,
            storyboard_element_ref: name.to_string(),
            state,
        }),
        pos,
    }
}

/// `every(period, offset: offset)` counted from the start of the run: SimulationTimeEvery at
/// the planner's step.
pub(crate) fn every_from_start(
    period: f64,
    offset: f64,
    step: f64,
    pos: scenario::SourcePos,
) -> Condition {
    every_since(None, period, offset, step, pos)
}

/// `every(period, offset: offset)` counted from the latest start of Act `act` (`None`: the
/// run's start): SimulationTimeEvery at the planner's step.
pub(crate) fn every_since(
    act: Option<&str>,
    period: f64,
    offset: f64,
    step: f64,
    pos: scenario::SourcePos,
) -> Condition {
    Condition {
        name: match act {
            Some(a) => format!("every {period} offset {offset} since {a}"),
            None => format!("every {period} offset {offset}"),
        },
        condition_edge: ConditionEdge::None,
        delay: 0.0,
        kind: ConditionKind::ByValue(ByValueCondition::SimulationTimeEvery {
            period,
            offset,
            step,
            since: act.map(str::to_string),
        }),
        pos,
    }
}

/// `elapsed(d)` counted from the latest start of Act `act`: oscsim's ElapsedSinceStart at the
/// planner's step.
pub(crate) fn elapsed_since(act: &str, d: f64, step: f64, pos: scenario::SourcePos) -> Condition {
    Condition {
        name: format!("elapsed {d} since {act}"),
        condition_edge: ConditionEdge::None,
        delay: 0.0,
        kind: ConditionKind::ByValue(ByValueCondition::ElapsedSinceStart {
            act: act.to_string(),
            value: d,
            step,
        }),
        pos,
    }
}

/// `SimulationTime rule t`.
pub(crate) fn sim_time(t: f64, rule: Rule, pos: scenario::SourcePos) -> Condition {
    Condition {
        name: format!("time {} {t}", rule.as_str()),
        condition_edge: ConditionEdge::None,
        delay: 0.0,
        kind: ConditionKind::ByValue(ByValueCondition::SimulationTime { value: t, rule }),
        pos,
    }
}
