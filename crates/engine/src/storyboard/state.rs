//! Storyboard element states and transitions, OpenSCENARIO 1.3 §8.1 "States" and §8.2
//! "Transitions".
//!
//! The standard's lifecycle has five states; `initState` and `endState` are implementation
//! specific (§8.1). oscsim keeps `initState` (an element that its parent has not set up yet, or
//! that its parent reset for a new execution) and has no `endState`: elements are never cleaned up
//! during a run. The names printed by [`ElementState`] and [`Transition`] are the literal values of
//! the XSD enumeration `StoryboardElementState`, so logs can be compared with other engines'.

use std::fmt;

/// The state of one storyboard element (OpenSCENARIO 1.3 §8.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
pub enum ElementState {
    /// `initState`: created, not yet set up by its parent (implementation specific, §8.1).
    #[serde(rename = "initState")]
    Init,
    /// `standbyState`: waiting for its (own or inherited) start trigger.
    #[serde(rename = "standbyState")]
    Standby,
    /// `runningState`: executing.
    #[serde(rename = "runningState")]
    Running,
    /// `completeState`: reached its goal, was stopped, or was skipped.
    #[serde(rename = "completeState")]
    Complete,
}

impl ElementState {
    /// The standard's name of the state, e.g. `"standbyState"`.
    pub fn as_str(self) -> &'static str {
        match self {
            ElementState::Init => "initState",
            ElementState::Standby => "standbyState",
            ElementState::Running => "runningState",
            ElementState::Complete => "completeState",
        }
    }

    /// True in `standbyState` and `runningState`: the standard calls such an element
    /// *executing* (OpenSCENARIO 1.3 §8.3).
    pub fn is_executing(self) -> bool {
        matches!(self, ElementState::Standby | ElementState::Running)
    }
}

impl fmt::Display for ElementState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A transition between two states (OpenSCENARIO 1.3 §8.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
pub enum Transition {
    /// `startTransition`: into `runningState`.
    #[serde(rename = "startTransition")]
    Start,
    /// `endTransition`: out of `runningState` after regular completion.
    #[serde(rename = "endTransition")]
    End,
    /// `stopTransition`: into `completeState` because of a stop trigger or an override.
    #[serde(rename = "stopTransition")]
    Stop,
    /// `skipTransition`: out of `standbyState` without running (priority skip, or the execution
    /// count is used up).
    #[serde(rename = "skipTransition")]
    Skip,
}

impl Transition {
    /// All four transitions, in the order of the standard's text.
    pub const ALL: [Transition; 4] = [
        Transition::Start,
        Transition::End,
        Transition::Stop,
        Transition::Skip,
    ];

    /// The standard's name of the transition, e.g. `"startTransition"`.
    pub fn as_str(self) -> &'static str {
        match self {
            Transition::Start => "startTransition",
            Transition::End => "endTransition",
            Transition::Stop => "stopTransition",
            Transition::Skip => "skipTransition",
        }
    }

    /// Position in [`Transition::ALL`], used to index per-transition tables.
    pub(crate) fn index(self) -> usize {
        match self {
            Transition::Start => 0,
            Transition::End => 1,
            Transition::Stop => 2,
            Transition::Skip => 3,
        }
    }
}

impl fmt::Display for Transition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The XSD type `StoryboardElementState` of `StoryboardElementStateCondition/@state`: a state
/// or a transition.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StoryboardElementState {
    /// `standbyState`, `runningState` or `completeState`.
    State(ElementState),
    /// `startTransition`, `endTransition`, `stopTransition` or `skipTransition`.
    Transition(Transition),
}

impl StoryboardElementState {
    /// Reads one of the seven XSD literals; `initState` is implementation specific (§8.1) and
    /// not among them.
    pub fn from_xsd(literal: &str) -> Option<Self> {
        let state = |s| Some(StoryboardElementState::State(s));
        let transition = |t| Some(StoryboardElementState::Transition(t));
        match literal {
            "standbyState" => state(ElementState::Standby),
            "runningState" => state(ElementState::Running),
            "completeState" => state(ElementState::Complete),
            "startTransition" => transition(Transition::Start),
            "endTransition" => transition(Transition::End),
            "stopTransition" => transition(Transition::Stop),
            "skipTransition" => transition(Transition::Skip),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn xsd_literals_round_trip_through_the_display_names() {
        let states = [
            ElementState::Standby,
            ElementState::Running,
            ElementState::Complete,
        ];
        for state in states {
            assert_eq!(
                StoryboardElementState::from_xsd(state.as_str()),
                Some(StoryboardElementState::State(state))
            );
        }
        for transition in Transition::ALL {
            assert_eq!(
                StoryboardElementState::from_xsd(transition.as_str()),
                Some(StoryboardElementState::Transition(transition))
            );
        }
        assert_eq!(StoryboardElementState::from_xsd("initState"), None);
        assert_eq!(StoryboardElementState::from_xsd("running"), None);
    }
}
