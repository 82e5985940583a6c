//! Class 2 (issue 16) and issue 34 class 5 — positions past the end of a road
//! (`position::beyond`): an s outside [0, length] of a RoadPosition or LanePosition
//! continues on the road connected at that end, following
//! the lane's links, as OpenSCENARIO 1.3 prescribes for the ds of RelativeRoadPosition and
//! RelativeLanePosition ("the reference line … continues seamlessly on the connecting road");
//! t and the lane offset keep their side. Where nothing connects the position is refused,
//! at load when it depends on no entity (`position::check`), with file:line:col.
//!
//! Fixture `past_road_end.xosc` on `two_roads_lane_end.xodr`: road 1 (x from 0 to 100)
//! continues as road 2 (x from 100 to 500), both along +x, y = t; lanes 1 and -1 are 3.5 m
//! wide (centres t = ±1.75), linked across; road 1 has no predecessor, road 2 no successor.
//! `sync_past_road_end.xosc` on the same road: SynchronizeAction targets past road 1's end
//! resolve through the same position code.

use std::f64::consts::PI;

use crate::support::{load, run};

/// Straight roads: closed forms up to round-off.
const POS_TOL: f64 = 1e-6;

#[test]
fn a_lane_position_past_the_end_continues_on_the_successor() {
    // LanePosition (1, -1, s = 130, offset 0.5): 30 m into road 2, lane -1:
    // (100 + 30, -1.75 + 0.5) = (130, -1.25), heading 0.
    // RoadPosition (1, s = 130, t = -1): road 2, s = 30, t = -1: (130, -1).
    // At t = 1 s Ego goes to LanePosition (2, -1, s = -20): 20 m back into road 1, s = 80:
    // (80, -1.75).
    let (_, rows, _) = run("past_road_end.xosc", &[]);
    let ego = rows.at("Ego", 0.0);
    assert!(
        (ego.x - 130.0).abs() < POS_TOL && (ego.y + 1.25).abs() < POS_TOL,
        "{ego:?}"
    );
    assert!(ego.h.abs() < POS_TOL, "{ego:?}");
    let road = ego.road.as_ref().expect("on a road");
    assert_eq!((road.0.as_str(), road.1), ("2", -1), "{ego:?}");
    assert!((road.2 - 30.0).abs() < POS_TOL, "{ego:?}");
    let car = rows.at("Car", 0.0);
    assert!(
        (car.x - 130.0).abs() < POS_TOL && (car.y + 1.0).abs() < POS_TOL,
        "{car:?}"
    );
    // Far: dsLane -50 along Ego's lane centre (Ego faces +s, so backwards): 30 m to the start
    // of road 2, then 20 m into road 1 from its end: road 1, s = 80, lane -1: (80, -1.75).
    let far = rows.at("Far", 0.0);
    assert!(
        (far.x - 80.0).abs() < POS_TOL && (far.y + 1.75).abs() < POS_TOL,
        "{far:?}"
    );
    let back = rows.at("Ego", 2.0);
    assert!(
        (back.x - 80.0).abs() < POS_TOL && (back.y + 1.75).abs() < POS_TOL,
        "{back:?}"
    );
}

#[test]
fn a_left_lane_and_a_negative_s_continue_the_same_way() {
    // Lane 1 (driven towards −s on a right-hand road) at s = 130 of road 1: road 2, lane 1,
    // s = 30, offset +0.5 (same side): (130, 1.75 + 0.5) = (130, 2.25), heading π.
    let (_, rows, _) = run("past_road_end.xosc", &[("Lane", "1")]);
    let ego = rows.at("Ego", 0.0);
    assert!(
        (ego.x - 130.0).abs() < POS_TOL && (ego.y - 2.25).abs() < POS_TOL,
        "{ego:?}"
    );
    assert!((ego.h.cos() - PI.cos()).abs() < POS_TOL, "{ego:?}");
    // s = -20 on road 2: road 1 at s = 80, lane -1: (80, -1.25).
    let (_, rows, _) = run("past_road_end.xosc", &[("Road", "2"), ("S", "-20")]);
    let ego = rows.at("Ego", 0.0);
    assert!(
        (ego.x - 80.0).abs() < POS_TOL && (ego.y + 1.25).abs() < POS_TOL,
        "{ego:?}"
    );
}

#[test]
fn a_position_past_an_end_with_nothing_connected_is_refused_at_load() {
    // Road 2 has no successor: s = 420 on it is nowhere. The Story's TeleportAction (its
    // Position at line 76, column 80) is refused when the file loads, not at t = 1 s.
    let err = load("past_road_end.xosc", &[("StoryS", "420")]).expect_err("refused");
    assert!(
        err.contains("expected s in [0, 400] on road \"2\", found 420 at ")
            && err.ends_with("past_road_end.xosc:76:80"),
        "{err}"
    );
    // Road 1 has no predecessor: s = -5 in Init, line 48.
    let err = load("past_road_end.xosc", &[("S", "-5")]).expect_err("refused");
    assert!(
        err.contains("found -5 at ") && err.contains("past_road_end.xosc:48:"),
        "{err}"
    );
}

#[test]
fn synchronize_targets_past_a_road_end_are_reached_on_the_successor() {
    // Issue 34 class 5 (`sync_past_road_end.xosc`): the SynchronizeAction's TargetPositionMaster
    // (1, -1, s = 150) and TargetPosition (1, -1, s = 140) lie past road 1's end (100 m): 50 m
    // and 40 m into road 2, x = 150 and 140. The master Ego covers 110 m at 10 m/s in
    // 11.00 s; the NPC must cover 140 m in the same time, arriving in that frame.
    let (_, rows, events) = run("sync_past_road_end.xosc", &[]);
    for (name, x, s) in [("Ego", 150.0, 50.0), ("NPC", 140.0, 40.0)] {
        let r = rows.at(name, 11.0);
        assert!(
            (r.x - x).abs() < POS_TOL && (r.y + 1.75).abs() < POS_TOL,
            "{name}: {r:?}"
        );
        let road = r.road.as_ref().expect("on a road");
        assert_eq!((road.0.as_str(), road.1), ("2", -1), "{name}");
        assert!((road.2 - s).abs() < POS_TOL, "{name}: {road:?}");
    }
    // Before that frame the NPC is short of its target, and the action ends once it is there.
    assert!(rows.at("NPC", 10.95).x < 140.0);
    let end = crate::support::transitions(
        &events,
        "Init NPC SynchronizeAction",
        engine::storyboard::Transition::End,
    );
    assert_eq!(end.len(), 1, "{end:?}");
    assert!((11.0 - 1e-9..=11.05 + 1e-9).contains(&end[0]), "{end:?}");
}
