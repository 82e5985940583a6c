//! Coverage members of the scenario that runs (ASAM OpenSCENARIO DSL 2.1 §7.3.12, `cover(…)`
//! and `record(…)`) resolved into plain data for the runtime: what to sample (an expression
//! over the run's state with the §8.7 methods, or over resolved values), when (the sampling
//! event), in which unit, into which buckets, and what to ignore. The planner does not read
//! coverage (it does not change the motion); it travels past the plan to `Lowered`, the front
//! door (`load`) samples it against the engine's frames, and a batch counts the buckets.
//! docs/dsl.md, "Coverage", has the choices.
//!
//! Arguments (§7.3.12): `name` (first positional; when `expression` is absent, the name is a
//! field of the scenario and its value is sampled), `expression`, `unit` (a unit of the
//! expression's physical type: the value is reported and bucketed in it), `range` (`[a..b]`,
//! with or without units; plain numbers are in `unit`), `every` (the bucket width, in
//! `unit`), `ignore` (a boolean expression: a sample for which it holds is dropped), `event`
//! (`start`, `end`, or an event the scenario emits; default `end`), `text` (a description).
//! `record` takes no `range`, `every` or `ignore`.

use dsl::semantics::hir::{Arg, Behavior, BinOp, CoverageKind, Expr, ExprKind, Labeled, Member};
use scenario::SourcePos;

use super::eval::{bind, bound_to, Eval as Ctx};
use super::value::Val;
use crate::error::{Error, ErrorKind as K};

/// When an item is sampled.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SampleAt {
    /// The scenario's start: the frame at t = 0.
    Start,
    /// The scenario's end: the last frame of the run (the default).
    End,
    /// Each emission of this event (`emit e`, `on …: emit e`): the frame of its step.
    Event(String),
}

/// A unit a value is reported in: SI value = value · factor + offset.
#[derive(Debug, Clone, PartialEq)]
pub struct CoverUnit {
    /// Its name (`kph`).
    pub name: String,
    /// SI value of one unit.
    pub factor: f64,
    /// SI value of zero units.
    pub offset: f64,
}

/// How a cover item's values fall into buckets.
#[derive(Debug, Clone, PartialEq)]
pub enum Buckets {
    /// None: a `record`, or a number without `range`.
    None,
    /// `range: [low..high]` in the item's unit, cut every `every` (one bucket without it).
    Range {
        /// Lower end (included).
        low: f64,
        /// Upper end (included in the last bucket).
        high: f64,
        /// Bucket width.
        every: Option<f64>,
    },
    /// One bucket per member of the expression's enum (declaration order), or `false`, `true`.
    Members(Vec<String>),
}

/// A binary operator of a sampled expression.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunOp {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `==`
    Eq,
    /// `!=`
    Ne,
    /// `and`
    And,
    /// `or`
    Or,
}

/// Which way a §8.7 distance is measured (`distance_direction`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// Along the road (or the object's x axis).
    Longitudinal,
    /// Across it.
    Lateral,
}

/// An expression the runtime evaluates on a frame: numbers in SI units.
#[derive(Debug, Clone, PartialEq)]
pub enum RunExpr {
    /// A number (SI), a resolved value or a literal.
    Num(f64),
    /// A boolean.
    Bool(bool),
    /// An enum member.
    Enum(String),
    /// `a.speed` (§8.7 movable_object), m/s.
    Speed(String),
    /// `a.space_gap(b, direction)` (§8.7.5.1.3), m.
    SpaceGap(String, String, Direction),
    /// `a.object_distance(b, direction, mode)` (§8.7.2.1.1), m; `true`: bounding boxes.
    ObjectDistance(String, String, Direction, bool),
    /// `a.time_headway(b)` (§8.7.5.1.2), s.
    TimeHeadway(String, String),
    /// `a.time_to_collision(b)` (§8.7.5.1.1), s.
    TimeToCollision(String, String),
    /// `a.get_s_coord()` (§8.7.2.1.2, on_road), m.
    SCoord(String),
    /// `a.get_t_coord()` (§8.7.2.1.2, on_road), m.
    TCoord(String),
    /// `-e`.
    Neg(Box<RunExpr>),
    /// `not e`.
    Not(Box<RunExpr>),
    /// `a op b`.
    Binary(RunOp, Box<RunExpr>, Box<RunExpr>),
}

