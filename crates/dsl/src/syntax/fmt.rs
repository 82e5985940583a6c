//! Canonical formatting of an OpenSCENARIO DSL file from its concrete syntax tree.
//!
//! The layout (ASAM OpenSCENARIO DSL 2.1 §7.2.1.2 line structure, §7.2.1.4 indentation) is
//! rebuilt from the tree's significant tokens; only comments and blank lines are taken from the
//! trivia:
//! - one logical line per statement, four spaces per block level; lines joined inside brackets
//!   and by `\` continuations are joined into one;
//! - one space around binary operators, `=`, `->`, `=>`, `?`, and after `,` and `:`; none inside
//!   brackets, around `.`, `..`, `::`, `!`, after `@` and prefix `-`, before a call's `(`, an
//!   index's `[` or a glued unit;
//! - comments kept: a comment on its own line at the indentation of the code it sits in, a
//!   comment after code two spaces after it (inside brackets the line then breaks and goes on one
//!   level deeper);
//! - blank lines kept, several collapsed into one, none at the start of a block or of the file;
//! - the file ends with one line break.
//!
//! Only significant tokens decide the output, and the formatter emits every one of them in order
//! with spacing that cannot glue two tokens into one or split one, so formatting is idempotent
//! and keeps the tree (tested on every fixture file). Files with syntax errors are not
//! formatted.

use super::kind::{SyntaxKind, SyntaxKind::*, SyntaxNode, SyntaxToken};
use super::{parse, SyntaxError};

/// Formats `source`; the syntax errors if it does not parse cleanly.
pub fn format(source: &str) -> Result<String, Vec<SyntaxError>> {
    let parse = parse(source);
    if !parse.errors().is_empty() {
        return Err(parse.errors().to_vec());
    }
    Ok(format_tree(&parse.syntax()))
}

/// Formats a tree (which should be free of syntax errors: ERROR nodes are printed as their
/// tokens).
pub fn format_tree(root: &SyntaxNode) -> String {
    let tokens: Vec<SyntaxToken> = root
        .descendants_with_tokens()
        .filter_map(|e| e.into_token())
        .collect();
    let mut f = Formatter {
        text: root.to_string(),
        out: String::new(),
        level: 0,
        depth: 0,
        line_start: true,
        line_ends: 0,
        prev: None,
        block_start: true,
        widths: vec![0],
    };
    for (i, token) in tokens.iter().enumerate() {
        f.token(token, &tokens[i + 1..]);
    }
    if !f.out.is_empty() && !f.out.ends_with('\n') {
        f.out.push('\n');
    }
    f.out
}

struct Formatter {
    /// The source text (for source columns).
    text: String,
    out: String,
    /// Block level (INDENT count).
    level: usize,
    /// Open brackets.
    depth: usize,
    /// Whether the next output starts a line (indentation not yet written).
    line_start: bool,
    /// Line ends seen since the last code or comment (2 or more make a blank line).
    line_ends: usize,
    /// The previous significant token.
    prev: Option<SyntaxToken>,
    /// Whether nothing was written since the block (or file) opened.
    block_start: bool,
    /// Source indentation widths of the open blocks, for own-line comments.
    widths: Vec<usize>,
}

impl Formatter {
    /// Source column (in bytes) of a token's start.
    fn column(&self, token: &SyntaxToken) -> usize {
        let offset = usize::from(token.text_range().start()).min(self.text.len());
        let line_start = self.text[..offset].rfind(['\n', '\r']).map_or(0, |i| i + 1);
        offset - line_start
    }

    fn token(&mut self, token: &SyntaxToken, rest: &[SyntaxToken]) {
        match token.kind() {
            WHITESPACE | LINE_CONTINUATION => {}
            LINE_BREAK | NEWLINE => {
                if token.kind() == NEWLINE || self.line_start {
                    self.line_ends += 1;
                }
                if token.kind() == NEWLINE {
                    self.out.push('\n');
                    self.line_start = true;
                }
            }
            INDENT => {
                self.level += 1;
                self.block_start = true;
                let width = self.column(token);
                self.widths.push(width);
            }
            DEDENT => {
                self.level = self.level.saturating_sub(1);
                self.widths.pop();
            }
            COMMENT => self.comment(token, rest),
            _ => self.code(token),
        }
    }

