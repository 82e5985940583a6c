//! AssignControllerAction, ActivateControllerAction and ObjectControllers at runtime
//! (OpenSCENARIO 1.3 §7.7.2.5 "ControllerAction"; the rules are in module `table`). Every
//! change is written to the event log as an [`EventRecord::Controller`] with the controller's
//! active domains after it.

use scenario::{ControllerDomains, SourcePos};

use super::properties::{classify, ControllerKind};
use super::table::{requested, Assigned, ControllerTable};
use super::view::ControllerView;
use crate::error::Error;
use crate::output::EventRecord;
use crate::store::driver_inputs::DriverInput;
use crate::store::lane_index::LaneIndex;
use crate::store::World;
use crate::world::ActiveDomains;
use crate::world::EntityId;

/// Where a change comes from, for the log.
pub(crate) struct Origin<'a> {
    /// The action (or "ObjectController").
    pub element: &'a str,
    /// Simulation time (s).
    pub time: f64,
    /// Its place in the file.
    pub pos: &'a SourcePos,
}

/// The motion domains a change gave to a built-in model: the actions running there lose them.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Taken {
    /// The longitudinal domain.
    pub longitudinal: bool,
    /// The lateral domain.
    pub lateral: bool,
}

fn record(
    world: &World,
    controllers: &ControllerTable,
    actor: EntityId,
    slot: usize,
    origin: &Origin<'_>,
    note: String,
    events: &mut Vec<EventRecord>,
) {
    let Some(a) = controllers
        .of(actor.index())
        .and_then(|c| c.assigned.get(slot))
    else {
        return;
    };
    events.push(EventRecord::Controller {
        time: origin.time,
        element: origin.element.to_owned(),
        entity: world.entity(actor).name.clone(),
        controller: a.name.clone(),
        model: a.model_name(),
        active: a.active,
        note,
    });
}

/// Assigns `controller` to `actor` (as ObjectController `object`, if named) and activates the
/// domains `activate` sets true.
#[allow(clippy::too_many_arguments)] // the world, the stage's table, the XSD attributes, origin, log.
pub(crate) fn assign(
    world: &mut World,
    controllers: &mut ControllerTable,
    actor: EntityId,
    controller: &scenario::Controller,
    object: Option<&str>,
    activate: &ControllerDomains,
    origin: &Origin<'_>,
    events: &mut Vec<EventRecord>,
) -> Result<Taken, Error> {
    let kind = classify(controller)?;
    let instance = match &kind {
        ControllerKind::Model { settings, .. } => Some(controllers.instantiate(settings)),
        _ => None,
    };
    let note = match &kind {
        ControllerKind::Foreign { what } => format!(
            "assigned; {what} is not an oscsim controller model: the default controller keeps its domains"
        ),
        _ => "assigned".to_owned(),
    };
    let assigned = Assigned {
        name: controller.name.clone(),
        object_controller: object.map(str::to_owned),
        kind,
        active: ActiveDomains::default(),
        instance,
    };
    let before = controllers.held_by(actor.index());
    let list = &mut controllers.of_mut(actor.index()).assigned;
    let same = |a: &Assigned| match (object, &a.object_controller) {
        (Some(o), Some(p)) => o == p,
        (None, None) => a.name == controller.name,
        _ => false,
    };
    let slot = match list.iter().position(same) {
        Some(i) => {
            let old = std::mem::replace(&mut list[i], assigned);
            controllers.release(old);
            i
        }
        None => {
            list.push(assigned);
            list.len() - 1
        }
    };
    controllers.recount_entity(actor.index(), before);
    record(world, controllers, actor, slot, origin, note, events);
    let switch_on = ControllerDomains {
        longitudinal: activate.longitudinal.filter(|on| *on),
        lateral: activate.lateral.filter(|on| *on),
        lighting: activate.lighting.filter(|on| *on),
        animation: activate.animation.filter(|on| *on),
    };
    if requested(&switch_on).iter().any(Option::is_some) {
        return Ok(set_domains(
            world,
            controllers,
            actor,
            slot,
            &switch_on,
            origin,
            None,
            events,
        ));
    }
    Ok(Taken::default())
}