/// A `cover(…)` or `record(…)` of the scenario.
#[derive(Debug, Clone, PartialEq)]
pub struct CoverItem {
    /// Its name (the results table's column `cover:NAME` or `record:NAME`).
    pub name: String,
    /// `cover` or `record`.
    pub kind: CoverageKind,
    /// What is sampled.
    pub expr: RunExpr,
    /// The unit of a physical value (`None`: SI, or not a number).
    pub unit: Option<CoverUnit>,
    /// The buckets of a `cover`.
    pub buckets: Buckets,
    /// Samples for which this holds are dropped.
    pub ignore: Option<RunExpr>,
    /// When it is sampled.
    pub at: SampleAt,
    /// `text:`.
    pub text: Option<String>,
    /// The member in the `.osc` file.
    pub pos: SourcePos,
}

/// The parameters of `cover`/`record`, positional order (§7.3.12).
const PARAMS: [&str; 8] = [
    "name",
    "expression",
    "unit",
    "range",
    "every",
    "ignore",
    "event",
    "text",
];

/// The coverage items among the scenario's `members`, in source order; `entities` are the
/// plan's actors and group members (the paths the runtime measures).
pub(crate) fn items(
    ctx: &Ctx<'_>,
    members: &[Member],
    entities: &[String],
) -> Result<Vec<CoverItem>, Error> {
    let mut emitted = Vec::new();
    for m in members {
        match m {
            Member::Do(b, _) => emits(b, &mut emitted),
            Member::On(_, body, _) => body.iter().for_each(|b| emits(b, &mut emitted)),
            _ => {}
        }
    }
    let mut out: Vec<CoverItem> = Vec::new();
    for m in members {
        let Member::Coverage(kind, args, span) = m else {
            continue;
        };
        let item = item(ctx, *kind, args, *span, entities, &emitted)?;
        if out
            .iter()
            .any(|o| o.name == item.name && o.kind == item.kind)
        {
            return Err(ctx.files.err(
                K::Value,
                *span,
                format!(
                    "expected one coverage item named `{}`, found a second",
                    item.name
                ),
            ));
        }
        out.push(item);
    }
    Ok(out)
}

/// Every event a behavior emits.
fn emits(b: &Labeled, out: &mut Vec<String>) {
    match &b.behavior {
        Behavior::Emit(name, _, _) => out.push(name.text.clone()),
        Behavior::Composition { children, .. } => children.iter().for_each(|c| emits(c, out)),
        _ => {}
    }
}

