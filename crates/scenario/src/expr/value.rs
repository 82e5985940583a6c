//! Typed values of OpenSCENARIO 1.3 §9.1 "Parameters" and §9.2 "Expressions": the parameter
//! types of the XSD's `ParameterType` and the lossless conversions between them.
//!
//! Arithmetic works on 64-bit integers and doubles; the 32- and 16-bit ranges of the XSD types
//! `int`, `unsignedInt` and `unsignedShort` are checked only when a value is converted to a
//! declared type ([`Value::convert_to`], [`Value::parse`]). A double converts to an integer type
//! only when it is integral and in range (no silent rounding).

use super::error::{ExprError, ExprErrorKind};
use super::value_type::ValueType;

/// A typed value: a parameter's value or an expression's result.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// `boolean`.
    Bool(bool),
    /// `int` (computed in 64 bits).
    Int(i64),
    /// `unsignedInt` or `unsignedShort` (computed in 64 bits).
    UnsignedInt(u64),
    /// `double`.
    Double(f64),
    /// `string`.
    String(String),
    /// `dateTime`, kept as written (ISO 8601).
    DateTime(String),
}

impl Value {
    /// The value's type (`UnsignedInt` for both unsigned XSD types).
    pub fn value_type(&self) -> ValueType {
        match self {
            Self::Bool(_) => ValueType::Boolean,
            Self::Int(_) => ValueType::Int,
            Self::UnsignedInt(_) => ValueType::UnsignedInt,
            Self::Double(_) => ValueType::Double,
            Self::String(_) => ValueType::String,
            Self::DateTime(_) => ValueType::DateTime,
        }
    }

    /// The numeric value as a double (ints convert implicitly); `None` for the other types.
    pub fn as_f64(&self) -> Option<f64> {
        match *self {
            // i64/u64 → f64 rounds beyond 2^53; the standard computes in double precision.
            Self::Int(i) => Some(i as f64),
            Self::UnsignedInt(u) => Some(u as f64),
            Self::Double(d) => Some(d),
            _ => None,
        }
    }

    /// The value as a signed integer when that is lossless (an integral double in range too).
    pub fn as_i64(&self) -> Option<i64> {
        match *self {
            Self::Int(i) => Some(i),
            Self::UnsignedInt(u) => i64::try_from(u).ok(),
            Self::Double(d) => {
                integral_in_range(d, i64::MIN as f64, i64::MAX as f64).map(|d| d as i64)
            }
            _ => None,
        }
    }

    /// The value as an unsigned integer when that is lossless.
    pub fn as_u64(&self) -> Option<u64> {
        match *self {
            Self::Int(i) => u64::try_from(i).ok(),
            Self::UnsignedInt(u) => Some(u),
            Self::Double(d) => integral_in_range(d, 0.0, u64::MAX as f64).map(|d| d as u64),
            _ => None,
        }
    }

    /// The boolean value; `None` for the other types (numbers are not truth values, §9.2.1).
    pub fn as_bool(&self) -> Option<bool> {
        match *self {
            Self::Bool(b) => Some(b),
            _ => None,
        }
    }

    /// The text of a `string` or `dateTime` value.
    pub fn as_str(&self) -> Option<&str> {
        match self {
            Self::String(s) | Self::DateTime(s) => Some(s),
            _ => None,
        }
    }

