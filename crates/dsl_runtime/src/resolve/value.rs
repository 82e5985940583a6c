//! The values a resolved scenario hands to the planner (ASAM OpenSCENARIO DSL 2.1 §7.4
//! expressions, evaluated): numbers in SI units, enumeration members, booleans and the paths of
//! the instances arguments name, each with where it is written; and the run's stream of draws.

use rand_chacha::rand_core::{RngCore, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::error::{Error, ErrorKind as K, Site};

/// A constant value.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Val {
    /// A number in SI units.
    Num(f64),
    /// An enumeration member.
    Enum(String),
    /// A boolean.
    Bool(bool),
    /// An actor or struct instance: its path in the resolution (`ego`, `g.vehicles[1]`).
    Instance(String),
}

/// An argument of an invocation or modifier, evaluated once when the scenario is resolved.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Arg {
    /// Where it is written.
    pub site: Site,
    /// The dotted path the expression names, when it is one (`ego`, `g.vehicles[0]`).
    pub path: Option<String>,
    /// Its value, or why it has none the planner can compute: reported where the planner reads
    /// it, so an argument nothing reads is no error.
    pub value: Result<Val, Error>,
}

impl Arg {
    /// Its value.
    pub(crate) fn eval(&self) -> Result<Val, Error> {
        self.value.clone()
    }

    /// Its value as a finite number in SI units.
    pub(crate) fn number(&self) -> Result<f64, Error> {
        match self.eval()? {
            Val::Num(x) if x.is_finite() => Ok(x),
            _ => Err(self
                .site
                .err(K::Value, "expected a number, found another value")),
        }
    }
}

/// Arguments by parameter name, in the order written.
pub(crate) type Args = Vec<(String, Arg)>;

/// The argument `name` of `args`.
pub(crate) fn arg<'a>(args: &'a Args, name: &str) -> Option<&'a Arg> {
    args.iter().find(|(n, _)| n == name).map(|(_, a)| a)
}

/// The run's draws of ranges, `one_of` members and other choices the standard leaves random, in
/// the order the pipeline makes them: a stream separate from the constraint solver's, keyed by
/// a constant so that the same seed does not give correlated draws.
#[derive(Debug, Clone)]
pub(crate) struct Draws(ChaCha8Rng);

impl Draws {
    /// The stream of `seed`.
    pub(crate) fn new(seed: u64) -> Self {
        Draws(ChaCha8Rng::seed_from_u64(seed ^ 0x6473_6c5f_706c_616e))
    }

    /// A uniform draw in [0, 1) from the top 53 bits (integer-only mapping, the same on every
    /// machine).
    pub(crate) fn uniform(&mut self) -> f64 {
        (self.0.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// A draw among `n` choices.
    pub(crate) fn choose(&mut self, n: usize) -> usize {
        ((self.uniform() * n as f64) as usize).min(n.saturating_sub(1))
    }
}
