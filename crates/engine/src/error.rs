//! [`Error`], the one error of the engine's public API: loading a scenario and its road
//! network ([`Engine::load`](crate::Engine::load), [`RoadNetworks`](crate::RoadNetworks)),
//! building an engine from them ([`Engine::new`](crate::Engine::new)) and running it
//! ([`Engine::step`](crate::Engine::step)). Its [`kind`](Error::kind) is the
//! `#[non_exhaustive]` [`ErrorKind`]; the errors of the `scenario` and `opendrive` readers and
//! of the engine's own modules (positions, trajectories, the storyboard, sinks) stay typed
//! inside it, and [`Error::pos`] is the scenario's `file:line:col` where the error has one.
//!
//! Messages follow the project's form "expected X, found Y at file:line:col"; the place is the
//! scenario element (action, position, entity reference) that caused the error.

use scenario::SourcePos;

use crate::storyboard::StoryboardError;

/// An error loading, building or running an [`Engine`](crate::Engine).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{kind}")]
pub struct Error {
    kind: Box<ErrorKind>,
}

impl Error {
    pub(crate) fn new(kind: ErrorKind) -> Self {
        Error {
            kind: Box::new(kind),
        }
    }

    /// What went wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }

    /// The scenario's `file:line:col` of the element the error is about, where it has one
    /// (a road-network error has its `.xodr` position instead: [`ErrorKind::RoadNetwork`]).
    pub fn pos(&self) -> Option<&SourcePos> {
        match &*self.kind {
            ErrorKind::Scenario(e) => Some(e.pos()),
            ErrorKind::Invalid { pos, .. } | ErrorKind::Unsupported { pos, .. } => Some(pos),
            ErrorKind::Position(e) => Some(e.pos()),
            ErrorKind::Trajectory(e) => Some(e.pos()),
            _ => None,
        }
    }

    /// An error at a scenario element: expected `expected`, found `found`, at `pos`.
    pub(crate) fn at(
        expected: impl Into<String>,
        found: impl Into<String>,
        pos: &SourcePos,
    ) -> Self {
        Error::new(ErrorKind::Invalid {
            expected: expected.into(),
            found: found.into(),
            pos: pos.clone(),
        })
    }

    /// An unsupported feature at `pos`.
    pub(crate) fn unsupported(what: impl Into<String>, pos: &SourcePos) -> Self {
        Error::new(ErrorKind::Unsupported {
            what: what.into(),
            pos: pos.clone(),
        })
    }
}

