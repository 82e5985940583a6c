//! Typed wrappers of top-level statements and type declarations (ASAM OpenSCENARIO DSL 2.1
//! §7.2.2.1–§7.2.2.3).

use super::{
    ast_nodes, child, children, identifier_text, token, Block, Expr, Member, Name, NameRef,
    NamedType, ParamDecl, PrimitiveType, Type,
};
use crate::syntax::kind::SyntaxKind::*;

ast_nodes! {
    /// `import "file.osc"` or `import osc.standard`.
    ImportStmt = IMPORT_STMT;
    /// `namespace name [use a, b]`.
    NamespaceStmt = NAMESPACE_STMT;
    /// `export a, ns::*`.
    ExportStmt = EXPORT_STMT;
    /// One export specification.
    ExportSpec = EXPORT_SPEC;
    /// `type length is SI(m: 1)`.
    PhysicalTypeDecl = PHYSICAL_TYPE_DECL;
    /// `unit kph of speed is SI(m: 1, s: -1, factor: 0.277…)`.
    UnitDecl = UNIT_DECL;
    /// `SI(…)`.
    SiSpec = SI_SPEC;
    /// One `name: value` of `SI(…)`.
    SiArg = SI_ARG;
    /// `enum color: [red, green = 2]`.
    EnumDecl = ENUM_DECL;
    /// `extend color: [purple]`.
    EnumExtension = ENUM_EXTENSION;
    /// `[a, b = 1]`.
    EnumMemberList = ENUM_MEMBER_LIST;
    /// `a` or `b = 1` in an enum.
    EnumMember = ENUM_MEMBER;
    /// `struct name [inherits …]: …`.
    StructDecl = STRUCT_DECL;
    /// `actor name [inherits …]: …`.
    ActorDecl = ACTOR_DECL;
    /// `scenario [actor.]name [inherits …]: …`.
    ScenarioDecl = SCENARIO_DECL;
    /// `action [actor.]name [inherits …]: …`.
    ActionDecl = ACTION_DECL;
    /// `modifier [actor.]name [of behavior]: …`.
    ModifierDecl = MODIFIER_DECL;
    /// `extend type: …` of a structured or primitive type.
    ExtendDecl = EXTEND_DECL;
    /// `global name: type = value`.
    GlobalParamDecl = GLOBAL_PARAM_DECL;
    /// `inherits parent [(field == value)]`.
    Inherits = INHERITS;
    /// `(field == value)` of an `inherits`.
    InheritsCondition = INHERITS_CONDITION;
    /// `[actor.]name` of a scenario, action or modifier being declared.
    BehaviorName = BEHAVIOR_NAME;
}

impl ImportStmt {
    /// The import reference as written: the string's content (quotes removed) or the
    /// structured identifier (`osc.standard`).
    pub fn reference(&self) -> Option<String> {
        if let Some(s) = token(&self.0, STRING) {
            return super::string_value(s.text()).ok();
        }
        let parts: Vec<String> = self
            .0
            .children_with_tokens()
            .filter_map(|e| e.into_token())
            .filter(|t| t.kind() == IDENT)
            .map(|t| identifier_text(&t).to_string())
            .collect();
        (!parts.is_empty()).then(|| parts.join("."))
    }

    /// Whether the reference is a string (a file path) rather than a library name.
    pub fn is_path(&self) -> bool {
        token(&self.0, STRING).is_some()
    }
}

impl NamespaceStmt {
    /// The namespace declared (`null` is the global namespace).
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
    /// The namespaces after `use`.
    pub fn uses(&self) -> impl Iterator<Item = NameRef> {
        children(&self.0)
    }
}

impl ExportStmt {
    /// The export specifications.
    pub fn specs(&self) -> impl Iterator<Item = ExportSpec> {
        children(&self.0)
    }
}

impl ExportSpec {
    /// The exported name, unless this is a wildcard.
    pub fn name(&self) -> Option<NameRef> {
        child(&self.0)
    }
    /// Whether this is `*`, `::*` or `ns::*`.
    pub fn is_wildcard(&self) -> bool {
        token(&self.0, STAR).is_some()
    }
    /// The namespace of a wildcard: `None` for `*` (the active one), `Some("")` for `::*` and
    /// `null::*`, `Some(ns)` for `ns::*`.
    pub fn wildcard_namespace(&self) -> Option<String> {
        token(&self.0, COLON2)?;
        let ns = token(&self.0, IDENT).map_or(String::new(), |t| identifier_text(&t).to_string());
        Some(if ns == "null" { String::new() } else { ns })
    }
}

impl PhysicalTypeDecl {
    /// The physical type's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
    /// Its SI base unit specifier.
    pub fn si(&self) -> Option<SiSpec> {
        child(&self.0)
    }
}

