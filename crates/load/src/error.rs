//! The front door's one error: what did not load, with the place in the file it is about
//! (`FILE:LINE:COL`), whichever language the scenario was written in.

use std::fmt;

use source::SourcePos;

/// What went wrong.
#[derive(Debug)]
#[non_exhaustive]
pub enum ErrorKind {
    /// An OpenSCENARIO XML scenario, a catalog or a parameter value did not load.
    Scenario(scenario::Error),
    /// The road network did not load.
    RoadNetwork(opendrive::Error),
    /// An OpenSCENARIO DSL file did not pass the language checks, or its constraints have no
    /// solution (`dsl`'s error: every error of the file, in source order).
    Check(dsl::Error),
    /// An OpenSCENARIO DSL scenario that checks but cannot be planned.
    Plan(dsl_runtime::Error),
    /// An option the scenario's language does not take (`road` for an XML scenario, which
    /// names its own; parameter overrides for a DSL one, which varies by seed).
    Option {
        /// Lowercase "expected …, found …".
        message: String,
        /// The scenario file (1:1).
        pos: SourcePos,
    },
}

/// A scenario that could not be made ready to run.
#[derive(Debug)]
pub struct Error(Box<ErrorKind>);

impl Error {
    /// What went wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.0
    }

    /// What went wrong, taken out of the error.
    pub fn into_kind(self) -> ErrorKind {
        *self.0
    }

    /// Where: the file, line and column of the first error (the file's start when the error
    /// is about the file as a whole; `None` for a road network error that names no file).
    pub fn pos(&self) -> Option<SourcePos> {
        match self.kind() {
            ErrorKind::Scenario(e) => Some(e.pos().clone()),
            ErrorKind::RoadNetwork(e) => e
                .pos()
                .cloned()
                .or_else(|| e.file().map(|f| SourcePos::start_of(f.into()))),
            ErrorKind::Check(e) => Some(e.pos()),
            ErrorKind::Plan(e) => e.pos(),
            ErrorKind::Option { pos, .. } => Some(pos.clone()),
        }
    }

    pub(crate) fn option(message: String, pos: SourcePos) -> Self {
        Error(Box::new(ErrorKind::Option { message, pos }))
    }
}

impl From<ErrorKind> for Error {
    fn from(kind: ErrorKind) -> Self {
        Error(Box::new(kind))
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.kind() {
            ErrorKind::Scenario(e) => e.fmt(f),
            ErrorKind::RoadNetwork(e) => write!(f, "cannot load the road network: {e}"),
            ErrorKind::Check(d) => d.fmt(f),
            ErrorKind::Plan(e) => e.fmt(f),
            ErrorKind::Option { message, pos } => write!(f, "{message} at {pos}"),
        }
    }
}

/// The message names everything (the inner error's text and place), so the error has no
/// `source`: a chain printer (`{:#}` of anyhow) shows it once.
impl std::error::Error for Error {}
