//! Types shared by several chapters of OpenSCENARIO 1.3: parameter declarations (§9.1),
//! catalog provenance (§9.4), Properties, FileHeader, Range.

use std::path::PathBuf;

use crate::expr::{Value, ValueType};
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
