//! TeleportAction (OpenSCENARIO 1.3 §7.7.2.4, XSD `TeleportAction`): put the actor at a
//! position at once. Takes no control domain.
//!
//! The position (any of the ten forms of §7.4) is resolved by [`crate::position::resolve`] to
//! a world pose and a road position; the world then places the entity there and, when it
//! stands on a lane along the lane's direction of travel, hands that lane to the default
//! controller.
//!
//! A TeleportAction of a Story places the entity at the end of its step: the step's frame shows
//! the target position itself, and the motion goes on from there in the next step (the default
//! controller does not also move the entity over the step in which it was put there). So the
//! position the scenario names appears in the trajectory output, and esmini's reference runs
//! show the same (lane_change_simple: teleported at 145.55 s, at s = 10 in the frame of
//! 145.60 s, 12.5 m at 145.70 s at 25 m/s). Init teleports define the state at t = 0 (§8.5.1),
//! the first frame, from which the first step moves as usual.

use scenario::Position;

use crate::error::{Error, ErrorKind};
use crate::position::resolve;
use crate::store::World;
use crate::world::entity::EntityId;

/// Teleports `actor` to `position`; `story`: started by a Story (not in Init), so the entity
/// stays at the target over this step.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    position: &Position,
    story: bool,
) -> Result<(), Error> {
    let resolved = resolve(position, &*world).map_err(|e| Error::new(ErrorKind::Position(e)))?;
    world.place_resolved(actor, resolved.pose, resolved.road_position);
    if story {
        world.entity_mut(actor).held = true;
    }
    Ok(())
}
