//! The constraint solver for `keep(...)` (ASAM OpenSCENARIO DSL 2.1 §7.3.6 constraints).
//!
//! # Algorithm
//! The checker lowers the constraints of a program into a [`Problem`]: scalar variables (one
//! per field of every instance: numbers in SI units, enumeration members, strings) and a
//! conjunction of constraints over them — linear (in)equalities `Σ aᵢxᵢ + k ⋈ 0`
//! (`==`, `!=`, `<`, `<=`; ranges `x in [a..b]` are two of them), enumeration (non-)membership
//! (`==`, `!=`, `in [bus, truck]`), equality of two enumeration variables, string (in)equality
//! (with a text or between two strings), and `n == trunc(x)` (a `float` converted to a whole
//! number, `truncate.rs`).
//!
//! 1. **Interval propagation** (`propagate`) of the hard constraints to a fixpoint: each
//!    numeric variable has an interval (open or closed ends; whole numbers for `int`, `uint`
//!    and list sizes), each enumeration a member set. Every bound keeps the set of constraints
//!    it was derived from, so when a domain empties the error names the conflicting
//!    constraints (all of them, at least two when two constraints disagree).
//! 2. **Default constraints** (`keep(default …)`, a field's `= value`) in declaration order:
//!    dropped when a hard constraint mentions one of their variables (the standard: a hard
//!    constraint overrides the default on the same field), or when they conflict with what is
//!    already taken; otherwise propagated like hard ones. A dropped default over one variable
//!    stays a sampling preference (`width >= 1.95m` overriding a default `[1.6m..2.1m]` samples
//!    in `[1.95m, 2.1m]`).
//! 3. **Seeded sampling** ([`Solver::finish`]) of each variable still free, in variable order:
//!    uniform in its interval (whole numbers for integers), uniform among its members; each
//!    choice is propagated before the next, so linked variables (`a == b + 1m`) stay consistent.
//!    A side left unbounded is sampled in a window of `max(|bound|, 10)` SI units. Random numbers
//!    come from ChaCha8 seeded with the user's seed and are mapped to floats with integer
//!    arithmetic only, so a seed gives the same values on every machine.
//!
//! Lists are sized in stages by the caller (`semantics::resolve`): the size variables of the
//! lists known so far are sampled ([`Solver::sample`]) after propagation, then the elements
//! are created and their constraints added, until no list is left unsized.
//!
//! Disjunctions (`or`, `=>`, `not (a and b)`) are lowered to disjunctive normal form (at most
//! 64 alternatives) and kept as one constraint: propagation narrows domains once a single
//! alternative is possible and reports a conflict when none is (naming the constraints that
//! ruled each out); before sampling, each disjunction still open takes one of its possible
//! alternatives, chosen with the seeded generator (others tried in turn if its propagation
//! fails), so `keep(x < 10m or x > 90m)` samples from either side, never in between.
//!
//! # Out of scope
//! Products or quotients of two variables,
//! constraints over `var` fields and method results other than `size()` (they hold at run
//! time, not at resolution) — the checker reports these as unsupported by the solver. `!=`
//! between numbers is only checked once its variables are fixed, so it is met by resampling
//! (a few tries) rather than by propagation.

mod domain;
mod ir;
mod propagate;
mod solve;
mod truncate;

pub use domain::{Bound, Domain, Interval, BOUND_TOLERANCE};
pub use ir::{
    Constraint, ConstraintId, ConstraintKind, Linear, Problem, Relation, Strength, Value, Var,
    VarId, VarKind,
};
pub use solve::{Solution, SolveError, Solver};

#[cfg(test)]
mod tests;
