//! RelativeRoadPosition and RelativeLanePosition beyond the end of the entity's road
//! (OpenSCENARIO 1.3: "the reference line of the road of the reference entity continues
//! seamlessly on the connecting road … the lane, where the reference entity is located,
//! continues seamlessly"), on two generated networks:
//! * road_link_unequal_number_of_lanes0.xodr: road "1" from (0, 0) along +x, 100 m, its end
//!   joined to the start of road "2" (from (100, 0) along +x); lanes 3 m wide, no lane offset.
//! * adjustable_planview0.xodr: junction road "102" (24.908 143 m) whose end joins the *end*
//!   of road "1" (230 m; contact point end): road 1's s runs against road 102's. Lane −1 of
//!   road 102 continues as lane 1 of road 1.

use crate::condition_support;

use condition_support::{corpus_road, relative_lane_to_ego, relative_road_to, FakeWorld};
use engine::position::resolve;

/// Tolerance of positions computed in closed form or by the road model (m).
const TOL: f64 = 1e-6;

#[test]
fn continues_onto_the_successor_road() {
    let mut w = FakeWorld::new(corpus_road(
        "generated/xodr/road_link_unequal_number_of_lanes0.xodr",
    ));
    w.place_on_lane("Ego", "1", -1, 90.0, true);
    // 10 m to the end of road 1, 10 m more on road 2: road 2 s = 10, lane −1 (t = −1.5).
    let r = resolve(&relative_lane_to_ego(0, 20.0), &w).unwrap();
    let rp = r.road_position.unwrap();
    assert_eq!((rp.road_id.as_str(), rp.lane_id), ("2", -1));
    assert!((r.pose.x - 110.0).abs() < TOL && (r.pose.y + 1.5).abs() < TOL);
    let p = relative_road_to("Ego", 20.0, 0.5);
    let r = resolve(&p, &w).unwrap();
    assert!((r.pose.x - 110.0).abs() < TOL && (r.pose.y + 1.0).abs() < TOL);
    // Against the traffic of lane 1 (driven towards −s) from road 2 back onto road 1.
    w.place_on_lane("Ego", "2", 1, 10.0, false);
    let r = resolve(&relative_lane_to_ego(0, -20.0), &w).unwrap();
    assert_eq!(r.road_position.unwrap().road_id, "1");
    assert!((r.pose.x - 90.0).abs() < TOL && (r.pose.y - 1.5).abs() < TOL);
}

#[test]
fn continues_onto_a_road_running_the_other_way() {
    let mut w = FakeWorld::new(corpus_road("generated/xodr/adjustable_planview0.xodr"));
    w.place_on_lane("Ego", "102", -1, 20.0, true);
    // 24.908 143 − 20 m to the end of road 102, then the rest of 10 m along road 1 from its
    // end towards −s: s = 230 − (10 − 4.908 143).
    let s = 230.0 - (10.0 - (24.908_143_168_284_15 - 20.0));
    let lane1 = w.network.lane_pose("1", 1, s, 0.0).unwrap();
    let r = resolve(&relative_lane_to_ego(0, 10.0), &w).unwrap();
    assert!((r.pose.x - lane1.x).abs() < TOL && (r.pose.y - lane1.y).abs() < TOL);
    // dLane +1 is to the left of road 102's s, which on road 1 is its right: lane 1 − 1 → −1.
    let lane_m1 = w.network.lane_pose("1", -1, s, 0.0).unwrap();
    let r = resolve(&relative_lane_to_ego(1, 10.0), &w).unwrap();
    assert_eq!(r.road_position.as_ref().unwrap().lane_id, -1);
    assert!((r.pose.x - lane_m1.x).abs() < TOL && (r.pose.y - lane_m1.y).abs() < TOL);
    // RelativeRoadPosition keeps the side: t = −1.5 on road 102 is t = +1.5 on road 1, the
    // centre of lane 1 there.
    let p = relative_road_to("Ego", 10.0, 0.0);
    let r = resolve(&p, &w).unwrap();
    assert!((r.pose.x - lane1.x).abs() < TOL && (r.pose.y - lane1.y).abs() < TOL);
}
