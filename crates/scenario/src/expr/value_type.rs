//! The parameter types of OpenSCENARIO 1.3 §9.1 "Parameters" (XSD `ParameterType`): their
//! XSD names and which of them the §9.2.1 arithmetic accepts. Below both the values
//! (`value`) and the errors (`error`) that name a type.

/// The parameter types of OpenSCENARIO 1.3 (XSD `ParameterType`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ValueType {
    /// `boolean`.
    Boolean,
    /// `int`: 32-bit signed (`integer` is its deprecated spelling).
    Int,
    /// `unsignedInt`: 32-bit unsigned.
    UnsignedInt,
    /// `unsignedShort`: 16-bit unsigned.
    UnsignedShort,
    /// `double`.
    Double,
    /// `string`.
    String,
    /// `dateTime`.
    DateTime,
}

impl ValueType {
    /// The type named by an XSD `ParameterType` literal (`"double"`, `"unsignedInt"`, …),
    /// including the deprecated `"integer"`.
    pub fn from_xsd_name(name: &str) -> Option<Self> {
        Some(match name {
            "boolean" => Self::Boolean,
            "int" | "integer" => Self::Int,
            "unsignedInt" => Self::UnsignedInt,
            "unsignedShort" => Self::UnsignedShort,
            "double" => Self::Double,
            "string" => Self::String,
            "dateTime" => Self::DateTime,
            _ => return None,
        })
    }

    /// The XSD spelling of the type.
    pub fn xsd_name(self) -> &'static str {
        match self {
            Self::Boolean => "boolean",
            Self::Int => "int",
            Self::UnsignedInt => "unsignedInt",
            Self::UnsignedShort => "unsignedShort",
            Self::Double => "double",
            Self::String => "string",
            Self::DateTime => "dateTime",
        }
    }

    /// Whether the standard's arithmetic operators accept the type (§9.2.1: int, unsignedInt,
    /// unsignedShort and double).
    pub fn is_numeric(self) -> bool {
        matches!(
            self,
            Self::Int | Self::UnsignedInt | Self::UnsignedShort | Self::Double
        )
    }
}

impl std::fmt::Display for ValueType {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.xsd_name())
    }
}
