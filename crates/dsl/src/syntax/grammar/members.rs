//! Structured type members (ASAM OpenSCENARIO DSL 2.1 §7.2.2.4): events, fields, constraints,
//! methods, coverage, modifier application, the argument list specifications of methods and
//! modifiers (§7.2.2.5.1); and the `for v in list:` constraint loop of the domain model's
//! vehicle_group example (§8.7.18.1.1).

use super::events::{at_sample, event_spec, sample};
use super::expressions::{arg_list, expr, postfix};
use super::types::{name, type_decl};
use super::{block, Ctx};
use crate::syntax::kind::SyntaxKind::{self, *};
use crate::syntax::parser::Parser;

/// `event-declaration ::= 'event' event-name ['(' argument-list-specification ')'] ['is'
/// event-specification] NEWLINE`.
pub(super) fn event(p: &mut Parser) {
    p.start(EVENT_DECL);
    p.bump_as(EVENT_KW);
    name(p);
    if p.eat(L_PAREN) {
        param_list(p);
        p.expect(R_PAREN);
    }
    if p.eat_word("is", IS_KW) {
        event_spec(p);
    }
    p.finish_node();
    p.end_of_line();
}

/// `parameter-declaration ::= field-name (',' field-name)* ':' type-declarator ['='
/// default-value] (parameter-with-declaration | NEWLINE)` ([`PARAM_DECL`]) and
/// `variable-declaration ::= 'var' field-name (',' field-name)* ':' type-declarator ['='
/// (default-value | sample-expression)] NEWLINE` ([`VAR_DECL`]).
pub(crate) fn field(p: &mut Parser, node: SyntaxKind) {
    if field_node(p, node) {
        p.end_of_line();
    }
}

/// [`field`] without its NEWLINE; true if the NEWLINE is still to be read (no `with:` block).
pub(crate) fn field_node(p: &mut Parser, node: SyntaxKind) -> bool {
    p.start(node);
    let mut eol = false;
    if node == VAR_DECL {
        p.bump_as(VAR_KW);
    }
    p.start(FIELD_NAMES);
    loop {
        name(p);
        if !p.eat(COMMA) {
            break;
        }
    }
    p.finish_node();
    if p.expect(COLON) {
        type_decl(p);
        if p.eat(EQ) {
            if at_sample(p) {
                if node != VAR_DECL {
                    let range = p.current_range();
                    p.error_at(range, "expected an expression as parameter default, found `sample(…)` (only a `var` can be sampled)");
                }
                sample(p);
            } else {
                expr(p);
            }
        }
        if node == PARAM_DECL && p.at_word("with") && p.nth(1) == COLON {
            // parameter-with-declaration ::= 'with' ':' NEWLINE INDENT constraint+ DEDENT
            p.start(PARAM_WITH);
            p.bump_as(WITH_KW);
            p.bump();
            block(p, Ctx::ParamWith);
            p.finish_node();
        } else {
            eol = true;
        }
    } else {
        p.skip_line();
    }
    p.finish_node();
    eol
}

/// Whether the word at the cursor is a constraint qualifier (`default`, `hard`) rather than the
/// start of the constraint expression: it is when an operand follows it, glued or spaced
/// (`default x`, `hard (a)`), but `default == 1`, `default.x` and `default(x)` treat it as a
/// name.
fn at_qualifier(p: &Parser) -> bool {
    if !(p.at_word("default") || p.at_word("hard")) {
        return false;
    }
    match p.nth(1) {
        IDENT | INT_NUMBER | FLOAT_NUMBER | STRING | COLON2 => true,
        L_PAREN | L_BRACK | MINUS => p.trivia_before(0),
        _ => false,
    }
}

/// `keep-constraint-declaration ::= 'keep' '(' [constraint-qualifier] constraint-expression ')'
/// NEWLINE`.
pub(super) fn keep(p: &mut Parser) {
    p.start(KEEP_CONSTRAINT);
    p.bump_as(KEEP_KW);
    if !p.expect(L_PAREN) {
        p.skip_line();
        p.finish_node();
        return;
    }
    if at_qualifier(p) {
        p.bump_as(if p.at_word("default") {
            DEFAULT_KW
        } else {
            HARD_KW
        });
    }
    expr(p);
    p.expect(R_PAREN);
    p.finish_node();
    p.end_of_line();
}

