//! Comparisons in constraints (ASAM OpenSCENARIO DSL 2.1 §7.4.2.4 relational operators,
//! §7.4.2.7.1 list relational operators): `==`, `!=`, `<`, `<=`, `>`, `>=` and `in` over
//! numbers, enumeration members, bools (a bool field equal to a condition), strings and lists.

use super::super::check::{Seg, TExpr, TKind};
use super::super::hir::BinOp;
use super::super::instance::{is_library, Node};
use super::super::model::Model;
use super::super::solver::{ConstraintKind, Linear, Relation};
use super::super::types::{CompoundId, Ty};
use super::{describe, Env, Fail, Lowerer};

impl Lowerer<'_> {
    pub(super) fn compare(
        &mut self,
        op: BinOp,
        a: &TExpr,
        b: &TExpr,
        env: &Env,
        whole: &TExpr,
    ) -> Result<(), Fail> {
        if op == BinOp::Eq && (self.runtime_point(a, env) || self.runtime_point(b, env)) {
            // A route element as a point of a relative path: the runtime's (module doc).
            return Ok(());
        }
        match (&a.ty, &b.ty) {
            (Ty::List(_), _) | (_, Ty::List(_)) => self.list_equality(op, a, b, env, whole),
            (Ty::Bool, _) | (_, Ty::Bool)
                if matches!(op, BinOp::Eq | BinOp::Ne) && !(plain(a) && plain(b)) =>
            {
                // `f == (x > 3)`: f holds exactly when the condition does, as the disjunction
                // (f and c) or (not f and not c); `!=` swaps the second side's negations.
                let both = |x: TExpr, y: TExpr| TExpr {
                    kind: TKind::Binary(BinOp::And, Box::new(x), Box::new(y)),
                    ty: Ty::Bool,
                    span: whole.span,
                };
                let not = |x: &TExpr| TExpr {
                    kind: TKind::Not(Box::new(x.clone())),
                    ty: Ty::Bool,
                    span: x.span,
                };
                let (same, other) = if op == BinOp::Eq {
                    (b.clone(), not(b))
                } else {
                    (not(b), b.clone())
                };
                let either = TExpr {
                    kind: TKind::Binary(
                        BinOp::Or,
                        Box::new(both(a.clone(), same)),
                        Box::new(both(not(a), other)),
                    ),
                    ty: Ty::Bool,
                    span: whole.span,
                };
                self.constraint(&either, env, false)
            }
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
                    _ => {
                        let (a, b) = (self.scalar(a, env)?, self.scalar(b, env)?);
                        self.add(ConstraintKind::SameText { a, b, negated });
                        return Ok(());
                    }
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

    /// `a == b` over lists (ASAM OpenSCENARIO DSL 2.1 §7.4.2.7.1: "every member of the first
    /// list is equal [...] to the member with the same index in the second list"): equal sizes,
    /// then each pair of members once the lists are sized (the next stage, `resolve`).
    fn list_equality(
        &mut self,
        op: BinOp,
        a: &TExpr,
        b: &TExpr,
        env: &Env,
        whole: &TExpr,
    ) -> Result<(), Fail> {
        if op != BinOp::Eq {
            return Err(Self::unsupported(
                whole,
                "inequality of lists (a disjunction)",
            ));
        }
        let (sa, ma) = self.list_side(a, env)?;
        let (sb, mb) = self.list_side(b, env)?;
        self.add(ConstraintKind::Linear {
            expr: sa.add_scaled(&sb, -1.0),
            rel: Relation::Eq,
        });
        let (Some(ma), Some(mb)) = (ma, mb) else {
            return Ok(());
        };
        for (x, y) in ma.iter().zip(&mb) {
            self.compare(BinOp::Eq, x, y, env, whole)?;
        }
        Ok(())
    }

    /// Whether `e` is a point of the `points` list of a library `relative_path` or
    /// `relative_trajectory` (`….points[i]`) that is a road-network reference (a `route_point`
    /// or `odr_point`, §8.12.33-34, §8.12.40-41), which the runtime reads from the constraint.
    fn runtime_point(&mut self, e: &TExpr, env: &Env) -> bool {
        let TKind::Path(place, segs) = &e.kind else {
            return false;
        };
        let [owner @ .., Seg::Field(f), Seg::Index(_)] = segs.as_slice() else {
            return false;
        };
        if f != "points" {
            return false;
        }
        let path = |segs: Vec<Seg>| TExpr {
            kind: TKind::Path(place.clone(), segs),
            ty: e.ty.clone(),
            span: e.span,
        };
        let library = |model: &Model, c: CompoundId, names: &[&str]| {
            model.ancestry(c).into_iter().any(|a| {
                let name = &model.compound(a).name;
                let bare = name.strip_prefix("std::").unwrap_or(name);
                is_library(model, a) && names.contains(&bare)
            })
        };
        let relative = match self.node(&path(owner.to_vec()), env) {
            Ok(n) => matches!(&self.tree.nodes[n], Node::Compound(c, _)
                if library(self.model, *c, &["relative_path", "relative_trajectory"])),
            Err(_) => false,
        };
        let points = path(
            owner
                .iter()
                .cloned()
                .chain([Seg::Field(f.clone())])
                .collect(),
        );
        relative
            && match self.node(&points, env) {
                Ok(n) => matches!(&self.tree.nodes[n], Node::List(Ty::Compound(c), ..)
                    if library(self.model, *c, &["route_element"])),
                Err(_) => false,
            }
    }

    /// The size of a list operand and its members, `None` while a list field is not sized.
    fn list_side(&mut self, e: &TExpr, env: &Env) -> Result<(Linear, Option<Vec<TExpr>>), Fail> {
        match &e.kind {
            TKind::List(items) => Ok((Linear::constant(items.len() as f64), Some(items.clone()))),
            TKind::Path(place, segs) => {
                let n = self.node(e, env)?;
                let Node::List(_, size, items) = &self.tree.nodes[n] else {
                    return Err(Self::unsupported(e, "this path"));
                };
                let (size, count) = (*size, items.as_ref().map(Vec::len));
                let elem = match &e.ty {
                    Ty::List(t) => (**t).clone(),
                    other => other.clone(),
                };
                let members = count.map(|k| {
                    (0..k)
                        .map(|i| TExpr {
                            kind: TKind::Path(
                                place.clone(),
                                segs.iter()
                                    .cloned()
                                    .chain([Seg::Index(Box::new(TExpr {
                                        kind: TKind::Number(i as f64),
                                        ty: Ty::Uint,
                                        span: e.span,
                                    }))])
                                    .collect(),
                            ),
                            ty: elem.clone(),
                            span: e.span,
                        })
                        .collect()
                });
                if members.is_none() {
                    self.out.pending.insert(n);
                }
                Ok((Linear::var(size), members))
            }
            _ => Err(Self::unsupported(e, describe(e))),
        }
    }

    pub(super) fn membership(
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

/// A boolean operand the enum and bool comparisons take as it is: a field or a constant.
fn plain(e: &TExpr) -> bool {
    matches!(e.kind, TKind::Path(..) | TKind::Bool(_) | TKind::Member(..))
}

fn member(e: &TExpr) -> Option<u32> {
    match e.kind {
        TKind::Member(_, m) => Some(m),
        TKind::Bool(b) => Some(b as u32),
        _ => None,
    }
}

pub(super) fn flip(op: BinOp) -> BinOp {
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
