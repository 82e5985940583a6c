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
