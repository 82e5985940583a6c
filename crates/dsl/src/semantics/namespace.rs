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
//! - the standard library (§7.7.5.2) resides in `stdtypes` (the sub-module `types`: physical
//!   types, units, basic structs) and `std` (the rest, §8.1.3). It is reachable from every
//!   namespace unprefixed, behind the active and used namespaces, with or without an import,
//!   and as `std::name` / `stdtypes::name`. A file's own declaration of a library name in the
//!   global namespace is another identifier and shadows the library's (§7.7.4.2 rule 2): the
//!   library's then takes the key `std::name` (or `stdtypes::name`) and the library's own
//!   references go on naming it. Shadowing is per class of table (type, behavior, global,
//!   unit): a file's `type speed` does not hide the library's modifier `speed`. oscsim
//!   provides the library by built-in declarations, which the standard allows;
//! - a file's own units are not namespaced (one program-wide table); they shadow the library's;
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
    /// A file of the standard library: its names are the library's.
    library: bool,
}

/// The table a top-level name goes into. A library declaration is shadowed only by a file's
/// own declaration of the same class: a file's `type speed` hides the library's physical type
/// `speed`, not its modifier `speed`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Class {
    /// Physical types, enums, structs, actors.
    Type,
    /// Actor-less scenarios, actions and modifiers.
    Behavior,
    /// Global parameters and top-level fields.
    Global,
    /// Units (a file's own units are not namespaced: one table for the program).
    Unit,
}

/// A declaration of the standard library.
#[derive(Debug, Clone)]
struct LibraryName {
    /// Its key: the bare name, or `std::name` / `stdtypes::name` where a file of the program
    /// declares the same name in the global namespace.
    key: String,
    /// Its namespace: `std` or `stdtypes` (§8.1.3: the `types` sub-module's in `stdtypes`,
    /// the rest in `std`).
    namespace: &'static str,
}

/// Declared and exported names per namespace.
#[derive(Debug, Default)]
struct Table {
    /// Namespace → its identifiers (the program's files, not the library).
    declared: BTreeMap<String, BTreeSet<String>>,
    /// Namespace → qualified keys on its export list.
    exports: BTreeMap<String, BTreeSet<String>>,
    /// The standard library's declarations by class and name.
    library: BTreeMap<(Class, String), LibraryName>,
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

    /// The key `text` names as a name of any class (an `export` names any kind).
    fn resolve_any(&self, scope: &Scope, text: &str) -> Result<String, Unresolved> {
        let mut first = None;
        for class in [Class::Type, Class::Behavior, Class::Global] {
            match self.resolve(scope, text, class) {
                Ok(k) => return Ok(k),
                Err(e) => {
                    first.get_or_insert(e);
                }
            }
        }
        Err(first.unwrap_or(Unresolved::Unknown))
    }

    /// The library's declaration of `name` in `class`, if the library declares one.
    fn library(&self, class: Class, name: &str) -> Option<&LibraryName> {
        self.library.get(&(class, name.to_string()))
    }

