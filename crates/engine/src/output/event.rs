//! Records of the event log: every storyboard state transition (OpenSCENARIO 1.3 §8.2), every
//! CustomCommandAction (§7.7.3), entities entering and leaving, traffic signal phases and
//! states, monitor values, actions and features skipped as unsupported, and errors.

use scenario::SourcePos;

use super::SinkError;
use crate::storyboard::TransitionRecord;

/// One record of the event log.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum EventRecord {
    /// A storyboard element changed state.
    Transition(TransitionRecord),
    /// A CustomCommandAction ran.
    CustomCommand {
        /// Simulation time (s).
        time: f64,
        /// The action's name.
        element: String,
        /// `type`.
        command_type: String,
        /// `content`.
        content: String,
    },
    /// An action or feature oscsim does not support was skipped (the action ended at once).
    Unsupported {
        /// Simulation time (s).
        time: f64,
        /// The action's name.
        element: String,
        /// What was skipped and where, e.g. "SynchronizeAction at x.xosc:10:5".
        message: String,
    },
    /// An entity changed outside its motion: it entered or left the scenario
    /// (AddEntityAction, DeleteEntityAction, a traffic source, sink or swarm), or an
    /// AppearanceAction set one of its lights or animations (actions/appearance.rs).
    Entity {
        /// Simulation time (s): of the action's start, or for traffic actions of the first frame
        /// that shows the vehicle (or its absence).
        time: f64,
        /// The action's or traffic action's name.
        element: String,
        /// The entity's name.
        entity: String,
        /// What changed, e.g. "spawned", "removed", "light lowBeam on".
        change: String,
    },
    /// A traffic signal controller entered a phase, or a traffic signal changed state
    /// (crate::signals).
    Signal {
        /// Simulation time (s).
        time: f64,
        /// The controller's name or the signal's id.
        element: String,
        /// Controller or signal.
        kind: SignalKind,
        /// The phase or state before; `None` for the first one.
        from: Option<String>,
        /// The phase or state now.
        to: String,
    },
    /// A monitor (MonitorDeclaration, OpenSCENARIO 1.3) took a value: its declared value at the
    /// start, then every SetMonitorAction that changes it.
    Monitor {
        /// Simulation time (s).
        time: f64,
        /// The monitor's name.
        element: String,
        /// The value now.
        value: bool,
    },
    /// A user controller of an entity was assigned, (de)activated, or given a motion action of
    /// the scenario (OpenSCENARIO 1.3 §6.6, §7.7.2.5; engine module `controller`): the
    /// controller's active domains after the change, the state a ControllerCondition reads.
    Controller {
        /// Simulation time (s).
        time: f64,
        /// The action's name ("ObjectController" for one assigned with the entity).
        element: String,
        /// The entity's name.
        entity: String,
        /// `Controller@name`.
        controller: String,
        /// Its model (`idm`, …), `default`, or `none` for a controller that is not oscsim's.
        model: String,
        /// Its active domains after the change.
        active: crate::world::ActiveDomains,
        /// What happened ("assigned", "activation changed", "desired speed 25 m/s", …).
        note: String,
    },
    /// Something failed at runtime: an action that could not start (the run stops with this
    /// error), or a condition that could not be evaluated, a route that could not be planned or
    /// a trajectory that could not be built (logged once; the condition reads false, the action
    /// does nothing, and the run goes on).
    Error {
        /// Simulation time (s).
        time: f64,
        /// The action's name.
        element: String,
        /// The error's message.
        message: String,
    },
}

impl EventRecord {
    pub(crate) fn unsupported(time: f64, element: &str, what: &str, pos: &SourcePos) -> Self {
        EventRecord::Unsupported {
            time,
            element: element.to_owned(),
            message: format!("{what} is not supported at {pos}"),
        }
    }

    pub(crate) fn error(time: f64, element: &str, error: &dyn std::fmt::Display) -> Self {
        EventRecord::Error {
            time,
            element: element.to_owned(),
            message: error.to_string(),
        }
    }

    /// Simulation time of the record (s).
    pub fn time(&self) -> f64 {
        match self {
            EventRecord::Transition(t) => t.time,
            EventRecord::CustomCommand { time, .. }
            | EventRecord::Unsupported { time, .. }
            | EventRecord::Entity { time, .. }
            | EventRecord::Signal { time, .. }
            | EventRecord::Monitor { time, .. }
            | EventRecord::Controller { time, .. }
            | EventRecord::Error { time, .. } => *time,
        }
    }
}

/// Receives the event records of each step, in the order they happened.
pub trait EventSink {
    /// Takes one record. An error ends the run.
    fn event(&mut self, record: &EventRecord) -> Result<(), SinkError>;

    /// Called once after the last record.
    fn finish(&mut self) -> Result<(), SinkError> {
        Ok(())
    }
}

/// Discards records.
impl EventSink for () {
    fn event(&mut self, _record: &EventRecord) -> Result<(), SinkError> {
        Ok(())
    }
}

/// Collects records (tests).
impl EventSink for Vec<EventRecord> {
    fn event(&mut self, record: &EventRecord) -> Result<(), SinkError> {
        self.push(record.clone());
        Ok(())
    }
}

/// What an [`EventRecord::Signal`] is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SignalKind {
    /// A TrafficSignalController changed phase.
    Controller,
    /// A traffic signal changed state.
    Signal,
}

impl SignalKind {
    /// The `kind` of the event log.
    pub fn name(self) -> &'static str {
        match self {
            SignalKind::Controller => "trafficSignalController",
            SignalKind::Signal => "trafficSignal",
        }
    }
}
