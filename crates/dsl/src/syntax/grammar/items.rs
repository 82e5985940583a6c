//! Prelude and main statements, type declarations, type extensions and global parameters
//! (ASAM OpenSCENARIO DSL 2.1 §7.2.2.1, §7.2.2.2, §7.2.2.3).

use super::expressions::expr;
use super::members;
use super::types::{at_primitive, behavior_name, name, name_ref, named_type, primitive_type};
use super::{block, Ctx};
use crate::syntax::kind::SyntaxKind::{self, *};
use crate::syntax::parser::Parser;

/// `import-statement ::= 'import' import-reference NEWLINE`, `import-reference ::=
/// string-literal | structured-identifier`.
pub(super) fn import(p: &mut Parser) {
    p.start(IMPORT_STMT);
    p.bump_as(IMPORT_KW);
    if !p.eat(STRING) {
        structured_identifier(p);
    }
    p.finish_node();
    p.end_of_line();
}

/// `structured-identifier ::= identifier | structured-identifier '.' identifier`, its tokens
/// directly in the current node.
fn structured_identifier(p: &mut Parser) {
    if !p.expect(IDENT) {
        return;
    }
    while p.at(DOT) && p.nth(1) == IDENT {
        p.bump();
        p.bump();
    }
}

/// `namespace-statement ::= 'namespace' namespace-name ['use' namespace-list] NEWLINE`.
pub(super) fn namespace(p: &mut Parser) {
    p.start(NAMESPACE_STMT);
    p.bump_as(NAMESPACE_KW);
    namespace_name(p, NAME);
    if p.eat_word("use", USE_KW) {
        loop {
            namespace_name(p, NAME_REF);
            if !p.eat(COMMA) {
                break;
            }
        }
    }
    p.finish_node();
    p.end_of_line();
}

/// `namespace-name ::= identifier | 'null'`.
fn namespace_name(p: &mut Parser, node: SyntaxKind) {
    if !p.at(IDENT) {
        p.error_expected("a namespace name");
        return;
    }
    p.start(node);
    if p.at_word("null") {
        p.bump_as(NULL_KW);
    } else {
        p.bump();
    }
    p.finish_node();
}

/// `export-statement ::= 'export' export-specification (',' export-specification)* NEWLINE`.
pub(super) fn export(p: &mut Parser) {
    p.start(EXPORT_STMT);
    p.bump_as(EXPORT_KW);
    loop {
        // export-specification ::= qualified-identifier | [[namespace-name] '::'] '*'
        p.start(EXPORT_SPEC);
        if p.at(STAR) {
            p.bump();
        } else if p.at(COLON2) && p.nth(1) == STAR {
            p.bump();
            p.bump();
        } else if p.at(IDENT) && p.nth(1) == COLON2 && p.nth(2) == STAR {
            p.bump();
            p.bump();
            p.bump();
        } else {
            name_ref(p);
        }
        p.finish_node();
        if !p.eat(COMMA) {
            break;
        }
    }
    p.finish_node();
    p.end_of_line();
}

/// `physical-type-declaration ::= 'type' physical-type-name 'is' base-unit-specifier NEWLINE`.
pub(super) fn physical_type(p: &mut Parser) {
    p.start(PHYSICAL_TYPE_DECL);
    p.bump_as(TYPE_KW);
    name(p);
    if p.expect_word("is", IS_KW) {
        si_spec(p, false);
    }
    p.finish_node();
    p.end_of_line();
}

/// `unit-declaration ::= 'unit' unit-name 'of' physical-type-name 'is' unit-specifier NEWLINE`.
pub(super) fn unit(p: &mut Parser) {
    p.start(UNIT_DECL);
    p.bump_as(UNIT_KW);
    name(p);
    if p.expect_word("of", OF_KW) {
        name_ref(p);
        if p.expect_word("is", IS_KW) {
            si_spec(p, true);
        }
    }
    p.finish_node();
    p.end_of_line();
}

/// `SI-base-unit-name`s (§7.2.2.2.1).
pub const SI_BASE_UNITS: &[&str] = &["kg", "m", "s", "A", "K", "mol", "cd", "rad"];

