//! The phase tree of a scenario's `do` (ASAM OpenSCENARIO DSL 2.1 §7.3.9 behavior
//! specification): compositions `serial`, `parallel` (its `overlap:` read by `overlap`),
//! `one_of` (its member chosen from the run's seed), `wait`, `emit`, and invocations of actions on actors with their arguments,
//! `with:` modifiers and `until`, every value evaluated. Each phase has a path: the labels (or,
//! unlabelled, the member's index) from the root `do` down, joined by `.` (`do.get_ahead.1`);
//! it is the phase's name in the event log.
//!
//! An invocation of a behavior with a `do` of its own (a user scenario, or a scenario declared
//! on an actor, §7.3.9) is that behavior's `do` tree, read in the invocation's frame (its
//! parameters, its actor) and planted at the invocation's path: `do.round_two` is the invoked
//! `do`'s root and `do.round_two.slow` its member labelled `slow` (the invoked `do`'s own label
//! is not part of the path). The invocation's `until` ends that root too.

use dsl::semantics::hir::{
    Arg as HirArg, Behavior, CompositionOp, Expr, ExprKind, Keep, Labeled, Member, Span, WithMember,
};
use dsl::semantics::types::{CompoundId, Ty};

use super::action::Action;
use super::cond::{self, every_args, Cond};
use super::eval::{Eval, Frame};
use super::modifier::{self, Modifier};
use super::position::{self, PlaceArg};
use super::route::LaneField;
use super::value::{Arg, Args, Val};
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
    /// `parallel`: members together, related in time by its `overlap:` argument (none: the
    /// members start together and each ends as it does, `plan::overlap`).
    Parallel(Option<super::overlap::OverlapArg>),
    /// `one_of`: the member drawn (its index among the written members).
    OneOf(usize),
    /// `wait`.
    Wait,
    /// `emit event`: an instant phase that `@event` conditions observe.
    Emit(String),
    /// `call m(…)`: an instant phase in which the host runs external method m.
    Call(super::Call),
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
    /// The action's name as written (`drive`).
    pub action: String,
    /// Which §8.8 action it is.
    pub kind: Action,
    /// The action's arguments by parameter name (positional ones bound in declaration order,
    /// own parameters first, as the checker binds them).
    pub args: Args,
    /// Its position and orientation arguments, read (`assign_position`, `change_position`,
    /// `assign_orientation`).
    pub places: Vec<PlaceArg>,
    /// The lane field of `change_lane(target: l)` / `follow_lane(target: l)`.
    pub lane_target: Option<LaneField>,
    /// Modifiers in order: those written, then those its semantic clarification implies
    /// (`remain_stationary()` is `move() with: keep_position()`, §8.8.2.10).
    pub modifiers: Vec<Modifier>,
}

impl Invoke {
    /// Every argument of the invocation with its name: the action's own (`None`), then each
    /// modifier's (`Some(modifier)`), in order.
    pub(crate) fn all_args(&self) -> impl Iterator<Item = (Option<&Modifier>, &String, &Arg)> {
        self.args.iter().map(|(n, a)| (None, n, a)).chain(
            self.modifiers
                .iter()
                .flat_map(|m| m.args.iter().map(move |(n, a)| (Some(m), n, a))),
        )
    }
}

/// An invocation of a behavior with a `do`, entered while the tree was built: the frame its
/// names are read in and the behavior (whose events the scenario then has too).
#[derive(Debug, Clone)]
pub(crate) struct Entered {
    /// The invocation's frame.
    pub frame: Frame,
    /// The invoked behavior.
    pub behavior: CompoundId,
    /// The invocation's phase path (`do.round_two`): its `on` handlers run while it does.
    pub path: String,
}

/// Deepest nesting of invocations (the checker reports recursive ones; this guards the stack).
const MAX_INVOCATION_DEPTH: usize = 64;

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

/// The path of a `do`'s root below the behavior's instance: `do`, or `do.LABEL`.
fn root_path(root: &Labeled) -> String {
    match &root.label {
        Some(l) => format!("do.{}", l.text),
        None => "do".to_string(),
    }
}