/// `remove-default-declaration ::= 'remove_default' '(' parameter-reference ')' NEWLINE`,
/// `parameter-reference ::= field-name | field-access`.
pub(super) fn remove_default(p: &mut Parser) {
    p.start(REMOVE_DEFAULT);
    p.bump_as(REMOVE_DEFAULT_KW);
    if !p.expect(L_PAREN) {
        p.skip_line();
        p.finish_node();
        return;
    }
    let range = p.current_range();
    if let Some(kind) = expr(p) {
        if !matches!(kind, NAME_EXPR | FIELD_EXPR) {
            p.error_at(range, "expected a parameter (`name` or `path.name`) in remove_default, found an expression");
        }
    }
    p.expect(R_PAREN);
    p.finish_node();
    p.end_of_line();
}

/// `method-declaration ::= 'def' method-name '(' [argument-list-specification] ')' ['->'
/// return-type] method-implementation NEWLINE`.
pub(super) fn method(p: &mut Parser) {
    p.start(METHOD_DECL);
    p.bump_as(DEF_KW);
    name(p);
    if p.expect(L_PAREN) {
        if !p.at(R_PAREN) {
            param_list(p);
        }
        p.expect(R_PAREN);
    }
    if p.at(ARROW) {
        p.start(RETURN_TYPE);
        p.bump();
        type_decl(p);
        p.finish_node();
    }
    // method-implementation ::= 'is' [method-qualifier] ('expression' expression | 'undefined'
    //   | 'external' structured-identifier '(' [argument-list] ')')
    p.start(METHOD_BODY);
    if p.expect_word("is", IS_KW) {
        p.eat_word("only", ONLY_KW);
        if p.eat_word("expression", EXPRESSION_KW) {
            expr(p);
        } else if p.eat_word("undefined", UNDEFINED_KW) {
        } else if p.eat_word("external", EXTERNAL_KW) {
            let range = p.current_range();
            if postfix(p).is_some_and(|k| k != CALL_EXPR) {
                p.error_at(
                    range,
                    "expected an external function call `library.function(args)`",
                );
            }
        } else {
            p.error_expected("`expression`, `undefined` or `external`");
        }
    }
    p.finish_node();
    p.finish_node();
    p.end_of_line();
}

/// `coverage-declaration ::= ('cover' | 'record') '(' argument-list ')' NEWLINE`.
pub(super) fn coverage(p: &mut Parser) {
    p.start(COVERAGE_DECL);
    let keyword = p.nth_text(0);
    p.bump_as(if p.at_word("cover") {
        COVER_KW
    } else {
        RECORD_KW
    });
    if p.at(L_PAREN) && p.nth(1) == R_PAREN {
        let start = p.current_range().start;
        let message = format!("expected an argument in `{keyword}(…)`, found `)` (coverage-declaration ::= ('cover' | 'record') '(' argument-list ')': at least the name)");
        p.bump();
        let end = p.current_range().end;
        p.error_at(start..end, message);
        p.bump();
    } else {
        arg_list(p);
    }
    p.finish_node();
    p.end_of_line();
}

/// `modifier-application ::= [actor-expression '.'] modifier-name '(' [argument-list] ')'
/// NEWLINE`.
pub(super) fn modifier_application(p: &mut Parser) {
    p.start(MODIFIER_APPLICATION);
    call_expression(p, "a modifier application `name(arguments)`");
    p.finish_node();
    p.end_of_line();
}

/// A postfix expression that must end in a call: `[actor-expression '.'] name '(' args ')'`.
pub(super) fn call_expression(p: &mut Parser, what: &str) {
    let range = p.current_range();
    match postfix(p) {
        Some(CALL_EXPR) => {}
        Some(_) => p.error_at(
            range.start..p.current_range().start,
            format!("expected {what}, found an expression without a call"),
        ),
        None => {}
    }
}

/// `for NAME in expression:` block of constraints. Not in the language reference's grammar;
/// the domain model's vehicle_group example (§8.7.18.1.1) writes `for v in g.vehicles:` and
/// oscsim accepts it as written there.
pub(super) fn for_constraint(p: &mut Parser) {
    p.start(FOR_CONSTRAINT);
    p.bump_as(FOR_KW);
    name(p);
    p.expect_word("in", IN_KW);
    expr(p);
    if p.expect(COLON) {
        block(p, Ctx::For);
    } else {
        p.skip_line();
    }
    p.finish_node();
}

/// `argument-list-specification ::= argument-specification (',' argument-specification)*`,
/// `argument-specification ::= argument-name ':' type-declarator ['=' default-value]`.
/// The caller handles the parentheses.
pub(crate) fn param_list(p: &mut Parser) {
    p.start(PARAM_LIST);
    loop {
        p.start(PARAM);
        name(p);
        p.expect(COLON);
        type_decl(p);
        if p.eat(EQ) {
            expr(p);
        }
        p.finish_node();
        if !p.eat(COMMA) {
            break;
        }
    }
    p.finish_node();
}
