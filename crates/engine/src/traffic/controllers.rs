//! Controllers of spawned vehicles (OpenSCENARIO 1.3 §7.2.2.3 spawned objects; XSD
//! `TrafficDefinition/ControllerDistribution`, `TrafficDistributionEntry/EntityDistribution`
//! templates with ObjectControllers).
//!
//! A spawned vehicle has no Init that could activate a controller, so the controller it gets
//! is assigned and activated at once on every motion domain it is defined for. Which one: a
//! draw from the TrafficDefinition's ControllerDistribution by weight; else the
//! ObjectControllers of the EntityDistribution template it was made from; else the run option
//! [`EngineConfig::traffic_model`](crate::EngineConfig::traffic_model) (`idm` or `mobil` with
//! the models' default parameters); else none (the default controller). The draw uses a
//! stream of its own per vehicle (the run's seed, stream keyed by the vehicle's name and
//! "/controller"), so the positions, speeds and templates drawn are those of a run without
//! controllers.
//!
//! The run option [`EngineConfig::vehicle_model`](crate::EngineConfig::vehicle_model) gives
//! the same controller to the scenario's own vehicles that have no ObjectController, when the
//! engine is built ([`equip_scenario_vehicles`]): assigned and activated before the Init, so
//! that the Init's SpeedAction sets the speed and the desired speed (engine module
//! `controller`).

use scenario::{Controller, ControllerDomains, ObjectController, Properties, TrafficMix};

use super::random::{stream, weighted};
use super::spawning::Tables;
use crate::controller::{assign, ControllerTable, Origin, TrafficModel};
use crate::error::Error;
use crate::output::EventRecord;
use crate::store::World;
use crate::world::entity::{EntityId, EntityKind};

/// Every domain a controller is defined for.
const ALL: ControllerDomains = ControllerDomains {
    longitudinal: Some(true),
    lateral: Some(true),
    animation: None,
    lighting: None,
};

/// The controller of a run option, named `prefix` and the model (`option`: the option's name,
/// as the source of the controller).
fn option_controller(model: TrafficModel, prefix: &str, option: &str) -> Controller {
    let name = match model {
        TrafficModel::Idm => "idm",
        TrafficModel::Mobil => "mobil",
    };
    Controller {
        name: format!("{prefix} {name}"),
        controller_type: None,
        properties: Properties {
            properties: vec![("model".to_owned(), name.to_owned())],
            ..Properties::default()
        },
        catalog: None,
        pos: scenario::SourcePos::start_of(std::sync::Arc::from(std::path::Path::new(option))),
    }
}

/// Gives the vehicle `id`, just spawned by traffic action `element` from `mix` (template ObjectControllers `templates`), its controller (module doc).
pub(crate) fn equip(
    world: &mut World,
    tables: &mut Tables<'_>,
    id: EntityId,
    mix: &TrafficMix,
    templates: &[ObjectController],
    element: &str,
) -> Result<(), Error> {
    let distribution = mix
        .definition
        .as_ref()
        .map_or(&[][..], |d| &d.controllers[..]);
    let chosen: Vec<(Controller, Option<String>)> = if !distribution.is_empty() {
        let name = format!("{}/controller", world.entity(id).name);
        let mut rng = stream(world.seed, &name);
        weighted(&mut rng, distribution.iter().map(|(_, w)| *w))
            .map(|i| (distribution[i].0.clone(), None))
            .into_iter()
            .collect()
    } else if !templates.is_empty() {
        templates
            .iter()
            .map(|oc| (oc.controller.clone(), oc.name.clone()))
            .collect()
    } else if let Some(model) = tables.spawning.model {
        vec![(
            option_controller(model, "traffic", "run option traffic_model"),
            None,
        )]
    } else {
        Vec::new()
    };
    let time = world.time;
    let mut events = Vec::new();
    for (controller, object) in &chosen {
        let origin = Origin {
            element,
            time,
            pos: &controller.pos,
        };
        assign(
            world,
            tables.controllers,
            id,
            controller,
            object.as_deref(),
            &ALL,
            &origin,
            &mut events,
        )?;
    }
    tables.spawning.events.append(&mut events);
    Ok(())
}

/// Gives every vehicle of the scenario without a controller of its own (no ObjectController)
/// the controller of run option `vehicle_model`, assigned and activated on every domain it is
/// defined for; the records go to `events`.
pub(crate) fn equip_scenario_vehicles(
    world: &mut World,
    controllers: &mut ControllerTable,
    model: TrafficModel,
    events: &mut Vec<EventRecord>,
) -> Result<(), Error> {
    let controller = option_controller(model, "vehicle", "run option vehicle_model");
    let bare: Vec<EntityId> = world
        .entities()
        .iter()
        .filter(|e| e.kind == EntityKind::Vehicle)
        .filter(|e| {
            controllers
                .of(e.id.index())
                .is_none_or(|c| c.assigned.is_empty())
        })
        .map(|e| e.id)
        .collect();
    for id in bare {
        let origin = Origin {
            element: "run option vehicle_model",
            time: 0.0,
            pos: &controller.pos,
        };
        assign(
            world,
            controllers,
            id,
            &controller,
            None,
            &ALL,
            &origin,
            events,
        )?;
    }
    Ok(())
}
