//! VisibilityAction (OpenSCENARIO 1.3 §7.7.2.3, XSD `VisibilityAction`): whether the actor is
//! seen by image generators, sensors and other traffic. Instantaneous.

use scenario::VisibilityAction;

use crate::runtime::entity::{EntityId, Visibility};
use crate::runtime::world::World;

/// Applies the flags.
pub(crate) fn start(world: &mut World, actor: EntityId, action: &VisibilityAction) {
    world.entity_mut(actor).visibility = Visibility {
        graphics: action.graphics,
        sensors: action.sensors,
        traffic: action.traffic,
    };
}
