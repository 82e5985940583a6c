//! Names of Init actions in the event log: `Init ACTIONTYPE` for a global one, with the XSD
//! element name of the action (issue 33: the engine had its own table of the names, which
//! called every TrafficSignalAction and SetMonitorAction "GlobalAction").

use crate::corpus::corpus;

use engine::output::EventRecord;
use engine::storyboard::Transition;
use engine::{Engine, EngineConfig};

/// esmini's traffic_lights.xosc sets three signals in its Init, each as
/// `<GlobalAction><InfrastructureAction><TrafficSignalAction>`: three starts named
/// "Init TrafficSignalAction" at t = 0, and none named "Init GlobalAction".
#[test]
fn init_traffic_signal_actions_are_named_by_their_element() {
    let path = corpus("esmini/xosc/traffic_lights.xosc");
    let config = EngineConfig {
        duration: Some(0.1),
        ..EngineConfig::default()
    };
    let mut engine = Engine::load(&path, &[], config).expect("loads");
    let mut events: Vec<EventRecord> = Vec::new();
    engine.run(&mut (), &mut events).expect("runs");
    let starts = |name: &str| {
        events
            .iter()
            .filter(|e| {
                matches!(e, EventRecord::Transition(t)
                    if t.name == name && t.transition == Transition::Start && t.time.abs() < 1e-9)
            })
            .count()
    };
    assert_eq!(starts("Init TrafficSignalAction"), 3);
    assert_eq!(starts("Init GlobalAction"), 0);
}
