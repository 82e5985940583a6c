//! Collects the declarations of all files into a [`Model`]: names first (so order of
//! declaration does not matter), then inheritance, then fields and methods (ASAM OpenSCENARIO
//! DSL 2.1 §7.3.4 physical types, §7.3.5 enums, §7.3.7 compound types, §7.3.8 extension).

use super::diagnostic::{Diagnostic, DiagnosticKind};
use super::hir::{CompoundKind, ExprKind, Item, Member, QualName, SiArg, SourceFile, TypeRef};
use super::model::{CompoundDef, EnumDef, FieldDef, MethodDef, Model, ParamDef, TypeName};
use super::types::{CompoundId, EnumId, Ty};
use super::units::{Dimension, PhysicalType, Unit};

/// Collects `files` (in load order) into a model, pushing diagnostics.
pub fn collect(files: &[SourceFile], diags: &mut Vec<Diagnostic>) -> Model {
    let mut m = Model::default();
    // 1. names: physical types, units, enums, compounds.
    for item in files.iter().flat_map(|f| &f.items) {
        match item {
            Item::PhysicalType { name, si, span } => {
                let (dim, _, _) = si_spec(si, diags);
                if !m.units.add_type(PhysicalType {
                    name: name.text.clone(),
                    dimension: dim,
                }) {
                    diags.push(Diagnostic::new(
                        DiagnosticKind::Duplicate,
                        name.span,
                        format!("physical type `{}` is declared twice", name.text),
                    ));
                    continue;
                }
                m.declare_type(&name.text, TypeName::Physical(dim), *span, diags);
            }
            Item::Enum {
                name,
                members,
                references,
                span,
            } => {
                let id = EnumId(m.enums.len() as u32);
                let mut list: Vec<String> = Vec::new();
                for mem in members {
                    if list.contains(&mem.text) {
                        diags.push(Diagnostic::new(
                            DiagnosticKind::Duplicate,
                            mem.span,
                            format!("enum `{}` has member `{}` twice", name.text, mem.text),
                        ));
                    } else {
                        list.push(mem.text.clone());
                    }
                }
                m.enums.push(EnumDef {
                    name: name.text.clone(),
                    members: list,
                    references: references.clone(),
                    span: *span,
                });
                m.declare_type(&name.text, TypeName::Enum(id), *span, diags);
            }
            Item::Compound(c) => {
                let id = CompoundId(m.compounds.len() as u32);
                let full = c.name.text();
                m.compounds.push(CompoundDef {
                    kind: c.kind,
                    name: full.clone(),
                    // Modifiers are applied by their bare name (namespace.rs).
                    short: c
                        .name
                        .last_text()
                        .rsplit("::")
                        .next()
                        .unwrap_or_default()
                        .to_string(),
                    actor: None,
                    parent: None,
                    of: None,
                    condition: c.inherits.as_ref().and_then(|i| i.condition.clone()),
                    fields: Vec::new(),
                    methods: Vec::new(),
                    members: c.members.clone(),
                    span: c.span,
                });
                match c.kind {
                    CompoundKind::Struct | CompoundKind::Actor => {
                        m.declare_type(&full, TypeName::Compound(id), c.name.span, diags)
                    }
                    _ => {
                        let key = c.name.text();
                        if let Some(first) = m.behaviors.get(&key) {
                            let first = m.compound(*first).span;
                            diags.push(
                                Diagnostic::new(
                                    DiagnosticKind::Duplicate,
                                    c.name.span,
                                    format!("{} `{full}` is declared twice", c.kind.keyword()),
                                )
                                .with(first, "first declared here"),
                            );
                        } else {
                            m.behaviors.insert(key, id);
                        }
                    }
                }
            }
            _ => {}
        }
    }
    for item in files.iter().flat_map(|f| &f.items) {
        if let Item::Unit { name, of, si, .. } = item {
            let (dim, factor, offset) = si_spec(si, diags);
            let Some(pt) = m.units.physical_type(&of.text()).cloned() else {
                diags.push(Diagnostic::new(
                    DiagnosticKind::UnknownName,
                    of.span,
                    format!("unknown physical type `{}`", of.text()),
                ));
                continue;
            };
            if pt.dimension != dim {
                diags.push(Diagnostic::new(
                    DiagnosticKind::Units,
                    name.span,
                    format!(
                        "unit `{}` has dimension {dim}, but its type `{}` has dimension {}",
                        name.text, pt.name, pt.dimension
                    ),
                ));
            }
            let unit = Unit {
                name: name.text.clone(),
                physical_type: pt.name.clone(),
                dimension: pt.dimension,
                factor,
                offset,
            };
            if !m.units.add_unit(unit) {
                diags.push(Diagnostic::new(
                    DiagnosticKind::Duplicate,
                    name.span,
                    format!("unit `{}` is declared twice", name.text),
                ));
            }
        }
    }
    // 2. actors of behaviors, parents, `of`.
    let mut index = 0;
    for item in files.iter().flat_map(|f| &f.items) {
        let Item::Compound(c) = item else { continue };
        let id = CompoundId(index);
        index += 1;
        if c.name.parts.len() > 1 && c.kind != CompoundKind::Struct && c.kind != CompoundKind::Actor
        {
            let actor_name = QualName {
                parts: c.name.parts[..c.name.parts.len() - 1].to_vec(),
                span: c.name.parts[0].span,
            };
            m.compounds[id.0 as usize].actor =
                compound_named(&m, &actor_name, Some(CompoundKind::Actor), diags);
        }
        if let Some(inh) = &c.inherits {
            let parent = match c.kind {
                CompoundKind::Struct | CompoundKind::Actor => {
                    compound_named(&m, &inh.parent, Some(c.kind), diags)
                }
                _ => match m.behaviors.get(&inh.parent.text()) {
                    Some(p) if m.compound(*p).kind == c.kind => Some(*p),
                    _ => {
                        diags.push(Diagnostic::new(
                            DiagnosticKind::Inheritance,
                            inh.parent.span,
                            format!(
                                "{} `{}` inherits from unknown {} `{}`",
                                c.kind.keyword(),
                                c.name.text(),
                                c.kind.keyword(),
                                inh.parent.text()
                            ),
                        ));
                        None
                    }
                },
            };
            m.compounds[id.0 as usize].parent = parent;
        }
        if let Some(of) = &c.of {
            match m.behaviors.get(&of.text()) {
                Some(b) if m.compound(*b).kind != CompoundKind::Modifier => {
                    m.compounds[id.0 as usize].of = Some(*b)
                }
                _ => diags.push(Diagnostic::new(
                    DiagnosticKind::UnknownName,
                    of.span,
                    format!(
                        "modifier `{}` is declared of unknown action or scenario `{}`",
                        c.name.text(),
                        of.text()
                    ),
                )),
            }
        }
    }
    for i in 0..m.compounds.len() {
        let id = CompoundId(i as u32);
        let chain = m.ancestry(id);
        let last = *chain.last().unwrap_or(&id);
        if m.compound(last).parent.is_some() {
            let d = m.compound(id);
            diags.push(Diagnostic::new(
                DiagnosticKind::Inheritance,
                d.span,
                format!("{} `{}` inherits from itself", d.kind.keyword(), d.name),
            ));
            m.compounds[i].parent = None;
        }
    }
    // 3. members: fields and methods, own then extensions; globals; enum extensions.
    let mut index = 0;
    for item in files.iter().flat_map(|f| &f.items) {
        match item {
            Item::Compound(c) => {
                let id = CompoundId(index);
                index += 1;
                add_members(&mut m, id, &c.members, diags);
            }
            Item::Extend {
                target, members, ..
            } => {
                // §7.3.9: structs, actors, scenarios and actions can be extended.
                let found = match m.types.get(&target.text()) {
                    Some((TypeName::Compound(c), _)) => Some(*c),
                    _ => m.behaviors.get(&target.text()).copied(),
                };
                let Some(id) = found.or_else(|| compound_named(&m, target, None, diags)) else {
                    continue;
                };
                m.compounds[id.0 as usize]
                    .members
                    .extend(members.iter().cloned());
                add_members(&mut m, id, members, diags);
            }
            Item::EnumExtension {
                name,
                members,
                references,
                ..
            } => match m.types.get(&name.text()) {
                Some((TypeName::Enum(e), _)) => {
                    let e = *e;
                    m.enums[e.0 as usize]
                        .references
                        .extend(references.iter().cloned());
                    for mem in members {
                        let def = &mut m.enums[e.0 as usize];
                        if def.members.contains(&mem.text) {
                            diags.push(Diagnostic::new(
                                DiagnosticKind::Duplicate,
                                mem.span,
                                format!("enum `{}` already has member `{}`", def.name, mem.text),
                            ));
                        } else {
                            def.members.push(mem.text.clone());
                        }
                    }
                }
                _ => diags.push(Diagnostic::new(
                    DiagnosticKind::UnknownName,
                    name.span,
                    format!("unknown enum `{}`", name.text()),
                )),
            },
            Item::Global(f) => {
                for def in field_defs(&m, f, diags) {
                    push_global(&mut m, def, diags);
                }
            }
            Item::Member(Member::Field(f)) => {
                for def in field_defs(&m, f, diags) {
                    push_global(&mut m, def, diags);
                }
            }
            Item::Member(other) => m.top.push(other.clone()),
            _ => {}
        }
    }
    m
}

