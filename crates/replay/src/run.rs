//! A run to show: its manifest, trajectories, event log and road network, opened from what
//! `oscsim run` wrote (the CSV with its `NAME.run.json` manifest, or the manifest itself) or
//! made by running a scenario here ([`Run::simulate`]).
//!
//! A CSV without a manifest (an esmini reference file, say) opens with `scenario` in
//! [`OpenOptions`]: entity boxes, kinds and the road then come from the scenario's
//! declarations (entities spawned during the run, which it does not declare, get a
//! 4.5 m × 1.8 m × 1.5 m box).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use engine::{Engine, EngineConfig};
use opendrive::RoadNetwork;
use scenario::{EntityObject, Scenario};

use crate::error::{Error, ErrorKind, Result};
use crate::events::{self, EventEntry};
use crate::manifest::{relative_to, EntityInfo, RunManifest, FORMAT};
use crate::recorder::{EventRecorder, Recorder};
use crate::scenario_info;
use crate::trajectories::Trajectories;

/// A run with everything needed to draw it.
#[derive(Debug)]
pub struct Run {
    /// What the run was.
    pub manifest: RunManifest,
    /// The frames.
    pub trajectories: Trajectories,
    /// The event log (empty when the run wrote none).
    pub events: Vec<EventEntry>,
    /// The road network, when the scenario names one.
    pub network: Option<Arc<RoadNetwork>>,
    /// A title for pages and charts (the scenario's or the CSV's file name).
    pub title: String,
}

/// How to open a run file.
#[derive(Debug, Clone, Default)]
pub struct OpenOptions {
    /// The scenario, for a CSV without a manifest.
    pub scenario: Option<PathBuf>,
    /// The event log, instead of the manifest's.
    pub events: Option<PathBuf>,
}

/// Where each file of a run is.
struct Paths {
    csv: PathBuf,
    events: Option<PathBuf>,
    road: Option<PathBuf>,
}

impl Run {
    /// Opens what `oscsim run` wrote: `path` is the trajectory CSV or its `.run.json`.
    pub fn open(path: &Path, options: &OpenOptions) -> Result<Run> {
        let is_manifest = path.to_string_lossy().ends_with(".json");
        let manifest_path = if is_manifest {
            path.to_owned()
        } else {
            RunManifest::beside(path)
        };
        let (manifest, paths) = if manifest_path.exists() {
            let m = RunManifest::read(&manifest_path)?;
            let resolve =
                |p: &Option<PathBuf>| p.as_ref().map(|p| RunManifest::resolve(&manifest_path, p));
            let csv = if is_manifest {
                resolve(&m.trajectories).ok_or_else(|| {
                    Error::invalid(&manifest_path, 1, 1, "a \"trajectories\" file", "null")
                })?
            } else {
                path.to_owned()
            };
            let paths = Paths {
                csv,
                events: resolve(&m.events),
                road: resolve(&m.road_network),
            };
            (m, paths)
        } else if let (Some(scenario_path), false) = (&options.scenario, is_manifest) {
            let scenario = Scenario::load(scenario_path)?;
            let m = declared_manifest(&scenario, scenario_path);
            let road = scenario.road_network.logic_file.clone();
            (
                m,
                Paths {
                    csv: path.to_owned(),
                    events: None,
                    road,
                },
            )
        } else {
            return Err(Error::new(ErrorKind::NoManifest {
                looked_for: manifest_path,
            }));
        };
        let trajectories = Trajectories::read(&paths.csv)?;
        let events = match options.events.as_ref().or(paths.events.as_ref()) {
            Some(p) => events::read(p)?,
            None => Vec::new(),
        };
        let network = paths
            .road
            .as_deref()
            .map(RoadNetwork::from_file)
            .transpose()?
            .map(Arc::new);
        let title = file_name(manifest.scenario.as_deref().unwrap_or(&paths.csv));
        Ok(Run {
            manifest,
            trajectories,
            events,
            network,
            title,
        })
    }

    /// Loads `scenario_path` through the front door (either language, with `options`: a DSL
    /// scenario's road network and seed, an XML scenario's `--param` overrides), runs it here
    /// and keeps its outputs in memory, as `oscsim run --csv --events` would have written them.
    pub fn simulate(
        scenario_path: &Path,
        options: &load::Options,
        config: EngineConfig,
    ) -> Result<Run> {
        let loaded = load::load(scenario_path, options)?;
        let mut engine = Engine::new(&loaded.scenario, Arc::clone(&loaded.network), config)?;
        let mut recorder = Recorder::new();
        let mut log = EventRecorder::new();
        engine.run(&mut recorder, &mut log)?;
        let (csv, entities) = recorder.into_parts();
        Run::from_memory(
            &loaded,
            scenario_path,
            &options.params,
            &config,
            (&csv, entities),
            &log.into_inner(),
        )
    }

