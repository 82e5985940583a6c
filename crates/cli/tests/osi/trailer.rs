//! `oscsim run --osi`: `vehicle_classification.has_trailer` and `trailer_id` (OSI 3.8
//! osi_object.proto `MovingObject.VehicleClassification`) follow the scenario's trailer
//! connections (OpenSCENARIO 1.3 §7.2.2.6 "Trailer modeling").
//!
//! The expected connections come from the scenario texts, not from the engine:
//! - `generated/xosc/trailer_example0.xosc`: `Ego` tows nothing until the event `connect`
//!   (ConnectTrailerAction trailerRef="trailer"), tows `trailer` from then on, and nothing
//!   again from the event `disconnect` (DisconnectTrailerAction); the two times are read
//!   from the run's own event log (`--events`), the storyboard's record of when each
//!   action ran.
//! - `esmini/xosc/trailers.xosc`: fixed chains from the start. Explicit `TrailerRef`
//!   parameters: Semi_tractor → Semi_trailer → Truck_trailer1 → Truck_trailer2. Catalog
//!   vehicles with inline trailers (esmini's names, as in
//!   `reference/esmini/trailers.csv`): Ego → Ego+, Semi_truck → Semi_truck+,
//!   Semi_truck_with_extra_trailer → …+ → …++.

use crate::osi_common;

use std::collections::BTreeMap;

use osi::osi3::{GroundTruth, MovingObject};
use osi_common::{corpus, traced_run as run};

/// `(has_trailer, trailer_id)` of every vehicle of one frame, by entity name, and the OSI
/// id of every moving object by entity name.
struct Classified {
    trailer: BTreeMap<String, (Option<bool>, Option<u64>)>,
    ids: BTreeMap<String, u64>,
}

fn name(o: &MovingObject) -> String {
    // Every object the adapter writes carries [kind, entity name] (osi::sink module doc).
    o.source_reference[0].identifier[1].clone()
}

fn classify(gt: &GroundTruth) -> Classified {
    let mut trailer = BTreeMap::new();
    let mut ids = BTreeMap::new();
    for o in &gt.moving_object {
        let id =
            o.id.and_then(|i| i.value)
                .expect("every moving object has an id");
        ids.insert(name(o), id);
        if let Some(v) = &o.vehicle_classification {
            trailer.insert(name(o), (v.has_trailer, v.trailer_id.and_then(|i| i.value)));
        }
    }
    Classified { trailer, ids }
}

/// Time of the `start` transition of the action named `action` in the JSON-lines log.
fn action_start(events: &str, action: &str) -> f64 {
    let element = format!("\"element\":\"{action}\"");
    let line = events
        .lines()
        .find(|l| l.contains(&element) && l.contains("\"transition\":\"start\""))
        .unwrap_or_else(|| panic!("the action {action} starts in the run"));
    let rest = &line[line.find("\"time\":").expect("every record has a time") + 7..];
    rest[..rest.find(',').expect("time is not the last field")]
        .parse()
        .expect("the time is a number")
}

fn seconds(gt: &GroundTruth) -> f64 {
    let ts = gt.timestamp.expect("every frame has a timestamp");
    ts.seconds.unwrap_or(0) as f64 + f64::from(ts.nanos.unwrap_or(0)) * 1e-9
}

#[test]
fn connect_and_disconnect_set_and_clear_the_tow_vehicles_trailer_id() {
    let scenario = corpus("generated/xosc/trailer_example0.xosc");
    // 10 s covers both events (they run near 5.5 s and 8 s with esmini-like timing).
    let (trace, events) = run("osi_trailer_connect", &scenario, 10.0);
    let connect = action_start(&events, "connect trailer");
    let disconnect = action_start(&events, "disconnect trailer");
    assert!(
        0.0 < connect && connect < disconnect && disconnect < 10.0,
        "connect at {connect} s, disconnect at {disconnect} s"
    );
    // A transition logged at t belongs to the step [t, t + dt], whose frame is stamped
    // t + dt (Engine::step, stages 1 and 5): the frame stamped t was written before the
    // action ran, the next one after. Half a step (dt = 0.05 s) of slack on the comparison.
    let half_step = 0.025;
    let mut seen = [0usize; 3];
    for gt in &trace {
        let t = seconds(gt);
        let c = classify(gt);
        let trailer_id = c.ids["trailer"];
        let phase = if t < connect + half_step {
            0
        } else if t < disconnect + half_step {
            1
        } else {
            2
        };
        seen[phase] += 1;
        let expected = if phase == 1 {
            (Some(true), Some(trailer_id))
        } else {
            (Some(false), None)
        };
        assert_eq!(c.trailer["Ego"], expected, "Ego at t = {t:.3} s");
        assert_eq!(
            c.trailer["trailer"],
            (Some(false), None),
            "the trailer tows nothing (t = {t:.3} s)"
        );
    }
    // Each phase has frames: the test checks all three states.
    assert!(seen.iter().all(|n| *n > 0), "frames per phase {seen:?}");
}

#[test]
fn trailer_chains_name_the_next_moving_object_in_every_frame() {
    let scenario = corpus("esmini/xosc/trailers.xosc");
    let (trace, _) = run("osi_trailer_chains", &scenario, 2.0);
    let tows = [
        ("Ego", Some("Ego+")),
        ("Ego+", None),
        ("Semi_truck", Some("Semi_truck+")),
        ("Semi_truck+", None),
        (
            "Semi_truck_with_extra_trailer",
            Some("Semi_truck_with_extra_trailer+"),
        ),
        (
            "Semi_truck_with_extra_trailer+",
            Some("Semi_truck_with_extra_trailer++"),
        ),
        ("Semi_truck_with_extra_trailer++", None),
        ("Truck_trailer2", None),
        ("Truck_trailer1", Some("Truck_trailer2")),
        ("Semi_trailer", Some("Truck_trailer1")),
        ("Semi_tractor", Some("Semi_trailer")),
    ];
    // 2 s at dt 0.05 s: frames 0.00 … 2.00.
    assert_eq!(trace.len(), 41);
    for gt in &trace {
        let t = seconds(gt);
        let c = classify(gt);
        assert_eq!(c.trailer.len(), tows.len(), "vehicles at t = {t:.3} s");
        for (tow, trailer) in tows {
            let expected = match trailer {
                Some(name) => (Some(true), Some(c.ids[name])),
                None => (Some(false), None),
            };
            assert_eq!(c.trailer[tow], expected, "{tow} at t = {t:.3} s");
        }
    }
}
