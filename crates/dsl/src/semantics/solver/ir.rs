//! The solver's input: typed variables and constraints over them (a small IR of its own, built by
//! `semantics::lower` from the checked `keep` constraints).

/// A variable's index in [`Problem::vars`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct VarId(pub u32);

/// A constraint's index in [`Problem::constraints`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ConstraintId(pub u32);

/// What values a variable takes.
#[derive(Debug, Clone, PartialEq)]
pub enum VarKind {
    /// A number in SI units; `integer` for `int`/`uint` (and list sizes), with `lo`/`hi` the
    /// type's own bounds (`uint` starts at 0).
    Number {
        /// Whether only whole numbers are allowed.
        integer: bool,
        /// The type's lower bound, if any.
        lo: Option<f64>,
        /// The type's upper bound, if any.
        hi: Option<f64>,
    },
    /// One of `count` enumeration members (by index); `bool` is a two-member enum (false, true).
    Enum {
        /// The number of members.
        count: u32,
    },
    /// A string.
    Text,
}

/// A variable: one scalar field of one instance.
#[derive(Debug, Clone, PartialEq)]
pub struct Var {
    /// Its path from the root instance (`my_wide_car.axles[0].number_of_wheels`), for messages.
    pub name: String,
    /// Its values.
    pub kind: VarKind,
}

/// `expr REL 0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Relation {
    /// `expr <= 0`
    Le,
    /// `expr < 0`
    Lt,
    /// `expr == 0`
    Eq,
    /// `expr != 0`
    Ne,
}

/// `Σ coefficient·var + constant`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Linear {
    /// Terms; a variable appears at most once.
    pub terms: Vec<(VarId, f64)>,
    /// The constant part.
    pub constant: f64,
}

impl Linear {
    /// The constant `c`.
    pub fn constant(c: f64) -> Linear {
        Linear {
            terms: Vec::new(),
            constant: c,
        }
    }

    /// The variable `v`.
    pub fn var(v: VarId) -> Linear {
        Linear {
            terms: vec![(v, 1.0)],
            constant: 0.0,
        }
    }

    /// `self + k·other`, merging terms of the same variable.
    pub fn add_scaled(mut self, other: &Linear, k: f64) -> Linear {
        for &(v, c) in &other.terms {
            match self.terms.iter_mut().find(|(w, _)| *w == v) {
                Some(t) => t.1 += k * c,
                None => self.terms.push((v, k * c)),
            }
        }
        self.terms.retain(|(_, c)| *c != 0.0);
        self.constant += k * other.constant;
        self
    }

    /// `k·self`.
    pub fn scale(mut self, k: f64) -> Linear {
        for t in &mut self.terms {
            t.1 *= k;
        }
        self.terms.retain(|(_, c)| *c != 0.0);
        self.constant *= k;
        self
    }
}

/// A constraint's body.
#[derive(Debug, Clone, PartialEq)]
pub enum ConstraintKind {
    /// A linear (in)equality over numbers.
    Linear {
        /// The left side of `expr REL 0`.
        expr: Linear,
        /// The relation.
        rel: Relation,
    },
    /// `var in {members}` (or `not in` when `negated`); `==`/`!=` a member is a one-member set.
    Member {
        /// The enumeration (or bool) variable.
        var: VarId,
        /// Member indices.
        set: Vec<u32>,
        /// `not in` / `!=`.
        negated: bool,
    },
    /// `a == b` (or `a != b`) between two enumeration variables of the same type.
    SameMember {
        /// One side.
        a: VarId,
        /// The other side.
        b: VarId,
        /// `!=`.
        negated: bool,
    },
    /// `var == "text"` (or `!=`).
    Text {
        /// The string variable.
        var: VarId,
        /// The text.
        value: String,
        /// `!=`.
        negated: bool,
    },
    /// `a == b` (or `a != b`) between two string variables.
    SameText {
        /// One side.
        a: VarId,
        /// The other side.
        b: VarId,
        /// `!=`.
        negated: bool,
    },
    /// `var == trunc(of)`: the whole part of a number, rounded toward zero (the conversion of a
    /// `float` to `int` or `uint`, `x.as(int)`).
    Truncate {
        /// The whole number.
        var: VarId,
        /// The number converted.
        of: VarId,
    },
    /// At least one of the alternatives holds, each a conjunction (`a or b`, `a => b`, in
    /// disjunctive normal form; alternatives hold no `Any` themselves). One alternative is a
    /// conjunction kept as one constraint (a default with the helper variables of a
    /// conversion is taken or dropped whole).
    Any(Vec<Vec<ConstraintKind>>),
}

impl ConstraintKind {
    /// The variables the constraint mentions.
    pub fn vars(&self) -> Vec<VarId> {
        match self {
            ConstraintKind::Linear { expr, .. } => expr.terms.iter().map(|t| t.0).collect(),
            ConstraintKind::Member { var, .. } | ConstraintKind::Text { var, .. } => vec![*var],
            ConstraintKind::SameMember { a, b, .. } | ConstraintKind::SameText { a, b, .. } => {
                vec![*a, *b]
            }
            ConstraintKind::Truncate { var, of } => vec![*var, *of],
            ConstraintKind::Any(alternatives) => {
                let mut vars: Vec<VarId> =
                    alternatives.iter().flatten().flat_map(Self::vars).collect();
                vars.sort_unstable();
                vars.dedup();
                vars
            }
        }
    }
}

/// Hard constraints must hold; a default one holds unless a hard constraint mentions one of its
/// variables (of its subject, [`Constraint::subject`]), or unless it contradicts the constraints
/// already taken (ASAM OpenSCENARIO DSL 2.1 §7.3.6.5 default constraints).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Strength {
    /// `keep(...)` / `keep(hard: ...)`.
    Hard,
    /// `keep(default ...)` and a field's `= value`.
    Default,
}

/// A constraint with where it came from (an opaque tag the caller maps back to source).
#[derive(Debug, Clone, PartialEq)]
pub struct Constraint {
    /// The body.
    pub kind: ConstraintKind,
    /// Hard or default.
    pub strength: Strength,
    /// The caller's tag for it (an index into its own table of spans).
    pub origin: u32,
    /// For a default: the variables it is a default of (a field's `= value` is about that
    /// field, not the fields its value reads); empty for every variable it mentions.
    pub subject: Vec<VarId>,
}

/// A conjunction of constraints over variables.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Problem {
    /// The variables.
    pub vars: Vec<Var>,
    /// The constraints.
    pub constraints: Vec<Constraint>,
}

impl Problem {
    /// Adds a variable.
    pub fn add_var(&mut self, name: impl Into<String>, kind: VarKind) -> VarId {
        self.vars.push(Var {
            name: name.into(),
            kind,
        });
        VarId(self.vars.len() as u32 - 1)
    }

    /// Adds a constraint.
    pub fn add(&mut self, kind: ConstraintKind, strength: Strength, origin: u32) -> ConstraintId {
        self.constraints.push(Constraint {
            kind,
            strength,
            origin,
            subject: Vec::new(),
        });
        ConstraintId(self.constraints.len() as u32 - 1)
    }
}

/// A variable's chosen value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// A number, in SI units.
    Number(f64),
    /// An enumeration member (index); for bool, 0 is false.
    Member(u32),
    /// A string.
    Text(String),
}
