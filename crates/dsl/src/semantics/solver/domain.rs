//! Variable domains: intervals (with open or closed ends) for numbers, member sets for
//! enumerations, a fixed-or-free value for strings. Each bound remembers the constraints that
//! produced it, so an empty domain names the constraints that conflict.

use super::ir::{ConstraintId, VarKind};

/// Relative tolerance under which two bounds count as equal (float rounding in propagation:
/// `x + y == 1` with `y = 0.3` gives `x ∈ [0.7000000000000001, 0.7]`).
pub const BOUND_TOLERANCE: f64 = 1e-9;

/// Constraints a bound or a removal derives from (sorted, no duplicates).
pub type Why = Vec<ConstraintId>;

/// Union of two reason sets.
pub fn union(a: &Why, b: &Why) -> Why {
    let mut out = Vec::with_capacity(a.len() + b.len());
    out.extend_from_slice(a);
    out.extend_from_slice(b);
    out.sort_unstable();
    out.dedup();
    out
}

/// One end of an interval.
#[derive(Debug, Clone, PartialEq)]
pub struct Bound {
    /// The value (±∞ when unbounded).
    pub value: f64,
    /// Whether the end itself is excluded.
    pub open: bool,
    /// The constraints that set it.
    pub why: Why,
}

/// A numeric domain.
#[derive(Debug, Clone, PartialEq)]
pub struct Interval {
    /// Lower end.
    pub lo: Bound,
    /// Upper end.
    pub hi: Bound,
    /// Whole numbers only.
    pub integer: bool,
}

impl Interval {
    /// The interval of a variable of kind `Number`.
    pub fn new(integer: bool, lo: Option<f64>, hi: Option<f64>) -> Interval {
        let b = |v: f64| Bound {
            value: v,
            open: false,
            why: Vec::new(),
        };
        Interval {
            lo: b(lo.unwrap_or(f64::NEG_INFINITY)),
            hi: b(hi.unwrap_or(f64::INFINITY)),
            integer,
        }
    }

    /// Whether no number fits.
    pub fn is_empty(&self) -> bool {
        let (lo, hi) = (self.lo.value, self.hi.value);
        if !lo.is_finite() || !hi.is_finite() {
            return lo > hi;
        }
        let tol = BOUND_TOLERANCE * lo.abs().max(hi.abs()).max(1.0);
        if lo > hi + tol {
            return true;
        }
        (self.lo.open || self.hi.open) && (hi - lo).abs() <= tol
    }

    /// The single value, if the interval is one point (an unbounded one never is: its
    /// tolerance would be infinite).
    pub fn fixed(&self) -> Option<f64> {
        let tol = BOUND_TOLERANCE * self.lo.value.abs().max(1.0);
        (self.lo.value.is_finite()
            && (self.hi.value - self.lo.value).abs() <= tol
            && !self.lo.open
            && !self.hi.open)
            .then_some(self.lo.value)
    }

    /// Raises the lower end to `value`; true when it moved.
    pub fn raise(&mut self, value: f64, open: bool, why: Why) -> bool {
        let (mut value, mut open) = (value, open);
        if self.integer && value.is_finite() {
            let c = value.ceil();
            value = if open && c == value { c + 1.0 } else { c };
            open = false;
        }
        let tighter = value > self.lo.value + significant(self.lo.value, value)
            || (value >= self.lo.value && open && !self.lo.open);
        if tighter {
            self.lo = Bound { value, open, why };
        }
        tighter
    }

    /// Lowers the upper end to `value`; true when it moved.
    pub fn lower(&mut self, value: f64, open: bool, why: Why) -> bool {
        let (mut value, mut open) = (value, open);
        if self.integer && value.is_finite() {
            let f = value.floor();
            value = if open && f == value { f - 1.0 } else { f };
            open = false;
        }
        let tighter = value < self.hi.value - significant(self.hi.value, value)
            || (value <= self.hi.value && open && !self.hi.open);
        if tighter {
            self.hi = Bound { value, open, why };
        }
        tighter
    }

