//! The engine→OSI mapping: [`GroundTruthSink`] turns each engine [`Frame`] into one ASAM OSI
//! 3.8.0 `osi3.GroundTruth` (osi_groundtruth.proto) with [`GroundTruthBuilder`]. The command
//! line (`oscsim run --osi`) writes them to a trace file; the Python and C bindings hand out the
//! latest one as bytes.
//!
//! Mapping (the engine's entity kinds, OpenSCENARIO 1.3 §7.2, onto OSI 3.8 osi_object.proto):
//! - `Vehicle` and `Pedestrian` → `MovingObject`; `base.position` is the bounding-box
//!   centre, reference point + R(h, p, r)·`BoundingBox/Center`; velocity and acceleration
//!   are those of that point (the `osi::rigid_body` kinematics), `orientation_rate` the yaw
//!   rate; lanes go to `moving_object_classification.assigned_lane_id` (the lane the engine
//!   reports, when the reference point is on the road surface).
//! - `MiscObject` and `ExternalObjectReference` → `StationaryObject`. The engine gives an
//!   external object the box of the road network's `<object>` it stands for
//!   (engine `runtime/external.rs`); one without a positive box is left out, with one
//!   warning ([`GroundTruthSink::take_warnings`]), since OSI requires a positive dimension.
//! - Categories come from the frame: a pedestrian's `pedestrianCategory` (default
//!   `pedestrian`), a vehicle's `vehicleCategory` (spawned traffic without one: `car`), a misc
//!   object's `miscObjectCategory` (default `none`).
//! - `source_reference` = {scenario file as opened ([`engine::ScenarioSource`]; for a
//!   ParameterValueDistribution the distribution file), `net.asam.openscenario`, [kind, entity
//!   name]}, `map_reference` the `LogicFile`, `model_reference` of the map the `SceneGraphFile`;
//!   `model_reference` from `model3d`, `color_description` from the entity's colour,
//!   `host_vehicle_id` from [`SinkOptions::host`] (default the entity named `Ego`, else none),
//!   lanes and boundaries in the first frame or every frame ([`SinkOptions::static_data`]).
//! - OpenDRIVE signals: `traffic_light` (one per bulb, mode from the engine's live signal
//!   states, `Frame::signals`) and `traffic_sign`, by [`crate::traffic_signals`]; their ids
//!   come after the first frame's entities'.
//! - The environment in force (`Frame::environment`, EnvironmentAction) →
//!   `environmental_conditions`, by [`crate::environment`], in every frame once an
//!   EnvironmentAction has set something; the wind's north is turned by the OpenDRIVE
//!   header `<offset>` heading.
//! - A vehicle towing a trailer (`TrailerHitch` connected by the scenario's `Trailer` or a
//!   `ConnectTrailerAction`, OpenSCENARIO 1.3 §7.2.2.6) gets
//!   `vehicle_classification.has_trailer = true` and `trailer_id` = the OSI id of the
//!   trailer's `MovingObject` (OSI 3.8 osi_object.proto); every other vehicle
//!   `has_trailer = false` and no `trailer_id`.
//! - VisibilityAction (OpenSCENARIO 1.3 XSD `VisibilityAction`): an entity with `sensors`
//!   false is left out of the GroundTruth while the flag is off (it keeps its id for when it
//!   returns), except the host vehicle, which carries the sensors; a vehicle whose trailer is
//!   left out so has `has_trailer = false` in those frames. `graphics` and `traffic` change
//!   nothing here. Why: docs/osi.md "Visibility".
//! - LightStateAction: a vehicle's lights go to `vehicle_classification.light_state` by the
//!   table of `osi::lights` (unset while no action touched a light).
//! - A vehicle's `role` (declared, or drawn for spawned traffic from its VehicleRoleDistribution)
//!   goes to `vehicle_classification.role` by `osi::classification::vehicle_role` (unset
//!   without a role).
//!
//!
//! Everything comes from the engine ([`Engine::road_network`], [`Engine::source`]) and its
//! frames: the sink never reads the scenario. [`StepFrames`] (the bindings) and [`OsiSink`]
//! (an OSI trace file, `oscsim run --osi`) are the two engine frame sinks built on it.

mod step_frames;
mod trace_sink;

pub use step_frames::StepFrames;
pub use trace_sink::{OsiSink, OsiSinkOptions};

use std::collections::BTreeSet;
use std::sync::Arc;

use engine::output::{EntityFrame, Frame};
use engine::{Engine, EntityKind as EngineKind, Visibility};
use opendrive::RoadNetwork;

use crate::entity::{EntityInfo, EntityKind, MiscObjectInfo};
use crate::ground_truth::{GroundTruthBuilder, StaticData};
use crate::lights::{LightMode, VehicleLight};
use crate::osi3::{ColorDescription, GroundTruth, Identifier};
use crate::polyline::Sampling;
use crate::rigid_body::RigidBodyState;
use crate::traffic_signals::TrafficSignals;
use crate::Error;

