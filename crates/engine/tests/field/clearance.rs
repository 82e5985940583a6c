//! Class 7 — RelativeClearanceCondition (OpenSCENARIO 1.3 §7.6.3, XSD
//! `RelativeClearanceCondition`, `RelativeLaneRange`) on a road whose lanes appear and end
//! (`condition::clearance`): lanes at another entity's place are counted from the lane the
//! triggering entity's lane becomes there, following the lane links, not by lane id.
//!
//! Fixture `clearance_2plus1.xosc` on `two_plus_one.xodr`: road 1 has lane -1 on [0, 100),
//! which continues as -2 on [100, 200) (a passing lane -1 appears on its left and ends at
//! 200) and as -1 on [200, 300]; road 2 continues road 1. Event Free starts in the first step
//! when the RelativeLaneRange $From..$To is clear 120 m ahead of Ego (oppositeLanes $Opposite,
//! default false, between reference points). Issue 34 class 4: with oppositeLanes false a range
//! naming only lanes driven the other way is an area that does not exist.

use crate::support::{run, transitions};
use engine::storyboard::Transition;

/// True when Event Free started: the clearance held.
fn free(params: &[(&str, &str)]) -> bool {
    let (_, _, events) = run("clearance_2plus1.xosc", params);
    !transitions(&events, "Free", Transition::Start).is_empty()
}

#[test]
fn a_lane_is_followed_through_the_section_where_its_id_changes() {
    // Ego on lane -1 at s = 50; Other on lane -2 at s = 150, 100 m ahead: the same lane
    // (−1 → −2 by the lane link at s = 100). Own lane (0..0): occupied.
    assert!(!free(&[]));
    // The lane left of Ego's at s = 50 is lane 1, driven the other way: the range 1..1 is
    // looked at with oppositeLanes true (see the_lanes_of_the_other_direction_are_no_area).
    // At Other's place the lane left of Ego's lane is the passing lane −1: Other is not in it.
    let left = [("From", "1"), ("To", "1"), ("Opposite", "true")];
    assert!(free(&left));
    // Other in the passing lane (−1 at s = 150): one lane left of Ego's lane, k = 1.
    let passing = ("OtherLane", "-1");
    let mut left_passing = left.to_vec();
    left_passing.push(passing);
    assert!(!free(&left_passing));
    assert!(free(&[passing]));
}

#[test]
fn the_lanes_of_the_other_direction_are_no_area() {
    // Issue 34 class 4. §7.6.3 / XSD RelativeClearanceCondition: "Evaluates to true, if the
    // specified area exists and is free, otherwise evaluates to false"; oppositeLanes: "If
    // true, then also lanes in the opposite direction are considered; otherwise only lanes in
    // the same direction are considered". Ego on lane −1 at s = 50 (section [0, 100): lanes 1
    // and −1 only); the lane to its left, k = 1, is lane 1, driven the other way (right-hand
    // traffic). Other far off on lane −1 at s = 250 (200 m ahead, outside the 120 m).
    let far = [("OtherLane", "-1"), ("OtherS", "250")];
    // oppositeLanes false: range 1..1 names no lane that is considered: no area, false
    // (before: the empty lane 1 counted as a free area and the event fired at once).
    let mut left = far.to_vec();
    left.extend([("From", "1"), ("To", "1")]);
    assert!(!free(&left));
    // oppositeLanes true: lane 1 is the area, nobody in it within 120 m: true.
    let mut both = left.clone();
    both.push(("Opposite", "true"));
    assert!(free(&both));
    // Other on lane 1 at s = 100, 50 m ahead of Ego: in the area, so false.
    let occupied = [
        ("OtherLane", "1"),
        ("OtherS", "100"),
        ("From", "1"),
        ("To", "1"),
        ("Opposite", "true"),
    ];
    assert!(!free(&occupied));
    // A range mixing both directions keeps the lanes driven Ego's way: 0..1 with oppositeLanes
    // false is Ego's own lane, free of Other at s = 250; Other on lane 1 is not looked at.
    let mut mixed = far.to_vec();
    mixed.extend([("From", "0"), ("To", "1")]);
    assert!(free(&mixed));
    let mut mixed_opposite = occupied[..2].to_vec();
    mixed_opposite.extend([("From", "0"), ("To", "1")]);
    assert!(free(&mixed_opposite));
}

#[test]
fn from_a_lane_that_ends_the_nearest_continuing_lane_is_followed() {
    // Ego in the passing lane (−1 at s = 150), which ends at 200; Other on the through lane
    // (−1 at s = 250). The lane beside Ego driven the same way, −2 (one to its right,
    // k = −1), continues as −1 there: Other is one lane right of Ego. Ego's own lane: clear.
    let base = [("EgoS", "150"), ("OtherLane", "-1"), ("OtherS", "250")];
    assert!(free(&base));
    let mut right = base.to_vec();
    right.extend([("From", "-1"), ("To", "-1")]);
    assert!(!free(&right));
}

#[test]
fn an_entity_on_the_connected_road_ahead_is_in_the_area() {
    // Ego on lane -1 at s = 250 of road 1; Other on road 2, lane -1, s = 10: 60 m ahead in
    // Ego's lane continued (before: other roads were not looked at).
    let params = [
        ("EgoS", "250"),
        ("OtherRoad", "2"),
        ("OtherLane", "-1"),
        ("OtherS", "10"),
    ];
    assert!(!free(&params));
    // 130 m ahead (s = 80 on road 2) it is outside distanceForward = 120.
    let mut far = params.to_vec();
    far[3] = ("OtherS", "80");
    assert!(free(&far));
}
