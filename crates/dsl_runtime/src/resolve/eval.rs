//! Constant values of the scenario as the resolver reads them (ASAM OpenSCENARIO DSL 2.1 §7.4
//! expressions): literals with units in SI, ranges `[a..b]` drawn from the run's seed, and
//! references to fields the constraint solver resolved (`npc_speed`, `ego.bounding_box.length`).
//! Only the `resolve` stage reads the program; what it hands on is plain data.
//!
//! Names are read in a [`Frame`]: the entry scenario's, or an invoked behavior's (§7.3.9), whose
//! parameters are its own instance's fields (`do.round_two.slow`) or, when the invocation gave
//! an actor or struct, that instance's path (`ego`).

use std::cell::RefCell;

use dsl::semantics::hir::{Arg as HirArg, BinOp, Expr, ExprKind, Span};
use dsl::semantics::model::Model;
use dsl::semantics::types::CompoundId;
use dsl::{Resolution, Value};

use super::value::{Arg, Draws, Val};
use crate::error::{Error, ErrorKind as K, Files, Site};

/// Where names are read: the entry scenario, or an invocation of a behavior with a `do`.
#[derive(Debug, Clone, Default)]
pub(crate) struct Frame {
    /// The instance's path relative to the entry scenario, with a trailing `.` (`""` for the
    /// entry scenario, `do.round_two.` for an invocation in its `do`).
    pub prefix: String,
    /// Parameters the invocation gave an instance of the caller's: name → that instance's
    /// path.
    pub aliases: Vec<(String, String)>,
    /// The actor of a behavior declared on an actor (`actor`), as a path.
    pub actor: Option<String>,
}

/// What the resolver reads the program with.
pub(crate) struct Eval<'a> {
    /// Declarations.
    pub model: &'a Model,
    /// The solver's values.
    pub res: &'a Resolution,
    /// The scenario's root in the resolution (`cut_in`, `dut.driving_alongside_group`).
    pub root: String,
    /// For positions in messages.
    pub files: Files<'a>,
    /// Where names are read.
    pub frame: Frame,
    /// Draws of ranges and `one_of` choices, in resolution order.
    draws: &'a RefCell<Draws>,
}

impl<'a> Eval<'a> {
    /// A reader of the scenario rooted at `root` in the resolution, drawing from `draws`.
    pub(crate) fn new(
        model: &'a Model,
        res: &'a Resolution,
        root: String,
        files: Files<'a>,
        draws: &'a RefCell<Draws>,
    ) -> Self {
        Eval {
            model,
            res,
            root,
            files,
            frame: Frame::default(),
            draws,
        }
    }

