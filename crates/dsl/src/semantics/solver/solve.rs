//! The solving loop: hard constraints, then default ones, then seeded sampling of what stays free.

use rand_chacha::rand_core::{RngCore, SeedableRng};
use rand_chacha::ChaCha8Rng;

use super::domain::{Domain, Interval, Why};
use super::ir::{Constraint, ConstraintId, ConstraintKind, Problem, Strength, Value, VarId};
use super::propagate::Store;

/// Samples tried for one variable before the solver gives up on it.
const TRIES: usize = 8;

/// Half-width of the window a variable unbounded on one or both sides is sampled in, at least:
/// `[lo, lo + max(|lo|, WINDOW)]`, `[-WINDOW, WINDOW]` (SI units).
const WINDOW: f64 = 10.0;

/// Why a problem has no solution.
#[derive(Debug, Clone, PartialEq)]
pub enum SolveError {
    /// The hard constraints conflict; these are the ones involved (at least one).
    Unsat {
        /// The conflicting constraints.
        constraints: Vec<ConstraintId>,
    },
    /// Propagation found no conflict, but no sampled value of `var` satisfied these constraints
    /// (constraints propagation cannot fully decide, such as `!=` between variables).
    NoValue {
        /// The variable.
        var: VarId,
        /// The constraints that rejected the samples.
        constraints: Vec<ConstraintId>,
    },
}

/// The values chosen, one per variable, and which default constraints were dropped.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// Indexed by `VarId`.
    pub values: Vec<Value>,
    /// Default constraints not applied (overridden or contradicted).
    pub dropped_defaults: Vec<ConstraintId>,
}

/// A problem with its hard and default constraints applied, ready to sample from.
#[derive(Debug, Clone)]
pub struct Solver<'p> {
    problem: &'p Problem,
    store: Store,
    /// Unconstrained domains, for working out hints.
    fresh: Store,
    active: Vec<bool>,
    watch: Vec<Vec<u32>>,
    hints: Vec<Option<Domain>>,
    dropped: Vec<ConstraintId>,
    rng: ChaCha8Rng,
}

