//! AddEntityAction and DeleteEntityAction (OpenSCENARIO 1.3 XSD `EntityAction`): an entity
//! leaves the scenario and comes back; conditions on it while it is away.

use crate::runtime_support;

use std::path::PathBuf;

use engine::output::EventRecord;
use engine::{Engine, EngineConfig};
use runtime_support::Recorder;

fn file(name: &str) -> PathBuf {
    crate::corpus::fixture("entities").join(name)
}

/// Car1 drives 10 m/s from s = 20. DeleteEntityAction starts at the first step with t > 2
/// (2.05 s): the frame of 2.05 s was written the step before, so Car1 is in it (x = 20 + 20.5
/// = 40.5) and in no frame after until AddEntityAction at 4.05 s puts it at s = 200 at rest
/// (frames from 4.10 s on). While Car1 is away, the condition "Car1 within 10 m of Car2"
/// cannot be evaluated: it reads false (logged once as an error naming the condition's
/// place); after the re-entry, 5 m from the parked Car2, it holds from the next step (4.10 s):
/// the triggers of the 4.05 s step all see the world as that step began, with Car1 still away
/// (runtime/trigger_view.rs; the order of the two Events in the file must not matter).
#[test]
fn deleted_entity_leaves_and_reenters_at_rest() {
    let mut engine =
        Engine::load(&file("add_delete.xosc"), &[], EngineConfig::default()).expect("loads");
    let mut frames = Recorder::default();
    let mut events = Vec::new();
    engine.run(&mut frames, &mut events).expect("runs");
    let car1 = |t: f64| {
        frames
            .0
            .iter()
            .find(|r| r.name == "Car1" && (r.time - t).abs() < 1e-6)
    };
    let last = car1(2.05).expect("Car1 still in the frame of 2.05 s");
    assert!((last.x - 40.5).abs() < 1e-9, "{last:?}");
    for step in 42..=81 {
        let t = step as f64 * 0.05;
        assert!(car1(t).is_none(), "Car1 in the frame of {t} s");
    }
    let back = car1(4.1).expect("Car1 back at 4.10 s");
    assert!(
        (back.x - 200.0).abs() < 1e-9 && back.speed == 0.0,
        "{back:?}"
    );
    let later = car1(6.0).expect("Car1 stays");
    assert!((later.x - 200.0).abs() < 1e-9, "{later:?}");
    let errors: Vec<_> = events
        .iter()
        .filter_map(|e| match e {
            EventRecord::Error {
                element, message, ..
            } => Some((element, message)),
            _ => None,
        })
        .collect();
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert_eq!(errors[0].0, "car1 near car2");
    assert!(
        errors[0].1.contains("add_delete.xosc:59:51"),
        "{}",
        errors[0].1
    );
    let near = events.iter().find_map(|e| match e {
        EventRecord::Transition(t) if t.name == "car1 near" => Some(t.time),
        _ => None,
    });
    assert!(near.is_some_and(|t| (t - 4.1).abs() < 1e-9), "{near:?}");
    let changes: Vec<(f64, &str)> = events
        .iter()
        .filter_map(|e| match e {
            EventRecord::Entity {
                time,
                entity,
                change,
                ..
            } if entity == "Car1" => Some((*time, change.as_str())),
            _ => None,
        })
        .collect();
    assert_eq!(changes.len(), 2, "{changes:?}");
    assert!((changes[0].0 - 2.05).abs() < 1e-9 && changes[0].1 == "deleted");
    assert!((changes[1].0 - 4.05).abs() < 1e-9 && changes[1].1 == "added");
}

/// The names a condition holds are resolved when the engine is built (engine
/// condition/refs.rs): one the scenario does not declare is refused then, at the condition's
/// file, line and column, naming the XSD element it stands in (OpenSCENARIO 1.3 §7.6.3
/// ByEntityCondition, an `entityRef` naming a ScenarioObject or an EntitySelection). The XML
/// reader refuses such a name already, so the model of add_delete.xosc is changed after
/// loading: the condition "car1 near car2" (59:51) with its RelativeDistanceCondition's
/// entityRef, then its triggering entity, renamed `ghost`.
#[test]
fn a_condition_naming_an_undeclared_entity_is_refused_when_the_engine_is_built() {
    let loaded = scenario::Scenario::load(&file("add_delete.xosc")).expect("loads");
    let build = |rename: &dyn Fn(&mut scenario::Condition)| {
        let mut s = loaded.clone();
        // The file's one Story, Act, ManeuverGroup and Maneuver; its third Event, "car1 near".
        let event = &mut s.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[0].events[2];
        assert_eq!(event.name, "car1 near");
        let trigger = event.start_trigger.as_mut().expect("its start trigger");
        let condition = &mut trigger.condition_groups[0].conditions[0];
        assert_eq!(condition.name, "car1 near car2");
        rename(condition);
        let network = engine::load::road_network(&s).expect("road network");
        match Engine::new(&s, network, EngineConfig::default()) {
            Ok(_) => panic!("built with a condition naming 'ghost'"),
            Err(e) => e,
        }
    };
    let reference = build(&|c| {
        if let scenario::ConditionKind::ByEntity {
            entity_condition: scenario::EntityCondition::RelativeDistance { entity_ref, .. },
            ..
        } = &mut c.kind
        {
            *entity_ref = "ghost".into();
        }
    });
    let triggering = build(&|c| {
        if let scenario::ConditionKind::ByEntity {
            triggering_entities,
            ..
        } = &mut c.kind
        {
            triggering_entities.entity_refs = vec!["ghost".into()];
        }
    });
    for (e, element) in [
        (reference, "RelativeDistanceCondition@entityRef"),
        (triggering, "TriggeringEntities/EntityRef@entityRef"),
    ] {
        let pos = e.pos().expect("the condition's position");
        assert_eq!((pos.line, pos.col), (59, 51), "{e}");
        assert!(pos.file.ends_with("add_delete.xosc"), "{e}");
        let text = e.to_string();
        let want = format!(
            "expected a declared entity for {element} of condition 'car1 near car2', found 'ghost' at "
        );
        assert!(
            text.starts_with(&want) && text.ends_with("add_delete.xosc:59:51"),
            "{text}"
        );
    }
}
