//! The scenario as a whole (OpenSCENARIO 1.3, XSD `OpenScenario` with group
//! `ScenarioDefinition`, `RoadNetwork`, `TrafficSignals`).

use std::path::PathBuf;

use crate::model::{
    Entities, FileHeader, MonitorDeclaration, ParameterDeclaration, Position, Storyboard,
    VariableDeclaration,
};
use crate::source::SourcePos;
use crate::warning::Warning;

/// A loaded scenario: every parameter, expression and catalog reference resolved.
#[derive(Debug, Clone, PartialEq)]
pub struct Scenario {
    /// The scenario file as opened.
    pub path: PathBuf,
    /// FileHeader.
    pub file_header: FileHeader,
    /// Global parameters after `--param` overrides.
    pub parameter_declarations: Vec<ParameterDeclaration>,
    /// VariableDeclarations (1.2+).
    pub variable_declarations: Vec<VariableDeclaration>,
    /// MonitorDeclarations (1.3).
    pub monitor_declarations: Vec<MonitorDeclaration>,
    /// CatalogLocations: (catalog kind element, directory resolved against the scenario).
    pub catalog_locations: Vec<(String, PathBuf)>,
    /// RoadNetwork.
    pub road_network: RoadNetwork,
    /// Entities.
    pub entities: Entities,
    /// Storyboard.
    pub storyboard: Storyboard,
    /// When the file opened was a ParameterValueDistribution: its path (the model is that of
    /// its ScenarioFile, loaded with the default parameter values).
    pub parameter_value_distribution: Option<PathBuf>,
    /// Deprecated forms and features newer than the declared version, in document order.
    pub warnings: Vec<Warning>,
    /// The files it was loaded from, kept for [`Scenario::with_parameters`].
    pub sources: crate::Sources,
}

/// The road network (XSD `RoadNetwork`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RoadNetwork {
    /// LogicFile, resolved against the scenario's directory; checked to exist.
    pub logic_file: Option<PathBuf>,
    /// SceneGraphFile as written (not checked: a visualisation asset).
    pub scene_graph_file: Option<String>,
    /// TrafficSignals controllers.
    pub traffic_signal_controllers: Vec<TrafficSignalController>,
    /// UsedArea corners (1.1+).
    pub used_area: Vec<Position>,
}

/// A traffic signal controller (XSD `TrafficSignalController`).
#[derive(Debug, Clone, PartialEq)]
pub struct TrafficSignalController {
    /// `name`.
    pub name: String,
    /// Delay to the referenced controller, s.
    pub delay: Option<f64>,
    /// Referenced controller.
    pub reference: Option<String>,
    /// Phases in order.
    pub phases: Vec<Phase>,
    /// Where the element is.
    pub pos: SourcePos,
}

/// A signal phase (XSD `Phase`).
#[derive(Debug, Clone, PartialEq)]
pub struct Phase {
    /// `name`.
    pub name: String,
    /// Duration, s.
    pub duration: f64,
    /// TrafficSignalState entries: (trafficSignalId, state).
    pub signal_states: Vec<(String, String)>,
    /// TrafficSignalGroupState@state (1.2+).
    pub group_state: Option<String>,
    /// Where the element is.
    pub pos: SourcePos,
}
