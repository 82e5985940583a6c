//! Syntax of ASAM OpenSCENARIO DSL 2.1 (compatible with 2.0): lexer, parser, lossless concrete
//! syntax tree (CST) with byte spans, a typed AST view over it, and canonical formatting.
//!
//! Grammar followed: the language reference §7.2 "Language structure and syntax" of ASAM
//! OpenSCENARIO DSL 2.1.0 (lexical structure §7.2.1, grammar §7.2.2, and its informative
//! `grammar.ebnf`), which extends 2.0 with namespaces (`namespace … use …`, `export`, `ns::name`)
//! and the `enum!member` reference without the enum name. Deviations and readings where the
//! grammar is ambiguous are listed under "Choices" below and in `docs/dsl.md`.
//!
//! # Entry point
//!
//! ```
//! use dsl::syntax::AstNode;
//! let parse = dsl::syntax::parse("scenario s:\n    ego: vehicle\n    do ego.drive()\n");
//! assert!(parse.errors().is_empty());
//! assert_eq!(parse.syntax().to_string(), "scenario s:\n    ego: vehicle\n    do ego.drive()\n");
//! let file = parse.tree();
//! let scenario = file.items().next().unwrap();
//! assert_eq!(scenario.syntax().kind(), dsl::syntax::SyntaxKind::SCENARIO_DECL);
//! ```
//!
//! [`parse`] never fails and never panics: it returns the whole tree plus every error found
//! ([`Parse::errors`]); bad input gives `ERROR` nodes in the tree. This is the function for
//! fuzzing.
//!
//! # The tree
//!
//! The CST is a [rowan](https://docs.rs/rowan) tree ([`SyntaxNode`], [`SyntaxToken`]): nodes
//! have a [`SyntaxKind`], children (nodes and tokens), a parent and a byte range
//! (`node.text_range()`); `node.to_string()` is its exact source text, and for the root that is
//! the whole input, byte for byte (trivia included). Walk it with `children()`,
//! `children_with_tokens()`, `descendants()`, `preorder()`; or use the typed view in [`ast`]
//! (`ast::SourceFile`, `ast::StructDecl`, `ast::Expr`, …), which wraps nodes and has accessors
//! named after the grammar (`StructDecl::name()`, `KeepConstraint::expr()`).
//!
//! Tokens: trivia (`WHITESPACE`, `COMMENT`, `LINE_BREAK`, `LINE_CONTINUATION`) sit between
//! significant tokens and are never needed for meaning; `NEWLINE` ends a logical line;
//! zero-width `INDENT` / `DEDENT` open and close a [`SyntaxKind::BLOCK`]. Words are `IDENT` unless
//! the grammar uses them as keywords there, where they get their keyword kind (`STRUCT_KW`, …):
//! keywords are contextual (§7.2.1.5.1). A number with a glued unit is `INT_NUMBER`/`FLOAT_NUMBER`
//! then `UNIT` inside one `LITERAL` node.
//!
//! A statement's node ends before its NEWLINE (the NEWLINE follows it in the parent BLOCK or
//! SOURCE_FILE), so a node's range is exactly the statement's text; a member with a block ends
//! with its BLOCK, which holds `NEWLINE INDENT … DEDENT`.
//!
//! Node kinds, one per production (children in order, `?` optional, `*` repeated):
//!
//! | node | children |
//! | --- | --- |
//! | `SOURCE_FILE` | statements and declarations |
//! | `IMPORT_STMT` | `import`, `STRING` or `IDENT (. IDENT)*` |
//! | `NAMESPACE_STMT` | `namespace`, NAME, (`use`, NAME_REF (`,` NAME_REF)*)? |
//! | `EXPORT_STMT` | `export`, EXPORT_SPEC (`,` EXPORT_SPEC)* |
//! | `PHYSICAL_TYPE_DECL` | `type`, NAME, `is`, SI_SPEC |
//! | `UNIT_DECL` | `unit`, NAME, `of`, NAME_REF, `is`, SI_SPEC |
//! | `SI_SPEC` | `SI`, `(`, SI_ARG (`,` SI_ARG)*, `)`; SI_ARG = base unit IDENT or `factor`/`offset`, `:`, expression |
//! | `ENUM_DECL` | `enum`, NAME, `:`, ENUM_MEMBER_LIST |
//! | `ENUM_EXTENSION` | `extend`, NAMED_TYPE, `:`, ENUM_MEMBER_LIST |
//! | `ENUM_MEMBER_LIST` | `[`, ENUM_MEMBER (NAME, (`=`, expression)?) separated by `,`, `]` |
//! | `STRUCT_DECL`, `ACTOR_DECL` | keyword, NAME, INHERITS?, (`:`, BLOCK)? |
//! | `SCENARIO_DECL`, `ACTION_DECL` | keyword, BEHAVIOR_NAME, INHERITS?, (`:`, BLOCK)? |
//! | `MODIFIER_DECL` | `modifier`, BEHAVIOR_NAME, (`of`, NAMED_TYPE)?, (`:`, BLOCK)? |
//! | `EXTEND_DECL` | `extend`, NAMED_TYPE or PRIMITIVE_TYPE, `:`, BLOCK |
//! | `GLOBAL_PARAM_DECL` | `global`, PARAM_DECL |
//! | `INHERITS` | `inherits`, NAMED_TYPE, INHERITS_CONDITION (`(`, NAME_REF, `==`, expression, `)`)? |
//! | `BLOCK` | NEWLINE, INDENT, members, DEDENT |
//! | `BEHAVIOR_NAME` | (NAME_REF `.`)?, NAME — `actor.behavior` being declared |
//! | `NAME` / `NAME_REF` | a declared / referenced qualified identifier: IDENT, or IDENT? `::` IDENT |
//! | `PRIMITIVE_TYPE` | `int`, `uint`, `float`, `bool` or `string` |
//! | `NAMED_TYPE` | NAME_REF (`.`, NAME_REF)? |
//! | `LIST_TYPE` / `RANGE_TYPE` | `list`/`range`, `of`, type |
//! | `EVENT_DECL` | `event`, NAME, (`(`, PARAM_LIST, `)`)?, (`is`, EVENT_SPEC)? |
//! | `PARAM_DECL` | FIELD_NAMES, `:`, type, (`=`, expression or SAMPLE_EXPR)?, PARAM_WITH? |
//! | `VAR_DECL` | `var`, FIELD_NAMES, `:`, type, (`=`, expression or SAMPLE_EXPR)? |
//! | `FIELD_NAMES` | NAME (`,` NAME)* |
//! | `PARAM_WITH` | `with`, `:`, BLOCK |
//! | `KEEP_CONSTRAINT` | `keep`, `(`, (`default` or `hard`)?, expression, `)` |
//! | `REMOVE_DEFAULT` | `remove_default`, `(`, expression, `)` |
//! | `METHOD_DECL` | `def`, NAME, `(`, PARAM_LIST?, `)`, RETURN_TYPE (`->`, type)?, METHOD_BODY |
//! | `METHOD_BODY` | `is`, `only`?, (`expression` expression / `undefined` / `external` CALL_EXPR) |
//! | `COVERAGE_DECL` | `cover` or `record`, ARG_LIST |
//! | `MODIFIER_APPLICATION` | CALL_EXPR |
//! | `FOR_CONSTRAINT` | `for`, NAME, `in`, expression, `:`, BLOCK |
//! | `ON_DIRECTIVE` | `on`, EVENT_SPEC, `:`, BLOCK |
//! | `DO_DIRECTIVE` | `do`, one do-member node |
//! | `COMPOSITION` | LABEL?, `serial`/`parallel`/`one_of`, ARG_LIST?, `:`, BLOCK, BEHAVIOR_WITH? |
//! | `BEHAVIOR_INVOCATION` | LABEL?, CALL_EXPR, BEHAVIOR_WITH? |
//! | `WAIT_DIRECTIVE` / `UNTIL_DIRECTIVE` | LABEL?, `wait`/`until`, EVENT_SPEC |
//! | `EMIT_DIRECTIVE` | LABEL?, `emit`, NAME_REF, ARG_LIST? |
//! | `CALL_DIRECTIVE` | LABEL?, `call`, CALL_EXPR |
//! | `LABEL` | NAME, `:` |
//! | `BEHAVIOR_WITH` | `with`, `:`, BLOCK |
//! | `EVENT_SPEC` | EVENT_REF (`@`, expression), EVENT_FIELD (`as`, NAME)?, (`if`, condition)? — or a condition |
//! | `RISE_EXPR`, `FALL_EXPR`, `ELAPSED_EXPR` | keyword, `(`, expression, `)` |
//! | `EVERY_EXPR` | `every`, `(`, expression, (`,`, `offset`, `:`, expression)?, `)` |
//! | `SAMPLE_EXPR` | `sample`, `(`, expression, `,`, EVENT_SPEC, (`,`, expression)?, `)` |
//! | `PARAM_LIST` | PARAM (NAME, `:`, type, (`=`, expression)?) separated by `,` |
//! | `ARG_LIST` | `(`, ARG (expression) / NAMED_ARG (NAME_REF, `:`, expression) separated by `,`, `)` |
//! | `LITERAL` | (`-`/`+`)?, number, UNIT? — or STRING, `true`, `false`, `inf`, `nan` |
//! | `NAME_EXPR` | NAME_REF |
//! | `ENUM_VALUE_EXPR` | NAME_REF, `!`, NAME_REF |
//! | `IT_EXPR` | `it` |
//! | `PAREN_EXPR` | `(`, expression, `)` |
//! | `LIST_EXPR` | `[`, expressions separated by `,`, `]` |
//! | `RANGE_EXPR` | `[`, expression, `..`, expression, `]` — or `range`, `(`, expression, `,`, expression, `)` |
//! | `BIN_EXPR` | expression, operator token, expression |
//! | `PREFIX_EXPR` | `not` or `-`, expression |
//! | `TERNARY_EXPR` | expression, `?`, expression, `:`, expression |
//! | `FIELD_EXPR` | expression, `.`, NAME_REF |
//! | `INDEX_EXPR` | expression, `[`, expression, `]` |
//! | `CALL_EXPR` | expression, ARG_LIST |
//! | `CAST_EXPR` / `TYPE_TEST_EXPR` | expression, `.`, `as`/`is`, `(`, type, `)` |
//! | `ERROR` | tokens the parser could not place (a diagnostic says why) |
//!
//! # Formatting
//!
//! [`format()`] prints a file in canonical layout from its tree (see the `fmt` module doc for the
//! rules); it is idempotent and keeps the tree: `parse(format(s))` dumps the same as `parse(s)`
//! ([`debug_dump`] leaves out trivia and layout).
//!
//! # Why hand-written
//!
//! The lexer and the recursive-descent / precedence-climbing parser are written by hand (the
//! tree itself is rowan's, the crate rust-analyzer uses): the indentation layout, contextual
//! keywords and glued units need state a generated lexer does not have; a lossless tree needs
//! every byte, trivia included, placed by the parser; error recovery needs to know where a
//! statement or block ends to go on after an error and report several errors per pass; and
//! precise spans need each error placed at the token that went wrong. Parser generators
//! (ANTLR-style, as in the public `OpenSCENARIO2.g4` grammars) give an AST without trivia and
//! stop or resynchronise poorly.
//!
//! # Choices where the standard is silent or ambiguous
//!
//! - `-` before a number: the standard's tokenizer takes `-1` as one literal (longest match), so
//!   `a -1` would be two operands. oscsim, like Python, reads `-` as an operator and folds it into
//!   the literal only in operand position when glued (`-3.5e2m` is one LITERAL, `a -1` and `a - 1`
//!   are subtractions, `- 1` is a prefix minus).
//! - Keywords are contextual: a keyword followed by `:` or `,` at the start of a member is a field
//!   name (`event: int`); `default`/`hard` in `keep(…)` are qualifiers only when an operand
//!   follows.
//! - `[]` is accepted as the empty list (the grammar asks for one element at least).
//! - A quoted identifier `|…|` ends at the end of its line (the grammar lets it span lines,
//!   which makes an unclosed `|` swallow the file).
//! - Fields, `keep`, modifier applications and `for v in list:` are accepted at top level and
//!   `for` inside structured types, as the domain model's examples (§8.7.2.2, §8.7.3.1.1,
//!   §8.7.18.1.1) write them.
//! - `sample(…)` as a parameter default is reported (the grammar allows it for `var` only).
//! - Nesting deeper than [`MAX_DEPTH`] expressions or blocks is an error.

