//! Lane graph and routes (OpenDRIVE 1.8 §12 junctions, §11 lane linkage, `road/@rule`),
//! against lengths read from the files by hand.

use crate::common;

use std::path::Path;

use common::corpus;
use opendrive::{Direction, LaneHandle, LanePosition, LaneType, RoadNetwork};

fn load(path: &Path) -> RoadNetwork {
    RoadNetwork::from_file(path).unwrap_or_else(|e| panic!("{e}"))
}

fn at(road: &str, lane: i32, s: f64) -> LanePosition {
    LanePosition {
        road_id: road.into(),
        lane_id: lane,
        s,
        offset: 0.0,
    }
}

/// `road/@length` as written in the file.
fn len(net: &RoadNetwork, road: &str) -> f64 {
    net.road(road).map_or(f64::NAN, |r| r.length)
}

fn junction_file() -> RoadNetwork {
    load(&corpus().join("generated/xodr/common_junction_creator0.xodr"))
}

#[test]
fn straight_through_a_common_junction() {
    // Road 1 (100 m) ends at junction 100; connection 1 links its lane −1 to lane −1 of
    // connecting road 100 (100.00000012397831 m, contactPoint start), whose successor is road 3
    // at its start, lane −1. From s = 50 on road 1 to s = 30 on road 3:
    // 50 + 100.00000012397831 + 30.
    let net = junction_file();
    let r = net
        .route(&at("1", -1, 50.0), &at("3", -1, 30.0))
        .unwrap_or_else(|| panic!("no route"));
    assert!((r.length - (80.0 + len(&net, "100"))).abs() < 1e-9, "{r:?}");
    let ids: Vec<(&str, i32)> = r
        .segments
        .iter()
        .map(|s| (s.road_id.as_str(), s.lane_id))
        .collect();
    assert_eq!(ids, [("1", -1), ("100", -1), ("3", -1)]);
    assert!(r.segments.iter().all(|s| s.direction == Direction::Forward));
    assert_eq!(r.lane_changes, 0);
}

#[test]
fn opposite_direction_through_the_same_junction() {
    // Lane 1 runs towards −s (right-hand traffic): road 3 from s = 30 down to its start, back
    // through road 100 lane 1 (end → start), then road 1 lane 1 from its end down to s = 50.
    let net = junction_file();
    let r = net
        .route(&at("3", 1, 30.0), &at("1", 1, 50.0))
        .unwrap_or_else(|| panic!("no route"));
    assert!((r.length - (80.0 + len(&net, "100"))).abs() < 1e-9, "{r:?}");
    assert!(
        r.segments
            .iter()
            .all(|s| s.direction == Direction::Backward),
        "{r:?}"
    );
    assert!((r.segments[0].s_start - 30.0).abs() < 1e-12 && r.segments[0].s_end.abs() < 1e-12);
}

#[test]
fn turn_written_only_in_the_other_direction_is_found_from_road_links() {
    // Junction 100 lists connecting road 101 only with incomingRoad 1 (lane 2 → 1). Road 101
    // (80.57849294213011 m) runs from road 1's end (predecessor) to road 2's start (successor);
    // its lane 1 runs towards −s, from road 2 lane 1 into road 1 lane 2. From road 2 lane 1
    // at s = 20 to road 1 lane 2 at s = 60: 20 + 80.57849294213011 + (100 − 60).
    let net = junction_file();
    let r = net
        .route(&at("2", 1, 20.0), &at("1", 2, 60.0))
        .unwrap_or_else(|| panic!("no route"));
    assert!(
        (r.length - (20.0 + len(&net, "101") + 40.0)).abs() < 1e-9,
        "{r:?}"
    );
    let ids: Vec<(&str, i32)> = r
        .segments
        .iter()
        .map(|s| (s.road_id.as_str(), s.lane_id))
        .collect();
    assert_eq!(ids, [("2", 1), ("101", 1), ("1", 2)]);
}

#[test]
fn successors_and_predecessors_are_inverse() {
    let net = junction_file();
    let h = net
        .lane_handle("1", -1, 99.0)
        .unwrap_or_else(|| panic!("lane"));
    let next = net.successors(h);
    assert!(!next.is_empty());
    for &n in next {
        assert!(net.predecessors(n).contains(&h), "{n:?}");
    }
}

