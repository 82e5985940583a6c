//! The OpenSCENARIO DSL 2.1 front end: any text lexed (`dsl::syntax::lex`) and parsed
//! (`dsl::syntax::parse`, which never fails), the typed AST walked. Must not panic or hang; the
//! tokens cover the text exactly, in order; the tree is lossless (its text is the input byte for
//! byte); every lexer and parser error's range lies inside the text on character boundaries and
//! renders with its line and column. A text that parses without error is formatted (`fmt`):
//! the result parses without error to the same tree and formats to itself. Every text is then
//! checked and resolved (`dsl::check_source_with`, imports unreadable): every semantic error
//! lies inside the text and renders with its position.
#![no_main]

use dsl::syntax::{self, AstNode, LineIndex};
use libfuzzer_sys::fuzz_target;

mod support;

fn check_range(text: &str, r: &std::ops::Range<usize>) {
    assert!(
        r.start <= r.end && r.end <= text.len(),
        "{r:?} outside {} bytes",
        text.len()
    );
    assert!(
        text.is_char_boundary(r.start) && text.is_char_boundary(r.end),
        "{r:?} not on character boundaries"
    );
}

fuzz_target!(|data: &[u8]| {
    support::watchdog::start(data);
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let lexed = syntax::lex(text);
    let covered: usize = lexed.tokens.iter().map(|t| t.len as usize).sum();
    assert_eq!(covered, text.len(), "tokens do not cover the text");
    for e in &lexed.errors {
        check_range(text, &e.range);
    }
    let parse = syntax::parse(text);
    assert_eq!(parse.syntax().to_string(), text, "the tree is not lossless");
    let index = LineIndex::new(text);
    for e in parse.errors() {
        check_range(text, &e.range());
        let _ = e.display("fuzz.osc", &index).to_string();
    }
    let file = parse.tree();
    for item in file.items() {
        let _ = item.syntax().kind();
    }
    let dump = syntax::debug_dump(&parse.syntax());
    if parse.errors().is_empty() {
        if let Ok(formatted) = syntax::format(text) {
            let again = syntax::parse(&formatted);
            assert!(again.errors().is_empty(), "formatted text has errors");
            assert_eq!(
                syntax::debug_dump(&again.syntax()),
                dump,
                "fmt changed the tree"
            );
            assert_eq!(
                syntax::format(&formatted).ok().as_deref(),
                Some(formatted.as_str()),
                "fmt is not idempotent"
            );
        }
    }
    if let Err(e) = dsl::check_source_with("fuzz.osc", text, &|_| None) {
        let d = e.diagnostics();
        for item in &d.items {
            let at = d.position(item.span);
            assert!(
                !at.starts_with("?:"),
                "{} points into no file",
                item.message
            );
        }
        let _ = d.lines();
    }
});