    /// The same reader in `frame` (same draws).
    pub(crate) fn enter(&self, frame: Frame) -> Eval<'a> {
        Eval {
            model: self.model,
            res: self.res,
            root: self.root.clone(),
            files: self.files,
            frame,
            draws: self.draws,
        }
    }

    /// The key of event `name` of the frame's behavior: its name, prefixed by the invocation's
    /// path in an invoked behavior (each invocation has events of its own).
    pub(crate) fn event_key(&self, name: &str) -> String {
        format!("{}{name}", self.frame.prefix)
    }

    /// A draw among `n` choices.
    pub(crate) fn choose(&self, n: usize) -> usize {
        self.draws.borrow_mut().choose(n)
    }

    /// The site of `span`.
    pub(crate) fn site(&self, span: Span) -> Site {
        self.files.site(span)
    }

    /// `e` evaluated as an argument: its value (or why it has none) and the path it names.
    pub(crate) fn arg(&self, e: &Expr) -> Arg {
        Arg {
            site: self.site(e.span),
            path: self.path_of(e),
            value: self.eval(e),
        }
    }

    /// `args` bound to `params` (see [`bind`]) and evaluated.
    pub(crate) fn args(&self, args: &[HirArg], params: &[String]) -> super::value::Args {
        bind(args, params)
            .into_iter()
            .map(|(n, e)| (n, self.arg(e)))
            .collect()
    }

    /// The dotted path an actor or field expression names (`dut.vehicle`, `g.vehicles[0]`),
    /// relative to the entry scenario: in an invoked behavior, a parameter bound to an
    /// instance of the caller names that instance, its own fields are under its prefix.
    pub(crate) fn path_of(&self, e: &Expr) -> Option<String> {
        match &e.kind {
            ExprKind::Name(n) => Some(self.name_path(n)),
            ExprKind::Field(inner, n) => Some(format!("{}.{}", self.path_of(inner)?, n.text)),
            ExprKind::Index(inner, i) => match i.kind {
                ExprKind::Int(i) => Some(format!("{}[{i}]", self.path_of(inner)?)),
                _ => None,
            },
            _ => None,
        }
    }

    /// The path of name `n` in the frame.
    fn name_path(&self, n: &str) -> String {
        if let Some((_, p)) = self.frame.aliases.iter().find(|(a, _)| a == n) {
            return p.clone();
        }
        if n == "actor" {
            if let Some(a) = &self.frame.actor {
                return a.clone();
            }
        }
        let own = format!("{}{n}", self.frame.prefix);
        if !self.frame.prefix.is_empty() && self.res.get(&format!("{}.{own}", self.root)).is_some()
        {
            return own;
        }
        n.to_string()
    }

    /// The resolved value at `path`: a field of the scenario first, then a global.
    pub(crate) fn lookup(&self, path: &str) -> Option<(String, &'a Value)> {
        let scoped = format!("{}.{path}", self.root);
        if let Some(v) = self.res.get(&scoped) {
            return Some((path.to_string(), v));
        }
        self.res.get(path).map(|v| (path.to_string(), v))
    }

    /// The solver's value at `path` (as [`Eval::lookup`] finds it), when it is a constant.
    pub(crate) fn value_at(&self, path: &str) -> Option<Val> {
        self.lookup(path).and_then(|(p, v)| from_value(p, v))
    }

    /// The compound type of a resolved instance.
    pub(crate) fn type_of(&self, v: &Value) -> Option<CompoundId> {
        match v {
            Value::Compound { ty, .. } => match self.model.types.get(ty.as_str()) {
                Some((dsl::semantics::model::TypeName::Compound(c), _)) => Some(*c),
                _ => None,
            },
            _ => None,
        }
    }

    /// Whether the resolved instance is of type `name` or inherits from it.
    pub(crate) fn is_a(&self, v: &Value, name: &str) -> bool {
        let Some(sup) = (match self.model.types.get(name) {
            Some((dsl::semantics::model::TypeName::Compound(c), _)) => Some(*c),
            _ => None,
        }) else {
            return false;
        };
        self.type_of(v)
            .is_some_and(|c| self.model.is_subtype(c, sup))
    }

    /// Evaluates a constant expression.
    pub(crate) fn eval(&self, e: &Expr) -> Result<Val, Error> {
        let bad = |what: &str| {
            self.files.err(
                K::Value,
                e.span,
                format!("expected a constant value, found {what}"),
            )
        };
        Ok(match &e.kind {
            ExprKind::Int(i) => Val::Num(*i as f64),
            ExprKind::Float(f) => Val::Num(*f),
            ExprKind::Bool(b) => Val::Bool(*b),
            ExprKind::Physical(v, unit) => match self.model.units.unit(&unit.text) {
                Some(u) => Val::Num(u.to_si(*v)),
                None => return Err(bad(&format!("the unknown unit `{}`", unit.text))),
            },
            ExprKind::Neg(inner) => match self.eval(inner)? {
                Val::Num(x) => Val::Num(-x),
                _ => return Err(bad("a negated non-number")),
            },
            ExprKind::Binary(op, a, b) => {
                let (Val::Num(x), Val::Num(y)) = (self.eval(a)?, self.eval(b)?) else {
                    return Err(bad("arithmetic on non-numbers"));
                };
                Val::Num(match op {
                    BinOp::Add => x + y,
                    BinOp::Sub => x - y,
                    BinOp::Mul => x * y,
                    BinOp::Div if y != 0.0 => x / y,
                    _ => return Err(bad("an operator other than + - * / on numbers")),
                })
            }
            ExprKind::Range(a, b) => {
                let (Val::Num(lo), Val::Num(hi)) = (self.eval(a)?, self.eval(b)?) else {
                    return Err(bad("a range of non-numbers"));
                };
                if hi < lo {
                    return Err(bad("a range whose upper end is below its lower end"));
                }
                Val::Num(lo + (hi - lo) * self.draws.borrow_mut().uniform())
            }
            ExprKind::EnumValue(_, m) => Val::Enum(m.text.clone()),
            // Where the checker found an enum member expected, the member wins over a field of
            // the same name (`track: projected` beside an actor `projected`).
            ExprKind::Name(n) if self.model.enum_member_names.contains(&e.span) => {
                Val::Enum(n.clone())
            }
            ExprKind::Name(_) | ExprKind::Field(..) | ExprKind::Index(..) => {
                let path = self
                    .path_of(e)
                    .ok_or_else(|| bad("an index that is not a number"))?;
                match self.lookup(&path) {
                    Some((p, v)) => from_value(p, v).ok_or_else(|| bad("a run-time value"))?,
                    None => match &e.kind {
                        ExprKind::Name(n) => Val::Enum(n.clone()),
                        _ => return Err(bad(&format!("`{path}`, which has no value"))),
                    },
                }
            }
            ExprKind::Call(callee, _) => match &callee.kind {
                ExprKind::Name(m) | ExprKind::Field(_, dsl::semantics::hir::Name { text: m, .. })
                    if self.method_decl(m).is_some_and(|d| {
                        matches!(d.body, dsl::semantics::hir::MethodBody::External)
                    }) =>
                {
                    return Err(bad(&format!("the result of external method `{m}`, which the host gives only while the scenario runs (read it in a condition: until, wait, an event)")))
                }
                _ => return Err(bad("an expression the planner does not compute")),
            },
            _ => return Err(bad("an expression the planner does not compute")),
        })
    }

    /// The declaration of method `name`: a top-level `def`, else the first compound declaring
    /// it.
    pub(crate) fn method_decl(&self, name: &str) -> Option<&'a dsl::semantics::hir::MethodDecl> {
        use dsl::semantics::hir::Member;
        let method = |m: &'a Member| match m {
            Member::Method(d) if d.name.text == name => Some(d),
            _ => None,
        };
        self.model.top.iter().find_map(method).or_else(|| {
            self.model
                .compounds
                .iter()
                .find_map(|c| c.members.iter().find_map(method))
        })
    }

    /// Evaluates to a number in SI units.
    pub(crate) fn number(&self, e: &Expr) -> Result<f64, Error> {
        match self.eval(e)? {
            Val::Num(x) if x.is_finite() => Ok(x),
            _ => Err(self
                .files
                .err(K::Value, e.span, "expected a number, found another value")),
        }
    }
}

