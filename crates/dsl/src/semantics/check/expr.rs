//! Expression typing (ASAM OpenSCENARIO DSL 2.1 §7.4): names, fields, indexing, method calls
//! with named and positional arguments, arithmetic with physical units, comparisons, enum
//! members (resolved from the type the other operand expects), `in` lists and ranges.

use super::super::diagnostic::{Diagnostic, DiagnosticKind as K};
use super::super::hir::{op_text, Arg, BinOp, Expr, ExprKind, Span};
use super::super::model::ParamDef;
use super::super::types::Ty;
use super::{Cx, Place, Scope, Seg, TExpr, TKind};

impl Cx<'_> {
    pub(crate) fn err(&mut self, kind: K, span: Span, msg: impl Into<String>) {
        self.out.diags.push(Diagnostic::new(kind, span, msg));
    }

    pub(crate) fn opaque(&self, ty: Ty, span: Span, why: &'static str) -> TExpr {
        TExpr {
            kind: TKind::Opaque(why),
            ty,
            span,
        }
    }

    fn error_expr(&self, span: Span) -> TExpr {
        self.opaque(Ty::Error, span, "error")
    }

    /// Whether a value of `actual` may stand where `expected` is wanted.
    pub(crate) fn assignable(&self, expected: &Ty, actual: &Ty) -> bool {
        match (expected, actual) {
            (Ty::Error, _) | (_, Ty::Error) => true,
            (Ty::Float, Ty::Int | Ty::Uint) | (Ty::Int, Ty::Uint) | (Ty::Uint, Ty::Int) => true,
            (Ty::Compound(sup), Ty::Compound(sub)) => self.model.is_subtype(*sub, *sup),
            (Ty::List(a), Ty::List(b)) | (Ty::Range(a), Ty::Range(b)) => self.assignable(a, b),
            (Ty::Bool, Ty::Event) | (Ty::Event, Ty::Bool) => true,
            (a, b) => a == b,
        }
    }

    /// Checks `e` where a `expected` is wanted, reporting a mismatch.
    pub(crate) fn expect(&mut self, e: &Expr, expected: &Ty, scope: &Scope, what: &str) -> TExpr {
        let t = self.expr(e, scope, Some(expected));
        if !self.assignable(expected, &t.ty) {
            let (want, found) = (self.model.type_name(expected), self.model.type_name(&t.ty));
            let kind = if matches!(
                (expected, &t.ty),
                (Ty::Physical(_), _) | (_, Ty::Physical(_))
            ) {
                K::Units
            } else {
                K::Type
            };
            self.err(
                kind,
                e.span,
                format!("expected {want} for {what}, found {found}"),
            );
        }
        t
    }

    /// Types an expression; `expected` resolves bare enum members.
    pub(crate) fn expr(&mut self, e: &Expr, scope: &Scope, expected: Option<&Ty>) -> TExpr {
        let span = e.span;
        let mk = |kind, ty| TExpr { kind, ty, span };
        match &e.kind {
            ExprKind::Int(i) => {
                let ty = if *i < 0 {
                    Ty::Int
                } else if matches!(expected, Some(Ty::Float)) {
                    Ty::Float
                } else if matches!(expected, Some(Ty::Int)) {
                    Ty::Int
                } else {
                    Ty::Uint
                };
                mk(TKind::Number(*i as f64), ty)
            }
            ExprKind::Float(f) => mk(TKind::Number(*f), Ty::Float),
            ExprKind::Physical(v, unit) => match self.model.units.unit(&unit.text) {
                Some(u) => mk(TKind::Number(u.to_si(*v)), Ty::Physical(u.dimension)),
                None => {
                    self.err(K::Units, unit.span, format!("unknown unit `{}`", unit.text));
                    self.error_expr(span)
                }
            },
            ExprKind::Bool(b) => mk(TKind::Bool(*b), Ty::Bool),
            ExprKind::Str(s) => mk(TKind::Str(s.clone()), Ty::Str),
            ExprKind::Name(n) => self.name(n, span, scope, expected),
            ExprKind::It => match scope.locals.iter().rev().find(|l| l.name == "it") {
                Some(l) => TExpr {
                    span,
                    ..l.value.clone()
                },
                None => {
                    self.err(K::UnknownName, span, "`it` is not defined here");
                    self.error_expr(span)
                }
            },
            ExprKind::EnumValue(ty, member) => match self.model.types.get(&ty.text()) {
                Some((super::super::model::TypeName::Enum(id), _)) => {
                    let id = *id;
                    match self
                        .model
                        .enum_def(id)
                        .members
                        .iter()
                        .position(|m| *m == member.text)
                    {
                        Some(i) => mk(TKind::Member(id, i as u32), Ty::Enum(id)),
                        None => {
                            let name = self.model.enum_def(id).name.clone();
                            self.err(
                                K::UnknownName,
                                member.span,
                                format!("enum `{name}` has no member `{}`", member.text),
                            );
                            self.error_expr(span)
                        }
                    }
                }
                _ => {
                    self.err(
                        K::UnknownName,
                        ty.span,
                        format!("unknown enum `{}`", ty.text()),
                    );
                    self.error_expr(span)
                }
            },
            ExprKind::Field(base, name) => {
                let b = self.expr(base, scope, None);
                self.field(b, &name.text, name.span, span)
            }
            ExprKind::Index(base, index) => {
                let b = self.expr(base, scope, None);
                let i = self.expect(index, &Ty::Int, scope, "a list index");
                match b.ty.clone() {
                    Ty::List(elem) => match b.kind {
                        TKind::Path(place, mut segs) => {
                            segs.push(Seg::Index(Box::new(i)));
                            mk(TKind::Path(place, segs), *elem)
                        }
                        _ => self.opaque(*elem, span, "element of a computed list"),
                    },
                    Ty::Error => self.error_expr(span),
                    other => {
                        let t = self.model.type_name(&other);
                        self.err(
                            K::Type,
                            base.span,
                            format!("expected a list to index, found {t}"),
                        );
                        self.error_expr(span)
                    }
                }
            }
            ExprKind::Call(callee, args) => self.call(callee, args, scope, span),
            ExprKind::Neg(inner) => {
                let t = self.expr(inner, scope, expected);
                if !t.ty.is_numeric() && t.ty != Ty::Error {
                    let n = self.model.type_name(&t.ty);
                    self.err(
                        K::Type,
                        span,
                        format!("expected a number to negate, found {n}"),
                    );
                }
                let ty = if t.ty == Ty::Uint {
                    Ty::Int
                } else {
                    t.ty.clone()
                };
                mk(TKind::Neg(Box::new(t)), ty)
            }
            ExprKind::Not(inner) => {
                let t = self.expect(inner, &Ty::Bool, scope, "`not`");
                mk(TKind::Not(Box::new(t)), Ty::Bool)
            }
            ExprKind::Binary(op, a, b) => self.binary(*op, a, b, scope, span),
            ExprKind::Ternary(c, a, b) => {
                self.expect(c, &Ty::Bool, scope, "a condition");
                let ta = self.expr(a, scope, expected);
                self.expect(b, &ta.ty.clone(), scope, "the other branch");
                self.opaque(ta.ty, span, "conditional expression")
            }
            ExprKind::List(items) => {
                let want = match expected {
                    Some(Ty::List(t)) => Some((**t).clone()),
                    _ => None,
                };
                let mut out = Vec::new();
                let mut elem: Option<Ty> = want.clone();
                for it in items {
                    let t = match &elem {
                        Some(t) => self.expect(it, &t.clone(), scope, "a list element"),
                        None => self.expr(it, scope, None),
                    };
                    if elem.is_none() && t.ty != Ty::Error {
                        elem = Some(t.ty.clone());
                    }
                    out.push(t);
                }
                mk(
                    TKind::List(out),
                    Ty::List(Box::new(elem.unwrap_or(Ty::Error))),
                )
            }
            ExprKind::Range(lo, hi) => {
                let want = match expected {
                    Some(Ty::Range(t)) => Some((**t).clone()),
                    other => other.cloned(),
                };
                let tl = self.expr(lo, scope, want.as_ref());
                let th = self.expect(hi, &tl.ty.clone(), scope, "the range's upper end");
                if !tl.ty.is_numeric() && tl.ty != Ty::Error {
                    let n = self.model.type_name(&tl.ty);
                    self.err(
                        K::Type,
                        lo.span,
                        format!("expected a number for a range, found {n}"),
                    );
                }
                let ty = Ty::Range(Box::new(tl.ty.clone()));
                mk(TKind::Range(Box::new(tl), Box::new(th)), ty)
            }
            ExprKind::Cast(inner, t) => {
                let x = self.expr(inner, scope, None);
                let ty = super::super::collect::resolve_type(self.model, t, &mut self.out.diags);
                self.convert(x, ty, span)
            }
            ExprKind::TypeTest(inner, t) => {
                let x = self.expr(inner, scope, None);
                let ty = super::super::collect::resolve_type(self.model, t, &mut self.out.diags);
                self.type_test(x, &ty, span)
            }
            ExprKind::Temporal(name, args) => self.temporal(&name.text, args, scope, span),
            ExprKind::Error => self.error_expr(span),
        }
    }

    fn name(&mut self, n: &str, span: Span, scope: &Scope, expected: Option<&Ty>) -> TExpr {
        // Where an enum is expected, its member wins over a field or global of another type
        // with the same name (`keep(default vehicle_category == car)` beside a field `car`).
        let member_of_expected = match expected.map(strip_list) {
            Some(Ty::Enum(id)) => self
                .model
                .enum_def(*id)
                .members
                .iter()
                .position(|m| m == n)
                .map(|i| (*id, i as u32)),
            _ => None,
        };
        let fits = |t: &Ty| match member_of_expected {
            Some((id, _)) => *t == Ty::Enum(id) || *t == Ty::Error,
            None => true,
        };
        if let Some(l) = scope
            .locals
            .iter()
            .rev()
            .find(|l| l.name == n && fits(&l.value.ty))
        {
            return TExpr {
                span,
                ..l.value.clone()
            };
        }
        if let Some(this) = scope.this {
            if let Some(f) = self.model.field(this, n).filter(|f| fits(&f.ty)) {
                return TExpr {
                    kind: TKind::Path(Place::This, vec![Seg::Field(n.into())]),
                    ty: f.ty.clone(),
                    span,
                };
            }
        }
        if n == "actor" {
            if let Some(a) = scope.actor {
                return self.opaque(Ty::Compound(a), span, "the behavior's actor");
            }
        }
        if let Some(i) = self
            .model
            .globals
            .iter()
            .position(|g| g.name == n && fits(&g.ty))
        {
            return TExpr {
                kind: TKind::Path(Place::Global(i), Vec::new()),
                ty: self.model.globals[i].ty.clone(),
                span,
            };
        }
        if let Some((id, i)) = member_of_expected {
            // Recorded for the runtime, which evaluates the name without the expected type.
            self.out.enum_member_names.insert(span);
            return TExpr {
                kind: TKind::Member(id, i),
                ty: Ty::Enum(id),
                span,
            };
        }
        // Events (`start`, declared ones) are not values: an expected enum member comes first.
        if scope.this.is_some_and(|this| self.has_event(this, n)) {
            return self.opaque(Ty::Event, span, "event");
        }
        let enums = self.model.enums_with_member(n);
        if matches!(expected, Some(Ty::Error)) && !enums.is_empty() {
            // The other operand already failed; say nothing more.
            return self.error_expr(span);
        }
        match enums.as_slice() {
            [one] if expected.is_none_or(|t| matches!(t, Ty::Error)) => {
                let i = self
                    .model
                    .enum_def(*one)
                    .members
                    .iter()
                    .position(|m| m == n)
                    .unwrap_or(0);
                TExpr {
                    kind: TKind::Member(*one, i as u32),
                    ty: Ty::Enum(*one),
                    span,
                }
            }
            [] => {
                match expected.map(strip_list) {
                    Some(Ty::Enum(id)) => {
                        let e = self.model.enum_def(*id).name.clone();
                        self.err(
                            K::UnknownName,
                            span,
                            format!("enum `{e}` has no member `{n}`"),
                        );
                    }
                    _ => self.err(K::UnknownName, span, format!("unknown name `{n}`")),
                }
                self.error_expr(span)
            }
            many => {
                let msg = match expected {
                    Some(t) if !matches!(t, Ty::Error) => {
                        format!(
                            "expected {}, found `{n}`, a member of {}",
                            self.model.type_name(t),
                            self.enum_list(many)
                        )
                    }
                    _ => format!(
                        "`{n}` is a member of {}: write `TYPE!{n}`",
                        self.enum_list(many)
                    ),
                };
                self.err(K::Type, span, msg);
                self.error_expr(span)
            }
        }
    }

    fn enum_list(&self, ids: &[super::super::types::EnumId]) -> String {
        ids.iter()
            .map(|e| format!("`{}`", self.model.enum_def(*e).name))
            .collect::<Vec<_>>()
            .join(", ")
    }

    pub(crate) fn has_event(&self, c: super::super::types::CompoundId, n: &str) -> bool {
        matches!(n, "start" | "end" | "fail")
            || self.model.ancestry(c).into_iter().any(|a| {
                self.model
                    .compound(a)
                    .members
                    .iter()
                    .any(|m| matches!(m, super::super::hir::Member::Event(ev) if ev.name.text == n))
            })
    }

    fn field(&mut self, b: TExpr, name: &str, name_span: Span, span: Span) -> TExpr {
        let (real, ty) = match &b.ty {
            Ty::Compound(c) => match self.model.field(*c, name) {
                Some(f) => (name.to_string(), f.ty.clone()),
                // The seed's spelling of a field the standard's table names otherwise.
                None => match seed_alias(name).and_then(|a| self.model.field(*c, a)) {
                    Some(f) => (f.name.clone(), f.ty.clone()),
                    None => {
                        let t = self.model.compound(*c).name.clone();
                        self.err(
                            K::UnknownName,
                            name_span,
                            format!("`{t}` has no field `{name}`"),
                        );
                        return self.error_expr(span);
                    }
                },
            },
            Ty::Error => return self.error_expr(span),
            other => {
                let t = self.model.type_name(other);
                self.err(K::Type, name_span, format!("{t} has no field `{name}`"));
                return self.error_expr(span);
            }
        };
        match b.kind {
            TKind::Path(place, mut segs) => {
                segs.push(Seg::Field(real));
                TExpr {
                    kind: TKind::Path(place, segs),
                    ty,
                    span,
                }
            }
            _ => self.opaque(ty, span, "field of a computed value"),
        }
    }

    fn call(&mut self, callee: &Expr, args: &[Arg], scope: &Scope, span: Span) -> TExpr {
        let (recv, name, name_span) = match &callee.kind {
            ExprKind::Field(base, name) => (
                Some(self.expr(base, scope, None)),
                name.text.clone(),
                name.span,
            ),
            ExprKind::Name(n) => (None, n.clone(), callee.span),
            _ => {
                self.err(K::Type, callee.span, "expected a method name before `(`");
                return self.error_expr(span);
            }
        };
        let recv_ty = recv
            .as_ref()
            .map(|r| r.ty.clone())
            .or(scope.this.map(Ty::Compound));
        match recv_ty {
            Some(Ty::List(_)) if name == "size" => {
                self.args(&[], args, "size()", scope, span);
                let r = recv.unwrap_or_else(|| self.error_expr(span));
                TExpr {
                    kind: TKind::Size(Box::new(r)),
                    ty: Ty::Uint,
                    span,
                }
            }
            Some(Ty::Compound(c)) => match self.model.method(c, &name).cloned() {
                Some(m) => {
                    let label = format!("{}()", m.name);
                    let vals = self.args(&m.params, args, &label, scope, span);
                    let r = recv.unwrap_or(TExpr {
                        kind: TKind::Path(Place::This, Vec::new()),
                        ty: Ty::Compound(c),
                        span,
                    });
                    let ty = m.ret.clone().unwrap_or(Ty::Error);
                    TExpr {
                        kind: TKind::Call(Box::new(r), name, vals.into_iter().flatten().collect()),
                        ty,
                        span,
                    }
                }
                None => {
                    let t = self.model.compound(c).name.clone();
                    self.err(
                        K::UnknownName,
                        name_span,
                        format!("`{t}` has no method `{name}`"),
                    );
                    self.error_expr(span)
                }
            },
            Some(Ty::Error) => self.error_expr(span),
            Some(other) => {
                let t = self.model.type_name(&other);
                self.err(K::Type, name_span, format!("{t} has no method `{name}`"));
                self.error_expr(span)
            }
            None => {
                self.err(
                    K::UnknownName,
                    name_span,
                    format!("unknown method `{name}`"),
                );
                self.error_expr(span)
            }
        }
    }

    /// Matches arguments to parameters: positional ones first, then named ones; reports
    /// unknown names, repeats, a positional argument after a named one, missing required
    /// parameters and type mismatches. Returns one slot per parameter.
    pub(crate) fn args(
        &mut self,
        params: &[ParamDef],
        args: &[Arg],
        what: &str,
        scope: &Scope,
        span: Span,
    ) -> Vec<Option<TExpr>> {
        let mut slots: Vec<Option<TExpr>> = vec![None; params.len()];
        let mut seen_named = false;
        for (i, a) in args.iter().enumerate() {
            let index = match &a.name {
                Some(n) => {
                    seen_named = true;
                    match params.iter().position(|p| p.name == n.text) {
                        Some(k) => k,
                        None => {
                            let list = params
                                .iter()
                                .map(|p| p.name.as_str())
                                .collect::<Vec<_>>()
                                .join(", ");
                            self.err(
                                K::Arguments,
                                n.span,
                                format!(
                                    "{what} has no parameter `{}` (parameters: {list})",
                                    n.text
                                ),
                            );
                            self.expr(&a.value, scope, None);
                            continue;
                        }
                    }
                }
                None if seen_named => {
                    self.err(
                        K::Arguments,
                        a.value.span,
                        format!("positional argument after named arguments in {what}"),
                    );
                    continue;
                }
                None if i >= params.len() => {
                    self.err(
                        K::Arguments,
                        a.value.span,
                        format!(
                            "{what} takes {} argument(s), found {}",
                            params.len(),
                            args.len()
                        ),
                    );
                    break;
                }
                None => i,
            };
            if slots[index].is_some() {
                let p = &params[index].name;
                self.err(
                    K::Arguments,
                    a.value.span,
                    format!("parameter `{p}` of {what} is given twice"),
                );
                continue;
            }
            let p = params[index].clone();
            let label = format!("parameter `{}` of {what}", p.name);
            // A numeric parameter also takes a range of its type (`speed([30kph..70kph])`,
            // §8.9.1): the value lies in it.
            let t = match &a.value.kind {
                ExprKind::Range(..) if p.ty.is_numeric() => {
                    self.expect(&a.value, &Ty::Range(Box::new(p.ty.clone())), scope, &label)
                }
                _ => self.expect(&a.value, &p.ty, scope, &label),
            };
            slots[index] = Some(t);
        }
        let missing: Vec<&str> = params
            .iter()
            .zip(&slots)
            .filter(|(p, s)| !p.optional && s.is_none())
            .map(|(p, _)| p.name.as_str())
            .collect();
        if !missing.is_empty() {
            self.err(
                K::Arguments,
                span,
                format!("missing argument `{}` of {what}", missing.join("`, `")),
            );
        }
        slots
    }

    fn temporal(&mut self, name: &str, args: &[Arg], scope: &Scope, span: Span) -> TExpr {
        let time = Ty::Physical(super::super::units::Dimension::base("s", 1).unwrap_or_default());
        let first = args.first().map(|a| &a.value);
        match (name, first) {
            ("rise" | "fall", Some(e)) => {
                self.expect(e, &Ty::Bool, scope, &format!("`{name}`"));
                self.opaque(Ty::Event, span, "event")
            }
            ("elapsed" | "every", Some(e)) => {
                self.expect(e, &time, scope, &format!("`{name}`"));
                for a in &args[1..] {
                    self.expr(&a.value, scope, Some(&time));
                }
                self.opaque(Ty::Event, span, "event")
            }
            // `@event`: the event's name is resolved where the events of the scenario are known
            // (the runtime reports an unknown one at its position).
            ("@", Some(_)) => self.opaque(Ty::Event, span, "event"),
            ("sample", Some(e)) => {
                let t = self.expr(e, scope, None);
                for a in &args[1..] {
                    self.expect(&a.value, &Ty::Event, scope, "the sampling event");
                }
                self.opaque(t.ty, span, "sampled value")
            }
            _ => {
                self.err(K::Arguments, span, format!("`{name}` needs an argument"));
                self.error_expr(span)
            }
        }
    }

    fn binary(&mut self, op: BinOp, a: &Expr, b: &Expr, scope: &Scope, span: Span) -> TExpr {
        use BinOp::*;
        // A bare enum member on the left takes its type from the right.
        let (ta, tb) = if self.is_free_name(a, scope) && !self.is_free_name(b, scope) {
            let tb = self.expr(b, scope, None);
            let want = elem_of(&tb.ty, op);
            (self.expr(a, scope, want.as_ref()), tb)
        } else {
            let ta = self.expr(a, scope, None);
            let want = if op == In {
                Some(Ty::List(Box::new(ta.ty.clone())))
            } else {
                Some(ta.ty.clone())
            };
            (ta, self.expr(b, scope, want.as_ref()))
        };
        let (ty_a, ty_b) = (ta.ty.clone(), tb.ty.clone());
        let name = |cx: &Self, t: &Ty| cx.model.type_name(t);
        let ty = match op {
            And | Or | Implies => {
                for (t, e) in [(&ty_a, a), (&ty_b, b)] {
                    if !self.assignable(&Ty::Bool, t) {
                        let n = name(self, t);
                        self.err(
                            K::Type,
                            e.span,
                            format!("expected bool for `{}`, found {n}", op_text(op)),
                        );
                    }
                }
                Ty::Bool
            }
            Add | Sub | Mul | Div | Rem => self.arith(op, &ty_a, &ty_b, span),
            Lt | Le | Gt | Ge | Eq | Ne => {
                let ok = if matches!(op, Eq | Ne) {
                    self.same_quantity(&ty_a, &ty_b)
                        || self.assignable(&ty_a, &ty_b)
                        || self.assignable(&ty_b, &ty_a)
                } else {
                    ty_a == Ty::Error
                        || ty_b == Ty::Error
                        || (ty_a.is_numeric() && self.same_quantity(&ty_a, &ty_b))
                };
                if !ok {
                    let (x, y) = (name(self, &ty_a), name(self, &ty_b));
                    let physical =
                        matches!((&ty_a, &ty_b), (Ty::Physical(_), _) | (_, Ty::Physical(_)));
                    let kind = if physical { K::Units } else { K::Type };
                    self.err(
                        kind,
                        span,
                        format!("cannot compare {x} with {y} using `{}`", op_text(op)),
                    );
                }
                Ty::Bool
            }
            In => {
                match &ty_b {
                    Ty::List(e) | Ty::Range(e) => {
                        if !(self.same_quantity(&ty_a, e) || self.assignable(e, &ty_a)) {
                            let (x, y) = (name(self, &ty_a), name(self, &ty_b));
                            let kind = if matches!(&ty_a, Ty::Physical(_)) {
                                K::Units
                            } else {
                                K::Type
                            };
                            self.err(kind, span, format!("cannot test {x} for membership in {y}"));
                        }
                    }
                    Ty::Error => {}
                    other => {
                        let y = name(self, other);
                        self.err(
                            K::Type,
                            b.span,
                            format!("expected a list or range after `in`, found {y}"),
                        );
                    }
                }
                Ty::Bool
            }
        };
        TExpr {
            kind: TKind::Binary(op, Box::new(ta), Box::new(tb)),
            ty,
            span,
        }
    }

    /// Numbers that may be compared: equal physical dimensions, or two plain numbers.
    fn same_quantity(&self, a: &Ty, b: &Ty) -> bool {
        match (a, b) {
            (Ty::Error, _) | (_, Ty::Error) => true,
            (Ty::Physical(x), Ty::Physical(y)) => x == y,
            (x, y) => x.is_plain_number() && y.is_plain_number(),
        }
    }

    fn arith(&mut self, op: BinOp, a: &Ty, b: &Ty, span: Span) -> Ty {
        use super::super::units::Dimension;
        let dim = |t: &Ty| match t {
            Ty::Physical(d) => Some(*d),
            t if t.is_plain_number() => Some(Dimension::NONE),
            _ => None,
        };
        if *a == Ty::Error || *b == Ty::Error {
            return Ty::Error;
        }
        let (Some(da), Some(db)) = (dim(a), dim(b)) else {
            let (x, y) = (self.model.type_name(a), self.model.type_name(b));
            self.err(
                K::Type,
                span,
                format!("cannot apply `{}` to {x} and {y}", op_text(op)),
            );
            return Ty::Error;
        };
        let plain = |x: &Ty, y: &Ty| {
            if *x == Ty::Float || *y == Ty::Float {
                Ty::Float
            } else if *x == Ty::Int || *y == Ty::Int {
                Ty::Int
            } else {
                Ty::Uint
            }
        };
        let result = match op {
            BinOp::Add | BinOp::Sub => {
                if da != db {
                    let (x, y) = (self.model.type_name(a), self.model.type_name(b));
                    let verb = if op == BinOp::Add { "add" } else { "subtract" };
                    self.err(
                        K::Units,
                        span,
                        format!("cannot {verb} {x} and {y}: dimensions {da} and {db} differ"),
                    );
                    return Ty::Error;
                }
                Some(da)
            }
            BinOp::Mul => da.times(db),
            BinOp::Div => da.per(db),
            _ => {
                if !(a.is_integer() && b.is_integer()) {
                    self.err(K::Type, span, "expected whole numbers for `%`");
                }
                Some(Dimension::NONE)
            }
        };
        match result {
            Some(d) if d.is_none() => {
                if da.is_none() && db.is_none() {
                    if op == BinOp::Div {
                        Ty::Float
                    } else {
                        plain(a, b)
                    }
                } else {
                    Ty::Float
                }
            }
            Some(d) => Ty::Physical(d),
            None => {
                self.err(K::Units, span, "dimension exponent out of range");
                Ty::Error
            }
        }
    }

    /// A bare name that is neither a local, a field nor a global: an enum member to be typed
    /// from the other operand.
    fn is_free_name(&self, e: &Expr, scope: &Scope) -> bool {
        let ExprKind::Name(n) = &e.kind else {
            return matches!(e.kind, ExprKind::List(_));
        };
        !scope.locals.iter().any(|l| l.name == *n)
            && scope.this.is_none_or(|t| self.model.field(t, n).is_none())
            && !self.model.globals.iter().any(|g| g.name == *n)
            && n != "actor"
    }
}

fn strip_list(t: &Ty) -> &Ty {
    match t {
        Ty::List(e) => e,
        t => t,
    }
}

fn elem_of(t: &Ty, op: BinOp) -> Option<Ty> {
    match (op, t) {
        (BinOp::In, Ty::List(e)) => Some((**e).clone()),
        _ => Some(t.clone()),
    }
}

/// Field names the seed's examples spell differently from the standard's tables
/// (docs/dsl.md): `v.category` for `v.vehicle_category` (§8.7.18 Code 4).
pub(crate) fn seed_alias(field: &str) -> Option<&'static str> {
    match field {
        "category" => Some("vehicle_category"),
        _ => None,
    }
}
