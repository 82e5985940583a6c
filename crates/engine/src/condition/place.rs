//! oscsim's PlaceReached (no XML form; `scenario::EntityCondition::PlaceReached`): the
//! OpenSCENARIO DSL runtime's trigger for the lane changes of a route through points in other
//! lanes in a phase that starts on a run-time condition (ASAM OpenSCENARIO DSL 2.1 §8.9
//! `along`, §8.12.2.1 `create_route`): each change starts when the actor reaches its point,
//! wherever the actor was when the phase started. The place is measured as the roads of the
//! plan say (`position::RoadChain`): over several roads in the plan's s, on one road in the
//! road's own s, and for an actor driving against s in u = L − s along its direction of
//! travel, so "reached" is "at or beyond" in the direction the actor drives.

use opendrive::{Real, RoadNetwork};
use scenario::PlanRoads;

use crate::position::{EntityView, RoadChain};

/// PlaceReached: `e`'s place in the measure of `roads` is `value` or beyond; false off them.
pub(super) fn place_reached(
    network: &RoadNetwork,
    e: &EntityView<'_>,
    value: Real,
    roads: &PlanRoads,
) -> bool {
    let chain = RoadChain::new(network, roads);
    e.road_position
        .and_then(|p| chain.s_of(&p.road_id, p.s))
        .is_some_and(|here| here >= value)
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use opendrive::{Pose, RoadNetwork};
    use scenario::{ObjectType, PlanRoads};

    use super::*;
    use crate::domain::{BoundingBox, Position3d};

    /// The DSL runtime's straight test road: road "1", 1000 m along +x from (0, 0), lanes 1, 2
    /// left and −1 … −3 right of 3.5 m.
    fn straight() -> RoadNetwork {
        let path =
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../dsl_runtime/tests/roads/straight.xodr");
        // The road is part of the repository; a missing file is a broken checkout.
        RoadNetwork::from_file(&path).expect("tests/roads/straight.xodr loads")
    }

    /// Whether an entity at (x, y) has reached `value` in the measure of `roads`.
    fn reached(net: &RoadNetwork, (x, y): (Real, Real), value: Real, roads: &PlanRoads) -> bool {
        let bb =
            BoundingBox::new(Position3d::new(1.4, 0.0, 0.75), 5.0, 2.0, 1.5).expect("a valid box");
        let pose = Pose {
            x,
            y,
            ..Pose::default()
        };
        let at = net.locate(x, y, None);
        let mut e = EntityView::new("e", ObjectType::Vehicle, pose, bb);
        e.road_position = at.as_ref();
        place_reached(net, &e, value, roads)
    }

    /// In +s on one road the measure is the road's s (x here): 50 m is reached at x = 50 and
    /// beyond, not at 49.9; on a chain of that road from the plan's s 100 m, s + 100. Against
    /// s the measure is u = 1000 − s: at x = 900, u = 100. Off the chain's roads, false.
    #[test]
    fn a_place_is_reached_at_or_beyond_it_in_the_plans_measure() {
        let net = straight();
        let plus = PlanRoads::default();
        assert!(reached(&net, (50.0, -1.75), 50.0, &plus));
        assert!(reached(&net, (60.0, -1.75), 50.0, &plus));
        assert!(!reached(&net, (49.9, -1.75), 50.0, &plus));
        let chain = PlanRoads {
            chain: vec![("1".to_string(), 100.0)],
            against: false,
        };
        assert!(reached(&net, (50.0, -1.75), 150.0, &chain));
        assert!(!reached(&net, (50.0, -1.75), 150.1, &chain));
        let against = PlanRoads {
            chain: Vec::new(),
            against: true,
        };
        assert!(reached(&net, (900.0, 1.75), 100.0, &against));
        assert!(!reached(&net, (900.1, 1.75), 100.0, &against));
        let elsewhere = PlanRoads {
            chain: vec![("7".to_string(), 0.0)],
            against: false,
        };
        assert!(!reached(&net, (500.0, -1.75), 0.0, &elsewhere));
    }
}
