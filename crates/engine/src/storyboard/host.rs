//! The storyboard's seams to the runtime: where condition values come from and where actions
//! run (OpenSCENARIO 1.3 §7.6 conditions, §8.4.1 execution of an action).
//!
//! The storyboard knows neither what a condition measures nor what an action does. Each step it
//! asks a [`ConditionSource`] for the raw value of every condition of every trigger it evaluates
//! (and of no other), and tells an [`ActionHost`] which actions to start and stop; it polls the
//! host for the actions' completion.

use super::element::{ActionId, ConditionId};
use super::view::StateView;

/// Supplies the raw value of a condition's logical expression.
pub trait ConditionSource {
    /// The value of condition `id`'s expression at simulation time `time`, before edge and
    /// delay (the storyboard applies both). `storyboard` shows the elements' states as they are at
    /// this moment of the step, for `StoryboardElementStateCondition`.
    ///
    /// Called once per condition per evaluated trigger per step, in document order, with no
    /// short-circuit, so that edges and delays see every sample.
    fn value(&mut self, id: ConditionId, time: f64, storyboard: &StateView<'_>) -> bool;
}

/// Where a started action stands, as the runtime reports it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ActionStatus {
    /// Still working towards its goal.
    Running,
    /// Reached its goal: the storyboard records an `endTransition`.
    Ended,
    /// Terminated by the runtime, e.g. by a newer action in the same control domain
    /// (OpenSCENARIO 1.3 §7.5.1): the storyboard records a `stopTransition`.
    Stopped,
}

/// Runs the actions of the storyboard.
pub trait ActionHost {
    /// Starts action `id`. An instantaneous action (e.g. TeleportAction, or a SpeedAction with
    /// `step` dynamics) should take effect here and report [`ActionStatus::Ended`] from then on:
    /// the storyboard polls right after starting Init actions and at the end of every step, so
    /// such an action starts and ends in the same step.
    fn start(&mut self, id: ActionId);
    /// Stops action `id` (stop trigger or priority override); it must not act any more.
    fn stop(&mut self, id: ActionId);
    /// The status of action `id`, which the storyboard started and has not stopped.
    fn status(&self, id: ActionId) -> ActionStatus;
    /// Called once, in the first step, when the Init actions have started and before the
    /// storyboard itself starts (§8.5.1): actions started from then on belong to the Stories.
    fn init_complete(&mut self) {}
}
