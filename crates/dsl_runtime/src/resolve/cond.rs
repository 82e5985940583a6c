//! `until` and `wait` conditions, event declarations and `on` handlers' events, read (ASAM
//! OpenSCENARIO DSL 2.1 §7.3.9 `until`, §7.3.10 events `rise`/`fall`, `every`, `elapsed`; §8.7
//! methods of the domain model). The §8.7 methods become the 1.x conditions the engine evaluates
//! each step with its own domain functions; events and `every`/`elapsed` stay symbolic here and
//! become triggers in the planner, which knows their event context:
//!
//! | DSL | OpenSCENARIO 1.x condition |
//! | --- | --- |
//! | `a.time_headway(b) < x` | TimeHeadwayCondition, reference points, road coordinates, longitudinal |
//! | `a.time_to_collision(b) < x` | TimeToCollisionCondition on entity b, bounding boxes (freespace) |
//! | `a.space_gap(b, d) < x` | RelativeDistanceCondition, freespace, road coordinates, direction d |
//! | `a.object_distance(b, d, mode) < x` | RelativeDistanceCondition, freespace when mode is bounding_boxes |
//! | `a.speed > x` | SpeedCondition |
//! | `m(args) > x`, `m` declared `is external` | UserDefinedValueCondition on the value `m(args)` (arguments as JSON values), which the host sets to its function's result before each step |
//! | `rise(c)` / `fall(c)` / `c` | edge rising / falling / none (a plain condition ends the phase at the first step it holds) |
//! | `c1 and c2`, `c1 or c2` | one ConditionGroup, two ConditionGroups |
//! | `@e` of an `emit e` | StoryboardElementStateCondition: an emitting phase's startTransition |
//! | `@e` of `event e is c` | the condition c |
//! | `every(p, offset: o)` in an `on` handler | SimulationTimeEvery (oscsim's periodic condition): the step reaching o + k·p, k ≥ 0 (an invoked behavior's: t0 + o + k·p, t0 its invocation's start; after a run-time start counted from the step its Act starts in) |
//! | `every(p, offset: o)` in a `wait`/`until` (also through `@e`) | its first occurrence: o after the phase's start |
//! | `elapsed(d)` in an `on` handler or an event declaration | from d after the event context's start on: SimulationTime ≥ d (an `on`; an invoked behavior's ≥ t0 + d, or after a run-time start oscsim's ElapsedSinceStart on its Act), d after the phase's start (a `wait`/`until`) |
//!
//! `every` follows §7.3.10.4: occurrences at each multiple of the period from the start of the
//! *event context* (an `on` handler's: the scenario's start, which for an invoked scenario is
//! the invocation's start, `plan::events`; a `wait`'s or `until`'s: the
//! phase's start; a declared event's: that of the place it is used), all shifted by `offset`;
//! a point between two steps moves to the next step.
//!
//! Conditions measure the world as it stood at the step's start (the engine's trigger rule).

use dsl::semantics::hir::{Arg as HirArg, BinOp, Expr, ExprKind, Span};
use scenario::{
    ByValueCondition, Condition, ConditionEdge, ConditionKind, CoordinateSystem, DistanceMeasure,
    EntityCondition, RelativeDistanceType, Rule, TimeToCollisionTarget,
};

use super::eval::Eval;
use super::value::Val;
use crate::error::{Error, ErrorKind as K, Site};

/// A condition, read.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Cond {
    /// `a or b`: the condition groups of both.
    Or(Box<Cond>, Box<Cond>),
    /// `a and b`: every group of a with every group of b.
    And(Box<Cond>, Box<Cond>),
    /// `@e`: the occurrence of the event named (`None`: not written as a name).
    Event(Option<String>, Site),
    /// A §8.7 method or `speed` compared with a value: the 1.x condition, and the actor paths
    /// it names (the subject, then the reference), each of which must be an entity of the plan.
    Measured {
        /// The condition, entities named by their paths.
        condition: Box<Condition>,
        /// The actor paths and where each is written (`None`: not a path).
        actors: Vec<(Option<String>, Site)>,
        /// For a `var x = sample(m, e)` compared: the sampling event e (`every(p, offset: o)`,
        /// `@e`, `rise(…)`, …), in the scenario's event context; the value is read at its
        /// occurrences only.
        sampled: Option<Box<Cond>>,
        /// An external method compared (`m(…) > 3`): its call, whose content names the
        /// user-defined value the host sets each step.
        external: Option<super::call::Call>,
    },
    /// `every(…)` or `elapsed(…)`, counted in the condition's event context.
    Timed(Timed, Site),
}

