//! Typed view over the concrete syntax tree: one wrapper type per node kind, with accessors
//! named after the productions of ASAM OpenSCENARIO DSL 2.1 §7.2.2.
//!
//! A wrapper is a [`SyntaxNode`] whose kind is known; [`AstNode::cast`] checks the kind,
//! [`AstNode::syntax`] gives the node back (for its span: `syntax().text_range()`). Accessors
//! return `Option` because a tree with errors may lack any child. Sum types group kinds:
//! [`Item`] (top-level statements), [`Member`] (members of blocks), [`Expr`], [`Type`],
//! [`EventCondition`].
//!
//! | file | wrappers |
//! | --- | --- |
//! | `mod.rs` | trait, helpers, [`SourceFile`], [`Item`], [`Member`], names |
//! | `items.rs` | imports, namespaces, type / unit / enum / structured declarations, extensions |
//! | `members.rs` | fields, events, constraints, methods, coverage, behavior directives |
//! | `expressions.rs` | expressions, literals and their values, types, arguments, events |

mod expressions;
mod items;
mod members;

pub use expressions::*;
pub use items::*;
pub use members::*;

use super::kind::{SyntaxKind, SyntaxKind::*, SyntaxNode, SyntaxToken};

/// A typed wrapper around a syntax node of known kind(s).
pub trait AstNode: Sized {
    /// Whether nodes of `kind` can be wrapped.
    fn can_cast(kind: SyntaxKind) -> bool;
    /// Wraps `node` if its kind fits.
    fn cast(node: SyntaxNode) -> Option<Self>;
    /// The wrapped node.
    fn syntax(&self) -> &SyntaxNode;
}

/// First child node of type `N`.
pub(crate) fn child<N: AstNode>(node: &SyntaxNode) -> Option<N> {
    node.children().find_map(N::cast)
}

/// All child nodes of type `N`.
pub(crate) fn children<N: AstNode>(node: &SyntaxNode) -> impl Iterator<Item = N> {
    node.children().filter_map(N::cast)
}

/// First child token of `kind`.
pub(crate) fn token(node: &SyntaxNode, kind: SyntaxKind) -> Option<SyntaxToken> {
    node.children_with_tokens()
        .filter_map(|e| e.into_token())
        .find(|t| t.kind() == kind)
}

