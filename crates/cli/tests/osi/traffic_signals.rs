//! `oscsim run --osi` and OpenDRIVE signals: traffic lights as one OSI `TrafficLight` per
//! bulb, lit by the engine's traffic signal controllers, and signs as `TrafficSign`s
//! (osi::traffic_signals, docs/osi.md "Traffic signals").
//!
//! `tests/files/osi_signals.xosc` on `osi_signals.xodr`: controller A cycles the vehicle light
//! S1 through go 8 s (`off;off;on`), attention 2 s (`off;on;off`), stop 10 s (`on;off;off`)
//! from t = 0; controller B references A with a delay of 3 s and drives the pedestrian light
//! S2: its cycle virtually starts at t = 3 s, so at t = 0 it is at 17 s of its 20 s cycle, in
//! "wait" (`on;off`, red), and "walk" (`off;on`, green) from 3 s to 11 s.
//!
//! Positions, by hand (OpenDRIVE 1.8 §9: the point (s, t) of a line from (x0, y0) with heading
//! h is (x0 + s·cos h − t·sin h, y0 + s·sin h + t·cos h); of an arc of radius R = 1/κ from the
//! origin with heading 0 it is ((R − t)·sin(s/R), R − (R − t)·cos(s/R)), heading s/R):
//! - S1, road 1 (x0 = 10, y0 = 5, cos h = 0.8, sin h = 0.6), s = 30, t = −4:
//!   x = 10 + 24 − (−4)(0.6) = 36.4, y = 5 + 18 + (−4)(0.8) = 19.8; 0.9 m high from
//!   zOffset 3.4, three bulbs of 0.3 m: centres at z = 4.15 (red), 3.85 (yellow), 3.55
//!   (green); orientation "+", so the face looks down −s: yaw = h + π − 2π
//!   = atan2(−0.6, −0.8) = −2.498091544796509.
//! - the sign "50" on road 1, s = 10, t = −5: x = 10 + 8 + 3 = 21, y = 5 + 6 − 4 = 7,
//!   z = 2 + 0.6 / 2 = 2.3.
//! - S2, road 2 (R = 100), s = 50, t = 5: x = 95·sin 0.5 = 45.545426167399, y = 100 −
//!   95·cos 0.5 = 16.629656620415 (sin 0.5 = 0.479425538604203, cos 0.5 =
//!   0.877582561890373); two bulbs of 0.3 m from zOffset 2.5: z = 2.95 (red), 2.65 (green);
//!   orientation "-" with hOffset 0.2: yaw = 0.5 + 0.2 = 0.7.

use crate::osi_common;

use std::collections::BTreeSet;
use std::path::Path;

use osi::osi3::traffic_light::classification::{Color, Icon, Mode};
use osi::osi3::traffic_sign::main_sign::classification::Type as SignType;
use osi::osi3::traffic_sign::Variability;
use osi::osi3::traffic_sign_value::Unit;
use osi::osi3::{GroundTruth, TrafficLight};
use osi_common::traced_run;

/// Position tolerance of the issue (1 mm) for the signals' world positions.
const POSITION_MM: f64 = 1e-3;
/// Angles are closed forms evaluated in f64.
const ANGLE: f64 = 1e-9;

fn scenario() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/osi_signals.xosc")
}

fn seconds(gt: &GroundTruth) -> f64 {
    let ts = gt.timestamp.expect("every frame has a timestamp");
    ts.seconds.unwrap_or(0) as f64 + f64::from(ts.nanos.unwrap_or(0)) * 1e-9
}

/// The bulbs of signal `id` in `gt`, top first (as written).
fn bulbs<'g>(gt: &'g GroundTruth, id: &str) -> Vec<&'g TrafficLight> {
    gt.traffic_light
        .iter()
        .filter(|l| l.source_reference[0].identifier == [id])
        .collect()
}

