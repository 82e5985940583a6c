//! The operators of OpenSCENARIO 1.3 §9.2.1 on typed values: `+ - * / %`, unary minus, the
//! comparisons and `not`/`and`/`or`, with the type rules this crate applies.
//!
//! Type rules (the standard gives only "numeric, numeric → numeric"; these make it concrete):
//! - Operands of `+ - * %` that are both integers give an integer, computed exactly (in 128
//!   bits) and typed `unsignedInt` when both operands are unsigned and the result is ≥ 0,
//!   otherwise `int`; a result outside 64 bits is an error, never a wrap-around.
//! - Any double operand makes the result a double (the other operand converts implicitly).
//! - `/` always gives a double: `5/2` is 2.5 (the standard evaluates in double precision).
//! - `%` is the remainder of truncated division (the sign follows the dividend), as C's
//!   `fmod`: `-7 % 3` is −1, `5.5 % 2` is 1.5.
//! - A zero divisor is an error for `/` and `%`, also for doubles; a double result that is
//!   NaN or infinite is an error.
//! - Comparisons take two numerics (`==`/`!=` also two booleans) and give a boolean; integers
//!   compare exactly, mixed integer/double pairs compare as doubles, doubles compare exactly
//!   (the standard names no tolerance).
//! - `not`, `and`, `or` take booleans only; numbers are not truth values.

use super::error::{ExprError, ExprErrorKind};
use super::value::Value;

/// A numeric operand after the implicit conversions.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Num {
    /// An integer (either signed or unsigned source), exactly.
    Integer { value: i128, unsigned: bool },
    /// A double.
    Double(f64),
}

impl Num {
    /// The numeric view of `value`, or a `WrongType` error naming `operator`.
    pub fn of(value: &Value, operator: &'static str, offset: usize) -> Result<Num, ExprError> {
        match *value {
            Value::Int(i) => Ok(Num::Integer {
                value: i128::from(i),
                unsigned: false,
            }),
            Value::UnsignedInt(u) => Ok(Num::Integer {
                value: i128::from(u),
                unsigned: true,
            }),
            Value::Double(d) => Ok(Num::Double(d)),
            _ => Err(wrong_type(operator, "numeric", value, offset)),
        }
    }

    /// As a double (implicit conversion).
    pub fn to_f64(self) -> f64 {
        match self {
            // Exact below 2^53; beyond, the nearest double, as the standard's double precision.
            Num::Integer { value, .. } => value as f64,
            Num::Double(d) => d,
        }
    }
}

/// A boolean operand, or a `WrongType` error naming `operator`.
pub(crate) fn boolean(
    value: &Value,
    operator: &'static str,
    offset: usize,
) -> Result<bool, ExprError> {
    value
        .as_bool()
        .ok_or_else(|| wrong_type(operator, "boolean", value, offset))
}

pub(crate) fn wrong_type(
    operator: &'static str,
    expected: &'static str,
    found: &Value,
    offset: usize,
) -> ExprError {
    ExprError::new(
        ExprErrorKind::WrongType {
            operator,
            expected,
            found: found.value_type(),
        },
        offset,
    )
}

/// An integer result as a [`Value`]: `UnsignedInt` if `unsigned` and ≥ 0, else `Int`; errors
/// outside 64 bits.
pub(crate) fn integer(
    value: i128,
    unsigned: bool,
    operator: &'static str,
    offset: usize,
) -> Result<Value, ExprError> {
    let overflow = || ExprError::new(ExprErrorKind::IntegerOverflow { operator }, offset);
    if unsigned && value >= 0 {
        u64::try_from(value)
            .map(Value::UnsignedInt)
            .map_err(|_| overflow())
    } else {
        i64::try_from(value).map(Value::Int).map_err(|_| overflow())
    }
}

/// A double result as a [`Value`], or a `NonFinite` error.
pub(crate) fn double(
    value: f64,
    operator: &'static str,
    offset: usize,
) -> Result<Value, ExprError> {
    if value.is_finite() {
        Ok(Value::Double(value))
    } else {
        Err(ExprError::new(
            ExprErrorKind::NonFinite {
                operator,
                found: value,
            },
            offset,
        ))
    }
}

/// Binary operators of the grammar.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum BinaryOp {
    Add,
    Sub,
    Mul,
    Div,
    Rem,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    And,
    Or,
}

