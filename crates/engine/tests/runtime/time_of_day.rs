//! TimeOfDayCondition reads the time of day that an EnvironmentAction set (OpenSCENARIO 1.3
//! XSD `TimeOfDayCondition`, `TimeOfDay`: with `animation` true the time runs on with the
//! simulation, with `animation` false it stands still).

use crate::runtime_support;

use engine::output::EventRecord;
use engine::storyboard::Transition;
use runtime_support::run;

/// The time of the first start transition of the storyboard element `name`, if any.
fn start_time(events: &[EventRecord], name: &str) -> Option<f64> {
    events.iter().find_map(|e| match e {
        EventRecord::Transition(t) if t.name == name && t.transition == Transition::Start => {
            Some(t.time)
        }
        _ => None,
    })
}

/// Init sets 06:00:00 with animation, so at simulation time t the clock reads 06:00:00 + t.
/// "Dawn" waits for a time after 06:00:09.975: false at t = 9.95 (06:00:09.95), true at the
/// step t = 10.0 (06:00:10). At t = 12.0 "Frozen" sets 12:00:00 without animation: "Noon"
/// (after 12:00:00.5) can then never hold, and before it the clock read at most 06:00:15.
#[test]
fn time_of_day_condition_follows_the_environment_clock() {
    let (_engine, _frames, events) = run("time_of_day.xosc");
    let dawn = start_time(&events, "Dawn").expect("Dawn starts");
    assert!((dawn - 10.0).abs() < 1e-9, "Dawn started at {dawn}");
    let frozen = start_time(&events, "Frozen").expect("Frozen starts");
    assert!((frozen - 12.0).abs() < 1e-9, "Frozen started at {frozen}");
    assert_eq!(
        start_time(&events, "Noon"),
        None,
        "a frozen clock never passes noon"
    );
    let noon = start_time(&events, "NoonOrLater").expect("NoonOrLater starts");
    // The time of day is a value of the scenario, not a measurement of an entity: an
    // EnvironmentAction sets it when its Event starts, and conditions evaluated after it in the
    // same step read the new value (runtime/trigger_view.rs: only the entities are read as the
    // step began). "NoonOrLater" comes after "Frozen" in document order, so it starts in the
    // same step.
    assert!((noon - 12.0).abs() < 1e-9, "NoonOrLater started at {noon}");
}
