//! AddEntityAction and DeleteEntityAction (OpenSCENARIO 1.3 XSD `EntityAction`): a declared
//! entity enters the scenario at a position, or leaves it. Instantaneous.
//!
//! A deleted entity keeps its id and name but is not placed: it leaves the frames (CSV, OSI)
//! and the ByType selections, and an EntityCondition naming it cannot be evaluated, so it reads
//! false and is logged once (runtime/conditions.rs) until the entity is added again. Adding an
//! entity that is in the scenario moves it there (as a TeleportAction); it enters at rest,
//! with no action running on it.

use scenario::{Position, SourcePos};

use super::teleport;
use crate::runtime::error::RuntimeError;
use crate::runtime::world::World;
use crate::traffic::leave;

/// Adds `entity_ref` at `add_at`, or deletes it when `add_at` is `None`.
pub(crate) fn apply(
    world: &mut World,
    entity_ref: &str,
    add_at: Option<&Position>,
    pos: &SourcePos,
) -> Result<(), RuntimeError> {
    let id = world.id(entity_ref).ok_or_else(|| {
        RuntimeError::at(
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
            teleport::start(world, id, position, false)
        }
        None => {
            leave(world, id);
            Ok(())
        }
    }
}
