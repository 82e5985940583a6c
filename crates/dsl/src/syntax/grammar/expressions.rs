//! Expressions (ASAM OpenSCENARIO DSL 2.1 §7.2.2.6), parsed by precedence climbing.
//!
//! Binding, loosest first (the standard's productions in brackets):
//!
//! | level | operators | associativity |
//! | --- | --- | --- |
//! | ternary-op-exp | `c ? a : b` | right |
//! | implication | `=>` | left |
//! | disjunction | `or` | left |
//! | conjunction | `and` | left |
//! | inversion | prefix `not` | — |
//! | relation | `==` `!=` `<` `<=` `>` `>=` `in` | left |
//! | sum | `+` `-` | left |
//! | term | `*` `/` `%` | left |
//! | factor | prefix `-` | — |
//! | postfix-exp | `.field` `.as(T)` `.is(T)` `[i]` `(args)` | left |
//!
//! A `-` or `+` glued to a number in operand position is part of a signed literal
//! ([`LITERAL`] holding the sign token), as in the lexical productions `int-literal ::= '-'
//! digit+` and `float-literal ::= ['+'|'-'] …`; elsewhere `-` is the binary or prefix operator.

use super::types::{name_ref, type_decl};
use crate::syntax::kind::SyntaxKind::{self, *};
use crate::syntax::parser::Parser;

/// `expression ::= implication | ternary-op-exp`. Returns the kind of the node built, `None` if
/// no expression could start here (an error is reported, nothing consumed).
pub(crate) fn expr(p: &mut Parser) -> Option<SyntaxKind> {
    if !p.enter() {
        p.skip_too_deep();
        return None;
    }
    let cp = p.checkpoint();
    let mut kind = expr_bp(p, 1);
    if kind.is_some() && p.at(QUESTION) {
        p.start_at(cp, TERNARY_EXPR);
        p.bump();
        expr(p);
        p.expect(COLON);
        expr(p);
        p.finish_node();
        kind = Some(TERNARY_EXPR);
    }
    p.leave();
    kind
}

/// The infix operator at the cursor: (left binding power, right binding power, keyword kind to
/// re-kind a word operator to).
fn infix(p: &Parser) -> Option<(u8, u8, Option<SyntaxKind>)> {
    let op = match p.current() {
        FAT_ARROW => (2, 3, None),
        EQ2 | NEQ | LT | LTEQ | GT | GTEQ => (9, 10, None),
        PLUS | MINUS => (11, 12, None),
        STAR | SLASH | PERCENT => (13, 14, None),
        IDENT => match p.nth_text(0) {
            "or" => (4, 5, Some(OR_KW)),
            "and" => (6, 7, Some(AND_KW)),
            "in" => (9, 10, Some(IN_KW)),
            _ => return None,
        },
        _ => return None,
    };
    Some(op)
}

/// Right binding power of prefix `not` (binds looser than relations) and prefix `-`.
const NOT_BP: u8 = 8;
const NEG_BP: u8 = 15;

fn expr_bp(p: &mut Parser, min_bp: u8) -> Option<SyntaxKind> {
    let cp = p.checkpoint();
    let mut kind = prefix(p)?;
    let mut entered = 0u32;
    while let Some((l_bp, r_bp, keyword)) = infix(p) {
        if l_bp < min_bp {
            break;
        }
        if !p.enter() {
            p.skip_too_deep();
            break;
        }
        entered += 1;
        p.start_at(cp, BIN_EXPR);
        match keyword {
            Some(k) => p.bump_as(k),
            None => p.bump(),
        }
        if expr_bp(p, r_bp).is_none() {
            p.finish_node();
            kind = BIN_EXPR;
            break;
        }
        p.finish_node();
        kind = BIN_EXPR;
    }
    for _ in 0..entered {
        p.leave();
    }
    Some(kind)
}

/// Whether the next token is a number glued to the sign at the cursor.
fn signed_number(p: &Parser) -> bool {
    matches!(p.nth(1), INT_NUMBER | FLOAT_NUMBER) && !p.trivia_before(0)
        || (p.nth_word(1, "inf") || p.nth_word(1, "nan")) && !p.trivia_before(0)
}

fn prefix(p: &mut Parser) -> Option<SyntaxKind> {
    let unary = match p.current() {
        IDENT if p.at_word("not") => Some((NOT_KW, NOT_BP)),
        MINUS | PLUS if signed_number(p) => None,
        MINUS => Some((MINUS, NEG_BP)),
        _ => None,
    };
    let Some((op, bp)) = unary else {
        return postfix(p);
    };
    if !p.enter() {
        p.skip_too_deep();
        return None;
    }
    p.start(PREFIX_EXPR);
    p.bump_as(op);
    expr_bp(p, bp);
    p.finish_node();
    p.leave();
    Some(PREFIX_EXPR)
}

/// `postfix-exp` (§7.2.2.6.5): a primary expression followed by field accesses, casts, type
/// tests, element accesses and calls.
pub(crate) fn postfix(p: &mut Parser) -> Option<SyntaxKind> {
    let cp = p.checkpoint();
    let mut kind = primary(p)?;
    let mut entered = 0u32;
    loop {
        let next = match p.current() {
            DOT if matches!(p.nth_text(1), "as" | "is")
                && p.nth(1) == IDENT
                && p.nth(2) == L_PAREN =>
            {
                if p.nth_text(1) == "as" {
                    CAST_EXPR
                } else {
                    TYPE_TEST_EXPR
                }
            }
            DOT => FIELD_EXPR,
            L_BRACK => INDEX_EXPR,
            L_PAREN => CALL_EXPR,
            _ => break,
        };
        if !p.enter() {
            p.skip_too_deep();
            break;
        }
        entered += 1;
        p.start_at(cp, next);
        match next {
            CAST_EXPR | TYPE_TEST_EXPR => {
                p.bump();
                p.bump_as(if next == CAST_EXPR { AS_KW } else { IS_KW });
                p.bump();
                type_decl(p);
                p.expect(R_PAREN);
            }
            FIELD_EXPR => {
                p.bump();
                name_ref(p);
            }
            INDEX_EXPR => {
                p.bump();
                expr(p);
                p.expect(R_BRACK);
            }
            _ => arg_list(p),
        }
        p.finish_node();
        kind = next;
    }
    for _ in 0..entered {
        p.leave();
    }
    Some(kind)
}

