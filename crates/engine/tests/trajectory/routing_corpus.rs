//! Route planning on corpus networks (OpenSCENARIO 1.3 §7.5 "Routes"): a route through two
//! junctions of esmini's multi_intersections.xodr, a closed route round circle_300m.xodr, and
//! a lane change on a two-lane road. Expected paths and lengths are worked out by hand from
//! the files' road links and lengths, quoted at each test.

use crate::trajectory_support;

use engine::routing::{plan_route, PlannedRoute, RoutingOptions};
use opendrive::{Direction, LanePosition};
use scenario::RouteStrategy;
use trajectory_support::{corpus, here, lane, route, Roads};

/// Tolerance of lengths summed from the file's road lengths (m).
const TOL: f64 = 1e-6;

fn plan(roads: &Roads, r: &scenario::Route) -> PlannedRoute {
    // Every route in this file is connected; a failure is the bug under test.
    plan_route(r, roads, &RoutingOptions::default(), &here()).expect("route plans")
}

#[test]
fn route_through_two_junctions_takes_the_shortest_path() {
    // multi_intersections.xodr, from road 196 lane −1 at s = 50 (driven towards +s, to its end
    // at road 261's end) to road 281 lane −1 at s = 100. By the files' links:
    //   196 (+s, 109 − 50 = 59) → 261 (−s, its whole 109) → junction 152 by connecting road
    //   260 (17.701274502691138) → 266 (+s, 109) → 267 (+s, 208.23892818012354) → 217 (−s,
    //   109) → junction 148 by connecting road 223 (22) → 227 (+s, 108.99999999999997) →
    //   281 (+s, 100).
    // Any other way to road 281's start (it is entered only from road 227) goes round by
    // junctions 150, 146 and road 222: hundreds of metres longer.
    let roads = corpus("esmini/xodr/multi_intersections.xodr");
    let r = route(
        vec![lane("196", -1, 50.0), lane("281", -1, 100.0)],
        RouteStrategy::Shortest,
        false,
    );
    let p = plan(&roads, &r);
    let ids: Vec<&str> = p.segments().iter().map(|s| s.road_id.as_str()).collect();
    assert_eq!(
        ids,
        ["196", "261", "260", "266", "267", "217", "223", "227", "281"]
    );
    let expected = 59.0
        + 109.0
        + 17.701_274_502_691_14
        + 109.0
        + 208.238_928_180_123_54
        + 109.0
        + 22.0
        + 108.999_999_999_999_97
        + 100.0;
    assert!((p.length() - expected).abs() < TOL, "{}", p.length());
    assert_eq!(p.junctions(), 2);
    let dirs: Vec<Direction> = p.segments().iter().map(|s| s.direction).collect();
    assert_eq!(dirs[1], Direction::Backward);
    assert_eq!(dirs[5], Direction::Backward);
    // The opendrive router (length + lane-change cost) agrees stretch for stretch.
    let lp = |road: &str, s: f64| LanePosition {
        road_id: road.into(),
        lane_id: -1,
        s,
        offset: 0.0,
    };
    let od = roads.0.route(&lp("196", 50.0), &lp("281", 100.0)).unwrap();
    assert_eq!(od.segments, p.segments());
    // Least intersections finds the same path: nothing reaches road 281 through fewer.
    let r = route(
        vec![lane("196", -1, 50.0), lane("281", -1, 100.0)],
        RouteStrategy::LeastIntersections,
        false,
    );
    assert_eq!(plan(&roads, &r).segments(), p.segments());
}

#[test]
fn closed_route_round_a_circle() {
    // circle_300m.xodr: road 1 (300 m) is its own successor. Lane −1 runs towards +s. A closed
    // route through s = 10 and s = 100 runs 10 → 100 (90 m), then 100 → 300 and 0 → 10
    // (210 m): 300 m, the second waypoint at path s 90, the first again at 300.
    let roads = corpus("esmini/xodr/circle_300m.xodr");
    let r = route(
        vec![lane("1", -1, 10.0), lane("1", -1, 100.0)],
        RouteStrategy::Shortest,
        true,
    );
    let p = plan(&roads, &r);
    assert!(p.closed());
    assert!((p.length() - 300.0).abs() < TOL, "{}", p.length());
    let path_s: Vec<f64> = p.waypoints().iter().map(|w| w.path_s).collect();
    assert_eq!(path_s.len(), 3);
    assert!((path_s[1] - 90.0).abs() < TOL && (path_s[2] - 300.0).abs() < TOL);
    let spans: Vec<(f64, f64)> = p.segments().iter().map(|s| (s.s_start, s.s_end)).collect();
    assert_eq!(spans.len(), 2, "{spans:?}");
    assert!((spans[0].0 - 10.0).abs() < TOL && (spans[0].1 - 300.0).abs() < TOL);
    assert!(spans[1].0.abs() < TOL && (spans[1].1 - 10.0).abs() < TOL);
    // Look-ups by path s: 295 m in is road s 5 on the second pass; road s 5 seen from path
    // s 100 on is that second pass.
    let (seg, s) = p.at(295.0).unwrap();
    assert!((s - 5.0).abs() < TOL && seg.s_start.abs() < TOL);
    assert!((p.path_s_of("1", Some(-1), 5.0, 100.0).unwrap() - 295.0).abs() < TOL);
    assert!((p.path_s_of("1", Some(-1), 50.0, 0.0).unwrap() - 40.0).abs() < TOL);
    assert!(p.path_s_of("1", Some(1), 50.0, 0.0).is_none());
    // The opendrive router is the same search (`RoadNetwork::route_by` with the cost of
    // length): from s = 100 to s = 10, behind the start, it drives round the circle,
    // 300 − 100 + 10 = 210 m, in two stretches (100 → 300, 0 → 10).
    let lp = |s: f64| LanePosition {
        road_id: "1".into(),
        lane_id: -1,
        s,
        offset: 0.0,
    };
    let od = roads
        .0
        .route(&lp(100.0), &lp(10.0))
        .expect("round the circle");
    assert!((od.length - 210.0).abs() < TOL, "{}", od.length);
    assert_eq!(od.segments.len(), 2);
}

#[test]
fn route_to_another_lane_needs_a_lane_change() {
    // multi_intersections.xodr road 209 has two driving lanes, −1 and −2 (3.75 m wide up to
    // s = 33.5, then narrowing to nothing at s = 59), both towards +s. From lane −1 at s = 5 to
    // lane −2 at s = 30: one lane change, made where the route starts (a lane change costs
    // `LANE_CHANGE_COST` wherever it is made, so the search takes it at the first point), then
    // 25 m on lane −2.
    let roads = corpus("esmini/xodr/multi_intersections.xodr");
    let r = route(
        vec![lane("209", -1, 5.0), lane("209", -2, 30.0)],
        RouteStrategy::Shortest,
        false,
    );
    let p = plan(&roads, &r);
    assert!((p.length() - 25.0).abs() < TOL);
    let changes = p.lane_changes();
    assert_eq!(changes.len(), 1);
    let c = &changes[0];
    assert_eq!(
        (c.road_id.as_str(), c.from_lane, c.to_lane),
        ("209", -1, -2)
    );
    assert!(c.path_s.abs() < TOL && (c.s - 5.0).abs() < TOL);
    let last = p.segments().last().unwrap();
    assert_eq!(last.lane_id, -2);
    assert!((last.s_end - 30.0).abs() < TOL);
}
