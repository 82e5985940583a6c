//! The names a condition holds, resolved once (OpenSCENARIO 1.3 §7.6.3 "ByEntityCondition":
//! `TriggeringEntities/EntityRef@entityRef` and the EntityCondition's own `entityRef`s, an
//! XSD `EntityRef` naming a ScenarioObject or an EntitySelection, §7.2.2; the `Position` of
//! ReachPositionCondition, DistanceCondition and TimeToCollisionConditionTarget, §7.4;
//! oscsim's marks, condition/mark.rs).
//!
//! The runtime resolves every condition when it builds the storyboard (`runtime::build`): each
//! entity to its id in the world's store, each selection to its index among the scenario's
//! selections, each mark to its slot; evaluation then reads by id and never looks a name up. A
//! name the scenario does not declare is an error at the condition then (a load error), as an
//! undeclared `entityRef` of an action is (the XML reader refuses one already; a model built
//! by other means may hold one).
//!
//! A condition's position ([`PositionRef`]): one of the four entity-free forms (World, Road,
//! Lane, Geo) is resolved to its pose then, once (a place the road network does not have is a
//! load error at the Position element, as an action's RoadPosition or LanePosition is,
//! position/check.rs); one of the four relative forms keeps its entity's id (an undeclared
//! `entityRef` is a load error at the Position element, naming its XSD element) and is worked
//! out from where that entity stands at each evaluation. A RoutePosition or TrajectoryPosition
//! whose route's waypoints or trajectory's points are all entity-free (recursively) depends on
//! the scenario and the road network alone, the route planned with the run's seed
//! (`EngineConfig::seed`, routeStrategy `random`): FromRoadCoordinates, FromLaneCoordinates
//! and a TrajectoryPosition are resolved once, to their pose, like an entity-free form (a
//! route that cannot be planned, a waypoint off the network, a pathS or s outside the path, a
//! shape that cannot be drawn: a load error at the Position element or the waypoint's); for
//! FromCurrentEntity the route is planned once and the entity (its `entityRef` resolved to
//! its id, undeclared: a load error as for a relative form) is placed on that plan at each
//! evaluation. A route or trajectory with a waypoint or point relative to an entity is planned
//! at each evaluation from the names it holds, as an action's.
//!
//! The position is the same for every triggering entity (its reference is the position's own
//! `entityRef`, never the triggering entity), so an evaluation works it out once, for the first
//! triggering entity that needs it (condition/by_entity.rs).
//!
//! Entities that are not in the scene when the storyboard is built keep their ids all the
//! same: an entity an AddEntityAction adds later (§7.2.2.3, XSD `AddEntityAction`) and a
//! member of DSL random traffic created later are declared ScenarioObjects with an id from the
//! start, not placed until they enter (a condition on one before reads its "no placed entity"
//! error, as before). Spawned objects (§7.2.2.3: a traffic action's vehicles, named by the
//! engine when they appear) have no declared name a condition could hold (the XML reader
//! refuses an undeclared `entityRef`); a condition reaches them only through an
//! EntitySelection, whose members §7.2.2.2 takes as they are when it is used: a selection is
//! resolved to its index here and its members are read at each evaluation, by id. So no
//! reference is kept by name.

use opendrive::{Pose, RoadNetwork};
use scenario::{
    CollisionTarget, Condition, ConditionKind, EntityCondition, Position, SourcePos,
    TimeToCollisionTarget,
};
use std::sync::Arc;

use super::mark::MarkId;
use crate::position::{needs, plan_entity_free, resolve_entity_free, Needs, PositionError};
use crate::routing::{PlannedRoute, RoutingOptions};
use crate::world::EntityId;

/// Handle of an EntitySelection: its index among the scenario's selections, in declaration
/// order (a runtime's own numbering; `ConditionContext::selection_id`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SelectionId(pub u32);

/// A triggering entity reference, resolved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Triggering {
    /// A ScenarioObject.
    Entity(EntityId),
    /// An EntitySelection: its members at each evaluation (§7.2.2.2).
    Selection(SelectionId),
}

