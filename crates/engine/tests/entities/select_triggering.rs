//! `Actors/@selectTriggeringEntities` (OpenSCENARIO 1.3 §7.3.1 "ManeuverGroups and Actors"):
//! "When the selectTriggeringEntities property is true, entities become actors if … the
//! Conditions using [their] states evaluate to true [and] are contained in ConditionGroups that
//! evaluate to true", the condition groups of the parent Act; with EntityRefs "the resulting
//! actors are the union".

use crate::runtime_support;

use std::path::PathBuf;

use engine::{Engine, EngineConfig};
use runtime_support::Recorder;

fn file(name: &str) -> PathBuf {
    crate::corpus::fixture("entities").join(name)
}

/// select_triggering.xosc: Car1, Car2, Car3 start at 10, 20, 10 m/s. Act "pick" fires in the
/// first step through group 1 ("any car > 15 m/s": only Car2 holds); group 2 ("Car3 < 15 m/s"
/// and "time > 100 s") is false although Car3 holds its first condition, so Car3 is not
/// selected. The actors of "to 25" are Car1 (EntityRef) ∪ {Car2}: both at 25 m/s from the first
/// frame, Car3 stays at 10 m/s. Act "both" ("Car1 and Car2 > 20 m/s", rule all, and "time ≥
/// 0.5 s") fires at 0.5 s with both cars holding; "to 5" has no EntityRef, so exactly Car1 and
/// Car2 step to 5 m/s, shown from the frame after that step (0.55 s). Act "delayed" ("some
/// car > 22 m/s", rising edge, delay 0.7 s): the triggers first see 25 m/s in the step at
/// 0.05 s (a step's triggers see the world as the step began), so it fires at 0.75 s, when all
/// cars are slower; a delay shifts the condition's value (storyboard::delay), so the entities
/// are those of 0.05 s: Car1 and Car2 step to 12 m/s (frame 0.80 s). Car3 is never touched.
#[test]
fn triggering_entities_of_the_firing_groups_join_the_actors() {
    const TOLERANCE: f64 = 1e-9;
    let mut engine = Engine::load(
        &file("select_triggering.xosc"),
        &[],
        EngineConfig::default(),
    )
    .expect("loads");
    let mut frames = Recorder::default();
    engine
        .run(&mut frames, &mut Vec::new())
        .expect("runs to its stop trigger");
    let speed = |name: &str, t: f64| frames.at(name, t).speed;
    for (t, car1, car2, car3) in [
        (0.0, 25.0, 25.0, 10.0),
        (0.5, 25.0, 25.0, 10.0),
        (0.55, 5.0, 5.0, 10.0),
        (0.75, 5.0, 5.0, 10.0),
        (0.8, 12.0, 12.0, 10.0),
        (1.0, 12.0, 12.0, 10.0),
    ] {
        assert!((speed("Car1", t) - car1).abs() < TOLERANCE, "Car1 at {t}");
        assert!((speed("Car2", t) - car2).abs() < TOLERANCE, "Car2 at {t}");
        assert!((speed("Car3", t) - car3).abs() < TOLERANCE, "Car3 at {t}");
    }
}
