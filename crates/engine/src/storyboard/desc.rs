//! The description of a storyboard that the runtime hands to [`Storyboard::new`]: the element
//! tree of OpenSCENARIO 1.3 §7.2.1 (Storyboard → Story → Act → ManeuverGroup → Maneuver → Event →
//! Action, plus Init) with triggers (§7.6), priorities and execution counts (§8.4), and opaque
//! condition and action ids.
//!
//! These types are deliberately independent of the scenario model (crate `scenario`), so the
//! storyboard can be built and tested on its own; the runtime converts the model in one function.
//! The tree shape is enforced by the types; [`Storyboard::new`] checks the values (delays, empty
//! condition groups).
//!
//! [`Storyboard::new`]: super::Storyboard::new

use super::edge::ConditionEdge;
use super::element::{ActionId, ConditionId};
use super::priority::Priority;

/// The whole storyboard (XSD `Storyboard`).
#[derive(Debug, Clone, PartialEq)]
pub struct StoryboardDesc {
    /// Name used in logs (the standard's Storyboard has none; esmini logs `storyBoard`).
    pub name: String,
    /// The Init actions (XSD `Init/Actions`), run in the init phase (§8.5).
    pub init_actions: Vec<ActionDesc>,
    /// The stories.
    pub stories: Vec<StoryDesc>,
    /// Ends the scenario; without one the storyboard never stops (§7.2.1).
    pub stop_trigger: Option<TriggerDesc>,
}

/// A `Story`.
#[derive(Debug, Clone, PartialEq)]
pub struct StoryDesc {
    /// `name`.
    pub name: String,
    /// The acts.
    pub acts: Vec<ActDesc>,
}

/// An `Act`.
#[derive(Debug, Clone, PartialEq)]
pub struct ActDesc {
    /// `name`.
    pub name: String,
    /// `StartTrigger`; without one the Act starts with its Story (§8.3).
    pub start_trigger: Option<TriggerDesc>,
    /// `StopTrigger`; evaluated while the Act runs.
    pub stop_trigger: Option<TriggerDesc>,
    /// The maneuver groups.
    pub maneuver_groups: Vec<ManeuverGroupDesc>,
}

/// A `ManeuverGroup`.
#[derive(Debug, Clone, PartialEq)]
pub struct ManeuverGroupDesc {
    /// `name`.
    pub name: String,
    /// `maximumExecutionCount` (required in the XSD).
    pub maximum_execution_count: u32,
    /// The maneuvers.
    pub maneuvers: Vec<ManeuverDesc>,
}

/// A `Maneuver`.
#[derive(Debug, Clone, PartialEq)]
pub struct ManeuverDesc {
    /// `name`.
    pub name: String,
    /// The events.
    pub events: Vec<EventDesc>,
}

/// An `Event`.
#[derive(Debug, Clone, PartialEq)]
pub struct EventDesc {
    /// `name`.
    pub name: String,
    /// `priority`.
    pub priority: Priority,
    /// `maximumExecutionCount`; the XSD makes it optional, the runtime passes 1 when absent.
    pub maximum_execution_count: u32,
    /// `StartTrigger`; without one the Event inherits its Act's (§8.4.2) and starts with its
    /// Maneuver.
    pub start_trigger: Option<TriggerDesc>,
    /// The actions.
    pub actions: Vec<ActionDesc>,
}

/// An `Action` (in an Event or in Init).
#[derive(Debug, Clone, PartialEq)]
pub struct ActionDesc {
    /// `name`.
    pub name: String,
    /// The runtime's handle for the action's behaviour.
    pub id: ActionId,
}

/// A `Trigger`: condition groups OR-ed (§7.6.1).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TriggerDesc {
    /// `ConditionGroup` elements. An empty list (allowed by OpenSCENARIO 1.0) never fires:
    /// the OR of no groups is false.
    pub condition_groups: Vec<ConditionGroupDesc>,
}

/// A `ConditionGroup`: conditions AND-ed (§7.6.1). Must hold at least one condition (XSD).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ConditionGroupDesc {
    /// The conditions.
    pub conditions: Vec<ConditionDesc>,
}

/// A `Condition` slot: the runtime's expression plus the edge and delay the storyboard applies.
#[derive(Debug, Clone, PartialEq)]
pub struct ConditionDesc {
    /// `name`.
    pub name: String,
    /// The runtime's handle for the logical expression.
    pub id: ConditionId,
    /// `conditionEdge`.
    pub edge: ConditionEdge,
    /// `delay` in seconds, ≥ 0.
    pub delay: f64,
    /// Where the condition was read, e.g. `cut-in.xosc:102:23`, shown in errors.
    pub origin: Option<String>,
}

impl TriggerDesc {
    /// A trigger of one group holding one condition.
    pub fn single(condition: ConditionDesc) -> Self {
        TriggerDesc::all_of(vec![condition])
    }

    /// A trigger of one group: all `conditions` AND-ed.
    pub fn all_of(conditions: Vec<ConditionDesc>) -> Self {
        TriggerDesc {
            condition_groups: vec![ConditionGroupDesc { conditions }],
        }
    }
}

impl ConditionDesc {
    /// A condition slot without origin.
    pub fn new(name: &str, id: ConditionId, edge: ConditionEdge, delay: f64) -> Self {
        ConditionDesc {
            name: name.to_owned(),
            id,
            edge,
            delay,
            origin: None,
        }
    }
}