    /// Whether `x` lies inside.
    pub fn contains(&self, x: f64) -> bool {
        let above = if self.lo.open {
            x > self.lo.value
        } else {
            x >= self.lo.value
        };
        let below = if self.hi.open {
            x < self.hi.value
        } else {
            x <= self.hi.value
        };
        above && below && (!self.integer || x.fract() == 0.0)
    }
}

/// The smallest change worth recording between two bounds, so that propagation on cycles
/// (`x < y`, `y < x` over floats) stops instead of creeping forever.
fn significant(old: f64, new: f64) -> f64 {
    if !old.is_finite() {
        return 0.0;
    }
    BOUND_TOLERANCE * old.abs().max(new.abs()).max(1.0)
}

/// A variable's domain.
#[derive(Debug, Clone, PartialEq)]
pub enum Domain {
    /// A number.
    Number(Interval),
    /// Enumeration members still allowed, and why each removed one went.
    Members {
        /// `allowed[i]`: member `i` may still be chosen.
        allowed: Vec<bool>,
        /// The constraints that removed members.
        why: Why,
    },
    /// A string: fixed to one text, or free except for excluded texts.
    Text {
        /// The text it must be.
        fixed: Option<String>,
        /// Texts it must not be.
        excluded: Vec<String>,
        /// The constraints that set or excluded texts.
        why: Why,
    },
}

impl Domain {
    /// The full domain of a variable kind.
    pub fn of(kind: &VarKind) -> Domain {
        match kind {
            VarKind::Number { integer, lo, hi } => {
                Domain::Number(Interval::new(*integer, *lo, *hi))
            }
            VarKind::Enum { count } => Domain::Members {
                allowed: vec![true; *count as usize],
                why: Vec::new(),
            },
            VarKind::Text => Domain::Text {
                fixed: None,
                excluded: Vec::new(),
                why: Vec::new(),
            },
        }
    }

    /// When empty: the constraints that emptied it.
    pub fn conflict(&self) -> Option<Why> {
        match self {
            Domain::Number(i) => i.is_empty().then(|| union(&i.lo.why, &i.hi.why)),
            Domain::Members { allowed, why } => (!allowed.iter().any(|a| *a)).then(|| why.clone()),
            Domain::Text {
                fixed,
                excluded,
                why,
            } => fixed
                .as_ref()
                .filter(|f| excluded.contains(f))
                .map(|_| why.clone()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_bounds_round_inwards_and_strict_ends_step_over() {
        let mut i = Interval::new(true, Some(0.0), None);
        // x > 2.5 over integers: x >= 3; x < 5: x <= 4.
        assert!(i.raise(2.5, true, vec![]));
        assert_eq!(i.lo.value, 3.0);
        assert!(i.lower(5.0, true, vec![]));
        assert_eq!(i.hi.value, 4.0);
        assert!(!i.is_empty());
        assert!(i.contains(4.0) && !i.contains(5.0) && !i.contains(3.5));
    }

    #[test]
    fn an_open_point_is_empty_and_a_closed_point_is_fixed() {
        let mut i = Interval::new(false, None, None);
        i.raise(2.0, false, vec![ConstraintId(0)]);
        i.lower(2.0, false, vec![ConstraintId(1)]);
        assert_eq!(i.fixed(), Some(2.0));
        i.lower(2.0, true, vec![ConstraintId(2)]);
        assert!(i.is_empty());
        let d = Domain::Number(i);
        assert_eq!(d.conflict(), Some(vec![ConstraintId(0), ConstraintId(2)]));
    }

    /// Regression (issue 30): an interval open on both sides (-inf, +inf) was "fixed" at -inf,
    /// since its tolerance BOUND_TOLERANCE·|-inf| is infinite; a free `float` or `int` field
    /// then resolved to -inf (and `int` to i64::MIN).
    #[test]
    fn an_unbounded_interval_is_not_fixed() {
        let i = Interval::new(false, None, None);
        assert_eq!(i.fixed(), None);
        let mut j = Interval::new(true, None, None);
        j.raise(-3.0, false, vec![]);
        assert_eq!(j.fixed(), None);
    }

    #[test]
    fn rounding_noise_is_not_a_conflict() {
        let mut i = Interval::new(false, None, None);
        i.raise(0.7000000000000001, false, vec![]);
        i.lower(0.7, false, vec![]);
        assert!(!i.is_empty());
    }
}
