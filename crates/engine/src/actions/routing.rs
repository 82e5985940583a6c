//! AssignRouteAction and AcquirePositionAction (OpenSCENARIO 1.3 §7.7.2.6 "RoutingAction",
//! XSD `AssignRouteAction`, `AcquirePositionAction`): give the actor a route, which the
//! default controller follows through junctions, changing lanes where the route needs it
//! (module `world::route_follow`). Planning is the `routing` module's, with the run's seed for
//! routeStrategy `random`.
//!
//! RandomRouteAction plans a seeded random walk from the actor's lane (routing/random_route.rs)
//! and assigns it like a route.
//!
//! AcquirePositionAction plans the shortest route from the actor's lane position to the target
//! and ends at once; reaching the target is the default controller's job along that route.
//! A route that cannot be planned is recorded in the event log and the actor keeps driving by
//! lane links.

use opendrive::LanePosition;
use scenario::{Position, Route, RouteStrategy, SourcePos};

use crate::output::EventRecord;
use crate::position::resolve;
use crate::routing::{plan_between, plan_random, plan_route, PlannedRoute, RoutingOptions};
use crate::store::World;
use crate::world::entity::EntityId;
use crate::world::RouteFollow;

/// The run's routing options: routeStrategy `random` draws from the run's seed
/// ([`EngineConfig::seed`](crate::EngineConfig), `oscsim run --seed`).
fn options(world: &World) -> RoutingOptions {
    crate::position::EntityQuery::routing_options(world)
}

/// Gives `actor` the planned route: for conditions and positions (`Entity::route`) and for the
/// default controller to follow (`Entity::route_follow`).
fn give(world: &mut World, actor: EntityId, planned: PlannedRoute) {
    let e = world.entity_mut(actor);
    e.route = Some(planned.route().clone());
    e.route_follow = Some(RouteFollow::new(planned));
}

/// AssignRouteAction: plans `route` and assigns it.
pub(crate) fn assign(
    world: &mut World,
    actor: EntityId,
    route: &Route,
    pos: &SourcePos,
    name: &str,
    time: f64,
    events: &mut Vec<EventRecord>,
) {
    match plan_route(route, &*world, &options(world), pos) {
        Ok(planned) => give(world, actor, planned),
        Err(e) => events.push(EventRecord::Error {
            time,
            element: name.to_owned(),
            message: format!("{e} (the route is not assigned)"),
        }),
    }
}

/// AcquirePositionAction: plans a route from the actor to `target` and assigns it.
pub(crate) fn acquire(
    world: &mut World,
    actor: EntityId,
    target: &Position,
    name: &str,
    time: f64,
    events: &mut Vec<EventRecord>,
) {
    let mut fail = |message: String| {
        events.push(EventRecord::Error {
            time,
            element: name.to_owned(),
            message: format!("{message} (the route is not assigned)"),
        })
    };
    let to = match resolve(target, &*world) {
        Ok(r) => r.road_position,
        Err(e) => return fail(e.to_string()),
    };
    let from = world.entity(actor).road_position.clone();
    let (Some(from), Some(to)) = (from, to) else {
        return fail(format!(
            "expected the actor and the target on roads, found one off the road at {}",
            target.pos
        ));
    };
    let lane = |r: &opendrive::RoadPosition| LanePosition {
        road_id: r.road_id.clone(),
        lane_id: r.lane_id,
        s: r.s,
        offset: r.offset,
    };
    match plan_between(
        &world.network,
        &lane(&from),
        &lane(&to),
        RouteStrategy::Shortest,
        &options(world),
        &target.pos,
    ) {
        Ok(planned) => give(world, actor, planned),
        Err(e) => fail(e.to_string()),
    }
}

/// RandomRouteAction: plans a random route from the actor's lane and assigns it.
pub(crate) fn random(
    world: &mut World,
    actor: EntityId,
    pos: &SourcePos,
    name: &str,
    time: f64,
    events: &mut Vec<EventRecord>,
) {
    let e = world.entity(actor);
    let Some(rp) = e.road_position.clone() else {
        events.push(EventRecord::Error {
            time,
            element: name.to_owned(),
            message: format!(
                "expected entity '{}' on a road for a RandomRouteAction, found it off the road at {pos} (the route is not assigned)",
                e.name
            ),
        });
        return;
    };
    let from = LanePosition {
        road_id: rp.road_id,
        lane_id: rp.lane_id,
        s: rp.s,
        offset: rp.offset,
    };
    let entity = e.name.clone();
    match plan_random(&world.network, &entity, &from, &options(world), pos) {
        Ok(planned) => give(world, actor, planned),
        Err(e) => events.push(EventRecord::Error {
            time,
            element: name.to_owned(),
            message: format!("{e} (the route is not assigned)"),
        }),
    }
}
