//! Positions that depend on no entity (RoadPosition, LanePosition) resolved at load, so that a
//! scenario naming a place the road network does not have (an s past a road's end with
//! nothing connected, an unknown road or lane) is refused with the position's file, line and
//! column before it runs, not when the action that holds it starts (issue 16 class 2; module
//! `beyond`). Looked at: the Init actions and every Event's actions — TeleportAction,
//! AcquirePositionAction, SynchronizeAction's two targets and AddEntityAction. Positions
//! relative to an entity depend on where it is when they are needed and are resolved then.
//! A condition's entity-free position (of any of the four entity-free forms, or a
//! RoutePosition or TrajectoryPosition whose waypoints or points are all entity-free) is
//! resolved once through [`resolve_entity_free`] when the storyboard is built, and the route of
//! a RoutePosition FromCurrentEntity whose waypoints are planned once through
//! [`plan_entity_free`] (condition/refs.rs).

use opendrive::RoadNetwork;
use scenario::{
    Action, ActionKind, GlobalAction, Position, PositionKind, PrivateAction, Route, RoutingAction,
    Scenario, SourcePos,
};

use crate::routing::{plan_route, PlannedRoute, RoutingOptions};

use super::{resolve, EntityQuery, EntityView, PositionError, ResolvedPosition};

/// Resolves every entity-free position of `scenario`'s actions on `network`; the first that
/// does not resolve, in document order.
pub fn check_positions(scenario: &Scenario, network: &RoadNetwork) -> Result<(), PositionError> {
    let query = NoEntities(network, RoutingOptions::default());
    let sb = &scenario.storyboard;
    let init = sb.init.actions.iter();
    let privates = sb.init.privates.iter().flat_map(|p| p.actions.iter());
    let events = sb
        .stories
        .iter()
        .flat_map(|s| &s.acts)
        .flat_map(|a| &a.maneuver_groups)
        .flat_map(|g| &g.maneuvers)
        .flat_map(|m| &m.events)
        .flat_map(|e| &e.actions);
    for action in init.chain(privates).chain(events) {
        for position in positions(action) {
            if matches!(
                position.kind,
                PositionKind::Road { .. } | PositionKind::Lane { .. }
            ) {
                resolve(position, &query)?;
            }
        }
    }
    Ok(())
}

/// Resolves a position that depends on no entity (`resolve::Needs::Nothing`: WorldPosition,
/// RoadPosition, LanePosition, GeoPosition, a RoutePosition or TrajectoryPosition whose
/// waypoints or points are such) on `network` alone, a route planned with `options` (the
/// run's seed for routeStrategy `random`): what a condition's position of such a form is
/// resolved to once, when the storyboard is built (condition/refs.rs).
pub(crate) fn resolve_entity_free(
    position: &Position,
    network: &RoadNetwork,
    options: RoutingOptions,
) -> Result<ResolvedPosition, PositionError> {
    resolve(position, &NoEntities(network, options))
}

/// Plans `route`, whose waypoints depend on no entity, on `network` with `options`, as
/// [`resolve`] plans a RoutePosition's route (`pos`: the element that uses it): the plan a
/// condition's RoutePosition FromCurrentEntity measures on, made once (condition/refs.rs).
pub(crate) fn plan_entity_free(
    route: &Route,
    network: &RoadNetwork,
    options: RoutingOptions,
    pos: &SourcePos,
) -> Result<PlannedRoute, PositionError> {
    plan_route(route, &NoEntities(network, options), &options, pos)
}

/// The positions an action names directly.
fn positions(action: &Action) -> Vec<&Position> {
    match &action.kind {
        ActionKind::Private(PrivateAction::Teleport(p)) => vec![p],
        ActionKind::Private(PrivateAction::Routing(r)) => match r.as_ref() {
            RoutingAction::AcquirePosition(p) => vec![p],
            _ => Vec::new(),
        },
        ActionKind::Private(PrivateAction::Synchronize(s)) => {
            vec![&s.target_position_master, &s.target_position]
        }
        ActionKind::Global(GlobalAction::Entity {
            add_at: Some(p), ..
        }) => vec![p],
        _ => Vec::new(),
    }
}

/// A world without entities, with the routing options routes are planned with: what an
/// entity-free position needs.
struct NoEntities<'a>(&'a RoadNetwork, RoutingOptions);

impl EntityQuery for NoEntities<'_> {
    fn entity(&self, _: &str) -> Option<EntityView<'_>> {
        None
    }

    fn entities(&self) -> Box<dyn Iterator<Item = EntityView<'_>> + '_> {
        Box::new(std::iter::empty())
    }

    fn road_network(&self) -> &RoadNetwork {
        self.0
    }

    fn routing_options(&self) -> RoutingOptions {
        self.1
    }
}