/// An event condition on the time since the start of the event context (§7.3.10.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Timed {
    /// `every(…)`.
    Every(Every),
    /// `elapsed(d)`: true from d on (s, 0 or more).
    Elapsed(f64),
}

/// The arguments of `every(period [, offset: o])` (s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Every {
    /// Above 0.
    pub period: f64,
    /// 0 or more (0 when not given: the first occurrence is the start of the event context).
    pub offset: f64,
}

/// Reads `every(…)`'s arguments: a period above 0 s and an offset of 0 s or more.
pub(crate) fn every_args(ctx: &Eval<'_>, span: Span, args: &[HirArg]) -> Result<Every, Error> {
    let time = |a: &HirArg, positive: bool| -> Result<f64, Error> {
        match ctx.eval(&a.value)? {
            Val::Num(x) if x.is_finite() && (x > 0.0 || (!positive && x == 0.0)) => Ok(x),
            _ => Err(ctx.files.err(
                K::Value,
                a.value.span,
                if positive {
                    "expected a period above 0 s in every(…), found another value"
                } else {
                    "expected an offset of 0 s or more in every(…), found another value"
                },
            )),
        }
    };
    let period = match args.first() {
        Some(a) => time(a, true)?,
        None => {
            return Err(ctx
                .files
                .err(K::Value, span, "expected a period in every(…), found none"))
        }
    };
    let offset = args
        .get(1)
        .map(|a| time(a, false))
        .transpose()?
        .unwrap_or(0.0);
    Ok(Every { period, offset })
}

/// Reads a DSL condition.
pub(crate) fn read(ctx: &Eval<'_>, e: &Expr) -> Result<Cond, Error> {
    read_edge(ctx, e, ConditionEdge::None)
}

