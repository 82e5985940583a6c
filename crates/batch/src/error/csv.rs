//! The kind of the error of reading a `results.csv` (table.rs).

/// A results CSV that cannot be read: the file, 1-based line, and what was expected.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("expected {expected}, found {found} at {file}:{line}")]
pub struct CsvErrorKind {
    /// The file.
    pub file: String,
    /// 1-based line.
    pub line: usize,
    /// What was expected.
    pub expected: String,
    /// What was found.
    pub found: String,
}

impl CsvErrorKind {
    /// The error at `line` of `file`: `expected`, `found` instead.
    pub fn at(file: &str, line: usize, expected: &str, found: &str) -> CsvErrorKind {
        CsvErrorKind {
            file: file.to_owned(),
            line,
            expected: expected.to_owned(),
            found: found.to_owned(),
        }
    }
}
