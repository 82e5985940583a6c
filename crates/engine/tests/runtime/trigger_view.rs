//! The rule of runtime/trigger_view.rs: all triggers of a step measure the entities as the step
//! began, whatever their place in the file (OpenSCENARIO 1.3 §8.3.1: the Acts and
//! ManeuverGroups of a Story run concurrently; document order has no meaning), and a Story's
//! TeleportAction shows its target in the step's frame.

use crate::runtime_support;

use engine::output::EventRecord;
use runtime_support::run;

/// Car1: s = 100 at t = 0, 10 m/s on lane −1 of the straight road (x = s). Frame of 1.05 s:
/// s = 100 + 10 · 1.05 = 110.5. At the step of 1.05 s the Event "teleport" fires
/// (SimulationTime > 1) and puts Car1 at s = 20; "near before" and "near after" need t > 1 and
/// |s − 110| < 1, which the step-start state (110.5) satisfies: both start at 1.05 s. Had the
/// later one seen the teleport, it would never start (Car1 stays far from s = 110 until 2 s).
#[test]
fn triggers_of_one_step_see_the_step_start_entities_in_any_document_order() {
    let (_, frames, events) = run("trigger_view.xosc");
    let start = |name: &str| {
        events.iter().find_map(|e| match e {
            // An Event's first record is its startTransition.
            EventRecord::Transition(t) if t.name == name => Some(t.time),
            _ => None,
        })
    };
    for name in ["teleport", "near before", "near after"] {
        let t = start(name).unwrap_or_else(|| panic!("{name} never started"));
        assert!((t - 1.05).abs() < 1e-9, "{name} started at {t}");
    }
    // The frame of 1.05 s (written by the step before) has Car1 at 110.5 m; the teleport's
    // step ends with Car1 at its target, s = 20 exactly (x = s on this road), and the motion
    // goes on from there: 20 + 10 · 0.05 = 20.5 m at 1.15 s.
    assert!((frames.at("Car1", 1.05).x - 110.5).abs() < 1e-9);
    assert!((frames.at("Car1", 1.1).x - 20.0).abs() < 1e-9);
    assert!((frames.at("Car1", 1.15).x - 20.5).abs() < 1e-9);
}
