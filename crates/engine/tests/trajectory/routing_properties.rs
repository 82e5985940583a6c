//! Properties of route planning over random waypoint pairs on esmini's
//! multi_intersections.xodr (OpenSCENARIO 1.3 §7.5): planning either succeeds or reports
//! the pair as not connected, never panics; a plan is continuous (each stretch starts where
//! the previous one ended, or on the next road); and `shortest` is never beaten on its own
//! cost (length + `LANE_CHANGE_COST` per lane change) by any other strategy.

use crate::trajectory_support;

use engine::position::PositionErrorKind;
use engine::routing::{plan_route, PlannedRoute, RoutingErrorKind, RoutingOptions};
use opendrive::LANE_CHANGE_COST;
use proptest::prelude::*;
use scenario::RouteStrategy;
use trajectory_support::{corpus, here, lane, route, Roads};

fn world() -> &'static Roads {
    static ROADS: std::sync::OnceLock<Roads> = std::sync::OnceLock::new();
    ROADS.get_or_init(|| corpus("esmini/xodr/multi_intersections.xodr"))
}

/// Roads of the network outside junctions, each 109 m or longer, with lanes −1 and 1.
const ROADS: [&str; 12] = [
    "196", "197", "202", "209", "217", "222", "227", "235", "256", "261", "266", "275",
];

fn cost(p: &PlannedRoute) -> f64 {
    p.length() + LANE_CHANGE_COST * p.lane_changes().len() as f64
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn plans_are_continuous_and_shortest_is_cheapest(
        a in 0..ROADS.len(),
        b in 0..ROADS.len(),
        la in prop::bool::ANY,
        lb in prop::bool::ANY,
        sa in 5.0..100.0f64,
        sb in 5.0..100.0f64,
        seed in any::<u64>(),
    ) {
        let lane_of = |left: bool| if left { 1 } else { -1 };
        let plan = |strategy| {
            let r = route(
                vec![lane(ROADS[a], lane_of(la), sa), lane(ROADS[b], lane_of(lb), sb)],
                strategy,
                false,
            );
            let options = RoutingOptions { seed, ..RoutingOptions::default() };
            plan_route(&r, world(), &options, &here())
        };
        let shortest = match plan(RouteStrategy::Shortest) {
            Ok(p) => p,
            Err(e) => {
                prop_assert!(
                    matches!(e.kind(), PositionErrorKind::Route(r)
                        if matches!(r.kind(), RoutingErrorKind::NotConnected { .. })),
                    "{e}"
                );
                return Ok(());
            }
        };
        for w in shortest.segments().windows(2) {
            if w[0].road_id == w[1].road_id {
                prop_assert!((w[0].s_end - w[1].s_start).abs() < 1e-6, "{:?}", w);
            }
        }
        let total: f64 = shortest.segments().iter().map(|s| (s.s_end - s.s_start).abs()).sum();
        prop_assert!((total - shortest.length()).abs() < 1e-6);
        for strategy in [
            RouteStrategy::Fastest,
            RouteStrategy::LeastIntersections,
            RouteStrategy::Random,
        ] {
            let other = plan(strategy).unwrap();
            prop_assert!(cost(&shortest) <= cost(&other) + 1e-6, "{strategy:?}");
            prop_assert!(shortest.junctions() >= other.junctions()
                || strategy != RouteStrategy::LeastIntersections);
        }
    }
}