/// How the ground truth is made.
#[derive(Debug, Clone, Default)]
pub struct SinkOptions {
    /// The host vehicle's entity name (default [`crate::ground_truth::DEFAULT_HOST`]).
    pub host: Option<String>,
    /// In which frames lanes and lane boundaries go.
    pub static_data: StaticData,
}

/// A frame that could not be mapped: its time, the entity and why.
#[derive(Debug, thiserror::Error)]
#[error("OSI frame at t = {time:.3} s, entity '{entity}': {source}")]
pub struct FrameError {
    /// Simulation time of the frame (s).
    pub time: f64,
    /// The entity.
    pub entity: String,
    /// Why.
    #[source]
    pub source: Error,
}

/// The OSI mapping of one run (see the module doc).
pub struct GroundTruthSink {
    builder: GroundTruthBuilder,
    network: Arc<RoadNetwork>,
    scenario_file: String,
    /// ExternalObjectReferences without a box, reported once and left out.
    unboxed: BTreeSet<String>,
    /// Warnings not yet taken by [`GroundTruthSink::take_warnings`].
    warnings: Vec<String>,
    /// The host vehicle's entity name.
    host: String,
    /// The road network's signals, placed.
    signals: TrafficSignals,
    /// Heading of the OpenDRIVE header `<offset>` (rad; 0 without one): world → projected
    /// frame, where north is.
    north_yaw: f64,
}

impl GroundTruthSink {
    /// Prepares the ground truth of a run of `engine`: lanes and boundaries sampled from its
    /// road network, map and source references from its [`engine::ScenarioSource`].
    pub fn new(engine: &Engine, options: &SinkOptions) -> Result<Self, Error> {
        let source = engine.source();
        let network = engine.road_network();
        let map_reference = source
            .road_network_file
            .as_ref()
            .map(|p| p.display().to_string());
        let mut builder = GroundTruthBuilder::new(options.static_data);
        builder.set_road_network(&network, map_reference.as_deref(), &Sampling::default())?;
        builder.set_model_reference(source.scene_graph_file.as_deref());
        builder.set_host(options.host.as_deref());
        let mut warnings = Vec::new();
        if let Some(host) = options.host.as_deref() {
            if engine.entity_id(host).is_none() {
                warnings.push(format!(
                    "host vehicle '{host}' names no entity of the scenario; host_vehicle_id is set \
                     only if an entity of that name appears"
                ));
            }
        }
        let (signals, signal_warnings) = TrafficSignals::new(&network, map_reference.as_deref());
        warnings.extend(signal_warnings);
        let north_yaw = network.header().offset.as_ref().map_or(0.0, |o| o.hdg);
        Ok(GroundTruthSink {
            north_yaw,
            signals,
            builder,
            network,
            scenario_file: source.file.display().to_string(),
            unboxed: BTreeSet::new(),
            warnings,
            host: options
                .host
                .clone()
                .unwrap_or_else(|| crate::ground_truth::DEFAULT_HOST.to_owned()),
        })
    }

    /// Warnings since the last call (entities left out, an unknown host), once each.
    pub fn take_warnings(&mut self) -> Vec<String> {
        std::mem::take(&mut self.warnings)
    }

    /// The GroundTruth of `frame`. The message is the sink's, written over by the next frame
    /// (see [`crate::ground_truth`]): encode or copy it before the next call.
    pub fn ground_truth(&mut self, frame: &Frame<'_>) -> Result<&GroundTruth, FrameError> {
        // Simulation time is non-negative and far below u64::MAX ns (584 years).
        let nanos = (frame.time * 1e9).round() as u64;
        let mut gt = self.builder.begin_frame(nanos);
        let host = self.host.as_str();
        for e in frame
            .objects()
            .filter(|e| in_ground_truth(e.name, e.visibility, host))
        {
            if e.kind == EngineKind::External && !has_box(&e) {
                if self.unboxed.insert(e.name.to_owned()) {
                    self.warnings.push(format!(
                        "OSI: ExternalObjectReference '{}' has no bounding box and names no \
                         <object> with length, width (or radius) and height in the road \
                         network; left out of the ground truth",
                        e.name
                    ));
                }
                continue;
            }
            // The engine's trailer id is an entity index (EntityFrame::trailer).
            let trailer = e
                .trailer
                .and_then(|t| frame.entity(t))
                .filter(|t| in_ground_truth(t.name, t.visibility, host))
                .map(|t| t.name);
            add(&mut gt, &self.network, &self.scenario_file, trailer, &e).map_err(|source| {
                FrameError {
                    time: frame.time,
                    entity: e.name.to_owned(),
                    source,
                }
            })?;
        }
        self.signals.add_to(&mut gt, |id| frame.signals.state(id));
        gt.set_environmental_conditions(crate::environment::environmental_conditions(
            frame.environment,
            frame.time,
            self.north_yaw,
        ));
        Ok(gt.finish())
    }
}

