//! Global and user-defined actions (OpenSCENARIO 1.3, "Actions", XSD `GlobalAction`,
//! `EntityAction`, `InfrastructureAction`, `ParameterAction`, `VariableAction`,
//! `SetMonitorAction`, `TrafficAction`, `UserDefinedAction`).

use crate::model::{Environment, Position, TrafficAction};

/// Global actions (XSD `GlobalAction`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum GlobalAction {
    /// EnvironmentAction (inline or catalog Environment).
    Environment(Box<Environment>),
    /// EntityAction: add an entity at a position, or delete it.
    Entity {
        /// The entity.
        entity_ref: String,
        /// AddEntityAction position, or None for DeleteEntityAction.
        add_at: Option<Position>,
    },
    /// InfrastructureAction/TrafficSignalAction.
    TrafficSignal(TrafficSignalAction),
    /// SetMonitorAction (1.3).
    SetMonitor {
        /// Monitor name.
        monitor_ref: String,
        /// New value.
        value: bool,
    },
    /// ParameterAction (deprecated since 1.2; parameters are constants at run time).
    Parameter {
        /// Parameter name.
        parameter_ref: String,
        /// Set or modify.
        rule: ModifyRule,
    },
    /// TrafficAction.
    Traffic {
        /// trafficName (1.2+).
        traffic_name: Option<String>,
        /// What to do.
        action: Box<TrafficAction>,
    },
    /// VariableAction (1.2+).
    Variable {
        /// Variable name.
        variable_ref: String,
        /// Set or modify.
        rule: ModifyRule,
    },
}

/// How a ParameterAction or VariableAction changes its value.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ModifyRule {
    /// SetAction: the new value as text.
    Set(String),
    /// ModifyAction/AddValue.
    AddValue(f64),
    /// ModifyAction/MultiplyByValue.
    MultiplyByValue(f64),
}

/// Traffic signal actions (XSD `TrafficSignalAction`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum TrafficSignalAction {
    /// TrafficSignalControllerAction: switch a controller to a phase.
    Controller {
        /// Controller name.
        traffic_signal_controller_ref: String,
        /// Phase name.
        phase: String,
    },
    /// TrafficSignalStateAction: set one signal's state.
    State {
        /// Signal name (id).
        name: String,
        /// State as text.
        state: String,
    },
}

/// A user-defined action (XSD `UserDefinedAction`/`CustomCommandAction`).
#[derive(Debug, Clone, PartialEq)]
pub struct UserDefinedAction {
    /// `type`.
    pub command_type: String,
    /// The element's text content.
    pub content: String,
}
