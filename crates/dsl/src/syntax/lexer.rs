//! Lexer: source text → tokens, trivia and layout included (ASAM OpenSCENARIO DSL 2.1 §7.2.1).
//!
//! Every byte of the input lands in exactly one token, so the tokens concatenated give the input
//! back. Besides the tokens of §7.2.1.5 the lexer produces:
//! - trivia: [`WHITESPACE`], [`COMMENT`] (`#` to the end of the physical line), [`LINE_BREAK`]
//!   (a line break that ends no logical line: in a blank or comment-only line, or inside
//!   parentheses / brackets, §7.2.1.2 implicit joining) and [`LINE_CONTINUATION`] (`\` right
//!   before a line break, explicit joining);
//! - layout: [`NEWLINE`] (the line break that ends a logical line; zero-width at the end of input
//!   when the last line has no line break), and zero-width [`INDENT`] / [`DEDENT`] tokens from
//!   the indentation of each logical line (Python 3.10 §2.1.8 algorithm, tabs to the next multiple
//!   of 8, form feeds reset the count, §7.2.1.4).
//!
//! Words are always [`IDENT`] (keywords are contextual, see [`super::kind`]); a word glued to a
//! number (`30kph`, `1.95m`) is a [`UNIT`] token (§7.2.1.5.2 physical literals). A `-` is always
//! an operator token: the parser folds a `-` glued to a number in operand position into a
//! negative literal (see the module doc of [`super`] for why).
//!
//! Recovery: a line break inside brackets followed by a top-level declaration keyword at column 0
//! (`scenario`, `struct`, …) closes the open brackets, so one missing `)` does not swallow the
//! rest of the file; the parser then reports the missing bracket.
//!
//! Hand-written rather than generated (e.g. with `logos`): the layout tokens depend on line
//! state, bracket depth and the indentation stack, units depend on adjacency, and strings and
//! quoted identifiers need tailored unterminated-literal errors.

use super::kind::SyntaxKind::{self, *};
use std::ops::Range;

/// One token: its kind and its byte length (offsets follow from the lengths).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Token {
    /// The kind.
    pub kind: SyntaxKind,
    /// Length in bytes (0 for INDENT, DEDENT and the end-of-input NEWLINE).
    pub len: u32,
}

/// A lexical error: the byte range and the message.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LexError {
    /// Byte range in the source.
    pub range: Range<usize>,
    /// Lowercase message, without position.
    pub message: String,
}

/// The lexer's output.
#[derive(Debug, Clone, Default)]
pub struct Lexed {
    /// All tokens in source order.
    pub tokens: Vec<Token>,
    /// Lexical errors in source order.
    pub errors: Vec<LexError>,
}

/// Words that start a top-level declaration (used for recovery from unclosed brackets).
const TOP_LEVEL_WORDS: &[&str] = &[
    "import",
    "namespace",
    "export",
    "type",
    "unit",
    "enum",
    "struct",
    "actor",
    "scenario",
    "action",
    "modifier",
    "extend",
    "global",
];

/// Splits `source` into tokens.
pub fn lex(source: &str) -> Lexed {
    let mut lexer = Lexer {
        src: source,
        pos: 0,
        out: Lexed::default(),
        indents: vec![0],
        depth: 0,
        at_line_start: true,
        line_has_tokens: false,
    };
    lexer.run();
    lexer.out
}

struct Lexer<'a> {
    src: &'a str,
    pos: usize,
    out: Lexed,
    /// Indentation widths of the open blocks; `indents[0] == 0`.
    indents: Vec<usize>,
    /// Open `(` and `[` count.
    depth: u32,
    at_line_start: bool,
    /// Whether the current logical line has a non-trivia token.
    line_has_tokens: bool,
}

fn is_id_start(c: char) -> bool {
    c == '_' || unicode_ident::is_xid_start(c)
}

fn is_id_continue(c: char) -> bool {
    unicode_ident::is_xid_continue(c)
}

