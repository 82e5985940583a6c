//! TeleportAction (OpenSCENARIO 1.3 §7.7.2.4, XSD `TeleportAction`): put the actor at a
//! position at once. Takes no control domain.
//!
//! The position (any of the ten forms of §7.4) is resolved by [`crate::position::resolve`] to
//! a world pose and a road position; the world then places the entity there and, when it
//! stands on a lane along the lane's direction of travel, hands that lane to the default
//! controller.

use scenario::Position;

use crate::position::resolve;
use crate::runtime::entity::EntityId;
use crate::runtime::error::{RuntimeError, RuntimeErrorKind};
use crate::runtime::world::World;

/// Teleports `actor` to `position`.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    position: &Position,
) -> Result<(), RuntimeError> {
    let resolved =
        resolve(position, &*world).map_err(|e| RuntimeError::new(RuntimeErrorKind::Position(e)))?;
    world.place_resolved(actor, resolved.pose, resolved.road_position);
    Ok(())
}
