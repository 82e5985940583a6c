//! Handles and kinds of storyboard elements, OpenSCENARIO 1.3 §7.2.1 "Storyboard" and the XSD
//! enumeration `StoryboardElementType`.
//!
//! Elements live in one store inside [`Storyboard`](super::Storyboard) and are addressed by
//! [`ElementId`], a `Copy` index. Conditions and actions are opaque to the storyboard: the runtime
//! names them with [`ConditionId`] and [`ActionId`] when it describes the tree, and answers for them
//! through [`ConditionSource`](super::ConditionSource) and [`ActionHost`](super::ActionHost).

use std::fmt;

/// Handle of one storyboard element in a [`Storyboard`](super::Storyboard).
///
/// Ids are dense indices in depth-first document order (the storyboard is 0), stable for the
/// lifetime of the storyboard that issued them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ElementId(pub(crate) u32);

impl ElementId {
    /// The index of the element in depth-first document order.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// The runtime's handle for one condition (the logical expression inside a `Condition`).
///
/// The storyboard never looks inside; it asks the runtime for the raw value of the expression
/// and applies `conditionEdge` and `delay` itself.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ConditionId(pub u32);

/// The runtime's handle for one action (the behaviour inside an `Action`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ActionId(pub u32);

/// The kind of a storyboard element.
///
/// The names follow the XSD enumeration `StoryboardElementType` (`story`, `act`,
/// `maneuverGroup`, `maneuver`, `event`, `action`), plus `storyboard` for the root and `init`
/// for the Init section, which the standard does not count as a storyboard element (§8.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "camelCase")]
pub enum ElementKind {
    /// The `Storyboard` root.
    Storyboard,
    /// The `Init` section; holds the init actions.
    Init,
    /// A `Story`.
    Story,
    /// An `Act`.
    Act,
    /// A `ManeuverGroup`.
    ManeuverGroup,
    /// A `Maneuver`.
    Maneuver,
    /// An `Event`.
    Event,
    /// An `Action` (of an Event, or of Init).
    Action,
}

impl ElementKind {
    /// The name used in logs, e.g. `"maneuverGroup"`.
    pub fn as_str(self) -> &'static str {
        match self {
            ElementKind::Storyboard => "storyboard",
            ElementKind::Init => "init",
            ElementKind::Story => "story",
            ElementKind::Act => "act",
            ElementKind::ManeuverGroup => "maneuverGroup",
            ElementKind::Maneuver => "maneuver",
            ElementKind::Event => "event",
            ElementKind::Action => "action",
        }
    }
}

impl ElementKind {
    /// Reads the XSD `StoryboardElementType` literal of `StoryboardElementStateCondition`
    /// (`story`, `act`, `maneuverGroup`, `maneuver`, `event`, `action`).
    pub fn from_xsd(literal: &str) -> Option<ElementKind> {
        match literal {
            "story" => Some(ElementKind::Story),
            "act" => Some(ElementKind::Act),
            "maneuverGroup" => Some(ElementKind::ManeuverGroup),
            "maneuver" => Some(ElementKind::Maneuver),
            "event" => Some(ElementKind::Event),
            "action" => Some(ElementKind::Action),
            _ => None,
        }
    }
}

impl fmt::Display for ElementKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}