fn read_edge(ctx: &Eval<'_>, e: &Expr, edge: ConditionEdge) -> Result<Cond, Error> {
    match &e.kind {
        ExprKind::Temporal(n, args) if n.text == "@" => {
            let name = args.first().and_then(|a| match &a.value.kind {
                ExprKind::Name(x) => Some(ctx.event_key(x)),
                _ => None,
            });
            Ok(Cond::Event(name, ctx.site(e.span)))
        }
        ExprKind::Binary(BinOp::Or, a, b) => Ok(Cond::Or(
            Box::new(read_edge(ctx, a, edge)?),
            Box::new(read_edge(ctx, b, edge)?),
        )),
        ExprKind::Binary(BinOp::And, a, b) => Ok(Cond::And(
            Box::new(read_edge(ctx, a, edge)?),
            Box::new(read_edge(ctx, b, edge)?),
        )),
        ExprKind::Temporal(n, args) if n.text == "rise" || n.text == "fall" => {
            let inner = args.first().ok_or_else(|| {
                ctx.files.err(
                    K::Condition,
                    e.span,
                    format!("expected a condition in {}(…), found none", n.text),
                )
            })?;
            let edge = if n.text == "rise" {
                ConditionEdge::Rising
            } else {
                ConditionEdge::Falling
            };
            read_edge(ctx, &inner.value, edge)
        }
        ExprKind::Binary(op, a, b) => {
            let (rule, flip) = match op {
                BinOp::Lt => (Rule::LessThan, Rule::GreaterThan),
                BinOp::Le => (Rule::LessOrEqual, Rule::GreaterOrEqual),
                BinOp::Gt => (Rule::GreaterThan, Rule::LessThan),
                BinOp::Ge => (Rule::GreaterOrEqual, Rule::LessOrEqual),
                BinOp::Eq => (Rule::EqualTo, Rule::EqualTo),
                BinOp::Ne => (Rule::NotEqualTo, Rule::NotEqualTo),
                _ => return Err(unsupported(ctx, e)),
            };
            let (measure, value, rule) = match (ctx.number(b), ctx.number(a)) {
                (Ok(v), _) => (a, v, rule),
                (Err(_), Ok(v)) => (b, v, flip),
                (Err(err), Err(_)) => return Err(err),
            };
            let mut actors = Vec::new();
            // A sampled variable: its method, read every period (§7.3.10 `sample`).
            let (measure, sampled) = match sampled_var(ctx, measure)? {
                Some((inner, event)) => (inner, Some(Box::new(event))),
                None => (&**measure, None),
            };
            // An external method's result: a value the host provides each step.
            let external = super::call::external(ctx, measure)?;
            let kind = match &external {
                Some(c) => ConditionKind::ByValue(ByValueCondition::UserDefinedValue {
                    name: c.content.clone(),
                    rule,
                    value: format!("{value}"),
                }),
                None => measured(ctx, measure, value, rule, &mut actors)?,
            };
            Ok(Cond::Measured {
                external,
                condition: Box::new(Condition {
                    name: format!("until@{}", ctx.site(e.span).at()),
                    // A sampled value changes only at its samples: the edge is read there
                    // (below, `sampled_var`).
                    condition_edge: if sampled.is_some() {
                        ConditionEdge::None
                    } else {
                        edge
                    },
                    delay: 0.0,
                    kind,
                    pos: ctx.site(e.span).pos,
                }),
                actors,
                sampled,
            })
        }
        ExprKind::Temporal(n, args) if n.text == "every" => Ok(Cond::Timed(
            Timed::Every(every_args(ctx, e.span, args)?),
            ctx.site(e.span),
        )),
        ExprKind::Temporal(n, args) if n.text == "elapsed" => {
            let d = match args.first().map(|a| ctx.eval(&a.value)).transpose()? {
                Some(Val::Num(d)) if d.is_finite() && d >= 0.0 => d,
                _ => {
                    return Err(ctx.files.err(
                        K::Value,
                        e.span,
                        "expected a time of 0 s or more in elapsed(…), found another value",
                    ))
                }
            };
            Ok(Cond::Timed(Timed::Elapsed(d), ctx.site(e.span)))
        }
        _ => Err(unsupported(ctx, e)),
    }
}

impl Cond {
    /// The external methods the condition reads, with where each comparison is written.
    pub(crate) fn externals(&self, out: &mut Vec<(super::call::Call, scenario::SourcePos)>) {
        match self {
            Cond::Or(a, b) | Cond::And(a, b) => {
                a.externals(out);
                b.externals(out);
            }
            Cond::Measured {
                external: Some(c),
                condition,
                ..
            } => out.push((c.clone(), condition.pos.clone())),
            _ => {}
        }
    }
}

/// When `e` names a `var` of the scenario declared `= sample(m, e)` (§7.3.10.5 "sample the
/// value of an expression when an event occurs"): the expression m and the event e, read as
/// a condition of its own (`every(p, offset: o)`: samples at o + k·p from the scenario's start;
/// `@e` of an emitted or declared event; `rise(…)`, `fall(…)`, `elapsed(d)`). The variable's
/// value changes only at the occurrences of e; a comparison of it holds from an occurrence at
/// which m satisfies it to the next one. So `rise(x < v)` in an `until` or `wait` is read as the
/// first occurrence at which m < v (an occurrence at which it held before cannot have been
/// followed by a rise in a phase that was still waiting for one, unless it held at the phase's
/// start: docs/dsl.md). The sample's default (its third argument) is the value before the
/// first occurrence, at which no comparison is read.
fn sampled_var<'e>(ctx: &Eval<'e>, e: &Expr) -> Result<Option<(&'e Expr, Cond)>, Error> {
    let ExprKind::Name(n) = &e.kind else {
        return Ok(None);
    };
    let Some(decl) = ctx.model.compounds.iter().find(|c| c.name == ctx.root) else {
        return Ok(None);
    };
    let default = decl.members.iter().find_map(|m| match m {
        dsl::semantics::hir::Member::Field(f)
            if f.is_var && f.names.iter().any(|x| &x.text == n) =>
        {
            f.default.as_ref()
        }
        _ => None,
    });
    let Some(ExprKind::Temporal(s, args)) = default.map(|d| &d.kind) else {
        return Ok(None);
    };
    if s.text != "sample" {
        return Ok(None);
    }
    let (Some(inner), Some(event)) = (args.first(), args.get(1)) else {
        return Ok(None);
    };
    Ok(Some((&inner.value, read(ctx, &event.value)?)))
}

