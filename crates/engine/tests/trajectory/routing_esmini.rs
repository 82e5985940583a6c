//! The catalog route "ComplexRoute" of esmini's routing-test.xosc (OpenSCENARIO 1.3 §7.5,
//! XSD `AssignRouteAction` with a `CatalogReference` into Catalogs/Routes/
//! RoutesAtMultiIntersections.xosc): four waypoints on multi_intersections.xodr, planned leg
//! by leg, against the roads esmini 3.6.0's car drove along it
//! (shared/corpus/reference/esmini/routing-test.csv, until the AcquirePositionAction at
//! 25.45 s).

use crate::trajectory_support;

use engine::routing::{plan_route, RoutingOptions};
use scenario::RoutingAction;
use trajectory_support::{corpus_scenario, init_routing_actions, scenario_roads, Roads};

#[test]
fn complex_catalog_route_follows_esmini() {
    let sc = corpus_scenario("esmini/xosc/routing-test.xosc");
    let roads = Roads(scenario_roads(&sc));
    let (route, pos) = init_routing_actions(&sc)
        .find_map(|(r, pos)| match r {
            RoutingAction::AssignRoute(route) => Some((route.clone(), pos.clone())),
            _ => None,
        })
        .expect("an AssignRouteAction in Init");
    assert_eq!(route.name, "ComplexRoute");
    assert_eq!(route.waypoints.len(), 4);
    let planned = plan_route(&route, &roads, &RoutingOptions::default(), &pos).unwrap();
    // Waypoints: 242 lane 1 s 100 → 261 lane 1 s 50 → 222 lane −1 s 20 → 197 lane −1 s 20.
    // esmini's car, teleported to pathS 20, drove (road, lane):
    // 242/1, 240/−1, 235/−1, 209/1, 205/−1, 196/−1, 261/1, 260/−1, 266/−1, 267/−1, 217/1,
    // 220/−1, 222/−1, 202/2, 214/−1, 197/−1.
    let driven: Vec<(&str, i32)> = planned
        .segments()
        .iter()
        .map(|s| (s.road_id.as_str(), s.lane_id))
        .collect();
    let esmini = [
        ("242", 1),
        ("240", -1),
        ("235", -1),
        ("209", 1),
        ("205", -1),
        ("196", -1),
        ("261", 1),
        ("260", -1),
        ("266", -1),
        ("267", -1),
        ("217", 1),
        ("220", -1),
        ("222", -1),
        ("202", 2),
        ("214", -1),
        ("197", -1),
    ];
    assert_eq!(driven, esmini);
    assert!(planned.lane_changes().is_empty());
    // Junctions entered: 150 (by 240), 146 (205), 152 (260), 148 (220), 146 again (214).
    assert_eq!(planned.junctions(), 5);
}
