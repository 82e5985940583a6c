//! The default controller drives its assigned route (OpenSCENARIO 1.3 §7.5 "Routes",
//! §7.7.2.6 AssignRouteAction): through junctions by the route's connecting roads, into the
//! lane a turn needs, round a closed route again and again, with routeStrategy `random` drawn
//! from the run's seed. The scenarios are `tests/files/routing/*.xosc` on road networks
//! written for these tests (each file's comment describes it); every expected road, time and
//! lateral position is worked out by hand at the test.

use crate::runtime_support;
use crate::trajectory_support;

use engine::output::EventRecord;
use engine::routing::{plan_route, RoutingOptions};
use engine::storyboard::ElementState;
use engine::EngineConfig;
use runtime_support::{run_with, Recorder};
use scenario::{RouteStrategy, Waypoint};
use trajectory_support::{fixture, here, lane};

/// Step length of the runs (s), `EngineConfig::default().dt`.
const DT: f64 = 0.05;

/// Runs `tests/files/routing/NAME` with parameter overrides and a seed.
fn run(name: &str, params: &[(&str, &str)], seed: u64) -> (Recorder, Vec<EventRecord>) {
    let path = crate::corpus::fixture("routing").join(name);
    let config = EngineConfig {
        seed,
        ..EngineConfig::default()
    };
    let (_, frames, events) = run_with(&path, params, config);
    (frames, events)
}

/// The roads Ego drives, in order, each with the time of its first frame there.
fn roads(frames: &Recorder) -> Vec<(String, f64)> {
    let mut out: Vec<(String, f64)> = Vec::new();
    for r in frames.0.iter().filter(|r| r.name == "Ego") {
        let road = r.road.as_ref().map_or("-", |p| p.0.as_str());
        if out.last().is_none_or(|(last, _)| last != road) {
            out.push((road.to_owned(), r.time));
        }
    }
    out
}

fn ids(roads: &[(String, f64)]) -> Vec<&str> {
    roads.iter().map(|(id, _)| id.as_str()).collect()
}

#[test]
fn drives_the_shortest_route_through_two_junctions() {
    // two_junction_choice.xodr: from road 1 s = 10 to road 4 s = 50 the shortest way is
    // 90 + 10 (road 12) + 100 (road 3) + 10 (road 31) + 50 = 260 m; by road 2 it is 360 m
    // (routing_strategies.rs). At 20 m/s on straight lanes (s advances 1 m per step), after
    // 12 s Ego has driven 240 m: 210 m to the start of road 4, so it is at road 4, s = 30.
    let (frames, events) = run("two_junctions.xosc", &[], 1);
    assert!(
        !events
            .iter()
            .any(|e| matches!(e, EventRecord::Error { .. })),
        "{events:?}"
    );
    let driven = roads(&frames);
    assert_eq!(ids(&driven), ["1", "12", "3", "31", "4"]);
    // Road 1 is left at 90 m / 20 m/s = 4.5 s, road 12 at 5.0 s, road 3 at 10.0 s, road 31
    // at 10.5 s: the first frame on each next road is one step later.
    for ((_, t), want) in driven[1..].iter().zip([4.5, 5.0, 10.0, 10.5]) {
        assert!((t - want - DT).abs() < 1e-6, "entered at {t}, hand {want}");
    }
    let end = frames.at("Ego", 12.0).road.clone().expect("Ego on a road");
    assert_eq!((end.0.as_str(), end.1), ("4", -1));
    assert!((end.2 - 30.0).abs() < 1e-6, "s = {}", end.2);

    // Without a route the controller takes the junction's first connection (road 11), so the
    // route above is the controller following the plan, not the network's default.
    let (frames, _) = run("two_junctions.xosc", &[("AssignAt", "100")], 1);
    assert_eq!(ids(&roads(&frames)), ["1", "11", "2"]);
}

#[test]
fn entity_behind_the_route_joins_it() {
    // The route starts on connecting road 12 (s = 5) of junction 100, ahead of Ego on road 1:
    // where road 1 ends, of the junction's connecting roads 11 (first) and 12 Ego takes the one
    // on the route, then follows it: 12, 3, 31, 4 (without the route: 11, 2).
    let (frames, _) = run(
        "two_junctions.xosc",
        &[("FromRoad", "12"), ("FromS", "5")],
        1,
    );
    assert_eq!(ids(&roads(&frames)), ["1", "12", "3", "31", "4"]);
}

