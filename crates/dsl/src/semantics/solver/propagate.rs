//! Bounds propagation to a fixpoint over the active constraints.
//!
//! A linear constraint `Σ aᵢxᵢ + k ≤ 0` bounds each `xᵢ` by the extreme values the other terms
//! can take (interval arithmetic); `==` is `≤` both ways; `!=` is only checked once all its
//! variables are fixed. Member constraints intersect member sets. A disjunction narrows
//! domains once only one of its alternatives is still possible, and is a conflict when none is. Each new bound records the
//! constraint and the bounds it was computed from, so an emptied domain names its causes.

use super::domain::{union, Domain, Interval, Why, BOUND_TOLERANCE};
use super::ir::{Constraint, ConstraintId, ConstraintKind, Linear, Relation, VarId};
use super::truncate;

/// Propagation budget: this many applications per constraint; past it propagation stops early,
/// which is sound (domains are only wider than they could be) and sampling still checks every
/// constraint.
const MAX_PASSES: usize = 1000;

/// The current domain of every variable, with a trail of replaced domains so that a failed
/// choice is undone in the time of its own changes (not a copy of every domain).
#[derive(Debug, Clone)]
pub struct Store {
    /// Indexed by `VarId`.
    pub doms: Vec<Domain>,
    /// `(variable, domain before)` for each domain about to change, oldest first.
    trail: Vec<(u32, Domain)>,
}

impl Store {
    /// A store with these domains.
    pub fn new(doms: Vec<Domain>) -> Store {
        Store {
            doms,
            trail: Vec::new(),
        }
    }

    /// A point to [`undo`](Self::undo) to.
    pub fn checkpoint(&self) -> usize {
        self.trail.len()
    }

    /// Restores every domain changed since `mark`.
    pub fn undo(&mut self, mark: usize) {
        while self.trail.len() > mark {
            if let Some((v, d)) = self.trail.pop() {
                self.doms[v as usize] = d;
            }
        }
    }

    /// Sets a domain (recorded on the trail).
    pub fn set(&mut self, v: VarId, d: Domain) {
        *self.dom_mut(v) = d;
    }

    fn dom_mut(&mut self, v: VarId) -> &mut Domain {
        let i = v.0 as usize;
        self.trail.push((v.0, self.doms[i].clone()));
        &mut self.doms[i]
    }

