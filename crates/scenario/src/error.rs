//! The crate's error type: an [`ErrorKind`] and the [`SourcePos`] it happened at.
//!
//! Messages are short lowercase sentences, "expected X, found Y at file:row:col", so the
//! author of a scenario can go straight to the attribute or element at fault.

use std::fmt;
use std::path::PathBuf;

use crate::source::SourcePos;

/// What went wrong while loading a scenario.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A file could not be read.
    Io {
        /// What the file is for ("scenario", "road network", "catalog").
        what: &'static str,
        /// The path as resolved.
        path: PathBuf,
        /// The operating system's message.
        message: String,
    },
    /// The text is not well-formed XML (roxmltree's message).
    Xml {
        /// roxmltree's description, without its position.
        message: String,
    },
    /// An element in a place where the schema allows others.
    UnexpectedElement {
        /// The parent element.
        parent: String,
        /// The element found.
        found: String,
        /// What the schema allows, e.g. "one of SpeedAction, LaneChangeAction".
        expected: String,
    },
    /// A required child element is missing.
    MissingElement {
        /// The parent element.
        parent: String,
        /// The element expected.
        expected: String,
    },
    /// A required attribute is missing.
    MissingAttribute {
        /// The element.
        element: String,
        /// The attribute expected.
        attribute: &'static str,
    },
    /// An attribute value that does not fit the attribute's type.
    InvalidValue {
        /// The element.
        element: String,
        /// The attribute.
        attribute: String,
        /// What the schema allows ("a double", "one of rising, falling, …").
        expected: String,
        /// The value after parameter resolution.
        found: String,
    },
    /// `$name` with no declaration in scope.
    UnknownParameter {
        /// The parameter name, without `$`.
        name: String,
        /// The attribute that uses it.
        attribute: String,
    },
    /// Parameter declarations that refer to each other in a circle.
    ParameterCycle {
        /// The names along the cycle, first repeated at the end.
        cycle: Vec<String>,
    },
    /// Declarations of one block that refer to each other in a chain longer than the
    /// loader follows.
    ParameterChainTooLong {
        /// The limit (declarations in the chain).
        limit: usize,
    },
    /// A `${…}` expression that does not evaluate.
    Expression {
        /// The attribute holding the expression.
        attribute: String,
        /// The evaluator's message ("expected X, found Y").
        message: String,
    },
    /// A reference to an entity that is not declared.
    UnknownEntity {
        /// The name referred to.
        name: String,
        /// The element holding the reference.
        element: String,
    },
    /// Entity selections that contain each other.
    SelectionCycle {
        /// The selection names along the cycle, first repeated at the end.
        cycle: Vec<String>,
    },
    /// Two entities or selections with the same name.
    DuplicateEntity {
        /// The name.
        name: String,
    },
    /// A catalog reference whose catalog is in none of the catalog files searched.
    CatalogNotFound {
        /// The catalog name.
        catalog: String,
        /// Where it was looked for: every CatalogLocations directory.
        searched: Vec<PathBuf>,
        /// Those of `searched` that do not exist.
        missing: Vec<PathBuf>,
    },
    /// Catalog entries that refer to each other in a circle (a vehicle whose trailer is
    /// itself).
    CatalogCycle {
        /// "catalog/entry" along the cycle, first repeated at the end.
        cycle: Vec<String>,
    },
    /// Init actions whose positions or speeds refer to each other in a circle, so no order
    /// resolves them (`init_order.rs`).
    InitCycle {
        /// "entity's action" along the cycle, each referring to the next one's entity, the
        /// first entity repeated at the end.
        cycle: Vec<String>,
    },
    /// A catalog that exists but has no entry of that name.
    CatalogEntryNotFound {
        /// The catalog name.
        catalog: String,
        /// The entry name.
        entry: String,
        /// The files of that catalog.
        searched: Vec<PathBuf>,
    },
    /// A file named by the scenario (road network, catalog directory, scenario file) that does
    /// not exist.
    FileNotFound {
        /// What the file is for.
        what: &'static str,
        /// The path as written in the scenario.
        written: String,
        /// Where it was looked for.
        resolved: PathBuf,
    },
    /// A parameter value that breaks its ValueConstraintGroups.
    ConstraintViolated {
        /// The parameter.
        name: String,
        /// The value.
        value: String,
        /// The constraints, e.g. "greaterThan 0".
        expected: String,
    },
    /// A StoryboardElementStateCondition naming no storyboard element of its type.
    UnknownStoryboardElement {
        /// The type written.
        element_type: crate::model::StoryboardElementType,
        /// The name written.
        name: String,
    },
    /// A StoryboardElementStateCondition whose (qualified) name designates more than one
    /// storyboard element of its type.
    AmbiguousStoryboardElement {
        /// The type written.
        element_type: crate::model::StoryboardElementType,
        /// The reference written.
        name: String,
        /// The name paths of the elements it designates, in document order.
        candidates: Vec<String>,
    },
    /// A VariableAction or VariableCondition naming an undeclared variable.
    UnknownVariable {
        /// The name written.
        name: String,
    },
    /// A SetMonitorAction naming an undeclared monitor.
    UnknownMonitor {
        /// The name written.
        name: String,
    },
    /// Elements nested deeper than the reader follows.
    TooDeep {
        /// The element at the limit.
        element: String,
        /// The limit (levels of elements).
        limit: usize,
    },
    /// A file larger than the loader accepts.
    FileTooLarge {
        /// The file.
        path: PathBuf,
        /// Its size, bytes.
        size: u64,
        /// The limit, bytes.
        limit: u64,
    },
    /// A file whose root holds no scenario (e.g. a catalog given to `validate`).
    NotAScenario {
        /// What was found instead.
        found: String,
    },
    /// A FileHeader revision this crate does not read (revMajor other than 1).
    UnsupportedVersion {
        /// revMajor.rev_minor as written.
        found: String,
    },
    /// A `--param` override for a parameter the scenario does not declare globally.
    UnknownOverride {
        /// The name given.
        name: String,
    },
}

