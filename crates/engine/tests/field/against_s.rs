//! Class 3 — driving against the reference line. A lane's driving direction comes from its
//! side and the road's `rule` (OpenDRIVE 1.8 §9.1 / §11.1: with right-hand traffic lanes with
//! negative ids are driven towards +s, with left-hand traffic those with positive ids); an
//! entity's own direction of travel is its heading relative to s (OpenSCENARIO 1.3 §6.3.3).
//! The default controller moves the entity along its own travel, whichever way that is
//! relative to s, and a RelativeTargetLane counts lanes to the left of that travel (1.3 XSD
//! RelativeTargetLane: "positive to the left"; semantics-pitfalls #15).
//!
//! Fixture `against_s.xosc`: Ego on lane `$Lane` of road 1 at s = 100, 10 m/s, Orientation
//! `$OType` h = `$H`; from t = 1 s a 2 s linear lane change by `$DLane`. Roads:
//! `lht_straight.xodr` (LHT, four 3.5 m lanes, centres t = ±1.75, ±5.25) and
//! `straight_500m.xodr` (RHT, lanes ±1 3.07 m, shoulders ±2 1.68 m).

use crate::support::run;

/// Straight roads: closed forms up to round-off.
const POS_TOL: f64 = 1e-6;

/// The heading of a lateral transition comes from the slope over one 0.05 s step; on the
/// linear shape's straight middle it equals the closed form to well within this.
const HEADING_TOL: f64 = 1e-4;

fn ego(params: &[(&str, &str)], t: f64) -> (f64, f64, f64, i32) {
    let (_, rows, _) = run("against_s.xosc", params);
    let r = rows.at("Ego", t);
    (r.x, r.y, r.h, r.road.as_ref().expect("on the road").1)
}

#[test]
fn the_default_controller_follows_the_lanes_driving_direction_on_lht_roads() {
    // LHT lane 1 is driven towards +s: heading 0, x = 100 + 10 · 4 = 140 at 4 s.
    let (x, y, h, lane) = ego(&[], 4.0);
    assert!((x - 140.0).abs() < POS_TOL && (y - 1.75).abs() < POS_TOL && h.abs() < POS_TOL);
    assert_eq!(lane, 1);
    // LHT lane -1 towards −s: heading π, x = 100 − 40 = 60.
    let (x, y, h, lane) = ego(&[("Lane", "-1"), ("CarLane", "-1")], 4.0);
    assert!(
        (x - 60.0).abs() < POS_TOL && (y + 1.75).abs() < POS_TOL,
        "{x} {y}"
    );
    assert!((h.abs() - std::f64::consts::PI).abs() < POS_TOL, "{h}");
    assert_eq!(lane, -1);
}

#[test]
fn an_entity_turned_against_its_lane_drives_its_own_way() {
    // RHT lane -1 is driven towards +s; Ego is put on it with absolute heading π: it drives
    // towards −s, x = 100 − 40 = 60, on the lane's centre t = −1.535.
    let turned = [
        ("Road", "straight_500m.xodr"),
        ("Lane", "-1"),
        ("OType", "absolute"),
        ("H", "3.141592653589793"),
    ];
    let (x, y, _, lane) = ego(&turned, 4.0);
    assert!(
        (x - 60.0).abs() < POS_TOL && (y + 1.535).abs() < POS_TOL,
        "{x} {y}"
    );
    assert_eq!(lane, -1);
    // One lane to the left of its travel (−x) is towards −t: shoulder lane −2, centre
    // t = −(3.07 + 0.84) = −3.91, reached at t = 3 s. (The road position reports the nearest
    // drivable lane, −1, with its offset: a shoulder is not a lane one drives in.)
    let mut params = turned.to_vec();
    params.push(("DLane", "1"));
    let (_, y, _, _) = ego(&params, 3.0);
    assert!((y + 3.91).abs() < POS_TOL, "{y}");
}

#[test]
fn a_relative_lane_change_counts_to_the_left_of_the_entitys_travel() {
    // LHT lane 1 (travel +x): left is +t, lane 2 at t = 5.25 when the 2 s change ends (3 s);
    // half-way (2 s) at t = 3.5, heading atan(v_lat / v_along) with v_lat = 3.5 / 2 =
    // 1.75 m/s and v_along = √(10² − 1.75²) = 9.8457 m/s: 0.17600 rad.
    let (_, y, h, _) = ego(&[("DLane", "1")], 2.0);
    assert!((y - 3.5).abs() < POS_TOL, "{y}");
    assert!(
        (h - (1.75f64 / (100.0f64 - 1.75 * 1.75).sqrt()).atan()).abs() < HEADING_TOL,
        "{h}"
    );
    let (_, y, _, lane) = ego(&[("DLane", "1")], 3.0);
    assert!((y - 5.25).abs() < POS_TOL && lane == 2, "{y} {lane}");
    // LHT lane -1 (travel −x): left is −t, lane −2 at t = −5.25; half-way heading
    // π − 0.17600, i.e. −2.96559 after normalisation.
    let params = [("Lane", "-1"), ("DLane", "1"), ("CarLane", "-1")];
    let (_, y, h, _) = ego(&params, 2.0);
    assert!((y + 3.5).abs() < POS_TOL, "{y}");
    let expected = -(std::f64::consts::PI - (1.75f64 / (100.0f64 - 1.75 * 1.75).sqrt()).atan());
    assert!((h - expected).abs() < HEADING_TOL, "{h}");
    let (_, y, _, lane) = ego(&params, 3.0);
    assert!((y + 5.25).abs() < POS_TOL && lane == -2, "{y} {lane}");
}
