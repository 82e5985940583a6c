//! ExternalObjectReference (OpenSCENARIO 1.3 §7.2.2 "Entities"): entities standing for
//! objects of the OpenDRIVE file, reported as stationary objects.

use std::path::PathBuf;

use engine::runtime::EntityKind;
use engine::{Engine, EngineConfig, Frame, FrameSink};

fn file(name: &str) -> PathBuf {
    crate::corpus::fixture("entities").join(name)
}

/// The message of the build error of test file `name`.
fn refused(name: &str) -> String {
    Engine::load(&file(name), &[], EngineConfig::default())
        .expect_err("must be refused")
        .to_string()
}

/// (time, name, kind, x, y, z, h, height, speed) of every object in every frame.
#[derive(Default)]
struct Objects(Vec<(f64, String, EntityKind, [f64; 6])>);

impl FrameSink for Objects {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        for o in frame.objects() {
            let p = o.pose;
            let values = [p.x, p.y, p.z, p.h, o.bounding_box.height(), o.speed];
            self.0.push((frame.time, o.name.to_owned(), o.kind, values));
        }
        Ok(())
    }
}

/// simple_road_with_objects0.xodr: road 0 runs from (0, 0) along +x, so an object at (s, t)
/// lies at (s, t). emergencyCallBox: s = 30, t = −6, hdg 0, no size. The first guardRail
/// (id 54): s = 0, t = 6.8, zOffset 0.4, hdg π, height 0.3. Id 59 (jerseyBarrier): s = 0,
/// t = 0, height 0.75. All three stand still at those poses in every frame of the 2 s run.
#[test]
fn external_objects_stand_at_their_road_network_objects() {
    const TOLERANCE: f64 = 1e-9;
    let mut engine =
        Engine::load(&file("external_objects.xosc"), &[], EngineConfig::default()).expect("loads");
    let mut objects = Objects::default();
    engine.run(&mut objects, &mut Vec::new()).expect("runs");
    let pi = std::f64::consts::PI;
    let expected = [
        ("CallBox", [30.0, -6.0, 0.0, 0.0, 0.0, 0.0]),
        ("Rail", [0.0, 6.8, 0.4, pi, 0.3, 0.0]),
        ("Barrier", [0.0, 0.0, 0.0, 0.0, 0.75, 0.0]),
    ];
    let frames = objects.0.iter().filter(|o| o.1 == "CallBox").count();
    assert_eq!(frames, 42, "frames 0 … 2.05 s");
    for (name, want) in expected {
        for (t, n, kind, got) in objects.0.iter().filter(|o| o.1 == name) {
            assert_eq!(*kind, EntityKind::External, "{n}");
            for (g, w) in got.iter().zip(want) {
                assert!(
                    (g - w).abs() < TOLERANCE,
                    "{n} at {t}: {got:?}, want {want:?}"
                );
            }
        }
    }
}

/// A reference to an object the road network does not have is refused at build, naming the
/// ScenarioObject's place.
#[test]
fn unknown_external_object_is_rejected() {
    let text = refused("external_unknown.xosc");
    assert!(
        text.starts_with("expected an object of the road network with this name, found ExternalObjectReference 'noSuchObject' at ")
            && text.ends_with("external_unknown.xosc:7:9"),
        "{text}"
    );
}

/// §7.2.2.5: actions that make no sense for an entity type are restricted. An
/// ExternalObjectReference is part of the road network: a SpeedAction on it is refused at
/// build, at the action's place.
#[test]
fn speed_action_on_an_external_object_is_rejected() {
    let text = refused("external_speed.xosc");
    assert!(
        text.starts_with("expected a Vehicle, Pedestrian or MiscObject as the actor of a LongitudinalAction (§7.2.2.5), found ExternalObjectReference 'CallBox' at ")
            && text.ends_with("external_speed.xosc:14:17"),
        "{text}"
    );
}
