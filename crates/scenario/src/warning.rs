//! The crate's warning: a non-fatal finding while loading a scenario, with the [`SourcePos`]
//! it is about (a 1.0–1.2 form mapped onto the 1.3 model, a feature newer than the file's
//! declared version). Scenario models keep them in
//! [`Scenario::warnings`](crate::Scenario::warnings).

use std::fmt;

use crate::source::SourcePos;

/// A non-fatal finding: a deprecated form mapped onto the 1.3 model, or a feature newer than
/// the file's declared version.
#[derive(Debug, Clone, PartialEq)]
pub struct Warning {
    /// The message ("… at file:row:col" is added by Display).
    pub message: String,
    /// Where.
    pub pos: SourcePos,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} at {}", self.message, self.pos)
    }
}
