//! Event priority, OpenSCENARIO 1.3 §8.4.2.2 "Event priority" and the XSD enumeration
//! `Priority`.
//!
//! The rule is decided when an Event's start trigger fires, against the other Events of the same
//! Maneuver (its scope):
//!
//! - `override`: the Event starts and "terminates any running Event in the same scope"; each of
//!   them moves to `completeState` with `stopTransition`, "regardless of the number of executions
//!   left". `overwrite` is the deprecated spelling (1.0, 1.1) of the same rule.
//! - `skip`: if another Event of the Maneuver is running, the Event "does not move to
//!   runningState and instead moves to completeState if no number of executions is defined"
//!   (1.3 §8.4.2.2; the 1.0/1.1 model documentation: "it will not be ran if there is any other
//!   event in the same scope (maneuver) in the running state"). oscsim records this as a
//!   `skipTransition`, the only transition out of standby that does not start the Event, and
//!   counts it as an execution (§8.4.2.1: executions are start plus skip transitions). So the
//!   Event returns to `standbyState` while executions are left and moves to `completeState` when
//!   they are used up (with the default `maximumExecutionCount` of 1, at once). It does not wait
//!   for the others to finish. If no other Event runs, it starts.
//! - `parallel`: the Event starts regardless of the others.

/// The `priority` of an Event.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Priority {
    /// `override` (deprecated spelling `overwrite`): stop the running Events of the Maneuver.
    Override,
    /// `skip`: do not start while another Event of the Maneuver runs.
    Skip,
    /// `parallel`: start regardless.
    Parallel,
}

impl Priority {
    /// Reads the XSD literal, accepting the deprecated `overwrite` as [`Priority::Override`].
    pub fn from_xsd(literal: &str) -> Option<Priority> {
        match literal {
            "override" | "overwrite" => Some(Priority::Override),
            "skip" => Some(Priority::Skip),
            "parallel" => Some(Priority::Parallel),
            _ => None,
        }
    }

    /// What a triggered Event with this priority does, given whether another Event of its
    /// Maneuver is running.
    pub fn decide(self, others_running: bool) -> PriorityDecision {
        match (self, others_running) {
            (Priority::Override, true) => PriorityDecision::StopOthersAndStart,
            (Priority::Skip, true) => PriorityDecision::Skip,
            _ => PriorityDecision::Start,
        }
    }
}

/// The outcome of [`Priority::decide`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PriorityDecision {
    /// Start the Event.
    Start,
    /// Stop the running Events of the Maneuver, then start the Event.
    StopOthersAndStart,
    /// Take a skip transition instead of starting.
    Skip,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overwrite_is_the_deprecated_spelling_of_override() {
        assert_eq!(Priority::from_xsd("overwrite"), Some(Priority::Override));
        assert_eq!(Priority::from_xsd("override"), Some(Priority::Override));
        assert_eq!(Priority::from_xsd("Override"), None);
    }

    #[test]
    fn decisions_follow_8_4_2_2() {
        use PriorityDecision::*;
        assert_eq!(Priority::Override.decide(true), StopOthersAndStart);
        assert_eq!(Priority::Override.decide(false), Start);
        assert_eq!(Priority::Skip.decide(true), Skip);
        assert_eq!(Priority::Skip.decide(false), Start);
        assert_eq!(Priority::Parallel.decide(true), Start);
        assert_eq!(Priority::Parallel.decide(false), Start);
    }
}
