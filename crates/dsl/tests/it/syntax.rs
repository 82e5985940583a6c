//! Syntax fixtures (roxmltree style): `tests/files/syntax/NAME.osc` beside either `NAME.tree`
//! (the tree dump of a file that parses without error) or `NAME.errors` (every syntax error,
//! one per line, "MESSAGE at NAME.osc:LINE:COL"). One line per case below; the index of cases
//! is `tests/files/syntax/README.md`.
//!
//! Every case also checks that the tree is lossless (its text is the input, byte for byte).
//! `OSC_BLESS=1 cargo test -p oscsim-dsl --test it syntax` writes the expectation files from the
//! current parser: review their diff before committing.
// An integration-test crate: its helpers outside #[test] functions may unwrap too (the
// workspace lint clippy::unwrap_used is for library code; a panic here is the test failing).
#![allow(clippy::unwrap_used)]

use crate::support;

use dsl::syntax::{debug_dump, parse, LineIndex};
use std::path::{Path, PathBuf};

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/syntax")
}

fn check(name: &str) {
    let osc = dir().join(format!("{name}.osc"));
    let source = std::fs::read_to_string(&osc).unwrap_or_else(|e| panic!("{}: {e}", osc.display()));
    let parse = parse(&source);
    assert_eq!(
        parse.syntax().to_string(),
        source,
        "{name}: the tree is not lossless"
    );
    let index = LineIndex::new(&source);
    let file = format!("{name}.osc");
    let errors: String = parse
        .errors()
        .iter()
        .map(|e| format!("{}\n", e.display(&file, &index)))
        .collect();
    let tree_path = dir().join(format!("{name}.tree"));
    let errors_path = dir().join(format!("{name}.errors"));
    let (path, other, actual) = if errors.is_empty() {
        (tree_path, errors_path, debug_dump(&parse.syntax()))
    } else {
        (errors_path, tree_path, errors)
    };
    if std::env::var_os("OSC_BLESS").is_some() {
        std::fs::write(&path, &actual).unwrap();
        let _ = std::fs::remove_file(other);
        return;
    }
    assert!(
        !other.exists(),
        "{name}: {} should not exist",
        other.display()
    );
    let expected = std::fs::read_to_string(&path).unwrap_or_else(|_| {
        panic!(
            "{name}: missing {} — the parse gave:\n{actual}",
            path.display()
        )
    });
    assert_eq!(actual, expected, "{name}: {} differs", path.display());
}

