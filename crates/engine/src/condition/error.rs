//! Errors of condition evaluation (OpenSCENARIO 1.3 §7.6): what was expected, what was found,
//! and where the condition was written ("expected X, found Y at file:line:col").

use scenario::SourcePos;

use crate::position::PositionError;

/// Why a condition could not be evaluated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ConditionErrorKind {
    /// An `entityRef` (triggering or reference entity) names no placed entity.
    #[error("expected a placed entity named \"{0}\", found none")]
    UnknownEntity(String),
    /// A ParameterCondition names an undeclared parameter.
    #[error("expected a declared parameter named \"{0}\", found none")]
    UnknownParameter(String),
    /// A VariableCondition names an undeclared variable.
    #[error("expected a declared variable named \"{0}\", found none")]
    UnknownVariable(String),
    /// A StoryboardElementStateCondition names no storyboard element of that type.
    #[error("expected a storyboard element {kind} named \"{name}\", found none")]
    UnknownElement {
        /// The XSD storyboardElementType literal.
        kind: &'static str,
        /// The name.
        name: String,
    },
    /// A StoryboardElementStateCondition's (qualified) name designates several elements of
    /// that type.
    #[error("expected \"{name}\" to name one storyboard element {kind}, found {found}; prefix it with enclosing names (Maneuver::Event)")]
    AmbiguousElement {
        /// The XSD storyboardElementType literal.
        kind: &'static str,
        /// The reference.
        name: String,
        /// How many elements it designates.
        found: usize,
    },
    /// The condition's `value` cannot be read as the type of the value it is compared with.
    #[error("expected a {expected} value, found \"{found}\"")]
    InvalidValue {
        /// The type expected (XSD ParameterType literal).
        expected: &'static str,
        /// The text found.
        found: String,
    },
    /// An ordering rule on values that have no order (booleans, strings).
    #[error("expected equalTo or notEqualTo for a {value_type} value, found rule {rule}")]
    UnorderedRule {
        /// The XSD ParameterType literal of the value.
        value_type: &'static str,
        /// The rule, as written.
        rule: &'static str,
    },
    /// TimeOfDayCondition: the dateTime is not an xsd:dateTime.
    #[error("expected an xsd:dateTime like 2020-10-12T12:00:00, found \"{0}\"")]
    InvalidDateTime(String),
    /// A position inside the condition could not be resolved.
    #[error("{0}")]
    Position(PositionError),
    /// A measurement oscsim does not support (yet).
    #[error("expected {expected}, found {found} (not supported by oscsim)")]
    Unsupported {
        /// What oscsim supports.
        expected: &'static str,
        /// What was found.
        found: &'static str,
    },
}

/// A condition that could not be evaluated: the kind and where the condition was written.
/// Boxed, so that `Result<bool, ConditionError>` stays small.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", display(.0))]
pub struct ConditionError(Box<Inner>);

/// The contents of a [`ConditionError`].
#[derive(Debug, Clone, PartialEq)]
struct Inner {
    kind: ConditionErrorKind,
    pos: SourcePos,
}

/// A position error already names its own place; every other kind gets the condition's.
fn display(inner: &Inner) -> String {
    match &inner.kind {
        ConditionErrorKind::Position(e) => format!("{e} (in condition at {})", inner.pos),
        kind => format!("{kind} at {}", inner.pos),
    }
}

impl ConditionError {
    /// An error of `kind` for the condition written at `pos`.
    pub(crate) fn new(kind: ConditionErrorKind, pos: &SourcePos) -> Self {
        Self(Box::new(Inner {
            kind,
            pos: pos.clone(),
        }))
    }

    /// What went wrong.
    pub fn kind(&self) -> &ConditionErrorKind {
        &self.0.kind
    }

    /// Where the condition was written (file, 1-based line and column).
    pub fn pos(&self) -> &SourcePos {
        &self.0.pos
    }
}
