//! Errors of the OpenSCENARIO 1.3 §9.2 expression language: syntax, names, types and
//! arithmetic, each with the byte offset of the offending token.

use super::value_type::ValueType;

/// What went wrong in an expression. Each variant's Display reads "expected X, found Y".
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ExprErrorKind {
    /// A character that starts no token of the grammar.
    UnexpectedChar {
        /// The character.
        found: char,
    },
    /// A number literal that does not follow `digits ['.' digits] [('e'|'E') ['+'|'-'] digits]`
    /// or does not fit the 64-bit types.
    InvalidNumber {
        /// The literal as written.
        text: String,
    },
    /// A token where the grammar wants something else.
    UnexpectedToken {
        /// What the grammar allows here.
        expected: &'static str,
        /// The token found, as written (or "end of expression").
        found: String,
    },
    /// A `$name` that the lookup does not know.
    UnknownParameter {
        /// The parameter name, without `$`.
        name: String,
    },
    /// A call of a name that is none of the standard's functions.
    UnknownFunction {
        /// The name as written.
        name: String,
    },
    /// A call with the wrong number of arguments.
    WrongArity {
        /// The function's name.
        function: &'static str,
        /// How many arguments it takes.
        expected: usize,
        /// How many were given.
        found: usize,
    },
    /// An operand whose type the operator or function does not accept.
    WrongType {
        /// The operator or function, as written in the grammar (`+`, `and`, `sqrt`).
        operator: &'static str,
        /// The types accepted ("numeric", "boolean").
        expected: &'static str,
        /// The operand's type.
        found: ValueType,
    },
    /// `/` with a zero divisor.
    DivisionByZero,
    /// `%` with a zero divisor.
    ModuloByZero,
    /// An operation whose double result is NaN or infinite (e.g. `sqrt(-1)`, `pow(10, 400)`).
    NonFinite {
        /// The operator or function.
        operator: &'static str,
        /// The result, "NaN", "inf" or "-inf".
        found: f64,
    },
    /// An integer result outside the 64-bit range, or a double too large for `round`'s int.
    IntegerOverflow {
        /// The operator or function.
        operator: &'static str,
    },
    /// More than [`MAX_DEPTH`](super::MAX_DEPTH) nested parentheses, calls or operators.
    TooDeep {
        /// The limit.
        limit: usize,
    },
    /// A value that cannot take the requested type without loss (e.g. 2.5 as int).
    Conversion {
        /// The value, as displayed.
        value: String,
        /// Its own type.
        from: ValueType,
        /// The requested type.
        to: ValueType,
    },
}

impl std::fmt::Display for ExprErrorKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::UnexpectedChar { found } => {
                write!(
                    f,
                    "expected an operator, operand or parenthesis, found '{found}'"
                )
            }
            Self::InvalidNumber { text } => {
                write!(f, "expected a number literal, found '{text}'")
            }
            Self::UnexpectedToken { expected, found } => {
                write!(f, "expected {expected}, found {found}")
            }
            Self::UnknownParameter { name } => {
                write!(
                    f,
                    "expected a declared parameter, found unknown parameter '${name}'"
                )
            }
            Self::UnknownFunction { name } => {
                write!(
                    f,
                    "expected one of the standard's functions, found unknown function '{name}'"
                )
            }
            Self::WrongArity {
                function,
                expected,
                found,
            } => {
                write!(
                    f,
                    "expected {expected} argument(s) for {function}, found {found}"
                )
            }
            Self::WrongType {
                operator,
                expected,
                found,
            } => {
                write!(
                    f,
                    "expected {expected} operand(s) for {operator}, found {found}"
                )
            }
            Self::DivisionByZero => write!(f, "expected a non-zero divisor for /, found 0"),
            Self::ModuloByZero => write!(f, "expected a non-zero divisor for %, found 0"),
            Self::NonFinite { operator, found } => {
                write!(f, "expected a finite result of {operator}, found {found}")
            }
            Self::IntegerOverflow { operator } => {
                write!(f, "expected a result of {operator} within the 64-bit integer range, found an overflow")
            }
            Self::TooDeep { limit } => {
                write!(f, "expected at most {limit} nested levels, found more")
            }
            Self::Conversion { value, from, to } => {
                write!(
                    f,
                    "expected a value convertible to {to}, found {from} {value}"
                )
            }
        }
    }
}

/// An error in an expression: a kind and the byte offset in the expression's source (the text
/// between `${` and `}`) of the token that caused it.
///
/// Display gives the kind's message only ("expected X, found Y"); the caller, who knows the
/// file and where the attribute starts, appends `at file:row:col`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{kind}")]
pub struct ExprError {
    kind: ExprErrorKind,
    offset: usize,
}

impl ExprError {
    pub(crate) fn new(kind: ExprErrorKind, offset: usize) -> Self {
        Self { kind, offset }
    }

    /// What went wrong.
    pub fn kind(&self) -> &ExprErrorKind {
        &self.kind
    }

    /// Byte offset in the expression source of the offending token (0 for conversions of a
    /// whole result).
    pub fn offset(&self) -> usize {
        self.offset
    }
}
