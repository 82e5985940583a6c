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

use opendrive::Real;
use scenario::ControllerDomains;

use super::command::{Commanded, Controller, Merged};
use super::drivers::{DriverModel, Drivers, Instance, Model, Run, Runs};
use super::external_input::ExternalInput;
use super::one_gap::Change;
use super::parallel::ParallelCommands;
use super::properties::{ControllerKind, ModelSettings, MotionDomains};
use crate::output::EventRecord;
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
    pub instance: Option<Instance>,
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
    /// The `idm` and `mobil` models, by value (drivers.rs).
    drivers: Drivers,
    /// The controllers holding a domain, as the stage walks them (drivers.rs).
    runs: Runs,
    /// The controllers that were handed a mandatory lane, asked for their notes after each
    /// controllers stage ([`ControllerTable::notes`]); empty in ordinary runs.
    noting: Vec<Noting>,
}

/// A controller that may have a note for the event log ([`Controller::note`]).
#[derive(Debug, Clone, PartialEq)]
struct Noting {
    /// The entity's index.
    entity: usize,
    /// The controller's place among the entity's assigned controllers.
    slot: usize,
    /// The action that handed it what it notes on (the record's `element`).
    element: String,
}

/// What the controllers stage rebuilds each step, kept so that a step allocates nothing once
/// it has grown: the lane index, the commands and the threads' storage.
#[derive(Debug, Default)]
pub(crate) struct StageStorage {
    /// The lane index of the step.
    pub index: LaneIndex,
    /// The commanded entities of the step in increasing entity index (not a slot per entity,
    /// written each step), each an acceleration alone or the place of its merged command
    /// (command.rs [`Commanded`]).
    pub commanded: Vec<Commanded>,
    /// The merged commands of the step that are more than an acceleration alone: (entity
    /// index, command) in increasing entity index.
    pub merged: Vec<(usize, Merged)>,
    /// The driver models' commands worked out on threads (parallel.rs).
    pub parallel: ParallelCommands,
    /// The driver models' lane changes of the step (one_gap.rs).
    pub changes: Vec<Change>,
}

impl ControllerTable {
    /// The controllers of entity `index`.
    pub fn of(&self, index: usize) -> Option<&EntityControllers> {
        self.per_entity.get(index)
    }

    /// The controllers of entity `index`, made on first use. Inline where the list is long
    /// enough (the controllers stage asks it of every commanded entity each step; issue 31),
    /// the list grown out of line.
    #[inline]
    pub fn of_mut(&mut self, index: usize) -> &mut EntityControllers {
        if self.per_entity.len() <= index {
            self.grow(index + 1);
        }
        &mut self.per_entity[index]
    }

    /// [`of_mut`](Self::of_mut)'s growth to `len` entities.
    #[cold]
    #[inline(never)]
    fn grow(&mut self, len: usize) {
        self.per_entity.resize_with(len, EntityControllers::default);
    }

    /// What the controllers stage walks: the controllers holding a domain (built again
    /// first if a controller list changed), the driver models they may name and every
    /// entity's controllers, by index (drivers.rs).
    pub fn walk(&mut self) -> (&[Run], &mut [DriverModel], &mut [EntityControllers]) {
        let per_entity = &self.per_entity;
        let runs = self.runs.current(|| runs_of(per_entity));
        (runs, self.drivers.all_mut(), &mut self.per_entity)
    }

    /// The running model of controller `slot` of entity `index`, if it is a built-in model.
    pub fn instance_mut(&mut self, index: usize, slot: usize) -> Option<&mut dyn Controller> {
        let a = self.per_entity.get_mut(index)?.assigned.get_mut(slot)?;
        match a.instance.as_mut()? {
            Instance::Driver(k) => self.drivers.get_mut(*k).map(DriverModel::as_controller),
            Instance::Boxed(b) => Some(b.as_mut()),
        }
    }

