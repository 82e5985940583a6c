//! The declarations of a program, collected from all its files (library first): physical types
//! and units, enumerations, compound types with their fields and methods after inheritance and
//! `extend` (ASAM OpenSCENARIO DSL 2.1 §7.3 types, §7.3.7 compound types, §7.3.8 extension).

use std::collections::{HashMap, HashSet};

use super::diagnostic::{Diagnostic, DiagnosticKind};
use super::hir::{CompoundKind, Expr, Keep, Member, Name, Span};
use super::types::{CompoundId, EnumId, Ty};
use super::units::{Dimension, UnitTable};

/// An enumeration.
#[derive(Debug, Clone, PartialEq)]
pub struct EnumDef {
    /// Its name.
    pub name: String,
    /// Members in order.
    pub members: Vec<String>,
    /// Members whose value names another member (`a = b`, `a = colors!b`), from the declaration
    /// and its extensions.
    pub references: Vec<(Name, Expr)>,
    /// Its declaration.
    pub span: Span,
}

/// A field of a compound type, or a global or top-level field.
#[derive(Debug, Clone, PartialEq)]
pub struct FieldDef {
    /// Its name.
    pub name: String,
    /// Its type.
    pub ty: Ty,
    /// A `var` (state variable): not a parameter, not resolved before the run.
    pub is_var: bool,
    /// `= value`.
    pub default: Option<Expr>,
    /// Constraints of its `with:` block (over `it`).
    pub keeps: Vec<Keep>,
    /// Its declaration.
    pub span: Span,
}

/// A method parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct ParamDef {
    /// Its name.
    pub name: String,
    /// Its type.
    pub ty: Ty,
    /// Whether it may be left out.
    pub optional: bool,
}

/// A method.
#[derive(Debug, Clone, PartialEq)]
pub struct MethodDef {
    /// Its name.
    pub name: String,
    /// Parameters.
    pub params: Vec<ParamDef>,
    /// Return type (`None`: returns nothing).
    pub ret: Option<Ty>,
    /// Its declaration.
    pub span: Span,
}

/// A struct, actor, scenario, action or modifier.
#[derive(Debug, Clone, PartialEq)]
pub struct CompoundDef {
    /// Which kind.
    pub kind: CompoundKind,
    /// Full name (`vehicle.drive`).
    pub name: String,
    /// Name without the actor (`drive`).
    pub short: String,
    /// The actor a behavior or modifier belongs to.
    pub actor: Option<CompoundId>,
    /// The parent type.
    pub parent: Option<CompoundId>,
    /// The behavior a modifier applies to (`of …`).
    pub of: Option<CompoundId>,
    /// The condition of a conditional `inherits Parent(field == value)`: every instance
    /// satisfies it (ASAM OpenSCENARIO DSL 2.1 §7.3.7.1 conditional inheritance).
    pub condition: Option<Expr>,
    /// Own fields (inherited ones live on the parents).
    pub fields: Vec<FieldDef>,
    /// Own methods.
    pub methods: Vec<MethodDef>,
    /// Own members, including those added by `extend`, in order, for the checker.
    pub members: Vec<Member>,
    /// Its declaration.
    pub span: Span,
}

/// What a type name denotes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TypeName {
    /// A physical type.
    Physical(Dimension),
    /// An enumeration.
    Enum(EnumId),
    /// A compound type.
    Compound(CompoundId),
}

/// All declarations of a program.
#[derive(Debug, Clone, Default)]
pub struct Model {
    /// Physical types and units.
    pub units: UnitTable,
    /// Enumerations.
    pub enums: Vec<EnumDef>,
    /// Compound types.
    pub compounds: Vec<CompoundDef>,
    /// Type names (physical, enum, struct, actor).
    pub types: HashMap<String, (TypeName, Span)>,
    /// Behaviors and modifiers by full name.
    pub behaviors: HashMap<String, CompoundId>,
    /// Global parameters and top-level fields.
    pub globals: Vec<FieldDef>,
    /// Top-level members other than fields (constraints, modifier applications).
    pub top: Vec<Member>,
    /// Files `0..library_files` are the standard library.
    pub library_files: u32,
    /// The spans of the bare names the checker resolved to a member of the enum their place
    /// expects although a field, global or local of another type has the same name in scope
    /// (`track: projected` beside an actor `projected`): where an enum is expected its member
    /// wins. The runtime evaluates expressions without their expected type, so it reads a name
    /// at one of these spans as that member, never as the field.
    pub enum_member_names: HashSet<Span>,
}

impl Model {
    /// The compound `id`.
    pub fn compound(&self, id: CompoundId) -> &CompoundDef {
        &self.compounds[id.0 as usize]
    }

    /// The enumeration `id`.
    pub fn enum_def(&self, id: EnumId) -> &EnumDef {
        &self.enums[id.0 as usize]
    }