impl fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Io {
                what,
                path,
                message,
            } => {
                write!(f, "cannot read {what} file {}: {message}", path.display())
            }
            Self::Xml { message } => write!(f, "expected well-formed XML, found: {message}"),
            Self::UnexpectedElement {
                parent,
                found,
                expected,
            } => {
                write!(f, "expected {expected} in {parent}, found element {found}")
            }
            Self::MissingElement { parent, expected } => {
                write!(f, "expected element {expected} in {parent}, found none")
            }
            Self::MissingAttribute { element, attribute } => {
                write!(f, "expected attribute {attribute} on {element}, found none")
            }
            Self::InvalidValue {
                element,
                attribute,
                expected,
                found,
            } => {
                write!(
                    f,
                    "expected {expected} for {element}@{attribute}, found '{found}'"
                )
            }
            Self::UnknownParameter { name, attribute } => {
                write!(f, "expected a declared parameter in {attribute}, found unknown parameter '${name}'")
            }
            Self::ParameterCycle { cycle } => {
                write!(
                    f,
                    "expected acyclic parameter declarations, found cycle {}",
                    cycle.join(" → ")
                )
            }
            Self::Expression { attribute, message } => {
                write!(f, "in expression of {attribute}: {message}")
            }
            Self::UnknownEntity { name, element } => {
                write!(
                    f,
                    "expected a declared entity in {element}, found unknown entity '{name}'"
                )
            }
            Self::SelectionCycle { cycle } => {
                write!(f, "entity selection cycle: {}", cycle.join(" → "))
            }
            Self::DuplicateEntity { name } => {
                write!(
                    f,
                    "expected unique entity names, found '{name}' a second time"
                )
            }
            Self::CatalogNotFound {
                catalog,
                searched,
                missing,
            } => {
                write!(
                    f,
                    "expected catalog '{catalog}', found it in none of [{}]",
                    paths(searched)
                )?;
                if !missing.is_empty() {
                    write!(f, " (no such directory: {})", paths(missing))?;
                }
                Ok(())
            }
            Self::CatalogEntryNotFound {
                catalog,
                entry,
                searched,
            } => write!(
                f,
                "expected entry '{entry}' in catalog '{catalog}', found none in [{}]",
                paths(searched)
            ),
            Self::FileNotFound {
                what,
                written,
                resolved,
            } => write!(
                f,
                "expected {what} file '{written}', found no file at {}",
                resolved.display()
            ),
            Self::ConstraintViolated {
                name,
                value,
                expected,
            } => {
                write!(f, "expected parameter {name} {expected}, found {value}")
            }
            Self::FileTooLarge { path, size, limit } => write!(
                f,
                "expected a file of at most {} MiB, found {} with {:.1} MiB",
                limit / (1024 * 1024),
                path.display(),
                *size as f64 / (1024.0 * 1024.0)
            ),
            Self::UnknownStoryboardElement { element_type, name } => write!(
                f,
                "expected a storyboard element of type {element_type} named '{name}', found none"
            ),
            Self::AmbiguousStoryboardElement {
                element_type,
                name,
                candidates,
            } => write!(
                f,
                "expected '{name}' to name one storyboard element of type {element_type}, found {} ({}); \
                 prefix it with enclosing names (Maneuver::Event)",
                candidates.len(),
                candidates.join(", ")
            ),
            Self::UnknownVariable { name } => {
                write!(
                    f,
                    "expected a declared variable, found unknown variable '{name}'"
                )
            }
            Self::CatalogCycle { cycle } => write!(
                f,
                "expected catalog references without cycles, found {}",
                cycle.join(" → ")
            ),
            Self::InitCycle { cycle } => write!(
                f,
                "expected Init actions whose positions and speeds can be resolved in some order, found a cycle {}",
                cycle.join(" → ")
            ),
            Self::TooDeep { element, limit } => write!(
                f,
                "expected elements nested at most {limit} deep, found {element} deeper"
            ),
            Self::ParameterChainTooLong { limit } => write!(
                f,
                "expected parameter declarations referring to each other at most {limit} deep, found a longer chain"
            ),
            Self::UnknownMonitor { name } => {
                write!(
                    f,
                    "expected a declared monitor, found unknown monitor '{name}'"
                )
            }
            Self::NotAScenario { found } => {
                write!(
                    f,
                    "expected a scenario definition or parameter value distribution, found {found}"
                )
            }
            Self::UnsupportedVersion { found } => {
                write!(
                    f,
                    "expected OpenSCENARIO revision 1.0 to 1.3, found {found}"
                )
            }
            Self::UnknownOverride { name } => {
                write!(
                    f,
                    "expected a globally declared parameter to override, found unknown '{name}'"
                )
            }
        }
    }
}

fn paths(list: &[PathBuf]) -> String {
    let names: Vec<String> = list.iter().map(|p| p.display().to_string()).collect();
    names.join(", ")
}

/// An error while loading a scenario: what went wrong and where.
///
/// Display: "expected X, found Y at file:row:col".
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{kind} at {pos}")]
pub struct Error {
    kind: Box<ErrorKind>,
    pos: SourcePos,
}

impl Error {
    pub(crate) fn new(kind: ErrorKind, pos: SourcePos) -> Self {
        Self {
            kind: Box::new(kind),
            pos,
        }
    }

    /// What went wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }

    /// Where: the file and 1-based line and column of the element or attribute at fault.
    pub fn pos(&self) -> &SourcePos {
        &self.pos
    }
}

/// The crate's result type.
pub type Result<T, E = Error> = std::result::Result<T, E>;
