//! The phase tree of a scenario's `do` (ASAM OpenSCENARIO DSL 2.1 §7.3.9 behavior
//! specification): compositions `serial`, `parallel`, `one_of` (its member chosen from the
//! run's seed), `wait`, `emit`, and invocations of actions on actors with their arguments,
//! `with:` modifiers and `until`, every value evaluated. Each phase has a path: the labels (or,
//! unlabelled, the member's index) from the root `do` down, joined by `.` (`do.get_ahead.1`);
//! it is the phase's name in the event log.

use dsl::semantics::hir::{Behavior, CompositionOp, Expr, ExprKind, Labeled, WithMember};

use super::cond::{self, every_args, Cond};
use super::eval::Eval;
use super::modifier::{self, Modifier};
use super::value::Val;
use crate::error::{Error, ErrorKind as K, Site};

/// One phase.
#[derive(Debug, Clone)]
pub(crate) struct Phase {
    /// `do.get_ahead.0`.
    pub path: String,
    /// Where it is written.
    pub site: Site,
    /// What it is.
    pub kind: Kind,
    /// Its own duration (s): `duration:` argument (a range drawn from the seed), or
    /// `wait elapsed(d)`, or the first occurrence of `every(…)` in a `wait`/`until`.
    pub duration: Option<f64>,
    /// `until` condition, or the condition of a `wait` (or why it cannot be run, reported
    /// when the phase is planned).
    pub until: Option<Result<Cond, Error>>,
    /// Members of a composition (for `one_of`, the chosen one only).
    pub children: Vec<Phase>,
}

/// The kinds of phase.
#[derive(Debug, Clone)]
pub(crate) enum Kind {
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
    Invoke(Invoke),
}

/// An action invoked on an actor.
#[derive(Debug, Clone)]
pub(crate) struct Invoke {
    /// The actor's path (`ego`, `dut.vehicle`, `g`).
    pub actor: String,
    /// The actor expression.
    pub actor_site: Site,
    /// The action (`drive`).
    pub action: String,
    /// Modifiers in order.
    pub modifiers: Vec<Modifier>,
}

impl Phase {
    /// Every leaf (invocation, wait or emit) in tree order.
    pub(crate) fn leaves(&self) -> Vec<&Phase> {
        let mut out = Vec::new();
        self.walk(&mut |p| {
            if p.children.is_empty() {
                out.push(p);
            }
        });
        out
    }

    /// Visits the phase and its descendants, parents first.
    pub(crate) fn walk<'s>(&'s self, f: &mut dyn FnMut(&'s Phase)) {
        f(self);
        for c in &self.children {
            c.walk(f);
        }
    }
}