fn item(
    ctx: &Ctx<'_>,
    kind: CoverageKind,
    args: &[Arg],
    span: dsl::semantics::hir::Span,
    entities: &[String],
    emitted: &[String],
) -> Result<CoverItem, Error> {
    let params: Vec<String> = PARAMS.iter().map(|p| p.to_string()).collect();
    let bound = bind(args, &params);
    let get = |n: &str| bound_to(&bound, n);
    let err = |at: dsl::semantics::hir::Span, m: String| ctx.files.err(K::Value, at, m);
    let word = if kind == CoverageKind::Record {
        "record"
    } else {
        "cover"
    };
    let name_expr = get("name");
    let name = match (name_expr.map(|e| &e.kind), get("expression")) {
        (Some(ExprKind::Name(n)), _) => n.clone(),
        (None, Some(e)) => ctx.path_of(e).ok_or_else(|| {
            err(
                span,
                format!("expected a name for {word}(…) (its first argument), found none"),
            )
        })?,
        _ => {
            return Err(err(
                span,
                format!("expected a name for {word}(…) (its first argument), found none"),
            ))
        }
    };
    let expr_src = get("expression").or(name_expr).ok_or_else(|| {
        err(
            span,
            format!("expected an expression in {word}(…), found none"),
        )
    })?;
    let expr = run_expr(ctx, expr_src, entities)?;
    if kind == CoverageKind::Record {
        for p in ["range", "every", "ignore"] {
            if let Some(e) = get(p) {
                return Err(err(
                    e.span,
                    format!("expected no `{p}` in record(…) (it has no buckets), found one"),
                ));
            }
        }
    }
    let unit = match get("unit") {
        None => None,
        Some(e) => {
            let ExprKind::Name(u) = &e.kind else {
                return Err(err(
                    e.span,
                    "expected a unit name (`kph`, `m`) in unit:, found another expression".into(),
                ));
            };
            let def = ctx
                .model
                .units
                .unit(u)
                .ok_or_else(|| err(e.span, format!("expected a unit, found `{u}`")))?;
            Some(CoverUnit {
                name: def.name.clone(),
                factor: def.factor,
                offset: def.offset,
            })
        }
    };
    // A number in the item's unit: a physical literal converted, a plain number as written.
    let in_unit = |e: &Expr| -> Result<f64, Error> {
        let x = ctx.number(e)?;
        Ok(match (&e.kind, &unit) {
            (ExprKind::Physical(..), Some(u)) => (x - u.offset) / u.factor,
            (ExprKind::Neg(inner), Some(u)) if matches!(inner.kind, ExprKind::Physical(..)) => {
                (x - u.offset) / u.factor
            }
            _ => x,
        })
    };
    let buckets = match (get("range"), get("every")) {
        (Some(r), every) => {
            let ExprKind::Range(a, b) = &r.kind else {
                return Err(err(
                    r.span,
                    "expected a range [low..high] in range:, found another expression".into(),
                ));
            };
            let (low, high) = (in_unit(a)?, in_unit(b)?);
            if !(low.is_finite() && high.is_finite() && low < high) {
                return Err(err(r.span, format!("expected a range whose low end is below its high end, found [{low}..{high}]")));
            }
            let every = every.map(&in_unit).transpose()?;
            if let Some(w) = every {
                if !(w.is_finite() && w > 0.0) {
                    return Err(err(
                        get("every").map_or(span, |e| e.span),
                        format!("expected a bucket width above 0 in every:, found {w}"),
                    ));
                }
            }
            Buckets::Range { low, high, every }
        }
        (None, Some(e)) => {
            return Err(err(
                e.span,
                "expected range: beside every:, found none".into(),
            ))
        }
        (None, None) if kind == CoverageKind::Cover => members(ctx, &expr),
        (None, None) => Buckets::None,
    };
    let ignore = get("ignore")
        .map(|e| run_expr(ctx, e, entities))
        .transpose()?;
    let at = match get("event") {
        None => SampleAt::End,
        Some(e) => match &e.kind {
            ExprKind::Name(n) if n == "end" => SampleAt::End,
            ExprKind::Name(n) if n == "start" => SampleAt::Start,
            ExprKind::Name(n) if emitted.contains(n) => SampleAt::Event(n.clone()),
            _ => {
                return Err(err(e.span, "expected start, end or an event the scenario emits (`emit e`) in event:, found another".into()))
            }
        },
    };
    let text = match get("text").map(|e| &e.kind) {
        Some(ExprKind::Str(t)) => Some(t.clone()),
        _ => None,
    };
    Ok(CoverItem {
        name,
        kind,
        expr,
        unit,
        buckets,
        ignore,
        at,
        text,
        pos: ctx.site(span).pos,
    })
}

/// The buckets of a cover without a range: the members of an enum value or a boolean's two.
fn members(ctx: &Ctx<'_>, expr: &RunExpr) -> Buckets {
    match expr {
        RunExpr::Bool(_) => Buckets::Members(vec!["false".into(), "true".into()]),
        RunExpr::Enum(member) => ctx
            .model
            .enums
            .iter()
            .find(|e| e.members.contains(member))
            .map_or(Buckets::None, |e| Buckets::Members(e.members.clone())),
        RunExpr::Binary(op, ..)
            if !matches!(op, RunOp::Add | RunOp::Sub | RunOp::Mul | RunOp::Div) =>
        {
            Buckets::Members(vec!["false".into(), "true".into()])
        }
        RunExpr::Not(_) => Buckets::Members(vec!["false".into(), "true".into()]),
        _ => Buckets::None,
    }
}

/// The entity an actor expression names, if it is a vehicle of the plan.
fn entity(ctx: &Ctx<'_>, e: &Expr, entities: &[String]) -> Option<String> {
    let path = ctx.path_of(e)?;
    entities.contains(&path).then_some(path)
}

