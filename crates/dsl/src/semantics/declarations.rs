//! Rules on declarations checked over the collected [`Model`] (ASAM OpenSCENARIO DSL 2.1):
//!
//! | rule | standard |
//! | --- | --- |
//! | an event is declared once in a compound type (with its extensions) | §7.3.6 events: a member name is declared once |
//! | a method's parameters have distinct names | §7.3.7 methods |
//! | a method redefined in a subtype or an extension says `is only …`, and keeps the signature | §7.3.7.2: "the overriding method implementation must contain an `only` qualifier. Otherwise, an error is raised. An error is raised if the method type signature of an overriding method is different" |
//! | a scenario or action of an actor inherits one of the same or a more general actor; one of no actor inherits one of no actor | §7.3.8.1 |
//! | a conditional inheritance's field is a bool or an enum | §7.3.8.2: "subtypes that depend upon a value of a Boolean or enumerated field" |
//! | an enum member of a namespace is no actor's name there | §7.7.4.2 rule 1: enumeration values and types are identifiers of their namespace |
//! | an enum member's value that names another member (`a = b`, `a = colors!b`) names an existing one, and such references do not come back to where they started | `enum-member-value ::= uint-literal \| hex-uint-literal \| enum-value-reference`: a reference takes the named member's value, and in a cycle (`[a = b, b = a]`) no member has one |
//!
//! `is only` with nothing to override is allowed: "It is not an error if a method definition
//! contains an `only` qualifier and there is no existing method to be overridden" (§7.3.7.2).
//! The standard library's own declarations are not checked (its `vehicle_group.drive` inherits
//! a movable object's action on purpose, docs/dsl.md).

use std::collections::{BTreeMap, BTreeSet};

use super::diagnostic::{Diagnostic, DiagnosticKind as K};
use super::hir::{BinOp, CompoundKind, Expr, ExprKind, Member, MethodDecl, Name, Span};
use super::model::{Model, TypeName};
use super::types::{CompoundId, Ty};

/// Pushes a diagnostic for each broken rule in the program's own files.
pub fn check(m: &Model, diags: &mut Vec<Diagnostic>) {
    let own = |span: Span| span.file.0 >= m.library_files;
    for i in 0..m.compounds.len() {
        let id = CompoundId(i as u32);
        let c = m.compound(id);
        // A library type's members may come from a file's `extend`: those are checked.
        events(m, id, diags);
        for member in &c.members {
            if let Member::Method(md) = member {
                if own(md.span) {
                    parameters(md, diags);
                    overriding(m, id, md, diags);
                }
            }
        }
        if own(c.span) {
            behavior_parent(m, id, diags);
            condition_field(m, id, diags);
        }
    }
    for member in &m.top {
        if let Member::Method(md) = member {
            parameters(md, diags);
        }
    }
    enum_members_and_types(m, diags);
    enum_references(m, diags);
}

fn events(m: &Model, id: CompoundId, diags: &mut Vec<Diagnostic>) {
    let c = m.compound(id);
    let mut seen: BTreeMap<&str, Span> = BTreeMap::new();
    for member in &c.members {
        let Member::Event(ev) = member else { continue };
        match seen.get(ev.name.text.as_str()) {
            Some(first) if ev.name.span.file.0 >= m.library_files => diags.push(
                Diagnostic::new(
                    K::Duplicate,
                    ev.name.span,
                    format!("event `{}` is declared twice in `{}`", ev.name.text, c.name),
                )
                .with(*first, "first declared here"),
            ),
            Some(_) => {}
            None => {
                seen.insert(&ev.name.text, ev.name.span);
            }
        }
    }
}

fn parameters(md: &MethodDecl, diags: &mut Vec<Diagnostic>) {
    for (i, p) in md.params.iter().enumerate() {
        if let Some(first) = md.params[..i].iter().find(|q| q.name.text == p.name.text) {
            diags.push(
                Diagnostic::new(
                    K::Duplicate,
                    p.name.span,
                    format!(
                        "method `{}` has two parameters named `{}`",
                        md.name.text, p.name.text
                    ),
                )
                .with(first.name.span, "first declared here"),
            );
        }
    }
}

