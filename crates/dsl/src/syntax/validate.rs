//! Literal checks after parsing (ASAM OpenSCENARIO DSL 2.1 §7.2.1.5.2): an integer literal must
//! fit `uint` (unsigned 64 bit) or, negative, `int` (signed 64 bit); a float literal must be
//! finite. Huge literals are errors here, never panics.

use super::ast::{self, AstNode, LiteralValue};
use super::diagnostic::{SyntaxError, SyntaxErrorKind};
use super::kind::SyntaxNode;

/// Errors for every LITERAL under `root` whose value cannot be represented.
pub(crate) fn literals(root: &SyntaxNode) -> Vec<SyntaxError> {
    root.descendants()
        .filter_map(ast::Literal::cast)
        .filter_map(|lit| match lit.value() {
            Err(message) => {
                let range = lit.syntax().text_range();
                Some(SyntaxError::new(
                    SyntaxErrorKind::Literal,
                    range.start().into()..range.end().into(),
                    message,
                ))
            }
            Ok(LiteralValue::String(_)) | Ok(_) => None,
        })
        .collect()
}
