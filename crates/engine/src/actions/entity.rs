//! AddEntityAction and DeleteEntityAction (OpenSCENARIO 1.3 XSD `EntityAction`): a declared
//! entity enters the scenario at a position, or leaves it. Instantaneous.
//!
//! A deleted entity keeps its id and name but is not placed: it leaves the frames (CSV, OSI)
//! and the ByType selections, and an EntityCondition naming it cannot be evaluated, so it reads
//! false and is logged once (runtime/conditions.rs) until the entity is added again. Adding an
//! entity that is in the scenario moves it there (as a TeleportAction); it enters at rest,
//! with no action running on it.
//!
//! The position of an AddEntityAction may be relative to the entity being added (esmini's
//! add_delete_entity test re-adds a deleted car 'relative to itself'). The standard gives a
//! deleted entity no position, and says nothing of this case; the position an entity had when
//! it left is the only one such a reference can mean, so the position is resolved with the
//! entity where it left (its pose, and the road position found there). An entity that was
//! never in the scenario has no such place: a reference to it stays an error.

use opendrive::{RoadNetwork, RoadPosition};
use scenario::{Position, SourcePos};

use crate::error::{Error, ErrorKind};
use crate::position::{resolve, EntityQuery, EntityView};
use crate::routing::RoutingOptions;
use crate::store::World;
use crate::traffic::leave;
use crate::world::entity::EntityId;

/// Adds `entity_ref` at `add_at`, or deletes it when `add_at` is `None`.
pub(crate) fn apply(
    world: &mut World,
    entity_ref: &str,
    add_at: Option<&Position>,
    pos: &SourcePos,
) -> Result<(), Error> {
    let id = world.id(entity_ref).ok_or_else(|| {
        Error::at(
            "a declared entity",
            format!("entityRef '{entity_ref}'"),
            pos,
        )
    })?;
    match add_at {
        Some(position) => {
            if !world.entity(id).placed {
                let e = world.entity_mut(id);
                e.speed = 0.0;
                e.longitudinal_action = None;
                e.lateral_action = None;
            }
            let e = world.entity(id);
            let returning = (!e.placed && e.departed).then(|| {
                let at = world.network.locate(e.pose.x, e.pose.y, Some(e.pose.h));
                (id, at)
            });
            let query = Readmitting {
                world: &*world,
                returning,
            };
            let resolved =
                resolve(position, &query).map_err(|e| Error::new(ErrorKind::Position(e)))?;
            world.place_resolved(id, resolved.pose, resolved.road_position);
            Ok(())
        }
        None => {
            leave(world, id);
            Ok(())
        }
    }
}

/// The world as a position sees it from an AddEntityAction: with the entity being added back
/// (`returning`) where it left, at the road position found there.
struct Readmitting<'a> {
    world: &'a World,
    returning: Option<(EntityId, Option<RoadPosition>)>,
}

impl EntityQuery for Readmitting<'_> {
    fn entity(&self, name: &str) -> Option<EntityView<'_>> {
        match &self.returning {
            Some((id, at)) if self.world.id(name) == Some(*id) => {
                let e = self.world.entity(*id);
                Some(EntityView {
                    road_position: at.as_ref(),
                    ..self.world.view(e)
                })
            }
            _ => EntityQuery::entity(self.world, name),
        }
    }

    fn entities(&self) -> Box<dyn Iterator<Item = EntityView<'_>> + '_> {
        EntityQuery::entities(self.world)
    }

    fn road_network(&self) -> &RoadNetwork {
        &self.world.network
    }

    fn routing_options(&self) -> RoutingOptions {
        EntityQuery::routing_options(self.world)
    }
}
