//! OpenSCENARIO 1.3 storyboard state machine: elements, states, transitions and triggers
//! (§7.2.1 "Storyboard", §7.6 "Conditions and triggers", §8 "Scenario at runtime").
//!
//! Build a [`Storyboard`] from a [`StoryboardDesc`], then call [`Storyboard::step`] once per
//! simulation step with a [`ConditionSource`] (raw condition values), an [`ActionHost`] (runs the
//! actions) and a [`TransitionSink`] (receives a [`TransitionRecord`] per state transition).
//!
//! | module | implements |
//! | --- | --- |
//! | `element` | element handles and kinds (XSD `StoryboardElementType`) |
//! | `state` | states and transitions (§8.1, §8.2) |
//! | `desc` | the description the runtime builds from the scenario model (§7.2.1) |
//! | `tree` | the element store and its construction |
//! | `edge` | `conditionEdge` and the first-evaluation rule (§7.6) |
//! | `delay` | `delay` as a shift of the condition's value in time |
//! | `trigger` | condition groups OR-ed, conditions AND-ed (§7.6.1) |
//! | `priority` | Event priority override / skip / parallel (§8.4.2.2) |
//! | `lifecycle` | start, end, skip and stop transitions and their consequences (§8.3, §8.4) |
//! | `executor` | the step's stages in their fixed order (§8.3–8.5) |
//! | `counters` | the work done by each stage of a step |
//! | `host` | the seams to the runtime: condition values and actions |
//! | `view` | element states for `StoryboardElementStateCondition` |
//! | `log` | transition records for the event log |
//! | `error` | errors |
//!
//! All parts are written by hand: the job is a small, standard-specific state machine that no
//! general crate models (statechart crates have no notion of execution counts, inherited
//! triggers or edge-and-delay conditions).

mod counters;
mod delay;
mod desc;
mod edge;
mod element;
mod error;
mod executor;
mod host;
mod lifecycle;
mod log;
mod priority;
mod state;
mod tree;
mod trigger;
mod view;

pub use counters::{StageCount, StageCounters};
pub use delay::DelayLine;
pub use desc::{
    ActDesc, ActionDesc, ConditionDesc, ConditionGroupDesc, EventDesc, ManeuverDesc,
    ManeuverGroupDesc, StoryDesc, StoryboardDesc, TriggerDesc,
};
pub use edge::{ConditionEdge, EdgeDetector};
pub use element::{ActionId, ConditionId, ElementId, ElementKind};
pub use error::{ErrorKind, StoryboardError, TriggerRole};
pub use executor::Storyboard;
pub use host::{ActionHost, ActionStatus, ConditionSource};
pub use log::{TransitionRecord, TransitionSink};
pub use priority::{Priority, PriorityDecision};
pub use state::{ElementState, StoryboardElementState, Transition};
pub use view::StateView;