impl UnitDecl {
    /// The unit's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
    /// The physical type after `of`.
    pub fn physical_type(&self) -> Option<NameRef> {
        child(&self.0)
    }
    /// Its SI unit specifier.
    pub fn si(&self) -> Option<SiSpec> {
        child(&self.0)
    }
}

impl SiSpec {
    /// The `name: value` entries in order.
    pub fn args(&self) -> impl Iterator<Item = SiArg> {
        children(&self.0)
    }
}

impl SiArg {
    /// `kg`, `m`, `s`, `A`, `K`, `mol`, `cd`, `rad`, `factor` or `offset`.
    pub fn name(&self) -> Option<String> {
        self.0
            .children_with_tokens()
            .filter_map(|e| e.into_token())
            .find(|t| matches!(t.kind(), IDENT | FACTOR_KW | OFFSET_KW))
            .map(|t| t.text().to_string())
    }
    /// The exponent, factor or offset.
    pub fn value(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl EnumDecl {
    /// The enum's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
    /// Its members.
    pub fn members(&self) -> impl Iterator<Item = EnumMember> {
        child::<EnumMemberList>(&self.0)
            .into_iter()
            .flat_map(|l| children(&l.0).collect::<Vec<_>>())
    }
}

impl EnumExtension {
    /// The enum extended.
    pub fn target(&self) -> Option<NamedType> {
        child(&self.0)
    }
    /// The members added.
    pub fn members(&self) -> impl Iterator<Item = EnumMember> {
        child::<EnumMemberList>(&self.0)
            .into_iter()
            .flat_map(|l| children(&l.0).collect::<Vec<_>>())
    }
}

impl EnumMember {
    /// The member's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
    /// Its explicit value (`= 3`), if any.
    pub fn value(&self) -> Option<Expr> {
        child(&self.0)
    }
}

/// Accessors shared by struct, actor, scenario, action and modifier declarations.
macro_rules! structured_accessors {
    ($($ty:ident),*) => {$(
        impl $ty {
            /// `inherits …`, if present.
            pub fn inherits(&self) -> Option<Inherits> {
                child(&self.0)
            }
            /// The members of the body (none for a declaration without `:`).
            pub fn members(&self) -> impl Iterator<Item = Member> {
                child::<Block>(&self.0).into_iter().flat_map(|b| b.members().collect::<Vec<_>>())
            }
            /// The body block, if any.
            pub fn block(&self) -> Option<Block> {
                child(&self.0)
            }
        }
    )*};
}
structured_accessors!(
    StructDecl,
    ActorDecl,
    ScenarioDecl,
    ActionDecl,
    ModifierDecl,
    ExtendDecl
);

impl StructDecl {
    /// The struct's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
}

impl ActorDecl {
    /// The actor's name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
}

impl ScenarioDecl {
    /// `[actor.]name`.
    pub fn name(&self) -> Option<BehaviorName> {
        child(&self.0)
    }
}

impl ActionDecl {
    /// `[actor.]name`.
    pub fn name(&self) -> Option<BehaviorName> {
        child(&self.0)
    }
}

impl ModifierDecl {
    /// `[actor.]name`.
    pub fn name(&self) -> Option<BehaviorName> {
        child(&self.0)
    }
    /// The behavior after `of`, if any.
    pub fn of(&self) -> Option<NamedType> {
        child(&self.0)
    }
}

impl ExtendDecl {
    /// The type extended.
    pub fn target(&self) -> Option<Type> {
        child(&self.0)
    }
    /// Whether a primitive type is extended (`extend int:`).
    pub fn is_primitive(&self) -> bool {
        child::<PrimitiveType>(&self.0).is_some()
    }
}

impl GlobalParamDecl {
    /// The parameter declaration after `global`.
    pub fn param(&self) -> Option<ParamDecl> {
        child(&self.0)
    }
}

impl Inherits {
    /// The parent type.
    pub fn parent(&self) -> Option<NamedType> {
        child(&self.0)
    }
    /// The condition `(field == value)`, if any.
    pub fn condition(&self) -> Option<InheritsCondition> {
        child(&self.0)
    }
}

impl InheritsCondition {
    /// The field tested.
    pub fn field(&self) -> Option<NameRef> {
        child(&self.0)
    }
    /// The enum value or bool it must equal.
    pub fn value(&self) -> Option<Expr> {
        child(&self.0)
    }
}

impl BehaviorName {
    /// The actor before `.`, if any.
    pub fn actor(&self) -> Option<NameRef> {
        child(&self.0)
    }
    /// The behavior's own name.
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }
}
