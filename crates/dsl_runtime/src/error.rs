//! Errors of planning and lowering, each with the place in the `.osc` file it is about
//! (`FILE:LINE:COL`), found before the run starts.

use std::fmt;
use std::path::Path;
use std::sync::Arc;

use dsl::semantics::hir::Span;
use dsl::Source;
use scenario::SourcePos;

/// What went wrong.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The file has no scenario with a `do` to run, or several.
    NoScenario,
    /// An actor expression that names no vehicle of the program.
    UnknownActor,
    /// A modifier the action does not take, or that the runtime does not run.
    Modifier,
    /// An action or behavior the runtime does not run.
    Unsupported,
    /// An action's argument is missing or has a value the action cannot take.
    Argument,
    /// A phase that cannot end (no duration, no `until`, nothing that ends it).
    NoEnd,
    /// Constraints the planner cannot meet (`at: end` out of the vehicle's limits, a lane that
    /// does not exist).
    Unsatisfiable,
    /// A value that is not a constant the planner can compute.
    Value,
    /// A condition (`until`, `wait`) the runtime cannot evaluate.
    Condition,
    /// The road network does not offer what the scenario needs.
    Road,
}

/// A planning error: what kind, the message, and the place in the `.osc` file.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct Error {
    kind: ErrorKind,
    message: String,
    pos: SourcePos,
}

impl Error {
    /// An error of `kind` at `pos`; `message` is lowercase ("expected …, found …").
    pub(crate) fn new(kind: ErrorKind, message: impl Into<String>, pos: SourcePos) -> Error {
        Error {
            kind,
            message: message.into(),
            pos,
        }
    }

    /// An error about file `file` as a whole, placed at its start (1:1).
    pub fn at_start_of(kind: ErrorKind, message: impl Into<String>, file: &Path) -> Error {
        Error::new(kind, message, SourcePos::start_of(Arc::from(file)))
    }

    /// What went wrong.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// Where: the construct's file and 1-based line and column.
    pub fn pos(&self) -> &SourcePos {
        &self.pos
    }

    /// The message without the position.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} at {}", self.message, self.pos)
    }
}

/// Where a construct is written: its span (which construct it is) and its place in the file
/// (for messages, and the scenario model's positions). Every resolved item carries one, so the
/// stages after `resolve` report errors without going back to the program's files.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Site {
    /// The construct's bytes.
    pub span: Span,
    /// Its file, line and column.
    pub pos: SourcePos,
}

impl Site {
    /// `FILE:LINE:COL`.
    pub(crate) fn at(&self) -> String {
        self.pos.to_string()
    }

    /// An error of `kind` here.
    pub(crate) fn err(&self, kind: ErrorKind, message: impl Into<String>) -> Error {
        Error::new(kind, message, self.pos.clone())
    }
}

/// Places spans in the program's files.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Files<'a>(pub &'a [Source]);

impl Files<'_> {
    /// The site of `span`.
    pub(crate) fn site(&self, span: Span) -> Site {
        Site {
            span,
            pos: dsl::source_pos(self.0, span),
        }
    }

    /// An error of `kind` at `span`.
    pub(crate) fn err(&self, kind: ErrorKind, span: Span, message: impl Into<String>) -> Error {
        self.site(span).err(kind, message)
    }
}
