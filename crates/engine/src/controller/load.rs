//! Controllers when the engine is built: every `Controller` of the scenario is read
//! (`properties`), so an unknown `model`, an unknown property or a bad value is a load
//! error at its `Property` element, wherever the controller is written: an entity's
//! ObjectController, an AssignControllerAction, a traffic action's ControllerDistribution or
//! its entity templates' ObjectControllers. The entities' own ObjectControllers are assigned,
//! deactivated (OpenSCENARIO 1.3 §6.6: "by default, controllers are assigned in a deactivated
//! state"); the assignment is not logged (a later activation is).

use scenario::{
    ActionKind, ControllerAction, ControllerDomains, GlobalAction, PrivateAction, Scenario,
    TrafficAction, TrafficMix,
};

use super::assign::{assign, Origin};
use super::properties::classify;
use super::table::ControllerTable;
use crate::error::Error;
use crate::store::World;
use crate::world::EntityId;

/// The controllers a traffic mix can give its vehicles: the ControllerDistribution and the
/// ObjectControllers of the distribution's templates.
pub(crate) fn traffic_controllers(mix: &TrafficMix) -> impl Iterator<Item = &scenario::Controller> {
    let distributed = mix
        .definition
        .iter()
        .flat_map(|d| d.controllers.iter().map(|(c, _)| c));
    let templates = mix.distribution.iter().flat_map(|entry| {
        entry
            .entities
            .iter()
            .flat_map(|(o, _)| o.object_controllers.iter().map(|oc| &oc.controller))
    });
    distributed.chain(templates)
}

fn mix(action: &TrafficAction) -> Option<&TrafficMix> {
    match action {
        TrafficAction::Source { traffic, .. }
        | TrafficAction::Sink { traffic, .. }
        | TrafficAction::Swarm { traffic, .. } => Some(traffic),
        _ => None,
    }
}

/// Reads every controller of the scenario and assigns the entities' ObjectControllers (module
/// doc): the table of user controllers the controllers stage receives. `actions` are the
/// storyboard's actions (Init and Stories).
pub(crate) fn set_up<'a>(
    scenario: &Scenario,
    world: &mut World,
    actions: impl Iterator<Item = &'a scenario::Action>,
) -> Result<ControllerTable, Error> {
    for action in actions {
        match &action.kind {
            ActionKind::Private(PrivateAction::Controller(c)) => {
                if let ControllerAction::Assign { controller, .. } = &**c {
                    classify(controller)?;
                }
            }
            ActionKind::Global(GlobalAction::Traffic { action, .. }) => {
                for c in mix(action).into_iter().flat_map(traffic_controllers) {
                    classify(c)?;
                }
            }
            _ => {}
        }
    }
    let mut controllers = ControllerTable::default();
    let mut discard = Vec::new();
    for (i, o) in scenario.entities.scenario_objects.iter().enumerate() {
        for oc in &o.object_controllers {
            let origin = Origin {
                element: "ObjectController",
                time: 0.0,
                pos: &oc.controller.pos,
            };
            assign(
                world,
                &mut controllers,
                EntityId(i as u32),
                &oc.controller,
                oc.name.as_deref(),
                &ControllerDomains::default(),
                &origin,
                &mut discard,
            )?;
        }
    }
    Ok(controllers)
}