macro_rules! cases {
    ($($name:ident),* $(,)?) => {
        $(#[test] fn $name() { check(stringify!($name)); })*

        /// Every fixture file has a case line above.
        #[test]
        fn every_fixture_is_listed() {
            let listed = [$(stringify!($name)),*];
            for entry in std::fs::read_dir(dir()).unwrap() {
                let path = entry.unwrap().path();
                if path.extension().is_some_and(|e| e == "osc") {
                    let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
                    assert!(listed.contains(&stem.as_str()), "{stem}.osc has no case line");
                }
            }
        }
    };
}

cases! {
    // The domain model's examples (seed 000, §8.7): must parse.
    seed_wide_car,
    seed_motorcycle,
    seed_bicycle,
    seed_stationary_location,
    seed_prevent_collision,
    seed_driving_alongside_group,
    // Issue 30: a keyword before a parenthesis (class 3), `extend ::name` (class 5).
    keyword_before_parenthesis,
    extend_global_prefix,
    // Issue 30, class 6: forbidden forms the grammar rules out.
    err_empty_list,
    err_coverage_without_arguments,
    err_enum_value_not_literal,
    // One file with every construct of the grammar.
    all_constructs,
    // Small cases, one construct or one error each (index: tests/files/syntax/README.md).
    lex_comments,
    lex_line_continuation,
    lex_bracket_joining,
    lex_quoted_identifier,
    lex_strings,
    lex_numbers,
    lex_physical_literals,
    lex_tabs_indentation,
    lex_crlf,
    lex_no_final_newline,
    lex_unicode_identifiers,
    lex_empty_file,
    lex_only_comments,
    err_unterminated_string,
    err_unterminated_long_string,
    err_unterminated_quoted_identifier,
    err_bad_dedent,
    err_unexpected_character,
    err_backslash_not_at_end,
    err_empty_quoted_identifier,
    err_integer_too_large,
    err_negative_integer_too_large,
    err_float_out_of_range,
    int_limits,
    import_statements,
    namespace_statements,
    export_statements,
    physical_type,
    unit_decl,
    enum_decl,
    enum_extension,
    enum_value_reference,
    global_parameter,
    struct_without_body,
    struct_inherits_condition,
    actor_members,
    scenario_qualified_name,
    action_decl,
    modifier_decl,
    extend_types,
    err_import_after_declaration,
    err_si_unknown_base_unit,
    err_si_factor_in_physical_type,
    err_si_order,
    err_enum_missing_bracket,
    err_enum_trailing_comma,
    err_struct_missing_block,
    err_inherits_condition_expression,
    err_top_level_do,
    err_top_level_number,
    err_unexpected_indent,
    err_declaration_in_struct,
    field_declarations,
    var_sample,
    param_with_block,
    keep_qualifiers,
    keep_qualifier_as_name,
    remove_default,
    method_declarations,
    event_declarations,
    coverage,
    keywords_as_field_names,
    for_constraint,
    err_sample_in_parameter,
    err_method_missing_is,
    err_method_bad_body,
    err_do_in_struct,
    err_emit_in_scenario,
    err_field_missing_type,
    err_keep_without_parens,
    err_remove_default_expression,
    err_list_of_list,
    err_until_in_struct,
    do_invocation,
    do_nested_compositions,
    composition_arguments,
    labels,
    with_blocks,
    composition_with,
    wait_forms,
    emit_and_call,
    on_directive,
    modifier_application,
    err_invocation_in_on,
    err_wait_in_with,
    err_invocation_without_call,
    err_composition_without_block,
    label_keyword_name,
    err_missing_with_colon,
    expr_arithmetic_precedence,
    expr_logic_precedence,
    expr_ternary,
    expr_relations,
    expr_postfix_chain,
    expr_unary_minus,
    expr_lists_ranges,
    expr_qualified_names,
    expr_it,
    expr_arguments,
    expr_not_precedence,
    err_positional_after_named,
    err_missing_operand,
    err_unclosed_paren,
    err_unclosed_list,
    err_trailing_comma_args,
    err_several_errors,
    err_range_missing_end,
    err_event_field_without_if,
    err_every_bad_offset,
    err_deep_nesting,
    err_deep_blocks,
}

/// `fmt` on every test file that parses (syntax, semantic and seed fixtures, imported library
/// files): the result parses to the same tree (dump without trivia and layout), and formatting
/// it again changes nothing.
#[test]
fn fmt_round_trips_every_fixture() {
    let mut checked = 0;
    let mut stack = vec![Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files")];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            if path.extension().is_none_or(|e| e != "osc") {
                continue;
            }
            let source = std::fs::read_to_string(&path).unwrap();
            let name = path.display().to_string();
            if support::assert_fmt_round_trips(&name, &source) {
                checked += 1;
            }
        }
    }
    // 118 syntax fixtures (some are errors), 130 semantic cases and their library files, the
    // seed's five examples: well over 200 files parse.
    assert!(checked >= 200, "only {checked} test files formatted");
}

/// The standard library shipped as .osc source (crates/dsl/stdlib) parses without error and
/// round-trips through fmt.
#[test]
fn stdlib_sources_parse_and_format() {
    let mut stack = vec![Path::new(env!("CARGO_MANIFEST_DIR")).join("stdlib")];
    let mut checked = 0;
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "osc") {
                let source = std::fs::read_to_string(&path).unwrap();
                let parse = parse(&source);
                let index = LineIndex::new(&source);
                let name = path.display().to_string();
                let errors: Vec<String> = parse
                    .errors()
                    .iter()
                    .map(|e| e.display(&name, &index).to_string())
                    .collect();
                assert!(errors.is_empty(), "{errors:#?}");
                assert!(support::assert_fmt_round_trips(&name, &source));
                checked += 1;
            }
        }
    }
    assert!(checked >= 1, "no stdlib .osc file found");
}