impl BinaryOp {
    /// The operator as written.
    pub fn symbol(self) -> &'static str {
        match self {
            Self::Add => "+",
            Self::Sub => "-",
            Self::Mul => "*",
            Self::Div => "/",
            Self::Rem => "%",
            Self::Eq => "==",
            Self::Ne => "!=",
            Self::Lt => "<",
            Self::Le => "<=",
            Self::Gt => ">",
            Self::Ge => ">=",
            Self::And => "and",
            Self::Or => "or",
        }
    }

    /// Applies the operator; `offset` is the operator's position for errors.
    pub fn apply(self, lhs: &Value, rhs: &Value, offset: usize) -> Result<Value, ExprError> {
        let op = self.symbol();
        match self {
            Self::And => Ok(Value::Bool(
                boolean(lhs, op, offset)? & boolean(rhs, op, offset)?,
            )),
            Self::Or => Ok(Value::Bool(
                boolean(lhs, op, offset)? | boolean(rhs, op, offset)?,
            )),
            Self::Eq | Self::Ne if lhs.as_bool().is_some() || rhs.as_bool().is_some() => {
                let equal = boolean(lhs, op, offset)? == boolean(rhs, op, offset)?;
                Ok(Value::Bool(equal == (self == Self::Eq)))
            }
            Self::Eq | Self::Ne | Self::Lt | Self::Le | Self::Gt | Self::Ge => {
                let ordering = compare(Num::of(lhs, op, offset)?, Num::of(rhs, op, offset)?);
                Ok(Value::Bool(self.accepts(ordering)))
            }
            Self::Add | Self::Sub | Self::Mul | Self::Div | Self::Rem => {
                self.arithmetic(Num::of(lhs, op, offset)?, Num::of(rhs, op, offset)?, offset)
            }
        }
    }

    fn accepts(self, ordering: Option<std::cmp::Ordering>) -> bool {
        use std::cmp::Ordering::{Equal, Greater, Less};
        match (self, ordering) {
            (Self::Eq, Some(Equal)) | (Self::Lt, Some(Less)) | (Self::Gt, Some(Greater)) => true,
            (Self::Le, Some(Less | Equal)) | (Self::Ge, Some(Greater | Equal)) => true,
            (Self::Ne, o) => o != Some(Equal),
            _ => false,
        }
    }

    fn arithmetic(self, lhs: Num, rhs: Num, offset: usize) -> Result<Value, ExprError> {
        let op = self.symbol();
        let zero_divisor = match rhs {
            Num::Integer { value, .. } => value == 0,
            Num::Double(d) => d == 0.0,
        };
        if zero_divisor && self == Self::Div {
            return Err(ExprError::new(ExprErrorKind::DivisionByZero, offset));
        }
        if zero_divisor && self == Self::Rem {
            return Err(ExprError::new(ExprErrorKind::ModuloByZero, offset));
        }
        match (lhs, rhs) {
            (
                Num::Integer {
                    value: a,
                    unsigned: ua,
                },
                Num::Integer {
                    value: b,
                    unsigned: ub,
                },
            ) if self != Self::Div => {
                // |a|, |b| < 2^64: the sum and difference fit 128 bits, the product may not
                // ((2^64 − 1)² > 2^127 − 1), so it is checked; beyond 128 bits it is beyond 64.
                let exact = match self {
                    Self::Add => a.checked_add(b),
                    Self::Sub => a.checked_sub(b),
                    Self::Mul => a.checked_mul(b),
                    _ => a.checked_rem(b),
                };
                match exact {
                    Some(exact) => integer(exact, ua && ub, op, offset),
                    None => Err(ExprError::new(
                        ExprErrorKind::IntegerOverflow { operator: op },
                        offset,
                    )),
                }
            }
            _ => {
                let (a, b) = (lhs.to_f64(), rhs.to_f64());
                let result = match self {
                    Self::Add => a + b,
                    Self::Sub => a - b,
                    Self::Mul => a * b,
                    Self::Div => a / b,
                    _ => a % b,
                };
                double(result, op, offset)
            }
        }
    }
}

/// Orders two numerics: integers exactly, otherwise as doubles (`None` never occurs for the
/// finite values expressions produce, but is kept for NaN parameters).
fn compare(lhs: Num, rhs: Num) -> Option<std::cmp::Ordering> {
    match (lhs, rhs) {
        (Num::Integer { value: a, .. }, Num::Integer { value: b, .. }) => Some(a.cmp(&b)),
        _ => lhs.to_f64().partial_cmp(&rhs.to_f64()),
    }
}

/// Unary operators of the grammar.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum UnaryOp {
    /// `-x`.
    Neg,
    /// `not x`.
    Not,
}

impl UnaryOp {
    /// Applies the operator; `offset` is the operator's position for errors.
    pub fn apply(self, operand: &Value, offset: usize) -> Result<Value, ExprError> {
        match self {
            Self::Not => Ok(Value::Bool(!boolean(operand, "not", offset)?)),
            Self::Neg => match Num::of(operand, "unary -", offset)? {
                // The negation of an unsigned value is signed.
                Num::Integer { value, .. } => integer(-value, false, "unary -", offset),
                Num::Double(d) => Ok(Value::Double(-d)),
            },
        }
    }
}
