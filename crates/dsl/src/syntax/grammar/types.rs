//! Names and type declarators (ASAM OpenSCENARIO DSL 2.1 §7.2.1.5.1 identifiers, §7.2.2.2
//! type declarators).

use crate::syntax::kind::SyntaxKind::{self, *};
use crate::syntax::parser::Parser;

/// Whether a `qualified-identifier` starts here: `name`, `ns::name` or `::name`.
pub(crate) fn at_name(p: &Parser) -> bool {
    p.at(IDENT) || (p.at(COLON2) && p.nth(1) == IDENT)
}

/// The tokens of a `qualified-identifier` (`prefixed-identifier ::= [namespace-name] '::'
/// identifier`, no spaces inside: it is a lexical production). False if none was there.
fn qualified_identifier(p: &mut Parser) -> bool {
    if p.at(IDENT)
        && p.nth(1) == COLON2
        && p.nth(2) == IDENT
        && !p.trivia_before(0)
        && !p.trivia_before(1)
    {
        p.bump();
        p.bump();
        p.bump();
    } else if p.at(COLON2) && p.nth(1) == IDENT && !p.trivia_before(0) {
        p.bump();
        p.bump();
    } else if p.at(IDENT) {
        p.bump();
    } else {
        p.error_expected("identifier");
        return false;
    }
    true
}

/// A reference to a declared name: [`NAME_REF`].
pub(crate) fn name_ref(p: &mut Parser) -> bool {
    named(p, NAME_REF)
}

/// A name being declared: [`NAME`].
pub(crate) fn name(p: &mut Parser) -> bool {
    named(p, NAME)
}

fn named(p: &mut Parser, node: SyntaxKind) -> bool {
    if !at_name(p) {
        p.error_expected("identifier");
        return false;
    }
    p.start(node);
    qualified_identifier(p);
    p.finish_node();
    true
}

/// `qualified-behavior-name ::= [actor-name '.'] behavior-name` being declared:
/// [`BEHAVIOR_NAME`] holding an optional actor [`NAME_REF`] and `.`, then the [`NAME`].
pub(crate) fn behavior_name(p: &mut Parser) {
    p.start(BEHAVIOR_NAME);
    let qualified = p.nth(1) == DOT || (p.nth(1) == COLON2 && p.nth(3) == DOT);
    if qualified {
        name_ref(p);
        p.bump();
    }
    name(p);
    p.finish_node();
}

/// A reference to a struct, actor, enum, physical type or `actor.behavior`: [`NAMED_TYPE`].
pub(crate) fn named_type(p: &mut Parser) {
    p.start(NAMED_TYPE);
    name_ref(p);
    if p.at(DOT) && p.nth(1) == IDENT {
        p.bump();
        name_ref(p);
    }
    p.finish_node();
}

const PRIMITIVES: &[(&str, SyntaxKind)] = &[
    ("int", INT_KW),
    ("uint", UINT_KW),
    ("float", FLOAT_KW),
    ("bool", BOOL_KW),
    ("string", STRING_KW),
];

/// Whether a primitive type name is next.
pub(crate) fn at_primitive(p: &Parser) -> bool {
    p.at(IDENT) && PRIMITIVES.iter().any(|(w, _)| p.at_word(w))
}

/// `primitive-type` as a [`PRIMITIVE_TYPE`] node.
pub(crate) fn primitive_type(p: &mut Parser) {
    let text = p.nth_text(0);
    let kind = PRIMITIVES
        .iter()
        .find(|(w, _)| *w == text)
        .map_or(IDENT, |(_, k)| *k);
    p.start(PRIMITIVE_TYPE);
    p.bump_as(kind);
    p.finish_node();
}

/// `type-declarator` (§7.2.2.2): primitive, named (struct, actor, enum, physical type,
/// `actor.behavior`), `list of T` or `range of T`.
pub(crate) fn type_decl(p: &mut Parser) {
    if p.at_word("list") && p.nth_word(1, "of") {
        p.start(LIST_TYPE);
        p.bump_as(LIST_KW);
        p.bump_as(OF_KW);
        if p.at_word("list") && p.nth_word(1, "of") {
            let range = p.current_range();
            p.error_at(range, "expected a non-list type after `list of`, found `list of` (lists of lists are not in the language)");
            // Take every further `list of` flat: reported once, no recursion.
            while p.at_word("list") && p.nth_word(1, "of") {
                p.bump_as(LIST_KW);
                p.bump_as(OF_KW);
            }
        }
        type_decl(p);
        p.finish_node();
    } else if p.at_word("range") && p.nth_word(1, "of") {
        p.start(RANGE_TYPE);
        p.bump_as(RANGE_KW);
        p.bump_as(OF_KW);
        if at_primitive(p) {
            primitive_type(p);
        } else if at_name(p) {
            named_type(p);
        } else {
            p.error_expected("a numeric type");
        }
        p.finish_node();
    } else if at_primitive(p) {
        primitive_type(p);
    } else if at_name(p) {
        named_type(p);
    } else {
        p.error_expected("a type");
    }
}
