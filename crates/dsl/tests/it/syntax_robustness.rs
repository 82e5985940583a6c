//! Bad input never panics, hangs or overflows the stack: property tests over the lexer and
//! parser (random bytes, random token soups, mutated fixture files), deep nesting and huge
//! literals. For every input the tree must give the input back byte for byte, every error must
//! lie inside the input, and formatting must either refuse (syntax errors) or round-trip.
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

use crate::support;

use dsl::syntax::{debug_dump, parse, MAX_DEPTH};
use proptest::prelude::*;
use std::path::Path;

/// The invariants every parse keeps, whatever the input.
fn check_invariants(source: &str) {
    let parse = parse(source);
    assert_eq!(parse.syntax().to_string(), source, "tree not lossless");
    for error in parse.errors() {
        let range = error.range();
        assert!(
            range.start <= range.end && range.end <= source.len(),
            "error range {range:?} outside the input"
        );
        assert!(
            source.is_char_boundary(range.start),
            "error start {} inside a character",
            range.start
        );
        assert!(!error.message().is_empty());
    }
    support::assert_fmt_round_trips("input", source);
}

/// Runs `f` on a thread with a 1 MiB stack: half the default test thread's, so the parser's
/// depth limit is shown to hold with margin.
fn on_small_stack(f: impl FnOnce() + Send + 'static) {
    std::thread::Builder::new()
        .stack_size(1 << 20)
        .spawn(f)
        .unwrap()
        .join()
        .unwrap();
}

fn fixtures() -> Vec<String> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/syntax");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "osc"))
        .collect();
    files.sort();
    files
        .iter()
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect()
}

