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
//! - `MiscObject` and `ExternalObjectReference` → `StationaryObject`. An external object
//!   has no BoundingBox in the scenario; its box is that of the road network's `<object>`
//!   of the same name (length, width or 2·radius, height; centre half the height above the
//!   object's origin, OpenDRIVE 1.8 §13.2). One without such a box is left out, with one
//!   warning ([`GroundTruthSink::take_warnings`]), since OSI requires a positive dimension.
//! - `source_reference` = {scenario file, `net.asam.openscenario`, [kind, entity name]},
//!   `model_reference` from `model3d`, `color_description` from the entity's colour,
//!   `host_vehicle_id` from [`SinkOptions::host`] (default the entity named `Ego`, else none),
//!   lanes and boundaries in the first frame or every frame ([`SinkOptions::static_data`]).
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
//!
//! The engine's frames do not carry the `pedestrianCategory` and `miscObjectCategory` OSI
//! needs, so the sink reads them from the scenario model it is made with (loaded with the same
//! parameter overrides as the engine's). Entities the scenario does not declare (spawned
//! traffic) are vehicles of their own category, else `car`.

use std::collections::{BTreeMap, BTreeSet};
use std::sync::Arc;

use engine::output::{EntityFrame, Frame};
use engine::runtime::{EntityKind as EngineKind, Visibility};
use opendrive::RoadNetwork;
use scenario::{EntityObject, Scenario};

use crate::entity::{EntityInfo, EntityKind, MiscObjectInfo};
use crate::ground_truth::{GroundTruthBuilder, StaticData};
use crate::lights::{LightMode, VehicleLight};
use crate::osi3::{ColorDescription, GroundTruth, Identifier};
use crate::polyline::Sampling;
use crate::rigid_body::RigidBodyState;
use crate::Error;

