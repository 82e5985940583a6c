//! Parser machinery: a cursor over the lexer's tokens that builds the rowan green tree.
//!
//! Grammar functions (in [`super::grammar`]) look at the next non-trivia tokens, open and close
//! nodes and consume tokens; trivia are attached automatically: pending trivia go into the
//! parent before a node opens, so a node starts at its first significant token.
//!
//! Errors never stop the parse. `expect` reports "expected X, found Y" and consumes nothing; a
//! statement that cannot go on is closed and the rest of its logical line (with any block below
//! it) is wrapped in an [`ERROR`] node. At most one error is kept per source offset, so one
//! missing `)` does not report once per open expression level.
//!
//! Recursion is bounded: [`MAX_DEPTH`] nested expressions or blocks. Deeper input is reported and
//! skipped flat, so 100,000 nested brackets or indentation levels give an error, not a stack
//! overflow.

use super::kind::SyntaxKind::{self, *};
use super::lexer::{Lexed, Token};
use rowan::{Checkpoint, GreenNode, GreenNodeBuilder};
use std::ops::Range;

/// Deepest nesting of expressions and blocks the parser descends into.
pub const MAX_DEPTH: u32 = 128;

/// A syntax error found by the parser (or passed on from the lexer).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParseError {
    /// Byte range of the offending text (empty at the position where something is missing).
    pub range: Range<usize>,
    /// Whether the lexer found it.
    pub lexical: bool,
    /// Lowercase message without position, e.g. "expected `:`, found identifier `x`".
    pub message: String,
}

/// Token cursor and tree builder.
pub(crate) struct Parser<'s> {
    src: &'s str,
    /// `(kind, start offset, end offset)` of every token.
    tokens: Vec<(SyntaxKind, usize, usize)>,
    /// Index of the next token to add to the tree (may be trivia).
    pos: usize,
    builder: GreenNodeBuilder<'static>,
    errors: Vec<ParseError>,
    /// Start offsets of the errors recorded (one error per offset).
    error_starts: std::collections::HashSet<usize>,
    /// Current nesting of expressions / blocks.
    pub(crate) depth: u32,
    /// Errors starting before this offset are follow-ons of a reported one and are dropped.
    quiet_until: usize,
}

impl<'s> Parser<'s> {
    pub(crate) fn new(src: &'s str, lexed: &Lexed) -> Parser<'s> {
        let mut offset = 0usize;
        let tokens = lexed
            .tokens
            .iter()
            .map(|&Token { kind, len }| {
                let start = offset;
                offset += len as usize;
                (kind, start, offset)
            })
            .collect();
        let errors: Vec<ParseError> = lexed
            .errors
            .iter()
            .map(|e| ParseError {
                range: e.range.clone(),
                lexical: true,
                message: e.message.clone(),
            })
            .collect();
        Parser {
            src,
            tokens,
            pos: 0,
            builder: GreenNodeBuilder::new(),
            error_starts: errors.iter().map(|e| e.range.start).collect(),
            errors,
            depth: 0,
            quiet_until: 0,
        }
    }

    /// Adds every token left (the trivia after the last significant token) to the current
    /// node; the file rule calls it before closing the root.
    pub(crate) fn bump_remaining(&mut self) {
        while self.pos < self.tokens.len() {
            self.bump_raw();
        }
    }

    pub(crate) fn finish(mut self) -> (GreenNode, Vec<ParseError>) {
        self.errors.sort_by_key(|e| (e.range.start, e.range.end));
        (self.builder.finish(), self.errors)
    }

    /// Index of the `n`-th non-trivia token from the cursor.
    fn nth_index(&self, mut n: usize) -> Option<usize> {
        let mut i = self.pos;
        while i < self.tokens.len() {
            if !self.tokens[i].0.is_trivia() {
                if n == 0 {
                    return Some(i);
                }
                n -= 1;
            }
            i += 1;
        }
        None
    }

    /// Kind of the `n`-th next significant token; `EOF` is reported as [`DEDENT`]-free
    /// [`SyntaxKind::__LAST`].
    pub(crate) fn nth(&self, n: usize) -> SyntaxKind {
        self.nth_index(n)
            .map_or(SyntaxKind::__LAST, |i| self.tokens[i].0)
    }

    pub(crate) fn current(&self) -> SyntaxKind {
        self.nth(0)
    }

    pub(crate) fn at(&self, kind: SyntaxKind) -> bool {
        self.current() == kind
    }

    pub(crate) fn at_eof(&self) -> bool {
        self.current() == SyntaxKind::__LAST
    }

    /// Text of the `n`-th next significant token ("" at the end).
    pub(crate) fn nth_text(&self, n: usize) -> &'s str {
        self.nth_index(n)
            .map_or("", |i| &self.src[self.tokens[i].1..self.tokens[i].2])
    }