fn from_value(path: String, v: &Value) -> Option<Val> {
    Some(match v {
        Value::Bool(b) => Val::Bool(*b),
        Value::Int(i) => Val::Num(*i as f64),
        Value::Float(f) => Val::Num(*f),
        Value::Quantity { si, .. } => Val::Num(*si),
        Value::Enum { member, .. } => Val::Enum(member.clone()),
        Value::Compound { .. } | Value::List(_) => Val::Instance(path),
        Value::Str(_) | Value::RunTime(_) => return None,
    })
}

/// Arguments matched to parameter names: positional ones take `params` in order, named ones
/// their name.
pub(crate) fn bind<'e>(args: &'e [HirArg], params: &[String]) -> Vec<(String, &'e Expr)> {
    let mut out = Vec::new();
    let mut next = 0;
    for a in args {
        match &a.name {
            Some(n) => out.push((n.text.clone(), &a.value)),
            None => {
                if let Some(p) = params.get(next) {
                    out.push((p.clone(), &a.value));
                }
                next += 1;
            }
        }
    }
    out
}

/// The argument [`bind`] matched to parameter `name`, if any.
pub(crate) fn bound_to<'e>(bound: &[(String, &'e Expr)], name: &str) -> Option<&'e Expr> {
    bound.iter().find(|(p, _)| p == name).map(|(_, e)| *e)
}
