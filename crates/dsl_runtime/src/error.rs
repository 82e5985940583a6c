//! Errors of planning and lowering, each with the place in the `.osc` file it is about
//! (`FILE:LINE:COL`), found before the run starts.

use std::fmt;

use dsl::semantics::hir::Span;
use dsl::Source;

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

/// A planning error.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct Error {
    /// What went wrong.
    pub kind: ErrorKind,
    /// Lowercase message ("expected …, found …").
    pub message: String,
    /// `FILE:LINE:COL` of the construct.
    pub at: String,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} at {}", self.message, self.at)
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
    pub pos: scenario::SourcePos,
}

impl Site {
    /// `FILE:LINE:COL`.
    pub(crate) fn at(&self) -> String {
        self.pos.to_string()
    }

    /// An error of `kind` here.
    pub(crate) fn err(&self, kind: ErrorKind, message: impl Into<String>) -> Error {
        Error {
            kind,
            message: message.into(),
            at: self.at(),
        }
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
