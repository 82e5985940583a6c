//! Source positions: where in which file a model element was written.
//!
//! roxmltree keeps byte ranges on nodes; [`LineIndex`] turns a byte offset into a 1-based
//! `line:col` by a binary search over the line starts (the document's own
//! `text_pos_at` scans from the start, which is quadratic over a whole file).
//! Columns count characters, as roxmltree's `TextPos` does.

use std::fmt;
use std::path::Path;
use std::sync::Arc;

/// A place in a scenario or catalog file: the file and the 1-based line and column.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct SourcePos {
    /// The file, as it was opened (the scenario path, or a catalog path joined to it).
    pub file: Arc<Path>,
    /// 1-based line.
    pub line: u32,
    /// 1-based column, in characters.
    pub col: u32,
}

impl SourcePos {
    /// The start of `file` (1:1), for errors about a file as a whole.
    pub fn start_of(file: Arc<Path>) -> Self {
        Self {
            file,
            line: 1,
            col: 1,
        }
    }
}

impl fmt::Display for SourcePos {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.file.display(), self.line, self.col)
    }
}

/// Byte offsets of the line starts of one text, for offset → line:col look-ups.
#[derive(Debug, Clone)]
pub(crate) struct LineIndex {
    starts: Vec<usize>,
}

impl LineIndex {
    /// Indexes `text`.
    pub(crate) fn new(text: &str) -> Self {
        let mut starts = vec![0];
        starts.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        Self { starts }
    }

    /// The 1-based line and character column of byte `offset` in `text` (the text indexed).
    pub(crate) fn line_col(&self, text: &str, offset: usize) -> (u32, u32) {
        let offset = offset.min(text.len());
        let line = self.starts.partition_point(|&s| s <= offset);
        // `starts[0] == 0 <= offset`, so the partition point is at least 1.
        let start = self.starts[line - 1];
        let col = text
            .get(start..offset)
            .map_or(offset - start, |s| s.chars().count());
        (to_u32(line), to_u32(col + 1))
    }
}

/// Saturating conversion for line and column numbers.
fn to_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_col_counts_from_one_and_in_characters() {
        let text = "ab\nçd\n\nx";
        let index = LineIndex::new(text);
        assert_eq!(index.line_col(text, 0), (1, 1));
        assert_eq!(index.line_col(text, 3), (2, 1));
        // 'ç' is two bytes: byte 5 is 'd', the second character of line 2.
        assert_eq!(index.line_col(text, 5), (2, 2));
        assert_eq!(index.line_col(text, 7), (3, 1));
        assert_eq!(index.line_col(text, 8), (4, 1));
    }
}
