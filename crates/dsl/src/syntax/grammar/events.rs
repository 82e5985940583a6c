//! Event specifications and conditions, `sample` (ASAM OpenSCENARIO DSL 2.1 §7.2.2.4.1 events,
//! §7.2.2.4.2 sample-expression).

use super::expressions::{expr, postfix};
use super::types::name;
use crate::syntax::kind::SyntaxKind::{self, *};
use crate::syntax::parser::Parser;

/// `event-specification ::= event-reference [[event-field-decl] 'if' event-condition] |
/// event-condition` as an [`EVENT_SPEC`] node.
pub(crate) fn event_spec(p: &mut Parser) {
    p.start(EVENT_SPEC);
    if p.at(AT) {
        // event-reference ::= '@' event-path, event-path ::= [expression '.'] event-name
        p.start(EVENT_REF);
        p.bump();
        postfix(p);
        p.finish_node();
        if p.at_word("as") && p.nth(1) == IDENT {
            p.start(EVENT_FIELD);
            p.bump_as(AS_KW);
            name(p);
            p.finish_node();
            if !p.at_word("if") {
                p.error_expected("`if` after the event field");
            }
        }
        if p.eat_word("if", IF_KW) {
            event_condition(p);
        }
    } else {
        event_condition(p);
    }
    p.finish_node();
}

/// `event-condition ::= bool-expression | rise-expression | fall-expression |
/// elapsed-expression | every-expression`.
pub(crate) fn event_condition(p: &mut Parser) {
    let special: Option<(SyntaxKind, SyntaxKind)> = match p.nth_text(0) {
        "rise" => Some((RISE_EXPR, RISE_KW)),
        "fall" => Some((FALL_EXPR, FALL_KW)),
        "elapsed" => Some((ELAPSED_EXPR, ELAPSED_KW)),
        "every" => Some((EVERY_EXPR, EVERY_KW)),
        _ => None,
    };
    let Some((node, keyword)) = special.filter(|_| p.at(IDENT) && p.nth(1) == L_PAREN) else {
        expr(p);
        return;
    };
    p.start(node);
    p.bump_as(keyword);
    p.bump();
    expr(p);
    // every-expression ::= 'every' '(' duration [',' 'offset' ':' duration] ')'
    if node == EVERY_EXPR && p.eat(COMMA) {
        if !p.expect_word("offset", OFFSET_KW) && p.at(IDENT) && p.nth(1) == COLON {
            // A wrong argument name: reported; take it so the rest still parses.
            p.bump();
        }
        p.expect(COLON);
        expr(p);
    }
    p.expect(R_PAREN);
    p.finish_node();
}

/// Whether a `sample(` expression starts here.
pub(crate) fn at_sample(p: &Parser) -> bool {
    p.at_word("sample") && p.nth(1) == L_PAREN
}

/// `sample-expression ::= 'sample' '(' expression ',' event-specification [',' default-value]
/// ')'` as a [`SAMPLE_EXPR`] node.
pub(crate) fn sample(p: &mut Parser) {
    p.start(SAMPLE_EXPR);
    p.bump_as(SAMPLE_KW);
    p.bump();
    expr(p);
    p.expect(COMMA);
    event_spec(p);
    if p.eat(COMMA) {
        expr(p);
    }
    p.expect(R_PAREN);
    p.finish_node();
}
