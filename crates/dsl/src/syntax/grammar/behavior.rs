//! Behavior specification (ASAM OpenSCENARIO DSL 2.1 §7.2.2.4.7): `on` and `do` directives,
//! compositions, behavior invocations with `with:` blocks, `wait`, `emit`, `call`, `until`.

use super::events::event_spec;
use super::expressions::arg_list;
use super::members::call_expression;
use super::types::{name, name_ref};
use super::{block, Ctx};
use crate::syntax::kind::SyntaxKind::*;
use crate::syntax::parser::Parser;

/// `on-directive ::= 'on' event-specification ':' NEWLINE INDENT on-member+ DEDENT`.
pub(super) fn on(p: &mut Parser) {
    p.start(ON_DIRECTIVE);
    p.bump_as(ON_KW);
    event_spec(p);
    if p.expect(COLON) {
        block(p, Ctx::On);
    } else {
        p.skip_line();
    }
    p.finish_node();
}

/// `do-directive ::= 'do' do-member`.
pub(super) fn do_directive(p: &mut Parser) {
    p.start(DO_DIRECTIVE);
    p.bump_as(DO_KW);
    do_member(p);
    p.finish_node();
}

/// `do-member ::= [label-name ':'] (composition | behavior-invocation | wait-directive |
/// emit-directive | call-directive)`. The [`LABEL`] is the first child of the member's node.
pub(super) fn do_member(p: &mut Parser) {
    let cp = p.checkpoint();
    let composition_start = |p: &Parser| {
        matches!(p.nth_text(0), "serial" | "parallel" | "one_of")
            && p.at(IDENT)
            && (p.nth(1) == L_PAREN || (p.nth(1) == COLON && p.nth(2) == NEWLINE))
    };
    if p.at(IDENT) && p.nth(1) == COLON && !composition_start(p) {
        p.start(LABEL);
        name(p);
        p.bump();
        p.finish_node();
    }
    // `wait` and `call` are keywords here also before a parenthesised operand (`wait (x > 1)`):
    // the grammar places them at the start of a do-member (§7.2.1.5.1).
    let node = if composition_start(p) {
        COMPOSITION
    } else if p.at(IDENT) && p.nth(1) != DOT {
        match (p.nth_text(0), p.nth(1)) {
            ("wait", _) => WAIT_DIRECTIVE,
            ("emit", next) if next != L_PAREN => EMIT_DIRECTIVE,
            ("call", _) => CALL_DIRECTIVE,
            _ => BEHAVIOR_INVOCATION,
        }
    } else {
        BEHAVIOR_INVOCATION
    };
    p.start_at(cp, node);
    // The NEWLINE goes after the node, so a statement's span is its text.
    let mut eol = false;
    match node {
        COMPOSITION => composition(p),
        WAIT_DIRECTIVE => {
            p.bump_as(WAIT_KW);
            event_spec(p);
            eol = true;
        }
        EMIT_DIRECTIVE => {
            // emit-directive ::= 'emit' event-name ['(' argument-list ')'] NEWLINE
            p.bump_as(EMIT_KW);
            name_ref(p);
            if p.at(L_PAREN) {
                arg_list(p);
            }
            eol = true;
        }
        CALL_DIRECTIVE => {
            p.bump_as(CALL_KW);
            call_expression(p, "a method call `path.method(arguments)`");
            eol = true;
        }
        _ => {
            // behavior-invocation ::= [actor-expression '.'] behavior-name '(' [argument-list]
            //   ')' (behavior-with-declaration | NEWLINE)
            call_expression(p, "a behavior invocation `actor.behavior(arguments)`");
            if !behavior_with(p) {
                eol = true;
            }
        }
    }
    p.finish_node();
    if eol {
        p.end_of_line();
    }
}

/// `composition ::= composition-operator ['(' [unqualified-argument-list] ')'] ':' NEWLINE
/// INDENT do-member+ DEDENT [behavior-with-declaration]`.
fn composition(p: &mut Parser) {
    let keyword = match p.nth_text(0) {
        "serial" => SERIAL_KW,
        "parallel" => PARALLEL_KW,
        _ => ONE_OF_KW,
    };
    p.bump_as(keyword);
    if p.at(L_PAREN) {
        arg_list(p);
    }
    if p.expect(COLON) {
        block(p, Ctx::Do);
        behavior_with(p);
    } else {
        p.skip_line();
    }
}

/// `behavior-with-declaration ::= 'with' ':' NEWLINE INDENT behavior-with-member+ DEDENT`, if
/// one is next.
fn behavior_with(p: &mut Parser) -> bool {
    if !(p.at_word("with") && matches!(p.nth(1), COLON | NEWLINE)) {
        return false;
    }
    p.start(BEHAVIOR_WITH);
    p.bump_as(WITH_KW);
    p.expect(COLON);
    block(p, Ctx::BehaviorWith);
    p.finish_node();
    true
}

/// `until-directive ::= 'until' event-specification NEWLINE`.
pub(super) fn until(p: &mut Parser) {
    p.start(UNTIL_DIRECTIVE);
    p.bump_as(UNTIL_KW);
    event_spec(p);
    p.finish_node();
    p.end_of_line();
}
