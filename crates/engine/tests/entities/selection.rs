//! Entity selections at runtime (OpenSCENARIO 1.3 §7.2.2.2 "Entity selections", §7.2.2.5
//! "Generalization of entities"): ManeuverGroup actors, nested selections, the multiplicity
//! restriction and cycles.

use crate::runtime_support;

use std::path::PathBuf;

use engine::{Engine, EngineConfig, ErrorKind, EventRecord};
use runtime_support::Recorder;

fn file(name: &str) -> PathBuf {
    crate::corpus::fixture("entities").join(name)
}

/// Loads test file `name`.
fn load(name: &str) -> Engine {
    Engine::load(&file(name), &[], EngineConfig::default())
        .unwrap_or_else(|e| panic!("{name} does not load: {e}"))
}

/// §7.2.2.2: "all private actions within the maneuver group are applied individually, to each
/// ScenarioObject instance in the entity selection". Actor `Cars` = Car1 + nested `Rest`
/// (Car2, Car3). All drive 10 m/s from s = 20, 60 (lane −1) and 100 (lane 1, towards −s);
/// the step SpeedAction to 20 m/s starts at the first step with t > 1, t = 1.05 s. At t = 2 s
/// each has covered 10 · 1.05 + 20 · 0.95 = 29.5 m: Car1 x = 49.5, Car2 x = 89.5, Car3
/// x = 100 − 29.5 = 70.5. Car4, not a member, keeps 10 m/s: x = 140 + 20 = 160.
#[test]
fn maneuver_group_actor_selection_of_three_vehicles_changes_all_three() {
    const TOLERANCE: f64 = 1e-9;
    let mut engine = load("selection_actors.xosc");
    let mut frames = Recorder::default();
    engine.run(&mut frames, &mut Vec::new()).expect("runs");
    for (name, x, speed) in [
        ("Car1", 49.5, 20.0),
        ("Car2", 89.5, 20.0),
        ("Car3", 70.5, 20.0),
        ("Car4", 160.0, 10.0),
    ] {
        let row = frames.at(name, 2.0);
        assert!((row.x - x).abs() < TOLERANCE, "{row:?}, want x = {x}");
        assert!((row.speed - speed).abs() < TOLERANCE, "{row:?}");
    }
}

/// §7.2.2.5: "the interpretation of the distance to an EntitySelection is ambiguous … A
/// reference to an Entity should be restricted to an instance of a ScenarioObject". A
/// RelativeDistanceCondition to the selection `Pair` is refused when the engine is built, at
/// the condition's position.
#[test]
fn distance_to_a_selection_is_rejected_with_its_position() {
    let err = Engine::load(
        &file("selection_distance.xosc"),
        &[],
        EngineConfig::default(),
    )
    .expect_err("a distance to a selection must be refused");
    assert!(matches!(err.kind(), ErrorKind::Invalid { .. }), "{err}");
    let pos = err.pos().expect("the condition's position");
    assert_eq!((pos.line, pos.col), (69, 51));
    let text = err.to_string();
    assert!(
        text.starts_with(
            "expected a ScenarioObject as the reference of a RelativeDistanceCondition (§7.2.2.5), found EntitySelection 'Pair' at "
        ) && text.ends_with("selection_distance.xosc:69:51"),
        "{text}"
    );
}

/// §7.2.2.2: A includes B, which includes A. Refused at load, naming the cycle and the
/// declaration that closes it (line 18, column 9 of the file).
#[test]
fn cyclic_selection_is_rejected_at_load() {
    let err = Engine::load(&file("selection_cycle.xosc"), &[], EngineConfig::default())
        .expect_err("a selection cycle must be refused");
    assert!(matches!(err.kind(), ErrorKind::Scenario(_)), "{err}");
    let text = err.to_string();
    assert!(
        text.starts_with("entity selection cycle: A → B → A at ")
            && text.ends_with("selection_cycle.xosc:18:9"),
        "{text}"
    );
}

/// §7.2.2.3: spawned objects may be actors through ByType. The ManeuverGroup's actor is the
/// ByType vehicle selection; its step SpeedAction to 5 m/s starts at 3.05 s and reaches every
/// vehicle present then: Ego and the source's vehicles of 1, 2 and 3 s (20 m/s before). A
/// vehicle spawned later (the fourth, once the slowed third has cleared the 10 m spawn gap)
/// is not an actor and keeps the source's 20 m/s.
#[test]
fn by_type_actor_selection_reaches_spawned_vehicles_present_at_the_start() {
    let mut engine = load("selection_spawned_actors.xosc");
    let mut frames = Recorder::default();
    engine.run(&mut frames, &mut Vec::new()).expect("runs");
    for name in ["Ego", "src.entity_1", "src.entity_2", "src.entity_3"] {
        let before = frames.at(name, 3.0);
        let after = frames.at(name, 4.0);
        let was = if name == "Ego" { 0.0 } else { 20.0 };
        assert!((before.speed - was).abs() < 1e-12, "{before:?}");
        assert!((after.speed - 5.0).abs() < 1e-12, "{after:?}");
    }
    let late: Vec<_> = frames
        .0
        .iter()
        .filter(|r| r.name == "src.entity_4")
        .collect();
    assert!(
        late.first().is_some_and(|r| r.time > 3.05),
        "{:?}",
        late.first()
    );
    assert!(late.iter().all(|r| (r.speed - 20.0).abs() < 1e-12));
}

/// §7.2.2.2: a selection as TriggeringEntities aggregates its members with `any` / `all`.
/// Cars = Car1 + Car2 at 10 m/s; "speed > 15 m/s" holds for Car1 from its step to 20 m/s at
/// 1.05 s, for Car2 from 2.05 s. The step speed actions start in those steps; the triggers of
/// a step see the world as the step began (runtime/trigger_view.rs), so the speeds are seen
/// one step later: `any` starts at 1.10 s and `all` only at 2.10 s.
#[test]
fn any_and_all_over_a_triggering_selection() {
    let mut engine = load("selection_triggering.xosc");
    let mut events = Vec::new();
    engine.run(&mut (), &mut events).expect("runs");
    let start = |name: &str| {
        events.iter().find_map(|e| match e {
            EventRecord::Transition(t) if t.name == name => Some(t.time),
            _ => None,
        })
    };
    let any = start("any fast").expect("any fired");
    let all = start("all fast").expect("all fired");
    assert!(
        (any - 1.1).abs() < 1e-9 && (all - 2.1).abs() < 1e-9,
        "{any} {all}"
    );
}
