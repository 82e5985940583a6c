//! The [`Controller`] trait and the commands a controller gives for one step (OpenSCENARIO
//! 1.3 §6.6 "Controllers": a controller controls the longitudinal and/or lateral motion
//! domain of its entity; §7.2.2.1: the default controller takes every domain no user
//! controller holds).
//!
//! A controller sees the step's world from its entity ([`ControllerView`]) and answers with a
//! [`Command`]: per domain it holds, what the entity does over the step. A domain it leaves
//! without a command is driven as the default controller drives it (keep the speed the
//! scenario set, follow the lane), so a longitudinal controller such as `idm` gives only an
//! acceleration and the entity keeps its lane, its lane changes and its route as before.

use opendrive::{Pose, Real};

use super::view::ControllerView;
use crate::world::EntityId;

/// What moves the entity along its path over the step.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Longitudinal {
    /// Accelerate at this rate (m/s², along the direction of travel) over the step; the
    /// vehicle's Performance bounds it, the speed does not turn negative, and the distance is
    /// that of the constant acceleration (ballistic update).
    Acceleration(Real),
    /// The motion a vehicle model worked out: speed at the end of the step (m/s, negative
    /// backwards), signed distance travelled (m) and the acceleration (m/s²).
    Motion {
        /// Speed at the end of the step.
        speed: Real,
        /// Distance travelled.
        distance: Real,
        /// Acceleration over the step.
        acceleration: Real,
    },
}

/// What moves the entity across its path over the step.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Lateral {
    /// Change into lane `lane` of the entity's road (cubic lateral shape over the distance
    /// that keeps the peak lateral acceleration at 1 m/s², as the route's lane changes).
    ChangeLane(i32),
    /// Leave the lane and drive along a circular arc of this curvature (1/m, positive left).
    Curvature(Real),
}

/// A controller's answer for one step.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Command {
    /// Per domain; `None` leaves the domain to the default controller's way of driving.
    Motion {
        /// The longitudinal command.
        longitudinal: Option<Longitudinal>,
        /// The lateral command.
        lateral: Option<Lateral>,
    },
    /// The pose the entity has at the end of the step (both domains); the speed is the
    /// distance moved along the heading per step.
    Pose(Pose),
}

impl Command {
    /// No command in either domain: drive as the default controller.
    pub const NONE: Command = Command::Motion {
        longitudinal: None,
        lateral: None,
    };

    /// A longitudinal acceleration only.
    pub fn acceleration(a: Real) -> Command {
        Command::Motion {
            longitudinal: Some(Longitudinal::Acceleration(a)),
            lateral: None,
        }
    }
}

/// A motion action of the scenario handed to the user controller holding its domain
/// (module `controller` doc): what the controller may take from it.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Strategy {
    /// A SpeedAction or SpeedProfileAction: the speed it asks for in the end (m/s).
    Speed(Real),
    /// A LaneChangeAction: the lane of the entity's road it asks for.
    Lane(i32),
    /// oscsim's mandatory lane (`scenario::LateralAction::MandatoryLane`): the lane of the
    /// entity's road to reach, each change only into a gap the model's safety criterion
    /// accepts, and to keep until released (`None`).
    MandatoryLane(Option<i32>),
    /// oscsim's free-road acceleration (`scenario::LongitudinalAction::ModelAcceleration`):
    /// what replaces the driver model's free-road term, the interaction term toward its
    /// leader still subtracted, until released (`None`: the model's own term again).
    FreeAcceleration(Option<FreeAcceleration>),
    /// oscsim's rate of a change to a speed (`scenario::ModelAcceleration::Toward`): `speed`
    /// the model's desired speed, and `rate`'s value in magnitude, signed toward `speed`, its
    /// free-road term (the step that reaches `speed` cut to end there) until the entity's
    /// speed reaches `speed`; then the model's own free-road term. With `of`, the speed is
    /// that entity's as the step's view shows it plus `speed`, read at every step: the
    /// desired speed follows it and the rate is kept toward it (never released by reaching
    /// it) until a later strategy replaces or releases it.
    FreeAccelerationToward {
        /// The speed the change ends at (m/s); with `of`, added to that entity's speed.
        speed: Real,
        /// Its rate (m/s², taken in magnitude).
        rate: FreeAcceleration,
        /// The entity whose speed `speed` is added to, read at every step (`None`: `speed`).
        of: Option<EntityId>,
    },
}