/// A method that redefines one of a parent (or an earlier one of the same type, through an
/// extension): `is only`, with the same parameter types and return type.
fn overriding(m: &Model, id: CompoundId, md: &MethodDecl, diags: &mut Vec<Diagnostic>) {
    let c = m.compound(id);
    let earlier_here = c
        .members
        .iter()
        .filter_map(|x| match x {
            Member::Method(other) if other.name.text == md.name.text => Some(other),
            _ => None,
        })
        .next()
        .filter(|first| first.span != md.span)
        .and_then(|_| c.methods.iter().find(|d| d.name == md.name.text));
    let inherited = c.parent.and_then(|p| {
        m.ancestry(p).into_iter().find_map(|a| {
            let d = m
                .compound(a)
                .methods
                .iter()
                .find(|d| d.name == md.name.text)?;
            Some((a, d))
        })
    });
    let (owner, prior) = match (earlier_here, inherited) {
        (Some(d), _) => (id, d),
        (None, Some((a, d))) => (a, d),
        (None, None) => return,
    };
    let owner_name = &m.compound(owner).name;
    let report = |diags: &mut Vec<Diagnostic>, why: String| {
        diags.push(
            Diagnostic::new(
                K::Inheritance,
                md.name.span,
                format!(
                    "method `{}` overrides `{owner_name}.{}`{why} (§7.3.7.2)",
                    md.name.text, md.name.text
                ),
            )
            .with(prior.span, "overridden method"),
        );
    };
    if !md.only {
        // The same type's second declaration without `only` is "declared twice" (collect.rs).
        if owner != id {
            report(
                diags,
                ": an overriding method is written `is only …`".to_string(),
            );
        }
        return;
    }
    let mut scratch = Vec::new();
    let params: Vec<Ty> = md
        .params
        .iter()
        .map(|p| super::collect::resolve_type(m, &p.ty, &mut scratch))
        .collect();
    let ret = md
        .ret
        .as_ref()
        .map(|t| super::collect::resolve_type(m, t, &mut scratch));
    let show = |t: &Option<Ty>| t.as_ref().map_or("nothing".to_string(), |t| m.type_name(t));
    let prior_params: Vec<Ty> = prior.params.iter().map(|p| p.ty.clone()).collect();
    let what = if ret != prior.ret {
        format!("returns {} instead of {}", show(&ret), show(&prior.ret))
    } else if params != prior_params {
        let list = |ts: &[Ty]| {
            ts.iter()
                .map(|t| m.type_name(t))
                .collect::<Vec<_>>()
                .join(", ")
        };
        format!(
            "takes ({}) instead of ({})",
            list(&params),
            list(&prior_params)
        )
    } else {
        return;
    };
    if params.contains(&Ty::Error) || ret == Some(Ty::Error) {
        return;
    }
    report(
        diags,
        format!(" but {what}: an overriding method keeps the signature"),
    );
}

/// §7.3.8.1: "scenarios and actions belonging to an actor must only inherit from a scenario or
/// action belonging to an actor of the same type, or an actor of a more general type, and
/// scenarios and actions not belonging to an actor must only inherit from a scenario or action
/// not belonging to an actor".
fn behavior_parent(m: &Model, id: CompoundId, diags: &mut Vec<Diagnostic>) {
    let c = m.compound(id);
    if matches!(
        c.kind,
        CompoundKind::Struct | CompoundKind::Actor | CompoundKind::Modifier
    ) {
        return;
    }
    let Some(p) = c.parent else { return };
    let parent = m.compound(p);
    let why = match (c.actor, parent.actor) {
        (Some(a), Some(b)) if !m.is_subtype(a, b) => format!(
            "its actor `{}` is not `{}` nor inherits from it",
            m.compound(a).name,
            m.compound(b).name
        ),
        (Some(_), None) => format!("`{}` belongs to no actor", parent.name),
        (None, Some(_)) => format!(
            "`{}` belongs to an actor and `{}` to none",
            parent.name, c.name
        ),
        _ => return,
    };
    diags.push(
        Diagnostic::new(
            K::Inheritance,
            c.span,
            format!(
                "{} `{}` cannot inherit `{}`: {why} (§7.3.8.1)",
                c.kind.keyword(),
                c.name,
                parent.name
            ),
        )
        .with(parent.span, "parent declared here"),
    );
}

/// §7.3.8.2: a conditional subtype depends "upon a value of a Boolean or enumerated field in the
/// base type".
fn condition_field(m: &Model, id: CompoundId, diags: &mut Vec<Diagnostic>) {
    let c = m.compound(id);
    let (Some(cond), Some(parent)) = (&c.condition, c.parent) else {
        return;
    };
    let ExprKind::Binary(BinOp::Eq, field, _) = &cond.kind else {
        return;
    };
    let ExprKind::Name(name) = &field.kind else {
        return;
    };
    let Some(f) = m.field(parent, name) else {
        return; // unknown: the checker reports it
    };
    if matches!(f.ty, Ty::Bool | Ty::Enum(_) | Ty::Error) {
        return;
    }
    diags.push(Diagnostic::new(
        K::Inheritance,
        field.span,
        format!(
            "conditional inheritance depends on a bool or enum field (§7.3.8.2), and `{name}` is {}",
            m.type_name(&f.ty)
        ),
    ));
}