/// A number with its glued unit, optionally after a glued sign.
fn number_literal(p: &mut Parser) {
    p.start(LITERAL);
    if p.at(MINUS) || p.at(PLUS) {
        p.bump();
    }
    match p.current() {
        IDENT if p.at_word("inf") => p.bump_as(INF_KW),
        IDENT if p.at_word("nan") => p.bump_as(NAN_KW),
        _ => p.bump(),
    }
    if p.at(UNIT) {
        p.bump();
    }
    p.finish_node();
}

/// `primary-exp` and `value-exp` (§7.2.2.6.6), list and range constructors (§7.2.2.6.7).
fn primary(p: &mut Parser) -> Option<SyntaxKind> {
    let kind = match p.current() {
        INT_NUMBER | FLOAT_NUMBER => {
            number_literal(p);
            LITERAL
        }
        MINUS | PLUS if signed_number(p) => {
            number_literal(p);
            LITERAL
        }
        STRING => {
            p.start(LITERAL);
            p.bump();
            p.finish_node();
            LITERAL
        }
        IDENT => match p.nth_text(0) {
            "true" | "false" => {
                p.start(LITERAL);
                p.bump_as(if p.at_word("true") { TRUE_KW } else { FALSE_KW });
                p.finish_node();
                LITERAL
            }
            "inf" | "nan" => {
                number_literal(p);
                LITERAL
            }
            "it" => {
                p.start(IT_EXPR);
                p.bump_as(IT_KW);
                p.finish_node();
                IT_EXPR
            }
            "range" if p.nth(1) == L_PAREN => {
                p.start(RANGE_EXPR);
                p.bump_as(RANGE_KW);
                p.bump();
                expr(p);
                p.expect(COMMA);
                expr(p);
                p.expect(R_PAREN);
                p.finish_node();
                RANGE_EXPR
            }
            _ => name_or_enum_value(p),
        },
        COLON2 => name_or_enum_value(p),
        L_PAREN => {
            // The depth is counted by `expr` inside.
            p.start(PAREN_EXPR);
            p.bump();
            expr(p);
            p.expect(R_PAREN);
            p.finish_node();
            PAREN_EXPR
        }
        L_BRACK => list_or_range(p)?,
        _ => {
            p.error_expected("expression");
            return None;
        }
    };
    Some(kind)
}

/// `qualified-identifier` as an expression, or `enum-value-reference ::= [enum-name '!']
/// enum-member-name`.
fn name_or_enum_value(p: &mut Parser) -> SyntaxKind {
    let cp = p.checkpoint();
    name_ref(p);
    if p.at(BANG) {
        p.start_at(cp, ENUM_VALUE_EXPR);
        p.bump();
        name_ref(p);
        p.finish_node();
        ENUM_VALUE_EXPR
    } else {
        p.start_at(cp, NAME_EXPR);
        p.finish_node();
        NAME_EXPR
    }
}

/// `'[' expression '..' expression ']'` or `'[' expression (',' expression)* ']'`; `[]` is
/// accepted as the empty list.
fn list_or_range(p: &mut Parser) -> Option<SyntaxKind> {
    // The depth is counted by `expr` inside.
    let cp = p.checkpoint();
    p.bump();
    let kind = if p.at(R_BRACK) {
        // list-constructor ::= '[' expression (',' expression)* ']' (§7.4.2.7.4).
        let range = p.current_range();
        p.error_at(
            range,
            "expected an element in the list, found `]` (a list constructor has at least one element, §7.4.2.7.4)",
        );
        LIST_EXPR
    } else {
        expr(p);
        if p.eat(DOT2) {
            expr(p);
            RANGE_EXPR
        } else {
            while p.eat(COMMA) {
                if expr(p).is_none() {
                    break;
                }
            }
            LIST_EXPR
        }
    };
    p.expect(R_BRACK);
    p.start_at(cp, kind);
    p.finish_node();
    Some(kind)
}

/// `'(' [argument-list] ')'` (§7.2.2.5.2): positional arguments first, then named ones.
pub(crate) fn arg_list(p: &mut Parser) {
    p.start(ARG_LIST);
    p.expect(L_PAREN);
    let mut seen_named = false;
    if !p.at(R_PAREN) && !p.at(NEWLINE) {
        loop {
            if p.at(IDENT) && p.nth(1) == COLON {
                seen_named = true;
                p.start(NAMED_ARG);
                name_ref(p);
                p.bump();
                expr(p);
                p.finish_node();
            } else {
                if seen_named {
                    let range = p.current_range();
                    p.error_at(range, "expected a named argument `name: value`, found a positional argument after a named one");
                }
                p.start(ARG);
                let ok = expr(p).is_some();
                p.finish_node();
                if !ok {
                    break;
                }
            }
            if !p.eat(COMMA) {
                break;
            }
        }
    }
    p.expect(R_PAREN);
    p.finish_node();
}