/// The free-road acceleration a driver model is handed ([`Strategy::FreeAcceleration`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum FreeAcceleration {
    /// This acceleration (m/s², along the direction of travel).
    Fixed(Real),
    /// The acceleration along its direction of travel of `reference` as the step's view shows
    /// it (measured by its last move: over the step before) plus `value` (m/s²), read at
    /// every step.
    Follow {
        /// The reference entity.
        reference: EntityId,
        /// Added to its acceleration (m/s²).
        value: Real,
    },
}

impl FreeAcceleration {
    /// Its value in `view` (m/s²).
    #[inline]
    pub fn value(&self, view: &ControllerView<'_>) -> Real {
        match *self {
            FreeAcceleration::Fixed(a) => a,
            FreeAcceleration::Follow { reference, value } => {
                let x = view.other(reference);
                x.travel_component(x.acceleration.translational) + value
            }
        }
    }
}

/// A controller of one entity's motion (OpenSCENARIO 1.3 §6.6): each step it gets the world
/// as seen from its entity and gives the [`Command`] for the domains it holds.
pub trait Controller: std::fmt::Debug + Send {
    /// The model's name (`idm`, `mobil`, `acc`, `vehicle_dynamics`, `external`).
    fn model(&self) -> &'static str;

    /// The controller was activated on a domain; `view` shows the entity at that moment (a
    /// model reads its defaults from it, such as the desired speed).
    fn activate(&mut self, view: &ControllerView<'_>) {
        let _ = view;
    }

    /// A motion action of the scenario on a domain this controller holds. Returns what was
    /// done with it, for the event log ("desired speed 25 m/s"), or `None` when the
    /// controller does not take such a strategy (the action is then ignored).
    fn strategy(&mut self, strategy: Strategy) -> Option<String> {
        let _ = strategy;
        None
    }

    /// The command for the step of `dt` s starting at `view.time()`.
    fn step(&mut self, view: &ControllerView<'_>, dt: Real) -> Command;

    /// What the controller has to tell the event log since it was last asked, once (a
    /// mandatory lane lost where its links do not lead onto the entity's road,
    /// controller/mobil.rs). Asked after each controllers stage only of the controllers that
    /// were handed a mandatory lane (`ControllerTable::noting`). Default: nothing.
    fn note(&mut self) -> Option<String> {
        None
    }
}

/// The commands of one entity's controllers for a step, merged per domain (the controllers
/// stage builds one per entity and applies it).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Merged {
    pub(super) longitudinal: Option<Longitudinal>,
    pub(super) lateral: Option<Lateral>,
    pub(super) pose: Option<Pose>,
}

impl Merged {
    /// An acceleration alone: the longitudinal domain's command, none in the lateral domain
    /// and no pose.
    #[inline]
    pub(super) fn acceleration(a: Real) -> Merged {
        Merged {
            longitudinal: Some(Longitudinal::Acceleration(a)),
            lateral: None,
            pose: None,
        }
    }
}

/// A commanded entity in the step's list of commands, which the moves' walk meets in entity
/// order (controller/stage.rs): the [`Merged`] command [`Merged::acceleration`] of `a`, or
/// the entity's [`Merged`] command at place `merged` of the step's merged commands.
///
/// **Why.** Most commands of driver-model traffic are an acceleration alone (an `idm`, or a
/// `mobil` that changes no lane this step): kept as 16 bytes here instead of a 112-byte
/// [`Merged`] built, pushed and read back per entity and step (issue 31). The moves' walk
/// applies `Merged::acceleration(a)` for them, the command the merge gives, so the move is
/// the same to the bit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Commanded {
    /// The entity's index.
    pub entity: u32,
    /// The place of its merged command, or [`Commanded::ACCELERATION`].
    pub merged: u32,
    /// The acceleration (m/s²) where `merged` is [`Commanded::ACCELERATION`].
    pub a: Real,
}

impl Commanded {
    /// `merged` of a command that is an acceleration alone.
    pub const ACCELERATION: u32 = u32::MAX;
}
