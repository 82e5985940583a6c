//! The storyboard (OpenSCENARIO 1.3 §7.2.1 "Storyboard", §7.3.1 "ManeuverGroups and
//! Actors"; XSD `Storyboard`, `Init`, `Story`, `Act`, `ManeuverGroup`, `Actors`, `Maneuver`,
//! `Event`, `Action`).

use crate::model::{
    CatalogOrigin, GlobalAction, Priority, PrivateAction, Trigger, UserDefinedAction,
};
use crate::source::SourcePos;

/// The storyboard (XSD `Storyboard`).
#[derive(Debug, Clone, PartialEq)]
pub struct Storyboard {
    /// Init.
    pub init: Init,
    /// Stories.
    pub stories: Vec<Story>,
    /// StopTrigger: ends the simulation when it fires (absent: never).
    pub stop_trigger: Option<Trigger>,
}

/// Init (XSD `Init`/`InitActions`): actions that set the initial state.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Init {
    /// GlobalAction and UserDefinedAction entries, in document order (name is empty).
    pub actions: Vec<Action>,
    /// Private entries: actions per entity.
    pub privates: Vec<Private>,
}

/// Private init actions of one entity (XSD `Private`).
#[derive(Debug, Clone, PartialEq)]
pub struct Private {
    /// The entity.
    pub entity_ref: String,
    /// Its actions (kind `Private`, name empty).
    pub actions: Vec<Action>,
}

/// A story (XSD `Story`).
#[derive(Debug, Clone, PartialEq)]
pub struct Story {
    /// `name`.
    pub name: String,
    /// Acts.
    pub acts: Vec<Act>,
    /// Where the Story starts.
    pub pos: SourcePos,
}

/// An act (XSD `Act`).
#[derive(Debug, Clone, PartialEq)]
pub struct Act {
    /// `name`.
    pub name: String,
    /// ManeuverGroups.
    pub maneuver_groups: Vec<ManeuverGroup>,
    /// StartTrigger (absent: starts with its story).
    pub start_trigger: Option<Trigger>,
    /// StopTrigger.
    pub stop_trigger: Option<Trigger>,
    /// Where the Act starts.
    pub pos: SourcePos,
}

/// A maneuver group (XSD `ManeuverGroup`).
#[derive(Debug, Clone, PartialEq)]
pub struct ManeuverGroup {
    /// `name`.
    pub name: String,
    /// `maximumExecutionCount`.
    pub maximum_execution_count: u32,
    /// Actors.
    pub actors: Actors,
    /// Maneuvers, the catalog ones (CatalogReference) resolved, in document order.
    pub maneuvers: Vec<Maneuver>,
    /// Where the ManeuverGroup starts.
    pub pos: SourcePos,
}

/// Actors (XSD `Actors`).
#[derive(Debug, Clone, PartialEq)]
pub struct Actors {
    /// `selectTriggeringEntities`: the entities that triggered the act are actors too.
    pub select_triggering_entities: bool,
    /// EntityRef names (objects or selections).
    pub entity_refs: Vec<String>,
}

/// A maneuver (XSD `Maneuver`).
#[derive(Debug, Clone, PartialEq)]
pub struct Maneuver {
    /// `name`.
    pub name: String,
    /// Events.
    pub events: Vec<Event>,
    /// Set when it came from a catalog.
    pub catalog: Option<CatalogOrigin>,
    /// Where the Maneuver starts.
    pub pos: SourcePos,
}

/// An event (XSD `Event`).
#[derive(Debug, Clone, PartialEq)]
pub struct Event {
    /// `name`.
    pub name: String,
    /// `priority` (the deprecated `overwrite` reads as `override`).
    pub priority: Priority,
    /// `maximumExecutionCount` (default 1).
    pub maximum_execution_count: u32,
    /// Actions.
    pub actions: Vec<Action>,
    /// StartTrigger (absent: starts with its maneuver).
    pub start_trigger: Option<Trigger>,
    /// Where the Event starts.
    pub pos: SourcePos,
}

/// An action with its name (XSD `Action`).
#[derive(Debug, Clone, PartialEq)]
pub struct Action {
    /// `name` (empty for Init actions).
    pub name: String,
    /// What it does.
    pub kind: ActionKind,
    /// Where the action element starts.
    pub pos: SourcePos,
}

/// The kinds of action (XSD `Action` choice).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ActionKind {
    /// GlobalAction.
    Global(GlobalAction),
    /// UserDefinedAction.
    UserDefined(UserDefinedAction),
    /// PrivateAction (for the actors).
    Private(PrivateAction),
    /// An `<Action>` with no child element. The XSD requires one of the three choices; the
    /// reader accepts the empty element with a warning (as esmini's own test scenarios write
    /// it) and the engine runs it as a no-op that ends at once, so that conditions on its
    /// state still see a start and an end.
    Empty,
}

impl ActionKind {
    /// The XSD element name of the action's choice: `LongitudinalAction`, `LateralAction`,
    /// `TeleportAction`, … for a PrivateAction; `EnvironmentAction`, `EntityAction`,
    /// `TrafficSignalAction`, `SetMonitorAction`, `ParameterAction`, `TrafficAction`,
    /// `VariableAction` for a GlobalAction; `UserDefinedAction`.
    pub fn type_name(&self) -> &'static str {
        match self {
            ActionKind::Private(p) => match p {
                PrivateAction::Longitudinal(_) => "LongitudinalAction",
                PrivateAction::Lateral(_) => "LateralAction",
                PrivateAction::Visibility(_) => "VisibilityAction",
                PrivateAction::Synchronize(_) => "SynchronizeAction",
                PrivateAction::Controller(_) => "ControllerAction",
                PrivateAction::Teleport(_) => "TeleportAction",
                PrivateAction::Routing(_) => "RoutingAction",
                PrivateAction::Appearance(_) => "AppearanceAction",
                PrivateAction::Trailer(_) => "TrailerAction",
                // No XML form: oscsim's own name.
                PrivateAction::Check(_) => "StateCheck",
                PrivateAction::CreateRandomTraffic(_) => "CreateRandomTraffic",
            },
            ActionKind::Global(g) => match g {
                GlobalAction::Environment(_) => "EnvironmentAction",
                GlobalAction::Entity { .. } => "EntityAction",
                GlobalAction::TrafficSignal(_) => "TrafficSignalAction",
                GlobalAction::SetMonitor { .. } => "SetMonitorAction",
                GlobalAction::Parameter { .. } => "ParameterAction",
                GlobalAction::Traffic { .. } => "TrafficAction",
                GlobalAction::Variable { .. } => "VariableAction",
            },
            ActionKind::UserDefined(_) => "UserDefinedAction",
            ActionKind::Empty => "Action",
        }
    }
}
