//! The phase tree of a scenario's `do` (ASAM OpenSCENARIO DSL 2.1 §7.3.9 behavior
//! specification): compositions `serial`, `parallel`, `one_of` (its member chosen from the
//! run's seed), `wait`, and invocations of actions on actors with their `with:` modifiers and
//! `until`. Each phase has a path: the labels (or, unlabelled, the member's index) from the
//! root `do` down, joined by `.` (`do.get_ahead.1`); it is the phase's name in the event log.

use dsl::semantics::hir::{
    Behavior, CompositionOp, Expr, ExprKind, Labeled, ModifierApp, Span, WithMember,
};

use crate::condition::every_args;
use crate::error::{Error, ErrorKind as K};
use crate::value::{bind, Ctx, Val};

/// One phase.
#[derive(Debug)]
pub(crate) struct Phase<'p> {
    /// `do.get_ahead.0`.
    pub path: String,
    /// Where it is written.
    pub span: Span,
    /// What it is.
    pub kind: Kind<'p>,
    /// Its own duration (s): `duration:` argument (a range drawn from the seed), or
    /// `wait elapsed(d)`, or the first occurrence of `every(…)` in a `wait`/`until`.
    pub duration: Option<f64>,
    /// `until` condition, or the condition of a `wait`.
    pub until: Option<&'p Expr>,
    /// Members of a composition (for `one_of`, the chosen one only).
    pub children: Vec<Phase<'p>>,
}

/// The kinds of phase.
#[derive(Debug)]
pub(crate) enum Kind<'p> {
    /// `serial`: members one after another.
    Serial,
    /// `parallel`: members together.
    Parallel,
    /// `one_of`: the member drawn (its index among the written members).
    OneOf(usize),
    /// `wait`.
    Wait,
    /// `emit event`: an instant phase that `@event` conditions observe.
    Emit(String),
    /// `actor.action(args) with: …`.
    Invoke(Invoke<'p>),
}

/// An action invoked on an actor.
#[derive(Debug)]
pub(crate) struct Invoke<'p> {
    /// The actor's path (`ego`, `dut.vehicle`, `g`).
    pub actor: String,
    /// The actor expression.
    pub actor_expr: &'p Expr,
    /// The action (`drive`).
    pub action: String,
    /// Modifiers in order.
    pub modifiers: Vec<&'p ModifierApp>,
}

impl Phase<'_> {
    /// Every leaf (invocation or wait) in tree order.
    pub(crate) fn leaves(&self) -> Vec<&Phase<'_>> {
        let mut out = Vec::new();
        self.walk(&mut |p| {
            if p.children.is_empty() {
                out.push(p);
            }
        });
        out
    }

    /// Visits the phase and its descendants, parents first.
    pub(crate) fn walk<'s>(&'s self, f: &mut dyn FnMut(&'s Phase<'_>)) {
        f(self);
        for c in &self.children {
            c.walk(f);
        }
    }
}

