//! `osi::sink::OsiSink` fed by the engine in-process, on the cli's `tests/files/osi_mapping.xosc`
//! (see that file and crates/cli/tests/osi/mapping.rs for the hand-worked positions): the
//! categories OSI needs travel on the engine's frames (no second reading of the scenario) —
//! Dog's pedestrianCategory `animal` → `TYPE_ANIMAL`, Chair's `wheelchair` → a vehicle of type
//! `WHEELCHAIR` (OSI 3.8 osi_object.proto), Tree's miscObjectCategory `tree` → stationary
//! `TYPE_TREE` — and the source reference names the scenario file as it was opened.

use std::num::NonZeroU64;
use std::path::Path;

use engine::{load, Engine, EngineConfig};
use osi::ground_truth::StaticData;
use osi::osi3::moving_object::vehicle_classification::Type as VehicleType;
use osi::osi3::moving_object::Type as MovingType;
use osi::osi3::stationary_object::classification::Type as StationaryType;
use osi::sink::{OsiSink, OsiSinkOptions};

#[test]
fn categories_and_sources_come_from_the_frames() {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../cli/tests/files/osi_mapping.xosc"
    );
    let scenario = scenario::Scenario::load(Path::new(file)).expect("scenario loads");
    let network = load::road_network(&scenario).expect("road loads");
    let config = EngineConfig {
        duration: Some(0.1),
        ..EngineConfig::default()
    };
    let mut engine = Engine::new(&scenario, network, config).expect("engine builds");
    let dir = std::env::temp_dir().join(format!("oscsim-osi-sink-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let trace = dir.join("gt.osi");
    let options = OsiSinkOptions {
        path: trace.clone(),
        host: None,
        static_data: StaticData::First,
        every: NonZeroU64::MIN,
        pinned_time: Some(0),
    };
    let mut sink = OsiSink::create(&engine, &options).expect("sink");
    assert!(sink.take_warnings().is_empty());
    engine.run(&mut sink, &mut ()).expect("runs");
    assert_eq!(sink.finished_path(), Some(trace.as_path()));
    // 0.1 s at 0.05 s: the frames at t = 0, 0.05, 0.1.
    assert_eq!(sink.frames(), 3);

    let frames = osi::trace::read_osi(&trace).expect("reads back");
    std::fs::remove_dir_all(&dir).expect("temp dir removed");
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
