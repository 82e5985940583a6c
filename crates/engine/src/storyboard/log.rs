//! The record of storyboard state transitions, one per transition (OpenSCENARIO 1.3 §8.2), for
//! the run's event log.
//!
//! A [`TransitionRecord`] serializes (serde) to the object `{"time", "element", "kind", "from",
//! "transition", "to"}` with the standard's literal names (`startTransition`, `runningState`, …);
//! its `Display` is the line format of esmini's reference logs,
//! `6.500 CutInEvent standbyState -> startTransition -> runningState`. (The run's
//! `--events FILE.jsonl`, written by `engine::output`, shortens the transition to `start`,
//! `end`, `stop`, `skip`, the form the corpus's `compare_run.py` reads.)

use std::fmt;

use super::element::{ElementId, ElementKind};
use super::state::{ElementState, Transition};

/// One state transition of one storyboard element.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct TransitionRecord {
    /// Simulation time of the step in which it happened, in seconds.
    pub time: f64,
    /// The element's name.
    #[serde(rename = "element")]
    pub name: String,
    /// The element's handle (not serialized).
    #[serde(skip)]
    pub element: ElementId,
    /// The element's kind.
    pub kind: ElementKind,
    /// State before.
    pub from: ElementState,
    /// The transition.
    pub transition: Transition,
    /// State after.
    pub to: ElementState,
}

impl fmt::Display for TransitionRecord {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{:.3} {} {} -> {} -> {}",
            self.time, self.name, self.from, self.transition, self.to
        )
    }
}

/// Receives the transitions of each step, in the order they happen.
pub trait TransitionSink {
    /// Takes one record.
    fn record(&mut self, record: TransitionRecord);
}

impl TransitionSink for Vec<TransitionRecord> {
    fn record(&mut self, record: TransitionRecord) {
        self.push(record);
    }
}
