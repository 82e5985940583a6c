//! Namespace resolution (ASAM OpenSCENARIO DSL 2.1 §7.7.3–§7.7.4, "Namespaces", "The
//! namespace statement", "Resolution rules for unprefixed identifiers"): every top-level name
//! is rewritten to its explicitly qualified form before declarations are collected, so the
//! later passes see one name per declaration (`foo::bar`; the global `null` namespace's names
//! stay bare: `bar`).
//!
//! The rules, as the standard gives them:
//! - a file starts in the `null` namespace; `namespace X [use A, B]` switches the active
//!   namespace and its use list up to the next namespace statement or the end of the file;
//! - a declaration puts its identifier into the active namespace unless it is written with a
//!   prefix (`struct foo::bar`);
//! - `ns::name` names `name` of `ns`; `::name` and `null::name` the global namespace's;
//! - an unprefixed name is the active namespace's if it declares one (it shadows the used
//!   namespaces), else the one name the used namespaces export; two different ones are an
//!   error (ambiguous);
//! - `export a, ns::b, *, ns::*` puts names on the active namespace's export list (`*`: every
//!   name the namespace holds, wherever declared); an exported name is still the original.
//!
//! What oscsim decides where the standard leaves it to the implementation:
//! - the standard library (§7.7.5.2) is reachable from every namespace unprefixed, behind the
//!   active and used namespaces (an own `vehicle` shadows it), and as `std::name` or
//!   `stdtypes::name`: oscsim provides it by built-in declarations, which the standard allows;
//! - namespaces apply to the names of physical types, enums, structs, actors, actor-less
//!   scenarios, actions and modifiers, and global parameters. Members (fields, methods,
//!   events, enum members, behaviors declared on an actor) are named within their type and
//!   take no prefix; a prefixed member name is reported as unknown.
//! - an unprefixed name in an expression is rewritten to a namespaced global only where no
//!   field, parameter or loop variable of that name is declared in the enclosing declaration
//!   (the members shadow globals, as in the checker).

use std::collections::{BTreeMap, BTreeSet};

use super::diagnostic::{Diagnostic, DiagnosticKind};
use super::hir::*;

/// Where a name is looked up: the active namespace and its use list.
#[derive(Debug, Clone, Default)]
struct Scope {
    active: String,
    uses: Vec<String>,
}

/// Declared and exported names per namespace.
#[derive(Debug, Default)]
struct Table {
    /// Namespace → its identifiers.
    declared: BTreeMap<String, BTreeSet<String>>,
    /// Namespace → qualified keys on its export list.
    exports: BTreeMap<String, BTreeSet<String>>,
    /// Names the standard library declares (global namespace, library files).
    library: BTreeSet<String>,
}

/// Why a name has no key.
enum Unresolved {
    /// No namespace in reach declares it: left for the checker, which names the kind of
    /// declaration it expected ("unknown type `x`").
    Unknown,
    /// A reason worth its own message (ambiguous, not exported, unknown namespace).
    Explained(String),
}

impl Unresolved {
    fn message(self, text: &str) -> String {
        match self {
            Unresolved::Unknown => format!("unknown name `{text}`"),
            Unresolved::Explained(m) => m,
        }
    }
}

/// The key of `name` in namespace `ns`: `ns::name`, or `name` for the global namespace.
fn key(ns: &str, name: &str) -> String {
    if ns.is_empty() {
        name.to_string()
    } else {
        format!("{ns}::{name}")
    }
}

/// `(prefix, name)` of a name as written; the prefix of `::x` is `""`.
fn split(text: &str) -> (Option<&str>, &str) {
    match text.rfind("::") {
        Some(i) => (Some(&text[..i]), &text[i + 2..]),
        None => (None, text),
    }
}

impl Table {
    fn holds(&self, ns: &str, name: &str) -> bool {
        self.declared.get(ns).is_some_and(|s| s.contains(name))
    }