pub mod ast;
mod diagnostic;
mod dump;
mod fmt;
mod grammar;
mod kind;
mod lexer;
mod parser;
mod validate;

pub use ast::AstNode;
pub use diagnostic::{LineIndex, SyntaxError, SyntaxErrorKind};
pub use dump::debug_dump;
pub use fmt::{format, format_tree};
pub use kind::{OscLanguage, SyntaxElement, SyntaxKind, SyntaxNode, SyntaxToken};
pub use lexer::{lex, LexError, Lexed, Token};
pub use parser::MAX_DEPTH;

use rowan::GreenNode;

/// The result of parsing a source text: the tree (always complete) and the syntax errors.
#[derive(Debug, Clone)]
pub struct Parse {
    green: GreenNode,
    errors: Vec<SyntaxError>,
}

impl Parse {
    /// The root node of the concrete syntax tree (kind [`SyntaxKind::SOURCE_FILE`]).
    pub fn syntax(&self) -> SyntaxNode {
        SyntaxNode::new_root(self.green.clone())
    }

    /// The typed view of the root.
    pub fn tree(&self) -> ast::SourceFile {
        ast::SourceFile::cast_root(self.syntax())
    }

    /// Syntax errors in source order (empty for a well-formed file).
    pub fn errors(&self) -> &[SyntaxError] {
        &self.errors
    }

    /// Splits into the root node and the errors.
    pub fn into_parts(self) -> (SyntaxNode, Vec<SyntaxError>) {
        (SyntaxNode::new_root(self.green), self.errors)
    }
}

/// Parses an OpenSCENARIO DSL source text. Never fails, never panics, always terminates: the
/// tree covers the whole input (`parse(s).syntax().to_string() == s`) and every problem is in
/// [`Parse::errors`].
pub fn parse(source: &str) -> Parse {
    let lexed = lexer::lex(source);
    let mut p = parser::Parser::new(source, &lexed);
    grammar::source_file(&mut p);
    let (green, parse_errors) = p.finish();
    let mut errors: Vec<SyntaxError> = parse_errors
        .into_iter()
        .map(|e| {
            let kind = if e.lexical {
                SyntaxErrorKind::Lexical
            } else {
                SyntaxErrorKind::Grammar
            };
            SyntaxError::new(kind, e.range, e.message)
        })
        .collect();
    let root = SyntaxNode::new_root(green.clone());
    errors.extend(validate::literals(&root));
    errors.sort_by_key(|e| (e.range().start, e.range().end));
    Parse { green, errors }
}
