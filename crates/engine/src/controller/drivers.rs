//! The driver models by value in a dense table, and the list of the controllers that hold a
//! motion domain, which the controllers stage walks (OpenSCENARIO 1.3 §6.6 user-defined
//! controllers, §7.2.2.1: a controller gives the motion of the domains it holds; issue 31).
//!
//! **Why.** The stage used to reach each entity's model through the entity's controller list
//! (`Assigned`, 168 bytes on the heap, one list per entity) and a boxed `dyn Controller`
//! behind it: two dependent loads from scattered heap lines per entity and step, then a
//! virtual call. At 4,000 `idm` vehicles the load of the `Assigned` alone held 11 % of the
//! stage's samples (`perf record`, issue 31). Here the `idm` and `mobil` models (the driver
//! models of traffic) live by value in one vector ([`Drivers`]), in the order they were
//! assigned, and the stage walks [`Runs`]: per entity in index order, each controller holding
//! a domain, with the domains it holds and where its model is. For a driver model the stage
//! reads the run and the model only, and calls its step without a virtual call. Other models
//! (`acc`, `vehicle_dynamics`, `external`) stay boxed in their `Assigned`, as before.
//!
//! **The same commands.** The runs are in the order the stage walked the controllers before
//! (entity index, then assignment order), each is a controller whose `holds()` is not empty,
//! and each gets the same view: the commands, their merge and the index's search hints are
//! the same, call for call. The list is built again from the controller lists after any change
//! of an entity's controllers (the table marks it stale where it recounts the held domains);
//! in debug builds (every `cargo test`) the stage asserts that the list it walks is the one
//! built from the controller lists.

use opendrive::Real;

use super::command::Controller;
use super::mobil::{IdmDriver, MobilController, Next};
use super::properties::MotionDomains;
use super::view::ControllerView;

/// Where a running built-in model is kept (an entity's `Assigned` holds it).
#[derive(Debug)]
pub(crate) enum Instance {
    /// `idm` or `mobil`: by value in the table's [`Drivers`], at this place.
    Driver(usize),
    /// Any other model.
    Boxed(Box<dyn Controller>),
}

/// A driver model held by value (module doc).
#[derive(Debug, Clone)]
pub(crate) enum DriverModel {
    /// `idm` (with the mandatory lane it may hold, controller/mobil.rs).
    Idm(IdmDriver),
    /// `mobil`.
    Mobil(MobilController),
}

impl DriverModel {
    /// The model as a [`Controller`] (for activation and strategies, which are rare).
    pub fn as_controller(&mut self) -> &mut dyn Controller {
        match self {
            DriverModel::Idm(c) => c,
            DriverModel::Mobil(c) => c,
        }
    }

    /// The model's step as numbers, without a virtual call: the acceleration and the lane to
    /// change to, if any ([`Controller::step`] gives them as a [`Command`]:
    /// `Command::Motion` with `Longitudinal::Acceleration` and `Lateral::ChangeLane`). The
    /// stage merges them into the entity's command without building the `Command` enum,
    /// which it copied through the stack with a 16-byte reload of 8-byte stores that waited
    /// for them (14-19 % of the stage's samples of `idm` at 4,000, issue 31).
    #[inline]
    pub fn command(&mut self, view: &ControllerView<'_>) -> (Real, Option<i32>) {
        match self {
            DriverModel::Idm(c) => c.command(view),
            DriverModel::Mobil(c) => c.command(view),
        }
    }

    /// The change this step's command gave yields (controller/one_gap.rs): whether it may, the
    /// model then being as if it had decided none ([`MobilController::yield_change`]; an
    /// `idm`'s change is always its mandatory lane's, judged, and it keeps no state of it).
    pub fn yield_change(&mut self) -> bool {
        match self {
            DriverModel::Idm(_) => true,
            DriverModel::Mobil(c) => c.yield_change(),
        }
    }

    /// MOBIL's safety criterion, as the model judges its changes, for its entity changing
    /// into a lane where `other` would be next to it (controller/mobil.rs `gap_safe`).
    pub fn gap_safe(&self, view: &ControllerView<'_>, other: Next) -> bool {
        match self {
            DriverModel::Idm(c) => c.gap_safe(view, other),
            DriverModel::Mobil(c) => c.gap_safe(view, other),
        }
    }
}

/// The driver models of every entity, by value, with the places of replaced ones to reuse.
#[derive(Debug, Default)]
pub(crate) struct Drivers {
    models: Vec<DriverModel>,
    /// Places of models no `Assigned` names any more (replaced by a new assignment).
    free: Vec<usize>,
}

impl Drivers {
    /// Keeps `model`; returns its place.
    pub fn add(&mut self, model: DriverModel) -> usize {
        match self.free.pop() {
            Some(k) => {
                self.models[k] = model;
                k
            }
            None => {
                self.models.push(model);
                self.models.len() - 1
            }
        }
    }

    /// The model at `k` is no longer used.
    pub fn release(&mut self, k: usize) {
        self.free.push(k);
    }

    /// The model at `k`.
    pub fn get_mut(&mut self, k: usize) -> Option<&mut DriverModel> {
        self.models.get_mut(k)
    }

    /// Every model, by place.
    pub fn all_mut(&mut self) -> &mut [DriverModel] {
        &mut self.models
    }
}

/// Where a run's model is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Model {
    /// In [`Drivers`], at this place.
    Driver(usize),
    /// Boxed in the entity's `Assigned` number `slot`.
    Boxed {
        /// The controller's place in the entity's list.
        slot: usize,
    },
}

/// One controller holding a motion domain (module doc).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Run {
    /// The entity's index.
    pub entity: usize,
    /// The domains the controller holds (never none).
    pub held: MotionDomains,
    /// Its model.
    pub model: Model,
}

/// The runs of a step, by entity index and then assignment order (module doc).
#[derive(Debug, Default)]
pub(crate) struct Runs {
    runs: Vec<Run>,
    /// A controller list changed since the runs were built.
    stale: bool,
}

impl Runs {
    /// A controller list changed: build the runs again before the next walk.
    pub fn mark_stale(&mut self) {
        self.stale = true;
    }

    /// The runs, built again from `fresh` (the runs of the controller lists, in order) first
    /// when stale, in place: no allocation once grown.
    pub fn current<I: Iterator<Item = Run>>(&mut self, fresh: impl Fn() -> I) -> &[Run] {
        if std::mem::take(&mut self.stale) {
            self.runs.clear();
            self.runs.extend(fresh());
        }
        debug_assert!(
            fresh().eq(self.runs.iter().copied()),
            "the runs walked are the runs of the controller lists"
        );
        &self.runs
    }
}