/// Builds the phase tree of `root` (the scenario's `do` member).
pub(crate) fn build<'p>(
    ctx: &Ctx<'_>,
    root: &'p Labeled,
    path: String,
) -> Result<Phase<'p>, Error> {
    let path = match &root.label {
        Some(l) if path == "do" => format!("do.{}", l.text),
        _ => path,
    };
    match &root.behavior {
        Behavior::Composition {
            op,
            args,
            children,
            span,
        } => {
            let mut duration = None;
            for (name, e) in bind(args, &["duration".to_string()]) {
                match name.as_str() {
                    "duration" => duration = Some(positive(ctx, e)?),
                    other => {
                        return Err(ctx.files.err(
                            K::Unsupported,
                            e.span,
                            format!("expected a `duration:` argument, found `{other}:`"),
                        ))
                    }
                }
            }
            let kind = match op {
                CompositionOp::Serial => Kind::Serial,
                CompositionOp::Parallel => Kind::Parallel,
                CompositionOp::OneOf => Kind::OneOf(ctx.choose(children.len())),
            };
            let picked: Vec<(usize, &Labeled)> = match kind {
                Kind::OneOf(i) => children.iter().enumerate().skip(i).take(1).collect(),
                _ => children.iter().enumerate().collect(),
            };
            let mut out = Vec::new();
            for (i, c) in picked {
                let seg = c.label.as_ref().map_or(i.to_string(), |l| l.text.clone());
                out.push(build(ctx, c, format!("{path}.{seg}"))?);
            }
            if out.is_empty() {
                return Err(ctx.files.err(
                    K::NoEnd,
                    *span,
                    "expected members in a composition, found none",
                ));
            }
            Ok(Phase {
                path,
                span: *span,
                kind,
                duration,
                until: None,
                children: out,
            })
        }
        Behavior::Wait(e, span) => {
            let (duration, until) = match &e.kind {
                ExprKind::Temporal(n, args) if n.text == "elapsed" => {
                    let d = args.first().ok_or_else(|| {
                        ctx.files
                            .err(K::Value, *span, "expected a time in elapsed(…), found none")
                    })?;
                    (Some(non_negative(ctx, &d.value)?), None)
                }
                // `wait every(p, offset: o)`: the wait ends at the first occurrence, o after
                // its start (§7.3.10.4: the event context of a wait starts with the wait).
                ExprKind::Temporal(n, args) if n.text == "every" => {
                    (Some(every_args(ctx, e.span, args)?.offset), None)
                }
                _ => (None, Some(e)),
            };
            Ok(Phase {
                path,
                span: *span,
                kind: Kind::Wait,
                duration,
                until,
                children: Vec::new(),
            })
        }
        Behavior::Invocation {
            actor,
            name,
            args,
            with,
            span,
        } => {
            let Some(actor_expr) = actor else {
                return Err(ctx.files.err(
                    K::Unsupported,
                    *span,
                    format!(
                        "expected an actor before `{}` (scenario invocations are not run yet)",
                        name.text
                    ),
                ));
            };
            let actor_path = ctx.path_of(actor_expr).ok_or_else(|| {
                ctx.files.err(
                    K::UnknownActor,
                    actor_expr.span,
                    "expected an actor name, found an expression",
                )
            })?;
            let params = action_params(ctx, &actor_path, &name.text);
            let bound = bind(args, &params);
            let mut duration = None;
            let mut until = None;
            let mut modifiers = Vec::new();
            for (n, e) in &bound {
                if n == "duration" {
                    duration = Some(positive(ctx, e)?);
                }
            }
            for w in with {
                match w {
                    WithMember::Modifier(m) => modifiers.push(m),
                    // `until elapsed(d)`: the phase lasts at most d.
                    WithMember::Until(e, _) => match &e.kind {
                        ExprKind::Temporal(n, a) if n.text == "elapsed" => {
                            let d = match a.first() {
                                Some(a) => positive(ctx, &a.value)?,
                                None => {
                                    return Err(ctx.files.err(
                                        K::Value,
                                        e.span,
                                        "expected a time in elapsed(…), found none",
                                    ))
                                }
                            };
                            duration = Some(duration.map_or(d, |x: f64| x.min(d)));
                        }
                        // `until every(p, offset: o)`: the first occurrence, o after the
                        // invocation's start, ends it; without an offset that is its start.
                        ExprKind::Temporal(n, a) if n.text == "every" => {
                            let d = every_args(ctx, e.span, a)?.offset;
                            if d <= 0.0 {
                                return Err(ctx.files.err(
                                    K::Value,
                                    e.span,
                                    "expected an offset above 0 s in until every(…), found none (the first occurrence is the start of the phase, which would end it at once)",
                                ));
                            }
                            duration = Some(duration.map_or(d, |x: f64| x.min(d)));
                        }
                        _ => until = Some(e),
                    },
                    WithMember::Keep(k) => {
                        return Err(ctx.files.err(
                            K::Unsupported,
                            k.span,
                            "expected modifiers or until in an invocation's with:, found keep (not run yet)",
                        ))
                    }
                }
            }
            Ok(Phase {
                path,
                span: *span,
                kind: Kind::Invoke(Invoke {
                    actor: actor_path,
                    actor_expr,
                    action: name.text.clone(),
                    modifiers,
                }),
                duration,
                until,
                children: Vec::new(),
            })
        }
        Behavior::Emit(name, _, span) => Ok(Phase {
            path,
            span: *span,
            kind: Kind::Emit(name.text.clone()),
            duration: None,
            until: None,
            children: Vec::new(),
        }),
        Behavior::Call(_, span) => Err(ctx.files.err(
            K::Unsupported,
            *span,
            "expected a composition, wait, emit or action invocation, found call (not run yet)",
        )),
    }
}

/// Parameter names of `actor.action`, own first then inherited (as the checker binds them).
fn action_params(ctx: &Ctx<'_>, actor: &str, action: &str) -> Vec<String> {
    let Some(ty) = ctx.lookup(actor).and_then(|(_, v)| ctx.type_of(v)) else {
        return vec!["duration".into()];
    };
    let Some(b) = ctx.model.behavior_of(ty, action) else {
        return vec!["duration".into()];
    };
    ctx.model
        .ancestry(b)
        .into_iter()
        .flat_map(|c| ctx.model.compound(c).fields.iter())
        .filter(|f| !f.is_var)
        .map(|f| f.name.clone())
        .collect()
}

fn non_negative(ctx: &Ctx<'_>, e: &Expr) -> Result<f64, Error> {
    match ctx.eval(e)? {
        Val::Num(x) if x >= 0.0 && x.is_finite() => Ok(x),
        _ => Err(ctx.files.err(
            K::Value,
            e.span,
            "expected a time of 0 s or more, found another value",
        )),
    }
}

fn positive(ctx: &Ctx<'_>, e: &Expr) -> Result<f64, Error> {
    match ctx.eval(e)? {
        Val::Num(x) if x > 0.0 && x.is_finite() => Ok(x),
        _ => Err(ctx.files.err(
            K::Value,
            e.span,
            "expected a duration above 0 s, found another value",
        )),
    }
}
