//! Deterministic parameter value distributions, OpenSCENARIO 1.3 §9.5: every combination of
//! the values of the distributions (the cross product, esmini #390), in document order.
//!
//! - `DistributionSet`: its `Element@value`s as written.
//! - `DistributionRange`: lowerLimit, lowerLimit + stepWidth, … while ≤ upperLimit. With
//!   q = (upper − lower)/step, the number of steps is q rounded to the nearest integer k when
//!   |q − k| ≤ 10⁻⁹·max(k, 1), else ⌊q⌋; so an upper limit the steps reach up to rounding
//!   (1.1 → 1.5 by 0.2, where q = 1.9999999999999996) is included. Each
//!   value lower + i·step is rounded to 12 significant digits, which removes the binary noise
//!   of decimal steps (1.1 + 0.2 = 1.3000000000000003 becomes 1.3) and changes a value by at
//!   most 5·10⁻¹³ of itself; values are written in Rust's shortest round-trip form.
//! - `ValueSetDistribution`: each `ParameterValueSet` is one alternative assigning its
//!   parameters together.
//!
//! Order: the first distribution in the document varies slowest, the last fastest, like nested
//! loops written in document order. With no distribution at all the plan has one empty run.

use std::collections::BTreeMap;

use super::error::DistributionErrorKind as Kind;
use super::error::MAX_RUNS;
use super::model::{
    DeterministicKind, DeterministicParameterDistribution,
    DeterministicSingleParameterDistributionType as Single,
};
use crate::SourcePos;

/// One distribution's alternatives: each a list of (parameter, value).
type Alternatives = Vec<Vec<(String, String)>>;

/// Expands the distributions into their cross product. Errors carry the position of the
/// distribution at fault.
pub(crate) fn expand(
    distributions: &[DeterministicParameterDistribution],
) -> Result<Vec<BTreeMap<String, String>>, (Kind, SourcePos)> {
    let mut seen = std::collections::BTreeSet::new();
    let mut runs = vec![BTreeMap::new()];
    for distribution in distributions {
        let alternatives =
            alternatives(&distribution.kind).map_err(|kind| (kind, distribution.pos.clone()))?;
        let names: std::collections::BTreeSet<&str> = alternatives
            .iter()
            .flatten()
            .map(|(name, _)| name.as_str())
            .collect();
        if let Some(name) = names.iter().find(|n| seen.contains(**n)) {
            return Err((
                Kind::DuplicateParameter {
                    name: (*name).to_owned(),
                },
                distribution.pos.clone(),
            ));
        }
        seen.extend(names.into_iter().map(str::to_owned));
        let count = runs.len() as u128 * alternatives.len() as u128;
        if count > MAX_RUNS as u128 {
            return Err((
                Kind::TooManyRuns {
                    limit: MAX_RUNS,
                    found: count,
                },
                distribution.pos.clone(),
            ));
        }
        runs = runs
            .iter()
            .flat_map(|run| {
                alternatives.iter().map(move |alternative| {
                    let mut next = run.clone();
                    next.extend(alternative.iter().cloned());
                    next
                })
            })
            .collect();
    }
    Ok(runs)
}

fn alternatives(kind: &DeterministicKind) -> Result<Alternatives, Kind> {
    Ok(match kind {
        DeterministicKind::ValueSetDistribution(sets) => sets.clone(),
        DeterministicKind::Single {
            parameter_name,
            values,
        } => {
            let values = match values {
                Single::DistributionSet(values) => values.clone(),
                Single::DistributionRange { range, step_width } => {
                    range_values(range.lower_limit, range.upper_limit, *step_width)?
                }
            };
            values
                .into_iter()
                .map(|v| vec![(parameter_name.clone(), v)])
                .collect()
        }
    })
}

/// The values of a `DistributionRange` (see the module doc), written as text.
fn range_values(lower: f64, upper: f64, step: f64) -> Result<Vec<String>, Kind> {
    let q = (upper - lower) / step;
    let nearest = q.round();
    let steps = if (q - nearest).abs() <= 1e-9 * nearest.max(1.0) {
        nearest
    } else {
        q.floor()
    };
    // `steps` is ≥ 0 (upper ≥ lower, step > 0, checked by the reader) and never NaN; it is
    // +∞ when the step is tiny enough for q to overflow.
    if steps >= MAX_RUNS as f64 {
        // `as` saturates at u128::MAX for a finite q beyond it (1e83 steps), so the + 1 must
        // too (fuzz finding distribution_range_count_overflows_u128).
        let found = if steps.is_finite() {
            (steps as u128).saturating_add(1)
        } else {
            u128::MAX
        };
        return Err(Kind::TooManyRuns {
            limit: MAX_RUNS,
            found,
        });
    }
    let count = steps as usize + 1;
    Ok((0..count)
        .map(|i| round_to_12_digits(lower + i as f64 * step).to_string())
        .collect())
}

/// `x` rounded to 12 significant decimal digits.
fn round_to_12_digits(x: f64) -> f64 {
    // Formatting with 11 digits after the point of the exponent form keeps 12 significant
    // digits; the text always parses back (finite input, Rust's own float syntax).
    format!("{x:.11e}").parse().unwrap_or(x)
}
