//! The crate's one error type: a kind and, for what comes from a file, the file and the
//! 1-based line and column. Display is "expected X, found Y at file:line:col".

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use scenario::SourcePos;

/// What went wrong.
#[derive(Debug)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A file could not be read or written.
    Io {
        /// What was being done ("cannot read", "cannot write").
        action: &'static str,
        /// The operating system's error.
        source: std::io::Error,
    },
    /// A value in a run file (trajectory CSV, event log, run manifest) is not what was
    /// expected.
    Invalid {
        /// What was expected.
        expected: String,
        /// What was found.
        found: String,
    },
    /// A run has no manifest beside its trajectory CSV and none was given.
    NoManifest {
        /// Where it was looked for.
        looked_for: PathBuf,
    },
    /// The road network did not load.
    Road(opendrive::Error),
    /// The scenario did not load.
    Scenario(scenario::Error),
    /// The scenario (either language) did not load through the front door.
    Load(load::Error),
    /// The scenario did not build or run (the engine's error, its place included).
    Run(engine::Error),
    /// A chart could not be drawn or encoded.
    Plot(String),
}

/// An error of the replay crate; see [`ErrorKind`].
#[derive(Debug)]
pub struct Error {
    kind: ErrorKind,
    /// The file, when the error concerns one.
    file: Option<PathBuf>,
    /// The file and 1-based line and column, when known.
    pos: Option<SourcePos>,
}

impl Error {
    /// An error of `kind` with no place.
    pub(crate) fn new(kind: ErrorKind) -> Self {
        Error {
            kind,
            file: None,
            pos: None,
        }
    }

    /// An "expected …, found …" error at `file`, 1-based `line` and `col`.
    pub(crate) fn invalid(
        file: &Path,
        line: usize,
        col: usize,
        expected: impl Into<String>,
        found: impl Into<String>,
    ) -> Self {
        Error {
            kind: ErrorKind::Invalid {
                expected: expected.into(),
                found: found.into(),
            },
            file: Some(file.to_owned()),
            pos: Some(SourcePos::new(
                Arc::from(file),
                u32::try_from(line).unwrap_or(u32::MAX),
                u32::try_from(col).unwrap_or(u32::MAX),
            )),
        }
    }

    /// An I/O error on `file`.
    pub(crate) fn io(action: &'static str, file: &Path, source: std::io::Error) -> Self {
        Error {
            kind: ErrorKind::Io { action, source },
            file: Some(file.to_owned()),
            pos: None,
        }
    }

    /// What went wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }

    /// The file it concerns, if any.
    pub fn file(&self) -> Option<&Path> {
        self.file.as_deref()
    }

    /// The file and 1-based line and column, if known.
    pub fn pos(&self) -> Option<&SourcePos> {
        self.pos.as_ref()
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.kind {
            ErrorKind::Io { action, source } => {
                let file = self.file.as_deref().unwrap_or(Path::new("?"));
                return write!(f, "{action} {}: {source}", file.display());
            }
            ErrorKind::Invalid { expected, found } => {
                write!(f, "expected {expected}, found {found}")?
            }
            ErrorKind::NoManifest { looked_for } => write!(
                f,
                "no run manifest {} (oscsim run writes it beside its --csv file; or name the \
                 scenario with --scenario)",
                looked_for.display()
            )?,
            ErrorKind::Road(e) => write!(f, "road network: {e}")?,
            ErrorKind::Scenario(e) => write!(f, "scenario: {e}")?,
            ErrorKind::Load(e) => write!(f, "scenario: {e}")?,
            ErrorKind::Run(e) => write!(f, "run: {e}")?,
            ErrorKind::Plot(e) => write!(f, "chart: {e}")?,
        }
        match (&self.pos, &self.file) {
            (Some(pos), _) => write!(f, " at {pos}"),
            (None, Some(file)) => write!(f, " in {}", file.display()),
            (None, None) => Ok(()),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match &self.kind {
            ErrorKind::Io { source, .. } => Some(source),
            ErrorKind::Road(e) => Some(e),
            ErrorKind::Scenario(e) => Some(e),
            ErrorKind::Load(e) => Some(e),
            ErrorKind::Run(e) => Some(e),
            _ => None,
        }
    }
}

impl From<opendrive::Error> for Error {
    fn from(e: opendrive::Error) -> Self {
        Error::new(ErrorKind::Road(e))
    }
}

impl From<engine::Error> for Error {
    fn from(e: engine::Error) -> Self {
        Error::new(ErrorKind::Run(e))
    }
}

impl From<scenario::Error> for Error {
    fn from(e: scenario::Error) -> Self {
        Error::new(ErrorKind::Scenario(e))
    }
}

impl From<load::Error> for Error {
    fn from(e: load::Error) -> Self {
        Error::new(ErrorKind::Load(e))
    }
}

/// Result with [`Error`].
pub type Result<T> = std::result::Result<T, Error>;