impl Lexer<'_> {
    fn rest(&self) -> &str {
        &self.src[self.pos..]
    }

    fn peek(&self) -> Option<char> {
        self.rest().chars().next()
    }

    fn peek_at(&self, n: usize) -> Option<char> {
        self.rest().chars().nth(n)
    }

    fn push(&mut self, kind: SyntaxKind, start: usize) {
        let len = (self.pos - start) as u32;
        if !kind.is_trivia() && kind != NEWLINE && kind != INDENT && kind != DEDENT {
            self.line_has_tokens = true;
        }
        self.out.tokens.push(Token { kind, len });
    }

    fn error(&mut self, range: Range<usize>, message: impl Into<String>) {
        self.out.errors.push(LexError {
            range,
            message: message.into(),
        });
    }

    /// Length of the line break at the cursor (`\n`, `\r\n`, `\r`), 0 if none.
    fn line_break_len(&self) -> usize {
        let bytes = self.rest().as_bytes();
        match bytes.first() {
            Some(b'\n') => 1,
            Some(b'\r') if bytes.get(1) == Some(&b'\n') => 2,
            Some(b'\r') => 1,
            _ => 0,
        }
    }

    fn run(&mut self) {
        while self.pos < self.src.len() {
            if self.at_line_start && self.depth == 0 {
                self.line_start();
                continue;
            }
            self.token();
        }
        let end = self.pos;
        if self.line_has_tokens {
            self.push(NEWLINE, end);
        }
        while self.indents.len() > 1 {
            self.indents.pop();
            self.push(DEDENT, end);
        }
    }

    /// Indentation of a new logical line: blank lines are trivia, others get INDENT/DEDENT.
    fn line_start(&mut self) {
        let start = self.pos;
        let mut width = 0usize;
        while let Some(c) = self.peek() {
            match c {
                ' ' => width += 1,
                '\t' => width = (width / 8 + 1) * 8,
                '\x0c' => width = 0,
                _ => break,
            }
            self.pos += 1;
        }
        if self.pos > start {
            self.push(WHITESPACE, start);
        }
        let blank = match self.peek() {
            None | Some('#') => true,
            Some(_) => self.line_break_len() > 0,
        };
        if blank {
            if self.peek() == Some('#') {
                self.comment();
            }
            let n = self.line_break_len();
            if n > 0 {
                let s = self.pos;
                self.pos += n;
                self.push(LINE_BREAK, s);
            }
            return;
        }
        self.at_line_start = false;
        let top = *self.indents.last().unwrap_or(&0);
        if width > top {
            self.indents.push(width);
            self.push(INDENT, self.pos);
        } else if width < top {
            while self.indents.last().is_some_and(|&w| w > width) {
                self.indents.pop();
                self.push(DEDENT, self.pos);
            }
            if self.indents.last().is_some_and(|&w| w < width) {
                self.error(
                    start..self.pos,
                    "unindent does not match any outer indentation level",
                );
                // Recover: take this width as the level of the block we fell back into.
                self.indents.push(width);
            }
        }
    }

    fn comment(&mut self) {
        let start = self.pos;
        let end = self
            .rest()
            .find(['\n', '\r'])
            .map_or(self.src.len(), |i| self.pos + i);
        self.pos = end;
        self.push(COMMENT, start);
    }

    fn token(&mut self) {
        let start = self.pos;
        let Some(c) = self.peek() else { return };
        match c {
            ' ' | '\t' | '\x0c' => {
                while matches!(self.peek(), Some(' ' | '\t' | '\x0c')) {
                    self.pos += 1;
                }
                self.push(WHITESPACE, start);
            }
            '#' => self.comment(),
            '\n' | '\r' => self.line_break(),
            '\\' => {
                self.pos += 1;
                let n = self.line_break_len();
                if n > 0 {
                    self.pos += n;
                    self.push(LINE_CONTINUATION, start);
                } else {
                    self.push(ERROR_TOKEN, start);
                    self.error(start..self.pos, "a `\\` outside a string must end the line");
                }
            }
            '0'..='9' => self.number(),
            '.' if self.peek_at(1).is_some_and(|c| c.is_ascii_digit()) => self.number(),
            '"' | '\'' => self.string(c),
            '|' => self.quoted_ident(),
            c if is_id_start(c) => {
                self.word();
                self.push(IDENT, start);
            }
            _ => self.punct(c),
        }
    }

    fn line_break(&mut self) {
        let start = self.pos;
        self.pos += self.line_break_len();
        if self.depth > 0 && self.next_line_starts_declaration() {
            self.depth = 0;
        }
        if self.depth > 0 || !self.line_has_tokens {
            self.push(LINE_BREAK, start);
        } else {
            self.push(NEWLINE, start);
            self.line_has_tokens = false;
            self.at_line_start = true;
        }
    }

    fn next_line_starts_declaration(&self) -> bool {
        let rest = self.rest();
        let word_len = rest
            .find(|c: char| !is_id_continue(c))
            .unwrap_or(rest.len());
        let word = &rest[..word_len];
        TOP_LEVEL_WORDS.contains(&word) && rest[word_len..].starts_with([' ', '\t'])
    }

    fn word(&mut self) {
        let len = self
            .rest()
            .find(|c: char| !is_id_continue(c))
            .unwrap_or(self.rest().len());
        self.pos += len;
    }

    fn digits(&mut self, hex: bool) {
        while self.peek().is_some_and(|c| {
            if hex {
                c.is_ascii_hexdigit()
            } else {
                c.is_ascii_digit()
            }
        }) {
            self.pos += 1;
        }
    }

    /// `uint-literal`, `hex-uint-literal`, `float-literal` (§7.2.1.5.2), then a glued unit.
    fn number(&mut self) {
        let start = self.pos;
        let bytes = self.rest().as_bytes();
        let hex = bytes.len() > 2
            && bytes[0] == b'0'
            && matches!(bytes[1], b'x' | b'X')
            && bytes[2].is_ascii_hexdigit();
        let kind = if hex {
            self.pos += 2;
            self.digits(true);
            INT_NUMBER
        } else {
            let mut kind = INT_NUMBER;
            self.digits(false);
            if self.peek() == Some('.') && self.peek_at(1).is_some_and(|c| c.is_ascii_digit()) {
                self.pos += 1;
                self.digits(false);
                kind = FLOAT_NUMBER;
            }
            let b = self.rest().as_bytes();
            if matches!(b.first(), Some(b'e' | b'E')) {
                let digit_at = if matches!(b.get(1), Some(b'+' | b'-')) {
                    2
                } else {
                    1
                };
                if b.get(digit_at).is_some_and(u8::is_ascii_digit) {
                    self.pos += digit_at;
                    self.digits(false);
                    kind = FLOAT_NUMBER;
                }
            }
            kind
        };
        self.push(kind, start);
        // A unit name glued to the number makes a physical literal.
        let unit_start = self.pos;
        match self.peek() {
            Some(c) if is_id_start(c) => {
                self.word();
                self.push(UNIT, unit_start);
            }
            Some('|') if self.quoted_ident_body() => self.push(UNIT, unit_start),
            _ => {}
        }
    }

    /// `|any chars but a vertical line|`, on one line. Returns whether it was terminated (the
    /// unterminated form is pushed as an error token here).
    fn quoted_ident_body(&mut self) -> bool {
        let start = self.pos;
        self.pos += 1;
        let rest = self.rest();
        match rest.find(['|', '\n', '\r']) {
            Some(i) if rest.as_bytes()[i] == b'|' => {
                if i == 0 {
                    self.error(start..self.pos + 1, "empty quoted identifier `||`");
                }
                self.pos += i + 1;
                true
            }
            found => {
                self.pos = found.map_or(self.src.len(), |i| self.pos + i);
                self.push(ERROR_TOKEN, start);
                self.error(
                    start..self.pos,
                    "unterminated quoted identifier: expected `|` before the end of the line",
                );
                false
            }
        }
    }

    fn quoted_ident(&mut self) {
        let start = self.pos;
        if self.quoted_ident_body() {
            self.push(IDENT, start);
        }
    }

    /// `shortstring` or `longstring` (§7.2.1.5.2); `\` escapes any character.
    fn string(&mut self, quote: char) {
        let start = self.pos;
        let triple: String = [quote; 3].iter().collect();
        let long = self.rest().starts_with(&triple);
        self.pos += if long { 3 } else { 1 };
        loop {
            let Some(c) = self.peek() else {
                self.push(ERROR_TOKEN, start);
                let what = if long { "long string" } else { "string" };
                self.error(
                    start..self.pos,
                    format!(
                        "unterminated {what}: expected `{}` before the end of the file",
                        if long { &triple[..] } else { &triple[..1] }
                    ),
                );
                return;
            };
            if c == '\\' {
                self.pos += 1;
                if let Some(next) = self.peek() {
                    self.pos += next.len_utf8();
                }
                continue;
            }
            if long {
                if self.rest().starts_with(&triple) {
                    self.pos += 3;
                    break;
                }
            } else if c == quote {
                self.pos += 1;
                break;
            } else if c == '\n' || c == '\r' {
                self.push(ERROR_TOKEN, start);
                self.error(
                    start..self.pos,
                    format!("unterminated string: expected `{quote}` before the end of the line"),
                );
                return;
            }
            self.pos += c.len_utf8();
        }
        self.push(STRING, start);
    }

    fn punct(&mut self, c: char) {
        let start = self.pos;
        let next = self.peek_at(1);
        let (kind, len) = match (c, next) {
            ('.', Some('.')) => (DOT2, 2),
            ('.', _) => (DOT, 1),
            (':', Some(':')) => (COLON2, 2),
            (':', _) => (COLON, 1),
            ('=', Some('=')) => (EQ2, 2),
            ('=', Some('>')) => (FAT_ARROW, 2),
            ('=', _) => (EQ, 1),
            ('-', Some('>')) => (ARROW, 2),
            ('-', _) => (MINUS, 1),
            ('!', Some('=')) => (NEQ, 2),
            ('!', _) => (BANG, 1),
            ('<', Some('=')) => (LTEQ, 2),
            ('<', _) => (LT, 1),
            ('>', Some('=')) => (GTEQ, 2),
            ('>', _) => (GT, 1),
            (',', _) => (COMMA, 1),
            ('@', _) => (AT, 1),
            ('?', _) => (QUESTION, 1),
            ('+', _) => (PLUS, 1),
            ('*', _) => (STAR, 1),
            ('/', _) => (SLASH, 1),
            ('%', _) => (PERCENT, 1),
            ('(', _) => (L_PAREN, 1),
            (')', _) => (R_PAREN, 1),
            ('[', _) => (L_BRACK, 1),
            (']', _) => (R_BRACK, 1),
            _ => (ERROR_TOKEN, c.len_utf8()),
        };
        self.pos += len;
        match kind {
            L_PAREN | L_BRACK => self.depth = self.depth.saturating_add(1),
            R_PAREN | R_BRACK => self.depth = self.depth.saturating_sub(1),
            ERROR_TOKEN => self.error(start..self.pos, format!("unexpected character {c:?}")),
            _ => {}
        }
        self.push(kind, start);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(src: &str) -> Vec<(SyntaxKind, &str)> {
        let lexed = lex(src);
        let mut pos = 0;
        lexed
            .tokens
            .iter()
            .map(|t| {
                let text = &src[pos..pos + t.len as usize];
                pos += t.len as usize;
                (t.kind, text)
            })
            .filter(|(k, _)| *k != WHITESPACE)
            .collect()
    }

    #[test]
    fn physical_literals_and_ranges() {
        assert_eq!(
            kinds("x 30kph 1.95m -3.5e2m [10..20] 0x1F .5"),
            vec![
                (IDENT, "x"),
                (INT_NUMBER, "30"),
                (UNIT, "kph"),
                (FLOAT_NUMBER, "1.95"),
                (UNIT, "m"),
                (MINUS, "-"),
                (FLOAT_NUMBER, "3.5e2"),
                (UNIT, "m"),
                (L_BRACK, "["),
                (INT_NUMBER, "10"),
                (DOT2, ".."),
                (INT_NUMBER, "20"),
                (R_BRACK, "]"),
                (INT_NUMBER, "0x1F"),
                (FLOAT_NUMBER, ".5"),
                (NEWLINE, ""),
            ]
        );
    }

    #[test]
    fn indentation_blocks() {
        let src = "a:\n    b\n\n    # c\n        d\ne\n";
        let ks: Vec<_> = kinds(src).into_iter().map(|(k, _)| k).collect();
        assert_eq!(
            ks,
            vec![
                IDENT, COLON, NEWLINE, INDENT, IDENT, NEWLINE, LINE_BREAK, COMMENT, LINE_BREAK,
                INDENT, IDENT, NEWLINE, DEDENT, DEDENT, IDENT, NEWLINE
            ]
        );
    }

    #[test]
    fn brackets_join_lines_and_tokens_cover_input() {
        let src = "f(a,\n  b) \\\n + 1 # c\r\n|my id| 'it''s' \"\"\"x\n\"\"\"";
        let lexed = lex(src);
        let total: u32 = lexed.tokens.iter().map(|t| t.len).sum();
        assert_eq!(total as usize, src.len());
        assert!(lexed.errors.is_empty(), "{:?}", lexed.errors);
        let newlines = lexed.tokens.iter().filter(|t| t.kind == NEWLINE).count();
        assert_eq!(newlines, 2);
    }

    #[test]
    fn bad_dedent_and_unterminated_string() {
        let lexed = lex("a:\n    b\n  c\nx = \"abc\n");
        let msgs: Vec<_> = lexed
            .errors
            .iter()
            .map(|e| (e.range.clone(), e.message.as_str()))
            .collect();
        assert_eq!(
            msgs[0],
            (9..11, "unindent does not match any outer indentation level")
        );
        assert_eq!(
            msgs[1],
            (
                17..21,
                "unterminated string: expected `\"` before the end of the line"
            )
        );
    }
}