/// Builds the phase tree of `root` (the scenario's `do` member).
pub(crate) fn build(ev: &Eval<'_>, root: &Labeled, path: String) -> Result<Phase, Error> {
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
            for (name, e) in super::eval::bind(args, &["duration".to_string()]) {
                match name.as_str() {
                    "duration" => duration = Some(positive(ev, e)?),
                    other => {
                        return Err(ev.files.err(
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
                CompositionOp::OneOf => Kind::OneOf(ev.choose(children.len())),
            };
            let picked: Vec<(usize, &Labeled)> = match kind {
                Kind::OneOf(i) => children.iter().enumerate().skip(i).take(1).collect(),
                _ => children.iter().enumerate().collect(),
            };
            let mut out = Vec::new();
            for (i, c) in picked {
                let seg = c.label.as_ref().map_or(i.to_string(), |l| l.text.clone());
                out.push(build(ev, c, format!("{path}.{seg}"))?);
            }
            if out.is_empty() {
                return Err(ev.files.err(
                    K::NoEnd,
                    *span,
                    "expected members in a composition, found none",
                ));
            }
            Ok(Phase {
                path,
                site: ev.site(*span),
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
                        ev.files
                            .err(K::Value, *span, "expected a time in elapsed(…), found none")
                    })?;
                    (Some(non_negative(ev, &d.value)?), None)
                }
                // `wait every(p, offset: o)`: the wait ends at the first occurrence, o after
                // its start (§7.3.10.4: the event context of a wait starts with the wait).
                ExprKind::Temporal(n, args) if n.text == "every" => {
                    (Some(every_args(ev, e.span, args)?.offset), None)
                }
                _ => (None, Some(cond::read(ev, e))),
            };
            Ok(Phase {
                path,
                site: ev.site(*span),
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
                return Err(ev.files.err(
                    K::Unsupported,
                    *span,
                    format!(
                        "expected an actor before `{}` (scenario invocations are not run yet)",
                        name.text
                    ),
                ));
            };
            let actor_path = ev.path_of(actor_expr).ok_or_else(|| {
                ev.files.err(
                    K::UnknownActor,
                    actor_expr.span,
                    "expected an actor name, found an expression",
                )
            })?;
            let params = action_params(ev, &actor_path, &name.text);
            let args = ev.args(args, &params);
            let mut duration = None;
            let mut until = None;
            let mut modifiers = Vec::new();
            for (n, a) in &args {
                if n == "duration" {
                    duration = Some(positive_value(a.eval()?, &a.site)?);
                }
            }
            for w in with {
                match w {
                    WithMember::Modifier(m) => modifiers.push(modifier::read(ev, m)?),
                    // `until elapsed(d)`: the phase lasts at most d.
                    WithMember::Until(e, _) => match &e.kind {
                        ExprKind::Temporal(n, a) if n.text == "elapsed" => {
                            let d = match a.first() {
                                Some(a) => positive(ev, &a.value)?,
                                None => {
                                    return Err(ev.files.err(
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
                            let d = every_args(ev, e.span, a)?.offset;
                            if d <= 0.0 {
                                return Err(ev.files.err(
                                    K::Value,
                                    e.span,
                                    "expected an offset above 0 s in until every(…), found none (the first occurrence is the start of the phase, which would end it at once)",
                                ));
                            }
                            duration = Some(duration.map_or(d, |x: f64| x.min(d)));
                        }
                        _ => until = Some(cond::read(ev, e)),
                    },
                    WithMember::Keep(k) => {
                        return Err(ev.files.err(
                            K::Unsupported,
                            k.span,
                            "expected modifiers or until in an invocation's with:, found keep (not run yet)",
                        ))
                    }
                }
            }
            Ok(Phase {
                path,
                site: ev.site(*span),
                kind: Kind::Invoke(Invoke {
                    actor: actor_path,
                    actor_site: ev.site(actor_expr.span),
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
            site: ev.site(*span),
            kind: Kind::Emit(name.text.clone()),
            duration: None,
            until: None,
            children: Vec::new(),
        }),
        Behavior::Call(_, span) => Err(ev.files.err(
            K::Unsupported,
            *span,
            "expected a composition, wait, emit or action invocation, found call (not run yet)",
        )),
    }
}

/// Parameter names of `actor.action`, own first then inherited (as the checker binds them).
fn action_params(ev: &Eval<'_>, actor: &str, action: &str) -> Vec<String> {
    let Some(ty) = ev.lookup(actor).and_then(|(_, v)| ev.type_of(v)) else {
        return vec!["duration".into()];
    };
    let Some(b) = ev.model.behavior_of(ty, action) else {
        return vec!["duration".into()];
    };
    ev.model
        .ancestry(b)
        .into_iter()
        .flat_map(|c| ev.model.compound(c).fields.iter())
        .filter(|f| !f.is_var)
        .map(|f| f.name.clone())
        .collect()
}

fn non_negative(ev: &Eval<'_>, e: &Expr) -> Result<f64, Error> {
    match ev.eval(e)? {
        Val::Num(x) if x >= 0.0 && x.is_finite() => Ok(x),
        _ => Err(ev.files.err(
            K::Value,
            e.span,
            "expected a time of 0 s or more, found another value",
        )),
    }
}

fn positive(ev: &Eval<'_>, e: &Expr) -> Result<f64, Error> {
    positive_value(ev.eval(e)?, &ev.site(e.span))
}

fn positive_value(v: Val, site: &Site) -> Result<f64, Error> {
    match v {
        Val::Num(x) if x > 0.0 && x.is_finite() => Ok(x),
        _ => Err(site.err(
            K::Value,
            "expected a duration above 0 s, found another value",
        )),
    }
}