    /// The controller at `slot` of entity `index`, handed a mandatory lane by the action
    /// `element`, is asked for its notes after each controllers stage from now on.
    pub fn note_from(&mut self, index: usize, slot: usize, element: &str) {
        self.noting.retain(|n| (n.entity, n.slot) != (index, slot));
        self.noting.push(Noting {
            entity: index,
            slot,
            element: element.to_owned(),
        });
    }

    /// The notes of the controllers [`ControllerTable::note_from`] named, as `controller`
    /// records at `time` ([`Controller::note`]), in the order they were named; `names` gives
    /// an entity's name by its index.
    pub fn notes<'n>(
        &mut self,
        time: Real,
        names: impl Fn(usize) -> &'n str,
        events: &mut Vec<EventRecord>,
    ) {
        for k in 0..self.noting.len() {
            let (entity, slot) = (self.noting[k].entity, self.noting[k].slot);
            let Some(note) = self.instance_mut(entity, slot).and_then(|c| c.note()) else {
                continue;
            };
            let Some(a) = self.of(entity).and_then(|c| c.assigned.get(slot)) else {
                continue;
            };
            events.push(EventRecord::Controller {
                time,
                element: self.noting[k].element.clone(),
                entity: names(entity).to_owned(),
                controller: a.name.clone(),
                model: a.model_name(),
                active: a.active,
                note,
            });
        }
    }

    /// The running model for `settings`: a driver model kept by value in the table, any
    /// other boxed.
    pub fn instantiate(&mut self, settings: &ModelSettings) -> Instance {
        use super::car_following::{AccController, IdmController};
        use super::external::ExternalController;
        use super::mobil::{IdmDriver, MobilController};
        use super::vehicle_dynamics::VehicleDynamicsController;
        let mut driver = |model| Instance::Driver(self.drivers.add(model));
        match settings {
            ModelSettings::Idm {
                idm,
                desired_speed_given,
            } => driver(DriverModel::Idm(IdmDriver::new(IdmController::new(
                *idm,
                *desired_speed_given,
            )))),
            ModelSettings::Mobil {
                idm,
                desired_speed_given,
                mobil,
            } => driver(DriverModel::Mobil(MobilController::new(
                *idm,
                *desired_speed_given,
                *mobil,
            ))),
            ModelSettings::Acc {
                acc,
                set_speed_given,
            } => Instance::Boxed(Box::new(AccController::new(*acc, *set_speed_given))),
            ModelSettings::VehicleDynamics {
                steering_ratio,
                steering_inertia,
            } => Instance::Boxed(Box::new(VehicleDynamicsController::new(
                *steering_ratio,
                *steering_inertia,
            ))),
            ModelSettings::External => Instance::Boxed(Box::new(ExternalController::new())),
        }
    }

    /// `old` was replaced: its driver model, if any, is no longer used.
    pub fn release(&mut self, old: Assigned) {
        if let Some(Instance::Driver(k)) = old.instance {
            self.drivers.release(k);
        }
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
        // Every change of an entity's controllers is recounted: the stage's runs too.
        self.runs.mark_stale();
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

/// The runs of `per_entity` (drivers.rs): each controller whose `holds()` is not empty, in
/// the order the lists give them.
fn runs_of(per_entity: &[EntityControllers]) -> impl Iterator<Item = Run> + '_ {
    per_entity.iter().enumerate().flat_map(|(i, ctrl)| {
        ctrl.assigned
            .iter()
            .enumerate()
            .filter_map(move |(slot, a)| {
                let held = a.holds();
                if held == MotionDomains::default() {
                    return None;
                }
                let model = match a.instance {
                    Some(Instance::Driver(k)) => Model::Driver(k),
                    // `holds()` is empty without an instance, so this is `Boxed`.
                    _ => Model::Boxed { slot },
                };
                Some(Run {
                    entity: i,
                    held,
                    model,
                })
            })
    })
}

