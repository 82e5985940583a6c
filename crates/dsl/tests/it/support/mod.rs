//! Checks shared by the syntax test binaries.

use dsl::syntax::{debug_dump, format, parse};

/// If `source` parses cleanly: its formatted text parses cleanly to the same tree (dump
/// without trivia and layout), and formatting that text again changes nothing. Returns whether
/// `source` was formatted (false for a file with syntax errors, which `format` refuses).
pub fn assert_fmt_round_trips(name: &str, source: &str) -> bool {
    let Ok(formatted) = format(source) else {
        return false;
    };
    let again = parse(&formatted);
    assert!(
        again.errors().is_empty(),
        "{name}: formatted text has errors {:?}\n{formatted}",
        again.errors()
    );
    assert_eq!(
        debug_dump(&again.syntax()),
        debug_dump(&parse(source).syntax()),
        "{name}: formatting changed the tree\n{formatted}"
    );
    assert_eq!(
        format(&formatted).ok().as_deref(),
        Some(formatted.as_str()),
        "{name}: formatting is not idempotent"
    );
    true
}