/// Builds the phase tree of the entry scenario's `do` member `root`; `entered` collects the
/// invocations of behaviors with a `do`.
pub(crate) fn build_root(
    ev: &Eval<'_>,
    root: &Labeled,
    entered: &mut Vec<Entered>,
) -> Result<Phase, Error> {
    let path = root_path(root);
    build(ev, root, path.clone(), &path, 0, entered)
}

/// Builds the phase of `root` at phase path `path`; `site_path` is its path in the `do` of the
/// behavior it is written in (the invocations' names in the resolution), `depth` the number of
/// enclosing invocations.
fn build(
    ev: &Eval<'_>,
    root: &Labeled,
    path: String,
    site_path: &str,
    depth: usize,
    entered: &mut Vec<Entered>,
) -> Result<Phase, Error> {
    match &root.behavior {
        Behavior::Composition {
            op,
            args,
            children,
            with,
            span,
        } => {
            let mut duration = None;
            let mut overlap = None;
            for (name, e) in super::eval::bind(args, &["duration".to_string()]) {
                match name.as_str() {
                    "duration" => duration = Some(positive(ev, e)?),
                    "overlap" if *op == CompositionOp::Parallel => {
                        overlap = Some(super::overlap::read(ev, e)?)
                    }
                    other => {
                        let which = match op {
                            CompositionOp::Parallel => "`duration:` or `overlap:`",
                            _ => "`duration:` (`overlap:` is parallel's)",
                        };
                        return Err(ev.files.err(
                            K::Argument,
                            e.span,
                            format!("expected a {which} argument, found `{other}:`"),
                        ));
                    }
                }
            }
            let kind = match op {
                CompositionOp::Serial => Kind::Serial,
                CompositionOp::Parallel => Kind::Parallel(overlap),
                CompositionOp::OneOf => Kind::OneOf(ev.choose(children.len())),
            };
            let picked: Vec<(usize, &Labeled)> = match kind {
                Kind::OneOf(i) => children.iter().enumerate().skip(i).take(1).collect(),
                _ => children.iter().enumerate().collect(),
            };
            let mut out = Vec::new();
            for (i, c) in picked {
                let seg = c.label.as_ref().map_or(i.to_string(), |l| l.text.clone());
                let site = format!("{site_path}.{seg}");
                out.push(build(
                    ev,
                    c,
                    format!("{path}.{seg}"),
                    &site,
                    depth,
                    entered,
                )?);
            }
            if out.is_empty() {
                return Err(ev.files.err(
                    K::NoEnd,
                    *span,
                    "expected members in a composition, found none",
                ));
            }
            // The composition's with: (§7.3.9): its `until` ends it as an invocation's does; a
            // `keep` is a constraint of the behavior whose `do` holds it, solved with its
            // instance (the checker's); a modifier is the checker's error.
            let mut until = None;
            for w in with {
                match w {
                    WithMember::Until(e, _) => with_until(ev, e, &mut duration, &mut until)?,
                    WithMember::Keep(_) => {}
                    WithMember::Modifier(m) => {
                        return Err(ev.files.err(
                            K::Modifier,
                            m.span,
                            format!("expected `until` or `keep` in the with: of a composition, found the modifier `{}`", m.name.text),
                        ))
                    }
                }
            }
            Ok(Phase {
                path,
                site: ev.site(*span),
                kind,
                duration,
                until,
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
            let actor_path = match actor {
                Some(a) => Some(ev.path_of(a).ok_or_else(|| {
                    ev.files.err(
                        K::UnknownActor,
                        a.span,
                        "expected an actor name, found an expression",
                    )
                })?),
                // In a behavior declared on an actor, `drive()` is `actor.drive()`.
                None => ev.frame.actor.clone(),
            };
            if let Some(callee) = invoked_behavior(ev, actor_path.as_deref(), &name.text) {
                let inv = Invocation {
                    callee,
                    actor: actor_path,
                    args,
                    with,
                    span: *span,
                };
                return behavior(ev, &inv, path, site_path, depth, entered);
            }
            let Some(actor_path) = actor_path else {
                return Err(ev.files.err(
                    K::Invocation,
                    *span,
                    format!(
                        "expected an actor before `{}`, or a scenario with a `do`, found neither",
                        name.text
                    ),
                ));
            };
            let (kind, params) = action_params(ev, &actor_path, &name.text);
            let places = position::read(ev, kind, args, &params)?;
            let mut args = ev.args(args, &params);
            let keeps: Vec<&Keep> = with
                .iter()
                .filter_map(|w| match w {
                    WithMember::Keep(k) => Some(k),
                    _ => None,
                })
                .collect();
            if !keeps.is_empty() {
                solved_args(ev, site_path, &params, &keeps, &mut args)?;
            }
            let lane_target = match (kind, super::value::arg(&args, "target")) {
                (Action::ChangeLane | Action::FollowLane, Some(a)) => {
                    Some(super::route::lane_field(ev, a)?)
                }
                _ => None,
            };
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
                    WithMember::Until(e, _) => with_until(ev, e, &mut duration, &mut until)?,
                    // Solved with the invocation's instance (`solved_args`).
                    WithMember::Keep(_) => {}
                }
            }
            let site = ev.site(*span);
            // along(…) of a path: follow_path along it.
            let mut places = places;
            let kind = super::along_path::follow(kind, &mut places, &mut args, &mut modifiers)?;
            modifiers.extend(modifier::implied(kind, &name.text, &site));
            Ok(Phase {
                path,
                site,
                kind: Kind::Invoke(Invoke {
                    actor: actor_path,
                    actor_site: ev.site(actor.as_ref().map_or(*span, |a| a.span)),
                    action: name.text.clone(),
                    kind,
                    args,
                    places,
                    lane_target,
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
            kind: Kind::Emit(ev.event_key(&name.text)),
            duration: None,
            until: None,
            children: Vec::new(),
        }),
        Behavior::Call(e, span) => Ok(Phase {
            path,
            site: ev.site(*span),
            kind: Kind::Call(super::call::read(ev, e)?),
            duration: None,
            until: None,
            children: Vec::new(),
        }),
    }
}

/// An `until` of a `with:` block (an invocation's or a composition's): `until elapsed(d)`
/// caps the phase's `duration` at d, `until every(p, offset: o)` at o (its first occurrence
/// after the phase's start), any other condition is the phase's `until`.
fn with_until(
    ev: &Eval<'_>,
    e: &Expr,
    duration: &mut Option<f64>,
    until: &mut Option<Result<Cond, Error>>,
) -> Result<(), Error> {
    let d = match &e.kind {
        ExprKind::Temporal(n, a) if n.text == "elapsed" => match a.first() {
            Some(a) => positive(ev, &a.value)?,
            None => {
                return Err(ev.files.err(
                    K::Value,
                    e.span,
                    "expected a time in elapsed(…), found none",
                ))
            }
        },
        // The first occurrence, o after the phase's start, ends it; without an offset that is
        // its start.
        ExprKind::Temporal(n, a) if n.text == "every" => {
            let d = every_args(ev, e.span, a)?.offset;
            if d <= 0.0 {
                return Err(ev.files.err(
                    K::Value,
                    e.span,
                    "expected an offset above 0 s in until every(…), found none (the first occurrence is the start of the phase, which would end it at once)",
                ));
            }
            d
        }
        _ => {
            *until = Some(cond::read(ev, e));
            return Ok(());
        }
    };
    *duration = Some(duration.map_or(d, |x: f64| x.min(d)));
    Ok(())
}

/// The pieces of an invocation of a behavior with a `do`.
struct Invocation<'h> {
    callee: CompoundId,
    /// The actor it is invoked on, as a path.
    actor: Option<String>,
    args: &'h [HirArg],
    with: &'h [WithMember],
    span: Span,
}

/// The behavior with a `do` that `actor.name` (or `name` without an actor) invokes, if it
/// is one (the library's actions have none).
fn invoked_behavior(ev: &Eval<'_>, actor: Option<&str>, name: &str) -> Option<CompoundId> {
    let id = match actor {
        Some(a) => {
            let ty = ev.lookup(a).and_then(|(_, v)| ev.type_of(v))?;
            ev.model.behavior_of(ty, name)?
        }
        None => *ev.model.behaviors.get(name)?,
    };
    do_of(ev, id).map(|_| id)
}

/// The `do` of behavior `id` (or of its nearest ancestor that has one).
fn do_of<'m>(ev: &Eval<'m>, id: CompoundId) -> Option<&'m Labeled> {
    ev.model.ancestry(id).into_iter().find_map(|c| {
        ev.model.compound(c).members.iter().find_map(|m| match m {
            Member::Do(d, _) => Some(d),
            _ => None,
        })
    })
}

