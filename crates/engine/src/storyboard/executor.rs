//! The storyboard and its step, OpenSCENARIO 1.3 §8 "Scenario at runtime" (§8.3 execution,
//! §8.4 storyboard element execution, §8.5 init section).
//!
//! # The step
//!
//! [`Storyboard::step`] runs these stages, in this order, at the step's time t:
//!
//! 1. `init_phase` (first step only): the Init actions start; those the runtime reports ended
//!    at once (instantaneous actions) end; the others keep running (§8.5.1). Then the
//!    storyboard starts and, recursively, every child without a start trigger (§8.3); children
//!    with one, and all Events (§8.4.2), enter standby. So Init actions have taken effect, and
//!    the instantaneous ones are complete, before any story trigger is evaluated.
//! 2. `stop_triggers`: the storyboard's stop trigger, then those of the running Acts in document
//!    order; a firing one stops the element and its executing descendants.
//! 3. `start_triggers`: a top-down walk of the running elements. Each standby child is handled
//!    when the walk reaches it: skipped if its executions are used up, else its start trigger is
//!    evaluated (an Event or ManeuverGroup without one inherits its Act's, which has fired) and,
//!    if true, the Event priority is applied and the element starts. A just-started element's
//!    children are walked in the same step, so a chain of triggers that are all true fires
//!    within one step: the standard says start triggers, action execution and stop triggers are
//!    the only things that take simulation time (§8.3.1). esmini behaves the same: in its
//!    `cut-in` reference log the Event triggered by the Act's startTransition starts in the
//!    Act's step (0.050 s).
//! 4. `completions`: a bottom-up walk of the running elements. Actions the runtime reports ended
//!    or stopped complete; an Event whose actions all completed ends, then its Maneuver if all its
//!    Events completed, and so up through ManeuverGroup, Act and Story. The storyboard itself
//!    ends only through its stop trigger (§7.2.1: "If no stopTrigger is defined, the Storyboard
//!    will never be stopped"); when all Stories completed it stays running and
//!    [`Storyboard::stories_complete`] tells the runtime, which may end the run.
//!
//! Each stage has a counter of the same name in [`StageCounters`] ([`Storyboard::counters`]):
//! the conditions it asked for and the transitions it recorded.
//!
//! An element that returns to standby after an end or skip transition is evaluated again from the
//! next step on, so a re-execution never happens twice in one step.
//!
//! Triggers come before completions, as in esmini: an action that reached its goal while the
//! runtime advanced from t − dt to t is recorded as ended in the completion stage at t, and a
//! StoryboardElementStateCondition sees that end from the next step (see
//! [`StateView::transition_happened`]). So a trigger on "Event1 endTransition" with a delay of
//! 4 s, Event1 ending at 5.000 s, fires at 9.050 s at dt = 0.05 s, exactly as in esmini's
//! `follow_reference` log; and an override Event triggered at t stops an Event whose action
//! would have been recorded as ended at t (esmini's `acc-test` log shows an endTransition there,
//! the standard a stopTransition, §8.4.2.2). The tests `storyboard_esmini_*` replay both logs.
//!
//! The runtime calls `step` once per fixed step, before it moves the actions and controllers and
//! before it takes measurements for the next step; instantaneous actions take effect inside
//! [`ActionHost::start`].

use super::counters::{Stage, StageCounters};
use super::desc::StoryboardDesc;
use super::element::{ElementId, ElementKind};
use super::error::{ErrorKind, StoryboardError};
use super::host::{ActionHost, ConditionSource};
use super::log::TransitionSink;
use super::priority::PriorityDecision;
use super::state::ElementState;
use super::tree::{build, Node, Status};
use super::trigger::TriggerState;
use super::view::StateView;

/// A storyboard at runtime: the element tree with states, trigger memory and execution counts.
#[derive(Debug, Clone)]
pub struct Storyboard {
    pub(crate) nodes: Vec<Node>,
    pub(crate) status: Vec<Status>,
    pub(crate) triggers: Vec<TriggerState>,
    root: ElementId,
    init: ElementId,
    /// The Acts, for their stop triggers.
    acts: Vec<ElementId>,
    /// Index of the current (or last) step.
    pub(crate) step: u64,
    last_time: Option<f64>,
    /// The work of the last step's stages.
    counters: StageCounters,
}

/// What one step works with.
pub(crate) struct StepContext<'a> {
    pub(crate) time: f64,
    pub(crate) dt: f64,
    pub(crate) conditions: &'a mut dyn ConditionSource,
    pub(crate) actions: &'a mut dyn ActionHost,
    pub(crate) log: &'a mut dyn TransitionSink,
    /// The stage running now.
    pub(crate) stage: Stage,
    pub(crate) counters: StageCounters,
}

