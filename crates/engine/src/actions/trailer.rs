//! ConnectTrailerAction and DisconnectTrailerAction (OpenSCENARIO 1.3 §7.2.2.6 "Trailer
//! modeling", XSD `TrailerAction`): the actor starts or stops towing. Instantaneous; the
//! kinematics live in `store/trailer.rs`.
//!
//! A disconnected trailer has no drive of its own: it stops where it stands (speed 0) and is
//! left to the default controller.

use scenario::{SourcePos, TrailerAction};

use crate::error::Error;
use crate::store::World;
use crate::world::entity::EntityId;

/// Applies `action` to the tow vehicle `actor`. Errors name `pos`: an unknown trailer, a
/// vehicle without hitch or coupler, a second trailer, a cycle.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    action: &TrailerAction,
    pos: &SourcePos,
) -> Result<(), Error> {
    match action {
        TrailerAction::Connect { trailer_ref } => {
            let trailer = world.id(trailer_ref).ok_or_else(|| {
                Error::at(
                    "a declared entity",
                    format!("trailerRef '{trailer_ref}'"),
                    pos,
                )
            })?;
            let names = world
                .entities()
                .iter()
                .map(|e| e.name.clone())
                .collect::<Vec<_>>();
            let name = |id: EntityId| names[id.index()].clone();
            world.trailers.connect(&name, actor, trailer, false, pos)
        }
        _ => {
            if let Some(trailer) = world.trailers.trailer_of(actor) {
                world.trailers.disconnect(actor);
                world.entity_mut(actor).trailer = None;
                let e = world.entity_mut(trailer);
                e.speed = 0.0;
                e.longitudinal_action = None;
            }
            Ok(())
        }
    }
}
