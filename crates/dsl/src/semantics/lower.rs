//! Lowers checked constraints ([`Template`]s) over an instance [`Tree`] into solver
//! constraints: once per instance of the owning type and per element of each `for` list.
//! Linear arithmetic over numbers and list sizes, enum and bool (in)equality and membership,
//! string equality and ranges are lowered; anything else is reported as unsupported.

use std::collections::BTreeSet;

use super::check::{Owner, Place, Seg, TExpr, TKind, Template};
use super::diagnostic::{Diagnostic, DiagnosticKind as K};
use super::hir::{BinOp, Span};
use super::instance::{Node, NodeId, Tree};
use super::model::Model;
use super::solver::{ConstraintKind, Linear, Relation, Strength, VarId};
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

struct Env {
    this: Option<NodeId>,
    /// The invoked instance of an invocation's constraints (`it`).
    it: Option<NodeId>,
    locals: Vec<NodeId>,
}

enum Fail {
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
            let mut lw = Lowerer {
                tree,
                out: &mut out,
                origin,
                strength: t.strength,
            };
            if let Err(Fail::Unsupported(span, msg)) = lw.loops(t, 0, &mut env) {
                if reported.insert(ti) {
                    out.diags.push(Diagnostic::new(K::Unsupported, span, msg));
                }
            }
        }
    }
    out
}

struct Lowerer<'a> {
    tree: &'a mut Tree,
    out: &'a mut Lowered,
    origin: u32,
    strength: Strength,
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

    fn compare(
        &mut self,
        op: BinOp,
        a: &TExpr,
        b: &TExpr,
        env: &Env,
        whole: &TExpr,
    ) -> Result<(), Fail> {
        match (&a.ty, &b.ty) {
            (Ty::Enum(_) | Ty::Bool, _) | (_, Ty::Enum(_) | Ty::Bool) => {
                let negated = match op {
                    BinOp::Eq => false,
                    BinOp::Ne => true,
                    _ => return Err(Self::unsupported(whole, "ordering of enumeration members")),
                };
                match (member(a), member(b)) {
                    (Some(x), Some(y)) => {
                        if (x == y) == negated {
                            self.add(ConstraintKind::Linear {
                                expr: Linear::constant(1.0),
                                rel: Relation::Le,
                            });
                        }
                    }
                    (None, Some(m)) => {
                        let var = self.scalar(a, env)?;
                        self.add(ConstraintKind::Member {
                            var,
                            set: vec![m],
                            negated,
                        });
                    }
                    (Some(m), None) => {
                        let var = self.scalar(b, env)?;
                        self.add(ConstraintKind::Member {
                            var,
                            set: vec![m],
                            negated,
                        });
                    }
                    (None, None) => {
                        let (x, y) = (self.scalar(a, env)?, self.scalar(b, env)?);
                        self.add(ConstraintKind::SameMember {
                            a: x,
                            b: y,
                            negated,
                        });
                    }
                }
                Ok(())
            }
            (Ty::Str, _) | (_, Ty::Str) => {
                let negated = match op {
                    BinOp::Eq => false,
                    BinOp::Ne => true,
                    _ => return Err(Self::unsupported(whole, "ordering of strings")),
                };
                let (var, text) = match (&a.kind, &b.kind) {
                    (_, TKind::Str(s)) => (self.scalar(a, env)?, s.clone()),
                    (TKind::Str(s), _) => (self.scalar(b, env)?, s.clone()),
                    _ => return Err(Self::unsupported(whole, "equality of two string fields")),
                };
                self.add(ConstraintKind::Text {
                    var,
                    value: text,
                    negated,
                });
                Ok(())
            }
            _ => {
                let (la, lb) = (self.linear(a, env)?, self.linear(b, env)?);
                let (expr, rel) = match op {
                    BinOp::Lt => (la.add_scaled(&lb, -1.0), Relation::Lt),
                    BinOp::Le => (la.add_scaled(&lb, -1.0), Relation::Le),
                    BinOp::Gt => (lb.add_scaled(&la, -1.0), Relation::Lt),
                    BinOp::Ge => (lb.add_scaled(&la, -1.0), Relation::Le),
                    BinOp::Eq => (la.add_scaled(&lb, -1.0), Relation::Eq),
                    _ => (la.add_scaled(&lb, -1.0), Relation::Ne),
                };
                self.add(ConstraintKind::Linear { expr, rel });
                Ok(())
            }
        }
    }

    fn membership(
        &mut self,
        a: &TExpr,
        b: &TExpr,
        env: &Env,
        negated: bool,
        whole: &TExpr,
    ) -> Result<(), Fail> {
        match &b.kind {
            TKind::Range(lo, hi) => {
                if negated {
                    return Err(Self::unsupported(whole, "`not in` a range (a disjunction)"));
                }
                let x = self.linear(a, env)?;
                let (l, h) = (self.linear(lo, env)?, self.linear(hi, env)?);
                self.add(ConstraintKind::Linear {
                    expr: l.add_scaled(&x, -1.0),
                    rel: Relation::Le,
                });
                self.add(ConstraintKind::Linear {
                    expr: x.add_scaled(&h, -1.0),
                    rel: Relation::Le,
                });
                Ok(())
            }
            TKind::List(items) if matches!(a.ty, Ty::Enum(_) | Ty::Bool) => {
                let set: Option<Vec<u32>> = items.iter().map(member).collect();
                let Some(set) = set else {
                    return Err(Self::unsupported(b, "a list of fields after `in`"));
                };
                let var = self.scalar(a, env)?;
                self.add(ConstraintKind::Member { var, set, negated });
                Ok(())
            }
            TKind::List(items) if items.len() == 1 => {
                let op = if negated { BinOp::Ne } else { BinOp::Eq };
                self.compare(op, a, &items[0], env, whole)
            }
            _ => Err(Self::unsupported(
                whole,
                "membership in a list of numbers (a disjunction)",
            )),
        }
    }
}

fn member(e: &TExpr) -> Option<u32> {
    match e.kind {
        TKind::Member(_, m) => Some(m),
        TKind::Bool(b) => Some(b as u32),
        _ => None,
    }
}

fn flip(op: BinOp) -> BinOp {
    match op {
        BinOp::Eq => BinOp::Ne,
        BinOp::Ne => BinOp::Eq,
        BinOp::Lt => BinOp::Ge,
        BinOp::Le => BinOp::Gt,
        BinOp::Gt => BinOp::Le,
        BinOp::Ge => BinOp::Lt,
        other => other,
    }
}

fn describe(e: &TExpr) -> &'static str {
    match &e.kind {
        TKind::Call(..) => "a method call (evaluated at run time)",
        TKind::Opaque(what) => what,
        TKind::List(_) => "a list value",
        TKind::Range(..) => "a range value",
        TKind::Binary(BinOp::Rem, ..) => "`%`",
        _ => "this expression",
    }
}