/// Declares wrapper structs for single node kinds.
macro_rules! ast_nodes {
    ($($(#[$doc:meta])* $name:ident = $kind:ident;)*) => {$(
        $(#[$doc])*
        #[derive(Debug, Clone, PartialEq, Eq, Hash)]
        pub struct $name($crate::syntax::SyntaxNode);

        impl $crate::syntax::ast::AstNode for $name {
            fn can_cast(kind: $crate::syntax::SyntaxKind) -> bool {
                kind == $crate::syntax::SyntaxKind::$kind
            }
            fn cast(node: $crate::syntax::SyntaxNode) -> Option<Self> {
                Self::can_cast(node.kind()).then(|| $name(node))
            }
            fn syntax(&self) -> &$crate::syntax::SyntaxNode {
                &self.0
            }
        }
    )*};
}

/// Declares a sum type over wrapper types.
macro_rules! ast_enum {
    ($(#[$doc:meta])* $name:ident { $($variant:ident($ty:ident)),* $(,)? }) => {
        $(#[$doc])*
        #[derive(Debug, Clone, PartialEq, Eq, Hash)]
        #[allow(missing_docs)]
        pub enum $name { $($variant($ty),)* }

        impl $crate::syntax::ast::AstNode for $name {
            fn can_cast(kind: $crate::syntax::SyntaxKind) -> bool {
                false $(|| <$ty as $crate::syntax::ast::AstNode>::can_cast(kind))*
            }
            fn cast(node: $crate::syntax::SyntaxNode) -> Option<Self> {
                $(if <$ty as $crate::syntax::ast::AstNode>::can_cast(node.kind()) {
                    return <$ty as $crate::syntax::ast::AstNode>::cast(node).map($name::$variant);
                })*
                None
            }
            fn syntax(&self) -> &$crate::syntax::SyntaxNode {
                match self { $($name::$variant(n) => n.syntax(),)* }
            }
        }
    };
}
pub(crate) use {ast_enum, ast_nodes};

ast_nodes! {
    /// The root: prelude and main statements.
    SourceFile = SOURCE_FILE;
    /// A declared name (`qualified-identifier`).
    Name = NAME;
    /// A referenced name (`qualified-identifier`).
    NameRef = NAME_REF;
    /// `NEWLINE INDENT member+ DEDENT`.
    Block = BLOCK;
}

impl SourceFile {
    /// Wraps the root of a parse (always a SOURCE_FILE).
    pub(crate) fn cast_root(node: SyntaxNode) -> SourceFile {
        SourceFile(node)
    }

    /// Top-level statements and declarations, in order.
    pub fn items(&self) -> impl Iterator<Item = Item> {
        children(&self.0)
    }

    /// The `import` statements (the prelude).
    pub fn imports(&self) -> impl Iterator<Item = ImportStmt> {
        children(&self.0)
    }
}

ast_enum! {
    /// A top-level statement: prelude and main statements (§7.2.2.1), and the members the
    /// domain model's examples write at top level (fields, `keep`, modifier application, `for`).
    Item {
        Import(ImportStmt), Namespace(NamespaceStmt), Export(ExportStmt),
        PhysicalType(PhysicalTypeDecl), Unit(UnitDecl), Enum(EnumDecl),
        EnumExtension(EnumExtension), Struct(StructDecl), Actor(ActorDecl),
        Scenario(ScenarioDecl), Action(ActionDecl), Modifier(ModifierDecl), Extend(ExtendDecl),
        Global(GlobalParamDecl), Param(ParamDecl), Keep(KeepConstraint),
        RemoveDefault(RemoveDefault), ModifierApplication(ModifierApplication),
        For(ForConstraint),
    }
}

ast_enum! {
    /// A member of a block: structured type members (§7.2.2.4), behavior directives and
    /// do-members (§7.2.2.4.7), with-block members.
    Member {
        Event(EventDecl), Param(ParamDecl), Var(VarDecl), Keep(KeepConstraint),
        RemoveDefault(RemoveDefault), Method(MethodDecl), Coverage(CoverageDecl),
        ModifierApplication(ModifierApplication), On(OnDirective), Do(DoDirective),
        For(ForConstraint), Until(UntilDirective), Composition(Composition),
        Invocation(BehaviorInvocation), Wait(WaitDirective), Emit(EmitDirective),
        Call(CallDirective),
    }
}

impl Block {
    /// The members, in order.
    pub fn members(&self) -> impl Iterator<Item = Member> {
        children(&self.0)
    }
}

/// The text of an identifier token, without the `|…|` of a quoted identifier.
pub fn identifier_text(token: &SyntaxToken) -> &str {
    let text = token.text();
    text.strip_prefix('|')
        .and_then(|t| t.strip_suffix('|'))
        .unwrap_or(text)
}

/// Shared accessors of [`Name`] and [`NameRef`].
fn name_parts(node: &SyntaxNode) -> (Option<String>, Option<String>) {
    let tokens: Vec<SyntaxToken> = node
        .children_with_tokens()
        .filter_map(|e| e.into_token())
        .filter(|t| !t.kind().is_trivia())
        .collect();
    let Some(last) = tokens.iter().rev().find(|t| t.kind() == IDENT) else {
        return (None, None);
    };
    let namespace = match tokens.iter().position(|t| t.kind() == COLON2) {
        Some(0) => Some(String::new()),
        Some(_) => tokens.first().map(|t| identifier_text(t).to_string()),
        None => None,
    };
    (namespace, Some(identifier_text(last).to_string()))
}

/// `ns::name` as written (a `null::` prefix written `::`), or the bare name.
fn qualified_text(node: &SyntaxNode) -> String {
    match name_parts(node) {
        (Some(ns), Some(n)) if ns == "null" => format!("::{n}"),
        (Some(ns), Some(n)) => format!("{ns}::{n}"),
        (None, Some(n)) => n,
        (_, None) => String::new(),
    }
}

impl Name {
    /// The identifier, without namespace prefix or `|…|` quotes.
    pub fn text(&self) -> String {
        name_parts(&self.0).1.unwrap_or_default()
    }

    /// The identifier with its namespace prefix as written (`ns::name`; `::name` for the
    /// global namespace, however it was spelled), without `|…|` quotes.
    pub fn qualified_text(&self) -> String {
        qualified_text(&self.0)
    }

    /// The namespace prefix of `ns::name` (`""` for `::name`), if any.
    pub fn namespace(&self) -> Option<String> {
        name_parts(&self.0).0
    }
}

impl NameRef {
    /// The identifier, without namespace prefix or `|…|` quotes.
    pub fn text(&self) -> String {
        name_parts(&self.0).1.unwrap_or_default()
    }

    /// The identifier with its namespace prefix as written (see [`Name::qualified_text`]).
    pub fn qualified_text(&self) -> String {
        qualified_text(&self.0)
    }

    /// The namespace prefix of `ns::name` (`""` for the global `::name`), if any.
    pub fn namespace(&self) -> Option<String> {
        name_parts(&self.0).0
    }
}
