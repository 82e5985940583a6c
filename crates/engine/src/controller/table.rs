//! The controllers assigned to each entity and the domains each holds (OpenSCENARIO 1.3
//! §6.6: any number of controllers per Vehicle or Pedestrian, assigned deactivated;
//! XSD `AssignControllerAction`, `ActivateControllerAction`, `ObjectController`).
//!
//! - **Assigning** adds the controller to the entity; one with the same ObjectController name
//!   (or, without one, the same Controller name) is replaced. `activate*` flags that are true
//!   activate it at once.
//! - **Activating** a motion domain gives it to that controller: another controller holding it
//!   loses it (the last activation wins). A controller is activated only in the domains it is
//!   defined for (ActivateControllerAction: "a controller cannot be activated in a domain in
//!   which it is not defined"): a built-in model's domains narrowed by `controllerType`
//!   (`properties`); a request for another domain is noted in the event log and has no
//!   effect. Lighting and animation are recorded (no built-in model drives them).
//! - **Deactivating** hands the domain back to the default controller, which keeps the speed
//!   and the lane offset the entity has then (§7.2.2.1).
//! - An ActivateControllerAction without `objectControllerRef` addresses the entity's only
//!   user controller; with several, the one assigned last (the 1.3 text calls the omission
//!   "unmeaningful" then), which the log names.
//!
//! A controller that is not one of oscsim's models (no `model` property; esmini's own) is
//! kept and its activation recorded, but it holds no domain: the default controller keeps
//! driving, and the event log says so.

use scenario::ControllerDomains;

use super::command::{Controller, Merged};
use super::external_input::ExternalInput;
use super::properties::{ControllerKind, ModelSettings, MotionDomains};
use crate::store::lane_index::LaneIndex;
use crate::world::ActiveDomains;

/// One controller assigned to an entity.
#[derive(Debug)]
pub(crate) struct Assigned {
    /// `Controller@name`.
    pub name: String,
    /// `ObjectController@name`, if given.
    pub object_controller: Option<String>,
    /// What it is.
    pub kind: ControllerKind,
    /// Active domains.
    pub active: ActiveDomains,
    /// The running model (built-in models only).
    pub instance: Option<Box<dyn Controller>>,
}

impl Assigned {
    /// The motion domains it holds now (active and a built-in model).
    pub fn holds(&self) -> MotionDomains {
        if self.instance.is_none() {
            return MotionDomains::default();
        }
        MotionDomains {
            longitudinal: self.active.longitudinal,
            lateral: self.active.lateral,
        }
    }

    /// The motion domains it is defined for (none for a controller that is not a model).
    pub fn defined(&self) -> MotionDomains {
        match &self.kind {
            ControllerKind::Model { domains, .. } => *domains,
            _ => MotionDomains::default(),
        }
    }

    /// "idm", or what the controller is when it is not a model.
    pub fn model_name(&self) -> String {
        match &self.kind {
            ControllerKind::Model { settings, .. } => settings.name().to_owned(),
            ControllerKind::Default => "default".to_owned(),
            ControllerKind::Foreign { .. } => "none".to_owned(),
        }
    }
}

/// The controllers of one entity and the lane change a controller started.
#[derive(Debug, Default)]
pub(crate) struct EntityControllers {
    /// In order of assignment.
    pub assigned: Vec<Assigned>,
    /// A lane change commanded by a controller ([`super::command::Lateral::ChangeLane`]).
    pub lane_change: Option<crate::world::lane_change::RouteLaneChange>,
    /// A controller steered the entity off its lane track.
    pub steered: bool,
    /// The host's input for an `external` controller.
    pub external: Option<ExternalInput>,
}

impl EntityControllers {
    /// The controller holding the longitudinal / lateral domain.
    pub fn holder(&self, longitudinal: bool) -> Option<usize> {
        self.assigned.iter().position(|a| {
            let h = a.holds();
            if longitudinal {
                h.longitudinal
            } else {
                h.lateral
            }
        })
    }

    /// The number of motion domains user controllers hold (0, 1 or 2).
    fn held_pairs(&self) -> usize {
        let h = self.held();
        usize::from(h.longitudinal) + usize::from(h.lateral)
    }