#[test]
fn unconnected_waypoints_are_reported_and_the_entity_drives_on() {
    // Road 1 s = 5 lies behind Ego's start on a one-way network with no loop: no path leads
    // there. The action logs the planner's error with the waypoint's place in the file and
    // assigns nothing; Ego drives on by lane links as without a route.
    let (frames, events) = run("two_junctions.xosc", &[("ToRoad", "1"), ("ToS", "5")], 1);
    let errors: Vec<&str> = events
        .iter()
        .filter_map(|e| match e {
            EventRecord::Error { message, .. } => Some(message.as_str()),
            _ => None,
        })
        .collect();
    assert_eq!(errors.len(), 1, "{errors:?}");
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/files/routing/two_junctions.xosc"
    );
    assert_eq!(
        errors[0],
        format!(
            "expected a path through the road network from waypoint 1 (road \"1\", lane -1, \
             s = 10.000) to waypoint 2 (road \"1\", lane -1, s = 5.000) of route \"R\", found \
             none at {path}:65:71 (the route is not assigned)"
        )
    );
    assert_eq!(ids(&roads(&frames)), ["1", "11", "2"]);
}

/// Lateral position t of lane −1's centre (m): 3.5 m lanes.
const LANE_1: f64 = -1.75;
/// Lateral position t of lane −2's centre (m).
const LANE_2: f64 = -5.25;

#[test]
fn turn_reached_from_another_lane_changes_lane_in_time() {
    // turn_lane.xodr: road 3 is reached only from lane −2 of road 1 (by connecting road 12);
    // Ego starts in lane −1 at s = 10, 10 m/s, with the route assigned in Init. The change
    // starts at once, cubic over D = v·√(6·Δ/a) = 10·√(6·3.5/1) = 10·√21 = 45.826 m
    // (world::lane_change: peak lateral acceleration 1 m/s²). Progress u = 10·T/D at time
    // T (the odometer), t(T) = −1.75 − 3.5·(3u² − 2u³). E.g. T = 2 s: u = 20/45.826 =
    // 0.436436, u² = 400/2100 = 0.190476, u³ = 0.083131, 3u² − 2u³ = 0.571429 − 0.166261 =
    // 0.405167, t = −1.75 − 1.418086 = −3.168086.
    let (frames, _) = run("turn_lane.xosc", &[], 1);
    let d = 10.0 * 21f64.sqrt();
    let t_at = |time: f64| frames.at("Ego", time).road.clone().expect("on road").3;
    assert!((t_at(2.0) - (-3.168_086)).abs() < 1e-6, "{}", t_at(2.0));
    for time in [0.5, 1.0, 2.0, 3.0, 4.0, 4.5] {
        let u: f64 = 10.0 * time / d;
        let hand = LANE_1 - 3.5 * (3.0 * u * u - 2.0 * u * u * u);
        assert!(
            (t_at(time) - hand).abs() < 1e-9,
            "t({time}) = {}",
            t_at(time)
        );
    }
    // The heading is the direction of the motion: the lateral share of the travel is
    // sin θ = Δ·f′(u)/D, f′ = 6u − 6u², on this straight road h = θ. T = 2 s: f′ = 1.475758,
    // sin θ = −3.5·1.475758/45.826 = −0.112713, h = −0.112953 rad.
    let h_at = |time: f64| frames.at("Ego", time).h;
    assert!((h_at(2.0) - (-0.112_953)).abs() < 1e-6, "{}", h_at(2.0));
    for time in [0.5, 1.0, 3.0, 4.0] {
        let u: f64 = 10.0 * time / d;
        let hand = (-3.5 * (6.0 * u - 6.0 * u * u) / d).asin();
        assert!(
            (h_at(time) - hand).abs() < 1e-9,
            "h({time}) = {}",
            h_at(time)
        );
    }
    // Done after D/v = 4.583 s, about 55 m of road before road 1 ends at s = 200.
    for time in [4.6, 10.0, 18.0] {
        let p = frames.at("Ego", time).road.clone().expect("on road");
        assert_eq!((p.0.as_str(), p.1), ("1", -2), "at {time}");
        assert!((p.3 - LANE_2).abs() < 1e-9, "t({time}) = {}", p.3);
    }
    assert_eq!(ids(&roads(&frames)), ["1", "12", "3"]);

    // A route straight on (road 2, reached from lane −1) needs no lane change.
    let (frames, _) = run("turn_lane.xosc", &[("ToRoad", "2")], 1);
    assert_eq!(ids(&roads(&frames)), ["1", "11", "2"]);
    let on_road_1 = frames
        .0
        .iter()
        .filter(|r| r.road.as_ref().is_some_and(|p| p.0 == "1"));
    assert!(on_road_1.into_iter().all(|r| r
        .road
        .as_ref()
        .is_some_and(|p| p.1 == -1 && (p.3 - LANE_1).abs() < 1e-9)));
}