    /// The key `text` names from `scope` as a name of `class`, or why none.
    fn resolve(&self, scope: &Scope, text: &str, class: Class) -> Result<String, Unresolved> {
        let (prefix, name) = split(text);
        if scope.library {
            // The library's own references never reach a file's declarations.
            return match self.library(class, name) {
                Some(l) if prefix.is_none_or(|p| p == l.namespace) => Ok(l.key.clone()),
                _ => Err(Unresolved::Unknown),
            };
        }
        if let Some(ns) = prefix {
            if self.holds(ns, name) {
                return Ok(key(ns, name));
            }
            if let Some(l) = self.library(class, name) {
                // `std::vehicle`, `stdtypes::length`; the bare library stands in the global
                // namespace where nothing of the program shadows it (`::vehicle`).
                if ns == l.namespace || (ns.is_empty() && l.key == name) {
                    return Ok(l.key.clone());
                }
                if ns == "std" || ns == "stdtypes" {
                    return Err(Unresolved::Explained(format!(
                        "namespace `{ns}` declares no `{name}`; the standard library puts it in `{}`",
                        l.namespace
                    )));
                }
            }
            return Err(Unresolved::Explained(if ns.is_empty() {
                format!("the global namespace declares no `{name}`")
            } else if self.declared.contains_key(ns) || ns == "std" || ns == "stdtypes" {
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
            // A used `std` / `stdtypes` makes the library's names of that namespace
            // accessible (§7.7.5.2.1).
            if let Some(l) = self.library(class, name).filter(|l| l.namespace == u) {
                found.insert(l.key.clone());
            }
        }
        match found.len() {
            1 => Ok(found.into_iter().next().unwrap_or_default()),
            // oscsim: the library stands behind every namespace (docs/dsl.md, "Namespaces").
            0 if self.library(class, name).is_some() => Ok(self
                .library(class, name)
                .map(|l| l.key.clone())
                .unwrap_or_default()),
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

/// Rewrites the top-level names of `files` to their qualified keys, pushing a diagnostic for
/// each name that cannot be resolved. Files `0..library.len()` are the standard library,
/// `library[i]` the namespace of file `i` (`std` or `stdtypes`).
pub fn resolve_namespaces(
    files: &mut [SourceFile],
    library: &[&'static str],
    diags: &mut Vec<Diagnostic>,
) {
    let mut t = Table::default();
    // 1. Declarations: the program's files first, so the library knows what they shadow.
    let (lib_files, own_files) = files.split_at_mut(library.len().min(files.len()));
    let mut shadowed: BTreeSet<(Class, String)> = BTreeSet::new();
    for f in own_files.iter_mut() {
        let mut active = String::new();
        for item in &mut f.items {
            if let Item::Namespace { name, .. } = item {
                active = name.clone();
                continue;
            }
            for (n, class) in declared_names(item) {
                let (ns, name) = match split(&n.text) {
                    (Some(p), name) => (p.to_string(), name.to_string()),
                    (None, name) => (active.clone(), name.to_string()),
                };
                // A file's units stay in one program-wide table (not namespaced).
                if class == Class::Unit || ns.is_empty() {
                    shadowed.insert((class, name.clone()));
                }
                if class == Class::Unit {
                    continue;
                }
                t.declared
                    .entry(ns.clone())
                    .or_default()
                    .insert(name.clone());
                n.text = key(&ns, &name);
            }
        }
    }
    for (f, namespace) in lib_files.iter_mut().zip(library) {
        for item in &mut f.items {
            for (n, class) in declared_names(item) {
                let name = n.text.clone();
                let own = shadowed.contains(&(class, name.clone()));
                n.text = if own {
                    key(namespace, &name)
                } else {
                    name.clone()
                };
                t.library.insert(
                    (class, name),
                    LibraryName {
                        key: n.text.clone(),
                        namespace,
                    },
                );
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
                ExportSpec::Name(n) => match t.resolve_any(scope, &n.text) {
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
    for (i, f) in files.iter_mut().enumerate() {
        let mut scope = Scope {
            library: i < library.len(),
            ..Scope::default()
        };
        for item in &mut f.items {
            if let Item::Namespace { name, uses, .. } = item {
                scope = Scope {
                    active: name.clone(),
                    uses: uses.iter().map(|u| u.text.clone()).collect(),
                    library: scope.library,
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
                library: false,
            };
        }
        (scope.clone(), item)
    })
}

/// The names an item declares at top level, each with its class.
fn declared_names(item: &mut Item) -> Vec<(&mut Name, Class)> {
    match item {
        Item::PhysicalType { name, .. } | Item::Enum { name, .. } => vec![(name, Class::Type)],
        Item::Unit { name, .. } => vec![(name, Class::Unit)],
        Item::Compound(c) if c.name.parts.len() == 1 => {
            let class = match c.kind {
                CompoundKind::Struct | CompoundKind::Actor => Class::Type,
                _ => Class::Behavior,
            };
            c.name.parts.iter_mut().map(|n| (n, class)).collect()
        }
        Item::Global(f) | Item::Member(Member::Field(f)) => {
            f.names.iter_mut().map(|n| (n, Class::Global)).collect()
        }
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
    /// Rewrites a name that must be a top-level one of `class`.
    fn top(&mut self, n: &mut Name, class: Class) {
        match self.t.resolve(self.scope, &n.text, class) {
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

    /// The first part of a type or behavior name (`T`, `actor.behavior`): a name of `class`
    /// when it stands alone, else an actor's (a type).
    fn qual(&mut self, q: &mut QualName, class: Class) {
        let class = if q.parts.len() > 1 {
            Class::Type
        } else {
            class
        };
        if let Some(first) = q.parts.first_mut() {
            self.top(first, class);
        }
    }

    fn ty(&mut self, t: &mut TypeRef) {
        match t {
            TypeRef::Primitive(_) => {}
            TypeRef::Named(q) => self.qual(q, Class::Type),
            TypeRef::List(inner, _) | TypeRef::Range(inner, _) => self.ty(inner),
        }
    }

    fn item(&mut self, item: &mut Item) {
        match item {
            Item::Namespace { .. } | Item::Export { .. } | Item::Import { .. } => {}
            Item::PhysicalType { si, .. } => si.iter_mut().for_each(|a| self.expr(&mut a.value)),
            Item::Unit { of, si, .. } => {
                self.qual(of, Class::Type);
                si.iter_mut().for_each(|a| self.expr(&mut a.value));
            }
            Item::Enum { references, .. } => self.enum_references(references),
            Item::EnumExtension {
                name, references, ..
            } => {
                self.qual(name, Class::Type);
                self.enum_references(references);
            }
            Item::Compound(c) => {
                if c.name.parts.len() > 1 {
                    self.qual(&mut c.name, Class::Type);
                }
                if let Some(of) = &mut c.of {
                    self.qual(of, Class::Behavior);
                }
                if let Some(inh) = &mut c.inherits {
                    let class = match c.kind {
                        CompoundKind::Struct | CompoundKind::Actor => Class::Type,
                        _ => Class::Behavior,
                    };
                    self.qual(&mut inh.parent, class);
                    if let Some(cond) = &mut inh.condition {
                        self.expr(cond);
                    }
                }
                self.members(&mut c.members);
            }
            Item::Extend {
                target, members, ..
            } => {
                self.qual(target, Class::Type);
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
            Member::Coverage(_, args, _) => self.args(args),
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
            Behavior::Composition {
                args,
                children,
                with,
                ..
            } => {
                self.args(args);
                children.iter_mut().for_each(|c| self.labeled(c));
                self.with_members(with);
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
                    None => self.top(name, Class::Behavior),
                }
                self.args(args);
                self.with_members(with);
            }
            Behavior::Wait(e, _) | Behavior::Call(e, _) => self.expr(e),
            Behavior::Emit(_, args, _) => self.args(args),
        }
    }

    /// `a = colors!b` names the enum `colors` like a type; a bare `a = b` is a member of the
    /// enum being declared, not a global.
    fn enum_references(&mut self, references: &mut [(Name, Expr)]) {
        for (_, e) in references {
            if let ExprKind::EnumValue(ty, _) = &mut e.kind {
                self.qual(ty, Class::Type);
            }
        }
    }

    fn with_members(&mut self, with: &mut [WithMember]) {
        for w in with {
            match w {
                WithMember::Modifier(app) => self.modifier(app),
                WithMember::Keep(k) => self.expr(&mut k.expr),
                WithMember::Until(e, _) => self.expr(e),
            }
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
                    self.top(&mut n, Class::Global);
                    *text = n.text;
                } else if !self.shadow.contains(text.as_str()) {
                    if let Ok(k) = self.t.resolve(self.scope, text, Class::Global) {
                        *text = k;
                    }
                }
            }
            ExprKind::Physical(_, unit) if self.scope.library => {
                if let Some(l) = self.t.library(Class::Unit, &unit.text) {
                    unit.text = l.key.clone();
                }
            }
            ExprKind::EnumValue(ty, _) => self.qual(ty, Class::Type),
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
