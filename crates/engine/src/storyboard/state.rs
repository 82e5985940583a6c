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