/// Pieces that make up token soups: every token class, keywords, layout.
const PIECES: &[&str] = &[
    "scenario",
    "struct",
    "actor",
    "action",
    "modifier",
    "extend",
    "enum",
    "type",
    "unit",
    "global",
    "import",
    "namespace",
    "export",
    "use",
    "inherits",
    "do",
    "serial",
    "parallel",
    "one_of",
    "on",
    "emit",
    "call",
    "wait",
    "until",
    "with",
    "keep",
    "default",
    "hard",
    "remove_default",
    "def",
    "is",
    "expression",
    "undefined",
    "external",
    "only",
    "event",
    "var",
    "sample",
    "rise",
    "fall",
    "elapsed",
    "every",
    "offset",
    "cover",
    "record",
    "it",
    "as",
    "if",
    "in",
    "not",
    "and",
    "or",
    "list",
    "of",
    "range",
    "SI",
    "factor",
    "for",
    "true",
    "false",
    "inf",
    "nan",
    "x",
    "ego",
    "|q id|",
    "42",
    "0x1F",
    "3.5e2",
    ".5",
    "30kph",
    "1.95m",
    "\"s\"",
    "'t'",
    "\"\"\"l\"\"\"",
    "(",
    ")",
    "[",
    "]",
    ",",
    ":",
    "::",
    ".",
    "..",
    "=",
    "==",
    "!=",
    "<",
    "<=",
    ">",
    ">=",
    "+",
    "-",
    "*",
    "/",
    "%",
    "?",
    "@",
    "!",
    "->",
    "=>",
    "#c",
    "\\",
    "\n",
    "\n    ",
    "\n        ",
    "\n\t",
    " ",
    "\r\n",
    "|",
    "\"",
    "$",
];

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn random_bytes(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        check_invariants(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn random_text(text in "\\PC{0,300}") {
        check_invariants(&text);
    }

    #[test]
    fn token_soup(pieces in proptest::collection::vec(0..PIECES.len(), 0..120), spaces in proptest::collection::vec(any::<bool>(), 120)) {
        let mut text = String::new();
        for (i, &p) in pieces.iter().enumerate() {
            text.push_str(PIECES[p]);
            if spaces[i] {
                text.push(' ');
            }
        }
        check_invariants(&text);
    }

    #[test]
    fn mutated_fixtures(file in 0usize..1000, edits in proptest::collection::vec((any::<u16>(), 0u8..4, 0..PIECES.len()), 1..6)) {
        let all = fixtures();
        let mut text = all[file % all.len()].clone().into_bytes();
        for (at, op, piece) in edits {
            let at = at as usize % (text.len() + 1);
            match op {
                0 => { text.drain(at..(at + 5).min(text.len())); }
                1 => { text.splice(at..at, PIECES[piece].bytes()); }
                2 => { let end = (at + 20).min(text.len()); let copy = text[at..end].to_vec(); text.splice(at..at, copy); }
                _ => { if at < text.len() { text[at] = b'('; } }
            }
        }
        check_invariants(&String::from_utf8_lossy(&text));
    }
}

/// 100,000 levels of each kind of nesting (5,000 for indentation): an error at the limit, no stack overflow.
#[test]
fn deep_nesting_is_an_error_not_an_overflow() {
    on_small_stack(|| {
        let n = 100_000;
        let cases = [
            (
                "parentheses",
                format!("global a: int = {}1{}\n", "(".repeat(n), ")".repeat(n)),
            ),
            (
                "brackets",
                format!("global a: int = {}1{}\n", "[".repeat(n), "]".repeat(n)),
            ),
            ("unclosed", format!("global a: int = {}\n", "(".repeat(n))),
            (
                "calls",
                format!("global a: int = {}1{}\n", "f(".repeat(n), ")".repeat(n)),
            ),
            ("not", format!("global a: bool = {}x\n", "not ".repeat(n))),
            ("minus", format!("global a: int = {}x\n", "- ".repeat(n))),
            (
                "field chain",
                format!("global a: int = x{}\n", ".y".repeat(n)),
            ),
            (
                "sum chain",
                format!("global a: int = 1{}\n", " + 1".repeat(n)),
            ),
            (
                "ternary",
                format!("global a: int = {}1\n", "c ? 1 : ".repeat(n)),
            ),
            (
                "lists",
                format!("global a: int = {}1{}\n", "[1, ".repeat(n), "]".repeat(n)),
            ),
            // Indentation levels: level i takes i spaces, so the file grows with the square of
            // the depth (100,000 levels would be 5 GB); 5,000 levels (12.5 MB) are 39 times the
            // limit.
            (
                "blocks",
                "scenario s:\n do serial:\n".to_string()
                    + &(2..5_000)
                        .map(|i| format!("{}serial:\n", " ".repeat(i)))
                        .collect::<String>(),
            ),
        ];
        for (what, source) in cases {
            let parse = parse(&source);
            assert_eq!(parse.syntax().to_string(), source, "{what}: not lossless");
            let deep =
                format!("nesting too deep: more than {MAX_DEPTH} levels of expressions or blocks");
            assert!(
                parse.errors().iter().any(|e| e.message() == deep),
                "{what}: no depth error in {:?}",
                parse.errors().iter().take(3).collect::<Vec<_>>()
            );
            // The tree can be walked and dropped on this stack too.
            let _ = debug_dump(&parse.syntax());
        }
    });
}

/// Nesting just under the limit parses without error (the limit is not hit early).
#[test]
fn nesting_under_the_limit_parses() {
    on_small_stack(|| {
        let n = (MAX_DEPTH - 2) as usize;
        let source = format!("global a: int = {}1{}\n", "(".repeat(n), ")".repeat(n));
        let parse = parse(&source);
        assert!(parse.errors().is_empty(), "{:?}", parse.errors());
    });
}

/// A 10,000-digit integer is an error naming the literal; a 10,000-digit float is a value.
#[test]
fn huge_literals_are_errors_or_values() {
    let digits = "9".repeat(10_000);
    let parse = parse(&format!("global a: uint = {digits}\n"));
    let errors: Vec<_> = parse
        .errors()
        .iter()
        .map(|e| (e.range(), e.message().to_string()))
        .collect();
    // `global a: uint = ` is 17 bytes: the literal starts at offset 17.
    assert_eq!(
        errors,
        vec![(17..17 + 10_000, "integer literal `99999999999999999999… (10000 characters)` does not fit uint (64-bit unsigned)".to_string())]
    );

    let parse = dsl::syntax::parse(&format!("global a: float = 0.{digits}\n"));
    assert!(parse.errors().is_empty(), "{:?}", parse.errors());
    let literal = parse
        .syntax()
        .descendants()
        .find_map(<dsl::syntax::ast::Literal as dsl::syntax::AstNode>::cast)
        .unwrap();
    // 0.999… (10,000 nines) rounds to 1.0 in f64.
    assert_eq!(
        literal.value(),
        Ok(dsl::syntax::ast::LiteralValue::Number(
            dsl::syntax::ast::Number::Float(1.0)
        ))
    );

    let parse = dsl::syntax::parse(&format!("global a: float = 1e{digits}\n"));
    assert_eq!(parse.errors().len(), 1);
    assert!(parse.errors()[0].message().contains("is out of range"));
}

/// Many errors in one file are all reported (one per statement), in source order, without the
/// parse slowing down quadratically (100,000 stray characters finish).
#[test]
fn many_errors_are_reported_in_one_pass() {
    let source = "struct s:\n".to_string() + &"    x: = 1\n".repeat(1000);
    let parse = parse(&source);
    assert_eq!(parse.errors().len(), 1000);
    let index = dsl::syntax::LineIndex::new(&source);
    let last = parse.errors().last().unwrap();
    assert_eq!(
        last.display("f.osc", &index).to_string(),
        "expected a type, found `=` at f.osc:1001:8"
    );

    let garbage = "$".repeat(100_000);
    assert_eq!(parse_count(&garbage), 100_000);
}

fn parse_count(source: &str) -> usize {
    parse(source).errors().len()
}

/// `list of list of …` 100,000 times: one error, no recursion.
#[test]
fn nested_list_types_are_one_error() {
    on_small_stack(|| {
        let source = format!("global a: {}int\n", "list of ".repeat(100_000));
        let parse = parse(&source);
        let messages: Vec<_> = parse
            .errors()
            .iter()
            .map(|e| (e.range(), e.message().to_string()))
            .collect();
        // `global a: list of ` is 18 bytes: the second `list` starts at offset 18.
        assert_eq!(messages, vec![(18..22, "expected a non-list type after `list of`, found `list of` (lists of lists are not in the language)".to_string())]);
    });
}