impl StepContext<'_> {
    /// The counter of the stage running now.
    pub(crate) fn count(&mut self) -> &mut super::counters::StageCount {
        self.counters.stage_mut(self.stage)
    }
}

impl Storyboard {
    /// Builds the storyboard from its description. All elements start in `initState`; nothing
    /// runs before the first [`step`](Storyboard::step).
    ///
    /// Fails if a condition's delay is negative or not finite, or a condition group is empty.
    pub fn new(desc: &StoryboardDesc) -> Result<Storyboard, StoryboardError> {
        let b = build(desc)?;
        Ok(Storyboard::from_parts(b.nodes, b.triggers, b.root, b.init))
    }

    pub(crate) fn from_parts(
        nodes: Vec<Node>,
        triggers: Vec<TriggerState>,
        root: ElementId,
        init: ElementId,
    ) -> Self {
        let acts = (0..nodes.len())
            .filter(|&i| nodes[i].kind == ElementKind::Act)
            .map(|i| ElementId(i as u32))
            .collect();
        Storyboard {
            status: vec![Status::INITIAL; nodes.len()],
            nodes,
            triggers,
            root,
            init,
            acts,
            step: 0,
            last_time: None,
            counters: StageCounters::default(),
        }
    }

    /// Runs one step at simulation time `time` (seconds) with step length `dt`: the stages of
    /// the module documentation. Transitions go to `log` in the order they happen.
    ///
    /// Fails, changing nothing, if `time` is not finite or not after the previous step's, or
    /// `dt` is not finite and positive. After the storyboard stopped, a step does nothing.
    pub fn step(
        &mut self,
        time: f64,
        dt: f64,
        conditions: &mut dyn ConditionSource,
        actions: &mut dyn ActionHost,
        log: &mut dyn TransitionSink,
    ) -> Result<(), StoryboardError> {
        if !time.is_finite() {
            return Err(StoryboardError::new(ErrorKind::InvalidTime { found: time }));
        }
        if !(dt.is_finite() && dt > 0.0) {
            return Err(StoryboardError::new(ErrorKind::InvalidStepLength {
                found: dt,
            }));
        }
        if let Some(previous) = self.last_time {
            if time <= previous {
                return Err(StoryboardError::new(ErrorKind::TimeNotIncreasing {
                    previous,
                    found: time,
                }));
            }
            self.step += 1;
        }
        self.last_time = Some(time);
        let mut ctx = StepContext {
            time,
            dt,
            conditions,
            actions,
            log,
            stage: Stage::InitPhase,
            counters: StageCounters::default(),
        };
        if self.status[self.root.index()].state == ElementState::Init {
            self.init_phase(&mut ctx);
        }
        if self.status[self.root.index()].state == ElementState::Running {
            ctx.stage = Stage::StopTriggers;
            self.stop_triggers(&mut ctx);
            ctx.stage = Stage::StartTriggers;
            self.start_triggers(self.root, &mut ctx);
            ctx.stage = Stage::Completions;
            self.completions(self.root, &mut ctx);
        }
        self.counters = ctx.counters;
        Ok(())
    }

    /// Stage 1: Init actions (§8.5.1), then the storyboard's start.
    fn init_phase(&mut self, ctx: &mut StepContext<'_>) {
        let init = self.init;
        self.status[init.index()].state = ElementState::Running;
        for i in 0..self.nodes[init.index()].children.len() {
            self.start(self.nodes[init.index()].children[i], ctx);
        }
        self.completions(init, ctx);
        ctx.actions.init_complete();
        self.start(self.root, ctx);
    }

    /// Evaluates trigger `index` at the step's time, with the states as they are now.
    fn evaluate_trigger(&mut self, index: usize, ctx: &mut StepContext<'_>) -> bool {
        let view = StateView {
            nodes: &self.nodes,
            status: &self.status,
            step: self.step,
        };
        let time = ctx.time;
        let conditions = &mut *ctx.conditions;
        let mut asked = 0;
        let fired = self.triggers[index].evaluate(time, ctx.dt, |id| {
            asked += 1;
            conditions.value(id, time, &view)
        });
        ctx.count().conditions += asked;
        fired
    }

    /// Stage 2: stop triggers of the storyboard and of the running Acts.
    fn stop_triggers(&mut self, ctx: &mut StepContext<'_>) {
        if let Some(trigger) = self.nodes[self.root.index()].stop_trigger {
            if self.evaluate_trigger(trigger, ctx) {
                self.stop_subtree(self.root, ctx);
                return;
            }
        }
        for i in 0..self.acts.len() {
            let act = self.acts[i];
            if self.status[act.index()].state != ElementState::Running {
                continue;
            }
            if let Some(trigger) = self.nodes[act.index()].stop_trigger {
                if self.evaluate_trigger(trigger, ctx) {
                    self.stop_subtree(act, ctx);
                }
            }
        }
    }

