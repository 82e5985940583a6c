//! The functions of OpenSCENARIO 1.3 §9.2.1 ("operators with highest precedence" written as
//! calls, and `pow` of the middle precedence), with the signatures the standard lists:
//!
//! | function | signature | note |
//! | --- | --- | --- |
//! | `round`, `floor`, `ceil` | double → int | `round` rounds half away from zero |
//! | `sqrt`, `sin`, `cos`, `tan`, `asin`, `acos`, `atan` | double → double | radians |
//! | `sign`, `abs` | numeric → numeric | the operand's type is kept |
//! | `max`, `min` | numeric, numeric → numeric | integer if both are integers |
//! | `pow` | double, double → double | |
//!
//! Integer arguments convert implicitly to double where a double is asked for. A result that
//! is NaN or infinite (`sqrt(-1)`, `asin(2)`, `pow(0, -1)`) is an error, as is a `round`,
//! `floor` or `ceil` result outside the 64-bit integer range.

use super::arith::{double, integer, Num};
use super::error::{ExprError, ExprErrorKind};
use super::value::Value;

/// A built-in function of the expression language.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Function {
    /// `round(x)`: nearest integer, halves away from zero.
    Round,
    /// `floor(x)`: largest integer ≤ x.
    Floor,
    /// `ceil(x)`: smallest integer ≥ x.
    Ceil,
    /// `sqrt(x)`.
    Sqrt,
    /// `sin(x)`, x in radians.
    Sin,
    /// `cos(x)`, x in radians.
    Cos,
    /// `tan(x)`, x in radians.
    Tan,
    /// `asin(x)`, result in radians.
    Asin,
    /// `acos(x)`, result in radians.
    Acos,
    /// `atan(x)`, result in radians.
    Atan,
    /// `sign(x)`: −1, 0 or 1, of x's type.
    Sign,
    /// `abs(x)`, of x's type.
    Abs,
    /// `max(a, b)`.
    Max,
    /// `min(a, b)`.
    Min,
    /// `pow(a, b)`: a to the power b.
    Pow,
}

const TABLE: [(Function, &str); 15] = [
    (Function::Round, "round"),
    (Function::Floor, "floor"),
    (Function::Ceil, "ceil"),
    (Function::Sqrt, "sqrt"),
    (Function::Sin, "sin"),
    (Function::Cos, "cos"),
    (Function::Tan, "tan"),
    (Function::Asin, "asin"),
    (Function::Acos, "acos"),
    (Function::Atan, "atan"),
    (Function::Sign, "sign"),
    (Function::Abs, "abs"),
    (Function::Max, "max"),
    (Function::Min, "min"),
    (Function::Pow, "pow"),
];

impl Function {
    /// The function called `name` (case-sensitive, as the standard spells it).
    pub fn from_name(name: &str) -> Option<Self> {
        TABLE.iter().find(|(_, n)| *n == name).map(|(f, _)| *f)
    }

    /// The standard's name of the function.
    pub fn name(self) -> &'static str {
        // Every variant has exactly one row in TABLE.
        TABLE
            .iter()
            .find(|(f, _)| *f == self)
            .map_or("", |(_, n)| n)
    }

    /// How many arguments the function takes.
    pub fn arity(self) -> usize {
        match self {
            Self::Max | Self::Min | Self::Pow => 2,
            _ => 1,
        }
    }

    /// Applies the function to `args` (already checked to number [`arity`](Self::arity));
    /// `offset` is the function name's position for errors.
    pub(crate) fn apply(self, args: &[Value], offset: usize) -> Result<Value, ExprError> {
        let name = self.name();
        let num = |i: usize| Num::of(&args[i], name, offset);
        match self {
            Self::Round | Self::Floor | Self::Ceil => {
                let x = num(0)?.to_f64();
                let r = match self {
                    Self::Round => x.round(),
                    Self::Floor => x.floor(),
                    _ => x.ceil(),
                };
                // i64::MIN as f64 is exactly −2^63; doubles in [−2^63, 2^63) fit an i64.
                let bound = i64::MIN as f64;
                if !(bound..-bound).contains(&r) {
                    return Err(ExprError::new(
                        ExprErrorKind::IntegerOverflow { operator: name },
                        offset,
                    ));
                }
                Ok(Value::Int(r as i64))
            }
            Self::Sqrt
            | Self::Sin
            | Self::Cos
            | Self::Tan
            | Self::Asin
            | Self::Acos
            | Self::Atan => {
                let x = num(0)?.to_f64();
                let r = match self {
                    Self::Sqrt => x.sqrt(),
                    Self::Sin => x.sin(),
                    Self::Cos => x.cos(),
                    Self::Tan => x.tan(),
                    Self::Asin => x.asin(),
                    Self::Acos => x.acos(),
                    _ => x.atan(),
                };
                double(r, name, offset)
            }
            Self::Pow => double(num(0)?.to_f64().powf(num(1)?.to_f64()), name, offset),
            Self::Sign | Self::Abs => match num(0)? {
                Num::Integer { value, unsigned } => {
                    let r = if self == Self::Sign {
                        value.signum()
                    } else {
                        value.abs()
                    };
                    integer(r, unsigned, name, offset)
                }
                Num::Double(d) => {
                    let r = if self == Self::Abs {
                        d.abs()
                    } else if d == 0.0 {
                        0.0
                    } else {
                        d.signum()
                    };
                    Ok(Value::Double(r))
                }
            },
            Self::Max | Self::Min => {
                let (a, b) = (num(0)?, num(1)?);
                let take_first = match (a, b) {
                    (Num::Integer { value: x, .. }, Num::Integer { value: y, .. }) => {
                        if self == Self::Max {
                            x >= y
                        } else {
                            x <= y
                        }
                    }
                    _ => {
                        let (x, y) = (a.to_f64(), b.to_f64());
                        return Ok(Value::Double(if self == Self::Max {
                            x.max(y)
                        } else {
                            x.min(y)
                        }));
                    }
                };
                Ok(if take_first {
                    args[0].clone()
                } else {
                    args[1].clone()
                })
            }
        }
    }
}
