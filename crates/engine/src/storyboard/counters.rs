//! Per-stage work counters of one [`Storyboard::step`](super::Storyboard::step), named after
//! the stages of the step (OpenSCENARIO 1.3 §8.3–8.5 as laid out in `executor`).
//!
//! They count work, not time, so they are deterministic: the runtime can report them, and tests
//! can check which stage did what.

/// The stages of a step, in their fixed order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Stage {
    InitPhase,
    StopTriggers,
    StartTriggers,
    Completions,
}

/// What one stage did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct StageCount {
    /// Condition values asked from the [`ConditionSource`](super::ConditionSource).
    pub conditions: u64,
    /// Transitions recorded.
    pub transitions: u64,
}

/// The work of each stage of the last step.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct StageCounters {
    /// Stage 1, first step only: Init actions and the storyboard's start.
    pub init_phase: StageCount,
    /// Stage 2: stop triggers of the storyboard and the running Acts.
    pub stop_triggers: StageCount,
    /// Stage 3: start triggers, priorities, skips and starts.
    pub start_triggers: StageCount,
    /// Stage 4: action ends and their propagation.
    pub completions: StageCount,
}

impl StageCounters {
    pub(crate) fn stage_mut(&mut self, stage: Stage) -> &mut StageCount {
        match stage {
            Stage::InitPhase => &mut self.init_phase,
            Stage::StopTriggers => &mut self.stop_triggers,
            Stage::StartTriggers => &mut self.start_triggers,
            Stage::Completions => &mut self.completions,
        }
    }
}