/// §7.7.4.2 rule 1: "For types, events, units, enumeration values, labels, and fields, the place
/// of their definition is always considered a place of initial definition for their identifier":
/// an enum member and an actor of one namespace cannot share a name (issue 30). Structs, enums
/// and physical types are let be: the domain model itself names the members of
/// `connect_route_points` (§8.12.29) after the structs `road`, `lane_section`, `lane` and
/// `crossing` of its own namespace (§8.12.8–§8.12.11).
fn enum_members_and_types(m: &Model, diags: &mut Vec<Diagnostic>) {
    let namespace = |key: &str| key.rsplit_once("::").map_or("", |(ns, _)| ns).to_string();
    for e in m.enums.iter().filter(|e| e.span.file.0 >= m.library_files) {
        let ns = namespace(&e.name);
        for member in &e.members {
            let key = if ns.is_empty() {
                member.clone()
            } else {
                format!("{ns}::{member}")
            };
            let Some((TypeName::Compound(c), span)) = m.types.get(&key) else {
                continue;
            };
            if span.file.0 < m.library_files || m.compound(*c).kind != CompoundKind::Actor {
                continue;
            }
            let place = if ns.is_empty() {
                "the global namespace".to_string()
            } else {
                format!("namespace `{ns}`")
            };
            diags.push(
                Diagnostic::new(
                    K::Duplicate,
                    *span,
                    format!(
                        "`{member}` is a member of enum `{}` and the name of actor `{key}` in {place}: both are identifiers of the namespace (§7.7.4.2)",
                        e.name
                    ),
                )
                .with(e.span, "enum declared here"),
            );
        }
    }
}

/// A member's value naming another member takes that member's value: the reference names a
/// member, and following references never comes back to the member it started from.
fn enum_references(m: &Model, diags: &mut Vec<Diagnostic>) {
    type Node<'a> = (usize, &'a str);
    // Each member with a reference: the member it names, the member's name and the value.
    let mut edges: BTreeMap<Node, (Node, &Name, &Expr)> = BTreeMap::new();
    for (i, e) in m.enums.iter().enumerate() {
        for (member, value) in &e.references {
            let own = member.span.file.0 >= m.library_files;
            let (target, shown) = match &value.kind {
                ExprKind::Name(n) => ((i, n.as_str()), format!("`{}`", e.name)),
                ExprKind::EnumValue(q, n) => match m.types.get(&q.text()) {
                    Some((TypeName::Enum(t), _)) => (
                        (t.0 as usize, n.text.as_str()),
                        format!("`{}`", m.enum_def(*t).name),
                    ),
                    _ => {
                        if own {
                            diags.push(Diagnostic::new(
                                K::UnknownName,
                                q.span,
                                format!("unknown enum `{}`", q.text()),
                            ));
                        }
                        continue;
                    }
                },
                _ => continue,
            };
            if !m.enums[target.0].members.iter().any(|x| x == target.1) {
                if own {
                    diags.push(Diagnostic::new(
                        K::UnknownName,
                        value.span,
                        format!(
                            "enum {shown} has no member `{}` for `{}` to take its value from",
                            target.1, member.text
                        ),
                    ));
                }
                continue;
            }
            edges.insert((i, member.text.as_str()), (target, member, value));
        }
    }
    let written = |value: &Expr| match &value.kind {
        ExprKind::EnumValue(q, n) => format!("{}!{}", q.text(), n.text),
        ExprKind::Name(n) => n.clone(),
        _ => String::new(),
    };
    let mut reported: BTreeSet<Node> = BTreeSet::new();
    for &start in edges.keys() {
        if reported.contains(&start) {
            continue;
        }
        // One reference per member: follow them until they end, loop back to `start`, or
        // enter a loop that `start` is not part of (found from one of its own members).
        let mut path = vec![start];
        let mut cur = edges[&start].0;
        let closed = loop {
            if cur == start {
                break true;
            }
            if path.contains(&cur) {
                break false;
            }
            let Some(next) = edges.get(&cur) else {
                break false;
            };
            path.push(cur);
            cur = next.0;
        };
        if !closed {
            continue;
        }
        reported.extend(path.iter().copied());
        // Reported at the member written first; the cycle listed from it.
        let first = (0..path.len())
            .min_by_key(|&k| {
                let span = edges[&path[k]].1.span;
                (span.file.0, span.start)
            })
            .unwrap_or(0); // `path` holds `start`: never empty
        path.rotate_left(first);
        let (_, member, _) = edges[&path[0]];
        if member.span.file.0 < m.library_files {
            continue;
        }
        let chain: Vec<String> = path
            .iter()
            .map(|node| {
                let (_, member, value) = edges[node];
                format!("`{} = {}`", member.text, written(value))
            })
            .collect();
        diags.push(Diagnostic::new(
            K::Recursion,
            member.span,
            format!(
                "enum member values refer to each other in a cycle, so none of them has a value: {} (enum-member-value ::= uint-literal | hex-uint-literal | enum-value-reference)",
                chain.join(", ")
            ),
        ));
    }
}