/// The names of one condition, resolved (module doc); empty for a ByValueCondition.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct ConditionRefs {
    /// Per `TriggeringEntities::entity_refs`, in order.
    pub triggering: Vec<Triggering>,
    /// The EntityCondition's reference entities, in the order of [`reference_names`].
    pub references: Vec<EntityId>,
    /// The mark a TraveledSinceMark or GapReachedSinceMark reads (`None`: none noted by
    /// that name, ever; or the condition reads none).
    pub mark: Option<MarkId>,
    /// The position of a ReachPosition or Distance condition, or TimeToCollision's Position
    /// target ([`condition_position`]); `None` when the condition holds none.
    pub position: Option<PositionRef>,
}

/// A condition's position (OpenSCENARIO 1.3 §7.4 `Position`), resolved as far as it can be
/// before the run: which form it is decides what is left for each evaluation.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum PositionRef {
    /// WorldPosition, RoadPosition, LanePosition, GeoPosition: they depend on the road
    /// network alone, so the pose is the same at every evaluation; resolved once.
    Fixed(Pose),
    /// RelativeWorldPosition, RelativeObjectPosition, RelativeRoadPosition,
    /// RelativeLanePosition: the entity of its `entityRef`, read by id at each evaluation,
    /// where it stands then.
    Relative(EntityId),
    /// RoutePosition FromCurrentEntity on a route whose waypoints are entity-free: the route
    /// planned once (shared, not copied, by the engine's clones of its tables), and the entity
    /// of `entityRef`, placed on it at each evaluation where it stands then.
    OnRoute(Arc<PlannedRoute>, EntityId),
    /// RoutePosition, TrajectoryPosition with a waypoint or point relative to an entity:
    /// planned at each evaluation from the positions and entity of the route or trajectory,
    /// which it reads by name (not resolved here).
    Planned,
}

/// What resolving reads: the runtime's world when it builds the storyboard, or a
/// `ConditionContext` (the `evaluate` front door).
pub(crate) trait Names {
    /// The id of the declared entity `name`.
    fn entity(&self, name: &str) -> Option<EntityId>;
    /// The handle of EntitySelection `name`.
    fn selection(&self, name: &str) -> Option<SelectionId>;
    /// The slot of mark `name` (`None`: no mark by that name can be noted).
    fn mark(&mut self, name: &str) -> Option<MarkId>;
    /// The road network the scenario runs on (a condition's entity-free position is resolved
    /// on it).
    fn network(&self) -> &RoadNetwork;
    /// The settings the run plans routes with (its seed for routeStrategy `random`): an
    /// entity-free route is planned with them once.
    fn routing_options(&self) -> RoutingOptions;
}

/// Why a condition's references do not resolve.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum RefError {
    /// A name that names nothing declared.
    Unresolved(Unresolved),
    /// An entity-free position the road network does not have (an unknown road or lane, an s
    /// past a road's end with nothing connected, a GeoPosition without a georeference), with
    /// the position's own place in the file.
    Position(PositionError),
}

/// A name that names nothing declared: the XSD element and attribute it stands in, and the
/// name.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Unresolved {
    /// E.g. `RelativeDistanceCondition@entityRef`.
    pub element: &'static str,
    /// The name written.
    pub name: String,
    /// Where the name is written when that is not the Condition element itself: the
    /// Position element of a relative position.
    pub at: Option<SourcePos>,
}

/// The position `condition` holds: ReachPositionCondition's and DistanceCondition's
/// `Position`, TimeToCollisionConditionTarget's `Position`.
pub(crate) fn condition_position(condition: &EntityCondition) -> Option<&Position> {
    match condition {
        EntityCondition::ReachPosition { position, .. }
        | EntityCondition::Distance { position, .. } => Some(position),
        EntityCondition::TimeToCollision {
            target: TimeToCollisionTarget::Position(p),
            ..
        } => Some(p),
        _ => None,
    }
}