/// How the ground truth is made.
#[derive(Debug, Clone, Default)]
pub struct SinkOptions {
    /// The host vehicle's entity name (default [`crate::ground_truth::DEFAULT_HOST`]).
    pub host: Option<String>,
    /// In which frames lanes and lane boundaries go.
    pub static_data: StaticData,
    /// The file the source references name (default the scenario's path; `oscsim run` names
    /// the file it was given, which for a parameter distribution is not the scenario's).
    pub scenario_file: Option<String>,
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

/// What OSI needs to know about an entity beyond the engine's frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Category {
    /// `pedestrianCategory`.
    Pedestrian(&'static str),
    /// `miscObjectCategory`.
    MiscObject(&'static str),
}

/// The OSI mapping of one run (see the module doc).
pub struct GroundTruthSink {
    builder: GroundTruthBuilder,
    network: Arc<RoadNetwork>,
    scenario_file: String,
    categories: BTreeMap<String, Category>,
    /// Boxes of the road objects that ExternalObjectReferences name.
    external_boxes: BTreeMap<String, ExternalBox>,
    /// ExternalObjectReferences without a box, reported once and left out.
    unboxed: BTreeSet<String>,
    /// Warnings not yet taken by [`GroundTruthSink::take_warnings`].
    warnings: Vec<String>,
    /// The host vehicle's entity name.
    host: String,
}

/// The bounding box of an OpenDRIVE `<object>`: centre relative to the object's origin
/// (its base, so `height / 2` up) and length, width, height (OpenDRIVE 1.8 §13.2; a
/// round object of `radius` r is 2r × 2r).
#[derive(Debug, Clone, Copy, PartialEq)]
struct ExternalBox {
    centre: [f64; 3],
    dimension: [f64; 3],
}

impl GroundTruthSink {
    /// Prepares the ground truth of a run of `scenario` on `network` (the road network the
    /// engine runs on): lanes and boundaries sampled from it, categories and object boxes
    /// read from the scenario.
    pub fn new(
        scenario: &Scenario,
        network: Arc<RoadNetwork>,
        options: &SinkOptions,
    ) -> Result<Self, Error> {
        let map_reference = scenario
            .road_network
            .logic_file
            .as_ref()
            .map(|p| p.display().to_string());
        let mut builder = GroundTruthBuilder::new(options.static_data);
        builder.set_road_network(&network, map_reference.as_deref(), &Sampling::default())?;
        builder.set_model_reference(scenario.road_network.scene_graph_file.as_deref());
        builder.set_host(options.host.as_deref());
        let mut warnings = Vec::new();
        if let Some(host) = options.host.as_deref() {
            if scenario.entities.object(host).is_none() {
                warnings.push(format!(
                    "host vehicle '{host}' names no entity of the scenario; host_vehicle_id is set \
                     only if an entity of that name appears"
                ));
            }
        }
        Ok(GroundTruthSink {
            builder,
            external_boxes: external_boxes(scenario, &network),
            network,
            scenario_file: options
                .scenario_file
                .clone()
                .unwrap_or_else(|| scenario.path.display().to_string()),
            categories: categories(scenario),
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

    /// The GroundTruth of `frame`.
    pub fn ground_truth(&mut self, frame: &Frame<'_>) -> Result<GroundTruth, FrameError> {
        // Simulation time is non-negative and far below u64::MAX ns (584 years).
        let nanos = (frame.time * 1e9).round() as u64;
        let mut gt = self.builder.begin_frame(nanos);
        let host = self.host.as_str();
        for e in frame
            .objects()
            .filter(|e| in_ground_truth(e.name, e.visibility, host))
        {
            let category = self.categories.get(e.name).copied();
            let external = (e.kind == EngineKind::External && !has_box(&e))
                .then(|| self.external_boxes.get(e.name));
            if external == Some(None) {
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
            let external = external.flatten();
            // The engine's trailer id indexes the frame's entity store (EntityFrame::trailer).
            let trailer = e
                .trailer
                .and_then(|t| frame.entities.get(t as usize))
                .filter(|t| in_ground_truth(&t.name, t.visibility, host))
                .map(|t| t.name.as_str());
            Self::add(
                &mut gt,
                &self.network,
                &self.scenario_file,
                category,
                external,
                trailer,
                &e,
            )
            .map_err(|source| FrameError {
                time: frame.time,
                entity: e.name.to_owned(),
                source,
            })?;
        }
        Ok(gt.finish())
    }

    /// Adds one entity to the open frame.
    fn add(
        frame: &mut crate::ground_truth::FrameBuilder<'_>,
        network: &RoadNetwork,
        scenario_file: &str,
        category: Option<Category>,
        external: Option<&ExternalBox>,
        trailer: Option<&str>,
        e: &EntityFrame<'_>,
    ) -> Result<(), Error> {
        let mut state = rigid_body_state(e);
        if let Some(b) = external {
            state.bbox_centre = b.centre;
            state.dimension = b.dimension;
        }
        let lanes: Vec<Identifier> = e
            .road_position
            .and_then(|p| crate::lanes::assigned_lane_at(frame.ids(), network, p))
            .into_iter()
            .collect();
        let color = color(e)?;
        let kind = match (e.kind, category) {
            (EngineKind::Pedestrian, Some(Category::Pedestrian(category))) => {
                EntityKind::Pedestrian { category }
            }
            (EngineKind::Pedestrian, _) => EntityKind::Pedestrian {
                category: "pedestrian",
            },
            (EngineKind::Vehicle, _) => EntityKind::Vehicle {
                category: e.vehicle_category.map_or("car", |v| v.as_str()),
            },
            (EngineKind::MiscObject | EngineKind::External, _) => {
                let category = match category {
                    Some(Category::MiscObject(c)) => Some(c),
                    _ if e.kind == EngineKind::MiscObject => Some("none"),
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
                return frame.add_misc_object(&info, &lanes).map(drop);
            }
        };
        let lights = match kind {
            EntityKind::Vehicle { .. } => crate::lights::light_state(&vehicle_lights(e)),
            EntityKind::Pedestrian { .. } => None,
        };
        let info = EntityInfo {
            name: e.name,
            kind,
            scenario_file: Some(scenario_file),
            model3d: e.model3d,
            color,
            trailer,
            lights,
        };
        frame.add_entity(&info, &state, &lanes).map(drop)
    }
}

/// Whether the entity `name` with `visibility` belongs in the GroundTruth: visible to sensors,
/// or the host vehicle `host` (module doc, docs/osi.md "Visibility").
fn in_ground_truth(name: &str, visibility: Visibility, host: &str) -> bool {
    visibility.sensors || name == host
}

/// The GroundTruths of the frames of the latest step, encoded (osi_groundtruth.proto bytes):
/// the engine frame sink of the Python and C bindings, which hand them out between steps. The
/// first step has two frames (t = 0, with the lanes, and t = dt), later steps one, a call
/// after the run's end none; [`StepFrames::begin_step`] before each step forgets the last
/// step's frames, [`StepFrames::latest`] keeps the newest frame of the run.
pub struct StepFrames {
    sink: GroundTruthSink,
    frames: Vec<Vec<u8>>,
    latest: Vec<u8>,
}

impl StepFrames {
    /// No frames yet.
    pub fn new(sink: GroundTruthSink) -> Self {
        StepFrames {
            sink,
            frames: Vec::new(),
            latest: Vec::new(),
        }
    }

    /// Forgets the frames of the step before (call before each step).
    pub fn begin_step(&mut self) {
        if let Some(last) = self.frames.pop() {
            self.latest = last;
        }
        self.frames.clear();
    }

    /// The frames of the latest step, in time order.
    pub fn frames(&self) -> &[Vec<u8>] {
        &self.frames
    }

    /// The newest frame of the run (the current state), empty before the first step.
    pub fn latest(&self) -> &[u8] {
        self.frames.last().unwrap_or(&self.latest)
    }
}

impl engine::FrameSink for StepFrames {
    fn frame(&mut self, frame: &Frame<'_>) -> std::io::Result<()> {
        use prost::Message;
        let gt = self
            .sink
            .ground_truth(frame)
            .map_err(std::io::Error::other)?;
        self.frames.push(gt.encode_to_vec());
        Ok(())
    }
}

/// The lights LightStateActions set on `e`, in the form `osi::lights` takes.
fn vehicle_lights<'e>(e: &EntityFrame<'e>) -> Vec<VehicleLight<'e>> {
    e.lights
        .iter()
        .filter_map(|(light, state)| {
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
        .collect()
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

/// Boxes of the road-network objects named by the scenario's ExternalObjectReferences
/// (the first `<object>` of that name, roads in file order).
fn external_boxes(scenario: &Scenario, network: &RoadNetwork) -> BTreeMap<String, ExternalBox> {
    let objects: Vec<&opendrive::Object> =
        network.roads().iter().flat_map(|r| &r.objects).collect();
    scenario
        .entities
        .scenario_objects
        .iter()
        .filter_map(|o| match &o.entity_object {
            EntityObject::ExternalObjectReference(name) => {
                let object = objects.iter().find(|x| x.name == *name)?;
                let dimension = match (object.length, object.width, object.radius) {
                    (Some(l), Some(w), _) => [l, w, object.height?],
                    (_, _, Some(r)) => [2.0 * r, 2.0 * r, object.height?],
                    _ => return None,
                };
                dimension
                    .iter()
                    .all(|d| d.is_finite() && *d > 0.0)
                    .then(|| {
                        let centre = [0.0, 0.0, dimension[2] / 2.0];
                        (o.name.clone(), ExternalBox { centre, dimension })
                    })
            }
            _ => None,
        })
        .collect()
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

/// Pedestrian and misc-object categories of the scenario's entities, by name.
fn categories(scenario: &Scenario) -> BTreeMap<String, Category> {
    scenario
        .entities
        .scenario_objects
        .iter()
        .filter_map(|o| {
            let category = match &o.entity_object {
                EntityObject::Pedestrian(p) => Category::Pedestrian(p.pedestrian_category.as_str()),
                EntityObject::MiscObject(m) => {
                    Category::MiscObject(m.misc_object_category.as_str())
                }
                _ => return None,
            };
            Some((o.name.clone(), category))
        })
        .collect()
}