/// The phase of an invocation of a behavior with a `do`: that `do`'s tree read in a frame of
/// its own (parameters given an instance of the caller's name it; the others are the
/// invocation's instance's fields, which the solver resolved with the arguments), at `path`,
/// ended also by the invocation's `until`.
fn behavior(
    ev: &Eval<'_>,
    inv: &Invocation<'_>,
    path: String,
    site_path: &str,
    depth: usize,
    entered: &mut Vec<Entered>,
) -> Result<Phase, Error> {
    let name = ev.model.compound(inv.callee).name.clone();
    if depth >= MAX_INVOCATION_DEPTH {
        return Err(ev.files.err(
            K::Unsupported,
            inv.span,
            format!("expected invocations nested at most {MAX_INVOCATION_DEPTH} deep, found `{name}` deeper"),
        ));
    }
    let params: Vec<String> = ev
        .model
        .ancestry(inv.callee)
        .into_iter()
        .flat_map(|c| ev.model.compound(c).fields.iter())
        .filter(|f| !f.is_var)
        .map(|f| f.name.clone())
        .collect();
    let mut aliases = Vec::new();
    for (p, e) in super::eval::bind(inv.args, &params) {
        let is_instance = ev
            .model
            .field(inv.callee, &p)
            .is_some_and(|f| matches!(f.ty, Ty::Compound(_)));
        if is_instance {
            let target = ev.path_of(e).ok_or_else(|| {
                ev.files.err(
                    K::Value,
                    e.span,
                    format!("expected an instance's name for parameter `{p}` of `{name}`, found an expression"),
                )
            })?;
            aliases.push((p, target));
        }
    }
    let mut until = None;
    for w in inv.with {
        match w {
            WithMember::Until(e, _) => until = Some(cond::read(ev, e)),
            // Solved with the invocation's instance (`it`).
            WithMember::Keep(_) => {}
            WithMember::Modifier(m) => {
                return Err(ev.files.err(
                    K::Modifier,
                    m.span,
                    format!(
                        "expected `until` or `keep` in the with: of an invocation of `{name}`, found the modifier `{}` (modifiers apply to the standard library's movement actions, not to a behavior that runs a `do` of its own)",
                        m.name.text
                    ),
                ))
            }
        }
    }
    let frame = Frame {
        prefix: format!("{}{site_path}.", ev.frame.prefix),
        aliases,
        actor: inv.actor.clone(),
    };
    let inner = ev.enter(frame.clone());
    // The invocation was found by its `do`.
    let Some(root) = do_of(ev, inv.callee) else {
        return Err(ev.files.err(
            K::Invocation,
            inv.span,
            format!("expected a `do` in `{name}`, found none"),
        ));
    };
    entered.push(Entered {
        frame,
        behavior: inv.callee,
        path: path.clone(),
    });
    let mut phase = build(&inner, root, path, &root_path(root), depth + 1, entered)?;
    phase.site = ev.site(inv.span);
    if let Some(u) = until {
        phase.until = Some(match phase.until.take() {
            None => u,
            Some(own) => own.and_then(|a| u.map(|b| Cond::Or(Box::new(a), Box::new(b)))),
        });
    }
    Ok(phase)
}

