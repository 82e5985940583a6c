//! Types shared by several chapters of OpenSCENARIO 1.3: parameter declarations (§9.1),
//! catalog provenance (§9.4), Properties, FileHeader, Range.

use std::path::PathBuf;

use crate::expr::{Value, ValueType};
use crate::model::Rule;
use crate::source::SourcePos;

/// A resolved parameter declaration (XSD `ParameterDeclaration`).
#[derive(Debug, Clone, PartialEq)]
pub struct ParameterDeclaration {
    /// Name, without `$`.
    pub name: String,
    /// Declared type.
    pub parameter_type: ValueType,
    /// The value after overrides and resolution, of the declared type.
    pub value: Value,
    /// Where the value was written.
    pub pos: SourcePos,
    /// ConstraintGroups (1.2+): a value must meet every constraint of at least one group
    /// ([`ValueConstraintGroup::check`]); empty: any value.
    pub constraint_groups: Vec<ValueConstraintGroup>,
}

/// XSD `ValueConstraintGroup` (1.2+): constraints that must all hold.
#[derive(Debug, Clone, PartialEq)]
pub struct ValueConstraintGroup {
    /// The ValueConstraints.
    pub constraints: Vec<ValueConstraint>,
}

/// XSD `ValueConstraint` (1.2+): `rule` against `value`.
#[derive(Debug, Clone, PartialEq)]
pub struct ValueConstraint {
    /// Comparison rule.
    pub rule: Rule,
    /// The bound, as written after parameter resolution.
    pub value: String,
}

impl ValueConstraintGroup {
    /// Whether `value` meets every constraint of one of `groups` (true when there are none);
    /// when it meets none, the groups described for an error message, e.g.
    /// "greaterOrEqual 0 and lessThan 10 or equalTo 20".
    pub fn check(groups: &[ValueConstraintGroup], value: &Value) -> Result<(), String> {
        if groups.is_empty()
            || groups
                .iter()
                .any(|g| g.constraints.iter().all(|c| meets(value, c.rule, &c.value)))
        {
            return Ok(());
        }
        Err(groups
            .iter()
            .map(|g| {
                g.constraints
                    .iter()
                    .map(|c| format!("{} {}", c.rule, c.value))
                    .collect::<Vec<_>>()
                    .join(" and ")
            })
            .collect::<Vec<_>>()
            .join(" or "))
    }
}

/// Whether `value` `rule` `bound` holds; numbers compare as doubles, other values as text.
pub(crate) fn meets(value: &Value, rule: Rule, bound: &str) -> bool {
    use crate::attr::FromAttr;
    use std::cmp::Ordering;
    let ordering = match (value.as_f64(), f64::from_attr(bound)) {
        (Some(v), Some((b, _)))
            if !matches!(
                value,
                Value::String(_) | Value::DateTime(_) | Value::Bool(_)
            ) =>
        {
            v.partial_cmp(&b)
        }
        _ => Some(value.to_string().as_str().cmp(bound.trim())),
    };
    let Some(o) = ordering else { return false };
    match rule {
        Rule::EqualTo => o == Ordering::Equal,
        Rule::NotEqualTo => o != Ordering::Equal,
        Rule::GreaterThan => o == Ordering::Greater,
        Rule::LessThan => o == Ordering::Less,
        Rule::GreaterOrEqual => o != Ordering::Less,
        Rule::LessOrEqual => o != Ordering::Greater,
    }
}

/// A variable declaration (XSD `VariableDeclaration`, 1.2+): the initial value of a
/// variable the runtime may change.
#[derive(Debug, Clone, PartialEq)]
pub struct VariableDeclaration {
    /// Name.
    pub name: String,
    /// Declared type.
    pub variable_type: ValueType,
    /// Initial value.
    pub value: Value,
    /// Where it was declared.
    pub pos: SourcePos,
}

/// A monitor declaration (XSD `MonitorDeclaration`, 1.3).
#[derive(Debug, Clone, PartialEq)]
pub struct MonitorDeclaration {
    /// Name.
    pub name: String,
    /// Initial value.
    pub value: bool,
    /// Where the declaration is.
    pub pos: SourcePos,
}

/// Where a catalog element came from (XSD `CatalogReference`, §9.4).
#[derive(Debug, Clone, PartialEq)]
pub struct CatalogOrigin {
    /// `catalogName`.
    pub catalog_name: String,
    /// `entryName`.
    pub entry_name: String,
    /// ParameterAssignments, resolved: (parameterRef without `$`, value).
    pub parameter_assignments: Vec<(String, String)>,
    /// The catalog file the entry was read from.
    pub file: PathBuf,
    /// Where the CatalogReference was written.
    pub pos: SourcePos,
}

/// Properties (XSD `Properties`): name/value pairs and file references for user extensions.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Properties {
    /// `Property` name/value pairs.
    pub properties: Vec<(String, String)>,
    /// Where each `Property` element was written, in the order of `properties`.
    pub positions: Vec<SourcePos>,
    /// `File` paths as written.
    pub files: Vec<String>,
    /// `CustomContent` texts (1.2+), trimmed.
    pub custom_content: Vec<String>,
}

/// FileHeader (XSD `FileHeader`).
#[derive(Debug, Clone, PartialEq)]
pub struct FileHeader {
    /// `revMajor` (1).
    pub rev_major: u16,
    /// `revMinor` (0–3).
    pub rev_minor: u16,
    /// `date` as written (ISO 8601).
    pub date: String,
    /// `description`.
    pub description: String,
    /// `author`.
    pub author: String,
    /// License (1.1+): name, resource, spdxId.
    pub license: Option<License>,
}

/// License (XSD `License`, 1.1+).
#[derive(Debug, Clone, PartialEq)]
pub struct License {
    /// `name`.
    pub name: String,
    /// `resource` (URL).
    pub resource: Option<String>,
    /// `spdxId`.
    pub spdx_id: Option<String>,
}

/// A closed interval (XSD `Range`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// `lowerLimit`.
    pub lower_limit: f64,
    /// `upperLimit`.
    pub upper_limit: f64,
}
