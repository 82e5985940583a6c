//! `oscsim run … --osi PATH`: the engine→OSI adapter, a [`FrameSink`] that turns each
//! engine [`Frame`] into one ASAM OSI 3.8.0 `osi3.GroundTruth` (osi_groundtruth.proto) with
//! `osi::ground_truth::GroundTruthBuilder` and writes it to an `osi::trace::TraceFile`
//! (`.osi` or `.mcap`, ASAM OSI 3.8 §2.2.6.1; directory naming §2.2.6.2).
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
//!   warning on stderr, since OSI requires a positive dimension.
//! - `source_reference` = {scenario file, `net.asam.openscenario`, [kind, entity name]},
//!   `model_reference` from `model3d`, `color_description` from the entity's colour,
//!   `host_vehicle_id` from `--osi-host` (default the entity named `Ego`, else none),
//!   lanes and boundaries in the first frame or every frame (`--osi-static first|every`).
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
//! The engine's runtime entity does not keep the `pedestrianCategory` and
//! `miscObjectCategory` OSI needs, so the adapter reads them from the scenario model,
//! loaded a second time with the same `--param` overrides (a few milliseconds, only with
//! `--osi`). Entities the scenario does not declare (spawned traffic) are vehicles of their
//! own category, else `car`.
//!
//! Determinism: the trace bytes depend only on the inputs. The clock enters only where the
//! standard asks for a recording time: the `<UTC timestamp>` of the file name when PATH is a
//! directory. `SOURCE_DATE_EPOCH` (Unix seconds, the reproducible-builds convention) pins
//! it, and then also fills the MCAP `creation_time`, which stays unset otherwise.

use std::collections::{BTreeMap, BTreeSet};
use std::num::NonZeroU64;
use std::path::{Path, PathBuf};

use anyhow::Context;
use engine::output::{EntityFrame, Frame};
use engine::runtime::{EntityKind as EngineKind, Visibility};
use engine::{Engine, FrameSink};
use opendrive::RoadNetwork;
use osi::entity::{EntityInfo, EntityKind, MiscObjectInfo};
use osi::ground_truth::{GroundTruthBuilder, StaticData};
use osi::lights::{LightMode, VehicleLight};
use osi::osi3::{ColorDescription, Identifier};
use osi::polyline::Sampling;
use osi::rigid_body::RigidBodyState;
use osi::trace::{utc_basic_timestamp, McapTraceInfo, TraceFile, TraceFormat, TraceOptions};
use scenario::{EntityObject, Scenario};

/// In which frames lanes and lane boundaries go (`--osi-static`).
#[derive(clap::ValueEnum, Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OsiStatic {
    /// Only in the first frame.
    #[default]
    First,
    /// In every frame.
    Every,
}

/// The `--osi*` settings of `oscsim run`.
#[derive(Debug, Clone)]
pub struct OsiOptions {
    /// `--osi PATH`: a `.osi` / `.mcap` file, or a directory for a conventionally named `.osi`.
    pub path: PathBuf,
    /// `--osi-host NAME`: the host vehicle (default `Ego`).
    pub host: Option<String>,
    /// `--osi-static`.
    pub static_data: OsiStatic,
    /// `--osi-every N`: keep every Nth step.
    pub every: NonZeroU64,
}