    /// A run of `loaded` (loaded from `scenario_path` with `params`) recorded in memory:
    /// `frames` the trajectory CSV text and the entities seen (`recorder::Recorder`), `log`
    /// the event log text (`recorder::EventRecorder`).
    pub fn from_memory(
        loaded: &load::Loaded,
        scenario_path: &Path,
        params: &[(String, String)],
        config: &EngineConfig,
        frames: (&[u8], Vec<EntityInfo>),
        log: &[u8],
    ) -> Result<Run> {
        let (csv, entities) = frames;
        let manifest = manifest_for(
            loaded,
            scenario_path,
            params,
            config,
            entities,
            Path::new("."),
        );
        let name = PathBuf::from(format!("{} (in memory)", file_name(scenario_path)));
        let trajectories = Trajectories::parse(&String::from_utf8_lossy(csv), &name)?;
        let events = events::parse(&String::from_utf8_lossy(log), &name)?;
        // The network the scenario names (a scenario that names none has none to draw).
        let network = loaded
            .scenario
            .road_network
            .logic_file
            .is_some()
            .then(|| Arc::clone(&loaded.network));
        Ok(Run {
            manifest,
            trajectories,
            events,
            network,
            title: file_name(scenario_path),
        })
    }
}

/// The file name of `path`, for titles.
fn file_name(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}

/// The manifest of a run of `loaded` (loaded from `scenario_path` with `params`) whose
/// frames showed `entities`; paths relative to folder `manifest_dir`. The caller fills in
/// `trajectories` and `events`.
pub fn manifest_for(
    loaded: &load::Loaded,
    scenario_path: &Path,
    params: &[(String, String)],
    config: &EngineConfig,
    entities: Vec<EntityInfo>,
    manifest_dir: &Path,
) -> RunManifest {
    let mut m = scenario_manifest(
        &loaded.scenario,
        scenario_path,
        params,
        config,
        entities,
        manifest_dir,
    );
    m.phases = loaded.phases.iter().map(|p| p.path.clone()).collect();
    m
}

/// [`manifest_for`] a scenario model alone (no DSL phases).
fn scenario_manifest(
    scenario: &Scenario,
    scenario_path: &Path,
    params: &[(String, String)],
    config: &EngineConfig,
    mut entities: Vec<EntityInfo>,
    manifest_dir: &Path,
) -> RunManifest {
    for e in &mut entities {
        e.controllers = scenario_info::controllers(scenario, &e.name);
    }
    RunManifest {
        format: FORMAT.to_owned(),
        scenario: Some(relative_to(scenario_path, manifest_dir)),
        road_network: scenario
            .road_network
            .logic_file
            .as_deref()
            .map(|p| relative_to(p, manifest_dir)),
        parameters: params.to_vec(),
        dt: config.dt,
        seed: config.seed,
        trajectories: None,
        events: None,
        entities,
        measures: scenario_info::measures(scenario),
        actions: scenario_info::action_actors(scenario),
        phases: Vec::new(),
    }
}

/// A manifest from the scenario's declarations alone (for a CSV written elsewhere): ids in
/// declaration order, boxes and kinds as declared.
fn declared_manifest(scenario: &Scenario, scenario_path: &Path) -> RunManifest {
    let entities = scenario
        .entities
        .scenario_objects
        .iter()
        .enumerate()
        .map(|(i, o)| {
            let (kind, category, bb) = match &o.entity_object {
                EntityObject::Vehicle(v) => (
                    "vehicle",
                    Some(v.vehicle_category.as_str().to_owned()),
                    Some(v.bounding_box),
                ),
                EntityObject::Pedestrian(p) => (
                    "pedestrian",
                    Some(p.pedestrian_category.as_str().to_owned()),
                    Some(p.bounding_box),
                ),
                EntityObject::MiscObject(m) => (
                    "miscObject",
                    Some(m.misc_object_category.as_str().to_owned()),
                    Some(m.bounding_box),
                ),
                _ => ("external", None, None),
            };
            let (box_center, box_size) = bb.map_or(([0.0, 0.0, 0.0], [0.0, 0.0, 0.0]), |b| {
                (b.center, [b.length, b.width, b.height])
            });
            EntityInfo {
                id: i as u32,
                name: o.name.clone(),
                kind: kind.to_owned(),
                category,
                color: None,
                box_center,
                box_size,
                trailer: None,
                controllers: Vec::new(),
            }
        })
        .collect();
    let config = EngineConfig::default();
    let mut m = scenario_manifest(
        scenario,
        scenario_path,
        &[],
        &config,
        entities,
        Path::new("."),
    );
    m.scenario = Some(scenario_path.to_owned());
    m.road_network = scenario.road_network.logic_file.clone();
    m
}

/// The box of an entity the manifest does not list (spawned in a run read without one).
pub const DEFAULT_BOX_SIZE: [f64; 3] = [4.5, 1.8, 1.5];