    /// The key `text` names from `scope`, or why none.
    fn resolve(&self, scope: &Scope, text: &str) -> Result<String, Unresolved> {
        let (prefix, name) = split(text);
        if let Some(ns) = prefix {
            if self.holds(ns, name) {
                return Ok(key(ns, name));
            }
            if (ns == "std" || ns == "stdtypes") && self.library.contains(name) {
                return Ok(name.to_string());
            }
            return Err(Unresolved::Explained(if ns.is_empty() {
                format!("the global namespace declares no `{name}`")
            } else if self.declared.contains_key(ns) {
                format!("namespace `{ns}` declares no `{name}`")
            } else {
                format!("unknown namespace `{ns}`")
            }));
        }
        if self.holds(&scope.active, name) {
            return Ok(key(&scope.active, name));
        }
        let mut found: BTreeSet<String> = BTreeSet::new();
        for u in &scope.uses {
            if let Some(list) = self.exports.get(u) {
                found.extend(list.iter().filter(|k| split(k).1 == name).cloned());
            }
        }
        match found.len() {
            1 => Ok(found.into_iter().next().unwrap_or_default()),
            0 if self.library.contains(name) => Ok(name.to_string()),
            0 => match scope.uses.iter().find(|u| self.holds(u, name)) {
                Some(u) => Err(Unresolved::Explained(format!(
                    "`{name}` is declared in namespace `{u}`, which does not export it; write `{}`",
                    key(u, name)
                ))),
                None => Err(Unresolved::Unknown),
            },
            _ => Err(Unresolved::Explained(format!(
                "`{name}` is ambiguous: the used namespaces export {}",
                found
                    .iter()
                    .map(|k| format!("`{k}`"))
                    .collect::<Vec<_>>()
                    .join(" and ")
            ))),
        }
    }
}

/// Rewrites the top-level names of `files` (files `0..library` are the standard library) to
/// their qualified keys, pushing a diagnostic for each name that cannot be resolved.
pub fn resolve_namespaces(files: &mut [SourceFile], library: usize, diags: &mut Vec<Diagnostic>) {
    let mut t = Table::default();
    // 1. Declarations.
    for (i, f) in files.iter_mut().enumerate() {
        let mut active = String::new();
        for item in &mut f.items {
            if let Item::Namespace { name, .. } = item {
                active = name.clone();
                continue;
            }
            for n in declared_names(item) {
                let (ns, name) = match split(&n.text) {
                    (Some(p), name) => (p.to_string(), name.to_string()),
                    (None, name) => (active.clone(), name.to_string()),
                };
                if i < library {
                    t.library.insert(name.clone());
                }
                t.declared
                    .entry(ns.clone())
                    .or_default()
                    .insert(name.clone());
                n.text = key(&ns, &name);
            }
        }
    }
    // 2. Export lists; re-exports through used namespaces settle in a few rounds.
    let exports: Vec<(Scope, ExportSpec)> = files
        .iter()
        .flat_map(|f| {
            scoped(f).filter_map(|(s, item)| match item {
                Item::Export { specs, .. } => {
                    Some(specs.iter().map(move |x| (s.clone(), x.clone())))
                }
                _ => None,
            })
        })
        .flatten()
        .collect();
    let mut unresolved: Vec<(Span, String)> = Vec::new();
    for _round in 0..=exports.len() {
        let before: usize = t.exports.values().map(BTreeSet::len).sum();
        unresolved.clear();
        for (scope, spec) in &exports {
            let keys: Vec<String> = match spec {
                ExportSpec::Wildcard(ns, _) => {
                    let ns = ns.clone().unwrap_or_else(|| scope.active.clone());
                    let names = t.declared.get(&ns).cloned().unwrap_or_default();
                    names.iter().map(|n| key(&ns, n)).collect()
                }
                ExportSpec::Name(n) => match t.resolve(scope, &n.text) {
                    Ok(k) => vec![k],
                    Err(e) => {
                        unresolved.push((n.span, e.message(&n.text)));
                        continue;
                    }
                },
            };
            t.exports
                .entry(scope.active.clone())
                .or_default()
                .extend(keys);
        }
        if t.exports.values().map(BTreeSet::len).sum::<usize>() == before {
            break;
        }
    }
    for (span, e) in unresolved {
        diags.push(Diagnostic::new(
            DiagnosticKind::UnknownName,
            span,
            format!("cannot export: {e}"),
        ));
    }
    // 3. References.
    for f in files.iter_mut() {
        let mut scope = Scope::default();
        for item in &mut f.items {
            if let Item::Namespace { name, uses, .. } = item {
                scope = Scope {
                    active: name.clone(),
                    uses: uses.iter().map(|u| u.text.clone()).collect(),
                };
                continue;
            }
            let mut r = Rewriter {
                t: &t,
                scope: &scope,
                diags,
                shadow: BTreeSet::new(),
            };
            r.item(item);
        }
    }
}

