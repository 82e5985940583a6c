//! Every scenario of the shared corpus runs without a panic; the two broken ones fail with an
//! error naming the missing file (corpus README). Also: a bad input in a test scenario gives
//! an error with file:line:col.

use crate::runtime_support;

use engine::{Engine, EngineConfig, ErrorKind};
use runtime_support::{corpus, file, Recorder};

/// Simulated seconds per scenario: long enough to pass the interesting parts of most
/// scenarios, short enough for a debug-build test.
const CAP: f64 = 30.0;

fn scenarios(dir: &str) -> Vec<std::path::PathBuf> {
    let mut files: Vec<_> = std::fs::read_dir(corpus(dir))
        .expect("corpus folder")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "xosc"))
        .collect();
    files.sort();
    files
}

#[test]
fn every_corpus_scenario_runs_or_fails_cleanly() {
    let config = EngineConfig {
        max_time: CAP,
        ..EngineConfig::default()
    };
    let mut ran = 0;
    for path in scenarios("esmini/xosc")
        .into_iter()
        .chain(scenarios("generated/xosc"))
    {
        let name = path
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or_default()
            .to_owned();
        match Engine::load(&path, &[], config) {
            Ok(mut engine) => {
                let mut frames = Recorder::default();
                let mut events = Vec::new();
                if let Err(e) = engine.run(&mut frames, &mut events) {
                    panic!("{name}: run failed: {e}");
                }
                assert!(engine.time() <= CAP + 1e-9, "{name} respects the cap");
                ran += 1;
            }
            Err(e) if matches!(e.kind(), ErrorKind::Scenario(_)) => {
                let message = e.to_string();
                match name.as_str() {
                    "auto_light.xosc" => assert!(message.contains("Vehicles"), "{message}"),
                    "car_walk.xosc" => assert!(message.contains("straight_500m.xodr"), "{message}"),
                    _ => panic!("{name} does not load: {message}"),
                }
            }
            Err(e) => panic!("{name}: engine not built: {e}"),
        }
    }
    // 57 esmini + 19 generated scenarios, all but the two broken ones run.
    assert_eq!(ran, 57 + 19 - 2);
}

/// bad_lane_id.xosc: laneId="minus one" in a TeleportAction at line 55, column 31: a
/// LanePosition that depends on no entity, refused at load (`position::check`, issue 16
/// class 2) rather than when the teleport starts.
#[test]
fn bad_lane_id_names_the_position() {
    let message = match Engine::load(&file("bad_lane_id.xosc"), &[], EngineConfig::default()) {
        Ok(_) => panic!("bad_lane_id.xosc loads"),
        Err(e) => e.to_string(),
    };
    assert!(message.contains("bad_lane_id.xosc:55:"), "{message}");
    assert!(message.contains("minus one"), "{message}");
}