/// `SI-base-unit-specifier ::= 'SI' '(' SI-base-exponent-list ')'` and, for units,
/// `SI-unit-specifier ::= 'SI' '(' SI-base-exponent-list [',' SI-factor] [',' SI-offset] ')'`.
fn si_spec(p: &mut Parser, unit: bool) {
    p.start(SI_SPEC);
    p.expect_word("SI", SI_KW);
    p.expect(L_PAREN);
    // 0: exponents, 1: after factor, 2: after offset
    let mut stage = 0;
    loop {
        let range = p.current_range();
        let text = p.nth_text(0);
        p.start(SI_ARG);
        match text {
            "factor" | "offset" if p.at(IDENT) => {
                let this = if text == "factor" { 1 } else { 2 };
                if !unit {
                    p.error_at(range, format!("expected an SI base unit exponent, found `{text}` (factor and offset belong to unit declarations, a physical type is SI base units only)"));
                } else if this <= stage {
                    p.error_at(range, format!("expected `)`, found `{text}` (SI(exponents…, factor, offset) in this order, each once)"));
                }
                stage = this;
                p.bump_as(if this == 1 { FACTOR_KW } else { OFFSET_KW });
            }
            _ if p.at(IDENT) => {
                if !SI_BASE_UNITS.contains(&text) {
                    p.error_at(range, format!("expected an SI base unit (kg, m, s, A, K, mol, cd, rad), found `{text}`"));
                } else if stage > 0 {
                    p.error_at(range, "expected `factor`, `offset` or `)`, found an SI base unit exponent after them".to_string());
                }
                p.bump();
            }
            _ => p.error_expected("an SI base unit (kg, m, s, A, K, mol, cd, rad)"),
        }
        p.expect(COLON);
        expr(p);
        p.finish_node();
        if !p.eat(COMMA) {
            break;
        }
    }
    p.expect(R_PAREN);
    p.finish_node();
}

/// `enum-declaration ::= 'enum' enum-name ':' '[' enum-member-decl (',' enum-member-decl)* ']'
/// NEWLINE`.
pub(super) fn enum_decl(p: &mut Parser) {
    p.start(ENUM_DECL);
    p.bump_as(ENUM_KW);
    name(p);
    if p.expect(COLON) {
        enum_member_list(p);
    }
    p.finish_node();
    p.end_of_line();
}

/// `'[' enum-member-decl (',' enum-member-decl)* ']'`, `enum-member-decl ::= enum-member-name
/// ['=' enum-member-value]`.
fn enum_member_list(p: &mut Parser) {
    p.start(ENUM_MEMBER_LIST);
    if p.expect(L_BRACK) {
        loop {
            p.start(ENUM_MEMBER);
            name(p);
            if p.eat(EQ) {
                enum_member_value(p);
            }
            p.finish_node();
            if !p.eat(COMMA) {
                break;
            }
        }
        p.expect(R_BRACK);
    }
    p.finish_node();
}

/// `enum-member-value ::= uint-literal | hex-uint-literal | enum-value-reference`: a literal
/// or another member (`b`, `colors!b`); whether a reference leads to a value is checked in
/// `semantics::declarations`. A computed value (`1 + 1`), a signed, float or physical literal
/// is reported here.
fn enum_member_value(p: &mut Parser) {
    let range = p.current_range();
    let found = match (p.current(), p.nth(1)) {
        (MINUS | PLUS, _) => "a signed number".to_string(),
        (INT_NUMBER | FLOAT_NUMBER, UNIT) => "a physical literal".to_string(),
        _ => p.found(),
    };
    let integer = p.at(INT_NUMBER) && p.nth(1) != UNIT;
    let kind = expr(p);
    let allowed = match kind {
        Some(LITERAL) => integer,
        Some(NAME_EXPR | ENUM_VALUE_EXPR) => true,
        None => return, // reported by `expr`
        Some(_) => false,
    };
    if !allowed {
        let what = if kind == Some(LITERAL) {
            found
        } else {
            "an expression".to_string()
        };
        let end = p.current_range().start.max(range.end);
        p.error_at(
            range.start..end,
            format!("expected a uint literal or another member as the enum member's value, found {what} (enum-member-value ::= uint-literal | hex-uint-literal | enum-value-reference)"),
        );
    }
}

