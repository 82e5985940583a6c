//! The §8.7 actors of a DSL scenario in every output of `oscsim run` (issue 27): the persons
//! and the animal of `dsl_runtime`'s `actors/walkers.osc` (on its `sidewalk.xodr`) are OSI
//! MovingObjects of type pedestrian and animal (OSI 3.x `MovingObject.Type`, seed 004), rows of
//! the CSV, and pedestrian entities of category pedestrian / animal in the run manifest the
//! replay reads; the stationary object of `actors/stop_behind_object.osc` is an OSI
//! StationaryObject (barrier) where its `location(pose)` puts it, in every frame.
//!
//! Hand values: alice stands on the sidewalk's centre (t = −8 m) at s = 20 m with her box
//! centred over her reference point, so her OSI position at 0 s is (20, −8, z); the barrier's
//! pose is (150, −8.75) with its box centred on it.

use std::path::{Path, PathBuf};

use osi::osi3::moving_object::Type as MovingType;
use osi::osi3::stationary_object::classification::Type as StationaryType;
use osi::trace::read_osi;

use crate::osi_common::{oscsim_for, out_dir, xyz};

/// Exact decimals through f64 arithmetic.
const TOLERANCE: f64 = 1e-9;

fn runtime_file(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../dsl_runtime/tests")
        .join(rel)
}

fn s(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

#[test]
fn persons_and_animals_are_pedestrians_and_animals_in_every_output() {
    let dir = out_dir("dsl_actors_walkers");
    let (trace, csv, events) = (dir.join("t.osi"), dir.join("t.csv"), dir.join("t.jsonl"));
    let scenario = runtime_file("scenarios/actors/walkers.osc");
    let road = runtime_file("roads/sidewalk.xodr");
    // Bounded past the scenario's own end (8 s), which ends the run.
    let out = oscsim_for(
        &scenario,
        9.0,
        &[
            "--road",
            s(&road),
            "--osi",
            s(&trace),
            "--csv",
            s(&csv),
            "--events",
            s(&events),
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let gt = read_osi(&trace).expect("the trace reads back");
    let first = &gt[0];
    let kind = |name: &str| {
        first
            .moving_object
            .iter()
            .find(|o| o.source_reference[0].identifier[1] == name)
            .unwrap_or_else(|| panic!("{name} in the frame"))
    };
    assert_eq!(kind("alice").r#type, Some(MovingType::Pedestrian as i32));
    assert_eq!(kind("bob").r#type, Some(MovingType::Pedestrian as i32));
    assert_eq!(kind("deer").r#type, Some(MovingType::Animal as i32));
    let p = xyz(kind("alice").base.as_ref().expect("base").position);
    assert!(
        (p[0] - 20.0).abs() < TOLERANCE && (p[1] + 8.0).abs() < TOLERANCE,
        "alice at {p:?}"
    );
    // The CSV: one row per actor per frame, alice on the sidewalk's centre.
    let text = std::fs::read_to_string(&csv).expect("the CSV");
    let row = text
        .lines()
        .find(|l| l.starts_with("0.000,") && l.contains(",alice,"))
        .expect("alice's first row");
    let y: f64 = row
        .split(',')
        .nth(4)
        .and_then(|v| v.parse().ok())
        .expect("y");
    assert!((y + 8.0).abs() < TOLERANCE, "{row}");
    // The event log: the phase runs 0 to 8 s.
    let log = std::fs::read_to_string(&events).expect("the event log");
    assert!(
        log.contains(
            r#"{"time":8.000,"element":"do","kind":"act","from":"runningState","transition":"stop""#
        ),
        "{log}"
    );
    // The run manifest the replay reads: kinds and categories.
    let manifest: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join("t.run.json")).expect("the run manifest"),
    )
    .expect("JSON");
    let entity = |name: &str| {
        manifest["entities"]
            .as_array()
            .expect("entities")
            .iter()
            .find(|e| e["name"] == name)
            .unwrap_or_else(|| panic!("{name} in the manifest"))
            .clone()
    };
    assert_eq!(entity("alice")["kind"], "pedestrian");
    assert_eq!(entity("alice")["category"], "pedestrian");
    assert_eq!(entity("deer")["kind"], "pedestrian");
    assert_eq!(entity("deer")["category"], "animal");
}

#[test]
fn a_stationary_object_is_an_osi_stationary_object_where_it_is_located() {
    let dir = out_dir("dsl_actors_barrier");
    let trace = dir.join("t.osi");
    let scenario = runtime_file("scenarios/actors/stop_behind_object.osc");
    let road = runtime_file("roads/straight.xodr");
    let out = oscsim_for(&scenario, 10.0, &["--road", s(&road), "--osi", s(&trace)]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let gt = read_osi(&trace).expect("the trace reads back");
    for frame in [&gt[0], &gt[gt.len() - 1]] {
        let barrier = frame
            .stationary_object
            .iter()
            .find(|o| o.source_reference[0].identifier[1] == "barrier")
            .expect("the barrier in the frame");
        let class = barrier.classification.as_ref().expect("classification");
        assert_eq!(class.r#type, Some(StationaryType::Barrier as i32));
        let p = xyz(barrier.base.as_ref().expect("base").position);
        assert!(
            (p[0] - 150.0).abs() < TOLERANCE && (p[1] + 8.75).abs() < TOLERANCE,
            "barrier at {p:?}"
        );
    }
}