/// (colour, mode) of each bulb of signal `id` at time `t`.
fn lit(trace: &[GroundTruth], t: f64, id: &str) -> Vec<(Color, Mode)> {
    let gt = trace
        .iter()
        .find(|g| (seconds(g) - t).abs() < 1e-6)
        .unwrap_or_else(|| panic!("a frame at t = {t}"));
    bulbs(gt, id)
        .iter()
        .map(|l| {
            let c = l.classification.as_ref().expect("classified");
            (c.color(), c.mode())
        })
        .collect()
}

fn position(base: &osi::osi3::BaseStationary) -> [f64; 4] {
    let p = base.position.expect("a position");
    let o = base.orientation.expect("an orientation");
    [p.x(), p.y(), p.z(), o.yaw()]
}

fn assert_at(found: [f64; 4], expected: [f64; 4], what: &str) {
    for k in 0..3 {
        assert!(
            (found[k] - expected[k]).abs() < POSITION_MM,
            "{what}: {found:?} vs {expected:?}"
        );
    }
    assert!(
        (found[3] - expected[3]).abs() < ANGLE,
        "{what} yaw: {found:?}"
    );
}

#[test]
fn lights_stand_where_the_opendrive_signals_are_and_switch_with_the_phases() {
    let (trace, _) = traced_run("osi_traffic_signals", &scenario(), 12.0);
    let first = &trace[0];

    // Positions and icons (module doc).
    let s1 = bulbs(first, "S1");
    assert_eq!(s1.len(), 3);
    let yaw1 = f64::atan2(-0.6, -0.8);
    for (bulb, z) in s1.iter().zip([4.15, 3.85, 3.55]) {
        let base = bulb.base.as_ref().expect("a base");
        assert_at(position(base), [36.4, 19.8, z, yaw1], "S1");
        let d = base.dimension.expect("a dimension");
        assert_eq!((d.length(), d.width(), d.height()), (0.2, 0.3, 0.9 / 3.0));
        assert_eq!(bulb.classification.as_ref().unwrap().icon(), Icon::None);
    }
    let s2 = bulbs(first, "S2");
    assert_eq!(s2.len(), 2);
    let (x2, y2) = (95.0 * 0.479425538604203, 100.0 - 95.0 * 0.877582561890373);
    for (bulb, z) in s2.iter().zip([2.95, 2.65]) {
        assert_at(
            position(bulb.base.as_ref().unwrap()),
            [x2, y2, z, 0.7],
            "S2",
        );
        let icon = bulb.classification.as_ref().unwrap().icon();
        assert_eq!(icon, Icon::Pedestrian);
    }

    // Colours and modes follow the controllers (module doc): S1 green to 8 s, yellow to
    // 10 s, red to 20 s; S2 red to 3 s, then green.
    use Color::{Green, Red, Yellow};
    use Mode::{Constant as On, Off};
    let green = vec![(Red, Off), (Yellow, Off), (Green, On)];
    assert_eq!(lit(&trace, 0.0, "S1"), green);
    assert_eq!(lit(&trace, 7.95, "S1"), green);
    assert_eq!(
        lit(&trace, 8.0, "S1"),
        [(Red, Off), (Yellow, On), (Green, Off)]
    );
    assert_eq!(
        lit(&trace, 10.0, "S1"),
        [(Red, On), (Yellow, Off), (Green, Off)]
    );
    assert_eq!(lit(&trace, 0.0, "S2"), [(Red, On), (Green, Off)]);
    assert_eq!(lit(&trace, 2.95, "S2"), [(Red, On), (Green, Off)]);
    assert_eq!(lit(&trace, 3.0, "S2"), [(Red, Off), (Green, On)]);
    assert_eq!(lit(&trace, 10.95, "S2"), [(Red, Off), (Green, On)]);
    assert_eq!(lit(&trace, 11.0, "S2"), [(Red, On), (Green, Off)]);

    // Ids: unique within each frame over every kind, the same in every frame.
    let light_ids = |gt: &GroundTruth| -> Vec<u64> {
        gt.traffic_light
            .iter()
            .map(|l| l.id.unwrap().value())
            .collect()
    };
    for gt in &trace {
        assert_eq!(light_ids(gt), light_ids(first));
        let mut ids: Vec<u64> = light_ids(gt);
        ids.extend(gt.traffic_sign.iter().map(|s| s.id.unwrap().value()));
        ids.extend(gt.moving_object.iter().map(|m| m.id.unwrap().value()));
        ids.extend(gt.lane.iter().map(|l| l.id.unwrap().value()));
        ids.extend(gt.lane_boundary.iter().map(|l| l.id.unwrap().value()));
        let unique: BTreeSet<u64> = ids.iter().copied().collect();
        assert_eq!(unique.len(), ids.len(), "t = {}", seconds(gt));
    }
}

