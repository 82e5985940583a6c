//! Errors of the runtime: building an engine from a scenario and running it.
//!
//! Messages follow the project's form "expected X, found Y at file:line:col"; the place is the
//! scenario element (action, position, entity reference) that caused the error.

use scenario::SourcePos;

use crate::storyboard::StoryboardError;

/// An error building or running an [`Engine`](super::Engine).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{kind}")]
pub struct RuntimeError {
    kind: RuntimeErrorKind,
}

impl RuntimeError {
    pub(crate) fn new(kind: RuntimeErrorKind) -> Self {
        RuntimeError { kind }
    }

    /// What went wrong.
    pub fn kind(&self) -> &RuntimeErrorKind {
        &self.kind
    }

    /// An error at a scenario element: expected `expected`, found `found`, at `pos`.
    pub(crate) fn at(
        expected: impl Into<String>,
        found: impl Into<String>,
        pos: &SourcePos,
    ) -> Self {
        RuntimeError::new(RuntimeErrorKind::Invalid {
            expected: expected.into(),
            found: found.into(),
            pos: pos.clone(),
        })
    }

    /// An unsupported feature at `pos`.
    pub(crate) fn unsupported(what: impl Into<String>, pos: &SourcePos) -> Self {
        RuntimeError::new(RuntimeErrorKind::Unsupported {
            what: what.into(),
            pos: pos.clone(),
        })
    }
}

/// The kinds of [`RuntimeError`].
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RuntimeErrorKind {
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
    /// A sink refused a frame or a record, or could not finish.
    #[error("cannot write {what}: {error}")]
    Output {
        /// Which output (`frames`, `events`).
        what: &'static str,
        /// The sink's error (in the message, so not also given as `source()`).
        error: crate::output::SinkError,
    },
}

impl From<StoryboardError> for RuntimeError {
    fn from(e: StoryboardError) -> Self {
        RuntimeError::new(RuntimeErrorKind::Storyboard(e))
    }
}
