//! The `overlap:` argument of the `parallel` composition operator (ASAM OpenSCENARIO DSL 2.1
//! §7.3.9 composition operators): how the time intervals of the parallel's members relate. The
//! kinds are words of the operator (`parallel(overlap: equal)`), read here by name; the plan
//! aligns the members' starts and ends to them (`plan::overlap`).
//!
//! Each kind relates the members' intervals [sᵢ, eᵢ], member 0 being the first written:
//! `equal` all sᵢ equal and all eᵢ equal; `start` all sᵢ equal; `end` all eᵢ equal; `initial`
//! s₀ ≤ sᵢ (the first member starts first); `final` eᵢ ≤ e₀ (it ends last); `inside` both (every
//! other member lies inside the first); `full` sᵢ ≤ s₀ and e₀ ≤ eᵢ (the first lies inside every
//! other); `any` some moment at which every member runs.

use dsl::semantics::hir::{Expr, ExprKind};

use super::eval::Eval;
use crate::error::{Error, ErrorKind as K, Site};

/// How a parallel's members overlap in time.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Overlap {
    /// Every member starts and ends together.
    Equal,
    /// Every member starts together.
    Start,
    /// Every member ends together.
    End,
    /// No member starts before the first.
    Initial,
    /// No member ends after the first.
    Final,
    /// Every other member lies inside the first.
    Inside,
    /// The first member lies inside every other.
    Full,
    /// The members share a moment.
    Any,
}

/// The kinds by name, in the order the errors list them.
const KINDS: [(&str, Overlap); 8] = [
    ("equal", Overlap::Equal),
    ("start", Overlap::Start),
    ("end", Overlap::End),
    ("initial", Overlap::Initial),
    ("final", Overlap::Final),
    ("inside", Overlap::Inside),
    ("full", Overlap::Full),
    ("any", Overlap::Any),
];

impl Overlap {
    /// Its name, as written.
    pub(crate) fn name(self) -> &'static str {
        KINDS
            .iter()
            .find(|(_, k)| *k == self)
            .map_or("any", |(n, _)| n)
    }
}

/// A parallel's `overlap:` argument, read, with where it is written.
#[derive(Debug, Clone)]
pub(crate) struct OverlapArg {
    /// The kind.
    pub kind: Overlap,
    /// The argument's value.
    pub site: Site,
}

/// Reads the value `e` of an `overlap:` argument.
pub(crate) fn read(ev: &Eval<'_>, e: &Expr) -> Result<OverlapArg, Error> {
    let word = match &e.kind {
        ExprKind::Name(n) => Some(n.as_str()),
        _ => None,
    };
    match word.and_then(|w| KINDS.iter().find(|(n, _)| *n == w)) {
        Some((_, kind)) => Ok(OverlapArg {
            kind: *kind,
            site: ev.site(e.span),
        }),
        None => Err(ev.files.err(
            K::Argument,
            e.span,
            format!(
                "expected one of {} in overlap:, found {}",
                KINDS.map(|(n, _)| n).join(", "),
                word.map_or("another expression".to_string(), |w| format!("`{w}`"))
            ),
        )),
    }
}