/// Whether the entity `name` with `visibility` belongs in the GroundTruth: visible to sensors,
/// or the host vehicle `host` (module doc, docs/osi.md "Visibility").
fn in_ground_truth(name: &str, visibility: Visibility, host: &str) -> bool {
    visibility.sensors || name == host
}

/// Adds entity `e` to the open frame; `trailer` is the name of the trailer it tows, if that
/// trailer is in the frame.
fn add(
    frame: &mut crate::ground_truth::FrameBuilder<'_>,
    network: &RoadNetwork,
    scenario_file: &str,
    trailer: Option<&str>,
    e: &EntityFrame<'_>,
) -> Result<(), Error> {
    let state = rigid_body_state(e);
    let lane: Option<Identifier> = e
        .road_position
        .and_then(|p| crate::lanes::assigned_lane_at(frame.ids(), network, p));
    let lanes = lane.as_slice();
    let color = color(e)?;
    let kind = match e.kind {
        EngineKind::Pedestrian => EntityKind::Pedestrian {
            category: e.pedestrian_category.map_or("pedestrian", |c| c.as_str()),
        },
        EngineKind::Vehicle => EntityKind::Vehicle {
            category: e.vehicle_category.map_or("car", |v| v.as_str()),
        },
        EngineKind::MiscObject | EngineKind::External => {
            let category = match e.kind {
                EngineKind::MiscObject => {
                    Some(e.misc_object_category.map_or("none", |c| c.as_str()))
                }
                _ => None,
            };
            let info = MiscObjectInfo {
                name: e.name,
                category,
                scenario_file: Some(scenario_file),
                model3d: e.model3d,
                color,
                position: state.bbox_centre_position(),
                orientation: state.orientation,
                dimension: state.dimension,
            };
            return frame.add_misc_object(&info, lanes).map(drop);
        }
    };
    let (lights, role) = match kind {
        EntityKind::Vehicle { .. } => (
            crate::lights::light_state_of(vehicle_lights(e)),
            e.role.map(|r| r.as_str()),
        ),
        EntityKind::Pedestrian { .. } => (None, None),
    };
    let info = EntityInfo {
        name: e.name,
        kind,
        scenario_file: Some(scenario_file),
        model3d: e.model3d,
        color,
        trailer,
        lights,
        role,
    };
    frame.add_entity(&info, &state, lanes).map(drop)
}

/// The lights LightStateActions set on `e`, in the form `osi::lights` takes.
fn vehicle_lights<'e>(e: &EntityFrame<'e>) -> impl Iterator<Item = VehicleLight<'e>> {
    e.lights.iter().filter_map(|(light, state)| {
        let mode = match state.mode.as_str() {
            "on" => LightMode::On,
            "off" => LightMode::Off,
            "flashing" => LightMode::Flashing,
            _ => return None,
        };
        Some(VehicleLight {
            light,
            mode,
            color_type: state.color.as_ref().map(|c| c.color_type.as_str()),
        })
    })
}

/// The reference-point state of `e` in the form `osi::rigid_body` takes.
fn rigid_body_state(e: &EntityFrame<'_>) -> RigidBodyState {
    let c = e.bounding_box.center();
    RigidBodyState {
        reference_point: [e.pose.x, e.pose.y, e.pose.z],
        orientation: [e.pose.h, e.pose.p, e.pose.r],
        orientation_rate: [e.yaw_rate, 0.0, 0.0],
        velocity: [e.velocity.x, e.velocity.y, e.velocity.z],
        acceleration: [e.acceleration.x, e.acceleration.y, e.acceleration.z],
        bbox_centre: [c.x, c.y, c.z],
        dimension: [
            e.bounding_box.length(),
            e.bounding_box.width(),
            e.bounding_box.height(),
        ],
        ..Default::default()
    }
}

/// Whether the engine knows a positive box for `e`.
fn has_box(e: &EntityFrame<'_>) -> bool {
    let b = e.bounding_box;
    b.length() > 0.0 && b.width() > 0.0 && b.height() > 0.0
}

/// The entity's colour as an OSI `ColorDescription` (sRGB channels 0–255 → 0–1).
fn color(e: &EntityFrame<'_>) -> Result<Option<ColorDescription>, Error> {
    e.color
        .map(|c| {
            let [r, g, b] = c.rgb();
            crate::color::from_rgb(
                f64::from(r) / 255.0,
                f64::from(g) / 255.0,
                f64::from(b) / 255.0,
            )
        })
        .transpose()
}