fn unsupported(ctx: &Eval<'_>, e: &Expr) -> Error {
    ctx.files.err(
        K::Condition,
        e.span,
        "expected a comparison of a §8.7 method or speed with a value (or rise/fall/and/or of such), found another expression",
    )
}

/// The 1.x condition of `measure rule value`; the actor paths it names are pushed on `actors`.
fn measured(
    ctx: &Eval<'_>,
    measure: &Expr,
    value: f64,
    rule: Rule,
    actors: &mut Vec<(Option<String>, Site)>,
) -> Result<ConditionKind, Error> {
    let mut actor = |e: &Expr| -> String {
        let path = ctx.path_of(e);
        actors.push((path.clone(), ctx.site(e.span)));
        path.unwrap_or_default()
    };
    let by = |who: String, c: EntityCondition| ConditionKind::by_entity(who, c);
    let measure_of = |freespace: bool, dir: Option<RelativeDistanceType>| DistanceMeasure {
        freespace,
        coordinate_system: Some(CoordinateSystem::Road),
        relative_distance_type: dir,
        routing_algorithm: None,
    };
    match &measure.kind {
        ExprKind::Field(obj, f) if f.text == "speed" => Ok(by(
            actor(obj),
            EntityCondition::Speed {
                value,
                rule,
                direction: None,
            },
        )),
        ExprKind::Call(callee, args) => {
            let ExprKind::Field(obj, method) = &callee.kind else {
                return Err(unsupported(ctx, measure));
            };
            let who = actor(obj);
            let arg = |name: &str, i: usize| {
                args.iter()
                    .find(|a| a.name.as_ref().is_some_and(|n| n.text == name))
                    .or_else(|| args.get(i).filter(|a| a.name.is_none()))
                    .map(|a| &a.value)
            };
            let reference = match arg("reference", 0) {
                Some(r) => actor(r),
                None => {
                    return Err(ctx.files.err(
                        K::Condition,
                        measure.span,
                        "expected a reference argument, found none",
                    ))
                }
            };
            let direction = |i: usize| -> Result<Option<RelativeDistanceType>, Error> {
                Ok(
                    match arg("direction", i).map(|d| ctx.eval(d)).transpose()? {
                        Some(Val::Enum(d)) if d == "lateral" => Some(RelativeDistanceType::Lateral),
                        _ => Some(RelativeDistanceType::Longitudinal),
                    },
                )
            };
            let c = match method.text.as_str() {
                "time_headway" => EntityCondition::TimeHeadway {
                    entity_ref: reference,
                    value,
                    rule,
                    measure: measure_of(false, Some(RelativeDistanceType::Longitudinal)),
                },
                "time_to_collision" => EntityCondition::TimeToCollision {
                    target: TimeToCollisionTarget::EntityRef(reference),
                    value,
                    rule,
                    measure: DistanceMeasure {
                        freespace: true,
                        coordinate_system: None,
                        relative_distance_type: None,
                        routing_algorithm: None,
                    },
                },
                "space_gap" => EntityCondition::RelativeDistance {
                    entity_ref: reference,
                    value,
                    rule,
                    measure: measure_of(true, direction(1)?),
                },
                "object_distance" => {
                    let boxes = matches!(
                        arg("mode", 2).map(|m| ctx.eval(m)).transpose()?,
                        Some(Val::Enum(m)) if m == "bounding_boxes"
                    );
                    EntityCondition::RelativeDistance {
                        entity_ref: reference,
                        value,
                        rule,
                        measure: measure_of(boxes, direction(1)?),
                    }
                }
                _ => return Err(unsupported(ctx, measure)),
            };
            Ok(by(who, c))
        }
        _ => Err(unsupported(ctx, measure)),
    }
}
