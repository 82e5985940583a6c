//! Members of compound types and of the top level: field defaults and their `with:` constraints,
//! `keep` (hard and default), `for … in …:` constraint loops, methods, events, modifier
//! applications and `do` (ASAM OpenSCENARIO DSL 2.1 §7.3.6, §7.3.7).

use super::super::diagnostic::DiagnosticKind as K;
use super::super::hir::{Expr, Keep, Member, MethodBody, Span};
use super::super::model::{FieldDef, Model};
use super::super::solver::Strength;
use super::super::types::{CompoundId, Ty};
use super::{Checked, Cx, Local, Owner, Place, Scope, Seg, TExpr, TKind, Template};
use crate::semantics::hir::BinOp;

/// Checks every member of every compound and of the top level.
pub fn check_model(model: &Model) -> Checked {
    let mut cx = Cx {
        model,
        out: Checked::default(),
    };
    let top = Scope::default();
    for (i, g) in model.globals.iter().enumerate() {
        let here = TExpr {
            kind: TKind::Path(Place::Global(i), Vec::new()),
            ty: g.ty.clone(),
            span: g.span,
        };
        cx.field_decl(g, here, &top, Owner::Top);
    }
    cx.members(&model.top, &top, Owner::Top, &[]);
    for i in 0..model.compounds.len() {
        let id = CompoundId(i as u32);
        let c = model.compound(id);
        let scope = Scope {
            this: Some(id),
            actor: c.actor,
            locals: Vec::new(),
        };
        for f in &c.fields {
            let here = TExpr {
                kind: TKind::Path(Place::This, vec![Seg::Field(f.name.clone())]),
                ty: f.ty.clone(),
                span: f.span,
            };
            cx.field_decl(f, here, &scope, Owner::Compound(id));
        }
        if let Some(cond) = &c.condition {
            let k = Keep {
                default: false,
                expr: cond.clone(),
                span: cond.span,
            };
            cx.keep(&k, &scope, Owner::Compound(id), &[]);
        }
        cx.members(&c.members, &scope, Owner::Compound(id), &[]);
    }
    let recursive = super::invocations::recursion(model, &cx.out.invocations);
    cx.out.diags.extend(recursive);
    cx.out
}