/// `position` resolved as far as the run allows ([`PositionRef`]): an entity-free form to
/// its pose on `names`' network, a relative one to its entity's id, a FromCurrentEntity on an
/// entity-free route to the route's plan and the entity's id.
fn position_ref(position: &Position, names: &dyn Names) -> Result<PositionRef, RefError> {
    let undeclared = |name: &str, element| {
        RefError::Unresolved(Unresolved {
            element,
            name: name.to_owned(),
            at: Some(position.pos.clone()),
        })
    };
    match needs(position) {
        Needs::Nothing => resolve_entity_free(position, names.network(), names.routing_options())
            .map(|r| PositionRef::Fixed(r.pose))
            .map_err(RefError::Position),
        Needs::Entity(name, element) => names
            .entity(name)
            .map(PositionRef::Relative)
            .ok_or_else(|| undeclared(name, element)),
        Needs::OnRoute(route, name) => {
            let id = names
                .entity(name)
                .ok_or_else(|| undeclared(name, "FromCurrentEntity@entityRef"))?;
            let planned = plan_entity_free(
                route,
                names.network(),
                names.routing_options(),
                &position.pos,
            )
            .map_err(RefError::Position)?;
            Ok(PositionRef::OnRoute(Arc::new(planned), id))
        }
        Needs::Plan => Ok(PositionRef::Planned),
    }
}

/// The entity references of `condition`'s EntityCondition besides the triggering entities,
/// each with the XSD element and attribute it is written in.
pub(crate) fn reference_names(condition: &EntityCondition) -> Vec<(&str, &'static str)> {
    match condition {
        EntityCondition::Collision(CollisionTarget::EntityRef(n)) => {
            vec![(n.as_str(), "CollisionCondition/EntityRef@entityRef")]
        }
        EntityCondition::TimeHeadway { entity_ref, .. } => {
            vec![(entity_ref.as_str(), "TimeHeadwayCondition@entityRef")]
        }
        EntityCondition::TimeToCollision {
            target: TimeToCollisionTarget::EntityRef(n),
            ..
        } => vec![(
            n.as_str(),
            "TimeToCollisionConditionTarget/EntityRef@entityRef",
        )],
        EntityCondition::RelativeSpeed { entity_ref, .. } => {
            vec![(entity_ref.as_str(), "RelativeSpeedCondition@entityRef")]
        }
        EntityCondition::RelativeDistance { entity_ref, .. } => {
            vec![(entity_ref.as_str(), "RelativeDistanceCondition@entityRef")]
        }
        EntityCondition::RelativeClearance { entity_refs, .. } => entity_refs
            .iter()
            .map(|n| (n.as_str(), "RelativeClearanceCondition/EntityRef@entityRef"))
            .collect(),
        EntityCondition::RelativeAngle { entity_ref, .. } => {
            vec![(entity_ref.as_str(), "RelativeAngleCondition@entityRef")]
        }
        EntityCondition::GapReachedSinceMark { gap, .. } => {
            vec![(
                gap.entity_ref.as_str(),
                "GapReachedSinceMark's gap (no XML form)",
            )]
        }
        _ => Vec::new(),
    }
}

impl ConditionRefs {
    /// The names of `condition` resolved through `names`, and its position as far as it can
    /// be; the first that names nothing declared, or a position the road network does not
    /// have, is the error.
    pub(crate) fn resolve(condition: &Condition, names: &mut dyn Names) -> Result<Self, RefError> {
        let ConditionKind::ByEntity {
            triggering_entities,
            entity_condition,
        } = &condition.kind
        else {
            return Ok(Self::default());
        };
        let unresolved = |element, name: &str| {
            RefError::Unresolved(Unresolved {
                element,
                name: name.to_owned(),
                at: None,
            })
        };
        let triggering = triggering_entities
            .entity_refs
            .iter()
            .map(|n| match names.entity(n) {
                Some(id) => Ok(Triggering::Entity(id)),
                None => names
                    .selection(n)
                    .map(Triggering::Selection)
                    .ok_or_else(|| unresolved("TriggeringEntities/EntityRef@entityRef", n)),
            })
            .collect::<Result<Vec<_>, _>>()?;
        let references = reference_names(entity_condition)
            .into_iter()
            .map(|(n, element)| names.entity(n).ok_or_else(|| unresolved(element, n)))
            .collect::<Result<Vec<_>, _>>()?;
        let mark = match entity_condition {
            EntityCondition::TraveledSinceMark { mark, .. }
            | EntityCondition::GapReachedSinceMark { mark, .. } => names.mark(mark),
            _ => None,
        };
        let position = condition_position(entity_condition)
            .map(|p| position_ref(p, names))
            .transpose()?;
        Ok(Self {
            triggering,
            references,
            mark,
            position,
        })
    }
}