#[test]
fn a_static_sign_is_a_traffic_sign_of_the_first_frame() {
    let (trace, _) = traced_run("osi_traffic_signs", &scenario(), 1.0);
    assert_eq!(trace[0].traffic_sign.len(), 1);
    // Static data goes in the first frame only by default (`--osi-static first`).
    assert!(trace[1..].iter().all(|gt| gt.traffic_sign.is_empty()));
    let sign = trace[0].traffic_sign[0].main_sign.as_ref().unwrap();
    assert_at(
        position(sign.base.as_ref().unwrap()),
        [21.0, 7.0, 2.3, f64::atan2(-0.6, -0.8)],
        "sign 50",
    );
    let c = sign.classification.as_ref().unwrap();
    assert_eq!(c.variability(), Variability::Fixed);
    assert_eq!(c.r#type(), SignType::SpeedLimitBegin);
    let value = c.value.as_ref().unwrap();
    assert_eq!(
        (value.value(), value.value_unit()),
        (50.0, Unit::KilometerPerHour)
    );
    assert_eq!((c.country(), c.code()), ("DE", "274"));
    let source = &trace[0].traffic_sign[0].source_reference[0];
    assert_eq!(source.r#type(), "net.asam.opendrive");
    assert_eq!(source.identifier, ["50"]);
}

/// `classification.assigned_lane_id` (osi::traffic_signals, OpenDRIVE 1.8 §14.2): neither
/// signal of osi_signals.xodr has `<validity>`, so each is for the drivable lanes of the
/// direction its orientation names. Both roads are right-hand traffic with lanes 1 (driven
/// towards −s) and −1 (towards +s): S1 and the sign "50" ("+") are for lane −1 of road 1, each
/// of S1's three bulbs alike; S2 ("-") for lane 1 of road 2. The OSI lane is found by its
/// source reference [road, lane section s, lane], in every frame the same.
#[test]
fn signals_are_assigned_the_lanes_of_their_direction() {
    let (trace, _) = traced_run("osi_signal_lanes", &scenario(), 1.0);
    let first = &trace[0];
    let lane = |road: &str, lane: &str| -> u64 {
        let found = first.lane.iter().find(|l| {
            l.source_reference
                .first()
                .is_some_and(|r| r.identifier == [road, "0", lane])
        });
        found.and_then(|l| l.id).expect("the OSI lane").value()
    };
    let assigned =
        |ids: &[osi::osi3::Identifier]| -> Vec<u64> { ids.iter().map(|i| i.value()).collect() };
    for gt in &trace {
        for bulb in bulbs(gt, "S1") {
            let c = bulb.classification.as_ref().expect("a classification");
            assert_eq!(assigned(&c.assigned_lane_id), [lane("1", "-1")]);
        }
        for bulb in bulbs(gt, "S2") {
            let c = bulb.classification.as_ref().expect("a classification");
            assert_eq!(assigned(&c.assigned_lane_id), [lane("2", "1")]);
        }
    }
    let sign = first
        .traffic_sign
        .iter()
        .find(|s| s.source_reference[0].identifier == ["50"])
        .expect("the sign in the first frame");
    let c = sign
        .main_sign
        .as_ref()
        .and_then(|m| m.classification.as_ref());
    assert_eq!(
        assigned(&c.expect("a classification").assigned_lane_id),
        [lane("1", "-1")]
    );
}
