//! The transitions of one element and what they set off, OpenSCENARIO 1.3 §8.2–8.4.
//!
//! - [`start`](Storyboard::start) (`startTransition` → `runningState`): starts the element's
//!   action, if it is one, and sets up its children (§8.3): a child that defines a start trigger
//!   enters `standbyState` (no named transition; its trigger memory is cleared), any other child
//!   starts at once, recursively, in the same step. Events always enter standby: "An Event
//!   enters standbyState when its enclosing Maneuver is started", and one without a trigger of
//!   its own "inherits the start trigger from its parent Act" (§8.4.2), which has fired; the
//!   step's trigger walk reaches it in the same step and starts it through the priority and
//!   count rules. (esmini's logs show the same `standbyState -> startTransition` for Events
//!   without a trigger, and `initState -> startTransition` for ManeuverGroups.) A child whose
//!   execution count is 0 waits in standby as well, where it is skipped. Children are reset to
//!   `initState` first, with their execution counts, so a re-executed Event or ManeuverGroup runs
//!   its subtree afresh.
//! - [`end`](Storyboard::end) (`endTransition`): back to `standbyState` while executions are
//!   left (Events, ManeuverGroups), else to `completeState` (§8.4.2.1).
//! - [`skip`](Storyboard::skip) (`skipTransition`): counts as an execution; to `standbyState`
//!   while executions are left, else to `completeState`.
//! - [`stop_subtree`](Storyboard::stop_subtree) (`stopTransition` → `completeState`): the element
//!   and every executing descendant, parent before children; running actions are stopped in the
//!   runtime.
//!
//! Every transition is recorded, except those of Init, which is not a storyboard element (§8.5).

use super::element::{ElementId, ElementKind};
use super::executor::{StepContext, Storyboard};
use super::host::ActionStatus;
use super::log::TransitionRecord;
use super::state::{ElementState, Transition};
use super::tree::Status;

impl Storyboard {
    /// Moves `id` through `transition` into `to`, counts start and skip transitions as
    /// executions, and records the transition.
    pub(crate) fn transition(
        &mut self,
        id: ElementId,
        transition: Transition,
        to: ElementState,
        ctx: &mut StepContext<'_>,
    ) {
        let status = &mut self.status[id.index()];
        let from = status.state;
        status.state = to;
        status.last_step[transition.index()] = Some(self.step);
        if matches!(transition, Transition::Start | Transition::Skip) {
            status.executions = status.executions.saturating_add(1);
        }
        let node = &self.nodes[id.index()];
        if node.kind != ElementKind::Init {
            ctx.count().transitions += 1;
            ctx.log.record(TransitionRecord {
                time: ctx.time,
                name: node.name.clone(),
                element: id,
                kind: node.kind,
                from,
                transition,
                to,
            });
        }
    }

    /// True while the element may still start: executions below `maximumExecutionCount`.
    pub(crate) fn has_executions_left(&self, id: ElementId) -> bool {
        self.status[id.index()].executions < self.nodes[id.index()].maximum_execution_count
    }

    /// `startTransition`, then the children's set-up (module documentation).
    pub(crate) fn start(&mut self, id: ElementId, ctx: &mut StepContext<'_>) {
        self.transition(id, Transition::Start, ElementState::Running, ctx);
        if let Some(trigger) = self.nodes[id.index()].stop_trigger {
            self.triggers[trigger].reset();
        }
        if let Some(action) = self.nodes[id.index()].action {
            ctx.actions.start(action);
        }
        for i in 0..self.nodes[id.index()].children.len() {
            let child = self.nodes[id.index()].children[i];
            if self.nodes[child.index()].kind == ElementKind::Init {
                // Init runs in the init phase, before the storyboard starts (§8.5).
                continue;
            }
            self.reset_subtree(child);
            if self.has_start_trigger(child) || !self.has_executions_left(child) {
                self.enter_standby(child);
            } else {
                self.start(child, ctx);
            }
        }
    }