/// The kinds of [`Error`].
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The scenario did not load (the scenario reader's error, with its file:line:col).
    #[error("{0}")]
    Scenario(scenario::Error),
    /// The road network did not load (the OpenDRIVE reader's error, with the `.xodr` file and
    /// line:col).
    #[error("cannot load the road network: {0}")]
    RoadNetwork(opendrive::Error),
    /// The scenario names no road network (`RoadNetwork/LogicFile`).
    #[error("expected a RoadNetwork/LogicFile, found none in {file}")]
    NoRoadNetwork {
        /// The scenario file.
        file: String,
    },
    /// A value or reference in the scenario that the runtime cannot use.
    #[error("expected {expected}, found {found} at {pos}")]
    Invalid {
        /// What was expected.
        expected: String,
        /// What was found.
        found: String,
        /// Where.
        pos: SourcePos,
    },
    /// A feature the runtime does not support.
    #[error("expected a supported feature, found {what} (not supported) at {pos}")]
    Unsupported {
        /// The feature.
        what: String,
        /// Where.
        pos: SourcePos,
    },
    /// A position did not resolve (the position module's error names file:line:col).
    #[error("{0}")]
    Position(crate::position::PositionError),
    /// A trajectory could not be built (the trajectory module's error names file:line:col).
    #[error("{0}")]
    Trajectory(crate::trajectory::TrajectoryError),
    /// The storyboard rejected its description or a step.
    #[error("storyboard: {0}")]
    Storyboard(#[from] StoryboardError),
    /// A configuration value is out of range.
    #[error("expected {expected}, found {found} for {name}")]
    Config {
        /// The setting.
        name: &'static str,
        /// What was expected.
        expected: &'static str,
        /// The value found.
        found: f64,
    },
    /// An entity's state became a non-finite number: finite extremes combined into an
    /// overflow (runtime/finite.rs). The step is refused before its frame is written.
    #[error(
        "expected a finite {quantity} of entity '{entity}' at t = {time:.3} s, found {value} (an overflow of extreme values)"
    )]
    NonFinite {
        /// The entity's name.
        entity: String,
        /// The state value (`x`, `speed`, `acceleration x`, …).
        quantity: &'static str,
        /// What it became.
        value: f64,
        /// Simulation time of the state (s).
        time: f64,
    },
    /// A host program gave an input to an entity that has no active `external` controller
    /// (engine module `controller`).
    #[error("expected an entity with an active external controller, found {found}")]
    NotExternal {
        /// The entity and what it has.
        found: String,
    },
    /// A host program gave an `external` controller an input the engine refuses
    /// ([`ExternalInput::check`](crate::controller::ExternalInput::check)): a value that is not
    /// finite, or a pedal outside 0..1. The input in force is kept.
    #[error("expected {expected}, found {found}")]
    ExternalInput {
        /// What the input must be.
        expected: String,
        /// The value given.
        found: String,
    },
    /// A host program set a parameter ([`Engine::set_parameter`](crate::Engine::set_parameter))
    /// to a value its declaration does not allow: one that does not convert to the declared
    /// type, or one outside its ConstraintGroups. The parameter keeps its value.
    #[error("expected {expected}, found {found}")]
    ParameterValue {
        /// The parameter's name.
        name: String,
        /// What the declaration allows.
        expected: String,
        /// The value given.
        found: String,
    },
    /// oscsim's state check (`scenario::StateCheck`) found the actor's state other than
    /// required when it started, or a RelativeAccelerationAction's speed change
    /// (`scenario::SpeedChange`) missed its time or the vehicle's rate: the run stops with
    /// this error.
    #[error("expected {expected} ({what}), found {found} at t = {time:.3} s")]
    CheckFailed {
        /// What was checked and where it is written.
        what: String,
        /// The state required.
        expected: String,
        /// The state found.
        found: String,
        /// Simulation time (s).
        time: f64,
    },
    /// A sink refused a frame or a record, or could not finish.
    #[error("cannot write {what}: {error}")]
    Output {
        /// Which output (`frames`, `events`).
        what: &'static str,
        /// The sink's error (in the message, so not also given as `source()`).
        error: crate::output::SinkError,
    },
}

impl From<StoryboardError> for Error {
    fn from(e: StoryboardError) -> Self {
        Error::new(ErrorKind::Storyboard(e))
    }
}

impl From<scenario::Error> for Error {
    fn from(e: scenario::Error) -> Self {
        Error::new(ErrorKind::Scenario(e))
    }
}

impl From<opendrive::Error> for Error {
    fn from(e: opendrive::Error) -> Self {
        Error::new(ErrorKind::RoadNetwork(e))
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;
    use std::sync::Arc;

    use super::*;

    /// The scenario position comes out of the kinds that carry one; a road-network error keeps
    /// its OpenDRIVE error (file and line:col) typed, and has no scenario position.
    #[test]
    fn pos_and_typed_sources() {
        let pos = SourcePos {
            file: Arc::from(Path::new("cut-in.xosc")),
            line: 12,
            col: 7,
        };
        let e = Error::at("a speed >= 0", "-3", &pos);
        assert_eq!(e.pos(), Some(&pos));
        assert_eq!(
            e.to_string(),
            "expected a speed >= 0, found -3 at cut-in.xosc:12:7"
        );

        let odr = opendrive::RoadNetwork::from_str("<OpenDRIVE>", Path::new("road.xodr"))
            .expect_err("unclosed root element");
        let e = Error::from(odr.clone());
        assert!(matches!(e.kind(), ErrorKind::RoadNetwork(inner) if *inner == odr));
        assert_eq!(e.pos(), None);
        assert_eq!(
            e.to_string(),
            format!("cannot load the road network: {odr}")
        );
    }
}
