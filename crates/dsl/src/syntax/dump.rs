//! A text dump of the syntax tree without trivia and layout tokens, for fixture tests and
//! debugging; the meaning-preservation check of the formatter compares these dumps.

use super::kind::{SyntaxKind, SyntaxNode};
use rowan::{NodeOrToken, WalkEvent};
use std::fmt::Write;

fn shown(kind: SyntaxKind) -> bool {
    !kind.is_trivia()
        && !matches!(
            kind,
            SyntaxKind::NEWLINE | SyntaxKind::INDENT | SyntaxKind::DEDENT
        )
}

/// Dumps `node` one node per line, indented by depth: `KIND` for a node with child nodes,
/// `KIND: TOKEN "text" …` for a node with tokens only; tokens among child nodes on their own
/// lines. Trivia and NEWLINE/INDENT/DEDENT are left out. Iterative: no recursion on the depth.
pub fn debug_dump(node: &SyntaxNode) -> String {
    let mut out = String::new();
    let mut depth = 0usize;
    let mut skip_tokens_of: Option<SyntaxNode> = None;
    for event in node.preorder_with_tokens() {
        match event {
            WalkEvent::Enter(NodeOrToken::Node(n)) => {
                let _ = write!(out, "{:width$}{:?}", "", n.kind(), width = depth * 2);
                if n.children().next().is_none() {
                    out.push(':');
                    for t in n.children_with_tokens().filter_map(|e| e.into_token()) {
                        if shown(t.kind()) {
                            let _ = write!(out, " {:?} {:?}", t.kind(), t.text());
                        }
                    }
                    skip_tokens_of = Some(n.clone());
                }
                out.push('\n');
                depth += 1;
            }
            WalkEvent::Leave(NodeOrToken::Node(n)) => {
                depth -= 1;
                if skip_tokens_of.as_ref() == Some(&n) {
                    skip_tokens_of = None;
                }
            }
            WalkEvent::Enter(NodeOrToken::Token(t)) => {
                let inline = t
                    .parent()
                    .is_some_and(|p| skip_tokens_of.as_ref() == Some(&p));
                if shown(t.kind()) && !inline {
                    let _ = writeln!(
                        out,
                        "{:width$}{:?} {:?}",
                        "",
                        t.kind(),
                        t.text(),
                        width = depth * 2
                    );
                }
            }
            WalkEvent::Leave(NodeOrToken::Token(_)) => {}
        }
    }
    out
}
