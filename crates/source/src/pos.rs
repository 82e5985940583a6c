//! [`SourcePos`]: a file and a 1-based line and column.

use std::fmt;
use std::path::Path;
use std::sync::Arc;

/// A place in a file: the file and the 1-based line and column. Display: `file:line:col`.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct SourcePos {
    /// The file, as it was opened (e.g. the scenario path, or a catalog path joined to it).
    pub file: Arc<Path>,
    /// 1-based line.
    pub line: u32,
    /// 1-based column, in characters.
    pub col: u32,
}

impl SourcePos {
    /// The place `line:col` (both 1-based) in `file`.
    pub fn new(file: Arc<Path>, line: u32, col: u32) -> Self {
        Self { file, line, col }
    }

    /// The start of `file` (1:1), for errors about a file as a whole.
    pub fn start_of(file: Arc<Path>) -> Self {
        Self::new(file, 1, 1)
    }

    /// `message` without a trailing ` at line:col` naming this place: a library's message
    /// (roxmltree ends every error so) whose position the caller reports as this `SourcePos`,
    /// so that the place is shown once. Other messages are returned unchanged.
    pub fn strip_from<'m>(&self, message: &'m str) -> &'m str {
        message
            .strip_suffix(&format!(" at {}:{}", self.line, self.col))
            .unwrap_or(message)
    }
}

impl fmt::Display for SourcePos {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.file.display(), self.line, self.col)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shows_file_line_col() {
        let pos = SourcePos::new(Arc::from(Path::new("roads/a.xodr")), 12, 7);
        assert_eq!(pos.to_string(), "roads/a.xodr:12:7");
        let start = SourcePos::start_of(Arc::from(Path::new("s.xosc")));
        assert_eq!((start.line, start.col), (1, 1));
        assert_eq!(start.to_string(), "s.xosc:1:1");
    }

    #[test]
    fn strips_its_own_place_from_a_message() {
        let pos = SourcePos::new(Arc::from(Path::new("a.xosc")), 3, 14);
        // roxmltree's message for a bad closing tag at 3:14.
        let message = "expected 'Init' tag, not 'Story' at 3:14";
        assert_eq!(pos.strip_from(message), "expected 'Init' tag, not 'Story'");
        // Another place, or none, is kept.
        assert_eq!(
            pos.strip_from("unexpected end at 3:15"),
            "unexpected end at 3:15"
        );
        assert_eq!(pos.strip_from("no position"), "no position");
    }
}