/// A handle of no lane of the network (a road index past the end, a lane id its section does
/// not have) has no successors or predecessors: the lane graph's view is empty, no panic.
#[test]
fn a_handle_of_no_lane_has_no_neighbours() {
    let net = junction_file();
    let h = net
        .lane_handle("1", -1, 99.0)
        .unwrap_or_else(|| panic!("lane"));
    let lanes = net.roads()[h.road as usize].lane_sections[h.section as usize]
        .right
        .len() as i32;
    for ghost in [
        LaneHandle {
            road: net.roads().len() as u32,
            ..h
        },
        LaneHandle {
            section: 1_000,
            ..h
        },
        LaneHandle {
            lane: -(lanes + 1),
            ..h
        },
    ] {
        assert!(net.successors(ghost).is_empty(), "{ghost:?}");
        assert!(net.predecessors(ghost).is_empty(), "{ghost:?}");
    }
}

#[test]
fn lane_changes_cost_and_directions_on_one_road() {
    let net = load(Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/files/three_lanes.xodr"
    )));
    // Along lane −1: 80 m, one segment.
    let r = net
        .route(&at("1", -1, 10.0), &at("1", -1, 90.0))
        .unwrap_or_else(|| panic!("no route"));
    assert!((r.length - 80.0).abs() < 1e-12 && r.segments.len() == 1);
    // To lane −2: one lane change (LANE_CHANGE_COST in the search, nothing in length).
    let r = net
        .route(&at("1", -1, 10.0), &at("1", -2, 90.0))
        .unwrap_or_else(|| panic!("no route"));
    assert!(
        (r.length - 80.0).abs() < 1e-12 && r.lane_changes == 1,
        "{r:?}"
    );
    // Backwards along a right-hand lane, across the centre line, onto a sidewalk: no route.
    assert!(net.route(&at("1", -1, 90.0), &at("1", -1, 10.0)).is_none());
    assert!(net.route(&at("1", -1, 10.0), &at("1", 1, 5.0)).is_none());
    assert!(net
        .route(&at("1", -1, 10.0), &at("1", -3, 90.0))
        .is_some_and(|r| r.lane_changes == 2));
    assert!(!LaneType::Sidewalk.is_drivable() && LaneType::Driving.is_drivable());
    // Lane 1 drives towards −s: 90 → 10.
    let r = net
        .route(&at("1", 1, 90.0), &at("1", 1, 10.0))
        .unwrap_or_else(|| panic!("no route"));
    assert!((r.length - 80.0).abs() < 1e-12 && r.segments[0].direction == Direction::Backward);
}

#[test]
fn left_hand_traffic_flips_the_driving_direction() {
    // e6mini-lht.xodr has rule="LHT": lanes 2..4 (driving) run towards +s, −2, −3 towards −s.
    // e6mini.xodr is the same road with right-hand traffic.
    let lht = load(&corpus().join("esmini/xodr/e6mini-lht.xodr"));
    let rht = load(&corpus().join("esmini/xodr/e6mini.xodr"));
    let fwd = lht
        .route(&at("0", 2, 10.0), &at("0", 4, 500.0))
        .unwrap_or_else(|| panic!("no route"));
    assert!(
        (fwd.length - 490.0).abs() < 1e-9 && fwd.lane_changes == 2,
        "{fwd:?}"
    );
    assert!(lht.route(&at("0", -2, 10.0), &at("0", -2, 500.0)).is_none());
    assert!(lht.route(&at("0", -2, 500.0), &at("0", -3, 10.0)).is_some());
    assert!(rht.route(&at("0", 2, 10.0), &at("0", 2, 500.0)).is_none());
    assert!(rht.route(&at("0", -2, 10.0), &at("0", -3, 500.0)).is_some());
}

#[test]
fn direct_junction_both_ways() {
    // direct_junction_creator0.xodr: junction 100 (direct) links road 1's end to road 2's
    // start (lanes −1 → −1), road 1 lane −3 to road 10 lane −1 (an exit), and road 20 lane 1
    // with road 2 lane 3 (an entry, written from road 20's side).
    let net = load(&corpus().join("generated/xodr/direct_junction_creator0.xodr"));
    // Road 1 (200 m) lane −1 from s = 100 to road 2 lane −1 at s = 20: 100 + 20.
    let r = net
        .route(&at("1", -1, 100.0), &at("2", -1, 20.0))
        .unwrap_or_else(|| panic!("no route"));
    assert!((r.length - 120.0).abs() < 1e-9, "{r:?}");
    // Exit: road 1 lane −3 at s = 150 to road 10 lane −1 at s = 40: 50 + 40.
    let r = net
        .route(&at("1", -3, 150.0), &at("10", -1, 40.0))
        .unwrap_or_else(|| panic!("no route"));
    assert!((r.length - 90.0).abs() < 1e-9, "{r:?}");
    // Lane 3 of road 2 runs towards −s into the junction, then road 20 (150 m) lane 1 from its
    // end: from s = 30 on road 2 to s = 100 on road 20 is 30 + 50.
    let r = net
        .route(&at("2", 3, 30.0), &at("20", 1, 100.0))
        .unwrap_or_else(|| panic!("no route"));
    assert!((r.length - 80.0).abs() < 1e-9, "{r:?}");
    // Against the driving direction there is no way back.
    assert!(net.route(&at("2", -1, 20.0), &at("1", -1, 100.0)).is_none());
}