    /// Whether the `n`-th next token is the word `word` (a contextual keyword candidate).
    pub(crate) fn nth_word(&self, n: usize, word: &str) -> bool {
        self.nth(n) == IDENT && self.nth_text(n) == word
    }

    pub(crate) fn at_word(&self, word: &str) -> bool {
        self.nth_word(0, word)
    }

    /// Whether the last significant token of the current logical line (before its `NEWLINE`
    /// or the end of input) is a `kind`.
    pub(crate) fn line_ends_with(&self, kind: SyntaxKind) -> bool {
        let mut last = None;
        for t in self.tokens[self.pos..].iter().filter(|t| !t.0.is_trivia()) {
            if matches!(t.0, NEWLINE | INDENT | DEDENT) {
                break;
            }
            last = Some(t.0);
        }
        last == Some(kind)
    }

    /// Whether trivia separate the `n`-th and `n+1`-th significant tokens.
    pub(crate) fn trivia_before(&self, n: usize) -> bool {
        match (self.nth_index(n), self.nth_index(n + 1)) {
            (Some(a), Some(b)) => b > a + 1,
            _ => false,
        }
    }

    /// Byte range of the next significant token (empty at the end of the input).
    pub(crate) fn current_range(&self) -> Range<usize> {
        match self.nth_index(0) {
            Some(i) => self.tokens[i].1..self.tokens[i].2,
            None => self.src.len()..self.src.len(),
        }
    }

    fn bump_raw(&mut self) {
        let (kind, start, end) = self.tokens[self.pos];
        self.builder.token(kind.into(), &self.src[start..end]);
        self.pos += 1;
    }

    fn flush_trivia(&mut self) {
        while self.pos < self.tokens.len() && self.tokens[self.pos].0.is_trivia() {
            self.bump_raw();
        }
    }

    /// Adds the next significant token (and the trivia before it) to the current node.
    pub(crate) fn bump(&mut self) {
        self.flush_trivia();
        if self.pos < self.tokens.len() {
            self.bump_raw();
        }
    }

    /// Adds the next token re-kinded as `kind` (contextual keywords).
    pub(crate) fn bump_as(&mut self, kind: SyntaxKind) {
        self.flush_trivia();
        if self.pos < self.tokens.len() {
            let (_, start, end) = self.tokens[self.pos];
            self.builder.token(kind.into(), &self.src[start..end]);
            self.pos += 1;
        }
    }

    /// Consumes the word `word` as keyword `kind` if it is next.
    pub(crate) fn eat_word(&mut self, word: &str, kind: SyntaxKind) -> bool {
        if self.at_word(word) {
            self.bump_as(kind);
            true
        } else {
            false
        }
    }

    pub(crate) fn eat(&mut self, kind: SyntaxKind) -> bool {
        if self.at(kind) {
            self.bump();
            true
        } else {
            false
        }
    }

    /// Opens the root node: unlike [`Parser::start`], leading trivia go inside it.
    pub(crate) fn start_root(&mut self, kind: SyntaxKind) {
        self.builder.start_node(kind.into());
    }

    pub(crate) fn start(&mut self, kind: SyntaxKind) {
        self.flush_trivia();
        self.builder.start_node(kind.into());
    }

    pub(crate) fn finish_node(&mut self) {
        self.builder.finish_node();
    }

    pub(crate) fn checkpoint(&mut self) -> Checkpoint {
        self.flush_trivia();
        self.builder.checkpoint()
    }

    pub(crate) fn start_at(&mut self, checkpoint: Checkpoint, kind: SyntaxKind) {
        self.builder.start_node_at(checkpoint, kind.into());
    }