impl<'p> Solver<'p> {
    /// Applies the hard constraints (`Err` on a conflict), then each default constraint in order
    /// unless a hard constraint mentions one of its subject's variables (all it mentions when it
    /// names none) or it conflicts with those taken.
    pub fn new(problem: &'p Problem, seed: u64) -> Result<Solver<'p>, SolveError> {
        let store = Store::new(problem.vars.iter().map(|v| Domain::of(&v.kind)).collect());
        let mut watch = vec![Vec::new(); problem.vars.len()];
        for (i, c) in problem.constraints.iter().enumerate() {
            for v in c.kind.vars() {
                watch[v.0 as usize].push(i as u32);
            }
        }
        let mut s = Solver {
            problem,
            fresh: store.clone(),
            store,
            active: vec![false; problem.constraints.len()],
            watch,
            hints: vec![None; problem.vars.len()],
            dropped: Vec::new(),
            rng: ChaCha8Rng::seed_from_u64(seed),
        };
        let mut hard_vars = vec![false; problem.vars.len()];
        for (i, c) in problem.constraints.iter().enumerate() {
            if c.strength == Strength::Hard {
                s.active[i] = true;
                for v in c.kind.vars() {
                    hard_vars[v.0 as usize] = true;
                }
            }
        }
        s.run(0..problem.constraints.len() as u32)
            .map_err(|constraints| SolveError::Unsat { constraints })?;
        for (i, c) in problem.constraints.iter().enumerate() {
            if c.strength != Strength::Default {
                continue;
            }
            let id = ConstraintId(i as u32);
            let vars = c.kind.vars();
            let subject = if c.subject.is_empty() {
                &vars
            } else {
                &c.subject
            };
            if subject.iter().any(|v| hard_vars[v.0 as usize]) {
                s.dropped.push(id);
                s.record_hint(&vars, c, id);
                continue;
            }
            let mark = s.store.checkpoint();
            s.active[i] = true;
            if s.run([id.0]).is_err() {
                s.active[i] = false;
                s.store.undo(mark);
                s.dropped.push(id);
            }
        }
        Ok(s)
    }

    /// The current domain of `v`.
    pub fn domain(&self, v: VarId) -> &Domain {
        &self.store.doms[v.0 as usize]
    }

    /// Chooses a value for each of `vars` in order, each choice propagated before the next;
    /// first, each disjunction over them still open takes one of its possible alternatives.
    pub fn sample(&mut self, vars: &[VarId]) -> Result<(), SolveError> {
        self.decide(vars);
        for &v in vars {
            self.sample_one(v)?;
        }
        Ok(())
    }

    /// Chooses values for every variable still free and returns the solution.
    pub fn finish(mut self) -> Result<Solution, SolveError> {
        let all: Vec<VarId> = (0..self.problem.vars.len() as u32).map(VarId).collect();
        self.sample(&all)?;
        let values = self.store.doms.iter().map(value_of).collect();
        Ok(Solution {
            values,
            dropped_defaults: self.dropped,
        })
    }

    /// For each active disjunction over one of `vars` with more than one alternative still
    /// possible, in constraint order: takes one of them, chosen uniformly with the seeded
    /// generator, and propagates it; one that fails is undone and the next (in a rotation
    /// from the chosen one) is tried. Taking an alternative only narrows domains; the
    /// disjunction itself stays active, so every sampled value is checked against all of it.
    fn decide(&mut self, vars: &[VarId]) {
        let mut mentioned = vec![false; self.problem.vars.len()];
        for v in vars {
            mentioned[v.0 as usize] = true;
        }
        for (i, c) in self.problem.constraints.iter().enumerate() {
            let ConstraintKind::Any(alternatives) = &c.kind else {
                continue;
            };
            if !self.active[i] || !c.kind.vars().iter().any(|v| mentioned[v.0 as usize]) {
                continue;
            }
            let id = ConstraintId(i as u32);
            let Ok(alive) = self.store.alive(id, alternatives) else {
                continue;
            };
            if alive.len() < 2 {
                continue;
            }
            let first = ((self.next_unit() * alive.len() as f64) as usize).min(alive.len() - 1);
            for k in 0..alive.len() {
                let alt = &alternatives[alive[(first + k) % alive.len()]];
                let mark = self.store.checkpoint();
                let seeds: Vec<u32> = alt
                    .iter()
                    .flat_map(ConstraintKind::vars)
                    .flat_map(|v| self.watch[v.0 as usize].clone())
                    .collect();
                if self.store.apply_all(id, alt).is_ok() && self.run(seeds).is_ok() {
                    break;
                }
                self.store.undo(mark);
            }
        }
    }

    fn run(&mut self, seeds: impl IntoIterator<Item = u32>) -> Result<(), Why> {
        self.store
            .propagate(&self.problem.constraints, &self.active, &self.watch, seeds)
    }

    /// A dropped default over one variable still says where its values usually lie: sampling
    /// prefers that range where the hard constraints leave room in it.
    fn record_hint(&mut self, vars: &[VarId], c: &Constraint, id: ConstraintId) {
        let [v] = vars else { return };
        let mark = self.fresh.checkpoint();
        if self.fresh.propagate_one(id, c).is_ok() {
            self.hints[v.0 as usize] = Some(self.fresh.doms[v.0 as usize].clone());
        }
        self.fresh.undo(mark);
    }

    fn sample_one(&mut self, v: VarId) -> Result<(), SolveError> {
        let idx = v.0 as usize;
        if is_fixed(&self.store.doms[idx]) {
            return Ok(());
        }
        let mut last_why = Vec::new();
        for attempt in 0..TRIES + 1 {
            let choice = self.choose(idx, attempt == TRIES);
            let mark = self.store.checkpoint();
            let mut fixed = self.store.doms[idx].clone();
            fix(&mut fixed, &choice);
            self.store.set(v, fixed);
            let watchers = self.watch[idx].clone();
            match self.run(watchers) {
                Ok(()) => return Ok(()),
                Err(why) => {
                    last_why = why;
                    self.store.undo(mark);
                }
            }
        }
        Err(SolveError::NoValue {
            var: v,
            constraints: last_why,
        })
    }

    fn next_unit(&mut self) -> f64 {
        // 53 random bits → [0, 1): the same on every machine for a seed.
        (self.rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn choose(&mut self, idx: usize, fallback: bool) -> Value {
        let hint = self.hints[idx].clone();
        match self.store.doms[idx].clone() {
            Domain::Number(i) => {
                let i = match hint {
                    Some(Domain::Number(h)) => intersect(&i, &h).unwrap_or(i),
                    _ => i,
                };
                let (lo, hi) = window(&i);
                if fallback {
                    return Value::Number(if i.integer { lo } else { (lo + hi) / 2.0 });
                }
                let u = self.next_unit();
                if i.integer {
                    let n = (hi - lo + 1.0).max(1.0);
                    Value::Number((lo + (u * n).floor()).min(hi))
                } else {
                    let x = lo + u * (hi - lo);
                    Value::Number(if i.contains(x) { x } else { (lo + hi) / 2.0 })
                }
            }
            Domain::Members { allowed, .. } => {
                let mut pool: Vec<u32> = (0..allowed.len() as u32)
                    .filter(|m| allowed[*m as usize])
                    .collect();
                if let Some(Domain::Members { allowed: h, .. }) = hint {
                    let preferred: Vec<u32> =
                        pool.iter().copied().filter(|m| h[*m as usize]).collect();
                    if !preferred.is_empty() {
                        pool = preferred;
                    }
                }
                if pool.is_empty() {
                    return Value::Member(0);
                }
                let k = ((self.next_unit() * pool.len() as f64) as usize).min(pool.len() - 1);
                Value::Member(pool[k])
            }
            Domain::Text {
                fixed, excluded, ..
            } => {
                if let Some(f) = fixed {
                    return Value::Text(f);
                }
                let mut n = 0;
                let mut t = String::new();
                while excluded.contains(&t) {
                    n += 1;
                    t = format!("text{n}");
                }
                Value::Text(t)
            }
        }
    }
}

/// The finite range a numeric domain is sampled in.
fn window(i: &Interval) -> (f64, f64) {
    let (lo, hi) = (i.lo.value, i.hi.value);
    let (lo, hi) = match (lo.is_finite(), hi.is_finite()) {
        (true, true) => (lo, hi),
        (true, false) => (lo, lo + lo.abs().max(WINDOW)),
        (false, true) => (hi - hi.abs().max(WINDOW), hi),
        (false, false) => (-WINDOW, WINDOW),
    };
    if i.integer {
        (lo.ceil(), hi.floor().max(lo.ceil()))
    } else {
        (lo, hi)
    }
}

fn intersect(a: &Interval, b: &Interval) -> Option<Interval> {
    let mut out = a.clone();
    out.raise(b.lo.value, b.lo.open, a.lo.why.clone());
    out.lower(b.hi.value, b.hi.open, a.hi.why.clone());
    (!out.is_empty()).then_some(out)
}

fn is_fixed(d: &Domain) -> bool {
    match d {
        Domain::Number(i) => i.fixed().is_some(),
        Domain::Members { allowed, .. } => allowed.iter().filter(|a| **a).count() == 1,
        Domain::Text { fixed, .. } => fixed.is_some(),
    }
}

fn fix(d: &mut Domain, v: &Value) {
    match (d, v) {
        (Domain::Number(i), Value::Number(x)) => {
            i.lo.value = *x;
            i.lo.open = false;
            i.hi.value = *x;
            i.hi.open = false;
        }
        (Domain::Members { allowed, .. }, Value::Member(m)) => {
            for (k, a) in allowed.iter_mut().enumerate() {
                *a = k as u32 == *m;
            }
        }
        (Domain::Text { fixed, .. }, Value::Text(t)) => *fixed = Some(t.clone()),
        _ => {}
    }
}

fn value_of(d: &Domain) -> Value {
    match d {
        Domain::Number(i) => Value::Number(i.lo.value),
        Domain::Members { allowed, .. } => {
            Value::Member(allowed.iter().position(|a| *a).unwrap_or(0) as u32)
        }
        Domain::Text { fixed, .. } => Value::Text(fixed.clone().unwrap_or_default()),
    }
}