/// Which action `actor.action` is, and its parameter names, own first then inherited (as the
/// checker binds them). An action the program declares (not the standard library) is
/// [`Action::Other`], whatever its name.
/// The arguments of an action invocation with `keep(…)` in its `with:` (§7.3.9
/// behavior-with-member): the invocation is an instance of the action the solver resolved with
/// its arguments (`it.p == argument`, `in` for a range) and those constraints, at the
/// invocation's path (`{prefix}{site_path}`, as an invoked scenario's), with the scenario's
/// seed. Each parameter given as an argument, or named by a keep as `it.p`, takes the solver's
/// value (a range argument is then drawn within the keep); parameters neither gives stay
/// absent, as without a keep (the solver's sample of them is not read). Instance arguments
/// (actors, structs) are the caller's own instances, unchanged.
fn solved_args(
    ev: &Eval<'_>,
    site_path: &str,
    params: &[String],
    keeps: &[&Keep],
    args: &mut Args,
) -> Result<(), Error> {
    let instance = format!("{}{site_path}", ev.frame.prefix);
    if ev.lookup(&instance).is_none() {
        // The checker records an instance for every invocation in a `do`; one elsewhere (an
        // `on` handler, whose members are `emit` and `call`, §7.3.10) the parser refuses first.
        return Err(ev.files.err(
            K::Invocation,
            keeps[0].span,
            "expected keep(…) in the with: of an invocation in a `do` (where the solver resolves the invocation), found it elsewhere",
        ));
    }
    let mut named: Vec<(String, Span)> = Vec::new();
    for k in keeps {
        it_fields(&k.expr, k.span, &mut named);
    }
    for p in params {
        let from_keep = named.iter().find(|(n, _)| n == p).map(|(_, s)| *s);
        let given = args.iter().position(|(n, _)| n == p);
        if from_keep.is_none() && given.is_none() {
            continue;
        }
        let value = match ev.value_at(&format!("{instance}.{p}")) {
            Some(Val::Instance(_)) | None => continue,
            Some(v) => v,
        };
        match (given, from_keep) {
            (Some(i), _) => args[i].1.value = Ok(value),
            (None, Some(span)) => args.push((
                p.clone(),
                Arg {
                    site: ev.site(span),
                    path: None,
                    value: Ok(value),
                },
            )),
            (None, None) => {}
        }
    }
    Ok(())
}