    /// Writes the indentation (and a pending blank line) at the start of a line.
    fn start_line(&mut self, level: usize) {
        if self.line_ends >= 2
            && !self.block_start
            && !self.out.is_empty()
            && !self.out.ends_with("\n\n")
        {
            self.out.push('\n');
        }
        self.out.push_str(&"    ".repeat(level));
        self.line_start = false;
        self.line_ends = 0;
        self.block_start = false;
    }

    fn comment(&mut self, token: &SyntaxToken, rest: &[SyntaxToken]) {
        let text = token.text().trim_end();
        if self.line_start {
            // Own-line comment: at the level of the code it sits in. A comment left of the
            // current block's indentation belongs to the code after the coming DEDENTs.
            let mut level = self.level + self.depth.min(1);
            if self.depth == 0 && self.column(token) < self.widths.last().copied().unwrap_or(0) {
                let dedents = rest
                    .iter()
                    .take_while(|t| t.kind().is_trivia() || t.kind() == DEDENT)
                    .filter(|t| t.kind() == DEDENT)
                    .count();
                level = level.saturating_sub(dedents);
            }
            self.start_line(level);
            self.out.push_str(text);
            self.out.push('\n');
            self.line_start = true;
        } else {
            self.out.push_str("  ");
            self.out.push_str(text);
            if self.depth > 0 {
                // Inside brackets the line break after the comment is trivia: keep it.
                self.out.push('\n');
                self.line_start = true;
            }
        }
        self.line_ends = 0;
    }

    fn code(&mut self, token: &SyntaxToken) {
        if self.line_start {
            let continuation = if self.depth > 0 { 1 } else { 0 };
            self.start_line(self.level + continuation);
        } else if let Some(prev) = &self.prev {
            if space_between(prev, token) {
                self.out.push(' ');
            }
        }
        self.out.push_str(token.text());
        match token.kind() {
            L_PAREN | L_BRACK => self.depth += 1,
            R_PAREN | R_BRACK => self.depth = self.depth.saturating_sub(1),
            _ => {}
        }
        self.prev = Some(token.clone());
        self.line_ends = 0;
    }
}

fn parent_kind(token: &SyntaxToken) -> SyntaxKind {
    token.parent().map_or(SOURCE_FILE, |p| p.kind())
}

/// Whether a `(` after `prev` opens an argument list or condition glued to it.
fn glued_paren(prev: &SyntaxToken) -> bool {
    match prev.kind() {
        IDENT | R_PAREN | R_BRACK => true,
        KEEP_KW | REMOVE_DEFAULT_KW | COVER_KW | RECORD_KW | SI_KW | RANGE_KW | RISE_KW
        | FALL_KW | ELAPSED_KW | EVERY_KW | SAMPLE_KW | SERIAL_KW | PARALLEL_KW | ONE_OF_KW => true,
        AS_KW | IS_KW => matches!(parent_kind(prev), CAST_EXPR | TYPE_TEST_EXPR),
        _ => false,
    }
}

/// The spacing rule between two significant tokens on one line.
fn space_between(prev: &SyntaxToken, next: &SyntaxToken) -> bool {
    let (p, n) = (prev.kind(), next.kind());
    if n == UNIT {
        return false;
    }
    match p {
        L_PAREN | L_BRACK | DOT | DOT2 | COLON2 | BANG | AT => return false,
        MINUS | PLUS if matches!(parent_kind(prev), LITERAL) => return false,
        // A prefix minus keeps its space before a number, which would otherwise fold into it.
        MINUS if parent_kind(prev) == PREFIX_EXPR => {
            return matches!(n, INT_NUMBER | FLOAT_NUMBER | INF_KW | NAN_KW)
        }
        _ => {}
    }
    match n {
        R_PAREN | R_BRACK | COMMA | DOT | DOT2 | BANG => false,
        // `ns::name` is glued; a global `::name` keeps its space (`a: ::b`, not `a:::b`).
        COLON2 => !(p == IDENT && prev.parent() == next.parent()),
        COLON => parent_kind(next) == TERNARY_EXPR,
        L_PAREN => !glued_paren(prev),
        L_BRACK => parent_kind(next) != INDEX_EXPR,
        _ => true,
    }
}
