//! Lowers checked constraints ([`Template`]s) over an instance [`Tree`] into solver
//! constraints: once per instance of the owning type and per element of each `for` list.
//! Linear arithmetic over numbers and list sizes, enum and bool (in)equality and membership,
//! a bool equal to a condition, string equality, list equality (size and members), `float` to
//! whole-number conversions (a helper variable `n == trunc(x)`) and ranges are lowered; anything
//! else is reported as unsupported, but for the points of a relative path or trajectory given
//! as route elements (`keep(it.points == [p0, p1])`, `keep(it.points[0] == p0)` of a
//! `relative_path_st`, `relative_path_odr`, `relative_trajectory_st`,
//! `relative_trajectory_odr`, §8.12.33-34, §8.12.40-41): road-network references, which the
//! runtime reads from the constraint itself, so the solver only sizes the list. `compare.rs` holds the comparisons (`==`, `<`, `in`, …).

mod compare;

use compare::flip;

use std::collections::BTreeSet;

use super::check::{Owner, Place, Seg, TExpr, TKind, Template};
use super::diagnostic::{Diagnostic, DiagnosticKind as K};
use super::hir::{BinOp, Span};
use super::instance::{Node, NodeId, Tree};
use super::model::Model;
use super::solver::{ConstraintKind, Linear, Relation, Strength, VarId, VarKind};
use super::types::Ty;

/// What lowering produced besides the constraints added to the tree's problem.
#[derive(Debug, Default)]
pub struct Lowered {
    /// Span of each constraint origin tag.
    pub origins: Vec<Span>,
    /// Constraints that cannot be lowered (reported once per template).
    pub diags: Vec<Diagnostic>,
    /// Lists a constraint reaches into that are not sized yet (so more stages are needed).
    pub pending: BTreeSet<NodeId>,
}

/// Most alternatives one constraint's `or`s may expand to (disjunctive normal form).
const MAX_ALTERNATIVES: usize = 64;

pub(super) struct Env {
    this: Option<NodeId>,
    /// The invoked instance of an invocation's constraints (`it`).
    it: Option<NodeId>,
    locals: Vec<NodeId>,
}

pub(super) enum Fail {
    /// A list on the way is not sized yet.
    Pending,
    /// Not lowerable; the message and where.
    Unsupported(Span, String),
}

/// Adds every template's constraints to `tree.problem`.
///
/// Default constraints are emitted outermost instance first (top level, then the roots' own
/// fields, then deeper), so that `keep(default bounding_box.center.x …)` of a vehicle comes
/// before the `x: length = 0m` of `position_3d` and wins where they disagree.
pub fn lower(model: &Model, templates: &[Template], tree: &mut Tree) -> Lowered {
    let mut out = Lowered::default();
    let mut reported = BTreeSet::new();
    type Context = (Option<NodeId>, Option<NodeId>);
    let mut work: Vec<(usize, usize, Context)> = Vec::new();
    for (ti, t) in templates.iter().enumerate() {
        let contexts: Vec<Context> = match t.owner {
            Owner::Top => vec![(None, None)],
            Owner::Compound(c) => tree
                .instances
                .iter()
                .filter(|(_, ty)| model.is_subtype(*ty, c))
                .map(|(n, _)| (Some(*n), None))
                .collect(),
            Owner::Invocation(k) => tree
                .invocations
                .iter()
                .filter(|(site, ..)| *site == k)
                .map(|(_, caller, it)| (Some(*caller), Some(*it)))
                .collect(),
        };
        for (this, it) in contexts {
            let depth = match (t.strength, it.or(this)) {
                (Strength::Hard, _) | (_, None) => 0,
                (_, Some(n)) => 1 + tree.paths[n].matches(['.', '[']).count(),
            };
            work.push((depth, ti, (this, it)));
        }
    }
    work.sort_by_key(|w| w.0);
    for (_, ti, (this, it)) in work {
        let t = &templates[ti];
        {
            let mut env = Env {
                this,
                it,
                locals: Vec::new(),
            };
            let origin = out.origins.len() as u32;
            out.origins.push(t.span);
            let start = tree.problem.constraints.len();
            let mut lw = Lowerer {
                model,
                tree,
                out: &mut out,
                origin,
                strength: t.strength,
                helpers: false,
            };
            let result = lw.loops(t, 0, &mut env);
            if lw.helpers {
                group(tree, start, t.strength, origin);
            }
            // A field's default is about the field: only hard constraints on it override it.
            let subject = match &t.subject {
                Some(s) => Lowerer {
                    model,
                    tree,
                    out: &mut out,
                    origin,
                    strength: t.strength,
                    helpers: false,
                }
                .node(s, &env)
                .map(|n| tree.vars_under(n))
                .unwrap_or_default(),
                None => Vec::new(),
            };
            for c in &mut tree.problem.constraints[start..] {
                c.subject.clone_from(&subject);
            }
            if let Err(Fail::Unsupported(span, msg)) = result {
                if reported.insert(ti) {
                    out.diags.push(Diagnostic::new(K::Unsupported, span, msg));
                }
            }
        }
    }
    out
}