    /// How the next token is named in "found …".
    pub(crate) fn found(&self) -> String {
        let mut n = 0;
        while self.nth(n) == DEDENT {
            n += 1;
        }
        let kind = self.nth(n);
        match kind {
            NEWLINE if self.nth_text(n).is_empty() => "end of file".to_string(),
            SyntaxKind::__LAST => "end of file".to_string(),
            NEWLINE => "end of line".to_string(),
            INDENT => "an indented block".to_string(),
            DEDENT => "end of block".to_string(),
            IDENT | INT_NUMBER | FLOAT_NUMBER | UNIT | STRING | ERROR_TOKEN => {
                let text = self.nth_text(n);
                let shown: String = text.chars().take(40).collect();
                let dots = if shown.len() < text.len() { "…" } else { "" };
                format!("{} `{shown}{dots}`", kind.describe())
            }
            _ => kind.describe().to_string(),
        }
    }

    /// Records an error at `range`, unless one is already recorded at the same start.
    pub(crate) fn error_at(&mut self, range: Range<usize>, message: impl Into<String>) {
        if range.start < self.quiet_until || !self.error_starts.insert(range.start) {
            return;
        }
        self.errors.push(ParseError {
            range,
            lexical: false,
            message: message.into(),
        });
    }

    /// Records "expected {what}, found {next token}" at the next token.
    pub(crate) fn error_expected(&mut self, what: &str) {
        let message = format!("expected {what}, found {}", self.found());
        let range = self.current_range();
        self.error_at(range, message);
    }

    /// Consumes `kind` or reports it missing.
    pub(crate) fn expect(&mut self, kind: SyntaxKind) -> bool {
        if self.eat(kind) {
            return true;
        }
        self.error_expected(kind.describe());
        false
    }

    /// Consumes the word `word` as `kind`, or reports it missing.
    pub(crate) fn expect_word(&mut self, word: &str, kind: SyntaxKind) -> bool {
        if self.eat_word(word, kind) {
            return true;
        }
        self.error_expected(&format!("`{word}`"));
        false
    }

    /// Wraps the rest of the logical line, and any indented block below it, in an [`ERROR`]
    /// node; consumes the line's NEWLINE. Used when a statement cannot go on.
    pub(crate) fn skip_line(&mut self) {
        let mut started = false;
        while !self.at_eof() && !self.at(NEWLINE) && !self.at(DEDENT) {
            if !started {
                self.start(ERROR);
                started = true;
            }
            self.bump();
        }
        if started {
            self.finish_node();
        }
        if self.eat(NEWLINE) && self.at(INDENT) {
            self.skip_block();
        }
    }

    /// Wraps an INDENT … matching DEDENT run in an [`ERROR`] node, without descending.
    pub(crate) fn skip_block(&mut self) {
        self.start(ERROR);
        let mut level = 0u32;
        while !self.at_eof() {
            match self.current() {
                INDENT => level += 1,
                DEDENT => level = level.saturating_sub(1),
                _ => {}
            }
            self.bump();
            if level == 0 {
                break;
            }
        }
        self.finish_node();
    }

    /// Ends a statement: expects NEWLINE; anything else left on the line is reported and skipped.
    pub(crate) fn end_of_line(&mut self) {
        if self.eat(NEWLINE) || self.at_eof() || self.at(DEDENT) {
            return;
        }
        self.error_expected("end of line");
        self.skip_line();
    }

    /// Enters one nesting level; false (with an error, once) when [`MAX_DEPTH`] is reached.
    pub(crate) fn enter(&mut self) -> bool {
        if self.depth >= MAX_DEPTH {
            let range = self.current_range();
            self.error_at(
                range,
                format!("nesting too deep: more than {MAX_DEPTH} levels of expressions or blocks"),
            );
            return false;
        }
        self.depth += 1;
        true
    }

    pub(crate) fn leave(&mut self) {
        self.depth = self.depth.saturating_sub(1);
    }

    /// Skips flat to the end of the logical line (tokens in brackets have no NEWLINE), for input
    /// nested beyond [`MAX_DEPTH`].
    pub(crate) fn skip_too_deep(&mut self) {
        self.start(ERROR);
        while !self.at_eof() && !self.at(NEWLINE) && !self.at(DEDENT) && !self.at(INDENT) {
            self.bump();
        }
        self.finish_node();
        // The enclosing levels' missing `)` and `]` at the line's end are follow-ons.
        self.quiet_until = self.current_range().end + 1;
    }
}
