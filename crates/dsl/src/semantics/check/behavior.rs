//! Behaviors (ASAM OpenSCENARIO DSL 2.1 §7.3.9): compositions, invocations of actions and
//! scenarios on actors with their arguments, `with:` blocks, and modifier applicability
//! (§8.9: a modifier declared `of B` applies to `B` and to behaviors inheriting from it).

use super::super::diagnostic::DiagnosticKind as K;
use super::super::hir::{
    Arg, Behavior, BinOp, CompoundKind, ExprKind, Labeled, Member, ModifierApp, Span, WithMember,
};
use super::super::model::ParamDef;
use super::super::solver::Strength;
use super::super::types::{CompoundId, Ty};
use super::{Cx, Invocation, Local, Owner, Place, Scope, Seg, TExpr, TKind, Template};

impl Cx<'_> {
    /// The parameters of a behavior or modifier, for argument matching: own fields first, then
    /// inherited ones (so `change_speed(20kph)` sets `target`, not the inherited `duration`);
    /// all optional (an action's unset parameter has no value).
    fn behavior_params(&self, id: CompoundId) -> Vec<ParamDef> {
        self.model
            .ancestry(id)
            .into_iter()
            .flat_map(|c| self.model.compound(c).fields.iter())
            .filter(|f| !f.is_var)
            .map(|f| ParamDef {
                name: f.name.clone(),
                ty: f.ty.clone(),
                optional: true,
            })
            .collect()
    }

    /// Whether behavior `id` (or an ancestor) has a `do` of its own: its invocations are
    /// instances with parameters (user scenarios), not the library's actions.
    pub(crate) fn has_do(&self, id: CompoundId) -> bool {
        self.model.ancestry(id).into_iter().any(|c| {
            self.model
                .compound(c)
                .members
                .iter()
                .any(|m| matches!(m, Member::Do(..)))
        })
    }

    /// Checks behavior `b` of a `do` at phase path `path` (`None`: in an `on` handler, where
    /// no invocation is recorded).
    pub(crate) fn behavior(&mut self, b: &Labeled, scope: &Scope, path: Option<&str>) {
        match &b.behavior {
            Behavior::Composition {
                args,
                children,
                with,
                ..
            } => {
                for a in args {
                    // `parallel(overlap: equal)`: the kind is a word of the composition
                    // operator (§7.3.9), read by the runtime, not a name in scope.
                    let overlap = a.name.as_ref().is_some_and(|n| n.text == "overlap")
                        && matches!(a.value.kind, ExprKind::Name(_));
                    if !overlap {
                        self.expr(&a.value, scope, None);
                    }
                }
                for (i, c) in children.iter().enumerate() {
                    let seg = c.label.as_ref().map_or(i.to_string(), |l| l.text.clone());
                    let child = path.map(|p| format!("{p}.{seg}"));
                    self.behavior(c, scope, child.as_deref());
                }
                self.composition_with(with, scope);
            }
            Behavior::Invocation {
                actor,
                name,
                args,
                with,
                span,
            } => {
                let target = match actor {
                    Some(e) => {
                        let t = self.expr(e, scope, None);
                        match t.ty {
                            Ty::Compound(c)
                                if self.model.compound(c).kind == CompoundKind::Actor =>
                            {
                                Some(c)
                            }
                            Ty::Error => return,
                            other => {
                                let n = self.model.type_name(&other);
                                self.err(
                                    K::Type,
                                    e.span,
                                    format!("expected an actor before `.{}`, found {n}", name.text),
                                );
                                return;
                            }
                        }
                    }
                    None => scope.actor,
                };
                let found = match target {
                    Some(a) => self.model.behavior_of(a, &name.text),
                    None => self.model.behaviors.get(&name.text).copied(),
                };
                let Some(bid) = found else {
                    let on = target
                        .map(|a| format!(" on actor `{}`", self.model.compound(a).name))
                        .unwrap_or_default();
                    self.err(
                        K::UnknownName,
                        name.span,
                        format!("unknown action or scenario `{}`{on}", name.text),
                    );
                    return;
                };
                let params = self.behavior_params(bid);
                let label = format!("`{}`", self.model.compound(bid).name);
                let bound = self.args(&params, args, &label, scope, *span);
                // An invocation of a behavior with a `do` is an instance of it: `it` in its
                // `with:` block is that instance, so `keep(it.p …)` constrains its parameter.
                // So is an invocation of an action with `keep(…)` in its `with:` (§7.3.9
                // behavior-with-member: the constraints hold for that invocation).
                let keeps = with.iter().any(|w| matches!(w, WithMember::Keep(_)));
                let site = match (path, scope.this) {
                    (Some(p), Some(caller)) if keeps || self.has_do(bid) => {
                        Some(self.invocation(caller, p, bid, &params, bound, name.span, *span))
                    }
                    _ => None,
                };
                let it = match site {
                    Some(_) => TKind::Path(Place::It, Vec::new()),
                    None => TKind::Opaque("invocation"),
                };
                let mut inner = scope.clone();
                inner.locals.push(Local {
                    name: "it".into(),
                    value: TExpr {
                        kind: it,
                        ty: Ty::Compound(bid),
                        span: *span,
                    },
                });
                for w in with {
                    match w {
                        WithMember::Modifier(app) => self.applied_modifier(app, bid, &inner),
                        WithMember::Keep(k) => {
                            let t = self.expect(&k.expr, &Ty::Bool, &inner, "a constraint");
                            if let Some(site) = site {
                                self.out.templates.push(Template {
                                    owner: Owner::Invocation(site),
                                    strength: if k.default {
                                        Strength::Default
                                    } else {
                                        Strength::Hard
                                    },
                                    expr: t,
                                    loops: Vec::new(),
                                    subject: None,
                                    span: k.span,
                                });
                            }
                        }
                        WithMember::Until(e, _) => {
                            self.expect(e, &Ty::Event, &inner, "`until`");
                        }
                    }
                }
            }
            Behavior::Wait(e, _) => {
                self.expect(e, &Ty::Event, scope, "`wait`");
            }
            Behavior::Emit(name, args, _) => {
                if scope.this.is_some_and(|t| !self.has_event(t, &name.text)) {
                    self.err(
                        K::UnknownName,
                        name.span,
                        format!("unknown event `{}`", name.text),
                    );
                }
                for a in args {
                    self.expr(&a.value, scope, None);
                }
            }
            Behavior::Call(e, _) => {
                self.expr(e, scope, None);
            }
        }
    }

    /// The `with:` block of a composition (§7.3.9): `until` ends it; a `keep` constrains the
    /// behavior whose `do` holds it (there is no instance `it` of a composition), as a `keep`
    /// in that behavior's body does; a modifier names no actor to apply to, an error.
    fn composition_with(&mut self, with: &[WithMember], scope: &Scope) {
        for w in with {
            match w {
                WithMember::Until(e, _) => {
                    self.expect(e, &Ty::Event, scope, "`until`");
                }
                WithMember::Keep(k) => match scope.this {
                    Some(this) => self.keep(k, scope, Owner::Compound(this), &[]),
                    None => {
                        self.expect(&k.expr, &Ty::Bool, scope, "a constraint");
                    }
                },
                WithMember::Modifier(app) => self.err(
                    K::Unsupported,
                    app.span,
                    format!(
                        "expected `until` or `keep` in the with: of a composition, found the modifier `{}` (a modifier applies to the actor of the action it modifies; a composition has none)",
                        app.name.text
                    ),
                ),
            }
        }
    }

    /// Records the invocation of `callee` (a behavior with a `do`) at `path` of `caller`'s
    /// `do`, with its arguments `bound` to `params`: each scalar argument a hard constraint
    /// `it.param == argument` (`in` for a range), each argument of a struct or actor type an
    /// alias. Returns the invocation's index.
    #[allow(clippy::too_many_arguments)]
    fn invocation(
        &mut self,
        caller: CompoundId,
        path: &str,
        callee: CompoundId,
        params: &[ParamDef],
        bound: Vec<Option<TExpr>>,
        name_span: Span,
        span: Span,
    ) -> usize {
        let site = self.out.invocations.len();
        let mut aliases = Vec::new();
        for (p, arg) in params.iter().zip(bound) {
            let Some(arg) = arg else { continue };
            if arg.ty == Ty::Error {
                continue;
            }
            if matches!(p.ty, Ty::Compound(_)) {
                aliases.push((p.name.clone(), arg));
                continue;
            }
            let param = TExpr {
                kind: TKind::Path(Place::It, vec![Seg::Field(p.name.clone())]),
                ty: p.ty.clone(),
                span: arg.span,
            };
            let op = match arg.kind {
                TKind::Range(..) => BinOp::In,
                _ => BinOp::Eq,
            };
            let arg_span = arg.span;
            self.out.templates.push(Template {
                owner: Owner::Invocation(site),
                strength: Strength::Hard,
                expr: TExpr {
                    kind: TKind::Binary(op, Box::new(param), Box::new(arg)),
                    ty: Ty::Bool,
                    span: arg_span,
                },
                loops: Vec::new(),
                subject: None,
                span: arg_span,
            });
        }
        self.out.invocations.push(Invocation {
            caller,
            path: path.to_string(),
            callee,
            aliases,
            name_span,
            span,
        });
        site
    }

    /// A modifier in the `with:` block of an invocation of behavior `bid`.
    fn applied_modifier(&mut self, app: &ModifierApp, bid: CompoundId, scope: &Scope) {
        if let Some(t) = &app.target {
            self.expr(t, scope, None);
        }
        let named = self.model.modifiers_named(&app.name.text);
        let chain = self.model.ancestry(bid);
        let applicable = named.iter().copied().find(|m| {
            self.model
                .compound(*m)
                .of
                .is_some_and(|of| chain.contains(&of))
        });
        match applicable {
            Some(m) => self.modifier_args(m, &app.args, scope, app.span),
            None if named.is_empty() => {
                self.err(
                    K::UnknownName,
                    app.name.span,
                    format!("unknown modifier `{}`", app.name.text),
                );
            }
            None => {
                let of: Vec<String> = named
                    .iter()
                    .filter_map(|m| self.model.compound(*m).of)
                    .map(|o| format!("`{}`", self.model.compound(o).name))
                    .collect();
                let b = self.model.compound(bid).name.clone();
                let to = if of.is_empty() {
                    "actors, not to actions".to_string()
                } else {
                    of.join(", ")
                };
                self.err(
                    K::Modifier,
                    app.name.span,
                    format!("modifier `{}` applies to {to}, not to `{b}`", app.name.text),
                );
            }
        }
    }

    /// A modifier applied as a member: `my_building.location(my_pose)`.
    pub(crate) fn member_modifier(&mut self, app: &ModifierApp, scope: &Scope) {
        let target_ty = match &app.target {
            Some(t) => self.expr(t, scope, None).ty,
            None => scope.actor.map(Ty::Compound).unwrap_or(Ty::Error),
        };
        let named = self.model.modifiers_named(&app.name.text);
        let Ty::Compound(actor) = target_ty else {
            if target_ty != Ty::Error || app.target.is_none() {
                self.err(
                    K::Modifier,
                    app.name.span,
                    format!("modifier `{}` needs an actor to apply to", app.name.text),
                );
            }
            return;
        };
        let fits = named.iter().copied().find(|m| {
            let d = self.model.compound(*m);
            d.of.is_none() && d.actor.is_some_and(|a| self.model.is_subtype(actor, a))
        });
        match fits {
            Some(m) => self.modifier_args(m, &app.args, scope, app.span),
            None if named.is_empty() => self.err(
                K::UnknownName,
                app.name.span,
                format!("unknown modifier `{}`", app.name.text),
            ),
            None => {
                let a = self.model.compound(actor).name.clone();
                self.err(
                    K::Modifier,
                    app.name.span,
                    format!("modifier `{}` does not apply to actor `{a}`", app.name.text),
                );
            }
        }
    }

    fn modifier_args(&mut self, m: CompoundId, args: &[Arg], scope: &Scope, span: Span) {
        let params = self.behavior_params(m);
        let label = format!("modifier `{}`", self.model.compound(m).short);
        self.args(&params, args, &label, scope, span);
    }
}
