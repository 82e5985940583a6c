//! The crate's one error, [`Error`]: a DSL file that does not check or resolve with the seed
//! (`dsl`'s error, typed), a road network that does not read (`opendrive`'s, typed), or a
//! scenario that cannot be planned and lowered, with the place in the `.osc` file it is about
//! (`FILE:LINE:COL`), found before the run starts. Also where each construct is written
//! ([`Site`], [`Files`]), so the stages after `resolve` report errors without the program's
//! files.

use std::fmt;
use std::path::Path;
use std::sync::Arc;

use dsl::semantics::hir::Span;
use dsl::Source;
use scenario::SourcePos;

/// What went wrong: the kinds of [`Error`].
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The file did not pass the language checks, or its constraints have no solution for
    /// the seed (`dsl`'s error: every error of the file, in source order).
    Check(dsl::Error),
    /// The road network could not be read (`opendrive`'s error, with the `.xodr` position).
    RoadNetwork(opendrive::Error),
    /// The file has no scenario with a `do` to run, or several.
    NoScenario,
    /// An actor expression that names no vehicle of the program.
    UnknownActor,
    /// A modifier the action does not take, or that the runtime does not run.
    Modifier,
    /// A form of the standard the runtime does not run (docs/dsl.md, "Not run yet"), or one of
    /// its resource guards (invocations nested deeper than 64). Never bad input: a scenario
    /// that is wrong has one of the other kinds.
    Unsupported,
    /// An invocation that names nothing to run (§7.3.9): a scenario invoked without an actor
    /// and without a `do`, an action the program declares with no `do` and no §8.8 action
    /// among its ancestors, a `keep(…)` in the `with:` of an invocation outside a `do`.
    Invocation,
    /// A `call` (§7.3.10 `on` handlers, `call` directives) of something that is not a method
    /// with an implementation: no method call, no method the program declares, a method
    /// `is undefined`, or an `on` member other than `emit` and `call`.
    Call,
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

/// An error of checking, planning or lowering a DSL scenario: its kind and, for the planner's
/// own kinds, the message and the place in the `.osc` file.
#[derive(Debug, Clone, PartialEq)]
pub struct Error(Box<Inner>);

#[derive(Debug, Clone, PartialEq)]
struct Inner {
    kind: ErrorKind,
    /// The planner's message and place; `None` for [`ErrorKind::Check`] and
    /// [`ErrorKind::RoadNetwork`], whose errors hold their own.
    at: Option<(String, SourcePos)>,
}

impl Error {
    /// An error of `kind` at `pos`; `message` is lowercase ("expected …, found …").
    pub(crate) fn new(kind: ErrorKind, message: impl Into<String>, pos: SourcePos) -> Error {
        Error(Box::new(Inner {
            kind,
            at: Some((message.into(), pos)),
        }))
    }

    /// An error about file `file` as a whole, placed at its start (1:1).
    pub(crate) fn at_start_of(kind: ErrorKind, message: impl Into<String>, file: &Path) -> Error {
        Error::new(kind, message, SourcePos::start_of(Arc::from(file)))
    }

    /// What went wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.0.kind
    }

    /// Where: the construct's file and 1-based line and column; for [`ErrorKind::Check`] the
    /// first error's, for [`ErrorKind::RoadNetwork`] the `.xodr` file's (its start when the
    /// error is about the file as a whole; `None` when it names no file).
    pub fn pos(&self) -> Option<SourcePos> {
        match (&self.0.kind, &self.0.at) {
            (_, Some((_, pos))) => Some(pos.clone()),
            (ErrorKind::Check(e), None) => Some(e.pos()),
            (ErrorKind::RoadNetwork(e), None) => e
                .pos()
                .cloned()
                .or_else(|| e.file().map(|f| SourcePos::start_of(f.into()))),
            (_, None) => None,
        }
    }
}

impl From<dsl::Error> for Error {
    fn from(e: dsl::Error) -> Error {
        Error(Box::new(Inner {
            kind: ErrorKind::Check(e),
            at: None,
        }))
    }
}

impl From<opendrive::Error> for Error {
    fn from(e: opendrive::Error) -> Error {
        Error(Box::new(Inner {
            kind: ErrorKind::RoadNetwork(e),
            at: None,
        }))
    }
}

/// The planner's errors read "MESSAGE at FILE:LINE:COL"; a check's or a road network's are
/// their own crate's text.
impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (&self.0.kind, &self.0.at) {
            (_, Some((message, pos))) => write!(f, "{message} at {pos}"),
            (ErrorKind::Check(e), None) => e.fmt(f),
            (ErrorKind::RoadNetwork(e), None) => e.fmt(f),
            // Not made: `Error::new` gives the planner's kinds their message and place.
            (kind, None) => write!(f, "{kind:?}"),
        }
    }
}

/// The text names the inner error and its place, so the error has no `source`: a chain printer
/// shows it once.
impl std::error::Error for Error {}

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