/// A sampled expression (module doc): §8.7 methods and `speed` of the plan's actors,
/// arithmetic, comparisons and logic, and constants (literals, resolved fields).
fn run_expr(ctx: &Ctx<'_>, e: &Expr, entities: &[String]) -> Result<RunExpr, Error> {
    let unsupported = || {
        ctx.files.err(
            K::Value,
            e.span,
            "expected a value the runtime samples (a constant, a resolved field, `a.speed` or a §8.7 method of a vehicle: space_gap, object_distance, time_headway, time_to_collision, get_s_coord, get_t_coord), found another expression",
        )
    };
    let rec = |x: &Expr| run_expr(ctx, x, entities).map(Box::new);
    Ok(match &e.kind {
        ExprKind::Field(actor, field) if field.text == "speed" => {
            match entity(ctx, actor, entities) {
                Some(a) => RunExpr::Speed(a),
                None => return Err(unsupported()),
            }
        }
        ExprKind::Call(callee, args) => {
            let ExprKind::Field(actor, method) = &callee.kind else {
                return Err(unsupported());
            };
            let a = entity(ctx, actor, entities).ok_or_else(unsupported)?;
            let params: Vec<String> = ["reference", "direction", "mode"]
                .map(String::from)
                .to_vec();
            let bound = bind(args, &params);
            let arg = |n: &str| bound_to(&bound, n);
            let reference = || {
                arg("reference")
                    .and_then(|r| entity(ctx, r, entities))
                    .ok_or_else(unsupported)
            };
            let word = |n: &str| match arg(n).map(|x| &x.kind) {
                Some(ExprKind::Name(w)) => Some(w.clone()),
                Some(ExprKind::EnumValue(_, m)) => Some(m.text.clone()),
                _ => None,
            };
            let direction = || match word("direction").as_deref() {
                Some("longitudinal") => Ok(Direction::Longitudinal),
                Some("lateral") => Ok(Direction::Lateral),
                _ => Err(unsupported()),
            };
            match method.text.as_str() {
                "space_gap" => RunExpr::SpaceGap(a, reference()?, direction()?),
                "object_distance" => {
                    let boxes = match word("mode").as_deref() {
                        None | Some("reference_points") => false,
                        Some("bounding_boxes") => true,
                        _ => return Err(unsupported()),
                    };
                    RunExpr::ObjectDistance(a, reference()?, direction()?, boxes)
                }
                "time_headway" => RunExpr::TimeHeadway(a, reference()?),
                "time_to_collision" => RunExpr::TimeToCollision(a, reference()?),
                "get_s_coord" if args.is_empty() => RunExpr::SCoord(a),
                "get_t_coord" if args.is_empty() => RunExpr::TCoord(a),
                _ => return Err(unsupported()),
            }
        }
        ExprKind::Neg(x) => RunExpr::Neg(rec(x)?),
        ExprKind::Not(x) => RunExpr::Not(rec(x)?),
        ExprKind::Binary(op, a, b) => {
            let op = match op {
                BinOp::Add => RunOp::Add,
                BinOp::Sub => RunOp::Sub,
                BinOp::Mul => RunOp::Mul,
                BinOp::Div => RunOp::Div,
                BinOp::Lt => RunOp::Lt,
                BinOp::Le => RunOp::Le,
                BinOp::Gt => RunOp::Gt,
                BinOp::Ge => RunOp::Ge,
                BinOp::Eq => RunOp::Eq,
                BinOp::Ne => RunOp::Ne,
                BinOp::And => RunOp::And,
                BinOp::Or => RunOp::Or,
                _ => return Err(unsupported()),
            };
            RunExpr::Binary(op, rec(a)?, rec(b)?)
        }
        ExprKind::Range(..) => return Err(unsupported()),
        _ => match ctx.eval(e) {
            Ok(Val::Num(x)) => RunExpr::Num(x),
            Ok(Val::Bool(b)) => RunExpr::Bool(b),
            Ok(Val::Enum(m)) => RunExpr::Enum(m),
            _ => return Err(unsupported()),
        },
    })
}
