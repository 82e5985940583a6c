//! `osi::sink::OsiSink` fed by the engine in-process, on the cli's `tests/files/osi_mapping.xosc`
//! (see that file and crates/cli/tests/osi/mapping.rs for the hand-worked positions): the
//! categories OSI needs travel on the engine's frames (no second reading of the scenario) —
//! Dog's pedestrianCategory `animal` → `TYPE_ANIMAL`, Chair's `wheelchair` → a vehicle of type
//! `WHEELCHAIR` (OSI 3.8 osi_object.proto), Tree's miscObjectCategory `tree` → stationary
//! `TYPE_TREE` — and the source reference names the scenario file as it was opened; declared
//! and drawn vehicle roles reach `vehicle_classification.role`.

use std::path::Path;

use engine::{load, Engine, EngineConfig};
use osi::osi3::moving_object::vehicle_classification::Role;
use osi::osi3::moving_object::vehicle_classification::Type as VehicleType;
use osi::osi3::moving_object::Type as MovingType;
use osi::osi3::stationary_object::classification::Type as StationaryType;
use osi::osi3::GroundTruth;
use osi::sink::{OsiSink, OsiSinkOptions};

use crate::common;

/// Runs scenario `file` for `duration` s into an OSI trace (a frame per step, static data in
/// the first) in a temp folder; returns the engine after the run and the frames read back.
/// The sink gives no warnings and finishes the trace it was asked for.
fn run_to_trace(file: &str, duration: f64, tag: &str) -> (Engine, Vec<GroundTruth>) {
    let scenario = scenario::Scenario::load(Path::new(file)).expect("scenario loads");
    let network = load::road_network(&scenario).expect("road loads");
    let config = EngineConfig {
        duration: Some(duration),
        ..EngineConfig::default()
    };
    let mut engine = Engine::new(&scenario, network, config).expect("engine builds");
    let dir = common::temp_dir(tag);
    let trace = dir.path().join("gt.osi");
    let options = OsiSinkOptions {
        pinned_time: Some(0),
        ..OsiSinkOptions::new(trace.clone())
    };
    let mut sink = OsiSink::create(&engine, &options).expect("sink");
    assert!(sink.take_warnings().is_empty());
    engine.run(&mut sink, &mut ()).expect("runs");
    assert_eq!(sink.finished_path(), Some(trace.as_path()));
    let frames = osi::trace::read_osi(&trace).expect("reads back");
    (engine, frames)
}

#[test]
fn categories_and_sources_come_from_the_frames() {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../cli/tests/files/osi_mapping.xosc"
    );
    let (_, frames) = run_to_trace(file, 0.1, "sink");
    // 0.1 s at 0.05 s: the frames at t = 0, 0.05, 0.1.
    assert_eq!(frames.len(), 3);
    let gt = &frames[0];
    let moving = |name: &str| {
        gt.moving_object
            .iter()
            .find(|o| o.source_reference[0].identifier[1] == name)
            .unwrap_or_else(|| panic!("{name} in the frame"))
    };
    assert_eq!(moving("Dog").r#type, Some(MovingType::Animal as i32));
    let chair = moving("Chair");
    assert_eq!(chair.r#type, Some(MovingType::Vehicle as i32));
    let class = chair.vehicle_classification.as_ref().expect("class");
    assert_eq!(class.r#type, Some(VehicleType::Wheelchair as i32));
    assert_eq!(chair.source_reference[0].reference.as_deref(), Some(file));
    let tree = &gt
        .stationary_object
        .iter()
        .find(|o| o.source_reference[0].identifier[1] == "Tree")
        .expect("Tree");
    let class = tree.classification.as_ref().expect("classification");
    assert_eq!(class.r#type, Some(StationaryType::Tree as i32));
    assert_eq!(tree.model_reference.as_deref(), Some("oak.osgb"));
}

/// Roles reach `vehicle_classification.role` (OSI 3.8 numbers: CIVIL 2, AMBULANCE 3, POLICE 5):
/// the Ego of the engine's `traffic_roles.xosc` is declared `ambulance`; its spawned vehicles
/// carry the role drawn from the VehicleRoleDistribution (civil or police), the same in the
/// trace as in the engine's snapshot.
#[test]
fn declared_and_drawn_roles_reach_the_vehicle_classification() {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../engine/tests/files/entities/traffic_roles.xosc"
    );
    let (engine, frames) = run_to_trace(file, 5.0, "roles");
    let last = frames.last().expect("frames");
    let role_of = |name: &str| {
        last.moving_object
            .iter()
            .find(|o| o.source_reference[0].identifier[1] == name)
            .and_then(|o| o.vehicle_classification.as_ref())
            .and_then(|c| c.role)
    };
    assert_eq!(role_of("Ego"), Some(Role::Ambulance as i32));
    let spawned: Vec<_> = engine
        .entities()
        .into_iter()
        .filter(|e| e.name.starts_with("src.entity_"))
        .collect();
    // 2 vehicles/s from t = 0.5 s: 10 by t = 5 s.
    assert_eq!(spawned.len(), 10);
    for e in spawned {
        let expected = match e.role {
            Some(scenario::Role::Civil) => Role::Civil,
            Some(scenario::Role::Police) => Role::Police,
            other => panic!("{} has role {other:?}", e.name),
        };
        assert_eq!(role_of(&e.name), Some(expected as i32), "{}", e.name);
    }
}