fn push_global(m: &mut Model, def: FieldDef, diags: &mut Vec<Diagnostic>) {
    if let Some(first) = m.globals.iter().find(|g| g.name == def.name) {
        diags.push(
            Diagnostic::new(
                DiagnosticKind::Duplicate,
                def.span,
                format!("`{}` is declared twice", def.name),
            )
            .with(first.span, "first declared here"),
        );
        return;
    }
    m.globals.push(def);
}

fn add_members(m: &mut Model, id: CompoundId, members: &[Member], diags: &mut Vec<Diagnostic>) {
    for member in members {
        match member {
            Member::Field(f) => {
                for def in field_defs(m, f, diags) {
                    if let Some(first) = m.field(id, &def.name) {
                        diags.push(
                            Diagnostic::new(
                                DiagnosticKind::Duplicate,
                                def.span,
                                format!(
                                    "`{}` already has a field `{}`",
                                    m.compound(id).name,
                                    def.name
                                ),
                            )
                            .with(first.span, "first declared here"),
                        );
                        continue;
                    }
                    m.compounds[id.0 as usize].fields.push(def);
                }
            }
            Member::Method(md) => {
                let params = md
                    .params
                    .iter()
                    .map(|p| ParamDef {
                        name: p.name.text.clone(),
                        ty: resolve_type(m, &p.ty, diags),
                        optional: p.default.is_some(),
                    })
                    .collect();
                let ret = md.ret.as_ref().map(|t| resolve_type(m, t, diags));
                let def = MethodDef {
                    name: md.name.text.clone(),
                    params,
                    ret,
                    span: md.span,
                };
                if m.compound(id).methods.iter().any(|x| x.name == def.name) {
                    if md.only {
                        // An override through an extension: its signature is checked in
                        // declarations.rs.
                        continue;
                    }
                    diags.push(Diagnostic::new(
                        DiagnosticKind::Duplicate,
                        md.name.span,
                        format!("method `{}` is declared twice", def.name),
                    ));
                    continue;
                }
                m.compounds[id.0 as usize].methods.push(def);
            }
            _ => {}
        }
    }
}