/// The requested change per domain, as (longitudinal, lateral, lighting, animation).
pub(crate) fn requested(d: &ControllerDomains) -> [Option<bool>; 4] {
    [d.longitudinal, d.lateral, d.lighting, d.animation]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::controller::car_following::IdmController;
    use crate::controller::external::ExternalController;
    use crate::controller::mobil::IdmDriver;
    use crate::models::idm::IdmParameters;

    fn assigned(instance: Option<Instance>, longitudinal: bool, lateral: bool) -> Assigned {
        Assigned {
            name: "c".to_owned(),
            object_controller: None,
            kind: ControllerKind::Default,
            active: ActiveDomains {
                longitudinal,
                lateral,
                lighting: true,
                animation: false,
            },
            instance,
        }
    }

    fn entity(assigned: Vec<Assigned>) -> EntityControllers {
        EntityControllers {
            assigned,
            ..EntityControllers::default()
        }
    }

    fn run(entity: usize, longitudinal: bool, lateral: bool, model: Model) -> Run {
        Run {
            entity,
            held: MotionDomains {
                longitudinal,
                lateral,
            },
            model,
        }
    }

    /// The runs are the controllers holding a motion domain, by entity and then by place in
    /// the entity's list, written out by hand for five entities: 0 an active `idm` (driver 0);
    /// 1 nothing; 2 an inactive driver 1, a controller of another tool (no instance) active on
    /// both domains (it holds none), a boxed `external` active laterally at slot 2; 3 only
    /// lighting (no motion domain); 4 a boxed model longitudinally at slot 0 and driver 2 on
    /// both at slot 1.
    #[test]
    fn the_runs_are_the_controllers_holding_a_domain_in_the_stages_order() {
        let boxed = || Some(Instance::Boxed(Box::new(ExternalController::new())));
        let per_entity = vec![
            entity(vec![assigned(Some(Instance::Driver(0)), true, false)]),
            entity(vec![]),
            entity(vec![
                assigned(Some(Instance::Driver(1)), false, false),
                assigned(None, true, true),
                assigned(boxed(), false, true),
            ]),
            entity(vec![assigned(boxed(), false, false)]),
            entity(vec![
                assigned(boxed(), true, false),
                assigned(Some(Instance::Driver(2)), true, true),
            ]),
        ];
        let expected = [
            run(0, true, false, Model::Driver(0)),
            run(2, false, true, Model::Boxed { slot: 2 }),
            run(4, true, false, Model::Boxed { slot: 0 }),
            run(4, true, true, Model::Driver(2)),
        ];
        let mut runs = Runs::default();
        runs.mark_stale();
        assert_eq!(runs.current(|| runs_of(&per_entity)), &expected[..]);
        // Not stale: the same list, not built again (the debug assertion compares it).
        assert_eq!(runs.current(|| runs_of(&per_entity)), &expected[..]);
    }

    /// A released place is reused by the next model, the others keep theirs.
    #[test]
    fn a_replaced_driver_models_place_is_reused() {
        let idm = |v0| {
            DriverModel::Idm(IdmDriver::new(IdmController::new(
                IdmParameters {
                    desired_speed: v0,
                    ..IdmParameters::default()
                },
                true,
            )))
        };
        let mut drivers = Drivers::default();
        assert_eq!((drivers.add(idm(10.0)), drivers.add(idm(20.0))), (0, 1));
        drivers.release(0);
        assert_eq!(drivers.add(idm(30.0)), 0);
        assert_eq!(drivers.add(idm(40.0)), 2);
        let v0 = |d: &mut Drivers, k| match d.get_mut(k) {
            Some(DriverModel::Idm(c)) => c.idm.params.desired_speed,
            _ => f64::NAN,
        };
        // Exact: stored, not computed.
        assert_eq!([0, 1, 2].map(|k| v0(&mut drivers, k)), [30.0, 20.0, 40.0]);
    }
}