/// Activates or deactivates the domains `domains` names on the controller of `actor` that
/// `object_ref` names (module `table` for the choice without one). No user controller
/// assigned: the default controller is meant, which always runs; nothing changes.
pub(crate) fn activate(
    world: &mut World,
    controllers: &mut ControllerTable,
    actor: EntityId,
    object_ref: Option<&str>,
    domains: &ControllerDomains,
    origin: &Origin<'_>,
    events: &mut Vec<EventRecord>,
) -> Result<Taken, Error> {
    let list = controllers
        .of(actor.index())
        .map_or(&[][..], |c| &c.assigned[..]);
    let (slot, note) = match object_ref {
        Some(name) => {
            let found = list
                .iter()
                .rposition(|a| a.object_controller.as_deref() == Some(name))
                .or_else(|| list.iter().rposition(|a| a.name == name));
            let Some(i) = found else {
                let names: Vec<String> = list
                    .iter()
                    .map(|a| {
                        a.object_controller
                            .clone()
                            .unwrap_or_else(|| a.name.clone())
                    })
                    .collect();
                return Err(Error::at(
                    format!(
                        "a controller assigned to '{}' ({})",
                        world.entity(actor).name,
                        if names.is_empty() {
                            "none is".to_owned()
                        } else {
                            names.join(", ")
                        }
                    ),
                    format!("objectControllerRef '{name}'"),
                    origin.pos,
                ));
            };
            (i, None)
        }
        None if list.is_empty() => return Ok(Taken::default()),
        None if list.len() == 1 => (0, None),
        None => (
            list.len() - 1,
            Some("no objectControllerRef with several controllers: the last assigned"),
        ),
    };
    Ok(set_domains(
        world,
        controllers,
        actor,
        slot,
        domains,
        origin,
        note,
        events,
    ))
}

/// Applies `domains` to controller `slot` of `actor`.
#[allow(clippy::too_many_arguments)] // the world, the stage's table, the XSD attributes, origin, log.
fn set_domains(
    world: &mut World,
    controllers: &mut ControllerTable,
    actor: EntityId,
    slot: usize,
    domains: &ControllerDomains,
    origin: &Origin<'_>,
    note: Option<&str>,
    events: &mut Vec<EventRecord>,
) -> Taken {
    let mut taken = Taken::default();
    let mut notes: Vec<String> = note.map(str::to_owned).into_iter().collect();
    let mut gave_back_lateral = false;
    let before = controllers.held_by(actor.index());
    {
        let ctrl = controllers.of_mut(actor.index());
        let defined = ctrl.assigned[slot].defined();
        let is_model = ctrl.assigned[slot].instance.is_some();
        let [lon, lat, light, anim] = requested(domains);
        for (which, on) in [(true, lon), (false, lat)] {
            let Some(on) = on else { continue };
            let name = if which { "longitudinal" } else { "lateral" };
            let allowed = if which {
                defined.longitudinal
            } else {
                defined.lateral
            };
            if on && is_model && !allowed {
                notes.push(format!(
                    "{name} is not a domain of this controller: not activated"
                ));
                continue;
            }
            if on && is_model {
                // The last activation wins: other controllers lose the domain.
                for (i, other) in ctrl.assigned.iter_mut().enumerate() {
                    if i != slot {
                        if which {
                            other.active.longitudinal = false;
                        } else {
                            other.active.lateral = false;
                        }
                    }
                }
            }
            let a = &mut ctrl.assigned[slot];
            let was = if which {
                std::mem::replace(&mut a.active.longitudinal, on)
            } else {
                std::mem::replace(&mut a.active.lateral, on)
            };
            if is_model && on && !was {
                if which {
                    taken.longitudinal = true;
                } else {
                    taken.lateral = true;
                }
            }
            if is_model && !on && was && !which {
                gave_back_lateral = true;
            }
        }
        let a = &mut ctrl.assigned[slot];
        if let Some(on) = light {
            a.active.lighting = on;
        }
        if let Some(on) = anim {
            a.active.animation = on;
        }
    }
    controllers.recount_entity(actor.index(), before);
    if gave_back_lateral {
        hand_back_lateral(world, controllers, actor);
    }
    if taken.longitudinal || taken.lateral {
        let index = LaneIndex::default();
        let (entities, network) = (world.entities(), &world.network);
        let entity = &entities[actor.index()];
        let input = DriverInput::of(entity, network);
        let view = ControllerView::new(
            origin.time,
            entity,
            &input,
            entities,
            network,
            &index,
            None,
            &world.signals,
        );
        if let Some(instance) = controllers.instance_mut(actor.index(), slot) {
            instance.activate(&view);
        }
    }
    if let Some(ControllerKind::Foreign { what }) = controllers
        .of(actor.index())
        .map(|c| &c.assigned[slot].kind)
    {
        notes.push(format!(
            "{what} is not an oscsim controller model: the default controller keeps its domains"
        ));
    }
    let what = if notes.is_empty() {
        "activation changed".to_owned()
    } else {
        format!("activation changed; {}", notes.join("; "))
    };
    record(world, controllers, actor, slot, origin, what, events);
    taken
}

/// The lateral domain goes back to the default controller: a controller's lane change in
/// progress stops where the entity is, an entity steered off its lane takes the lane it is on,
/// keeping its offset (§7.2.2.1: the default controller keeps the lane offset).
pub(crate) fn hand_back_lateral(
    world: &mut World,
    controllers: &mut ControllerTable,
    actor: EntityId,
) {
    let ctrl = controllers.of_mut(actor.index());
    let steered = std::mem::take(&mut ctrl.steered);
    let changing = ctrl.lane_change.take().is_some();
    if changing {
        world.keep_lateral_position(actor);
    }
    if steered {
        world.release_to_road(actor, false);
    }
}