fn field_defs(m: &Model, f: &super::hir::FieldDecl, diags: &mut Vec<Diagnostic>) -> Vec<FieldDef> {
    let ty = resolve_type(m, &f.ty, diags);
    f.names
        .iter()
        .map(|n| FieldDef {
            name: n.text.clone(),
            ty: ty.clone(),
            is_var: f.is_var,
            default: f.default.clone(),
            keeps: f.keeps.clone(),
            span: n.span,
        })
        .collect()
}

/// The type a [`TypeRef`] names; `Ty::Error` after a diagnostic.
pub fn resolve_type(m: &Model, t: &TypeRef, diags: &mut Vec<Diagnostic>) -> Ty {
    match t {
        TypeRef::Primitive(n) => match n.text.as_str() {
            "bool" => Ty::Bool,
            "int" => Ty::Int,
            "uint" => Ty::Uint,
            "float" => Ty::Float,
            "string" => Ty::Str,
            other => {
                diags.push(Diagnostic::new(
                    DiagnosticKind::UnknownName,
                    n.span,
                    format!("unknown type `{other}`"),
                ));
                Ty::Error
            }
        },
        TypeRef::Named(q) => match m.types.get(&q.text()) {
            Some((TypeName::Physical(d), _)) => Ty::Physical(*d),
            Some((TypeName::Enum(e), _)) => Ty::Enum(*e),
            Some((TypeName::Compound(c), _)) => Ty::Compound(*c),
            None => {
                diags.push(Diagnostic::new(
                    DiagnosticKind::UnknownName,
                    q.span,
                    format!("unknown type `{}`", q.text()),
                ));
                Ty::Error
            }
        },
        TypeRef::List(inner, span) => {
            let t = resolve_type(m, inner, diags);
            if matches!(t, Ty::List(_)) {
                diags.push(Diagnostic::new(
                    DiagnosticKind::Type,
                    *span,
                    "a list cannot hold lists",
                ));
                return Ty::Error;
            }
            Ty::List(Box::new(t))
        }
        TypeRef::Range(inner, span) => {
            let t = resolve_type(m, inner, diags);
            // §7.4.1.3: "A range expression can be given for any numerical type".
            if !t.is_numeric() && t != Ty::Error {
                diags.push(Diagnostic::new(
                    DiagnosticKind::Type,
                    *span,
                    format!(
                        "a range is of a numeric type (int, uint, float or a physical type, §7.4.1.3), found range of {}",
                        m.type_name(&t)
                    ),
                ));
                return Ty::Error;
            }
            Ty::Range(Box::new(t))
        }
    }
}

