//! The state of a running scenario as plain values, for library users (bindings, batch runs,
//! tools): each entity in the scene (OpenSCENARIO 1.3 §7.2.2 "Entities"; poses in the world
//! frame of §6.3), the parameter and variable values (§9.1, §7.7.1), the environment in force.
//! Owned copies: they stay valid while the engine steps on, and reading them never exposes the
//! engine's internal state. [`Engine`](crate::Engine) gives them (`runtime/read.rs`).

use std::collections::BTreeMap;
use std::path::PathBuf;

use opendrive::{Pose, Real, RoadPosition};
use scenario::{
    LightState, MiscObjectCategory, PedestrianCategory, Role, Scenario, VehicleCategory,
};

use crate::domain::{BoundingBox, Color, Vector3};
use crate::world::{ControllerOverrides, EntityId, EntityKind, Visibility};

pub use crate::world::{Clock, EnvironmentState};

/// One entity in the scene at one moment: what a frame carries, owned.
#[derive(Debug, Clone, PartialEq)]
pub struct EntityState {
    /// Handle: index in declaration order (spawned entities after), stable through the run.
    pub id: EntityId,
    /// `ScenarioObject/@name` (spawned traffic: the name the traffic action gave).
    pub name: String,
    /// Vehicle, pedestrian, misc object or external object.
    pub kind: EntityKind,
    /// Pose of the reference point in the world frame (a vehicle's rear-axle centre, on the
    /// ground).
    pub pose: Pose,
    /// Bounding box, centre relative to the reference point.
    pub bounding_box: BoundingBox,
    /// Velocity of the reference point in world axes (m/s).
    pub velocity: Vector3,
    /// Acceleration of the reference point in world axes (m/s²).
    pub acceleration: Vector3,
    /// Yaw rate (rad/s).
    pub yaw_rate: Real,
    /// Signed longitudinal speed (m/s).
    pub speed: Real,
    /// Distance travelled since the start (m).
    pub odometer: Real,
    /// Road and lane position of the reference point, if on a road.
    pub road_position: Option<RoadPosition>,
    /// Vehicle category (vehicles only).
    pub vehicle_category: Option<VehicleCategory>,
    /// Pedestrian category (pedestrians declared in the scenario only).
    pub pedestrian_category: Option<PedestrianCategory>,
    /// Misc object category (misc objects only).
    pub misc_object_category: Option<MiscObjectCategory>,
    /// Role in traffic (`role` of a Vehicle or Pedestrian; spawned vehicles: the role drawn
    /// from their TrafficDefinition's VehicleRoleDistribution).
    pub role: Option<Role>,
    /// Colour, if known.
    pub color: Option<Color>,
    /// `model3d`, if given.
    pub model3d: Option<String>,
    /// VisibilityAction flags (all true unless an action changed them).
    pub visibility: Visibility,
    /// The state LightStateAction last gave each light, by light type; lights no action
    /// touched are absent.
    pub lights: BTreeMap<String, LightState>,
    /// The trailer this vehicle tows now.
    pub trailer: Option<EntityId>,
    /// Driver inputs overridden by OverrideControllerValueAction (recorded, not applied).
    pub overrides: ControllerOverrides,
}

/// Where the scenario came from, for outputs that name their sources (an OSI
/// `source_reference` and `map_reference`, a trace's metadata). Carried on every
/// [`Frame`](crate::Frame) and given by [`Engine::source`](crate::Engine::source).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ScenarioSource {
    /// The scenario file as it was opened (for a ParameterValueDistribution, the distribution
    /// file); the scenario's own path when it was not loaded from files.
    pub file: PathBuf,
    /// `RoadNetwork/LogicFile`, resolved against the scenario's folder.
    pub road_network_file: Option<PathBuf>,
    /// `RoadNetwork/SceneGraphFile`, as written.
    pub scene_graph_file: Option<String>,
}

impl ScenarioSource {
    /// The source of `scenario`.
    pub fn of(scenario: &Scenario) -> Self {
        let opened = scenario.sources.opened();
        ScenarioSource {
            file: if opened.as_os_str().is_empty() {
                scenario.path.clone()
            } else {
                opened.to_path_buf()
            },
            road_network_file: scenario.road_network.logic_file.clone(),
            scene_graph_file: scenario.road_network.scene_graph_file.clone(),
        }
    }
}