#[test]
fn lane_change_across_a_lane_section_follows_the_lane_links() {
    // turn_lane_sections.xodr: on road 1 lane −1 narrows to nothing at s = 50 (width
    // w₁(s) = 3.5 − 0.07·s) and lanes −2, −3 continue as −1, −2 of the next lane section, of
    // which only −2 (before s = 50: −3) turns to road 3. Ego starts in lane −2 at s = 10,
    // 10 m/s: its lane, carried by the links to the road's end, goes straight on, so the route
    // needs lane −3 at once. Both lanes' centres move with w₁: lane −2's is at −(w₁ + 1.75),
    // lane −3's at −(w₁ + 5.25), so the cubic over D = 10·√21 m gives
    // t = −w₁(s) − 1.75 − 3.5·f(u), u = 10·T/D, with w₁ = 0 from s = 50 on, where the blend's
    // two lanes (−2 → −1, −3 → −2) are carried across the section boundary by their links.
    let (frames, _) = run("turn_lane_sections.xosc", &[], 1);
    let d = 10.0 * 21f64.sqrt();
    for time in [1.0, 2.0, 3.0, 3.95, 4.0, 4.05, 4.1, 4.5] {
        let p = frames.at("Ego", time).road.clone().expect("on road");
        let w1 = if p.2 < 50.0 { 3.5 - 0.07 * p.2 } else { 0.0 };
        let u: f64 = 10.0 * time / d;
        let hand = -w1 - 1.75 - 3.5 * (3.0 * u * u - 2.0 * u * u * u);
        assert!(
            (p.3 - hand).abs() < 1e-9,
            "t({time}) = {}, hand {hand}",
            p.3
        );
    }
    assert!(frames
        .at("Ego", 3.95)
        .road
        .as_ref()
        .is_some_and(|p| p.2 < 50.0));
    assert!(frames
        .at("Ego", 4.05)
        .road
        .as_ref()
        .is_some_and(|p| p.2 > 50.0));
    assert_eq!(ids(&roads(&frames)), ["1", "12", "3"]);
}

#[test]
fn lateral_action_takes_the_lateral_domain_from_the_route() {
    // turn_lane_override.xosc: as turn_lane.xosc, but at 1 s a LaneChangeAction back to lane −1
    // (cubic, 2 s) takes the lateral domain (§7.5.1 control domains): the route's lane change
    // gives way, Ego moves back towards lane −1 (t rises) until the action ends. Then the route
    // still needs lane −2 and starts again from where the action left Ego, t_e at time T_e:
    // t(T) = t_e + (−5.25 − t_e)·f(u), u = 10·(T − T_e)/D, D = 10·√(6·|−5.25 − t_e|), f the
    // cubic 3u² − 2u³ (world::lane_change), until u = 1; then lane −2 and road 12.
    let (frames, events) = run("turn_lane_override.xosc", &[], 1);
    let ended = events
        .iter()
        .find_map(|e| match e {
            EventRecord::Transition(t)
                if t.name == "LaneChangeAction" && t.to == ElementState::Complete =>
            {
                Some(t.time)
            }
            _ => None,
        })
        .expect("the LaneChangeAction ends");
    let t_at = |time: f64| frames.at("Ego", time).road.clone().expect("on road").3;
    assert!(
        t_at(1.5) > t_at(1.05) && t_at(2.5) > t_at(1.5),
        "moving back towards lane −1"
    );
    let t_e = t_at(ended);
    assert!((t_e - LANE_1).abs() < 0.01, "the action's end: t = {t_e}");
    let d = 10.0 * (6.0 * (LANE_2 - t_e).abs()).sqrt();
    for dt in [0.05, 1.0, 2.0, 4.0] {
        let u: f64 = 10.0 * dt / d;
        let hand = t_e + (LANE_2 - t_e) * (3.0 * u * u - 2.0 * u * u * u);
        let time = ended + dt;
        assert!(
            (t_at(time) - hand).abs() < 1e-9,
            "t({time}) = {}",
            t_at(time)
        );
    }
    let done = ended + d / 10.0 + DT;
    let after = frames
        .at("Ego", (done / DT).ceil() * DT)
        .road
        .clone()
        .expect("on road");
    assert_eq!(after.1, -2);
    assert!((after.3 - LANE_2).abs() < 1e-9);
    assert_eq!(ids(&roads(&frames)), ["1", "12", "3"]);
}

