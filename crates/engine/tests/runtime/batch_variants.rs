//! The library front door for batches (issue 12): 1,000 engines built from one parsed scenario
//! and one `Arc<RoadNetwork>`, each with another value of a global parameter, without reading
//! a file after the first load — the scenario and road files are deleted before the engines
//! are built, so any read would fail.
//!
//! examples/scenarios/cut_in_highway.xosc: Ego is placed at s = 30 on lane −2 of road 0 and
//! its Init SpeedAction (step shape) sets `$EgoSpeed`. After the first step of dt = 0.05 s its
//! speed is that value exactly and it has travelled speed · dt along its lane.

use std::fs;
use std::sync::Arc;

use engine::{load, Engine, EngineConfig};
use scenario::Scenario;

/// Engines built.
const VARIANTS: usize = 1000;
/// Odometer after one step: v · dt written as a product of two decimals (m).
const TOL: f64 = 1e-9;

#[test]
fn a_thousand_engines_share_one_network_and_read_no_file() {
    let repo = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
    // Removed below to show that the engines read no file; on a failure before, at the drop.
    let tmp = tempfile::Builder::new()
        .prefix("oscsim-batch-")
        .tempdir()
        .expect("temp dir");
    let dir = tmp.path();
    fs::create_dir_all(dir.join("scenarios")).expect("temp dir");
    fs::create_dir_all(dir.join("roads")).expect("temp dir");
    let scenario_path = dir.join("scenarios/cut_in_highway.xosc");
    fs::copy(
        format!("{repo}/examples/scenarios/cut_in_highway.xosc"),
        &scenario_path,
    )
    .expect("copy scenario");
    fs::copy(
        format!("{repo}/examples/roads/highway.xodr"),
        dir.join("roads/highway.xodr"),
    )
    .expect("copy road");

    // The first (and only) load: scenario, then its road network.
    let base = Scenario::load(&scenario_path).expect("scenario loads");
    let network = load::road_network(&base).expect("road network loads");
    fs::remove_dir_all(dir).expect("temp dir removed");
    assert!(!scenario_path.exists());

    let config = EngineConfig::default();
    let speed_of = |i: usize| 10.0 + 0.02 * i as f64;
    let mut engines = Vec::with_capacity(VARIANTS);
    for i in 0..VARIANTS {
        let value = speed_of(i).to_string();
        let variant = base
            .with_parameters(&[("EgoSpeed".to_owned(), value)])
            .expect("variant resolves from memory");
        let mut engine = Engine::new(&variant, network.clone(), config).expect("engine builds");
        engine.step(&mut (), &mut ()).expect("first step runs");
        engines.push(engine);
    }
    // One network, shared: this handle and one per engine.
    assert_eq!(Arc::strong_count(&network), VARIANTS + 1);
    assert!(engines
        .iter()
        .all(|e| Arc::ptr_eq(&e.road_network(), &network)));
    for (i, engine) in engines.iter().enumerate() {
        let ego = engine.entity("Ego").expect("Ego placed by Init");
        assert_eq!(ego.speed, speed_of(i), "variant {i}");
        assert!(
            (ego.odometer - speed_of(i) * config.dt).abs() < TOL,
            "variant {i}: odometer {} m",
            ego.odometer
        );
    }
    drop(engines);
    assert_eq!(Arc::strong_count(&network), 1);
}

/// `RoadNetworks` reads each road file once: two loads of the bundled example (its
/// `../roads/highway.xodr`) get the same network; esmini's cut-in.xosc (`../xodr/e6mini.xodr`)
/// another.
#[test]
fn road_networks_are_read_once_per_file() {
    let example = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/scenarios/cut_in_highway.xosc"
    );
    let first = Scenario::load(example.as_ref()).expect("loads");
    let second = Scenario::load(example.as_ref()).expect("loads");
    let other = Scenario::load(&crate::corpus::corpus("esmini/xosc/cut-in.xosc")).expect("loads");
    let mut networks = engine::RoadNetworks::new();
    let a = networks.get(&first).expect("reads highway.xodr");
    let b = networks.get(&second).expect("kept");
    assert!(Arc::ptr_eq(&a, &b));
    assert_eq!(networks.len(), 1);
    let c = networks.get(&other).expect("reads e6mini.xodr");
    assert!(!Arc::ptr_eq(&a, &c));
    assert_eq!(networks.len(), 2);
}
