//! The comparison rules of OpenSCENARIO 1.3 (XSD `Rule`: greaterThan, lessThan, equalTo,
//! greaterOrEqual, lessOrEqual, notEqualTo) on measured numbers and on typed values.
//!
//! Measured numbers are floats, so `equalTo` holds within [`EQUAL_TOLERANCE`]: |a − b| ≤
//! 1e-9 · max(1, |a|, |b|), i.e. 1e-9 absolute for values up to 1 and relative beyond. This
//! absorbs the round-off of summed time steps (0.05 · 100 ≠ 5 exactly) and nothing a
//! scenario could mean. The strict rules exclude that band (a value within it is equal, so
//! not greater), the inclusive ones include it. `equalTo` on a continuously changing quantity
//! (a speed passing 10 m/s) is then true only if a sample lands within the band: use
//! greaterOrEqual / lessOrEqual with an edge for crossings.
//!
//! Typed values (ParameterCondition, VariableCondition, UserDefinedValueCondition): the
//! condition's text is parsed as the type of the current value; numbers compare as above,
//! booleans, strings and dateTimes only under equalTo / notEqualTo.

use scenario::expr::Value;
use scenario::Rule;

use super::ConditionErrorKind;

/// Relative (and, below 1, absolute) tolerance of `equalTo` on floats.
pub const EQUAL_TOLERANCE: f64 = crate::tolerance::VALUE;

/// `a rule b` on numbers, with `equalTo` within [`EQUAL_TOLERANCE`].
pub fn compare(a: f64, rule: Rule, b: f64) -> bool {
    let eq = (a - b).abs() <= EQUAL_TOLERANCE * a.abs().max(b.abs()).max(1.0);
    match rule {
        Rule::EqualTo => eq,
        Rule::NotEqualTo => !eq,
        Rule::GreaterThan => a > b && !eq,
        Rule::LessThan => a < b && !eq,
        Rule::GreaterOrEqual => a > b || eq,
        Rule::LessOrEqual => a < b || eq,
        // `Rule` is non-exhaustive; a future rule is not met rather than guessed.
        _ => false,
    }
}

/// The XSD literal of `rule`.
fn rule_name(rule: Rule) -> &'static str {
    match rule {
        Rule::EqualTo => "equalTo",
        Rule::NotEqualTo => "notEqualTo",
        Rule::GreaterThan => "greaterThan",
        Rule::LessThan => "lessThan",
        Rule::GreaterOrEqual => "greaterOrEqual",
        Rule::LessOrEqual => "lessOrEqual",
        _ => "unknown",
    }
}

/// `current rule text`, `text` read as `current`'s type.
pub(crate) fn compare_value(
    current: &Value,
    rule: Rule,
    text: &str,
) -> Result<bool, ConditionErrorKind> {
    let ty = current.value_type();
    let wanted = Value::parse(ty, text.trim()).map_err(|_| ConditionErrorKind::InvalidValue {
        expected: ty.xsd_name(),
        found: text.to_string(),
    })?;
    if ty.is_numeric() {
        // Both are numeric values of the same type: as_f64 is Some for every numeric Value.
        if let (Some(a), Some(b)) = (current.as_f64(), wanted.as_f64()) {
            return Ok(compare(a, rule, b));
        }
    }
    let equal = *current == wanted;
    match rule {
        Rule::EqualTo => Ok(equal),
        Rule::NotEqualTo => Ok(!equal),
        other => Err(ConditionErrorKind::UnorderedRule {
            value_type: ty.xsd_name(),
            rule: rule_name(other),
        }),
    }
}