impl Cx<'_> {
    /// A field's `= value` (a default constraint) and its `with:` constraints over `it`.
    fn field_decl(&mut self, f: &FieldDef, here: TExpr, scope: &Scope, owner: Owner) {
        if let Some(d) = &f.default {
            let v = self.expect(d, &f.ty, scope, &format!("field `{}`", f.name));
            // A route's value (`r: route = m.create_route(…)`) is found in the map by the
            // runtime, as the route itself: no constraint of the solver's.
            let route = matches!(&f.ty, Ty::Compound(c) if self.model.is_route(*c));
            if !f.is_var && !route {
                let eq = TExpr {
                    kind: TKind::Binary(BinOp::Eq, Box::new(here.clone()), Box::new(v)),
                    ty: Ty::Bool,
                    span: d.span,
                };
                self.out.templates.push(Template {
                    owner,
                    strength: Strength::Default,
                    expr: eq,
                    loops: Vec::new(),
                    subject: Some(here.clone()),
                    span: d.span,
                });
            }
        }
        let mut inner = scope.clone();
        inner.locals.push(Local {
            name: "it".into(),
            value: here,
        });
        for k in &f.keeps {
            self.keep(k, &inner, owner, &[]);
        }
    }

    pub(crate) fn keep(&mut self, k: &Keep, scope: &Scope, owner: Owner, loops: &[TExpr]) {
        let t = self.expect(&k.expr, &Ty::Bool, scope, "a constraint");
        let strength = if k.default {
            Strength::Default
        } else {
            Strength::Hard
        };
        self.out.templates.push(Template {
            owner,
            strength,
            expr: t,
            loops: loops.to_vec(),
            subject: None,
            span: k.span,
        });
    }

    fn members(&mut self, members: &[Member], scope: &Scope, owner: Owner, loops: &[TExpr]) {
        for m in members {
            match m {
                Member::Field(_) => {}
                Member::Keep(k) => self.keep(k, scope, owner, loops),
                Member::RemoveDefault(e, _) => {
                    self.expr(e, scope, None);
                }
                Member::For {
                    var,
                    list,
                    body,
                    span,
                } => self.for_loop(&var.text, list, body, *span, scope, owner, loops),
                Member::Method(md) => {
                    let mut inner = scope.clone();
                    let def = scope
                        .this
                        .and_then(|t| self.model.method(t, &md.name.text).cloned());
                    for p in def.iter().flat_map(|d| d.params.iter()) {
                        let value = TExpr {
                            kind: TKind::Opaque("method parameter"),
                            ty: p.ty.clone(),
                            span: md.span,
                        };
                        inner.locals.push(Local {
                            name: p.name.clone(),
                            value,
                        });
                    }
                    if let MethodBody::Expression(e) = &md.body {
                        match def.and_then(|d| d.ret) {
                            Some(ret) => {
                                self.expect(
                                    e,
                                    &ret,
                                    &inner,
                                    &format!("the result of `{}`", md.name.text),
                                );
                            }
                            None => {
                                self.expr(e, &inner, None);
                            }
                        }
                    }
                }
                Member::Event(ev) => {
                    if let Some(spec) = &ev.spec {
                        self.expect(
                            spec,
                            &Ty::Event,
                            scope,
                            &format!("event `{}`", ev.name.text),
                        );
                    }
                }
                Member::Modifier(app) => self.member_modifier(app, scope),
                Member::Do(b, _) => {
                    let path = match &b.label {
                        Some(l) => format!("do.{}", l.text),
                        None => "do".to_string(),
                    };
                    self.behavior(b, scope, Some(&path));
                }
                Member::On(e, body, _) => {
                    self.expect(e, &Ty::Event, scope, "`on`");
                    for b in body {
                        self.behavior(b, scope, None);
                    }
                }
                Member::Coverage(_, args, _) => {
                    // §7.3.12: the first positional argument is the item's name; it names a
                    // field (checked as an expression) only when no `expression:` is given.
                    let named = |n: &str| {
                        args.iter()
                            .find(|a| a.name.as_ref().is_some_and(|x| x.text == n))
                    };
                    let sampled =
                        named("expression").or_else(|| args.iter().find(|a| a.name.is_none()));
                    for a in sampled.into_iter().chain(named("ignore")) {
                        self.expr(&a.value, scope, None);
                    }
                }
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn for_loop(
        &mut self,
        var: &str,
        list: &Expr,
        body: &[Member],
        span: Span,
        scope: &Scope,
        owner: Owner,
        loops: &[TExpr],
    ) {
        let l = self.expr(list, scope, None);
        let elem = match &l.ty {
            Ty::List(e) => (**e).clone(),
            Ty::Error => Ty::Error,
            other => {
                let t = self.model.type_name(other);
                self.err(
                    K::Type,
                    list.span,
                    format!("expected a list after `in`, found {t}"),
                );
                Ty::Error
            }
        };
        let k = loops.len();
        let mut inner = scope.clone();
        inner.locals.push(Local {
            name: var.into(),
            value: TExpr {
                kind: TKind::Path(Place::Local(k), Vec::new()),
                ty: elem,
                span,
            },
        });
        let mut nested = loops.to_vec();
        nested.push(l);
        for m in body {
            match m {
                Member::Keep(_) | Member::For { .. } => {
                    self.members(std::slice::from_ref(m), &inner, owner, &nested)
                }
                other => {
                    let s = member_span(other).unwrap_or(span);
                    self.err(
                        K::Unsupported,
                        s,
                        "only `keep` constraints may appear in a `for` block",
                    );
                }
            }
        }
    }
}

fn member_span(m: &Member) -> Option<Span> {
    match m {
        Member::Field(f) => Some(f.span),
        Member::Method(md) => Some(md.span),
        Member::Event(e) => Some(e.span),
        Member::Modifier(a) => Some(a.span),
        Member::Do(_, s)
        | Member::On(_, _, s)
        | Member::Coverage(_, _, s)
        | Member::RemoveDefault(_, s) => Some(*s),
        Member::Keep(k) => Some(k.span),
        Member::For { span, .. } => Some(*span),
    }
}