    /// The motion domains user controllers hold.
    pub fn held(&self) -> MotionDomains {
        self.assigned
            .iter()
            .fold(MotionDomains::default(), |acc, a| {
                let h = a.holds();
                MotionDomains {
                    longitudinal: acc.longitudinal || h.longitudinal,
                    lateral: acc.lateral || h.lateral,
                }
            })
    }
}

/// The controllers of every entity, by entity index.
#[derive(Debug, Default)]
pub(crate) struct ControllerTable {
    per_entity: Vec<EntityControllers>,
    /// Number of (entity, domain) pairs a built-in model holds: the stage skips the lane
    /// index when none does.
    held: usize,
    /// The controllers stage's storage, kept from step to step (stage.rs).
    pub stage: StageStorage,
}

/// What the controllers stage rebuilds each step, kept so that a step allocates nothing once
/// it has grown: the lane index and the merged commands.
#[derive(Debug, Default)]
pub(crate) struct StageStorage {
    /// The lane index of the step.
    pub index: LaneIndex,
    /// The merged commands of the step, by entity index.
    pub merged: Vec<Option<Merged>>,
}

impl ControllerTable {
    /// The controllers of entity `index`.
    pub fn of(&self, index: usize) -> Option<&EntityControllers> {
        self.per_entity.get(index)
    }

    /// The controllers of entity `index`, made on first use.
    pub fn of_mut(&mut self, index: usize) -> &mut EntityControllers {
        if self.per_entity.len() <= index {
            self.per_entity
                .resize_with(index + 1, EntityControllers::default);
        }
        &mut self.per_entity[index]
    }

    /// Every entity's controllers, by index.
    pub fn iter_mut(&mut self) -> impl Iterator<Item = (usize, &mut EntityControllers)> {
        self.per_entity.iter_mut().enumerate()
    }

    /// Some built-in model holds a domain of some entity.
    pub fn any_held(&self) -> bool {
        self.held > 0
    }

    /// The (entity, motion domain) pairs that entity `index`'s models hold.
    pub fn held_by(&self, index: usize) -> usize {
        self.of(index).map_or(0, EntityControllers::held_pairs)
    }

    /// Counts the held pairs again after a change to the controllers of entity `index` alone,
    /// which held `before` of them ([`held_by`](Self::held_by) before the change): the other
    /// entities' pairs are as they were, so the count moves by this entity's difference. (A
    /// count over every entity at each change made loading a scenario that gives each of N
    /// vehicles a controller quadratic in N: 22 % of the load of 4,000, issue 31.)
    pub fn recount_entity(&mut self, index: usize, before: usize) {
        // `before` is part of `held` (the count is the sum over every entity), so no underflow.
        self.held = self.held + self.held_by(index) - before;
        debug_assert_eq!(
            self.held,
            self.per_entity
                .iter()
                .map(EntityControllers::held_pairs)
                .sum::<usize>(),
            "the count by difference is the count over every entity"
        );
    }
}

/// The running model for `settings`.
pub(crate) fn instantiate(settings: &ModelSettings) -> Box<dyn Controller> {
    use super::car_following::{AccController, IdmController};
    use super::external::ExternalController;
    use super::mobil::MobilController;
    use super::vehicle_dynamics::VehicleDynamicsController;
    match settings {
        ModelSettings::Idm {
            idm,
            desired_speed_given,
        } => Box::new(IdmController::new(*idm, *desired_speed_given)),
        ModelSettings::Mobil {
            idm,
            desired_speed_given,
            mobil,
        } => Box::new(MobilController::new(*idm, *desired_speed_given, *mobil)),
        ModelSettings::Acc {
            acc,
            set_speed_given,
        } => Box::new(AccController::new(*acc, *set_speed_given)),
        ModelSettings::VehicleDynamics {
            steering_ratio,
            steering_inertia,
        } => Box::new(VehicleDynamicsController::new(
            *steering_ratio,
            *steering_inertia,
        )),
        ModelSettings::External => Box::new(ExternalController::new()),
    }
}

/// The requested change per domain, as (longitudinal, lateral, lighting, animation).
pub(crate) fn requested(d: &ControllerDomains) -> [Option<bool>; 4] {
    [d.longitudinal, d.lateral, d.lighting, d.animation]
}