/// What OSI needs to know about an entity beyond the engine's frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Category {
    /// `pedestrianCategory`.
    Pedestrian(&'static str),
    /// `miscObjectCategory`.
    MiscObject(&'static str),
}

/// The OSI writer of one run (see the module doc).
pub struct OsiSink {
    builder: GroundTruthBuilder,
    trace: TraceFile,
    network: std::sync::Arc<RoadNetwork>,
    scenario_file: String,
    categories: BTreeMap<String, Category>,
    /// Boxes of the road objects that ExternalObjectReferences name.
    external_boxes: BTreeMap<String, ExternalBox>,
    /// ExternalObjectReferences without a box, reported once and left out.
    unboxed: BTreeSet<String>,
    /// The host vehicle's entity name (`--osi-host`, else `Ego`).
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

impl OsiSink {
    /// Prepares the OSI output of `engine`, built from `scenario` (read from `scenario_path`).
    pub fn create(
        engine: &Engine,
        scenario: &Scenario,
        scenario_path: &Path,
        options: &OsiOptions,
    ) -> anyhow::Result<Self> {
        let network = engine.road_network();
        let map_reference = scenario
            .road_network
            .logic_file
            .as_ref()
            .map(|p| p.display().to_string());
        let mut builder = GroundTruthBuilder::new(match options.static_data {
            OsiStatic::First => StaticData::First,
            OsiStatic::Every => StaticData::Every,
        });
        builder
            .set_road_network(&network, map_reference.as_deref(), &Sampling::default())
            .context("cannot build the OSI lanes of the road network")?;
        builder.set_model_reference(scenario.road_network.scene_graph_file.as_deref());
        builder.set_host(options.host.as_deref());
        if let Some(host) = options.host.as_deref() {
            if scenario.entities.object(host).is_none() {
                eprintln!(
                    "warning: --osi-host '{host}' names no entity of the scenario; \
                     host_vehicle_id is set only if an entity of that name appears"
                );
            }
        }
        make_room(&options.path)?;
        let pinned = source_date_epoch()?;
        let start = pinned.unwrap_or_else(now_unix_seconds);
        let scenario_name = scenario_path.file_stem().map_or_else(
            || "scenario".to_owned(),
            |s| s.to_string_lossy().into_owned(),
        );
        let trace = TraceFile::create(
            &options.path,
            TraceOptions {
                scenario_name: scenario_name.clone(),
                directory_format: TraceFormat::Osi,
                every: options.every,
                start_unix_seconds: start,
                mcap_info: McapTraceInfo {
                    creation_time: pinned.map(iso8601),
                    description: Some(format!("oscsim ground truth of scenario {scenario_name}")),
                    data_sources: Some(scenario_path.display().to_string()),
                },
            },
        )
        .with_context(|| format!("cannot create the OSI trace {}", options.path.display()))?;
        Ok(OsiSink {
            builder,
            trace,
            external_boxes: external_boxes(scenario, &network),
            network,
            scenario_file: scenario_path.display().to_string(),
            categories: categories(scenario),
            unboxed: BTreeSet::new(),
            host: options
                .host
                .clone()
                .unwrap_or_else(|| osi::ground_truth::DEFAULT_HOST.to_owned()),
        })
    }

    /// Adds one entity to the open frame.
    fn add(
        frame: &mut osi::ground_truth::FrameBuilder<'_>,
        network: &RoadNetwork,
        scenario_file: &str,
        category: Option<Category>,
        external: Option<&ExternalBox>,
        trailer: Option<&str>,
        e: &EntityFrame<'_>,
    ) -> Result<(), osi::Error> {
        let mut state = rigid_body_state(e);
        if let Some(b) = external {
            state.bbox_centre = b.centre;
            state.dimension = b.dimension;
        }
        let lanes: Vec<Identifier> = e
            .road_position
            .and_then(|p| osi::lanes::assigned_lane_at(frame.ids(), network, p))
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
            EntityKind::Vehicle { .. } => osi::lights::light_state(&vehicle_lights(e)),
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

impl FrameSink for OsiSink {
    fn frame(&mut self, frame: &Frame<'_>) -> std::io::Result<()> {
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
                    eprintln!(
                        "warning: OSI: ExternalObjectReference '{}' has no bounding box and \
                         names no <object> with length, width (or radius) and height in the \
                         road network; left out of the ground truth",
                        e.name
                    );
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
            .map_err(|err| {
                std::io::Error::other(format!(
                    "OSI frame at t = {:.3} s, entity '{}': {err}",
                    frame.time, e.name
                ))
            })?;
        }
        let gt = gt.finish();
        self.trace.offer(&gt).map_err(std::io::Error::other)
    }

    fn finish(&mut self) -> std::io::Result<()> {
        let path = self.trace.finish().map_err(std::io::Error::other)?;
        println!(
            "OSI trace {} ({} frames)",
            path.display(),
            self.trace.frames()
        );
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
fn color(e: &EntityFrame<'_>) -> Result<Option<ColorDescription>, osi::Error> {
    e.color
        .map(|c| {
            let [r, g, b] = c.rgb();
            osi::color::from_rgb(
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

/// Creates the folder `path` names when it ends in a separator (directory mode), else the
/// folder the trace file goes in.
fn make_room(path: &Path) -> anyhow::Result<()> {
    let as_dir = path
        .as_os_str()
        .to_string_lossy()
        .ends_with(std::path::MAIN_SEPARATOR);
    let dir = if as_dir { Some(path) } else { path.parent() };
    match dir.filter(|d| !d.as_os_str().is_empty()) {
        Some(d) => std::fs::create_dir_all(d)
            .with_context(|| format!("cannot create folder {}", d.display())),
        None => Ok(()),
    }
}

/// `SOURCE_DATE_EPOCH` as Unix seconds, if set.
fn source_date_epoch() -> anyhow::Result<Option<i64>> {
    match std::env::var("SOURCE_DATE_EPOCH") {
        Ok(text) => {
            text.trim().parse().map(Some).with_context(|| {
                format!("expected Unix seconds in SOURCE_DATE_EPOCH, found '{text}'")
            })
        }
        Err(_) => Ok(None),
    }
}

/// The wall clock as Unix seconds (0 if the clock is before 1970).
fn now_unix_seconds() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| i64::try_from(d.as_secs()).unwrap_or(i64::MAX))
}

/// ISO 8601 extended UTC time (`2026-11-21T05:00:00Z`) for the MCAP `creation_time`.
fn iso8601(unix_seconds: i64) -> String {
    // `utc_basic_timestamp` gives YYYYMMDDTHHMMSSZ (ASCII; four-digit years up to 9999).
    let b = utc_basic_timestamp(unix_seconds);
    if b.len() != 16 {
        return b;
    }
    format!(
        "{}-{}-{}T{}:{}:{}Z",
        &b[0..4],
        &b[4..6],
        &b[6..8],
        &b[9..11],
        &b[11..13],
        &b[13..15]
    )
}