#[test]
fn handles_resolve_ids_once_and_agree_with_the_string_api() {
    // Road "100" is a connecting road of junction "100" (road/@junction="100" in the file);
    // road "1" belongs to no junction. A handle names the same road as its id, and locating a
    // point by handle gives the string API's answer with the ids left out.
    let net = junction_file();
    let h = net.road_handle("100").unwrap_or_else(|| panic!("road 100"));
    assert_eq!(net.road_at(h).id, "100");
    assert_eq!(net.roads()[h.index()].id, "100");
    let j = net
        .road_junction(h)
        .unwrap_or_else(|| panic!("junction of road 100"));
    assert_eq!(net.junction_at(j).id, "100");
    assert_eq!(net.junction_handle("100"), Some(j));
    let one = net.road_handle("1").unwrap_or_else(|| panic!("road 1"));
    assert_eq!(net.road_junction(one), None);
    assert_eq!(net.road_handle("no such road"), None);
    let lane = net
        .lane_handle("1", -1, 50.0)
        .unwrap_or_else(|| panic!("lane"));
    assert_eq!(lane.road_handle(), one);
    let pose = net
        .lane_pose("1", -1, 50.0, 0.25)
        .unwrap_or_else(|e| panic!("{e}"));
    let by_id = net.locate(pose.x, pose.y, Some(pose.h));
    let point = net
        .locate_point(pose.x, pose.y, Some(pose.h))
        .unwrap_or_else(|| panic!("no point"));
    assert_eq!(point.road, one);
    assert_eq!(by_id, Some(net.road_position(&point)));
    let on_road = net
        .locate_point_on_road(one, pose.x, pose.y)
        .unwrap_or_else(|| panic!("not on road 1"));
    // s = 50 and the offset 0.25 m from lane −1's centre, to the solver's tolerance.
    assert!((on_road.s - 50.0).abs() < 1e-9 && (on_road.offset - 0.25).abs() < 1e-9);
    assert_eq!(on_road.lane_id, -1);
}

/// `RoadNetwork::joined_roads` on common_junction_creator0.xodr, read from the file by hand:
/// roads 1, 2, 3 end at junction 100; connections (incoming → connecting, contactPoint):
/// 3 → 100 end, 1 → 100 start, 1 → 101 start, 2 → 102 start; the connecting roads' links:
/// 100 = 1 end … 3 start, 101 = 1 end … 2 start, 102 = 2 start … 3 start.
#[test]
fn roads_joined_at_a_junction_end_by_connections_and_road_links() {
    let net = junction_file();
    let joined = |road: &str, dir: Direction| -> Vec<(String, Direction)> {
        let h = net.road_handle(road).expect("road");
        net.joined_roads(h, dir)
            .into_iter()
            .map(|(r, d)| (net.roads()[r.index()].id.clone(), d))
            .collect()
    };
    let pairs = |v: &[(&str, Direction)]| -> Vec<(String, Direction)> {
        v.iter().map(|&(r, d)| (r.to_owned(), d)).collect()
    };
    use Direction::{Backward, Forward};
    // Road 1's end: 100 (first found from 100's own predecessor link), 101; once each.
    assert_eq!(
        joined("1", Forward),
        pairs(&[("100", Forward), ("101", Forward)])
    );
    // Road 2's start: 101 only by its successor link (entered at its end), 102 by connection 3.
    assert_eq!(
        joined("2", Backward),
        pairs(&[("101", Backward), ("102", Forward)])
    );
    // Road 3's start: 100 by connection 0 (contactPoint end), 102 by its successor link.
    assert_eq!(
        joined("3", Backward),
        pairs(&[("100", Backward), ("102", Backward)])
    );
    // A connecting road's end: its road link, road 2 entered at its start.
    assert_eq!(joined("101", Forward), pairs(&[("2", Forward)]));
    // Road 1's start links to nothing.
    assert_eq!(joined("1", Backward), pairs(&[]));
}