/// The fields `e` names on `it` (`it.target`), with the keep's span.
fn it_fields(e: &Expr, span: Span, out: &mut Vec<(String, Span)>) {
    let mut sub = |x: &Expr| it_fields(x, span, out);
    match &e.kind {
        ExprKind::Field(inner, n) if matches!(inner.kind, ExprKind::It) => {
            out.push((n.text.clone(), span))
        }
        ExprKind::Field(a, _)
        | ExprKind::Neg(a)
        | ExprKind::Not(a)
        | ExprKind::Cast(a, _)
        | ExprKind::TypeTest(a, _) => sub(a),
        ExprKind::Index(a, b) | ExprKind::Binary(_, a, b) | ExprKind::Range(a, b) => {
            sub(a);
            sub(b);
        }
        ExprKind::Ternary(a, b, c) => {
            sub(a);
            sub(b);
            sub(c);
        }
        ExprKind::List(xs) => xs.iter().for_each(sub),
        ExprKind::Call(f, xs) => {
            sub(f);
            xs.iter().for_each(|x| sub(&x.value));
        }
        ExprKind::Temporal(_, xs) => xs.iter().for_each(|x| sub(&x.value)),
        _ => {}
    }
}

fn action_params(ev: &Eval<'_>, actor: &str, action: &str) -> (Action, Vec<String>) {
    let fallback = (Action::Other, vec!["duration".into()]);
    let Some(ty) = ev.lookup(actor).and_then(|(_, v)| ev.type_of(v)) else {
        return fallback;
    };
    let Some(b) = ev.model.behavior_of(ty, action) else {
        return fallback;
    };
    // An action the program declares without a `do` of its own (one with a `do` runs it,
    // `behavior`) has the meaning of the nearest library action it inherits (`action
    // vehicle.brake inherits movable_object.change_speed` is a change_speed), if any.
    let kind = ev
        .model
        .ancestry(b)
        .into_iter()
        .map(|c| ev.model.compound(c))
        .filter(|c| c.span.file.0 < ev.model.library_files)
        .map(|c| Action::of_library(&c.short))
        .find(|k| *k != Action::Other)
        .unwrap_or(Action::Other);
    let params = ev
        .model
        .ancestry(b)
        .into_iter()
        .flat_map(|c| ev.model.compound(c).fields.iter())
        .filter(|f| !f.is_var)
        .map(|f| f.name.clone())
        .collect();
    (kind, params)
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
