//! Errors of reading and expanding an OpenSCENARIO 1.3 §9.5 parameter value distribution file,
//! each with the file and the 1-based line:column (a [`SourcePos`]) of the element or attribute at fault.

use crate::SourcePos;

/// Most parameter sets one distribution file may produce (memory bound against typos such as a
/// tiny `stepWidth`).
pub const MAX_RUNS: usize = 100_000;

/// What went wrong. Each variant's Display reads "expected X, found Y".
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum DistributionErrorKind {
    /// The file could not be read.
    Io {
        /// The operating system's message.
        message: String,
    },
    /// The file is not well-formed XML.
    Xml {
        /// roxmltree's message, without its position.
        message: String,
    },
    /// An element where another is required.
    UnexpectedElement {
        /// The element(s) allowed here.
        expected: String,
        /// The element found.
        found: String,
    },
    /// A required child element is missing.
    MissingElement {
        /// The parent element.
        parent: String,
        /// The missing child.
        expected: &'static str,
    },
    /// A required attribute is missing.
    MissingAttribute {
        /// The element.
        element: String,
        /// The attribute.
        attribute: &'static str,
    },
    /// An attribute whose value is out of its domain.
    InvalidAttribute {
        /// The element.
        element: String,
        /// The attribute.
        attribute: &'static str,
        /// What the value must be.
        expected: &'static str,
        /// The value as written.
        found: String,
    },
    /// A distribution oscsim cannot sample (`UserDefinedDistribution`).
    Unsupported {
        /// The element.
        element: String,
        /// Its `type` attribute.
        kind: String,
    },
    /// A parameter named by two distributions.
    DuplicateParameter {
        /// The parameter.
        name: String,
    },
    /// More concrete parameter sets than [`MAX_RUNS`](super::MAX_RUNS).
    TooManyRuns {
        /// The limit.
        limit: usize,
        /// How many the distributions would give (saturating).
        found: u128,
    },
    /// A truncated distribution that gave no sample inside its `Range`.
    RangeUnreachable {
        /// How many draws were tried for one value.
        attempts: u32,
    },
    /// Truncation ranges discarded more draws over the plan than
    /// [`MAX_REJECTED_DRAWS`](super::stochastic::MAX_REJECTED_DRAWS); reported at the
    /// distribution whose draw went over.
    RangeRarelyReached {
        /// The limit on discarded draws.
        limit: u64,
    },
}

impl std::fmt::Display for DistributionErrorKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Io { message } => write!(f, "expected a readable file, found {message}"),
            Self::Xml { message } => write!(f, "expected well-formed XML, found {message}"),
            Self::UnexpectedElement { expected, found } => write!(f, "expected {expected}, found <{found}>"),
            Self::MissingElement { parent, expected } => {
                write!(f, "expected <{expected}> in <{parent}>, found none")
            }
            Self::MissingAttribute { element, attribute } => {
                write!(f, "expected attribute {attribute} on <{element}>, found none")
            }
            Self::InvalidAttribute { element, attribute, expected, found } => {
                write!(f, "expected {expected} for {element}@{attribute}, found '{found}'")
            }
            Self::Unsupported { element, kind } => {
                write!(f, "expected a distribution oscsim can sample, found <{element}> of type '{kind}'")
            }
            Self::DuplicateParameter { name } => {
                write!(f, "expected each parameter in one distribution only, found '{name}' again")
            }
            Self::TooManyRuns { limit, found } => {
                write!(f, "expected at most {limit} parameter sets, found {found}")
            }
            Self::RangeUnreachable { attempts } => write!(
                f,
                "expected a Range the distribution reaches, found no sample inside it in {attempts} draws"
            ),
            Self::RangeRarelyReached { limit } => write!(
                f,
                "expected Ranges the distributions reach more often, found more than {limit} draws outside them"
            ),
        }
    }
}

/// An error in a parameter value distribution file: kind, file and position.
///
/// Display: "expected X, found Y at file:line:col".
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{kind} at {pos}")]
pub struct DistributionError {
    kind: DistributionErrorKind,
    pos: SourcePos,
}

impl DistributionError {
    pub(crate) fn new(kind: DistributionErrorKind, pos: SourcePos) -> Self {
        Self { kind, pos }
    }

    /// What went wrong.
    pub fn kind(&self) -> &DistributionErrorKind {
        &self.kind
    }

    /// The distribution file.
    pub fn file(&self) -> &std::path::Path {
        &self.pos.file
    }

    /// The file and where in it (1:1 for errors of the whole file).
    pub fn pos(&self) -> &SourcePos {
        &self.pos
    }
}
