//! Syntax diagnostics: positions (1-based line:column), one-line text and miette reports.
//!
//! A [`SyntaxError`] keeps a byte range only; [`LineIndex`] turns offsets into `line:col` when a
//! message is shown (columns count characters, not bytes). [`SyntaxError::display`] gives the
//! one-line form "expected X, found Y at FILE:LINE:COL" used in tests and logs;
//! [`SyntaxError::to_report`] gives a [`miette::Report`] with the source snippet and a labelled
//! span, for the CLI.

use std::fmt;
use std::ops::Range;
use std::sync::Arc;

/// What kind of syntax error.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum SyntaxErrorKind {
    /// A character or literal the lexer cannot read (unterminated string, stray character, bad
    /// indentation).
    Lexical,
    /// The token sequence does not follow the grammar.
    Grammar,
    /// A literal whose value cannot be represented (integer beyond `uint`/`int`, float overflow).
    Literal,
}

/// One syntax error: kind, byte range and message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SyntaxError {
    kind: SyntaxErrorKind,
    range: Range<usize>,
    message: String,
}

impl SyntaxError {
    pub(crate) fn new(
        kind: SyntaxErrorKind,
        range: Range<usize>,
        message: impl Into<String>,
    ) -> Self {
        SyntaxError {
            kind,
            range,
            message: message.into(),
        }
    }

    /// The kind.
    pub fn kind(&self) -> SyntaxErrorKind {
        self.kind
    }

    /// Byte range in the source; empty where something is missing.
    pub fn range(&self) -> Range<usize> {
        self.range.clone()
    }

    /// The message without position, lowercase ("expected `:`, found end of line").
    pub fn message(&self) -> &str {
        &self.message
    }

    /// The error with its position: "MESSAGE at FILE:LINE:COL".
    pub fn display<'a>(&'a self, file: &'a str, index: &'a LineIndex) -> impl fmt::Display + 'a {
        DisplayError {
            error: self,
            file,
            index,
        }
    }

    /// A miette report with the source snippet and the range labelled.
    pub fn to_report(&self, file: &str, source: &str) -> miette::Report {
        let len = self.range.len();
        let label = miette::LabeledSpan::at(self.range.start..self.range.start + len, self.label());
        let diagnostic = miette::MietteDiagnostic::new(self.message.clone())
            .with_code(match self.kind {
                SyntaxErrorKind::Lexical => "osc::syntax::lexical",
                SyntaxErrorKind::Grammar => "osc::syntax::grammar",
                SyntaxErrorKind::Literal => "osc::syntax::literal",
            })
            .with_label(label);
        miette::Report::new(diagnostic)
            .with_source_code(miette::NamedSource::new(file, Arc::new(source.to_string())))
    }

    fn label(&self) -> String {
        match self.message.split_once(", found ") {
            Some((expected, _)) => expected.to_string(),
            None => "here".to_string(),
        }
    }
}

struct DisplayError<'a> {
    error: &'a SyntaxError,
    file: &'a str,
    index: &'a LineIndex,
}

impl fmt::Display for DisplayError<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (line, col) = self.index.line_col(self.error.range.start);
        write!(f, "{} at {}:{line}:{col}", self.error.message, self.file)
    }
}

/// A text with its line index, to turn offsets into 1-based line:column (the workspace's
/// one offset → line:col look-up, [`source::LineIndex`], over a text of its own).
#[derive(Debug, Clone)]
pub struct LineIndex {
    text: String,
    lines: source::LineIndex,
}

impl LineIndex {
    /// Indexes `text` (line breaks `\n`, `\r\n` and `\r`, as the lexer reads them).
    pub fn new(text: &str) -> LineIndex {
        LineIndex {
            text: text.to_string(),
            lines: source::LineIndex::new(text),
        }
    }

    /// 1-based (line, column) of a byte offset; the column counts characters.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let (line, col) = self.lines.line_col(&self.text, offset);
        (line as usize, col as usize)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_columns_count_characters() {
        let index = LineIndex::new("ab\ncé d\r\nx\ry");
        assert_eq!(index.line_col(0), (1, 1));
        assert_eq!(index.line_col(3), (2, 1));
        // "cé " is 4 bytes, 3 characters: 'd' is column 4.
        assert_eq!(index.line_col(7), (2, 4));
        assert_eq!(index.line_col(10), (3, 1));
        assert_eq!(index.line_col(12), (4, 1));
    }
}