#[test]
fn closed_route_wraps_and_an_open_one_ends() {
    // loop_exit.xodr: road 1 (100 m) → junction 100 → road 12 (half circle R = 50 m, exit by
    // road 11 is the junction's first connection) → road 3 (100 m) → road 4 (half circle) →
    // road 1. Lane −1 of a left-turning half circle is 1.75 m outside the reference line: it
    // is π·51.75 = 162.577 m long. From road 1 s = 10 at 20 m/s, Ego leaves road 1 at
    // 90/20 = 4.5 s, road 12 at 4.5 + 8.129 = 12.629 s, road 3 at 17.629 s, road 4 at
    // 25.757 s; a lap takes (200 + 2·162.577)/20 = 26.258 s.
    let lap = (200.0 + 2.0 * 51.75 * std::f64::consts::PI) / 20.0;
    let arc = 51.75 * std::f64::consts::PI / 20.0;
    let left = [4.5, 4.5 + arc, 9.5 + arc, 9.5 + 2.0 * arc];
    // The closed route (road 1 s = 10 → road 3 s = 50 → back to road 1 s = 10) is driven
    // again and again in 60 s: never the exit.
    let (frames, _) = run("loop.xosc", &[], 1);
    let driven = roads(&frames);
    assert_eq!(
        ids(&driven),
        ["1", "12", "3", "4", "1", "12", "3", "4", "1", "12"]
    );
    for (k, (_, t)) in driven[1..].iter().enumerate() {
        let hand = left[k % 4] + lap * (k / 4) as f64;
        assert!(
            *t > hand && *t <= hand + DT + 1e-6,
            "entered at {t}, hand {hand}"
        );
    }
    // The same route open ends at road 3 s = 50; at the junction the second time round Ego
    // takes the first connection, the exit.
    let (frames, _) = run("loop.xosc", &[("Closed", "false")], 1);
    assert_eq!(ids(&roads(&frames)), ["1", "12", "3", "4", "1", "11", "2"]);
}

#[test]
fn random_route_draws_from_the_run_seed() {
    // two_equal_ways.xodr: roads 11 and 12 are mirror images, 104.72 m each, so routeStrategy
    // random chooses by its lane weights alone, which hash the run's seed with the route's
    // name ("RandomRoute"). The way driven is the one the planner gives for that seed, a run
    // is the same for the same seed, and seeds 1 and 2 fall on different ways.
    let network = fixture("routing/two_equal_ways.xodr");
    let route = scenario::Route {
        name: "RandomRoute".into(),
        closed: false,
        waypoints: [lane("1", -1, 10.0), lane("4", -1, 50.0)]
            .into_iter()
            .map(|position| Waypoint {
                route_strategy: RouteStrategy::Random,
                position,
            })
            .collect(),
        catalog: None,
    };
    let mut taken = Vec::new();
    for seed in 1..=6 {
        let options = RoutingOptions {
            seed,
            ..RoutingOptions::default()
        };
        // Both ways lead to road 4; a failure is the bug under test.
        let plan = plan_route(&route, &network, &options, &here()).expect("route plans");
        let planned = plan.segments()[1].road_id.clone();
        let (frames, _) = run("equal_ways.xosc", &[], seed);
        let driven = roads(&frames);
        assert_eq!(ids(&driven), ["1", planned.as_str(), "4"], "seed {seed}");
        let (again, _) = run("equal_ways.xosc", &[], seed);
        assert_eq!(frames.0, again.0, "seed {seed}");
        taken.push(planned);
    }
    assert_ne!(taken[0], taken[1], "seeds 1 and 2: {taken:?}");
}

#[test]
fn route_in_crossing0_takes_the_routes_roads() {
    // generated/route_in_crossing0.xosc: Ego on fabriksgatan.xodr road 0 lane 1 (driven
    // towards −s) at s = 50, 10 m/s; at 1 s a route from road 0 s = 30 to road 1 lane −1
    // s = 10. Junction 4 joins road 0 to road 1 only by connecting road 8 (its connections
    // from road 0: 8 → road 1, 9 → road 2, 10 → road 3), so the route is 0, 8, 1, and Ego
    // drives it: 50 m to road 0's start (5 s), 9.14 m of road 8, then road 1.
    let path = runtime_support::corpus("generated/xosc/route_in_crossing0.xosc");
    let (_, frames, events) = run_with(&path, &[], EngineConfig::default());
    assert!(!events
        .iter()
        .any(|e| matches!(e, EventRecord::Error { .. })));
    let driven = roads(&frames);
    assert_eq!(ids(&driven), ["0", "8", "1"]);
    assert!((driven[1].1 - 5.0).abs() <= DT + 1e-6, "{driven:?}");
}