    /// Propagates to a fixpoint with a work list: starts from `seeds`, and each time a
    /// constraint narrows a domain, queues the active constraints watching its variables.
    /// `Err` names the constraints of a conflict.
    pub fn propagate(
        &mut self,
        constraints: &[Constraint],
        active: &[bool],
        watch: &[Vec<u32>],
        seeds: impl IntoIterator<Item = u32>,
    ) -> Result<(), Why> {
        let mut queued = vec![false; constraints.len()];
        let mut queue = std::collections::VecDeque::new();
        for c in seeds {
            if active[c as usize] && !queued[c as usize] {
                queued[c as usize] = true;
                queue.push_back(c);
            }
        }
        let mut budget = MAX_PASSES * (constraints.len() + 1);
        while let Some(c) = queue.pop_front() {
            queued[c as usize] = false;
            if budget == 0 {
                return Ok(());
            }
            budget -= 1;
            let kind = &constraints[c as usize].kind;
            if self.apply(ConstraintId(c), kind)? {
                for v in kind.vars() {
                    for &w in &watch[v.0 as usize] {
                        if active[w as usize] && !queued[w as usize] {
                            queued[w as usize] = true;
                            queue.push_back(w);
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// Propagates one constraint alone to a fixpoint.
    pub fn propagate_one(&mut self, id: ConstraintId, c: &Constraint) -> Result<(), Why> {
        for _ in 0..MAX_PASSES {
            if !self.apply(id, &c.kind)? {
                return Ok(());
            }
        }
        Ok(())
    }

    fn interval(&self, v: VarId) -> Option<&Interval> {
        match &self.doms[v.0 as usize] {
            Domain::Number(i) => Some(i),
            _ => None,
        }
    }

    /// One constraint once; true when a domain changed.
    fn apply(&mut self, id: ConstraintId, kind: &ConstraintKind) -> Result<bool, Why> {
        match kind {
            ConstraintKind::Linear { expr, rel } => match rel {
                Relation::Le => self.linear_le(id, expr, false),
                Relation::Lt => self.linear_le(id, expr, true),
                Relation::Eq => {
                    let a = self.linear_le(id, expr, false)?;
                    let b = self.linear_le(id, &expr.clone().scale(-1.0), false)?;
                    Ok(a || b)
                }
                Relation::Ne => self.linear_ne(id, expr).map(|_| false),
            },
            ConstraintKind::Member { var, set, negated } => {
                let Domain::Members { allowed, why } = self.dom_mut(*var) else {
                    return Ok(false);
                };
                let mut changed = false;
                for (m, a) in allowed.iter_mut().enumerate() {
                    let listed = set.contains(&(m as u32));
                    if *a && listed == *negated {
                        *a = false;
                        changed = true;
                    }
                }
                if changed {
                    *why = union(why, &vec![id]);
                }
                self.check(*var)?;
                Ok(changed)
            }
            ConstraintKind::SameMember { a, b, negated } => {
                let (Some((aa, wa)), Some((ab, wb))) = (self.members(*a), self.members(*b)) else {
                    return Ok(false);
                };
                let mut changed = false;
                if *negated {
                    let why = union(&union(&wa, &wb), &vec![id]);
                    if let Some(m) = single(&aa) {
                        changed |= self.remove(*b, m, why.clone());
                    }
                    if let Some(m) = single(&ab) {
                        changed |= self.remove(*a, m, why);
                    }
                } else {
                    let both: Vec<bool> = aa.iter().zip(&ab).map(|(x, y)| *x && *y).collect();
                    let why = union(&union(&wa, &wb), &vec![id]);
                    for v in [*a, *b] {
                        for (m, keep) in both.iter().enumerate() {
                            if !keep {
                                changed |= self.remove(v, m, why.clone());
                            }
                        }
                    }
                }
                self.check(*a)?;
                self.check(*b)?;
                Ok(changed)
            }
            ConstraintKind::SameText { a, b, negated } => self.same_text(id, *a, *b, *negated),
            ConstraintKind::Truncate { var, of } => self.truncate(id, *var, *of),
            // A disjunction narrows domains only once a single alternative is left.
            ConstraintKind::Any(alternatives) => match self.alive(id, alternatives)?.as_slice() {
                [only] => self.apply_all(id, &alternatives[*only]),
                _ => Ok(false),
            },
            ConstraintKind::Text {
                var,
                value,
                negated,
            } => {
                let Domain::Text {
                    fixed,
                    excluded,
                    why,
                } = self.dom_mut(*var)
                else {
                    return Ok(false);
                };
                let mut changed = false;
                if *negated {
                    if !excluded.contains(value) {
                        excluded.push(value.clone());
                        *why = union(why, &vec![id]);
                        changed = true;
                    }
                } else {
                    match fixed {
                        None => {
                            *fixed = Some(value.clone());
                            *why = union(why, &vec![id]);
                            changed = true;
                        }
                        Some(f) if f != value => return Err(union(why, &vec![id])),
                        Some(_) => {}
                    }
                }
                self.check(*var)?;
                Ok(changed)
            }
        }
    }

    /// Applies every constraint of a conjunction until none narrows a domain (the budget of
    /// [`propagate_one`](Self::propagate_one)); true when a domain changed.
    pub fn apply_all(&mut self, id: ConstraintId, kinds: &[ConstraintKind]) -> Result<bool, Why> {
        let mut any = false;
        for _ in 0..MAX_PASSES {
            let mut changed = false;
            for k in kinds {
                changed |= self.apply(id, k)?;
            }
            if !changed {
                break;
            }
            any = true;
        }
        Ok(any)
    }

    /// The alternatives of a disjunction that the current domains still allow, or why none.
    pub fn alive(
        &mut self,
        id: ConstraintId,
        alternatives: &[Vec<ConstraintKind>],
    ) -> Result<Vec<usize>, Why> {
        let mut alive = Vec::new();
        let mut why: Why = vec![id];
        for (k, alt) in alternatives.iter().enumerate() {
            let mark = self.checkpoint();
            match self.apply_all(id, alt) {
                Ok(_) => alive.push(k),
                Err(w) => why = union(&why, &w),
            }
            self.undo(mark);
        }
        if alive.is_empty() {
            Err(why)
        } else {
            Ok(alive)
        }
    }

    /// `a == b` between strings: a fixed side fixes the other (`!=`: excludes its text there).
    fn same_text(
        &mut self,
        id: ConstraintId,
        a: VarId,
        b: VarId,
        negated: bool,
    ) -> Result<bool, Why> {
        let mut changed = false;
        for (from, to) in [(a, b), (b, a)] {
            let Domain::Text {
                fixed: Some(text),
                why: from_why,
                ..
            } = &self.doms[from.0 as usize]
            else {
                continue;
            };
            let (text, reason) = (text.clone(), union(from_why, &vec![id]));
            let Domain::Text {
                fixed,
                excluded,
                why,
                ..
            } = &self.doms[to.0 as usize]
            else {
                continue;
            };
            let done = if negated {
                excluded.contains(&text)
            } else {
                fixed.as_ref() == Some(&text)
            };
            if done {
                continue;
            }
            if !negated && fixed.is_some() {
                return Err(union(why, &reason));
            }
            let Domain::Text {
                fixed,
                excluded,
                why,
                ..
            } = self.dom_mut(to)
            else {
                continue;
            };
            if negated {
                excluded.push(text);
            } else {
                *fixed = Some(text);
            }
            *why = union(why, &reason);
            changed = true;
            self.check(to)?;
        }
        Ok(changed)
    }

    /// `var == trunc(of)` both ways over intervals (`truncate.rs`).
    fn truncate(&mut self, id: ConstraintId, var: VarId, of: VarId) -> Result<bool, Why> {
        let (Some(x), Some(n)) = (self.interval(of).cloned(), self.interval(var).cloned()) else {
            return Ok(false);
        };
        let mut changed = false;
        let (lo, hi) = truncate::image(&x);
        let Domain::Number(iv) = self.dom_mut(var) else {
            return Ok(false);
        };
        if let Some(lo) = lo {
            changed |= iv.raise(lo, false, union(&x.lo.why, &vec![id]));
        }
        if let Some(hi) = hi {
            changed |= iv.lower(hi, false, union(&x.hi.why, &vec![id]));
        }
        self.check(var)?;
        let ((lo, lo_open), (hi, hi_open)) = truncate::preimage(&n);
        let Domain::Number(iv) = self.dom_mut(of) else {
            return Ok(changed);
        };
        if lo.is_finite() {
            changed |= iv.raise(lo, lo_open, union(&n.lo.why, &vec![id]));
        }
        if hi.is_finite() {
            changed |= iv.lower(hi, hi_open, union(&n.hi.why, &vec![id]));
        }
        self.check(of)?;
        Ok(changed)
    }

    fn members(&self, v: VarId) -> Option<(Vec<bool>, Why)> {
        match &self.doms[v.0 as usize] {
            Domain::Members { allowed, why } => Some((allowed.clone(), why.clone())),
            _ => None,
        }
    }

    fn remove(&mut self, v: VarId, m: usize, reason: Why) -> bool {
        if let Domain::Members { allowed, why } = self.dom_mut(v) {
            if allowed.get(m).copied().unwrap_or(false) {
                allowed[m] = false;
                *why = union(why, &reason);
                return true;
            }
        }
        false
    }

    fn check(&self, v: VarId) -> Result<(), Why> {
        match self.doms[v.0 as usize].conflict() {
            Some(why) => Err(why),
            None => Ok(()),
        }
    }

    /// `expr ≤ 0` (`< 0` when `strict`).
    fn linear_le(&mut self, id: ConstraintId, expr: &Linear, strict: bool) -> Result<bool, Why> {
        // The least value of each term, with whether it is attained and why.
        let mut mins = Vec::with_capacity(expr.terms.len());
        for &(v, a) in &expr.terms {
            let Some(i) = self.interval(v) else {
                return Ok(false);
            };
            let b = if a > 0.0 { &i.lo } else { &i.hi };
            mins.push((a * b.value, b.open, b.why.clone()));
        }
        if expr.terms.is_empty() {
            let holds = if strict {
                expr.constant < 0.0
            } else {
                expr.constant <= 0.0
            };
            return if holds { Ok(false) } else { Err(vec![id]) };
        }
        let mut changed = false;
        for (i, &(v, a)) in expr.terms.iter().enumerate() {
            // a·x ≤ -(k + Σ_{j≠i} min_j)
            let mut rest = expr.constant;
            let mut open = strict;
            let mut why = vec![id];
            for (j, (m, o, w)) in mins.iter().enumerate() {
                if j != i {
                    rest += m;
                    open |= *o;
                    why = union(&why, w);
                }
            }
            if !rest.is_finite() {
                continue;
            }
            let bound = -rest / a;
            let Domain::Number(iv) = self.dom_mut(v) else {
                continue;
            };
            let moved = if a > 0.0 {
                iv.lower(bound, open, why)
            } else {
                iv.raise(bound, open, why)
            };
            changed |= moved;
            self.check(v)?;
        }
        Ok(changed)
    }

    /// `expr != 0`: a conflict only when every variable is fixed and the value is 0.
    fn linear_ne(&self, id: ConstraintId, expr: &Linear) -> Result<(), Why> {
        let mut value = expr.constant;
        let mut why = vec![id];
        for &(v, a) in &expr.terms {
            let Some(i) = self.interval(v) else {
                return Ok(());
            };
            let Some(x) = i.fixed() else { return Ok(()) };
            value += a * x;
            why = union(&why, &union(&i.lo.why, &i.hi.why));
        }
        let scale = expr.constant.abs().max(1.0);
        if value.abs() <= BOUND_TOLERANCE * scale {
            Err(why)
        } else {
            Ok(())
        }
    }
}

fn single(allowed: &[bool]) -> Option<usize> {
    let mut it = allowed.iter().enumerate().filter(|(_, a)| **a);
    let first = it.next()?.0;
    it.next().is_none().then_some(first)
}