    /// Stage 3: the top-down walk handling standby elements under running parents.
    fn start_triggers(&mut self, id: ElementId, ctx: &mut StepContext<'_>) {
        if self.status[id.index()].state == ElementState::Standby {
            self.try_start(id, ctx);
        }
        if self.status[id.index()].state != ElementState::Running {
            return;
        }
        for i in 0..self.nodes[id.index()].children.len() {
            let child = self.nodes[id.index()].children[i];
            if !matches!(
                self.nodes[child.index()].kind,
                ElementKind::Init | ElementKind::Action
            ) {
                self.start_triggers(child, ctx);
            }
        }
    }

    /// A standby element: skip, or evaluate its start trigger and apply the Event priority.
    fn try_start(&mut self, id: ElementId, ctx: &mut StepContext<'_>) {
        if !self.has_executions_left(id) {
            // §8.4.2.1: standby with the executions used up → skipTransition → completeState.
            self.skip(id, ctx);
            return;
        }
        let fired = match self.nodes[id.index()].start_trigger {
            Some(trigger) => self.evaluate_trigger(trigger, ctx),
            // Inherited from the Act, whose start trigger has fired (the Act runs).
            None => true,
        };
        if !fired {
            return;
        }
        if self.nodes[id.index()].kind == ElementKind::Event {
            let others_running = self.running_siblings(id).next().is_some();
            match self.nodes[id.index()].priority.decide(others_running) {
                PriorityDecision::Skip => {
                    self.skip(id, ctx);
                    return;
                }
                PriorityDecision::StopOthersAndStart => {
                    let running: Vec<ElementId> = self.running_siblings(id).collect();
                    for sibling in running {
                        self.stop_subtree(sibling, ctx);
                    }
                }
                PriorityDecision::Start => {}
            }
        }
        self.start(id, ctx);
    }

    /// The running elements that share `id`'s parent (for an Event: its Maneuver's scope).
    fn running_siblings(&self, id: ElementId) -> impl Iterator<Item = ElementId> + '_ {
        let siblings = match self.nodes[id.index()].parent {
            Some(parent) => self.nodes[parent.index()].children.as_slice(),
            None => &[],
        };
        siblings.iter().copied().filter(move |&sibling| {
            sibling != id && self.status[sibling.index()].state == ElementState::Running
        })
    }

    /// Stage 4: the bottom-up walk ending elements whose work is done.
    fn completions(&mut self, id: ElementId, ctx: &mut StepContext<'_>) {
        if self.status[id.index()].state != ElementState::Running {
            return;
        }
        for i in 0..self.nodes[id.index()].children.len() {
            self.completions(self.nodes[id.index()].children[i], ctx);
        }
        match self.nodes[id.index()].kind {
            ElementKind::Storyboard => {}
            ElementKind::Action => self.poll_action(id, ctx),
            // Init is not a storyboard element and has no transitions (§8.5).
            ElementKind::Init if self.children_complete(id) => {
                self.status[id.index()].state = ElementState::Complete;
            }
            ElementKind::Init => {}
            _ if self.children_complete(id) => self.end(id, ctx),
            _ => {}
        }
    }

    fn children_complete(&self, id: ElementId) -> bool {
        self.nodes[id.index()]
            .children
            .iter()
            .all(|child| self.status[child.index()].state == ElementState::Complete)
    }

    /// The work of each stage in the last step.
    pub fn counters(&self) -> StageCounters {
        self.counters
    }

    /// The element states now.
    pub fn view(&self) -> StateView<'_> {
        StateView {
            nodes: &self.nodes,
            status: &self.status,
            step: self.step,
        }
    }

    /// The state of element `id`.
    pub fn state(&self, id: ElementId) -> ElementState {
        self.view().state(id)
    }

    /// The first element named `name`, in document order.
    pub fn find(&self, name: &str) -> Option<ElementId> {
        self.view().find(name)
    }

    /// The storyboard root.
    pub fn root(&self) -> ElementId {
        self.root
    }

    /// True once the storyboard's stop trigger fired.
    pub fn is_complete(&self) -> bool {
        self.status[self.root.index()].state == ElementState::Complete
    }

    /// True once every Story is complete (the storyboard itself keeps running until its stop
    /// trigger fires).
    pub fn stories_complete(&self) -> bool {
        self.nodes[self.root.index()]
            .children
            .iter()
            .filter(|child| self.nodes[child.index()].kind == ElementKind::Story)
            .all(|child| self.status[child.index()].state == ElementState::Complete)
    }

    /// True once every Init action completed.
    pub fn init_complete(&self) -> bool {
        self.status[self.init.index()].state == ElementState::Complete
    }
}
