//! [`LineIndex`]: byte offset → 1-based line and column, by a binary search over the line
//! starts (a scan from the file's start per position, as roxmltree's `text_pos_at` does, is
//! quadratic over a file with many positions).

use std::ops::Range;
use std::path::Path;
use std::sync::Arc;

use crate::SourcePos;

/// Byte offsets of the line starts of one text. The text itself is not kept: look-ups take
/// it again (the same text that was indexed).
#[derive(Debug, Clone, Default)]
pub struct LineIndex {
    starts: Vec<usize>,
}

impl LineIndex {
    /// Indexes `text`; lines end at `\n`, `\r\n` or a lone `\r`.
    pub fn new(text: &str) -> Self {
        let bytes = text.as_bytes();
        let mut starts = vec![0];
        for (i, &b) in bytes.iter().enumerate() {
            match b {
                b'\n' => starts.push(i + 1),
                b'\r' if bytes.get(i + 1) != Some(&b'\n') => starts.push(i + 1),
                _ => {}
            }
        }
        Self { starts }
    }

    /// The 1-based line and character column of byte `offset` in `text` (the text indexed).
    /// An offset past the end is taken as the end; one inside a character counts bytes from
    /// the line's start.
    pub fn line_col(&self, text: &str, offset: usize) -> (u32, u32) {
        let offset = offset.min(text.len());
        let line = self
            .starts
            .partition_point(|&s| s <= offset)
            .saturating_sub(1);
        let start = self.starts.get(line).copied().unwrap_or(0).min(offset);
        let col = text
            .get(start..offset)
            .map_or(offset - start, |s| s.chars().count());
        (to_u32(line + 1), to_u32(col + 1))
    }

    /// The byte range of 1-based line `line` of `text` (the text indexed), without its line
    /// end; `None` for line 0 or past the last line. The inverse look-up, for showing the line
    /// a position names.
    pub fn line_range(&self, text: &str, line: u32) -> Option<Range<usize>> {
        let i = usize::try_from(line).ok()?.checked_sub(1)?;
        let start = *self.starts.get(i)?;
        let next = self.starts.get(i + 1).copied().unwrap_or(text.len());
        let mut end = next.min(text.len()).max(start);
        if end > start && text.get(..end)?.ends_with('\n') {
            end -= 1;
        }
        if end > start && text.get(..end)?.ends_with('\r') {
            end -= 1;
        }
        Some(start..end)
    }

    /// The [`SourcePos`] of byte `offset` of `text` (the text indexed) in `file`.
    pub fn pos(&self, file: &Arc<Path>, text: &str, offset: usize) -> SourcePos {
        let (line, col) = self.line_col(text, offset);
        SourcePos::new(Arc::clone(file), line, col)
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
        // Past the end: the end (line 4, after 'x').
        assert_eq!(index.line_col(text, 99), (4, 2));
    }

    #[test]
    fn lines_end_at_lf_crlf_and_lone_cr() {
        let text = "ab\ncé d\r\nx\ry";
        let index = LineIndex::new(text);
        assert_eq!(index.line_col(text, 3), (2, 1));
        // "cé " is 4 bytes, 3 characters: 'd' (byte 7) is column 4.
        assert_eq!(index.line_col(text, 7), (2, 4));
        // "\r\n" is one line end: 'x' (byte 10) starts line 3; the lone '\r' ends it.
        assert_eq!(index.line_col(text, 10), (3, 1));
        assert_eq!(index.line_col(text, 12), (4, 1));
    }

    #[test]
    fn line_ranges_leave_out_the_line_ends() {
        let text = "ab\ncé d\r\nx\ry";
        let index = LineIndex::new(text);
        let line = |n| index.line_range(text, n).map(|r| &text[r]);
        assert_eq!(line(1), Some("ab"));
        assert_eq!(line(2), Some("cé d"));
        assert_eq!(line(3), Some("x"));
        assert_eq!(line(4), Some("y"));
        assert_eq!(line(0), None);
        assert_eq!(line(5), None);
        // A text ending in a line end has an empty last line.
        let text = "a\r\n";
        let index = LineIndex::new(text);
        assert_eq!(index.line_range(text, 1), Some(0..1));
        assert_eq!(index.line_range(text, 2), Some(3..3));
    }

    #[test]
    fn pos_carries_the_file() {
        let file: Arc<Path> = Arc::from(Path::new("a.osc"));
        let text = "x\n  y";
        let pos = LineIndex::new(text).pos(&file, text, 4);
        assert_eq!(pos.to_string(), "a.osc:2:3");
    }
}