/// The struct or actor named `q` (of `kind` when given).
fn compound_named(
    m: &Model,
    q: &QualName,
    kind: Option<CompoundKind>,
    diags: &mut Vec<Diagnostic>,
) -> Option<CompoundId> {
    match m.types.get(&q.text()) {
        Some((TypeName::Compound(c), _)) if kind.is_none_or(|k| m.compound(*c).kind == k) => {
            Some(*c)
        }
        Some(_) => {
            let want = kind.map_or("struct or actor", |k| k.keyword());
            diags.push(Diagnostic::new(
                DiagnosticKind::Inheritance,
                q.span,
                format!("`{}` is not a {want}", q.text()),
            ));
            None
        }
        None => {
            let what = kind.map_or("type", |k| k.keyword());
            diags.push(Diagnostic::new(
                DiagnosticKind::UnknownName,
                q.span,
                format!("unknown {what} `{}`", q.text()),
            ));
            None
        }
    }
}

/// Dimension, factor and offset of an `SI(…)` specification.
fn si_spec(args: &[SiArg], diags: &mut Vec<Diagnostic>) -> (Dimension, f64, f64) {
    let mut dim = Dimension::NONE;
    let (mut factor, mut offset) = (1.0, 0.0);
    for a in args {
        let value = match number(&a.value.kind) {
            Some(v) => v,
            None => {
                diags.push(Diagnostic::new(
                    DiagnosticKind::Type,
                    a.value.span,
                    format!("expected a number for `{}`", a.name.text),
                ));
                continue;
            }
        };
        match a.name.text.as_str() {
            "factor" => factor = value,
            "offset" => offset = value,
            base => {
                let exp = value as i64;
                let ok = value.fract() == 0.0 && (i8::MIN as i64..=i8::MAX as i64).contains(&exp);
                match Dimension::base(base, exp as i8).filter(|_| ok) {
                    Some(d) => dim = dim.times(d).unwrap_or(dim),
                    None => diags.push(Diagnostic::new(
                        DiagnosticKind::Units,
                        a.name.span,
                        format!("expected an SI base unit (kg, m, s, A, K, mol, cd, rad) with a whole exponent, found `{base}: {value}`"),
                    )),
                }
            }
        }
    }
    (dim, factor, offset)
}

fn number(e: &ExprKind) -> Option<f64> {
    match e {
        ExprKind::Int(i) => Some(*i as f64),
        ExprKind::Float(f) => Some(*f),
        ExprKind::Neg(inner) => number(&inner.kind).map(|v| -v),
        _ => None,
    }
}