/// The items of a file with the scope each stands in.
fn scoped(f: &SourceFile) -> impl Iterator<Item = (Scope, &Item)> {
    let mut scope = Scope::default();
    f.items.iter().map(move |item| {
        if let Item::Namespace { name, uses, .. } = item {
            scope = Scope {
                active: name.clone(),
                uses: uses.iter().map(|u| u.text.clone()).collect(),
            };
        }
        (scope.clone(), item)
    })
}

/// The names an item declares at top level.
fn declared_names(item: &mut Item) -> Vec<&mut Name> {
    match item {
        Item::PhysicalType { name, .. } | Item::Enum { name, .. } => vec![name],
        Item::Compound(c) if c.name.parts.len() == 1 => c.name.parts.iter_mut().collect(),
        Item::Global(f) | Item::Member(Member::Field(f)) => f.names.iter_mut().collect(),
        _ => Vec::new(),
    }
}

struct Rewriter<'a> {
    t: &'a Table,
    scope: &'a Scope,
    diags: &'a mut Vec<Diagnostic>,
    /// Member names of the enclosing declaration (they shadow globals).
    shadow: BTreeSet<String>,
}

impl Rewriter<'_> {
    /// Rewrites a name that must be a top-level one.
    fn top(&mut self, n: &mut Name) {
        match self.t.resolve(self.scope, &n.text) {
            Ok(k) => n.text = k,
            // Left for the checker, which reports an unknown name in its own words.
            Err(Unresolved::Unknown) => {}
            // The checker's "unknown …" at the same place is dropped (program.rs).
            Err(Unresolved::Explained(e)) => {
                self.diags
                    .push(Diagnostic::new(DiagnosticKind::UnknownName, n.span, e));
            }
        }
    }

    /// The first part of a type or behavior name (`T`, `actor.behavior`).
    fn qual(&mut self, q: &mut QualName) {
        if let Some(first) = q.parts.first_mut() {
            self.top(first);
        }
    }

    fn ty(&mut self, t: &mut TypeRef) {
        match t {
            TypeRef::Primitive(_) => {}
            TypeRef::Named(q) => self.qual(q),
            TypeRef::List(inner, _) | TypeRef::Range(inner, _) => self.ty(inner),
        }
    }

    fn item(&mut self, item: &mut Item) {
        match item {
            Item::Namespace { .. } | Item::Export { .. } | Item::Import { .. } => {}
            Item::PhysicalType { si, .. } => si.iter_mut().for_each(|a| self.expr(&mut a.value)),
            Item::Unit { of, si, .. } => {
                self.qual(of);
                si.iter_mut().for_each(|a| self.expr(&mut a.value));
            }
            Item::Enum { .. } => {}
            Item::EnumExtension { name, .. } => self.qual(name),
            Item::Compound(c) => {
                if c.name.parts.len() > 1 {
                    self.qual(&mut c.name);
                }
                if let Some(of) = &mut c.of {
                    self.qual(of);
                }
                if let Some(inh) = &mut c.inherits {
                    self.qual(&mut inh.parent);
                    if let Some(cond) = &mut inh.condition {
                        self.expr(cond);
                    }
                }
                self.members(&mut c.members);
            }
            Item::Extend {
                target, members, ..
            } => {
                self.qual(target);
                self.members(members);
            }
            Item::Global(f) => self.field(f),
            Item::Member(m) => self.members(std::slice::from_mut(m)),
        }
    }

    fn members(&mut self, members: &mut [Member]) {
        let saved = self.shadow.clone();
        for m in members.iter() {
            match m {
                Member::Field(f) => self.shadow.extend(f.names.iter().map(|n| n.text.clone())),
                Member::Method(md) => self
                    .shadow
                    .extend(md.params.iter().map(|p| p.name.text.clone())),
                Member::For { var, .. } => {
                    self.shadow.insert(var.text.clone());
                }
                _ => {}
            }
        }
        for m in members {
            self.member(m);
        }
        self.shadow = saved;
    }

    fn field(&mut self, f: &mut FieldDecl) {
        self.ty(&mut f.ty);
        if let Some(d) = &mut f.default {
            self.expr(d);
        }
        f.keeps.iter_mut().for_each(|k| self.expr(&mut k.expr));
    }

    fn member(&mut self, m: &mut Member) {
        match m {
            Member::Field(f) => self.field(f),
            Member::Keep(k) => self.expr(&mut k.expr),
            Member::RemoveDefault(e, _) => self.expr(e),
            Member::On(e, body, _) => {
                self.expr(e);
                body.iter_mut().for_each(|l| self.labeled(l));
            }
            Member::For { list, body, .. } => {
                self.expr(list);
                self.members(body);
            }
            Member::Method(md) => {
                for p in &mut md.params {
                    self.ty(&mut p.ty);
                    if let Some(d) = &mut p.default {
                        self.expr(d);
                    }
                }
                if let Some(r) = &mut md.ret {
                    self.ty(r);
                }
                if let MethodBody::Expression(e) = &mut md.body {
                    self.expr(e);
                }
            }
            Member::Event(ev) => {
                if let Some(e) = &mut ev.spec {
                    self.expr(e);
                }
            }
            Member::Modifier(app) => self.modifier(app),
            Member::Do(l, _) => self.labeled(l),
            Member::Coverage(args, _) => self.args(args),
        }
    }

    fn modifier(&mut self, app: &mut ModifierApp) {
        if let Some(t) = &mut app.target {
            self.expr(t);
        }
        self.args(&mut app.args);
    }

    fn labeled(&mut self, l: &mut Labeled) {
        match &mut l.behavior {
            Behavior::Composition { args, children, .. } => {
                self.args(args);
                children.iter_mut().for_each(|c| self.labeled(c));
            }
            Behavior::Invocation {
                actor,
                name,
                args,
                with,
                ..
            } => {
                match actor {
                    Some(a) => self.expr(a),
                    // An actor-less invocation names a top-level scenario or action.
                    None => self.top(name),
                }
                self.args(args);
                for w in with {
                    match w {
                        WithMember::Modifier(app) => self.modifier(app),
                        WithMember::Keep(k) => self.expr(&mut k.expr),
                        WithMember::Until(e, _) => self.expr(e),
                    }
                }
            }
            Behavior::Wait(e, _) | Behavior::Call(e, _) => self.expr(e),
            Behavior::Emit(_, args, _) => self.args(args),
        }
    }

    fn args(&mut self, args: &mut [Arg]) {
        args.iter_mut().for_each(|a| self.expr(&mut a.value));
    }

    fn expr(&mut self, e: &mut Expr) {
        match &mut e.kind {
            ExprKind::Name(text) => {
                if text.contains("::") {
                    let mut n = Name {
                        text: text.clone(),
                        span: e.span,
                    };
                    self.top(&mut n);
                    *text = n.text;
                } else if !self.shadow.contains(text.as_str()) {
                    if let Ok(k) = self.t.resolve(self.scope, text) {
                        *text = k;
                    }
                }
            }
            ExprKind::EnumValue(ty, _) => self.qual(ty),
            ExprKind::Field(inner, _) | ExprKind::Neg(inner) | ExprKind::Not(inner) => {
                self.expr(inner)
            }
            ExprKind::Index(a, b) | ExprKind::Binary(_, a, b) | ExprKind::Range(a, b) => {
                self.expr(a);
                self.expr(b);
            }
            ExprKind::Call(f, args) => {
                self.expr(f);
                self.args(args);
            }
            ExprKind::Ternary(a, b, c) => {
                self.expr(a);
                self.expr(b);
                self.expr(c);
            }
            ExprKind::List(xs) => xs.iter_mut().for_each(|x| self.expr(x)),
            ExprKind::Cast(inner, t) | ExprKind::TypeTest(inner, t) => {
                self.expr(inner);
                self.ty(t);
            }
            ExprKind::Temporal(_, args) => self.args(args),
            ExprKind::Int(_)
            | ExprKind::Float(_)
            | ExprKind::Physical(..)
            | ExprKind::Bool(_)
            | ExprKind::Str(_)
            | ExprKind::It
            | ExprKind::Error => {}
        }
    }
}