/// Joins the constraints from `start` on into one conjunction (a disjunction of one
/// alternative), unless one of them is a disjunction itself (alternatives hold none).
fn group(tree: &mut Tree, start: usize, strength: Strength, origin: u32) {
    let added = &tree.problem.constraints[start..];
    if added.len() < 2
        || added
            .iter()
            .any(|c| matches!(c.kind, ConstraintKind::Any(_)))
    {
        return;
    }
    let kinds: Vec<ConstraintKind> = tree
        .problem
        .constraints
        .drain(start..)
        .map(|c| c.kind)
        .collect();
    tree.problem
        .add(ConstraintKind::Any(vec![kinds]), strength, origin);
}

pub(super) struct Lowerer<'a> {
    model: &'a Model,
    tree: &'a mut Tree,
    out: &'a mut Lowered,
    origin: u32,
    strength: Strength,
    /// Whether a helper variable was made (a conversion's result): the constraints of the
    /// template are then kept together as one, so a default is taken or dropped whole.
    helpers: bool,
}

impl Lowerer<'_> {
    fn loops(&mut self, t: &Template, k: usize, env: &mut Env) -> Result<(), Fail> {
        if k == t.loops.len() {
            return self.constraint(&t.expr, env, false);
        }
        let list = self.node(&t.loops[k], env)?;
        let Node::List(_, _, items) = &self.tree.nodes[list] else {
            return Err(Fail::Unsupported(
                t.loops[k].span,
                "expected a list of the instance".into(),
            ));
        };
        let Some(items) = items.clone() else {
            self.out.pending.insert(list);
            return Ok(());
        };
        for item in items {
            env.locals.push(item);
            let r = self.loops(t, k + 1, env);
            env.locals.pop();
            r?;
        }
        Ok(())
    }

    fn add(&mut self, kind: ConstraintKind) {
        self.tree.problem.add(kind, self.strength, self.origin);
    }

    /// `e` (negated when `negate`) in disjunctive normal form: alternatives, each a conjunction
    /// of constraints the leaves lower to. `a or b`, `a => b` (= `not a or b`) and `not (a and
    /// b)` join their sides' alternatives; `a and b`, `not (a or b)` and `not (a => b)` combine
    /// every alternative of one side with every one of the other (at most
    /// [`MAX_ALTERNATIVES`]).
    fn alternatives(
        &mut self,
        e: &TExpr,
        env: &Env,
        negate: bool,
    ) -> Result<Vec<Vec<ConstraintKind>>, Fail> {
        let (join, a, b, neg_a, neg_b) = match (&e.kind, negate) {
            (TKind::Not(a), _) => return self.alternatives(a, env, !negate),
            (TKind::Binary(BinOp::Or, a, b), false) => (true, a, b, false, false),
            (TKind::Binary(BinOp::Implies, a, b), false) => (true, a, b, true, false),
            (TKind::Binary(BinOp::And, a, b), true) => (true, a, b, true, true),
            (TKind::Binary(BinOp::And, a, b), false) => (false, a, b, false, false),
            (TKind::Binary(BinOp::Or, a, b), true) => (false, a, b, true, true),
            (TKind::Binary(BinOp::Implies, a, b), true) => (false, a, b, false, true),
            _ => {
                // A leaf: lower it as usual, then take back what it added.
                let start = self.tree.problem.constraints.len();
                let r = self.constraint(e, env, negate);
                let added: Vec<ConstraintKind> = self
                    .tree
                    .problem
                    .constraints
                    .drain(start..)
                    .map(|c| c.kind)
                    .collect();
                r?;
                return Ok(vec![added]);
            }
        };
        let left = self.alternatives(a, env, neg_a)?;
        let right = self.alternatives(b, env, neg_b)?;
        // Checked before the product is built, so a blow-up is never allocated.
        let count = if join {
            left.len() + right.len()
        } else {
            left.len() * right.len()
        };
        if count > MAX_ALTERNATIVES {
            return Err(Self::unsupported(
                e,
                &format!("more than {MAX_ALTERNATIVES} alternatives of `or`"),
            ));
        }
        Ok(if join {
            left.into_iter().chain(right).collect()
        } else {
            left.iter()
                .flat_map(|l| {
                    right
                        .iter()
                        .map(move |r| l.iter().chain(r).cloned().collect())
                })
                .collect()
        })
    }

    fn unsupported(e: &TExpr, what: &str) -> Fail {
        Fail::Unsupported(
            e.span,
            format!("the solver does not handle {what} in a constraint"),
        )
    }

    /// The node a path expression names.
    fn node(&mut self, e: &TExpr, env: &Env) -> Result<NodeId, Fail> {
        let TKind::Path(place, segs) = &e.kind else {
            return Err(Self::unsupported(e, describe(e)));
        };
        let mut cur = match place {
            Place::Global(i) => self.tree.roots.get(*i).map(|r| r.1),
            Place::This => env.this,
            Place::Local(k) => env.locals.get(*k).copied(),
            Place::It => env.it,
        }
        .ok_or_else(|| Self::unsupported(e, "a name outside an instance"))?;
        for seg in segs {
            cur = match (seg, &self.tree.nodes[cur]) {
                (Seg::Field(f), Node::Compound(_, fields)) => fields
                    .iter()
                    .find(|(n, _)| n == f)
                    .map(|(_, id)| *id)
                    .ok_or_else(|| Self::unsupported(e, "a field of a subtype"))?,
                (Seg::Index(i), Node::List(_, size, items)) => {
                    let (size, items) = (*size, items.clone());
                    let TKind::Number(x) = i.kind else {
                        return Err(Self::unsupported(i, "a computed list index"));
                    };
                    if x < 0.0 || x.fract() != 0.0 {
                        return Err(Fail::Unsupported(
                            i.span,
                            format!("list index {x} is not a whole number ≥ 0"),
                        ));
                    }
                    // Indexing element i needs at least i + 1 elements.
                    let need = Linear::constant(x + 1.0).add_scaled(&Linear::var(size), -1.0);
                    self.add(ConstraintKind::Linear {
                        expr: need,
                        rel: Relation::Le,
                    });
                    match items {
                        Some(items) => *items.get(x as usize).ok_or(Fail::Pending)?,
                        None => {
                            self.out.pending.insert(cur);
                            return Err(Fail::Pending);
                        }
                    }
                }
                (_, Node::Reference(_)) => {
                    return Err(Self::unsupported(
                        e,
                        "a road-network reference (resolved at run time)",
                    ))
                }
                (_, Node::State(_)) => {
                    return Err(Self::unsupported(
                        e,
                        "a state variable (`var`, known only at run time)",
                    ))
                }
                _ => return Err(Self::unsupported(e, "this path")),
            };
        }
        Ok(cur)
    }

    fn scalar(&mut self, e: &TExpr, env: &Env) -> Result<VarId, Fail> {
        let n = self.node(e, env)?;
        match &self.tree.nodes[n] {
            Node::Scalar(v, _) => Ok(*v),
            Node::State(_) => Err(Self::unsupported(
                e,
                "a state variable (`var`, known only at run time)",
            )),
            Node::Reference(_) => Err(Self::unsupported(
                e,
                "a road-network reference (resolved at run time)",
            )),
            _ => Err(Self::unsupported(e, "a whole struct or list")),
        }
    }

    fn linear(&mut self, e: &TExpr, env: &Env) -> Result<Linear, Fail> {
        match &e.kind {
            TKind::Number(x) => Ok(Linear::constant(*x)),
            TKind::Path(..) => Ok(Linear::var(self.scalar(e, env)?)),
            TKind::Size(list) => {
                let n = self.node(list, env)?;
                match &self.tree.nodes[n] {
                    Node::List(_, size, _) => Ok(Linear::var(*size)),
                    _ => Err(Self::unsupported(
                        list,
                        "`size()` of something other than a list field",
                    )),
                }
            }
            TKind::Neg(a) => Ok(self.linear(a, env)?.scale(-1.0)),
            TKind::Truncate(a) => {
                let x = self.linear(a, env)?;
                Ok(Linear::var(self.truncate(x, e.ty == Ty::Uint)))
            }
            TKind::Binary(op @ (BinOp::Add | BinOp::Sub | BinOp::Mul | BinOp::Div), a, b) => {
                let (la, lb) = (self.linear(a, env)?, self.linear(b, env)?);
                match op {
                    BinOp::Add => Ok(la.add_scaled(&lb, 1.0)),
                    BinOp::Sub => Ok(la.add_scaled(&lb, -1.0)),
                    BinOp::Mul if lb.terms.is_empty() => Ok(la.scale(lb.constant)),
                    BinOp::Mul if la.terms.is_empty() => Ok(lb.scale(la.constant)),
                    BinOp::Div if lb.terms.is_empty() && lb.constant != 0.0 => {
                        Ok(la.scale(1.0 / lb.constant))
                    }
                    _ => Err(Self::unsupported(e, "a product or quotient of two fields")),
                }
            }
            _ => Err(Self::unsupported(e, describe(e))),
        }
    }

    /// A helper variable `n == trunc(x)` (`x.as(int)` of a float; `uint`: n ≥ 0).
    fn truncate(&mut self, x: Linear, uint: bool) -> VarId {
        let whole = |s: &mut Self, name: String, integer: bool, lo: Option<f64>| {
            s.helpers = true;
            s.tree.problem.add_var(
                name,
                VarKind::Number {
                    integer,
                    lo,
                    hi: None,
                },
            )
        };
        let of = match x.terms.as_slice() {
            [(v, c)] if *c == 1.0 && x.constant == 0.0 => *v,
            _ => {
                let v = whole(self, "a converted value".into(), false, None);
                self.add(ConstraintKind::Linear {
                    expr: Linear::var(v).add_scaled(&x, -1.0),
                    rel: Relation::Eq,
                });
                v
            }
        };
        let name = format!(
            "{}.as({})",
            self.tree.problem.vars[of.0 as usize].name,
            if uint { "uint" } else { "int" }
        );
        let var = whole(self, name, true, uint.then_some(0.0));
        self.add(ConstraintKind::Truncate { var, of });
        var
    }

    /// Adds `e` (a boolean) as constraints; `negate` for `not`.
    fn constraint(&mut self, e: &TExpr, env: &Env, negate: bool) -> Result<(), Fail> {
        match &e.kind {
            TKind::Bool(b) => {
                if *b == negate {
                    self.add(ConstraintKind::Linear {
                        expr: Linear::constant(1.0),
                        rel: Relation::Le,
                    });
                }
                Ok(())
            }
            TKind::Not(a) => self.constraint(a, env, !negate),
            TKind::Binary(BinOp::And, a, b) if !negate => {
                self.constraint(a, env, false)?;
                self.constraint(b, env, false)
            }
            TKind::Path(..) if e.ty == Ty::Bool => {
                let var = self.scalar(e, env)?;
                self.add(ConstraintKind::Member {
                    var,
                    set: vec![1],
                    negated: negate,
                });
                Ok(())
            }
            TKind::Binary(
                op @ (BinOp::Eq | BinOp::Ne | BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge),
                a,
                b,
            ) => {
                let op = if negate { flip(*op) } else { *op };
                self.compare(op, a, b, env, e)
            }
            TKind::Binary(BinOp::In, a, b) => self.membership(a, b, env, negate, e),
            TKind::Binary(BinOp::Or | BinOp::Implies, a, b) if negate => {
                // not (a or b) = not a and not b; not (a => b) = a and not b.
                let first_negated = matches!(e.kind, TKind::Binary(BinOp::Or, ..));
                self.constraint(a, env, first_negated)?;
                self.constraint(b, env, true)
            }
            TKind::Binary(BinOp::Or | BinOp::Implies | BinOp::And, ..) => {
                let mut alternatives = self.alternatives(e, env, negate)?;
                if alternatives.len() == 1 {
                    for kind in alternatives.pop().unwrap_or_default() {
                        self.add(kind);
                    }
                } else {
                    self.add(ConstraintKind::Any(alternatives));
                }
                Ok(())
            }
            _ => Err(Self::unsupported(e, describe(e))),
        }
    }
}

pub(super) fn describe(e: &TExpr) -> &'static str {
    match &e.kind {
        TKind::Call(..) => "a method call (evaluated at run time)",
        TKind::Opaque(what) => what,
        TKind::List(_) => "a list value",
        TKind::Range(..) => "a range value",
        TKind::Binary(BinOp::Rem, ..) => "`%`",
        _ => "this expression",
    }
}