    /// Parses a parameter's text (`value` attribute of a `ParameterDeclaration`) as type `ty`.
    ///
    /// `boolean` takes `true`/`false` (and the XSD's `1`/`0`); the integer types take decimal
    /// integers in their XSD range; `double` takes any decimal or exponent form Rust's `f64`
    /// parser reads, but no NaN or infinity. Errors have kind `Conversion` and offset 0.
    pub fn parse(ty: ValueType, text: &str) -> Result<Value, ExprError> {
        let fail = || conversion_error(&Value::String(text.to_owned()), ty);
        let t = text.trim();
        match ty {
            ValueType::Boolean => match t {
                "true" | "1" => Ok(Value::Bool(true)),
                "false" | "0" => Ok(Value::Bool(false)),
                _ => Err(fail()),
            },
            ValueType::Int => t
                .parse::<i32>()
                .map(|i| Value::Int(i64::from(i)))
                .map_err(|_| fail()),
            ValueType::UnsignedInt => t
                .parse::<u32>()
                .map(|u| Value::UnsignedInt(u64::from(u)))
                .map_err(|_| fail()),
            ValueType::UnsignedShort => t
                .parse::<u16>()
                .map(|u| Value::UnsignedInt(u64::from(u)))
                .map_err(|_| fail()),
            ValueType::Double => match t.parse::<f64>() {
                Ok(d) if d.is_finite() => Ok(Value::Double(d)),
                _ => Err(fail()),
            },
            ValueType::String => Ok(Value::String(text.to_owned())),
            ValueType::DateTime => Ok(Value::DateTime(text.to_owned())),
        }
    }

    /// Converts an expression result to the declared type of the attribute or parameter it is
    /// assigned to, without loss: ints widen to double, integral doubles in range narrow to the
    /// integer types, anything becomes a string through Display; booleans and strings do not
    /// become numbers. Errors have kind `Conversion` and offset 0.
    pub fn convert_to(&self, ty: ValueType) -> Result<Value, ExprError> {
        let fail = || conversion_error(self, ty);
        match ty {
            ValueType::Boolean => self.as_bool().map(Value::Bool).ok_or_else(fail),
            ValueType::Int => self
                .as_i64()
                .filter(|i| i32::try_from(*i).is_ok())
                .map(Value::Int)
                .ok_or_else(fail),
            ValueType::UnsignedInt => self
                .as_u64()
                .filter(|u| u32::try_from(*u).is_ok())
                .map(Value::UnsignedInt)
                .ok_or_else(fail),
            ValueType::UnsignedShort => self
                .as_u64()
                .filter(|u| u16::try_from(*u).is_ok())
                .map(Value::UnsignedInt)
                .ok_or_else(fail),
            ValueType::Double => self.as_f64().map(Value::Double).ok_or_else(fail),
            ValueType::String => Ok(Value::String(self.to_string())),
            ValueType::DateTime => match self {
                Value::DateTime(s) | Value::String(s) => Ok(Value::DateTime(s.clone())),
                _ => Err(fail()),
            },
        }
    }
}

fn conversion_error(value: &Value, to: ValueType) -> ExprError {
    ExprError::new(
        ExprErrorKind::Conversion {
            value: value.to_string(),
            from: value.value_type(),
            to,
        },
        0,
    )
}

fn integral_in_range(d: f64, min: f64, max: f64) -> Option<f64> {
    // `max` as f64 is 2^63 or 2^64 (rounded up), so the bound is exclusive.
    (d.is_finite() && d.fract() == 0.0 && d >= min && d < max).then_some(d)
}

/// Writes the value as it would appear in an attribute: `true`, `42`, `2.5`, the text of
/// strings. Doubles use Rust's shortest round-trip form (`0.1`, `6`, `1e-7` as `0.0000001`),
/// so parsing the text back gives the same double.
impl std::fmt::Display for Value {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Bool(b) => write!(f, "{b}"),
            Self::Int(i) => write!(f, "{i}"),
            Self::UnsignedInt(u) => write!(f, "{u}"),
            Self::Double(d) => write!(f, "{d}"),
            Self::String(s) | Self::DateTime(s) => f.write_str(s),
        }
    }
}

impl From<bool> for Value {
    fn from(b: bool) -> Self {
        Self::Bool(b)
    }
}

impl From<i64> for Value {
    fn from(i: i64) -> Self {
        Self::Int(i)
    }
}

impl From<u64> for Value {
    fn from(u: u64) -> Self {
        Self::UnsignedInt(u)
    }
}

impl From<f64> for Value {
    fn from(d: f64) -> Self {
        Self::Double(d)
    }
}

impl From<&str> for Value {
    fn from(s: &str) -> Self {
        Self::String(s.to_owned())
    }
}
