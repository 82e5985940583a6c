//! Values from outside the scenario for UserDefinedValueCondition (OpenSCENARIO 1.3 §7.6.2,
//! XSD `UserDefinedValueCondition`: "a value provided by an external source … compared to a
//! given value"): the text form of a value, a time series of values, and its CSV file.
//!
//! A host program sets values through [`Engine::set_user_value`](crate::Engine) between steps;
//! a run can also be given fixed values (`oscsim run --value NAME=VALUE`) or a time series
//! (`--values FILE.csv`), which the engine applies at the start of the first step at or after
//! each row's time, before that step's triggers.
//!
//! Text is typed the way a person writing `--value` means it: an integer or decimal number is a
//! `double` (so `greaterThan 10` compares numbers), `true`/`false` a `boolean`, anything else a
//! `string`. The condition's own value is then read as that type (condition/rule.rs).
//!
//! The CSV file has the header `time,name,value` and one row per change: time in seconds
//! (non-decreasing), the value's name, and the value's text (the rest of the line, so a string
//! value may hold commas). Blank lines are skipped. Written by hand (a few lines) rather than
//! with a CSV crate: no quoting rules are needed for three columns of which only the last is
//! free text.

use std::path::Path;
use std::sync::Arc;

use scenario::expr::Value;
use scenario::SourcePos;

/// A value set at a time.
#[derive(Debug, Clone, PartialEq)]
pub struct TimedValue {
    /// Simulation time from which the value holds (s).
    pub time: f64,
    /// The name UserDefinedValueConditions ask for.
    pub name: String,
    /// The value.
    pub value: Value,
}

/// Why a values file could not be read: the file, 1-based line and column, and what was
/// expected.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("expected {expected}, found {found} at {pos}")]
pub struct ValuesFileError {
    /// The file and 1-based line and column.
    pub pos: SourcePos,
    /// What was expected.
    pub expected: &'static str,
    /// What was found.
    pub found: String,
}

/// The typed value of `text` (see the module doc): a number is a double, `true`/`false` a
/// boolean, anything else a string.
pub fn parse_value(text: &str) -> Value {
    let t = text.trim();
    match t {
        "true" => Value::Bool(true),
        "false" => Value::Bool(false),
        _ => match t.parse::<f64>() {
            // "inf" and "NaN" parse as floats but are no numbers a person writes: strings.
            Ok(x) if x.is_finite() => Value::Double(x),
            _ => Value::String(t.to_owned()),
        },
    }
}

/// Reads a values file (see the module doc).
pub fn read_csv(path: &Path) -> Result<Vec<TimedValue>, ValuesFileError> {
    let text = std::fs::read_to_string(path).map_err(|e| ValuesFileError {
        pos: SourcePos::start_of(Arc::from(path)),
        expected: "a readable values file",
        found: e.to_string(),
    })?;
    parse_csv(&text, path)
}

/// Reads the text of a values file named `file` (for messages).
pub fn parse_csv(text: &str, file: impl AsRef<Path>) -> Result<Vec<TimedValue>, ValuesFileError> {
    let file: Arc<Path> = Arc::from(file.as_ref());
    let err = |line: usize, col: usize, expected: &'static str, found: &str| ValuesFileError {
        pos: SourcePos::new(
            Arc::clone(&file),
            u32::try_from(line).unwrap_or(u32::MAX),
            u32::try_from(col).unwrap_or(u32::MAX),
        ),
        expected,
        found: format!("'{found}'"),
    };
    let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l));
    match lines.next() {
        Some((_, header)) if header.trim() == "time,name,value" => {}
        Some((n, header)) => return Err(err(n, 1, "the header 'time,name,value'", header)),
        None => return Err(err(1, 1, "the header 'time,name,value'", "")),
    }
    let mut out: Vec<TimedValue> = Vec::new();
    for (n, line) in lines {
        if line.trim().is_empty() {
            continue;
        }
        let mut cells = line.splitn(3, ',');
        let (time, name, value) = match (cells.next(), cells.next(), cells.next()) {
            (Some(t), Some(k), Some(v)) => (t, k, v),
            _ => return Err(err(n, 1, "three cells 'time,name,value'", line)),
        };
        let time_value = match time.trim().parse::<f64>() {
            Ok(t) if t.is_finite() && t >= 0.0 => t,
            _ => return Err(err(n, 1, "a time in seconds ≥ 0", time)),
        };
        if out.last().is_some_and(|last| time_value < last.time) {
            return Err(err(n, 1, "times in non-decreasing order", time));
        }
        let name_col = time.chars().count() + 2;
        if name.trim().is_empty() {
            return Err(err(n, name_col, "a value name", name));
        }
        out.push(TimedValue {
            time: time_value,
            name: name.trim().to_owned(),
            value: parse_value(value),
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_typed_as_a_person_means_it() {
        assert_eq!(parse_value("12"), Value::Double(12.0));
        assert_eq!(parse_value(" -2.5e1 "), Value::Double(-25.0));
        assert_eq!(parse_value("true"), Value::Bool(true));
        assert_eq!(parse_value("on"), Value::String("on".into()));
        assert_eq!(parse_value("NaN"), Value::String("NaN".into()));
    }

    #[test]
    fn a_values_file_reads_in_order_with_free_text_values() {
        let rows = parse_csv("time,name,value\n0,Mode,a, b\n\n1.5,Speed,12\n", "v.csv").unwrap();
        assert_eq!(
            rows,
            [
                TimedValue {
                    time: 0.0,
                    name: "Mode".into(),
                    value: Value::String("a, b".into())
                },
                TimedValue {
                    time: 1.5,
                    name: "Speed".into(),
                    value: Value::Double(12.0)
                },
            ]
        );
    }

    #[test]
    fn bad_values_files_name_the_place() {
        let e = |text: &str| parse_csv(text, "v.csv").unwrap_err().to_string();
        assert_eq!(
            e("t,n,v\n"),
            "expected the header 'time,name,value', found 't,n,v' at v.csv:1:1"
        );
        assert_eq!(
            e("time,name,value\n2,A,1\n1,B,2\n"),
            "expected times in non-decreasing order, found '1' at v.csv:3:1"
        );
        assert_eq!(
            e("time,name,value\nsoon,A,1\n"),
            "expected a time in seconds ≥ 0, found 'soon' at v.csv:2:1"
        );
        assert_eq!(
            e("time,name,value\n1.25, ,1\n"),
            "expected a value name, found ' ' at v.csv:2:6"
        );
        assert_eq!(
            e("time,name,value\n1,A\n"),
            "expected three cells 'time,name,value', found '1,A' at v.csv:2:1"
        );
    }
}