/// `struct`, `actor`, `scenario` and `action` declarations: keyword, name, optional
/// `inherits`, then a member block or NEWLINE.
pub(super) fn structured(p: &mut Parser, node: SyntaxKind, keyword: SyntaxKind) {
    p.start(node);
    p.bump_as(keyword);
    let behavior = matches!(node, SCENARIO_DECL | ACTION_DECL);
    if behavior {
        behavior_name(p);
    } else {
        name(p);
    }
    if p.at_word("inherits") {
        inherits(p);
    }
    let ctx = if behavior { Ctx::Scenario } else { Ctx::Struct };
    let eol = body(p, ctx);
    p.finish_node();
    if eol {
        p.end_of_line();
    }
}

/// `( ':' NEWLINE INDENT member+ DEDENT ) | NEWLINE`; true when there is no block, and the
/// NEWLINE is for the caller to read after closing its node.
fn body(p: &mut Parser, ctx: Ctx) -> bool {
    if p.eat(COLON) {
        block(p, ctx);
        false
    } else if p.at(NEWLINE) || p.at_eof() {
        true
    } else {
        p.error_expected("`:` or end of line");
        p.skip_line();
        false
    }
}

/// `'inherits' name ['(' field-name '==' (enum-value-reference | bool-literal) ')']`.
fn inherits(p: &mut Parser) {
    p.start(INHERITS);
    p.bump_as(INHERITS_KW);
    named_type(p);
    if p.at(L_PAREN) {
        p.start(INHERITS_CONDITION);
        p.bump();
        name_ref(p);
        p.expect(EQ2);
        let range = p.current_range();
        if let Some(kind) = expr(p) {
            if !matches!(kind, NAME_EXPR | ENUM_VALUE_EXPR | LITERAL) {
                p.error_at(range, "expected an enum value or `true`/`false` in an inherits condition, found an expression");
            }
        }
        p.expect(R_PAREN);
        p.finish_node();
    }
    p.finish_node();
}

/// `modifier-declaration ::= 'modifier' [actor-name '.'] modifier-name ['of'
/// qualified-behavior-name] ( ':' NEWLINE INDENT (scenario-member-decl | on-directive)+ DEDENT
/// | NEWLINE )`.
pub(super) fn modifier(p: &mut Parser) {
    p.start(MODIFIER_DECL);
    p.bump_as(MODIFIER_KW);
    behavior_name(p);
    if p.eat_word("of", OF_KW) {
        named_type(p);
    }
    let eol = body(p, Ctx::Modifier);
    p.finish_node();
    if eol {
        p.end_of_line();
    }
}

/// `type-extension`: `extend name: [members]` (enum, [`ENUM_EXTENSION`]), `extend name:` block
/// (structured type) or `extend int:` block of methods (primitive), as [`EXTEND_DECL`].
pub(super) fn extend(p: &mut Parser) {
    let cp = p.checkpoint();
    p.bump_as(EXTEND_KW);
    let primitive = at_primitive(p) && p.nth(1) == COLON;
    if primitive {
        primitive_type(p);
    } else {
        named_type(p);
    }
    if !p.expect(COLON) {
        p.start_at(cp, EXTEND_DECL);
        p.skip_line();
        p.finish_node();
        return;
    }
    let enum_extension = p.at(L_BRACK);
    if enum_extension {
        p.start_at(cp, ENUM_EXTENSION);
        enum_member_list(p);
    } else {
        p.start_at(cp, EXTEND_DECL);
        block(
            p,
            if primitive {
                Ctx::ExtendPrimitive
            } else {
                Ctx::Extend
            },
        );
    }
    p.finish_node();
    if enum_extension {
        p.end_of_line();
    }
}

/// `global-parameter-declaration ::= 'global' parameter-declaration`.
pub(super) fn global(p: &mut Parser) {
    p.start(GLOBAL_PARAM_DECL);
    p.bump_as(GLOBAL_KW);
    let eol = members::field_node(p, PARAM_DECL);
    p.finish_node();
    if eol {
        p.end_of_line();
    }
}
