//! `oscsim run --osi` and VisibilityAction (OpenSCENARIO 1.3 XSD `VisibilityAction`: the actor
//! is visible in image generators `graphics`, in sensors `sensors`, for other traffic
//! participants `traffic`). The GroundTruth is what oscsim hands to sensor models, so an entity
//! invisible to sensors is not in it, while `graphics` and `traffic` leave it there; the host
//! vehicle carries the sensors and always stays (docs/osi.md "Visibility").
//!
//! `tests/files/osi_visibility.xosc`: Ego (host) hidden from sensors by "hideEgo" from 0.5 s;
//! Target hidden from sensors by "hideTarget" from 1 s, shown to sensors but hidden from image
//! generators and traffic by "showTarget" from 2 s. The times each action ran are read from the
//! run's own event log; an action started in the step at time T shapes the frames after T
//! (the frame at T shows the state before that step's actions).

use crate::osi_common;

use std::path::Path;

use osi::osi3::GroundTruth;
use osi_common::traced_run;

fn scenario() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/osi_visibility.xosc")
}

fn seconds(gt: &GroundTruth) -> f64 {
    let ts = gt.timestamp.expect("every frame has a timestamp");
    ts.seconds.unwrap_or(0) as f64 + f64::from(ts.nanos.unwrap_or(0)) * 1e-9
}

/// The OSI id of the moving object of entity `name` in `gt`, if it is there.
fn id_of(gt: &GroundTruth, name: &str) -> Option<u64> {
    gt.moving_object
        .iter()
        // Every object the adapter writes carries [kind, entity name] (osi::sink module doc).
        .find(|o| o.source_reference[0].identifier[1] == name)
        .map(|o| o.id.and_then(|i| i.value).expect("every object has an id"))
}

/// `(time, change)` of the `entity` records of `entity` in the JSON-lines event log.
fn visibility_records(events: &str, entity: &str) -> Vec<(f64, String)> {
    let field = |line: &str, key: &str| -> String {
        let start = line.find(&format!("\"{key}\":")).expect("field present") + key.len() + 3;
        let rest = &line[start..];
        let end = rest.find([',', '}']).expect("field ends");
        rest[..end].trim_matches('"').to_owned()
    };
    events
        .lines()
        .filter(|l| l.contains("\"kind\":\"entity\"") && l.contains("visibility"))
        .filter(|l| field(l, "entity") == entity)
        .map(|l| {
            let time = field(l, "time").parse().expect("a time");
            (time, field(l, "change"))
        })
        .collect()
}

#[test]
fn entity_invisible_to_sensors_leaves_the_ground_truth_and_returns_with_its_id() {
    let (trace, events) = traced_run("osi_visibility", &scenario(), 3.0);

    // The log names each change; the times are the steps the three actions ran in.
    let ego = visibility_records(&events, "Ego");
    assert_eq!(ego.len(), 1, "{ego:?}");
    assert_eq!(ego[0].1, "visibility graphics on sensors off traffic on");
    let target = visibility_records(&events, "Target");
    assert_eq!(target.len(), 2, "{target:?}");
    assert_eq!(target[0].1, "visibility graphics on sensors off traffic on");
    assert_eq!(
        target[1].1,
        "visibility graphics off sensors on traffic off"
    );
    let (hidden, shown) = (target[0].0, target[1].0);
    assert!(ego[0].0 < hidden && hidden < shown);

    let slack = 1e-6;
    let target_id = id_of(&trace[0], "Target").expect("Target is in the first frame");
    let ego_id = id_of(&trace[0], "Ego").expect("Ego is in the first frame");
    let (mut absent, mut present_after) = (0, 0);
    for gt in &trace {
        let t = seconds(gt);
        // The host stays in every frame, also while it is invisible to sensors.
        assert_eq!(id_of(gt, "Ego"), Some(ego_id), "Ego at {t}");
        assert_eq!(gt.host_vehicle_id.and_then(|i| i.value), Some(ego_id));
        let expected = if t > hidden + slack && t <= shown + slack {
            absent += 1;
            None
        } else {
            if t > shown + slack {
                present_after += 1;
            }
            Some(target_id)
        };
        assert_eq!(id_of(gt, "Target"), expected, "Target at {t}");
    }
    // 1.05 … 2.00 s without Target (20 frames at dt 0.05 s); with it again, graphics and
    // traffic off, from 2.05 to 3.00 s (20 frames).
    assert_eq!((absent, present_after), (20, 20));
}