    /// True if the element waits in standbyState when its parent starts: it defines a start
    /// trigger (§8.3), or it is an Event, which "enters standbyState when its enclosing
    /// Maneuver is started" and, lacking a trigger, "inherits the start trigger from its parent
    /// Act" (§8.4.2).
    pub(crate) fn has_start_trigger(&self, id: ElementId) -> bool {
        let node = &self.nodes[id.index()];
        node.start_trigger.is_some() || node.kind == ElementKind::Event
    }

    /// `initState` → `standbyState`, which the standard gives no transition name; the start
    /// trigger's memory is cleared so its next evaluation is the first.
    fn enter_standby(&mut self, id: ElementId) {
        self.status[id.index()].state = ElementState::Standby;
        self.reset_start_trigger(id);
    }

    fn reset_start_trigger(&mut self, id: ElementId) {
        if let Some(trigger) = self.nodes[id.index()].start_trigger {
            self.triggers[trigger].reset();
        }
    }

    /// Puts `id` and its descendants back into `initState` with no executions, keeping the
    /// record of past transitions for `StoryboardElementStateCondition`.
    fn reset_subtree(&mut self, id: ElementId) {
        let status = &mut self.status[id.index()];
        *status = Status {
            last_step: status.last_step,
            ..Status::INITIAL
        };
        for i in 0..self.nodes[id.index()].children.len() {
            self.reset_subtree(self.nodes[id.index()].children[i]);
        }
    }

    /// The state after a transition that ends an execution, given the executions counted then:
    /// standby while executions are left, else complete.
    fn after_execution(&self, id: ElementId, executions: u32) -> ElementState {
        if executions < self.nodes[id.index()].maximum_execution_count {
            ElementState::Standby
        } else {
            ElementState::Complete
        }
    }

    /// `endTransition` of a running element whose work is done.
    pub(crate) fn end(&mut self, id: ElementId, ctx: &mut StepContext<'_>) {
        let to = self.after_execution(id, self.status[id.index()].executions);
        self.transition(id, Transition::End, to, ctx);
        if to == ElementState::Standby {
            self.reset_start_trigger(id);
        }
    }

    /// `skipTransition` of a standby element; the skip counts as an execution.
    pub(crate) fn skip(&mut self, id: ElementId, ctx: &mut StepContext<'_>) {
        // The skip itself is counted by `transition`.
        let to = self.after_execution(id, self.status[id.index()].executions.saturating_add(1));
        self.transition(id, Transition::Skip, to, ctx);
        if to == ElementState::Standby {
            self.reset_start_trigger(id);
        }
    }

    /// `stopTransition` of `id` and of every executing descendant, parent first.
    pub(crate) fn stop_subtree(&mut self, id: ElementId, ctx: &mut StepContext<'_>) {
        let state = self.status[id.index()].state;
        if state.is_executing() {
            if state == ElementState::Running {
                if let Some(action) = self.nodes[id.index()].action {
                    ctx.actions.stop(action);
                }
            }
            self.transition(id, Transition::Stop, ElementState::Complete, ctx);
        }
        for i in 0..self.nodes[id.index()].children.len() {
            self.stop_subtree(self.nodes[id.index()].children[i], ctx);
        }
    }

    /// Records the end of a running action once the runtime reports it ended or stopped.
    pub(crate) fn poll_action(&mut self, id: ElementId, ctx: &mut StepContext<'_>) {
        let Some(action) = self.nodes[id.index()].action else {
            return;
        };
        match ctx.actions.status(action) {
            ActionStatus::Running => {}
            ActionStatus::Ended => {
                self.transition(id, Transition::End, ElementState::Complete, ctx)
            }
            ActionStatus::Stopped => {
                self.transition(id, Transition::Stop, ElementState::Complete, ctx)
            }
        }
    }
}