    /// `id` and its ancestors, nearest first (stops at a cycle).
    pub fn ancestry(&self, id: CompoundId) -> Vec<CompoundId> {
        let mut out = vec![id];
        let mut cur = self.compound(id).parent;
        while let Some(p) = cur {
            if out.contains(&p) {
                break;
            }
            out.push(p);
            cur = self.compound(p).parent;
        }
        out
    }

    /// Whether `sub` is `sup` or inherits from it.
    pub fn is_subtype(&self, sub: CompoundId, sup: CompoundId) -> bool {
        self.ancestry(sub).contains(&sup)
    }

    /// The field `name` of `id` or of an ancestor.
    pub fn field(&self, id: CompoundId, name: &str) -> Option<&FieldDef> {
        self.ancestry(id)
            .into_iter()
            .find_map(|c| self.compound(c).fields.iter().find(|f| f.name == name))
    }

    /// Every field of `id`, ancestors' first.
    pub fn all_fields(&self, id: CompoundId) -> Vec<&FieldDef> {
        let mut chain = self.ancestry(id);
        chain.reverse();
        chain
            .into_iter()
            .flat_map(|c| self.compound(c).fields.iter())
            .collect()
    }

    /// Whether `id` is the library's `route` or inherits from it (`road`, `lane`,
    /// `compound_route`, …): a road-network value the runtime finds in the map, so a value
    /// given at a field's declaration (`r: route = m.create_route(…)`) is the runtime's, not a
    /// constraint.
    pub fn is_route(&self, id: CompoundId) -> bool {
        self.ancestry(id).into_iter().any(|a| {
            let d = self.compound(a);
            d.span.file.0 < self.library_files
                && d.name.strip_prefix("std::").unwrap_or(&d.name) == "route"
        })
    }

    /// The method `name` of `id` or of an ancestor.
    pub fn method(&self, id: CompoundId, name: &str) -> Option<&MethodDef> {
        self.ancestry(id)
            .into_iter()
            .find_map(|c| self.compound(c).methods.iter().find(|m| m.name == name))
    }

    /// The behavior (action or scenario) `name` of actor `actor` or of its ancestors.
    pub fn behavior_of(&self, actor: CompoundId, name: &str) -> Option<CompoundId> {
        self.ancestry(actor).into_iter().find_map(|a| {
            let full = format!("{}.{name}", self.compound(a).name);
            self.behaviors
                .get(&full)
                .copied()
                .filter(|b| self.compound(*b).kind != CompoundKind::Modifier)
        })
    }

    /// Modifiers called `name` (by short name): the program's own first, then the standard
    /// library's (a file's own `modifier speed` shadows the library's, §7.7.4.2).
    pub fn modifiers_named(&self, name: &str) -> Vec<CompoundId> {
        let mut found: Vec<CompoundId> = (0..self.compounds.len() as u32)
            .map(CompoundId)
            .filter(|c| {
                let d = self.compound(*c);
                d.kind == CompoundKind::Modifier && d.short == name
            })
            .collect();
        found.sort_by_key(|c| self.compound(*c).span.file.0 < self.library_files);
        found
    }

    /// Enumerations that have a member `name`.
    pub fn enums_with_member(&self, name: &str) -> Vec<EnumId> {
        (0..self.enums.len() as u32)
            .map(EnumId)
            .filter(|e| self.enum_def(*e).members.iter().any(|m| m == name))
            .collect()
    }

    /// The type's name for messages.
    pub fn type_name(&self, ty: &Ty) -> String {
        match ty {
            Ty::Bool => "bool".into(),
            Ty::Int => "int".into(),
            Ty::Uint => "uint".into(),
            Ty::Float => "float".into(),
            Ty::Str => "string".into(),
            Ty::Physical(d) => match self.units.type_of_dimension(*d) {
                Some(t) => t.name.clone(),
                None => format!("physical quantity of dimension {d}"),
            },
            Ty::Enum(e) => self.enum_def(*e).name.clone(),
            Ty::Compound(c) => self.compound(*c).name.clone(),
            Ty::List(t) => format!("list of {}", self.type_name(t)),
            Ty::Range(t) => format!("range of {}", self.type_name(t)),
            Ty::Event => "event".into(),
            Ty::Error => "unknown".into(),
        }
    }

    /// Declares a type name; a second declaration is a diagnostic naming the first.
    pub(crate) fn declare_type(
        &mut self,
        name: &str,
        what: TypeName,
        span: Span,
        diags: &mut Vec<Diagnostic>,
    ) {
        if let Some((_, first)) = self.types.get(name) {
            diags.push(
                Diagnostic::new(
                    DiagnosticKind::Duplicate,
                    span,
                    format!("type `{name}` is declared twice"),
                )
                .with(*first, "first declared here"),
            );
            return;
        }
        self.types.insert(name.to_string(), (what, span));
    }
}
