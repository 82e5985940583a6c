//! Stochastic parameter value distributions, OpenSCENARIO 1.3 §9.5: `numberOfTestRuns` draws
//! of every `StochasticDistribution`, reproducible from `randomSeed`.
//!
//! Generator and seeding: ChaCha20 (`rand_chacha::ChaCha20Rng`, whose stream is fixed by its
//! specification) seeded with `seed_from_u64(s)` (rand_core 0.6's documented, portable PCG32
//! expansion), where `s` is `randomSeed` itself when that is an integer in [0, 2⁶⁴), else the
//! IEEE-754 bits of the double (`f64::to_bits`), and 0 when `randomSeed` is absent.
//!
//! Draw order: run 1 draws one value for each `StochasticDistribution` in document order, then
//! run 2, and so on, all from the one generator. Per distribution (rand 0.8 / rand_distr 0.4):
//! - `UniformDistribution`: lower + (upper − lower)·u with u = `rng.gen::<f64>()` ∈ [0, 1)
//!   (53 random bits), so the upper limit itself is never drawn;
//! - `NormalDistribution`: `rand_distr::Normal` (ziggurat) with σ = √variance;
//! - `LogNormalDistribution`: `expectedValue` m and `variance` v are those of the log-normal
//!   values themselves, so the underlying normal has σ² = ln(1 + v/m²), μ = ln m − σ²/2;
//! - `PoissonDistribution`: `rand_distr::Poisson` with λ = `expectedValue`, written as an
//!   integer;
//! - `Histogram`: a bin by `WeightedIndex` over the weights, then uniform in the bin's range;
//! - `ProbabilityDistributionSet`: a value by `WeightedIndex` over the weights.
//!
//! A `Range` on Normal, LogNormal or Poisson truncates the distribution: draws outside
//! [lower, upper] are discarded and drawn again, at most [`MAX_ATTEMPTS`] times per value and
//! [`MAX_REJECTED_DRAWS`] times over the whole plan (then an error, never a hang: a Range
//! that accepts one draw in a few hundred, on many parameters and runs, would otherwise take
//! billions of draws). The same seed gives the same values on every machine whose
//! `f64` `ln`/`exp` (used by the ziggurat tails and Poisson) agree, which holds for one target.

use std::collections::BTreeMap;

use rand::distributions::{Distribution, WeightedIndex};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha20Rng;
use rand_distr::{LogNormal, Normal, Poisson};

use super::error::DistributionErrorKind as Kind;
use super::error::MAX_RUNS;
use super::model::{Range, Stochastic, StochasticDistributionType as Sto};
use crate::SourcePos;

/// Most draws tried for one value of a truncated distribution.
pub const MAX_ATTEMPTS: u32 = 10_000;

/// Most draws discarded by truncation ranges over one plan (about a second of drawing).
pub const MAX_REJECTED_DRAWS: u64 = 10_000_000;

/// The generator seed for `randomSeed` (see the module doc).
pub fn seed_for(random_seed: Option<f64>) -> u64 {
    match random_seed {
        None => 0,
        // u64::MAX as f64 rounds up to 2^64 exactly; integral doubles below it convert exactly.
        Some(r) if r.fract() == 0.0 && (0.0..u64::MAX as f64).contains(&r) => r as u64,
        Some(r) => r.to_bits(),
    }
}

/// A distribution ready to sample (rand_distr objects built once).
enum Sampler<'a> {
    Uniform(Range),
    Normal(Normal<f64>, Option<Range>),
    LogNormal(LogNormal<f64>, Option<Range>),
    Poisson(Poisson<f64>, Option<Range>),
    Histogram(WeightedIndex<f64>, &'a [(Range, f64)]),
    Set(WeightedIndex<f64>, &'a [(String, f64)]),
}

/// Draws the runs. Errors carry the position of the distribution at fault.
pub(crate) fn sample(
    stochastic: &Stochastic,
) -> Result<Vec<BTreeMap<String, String>>, (Kind, SourcePos)> {
    let runs = stochastic.number_of_test_runs as usize;
    if runs > MAX_RUNS {
        return Err((
            Kind::TooManyRuns {
                limit: MAX_RUNS,
                found: runs as u128,
            },
            stochastic.pos.clone(),
        ));
    }
    let mut seen = std::collections::BTreeSet::new();
    for d in &stochastic.distributions {
        if !seen.insert(d.parameter_name.as_str()) {
            return Err((
                Kind::DuplicateParameter {
                    name: d.parameter_name.clone(),
                },
                d.pos.clone(),
            ));
        }
    }
    let samplers = stochastic
        .distributions
        .iter()
        .map(|d| sampler(&d.kind).map_err(|kind| (kind, d.pos.clone())))
        .collect::<Result<Vec<_>, _>>()?;
    let mut rng = ChaCha20Rng::seed_from_u64(seed_for(stochastic.random_seed));
    let mut rejected = 0u64;
    (0..runs)
        .map(|_| {
            stochastic
                .distributions
                .iter()
                .zip(&samplers)
                .map(|(d, s)| {
                    Ok((
                        d.parameter_name.clone(),
                        draw(s, &mut rng, &mut rejected).map_err(|kind| (kind, d.pos.clone()))?,
                    ))
                })
                .collect()
        })
        .collect()
}

fn sampler(kind: &Sto) -> Result<Sampler<'_>, Kind> {
    // The reader has checked every domain (variance ≥ 0, means > 0, weights ≥ 0 with a
    // positive sum), so the constructors below fail only on values beyond those checks
    // (e.g. a Poisson mean too large for rand_distr); report them as invalid.
    let invalid = |element: &str, attribute: &'static str, found: f64| Kind::InvalidAttribute {
        element: element.to_owned(),
        attribute,
        expected: "a value the distribution accepts",
        found: found.to_string(),
    };
    Ok(match kind {
        Sto::UniformDistribution(range) => Sampler::Uniform(*range),
        Sto::NormalDistribution {
            expected_value,
            variance,
            range,
        } => Sampler::Normal(
            Normal::new(*expected_value, variance.sqrt())
                .map_err(|_| invalid("NormalDistribution", "variance", *variance))?,
            *range,
        ),
        Sto::LogNormalDistribution {
            expected_value: m,
            variance: v,
            range,
        } => {
            let sigma2 = (v / (m * m)).ln_1p();
            let mu = m.ln() - sigma2 / 2.0;
            let d = LogNormal::new(mu, sigma2.sqrt())
                .map_err(|_| invalid("LogNormalDistribution", "variance", *v))?;
            Sampler::LogNormal(d, *range)
        }
        Sto::PoissonDistribution {
            expected_value,
            range,
        } => Sampler::Poisson(
            Poisson::new(*expected_value)
                .map_err(|_| invalid("PoissonDistribution", "expectedValue", *expected_value))?,
            *range,
        ),
        Sto::Histogram(bins) => Sampler::Histogram(
            WeightedIndex::new(bins.iter().map(|b| b.1))
                .map_err(|_| invalid("Histogram", "weight", 0.0))?,
            bins,
        ),
        Sto::ProbabilityDistributionSet(elements) => Sampler::Set(
            WeightedIndex::new(elements.iter().map(|e| e.1))
                .map_err(|_| invalid("ProbabilityDistributionSet", "weight", 0.0))?,
            elements,
        ),
    })
}

/// One value; `rejected` counts the plan's draws discarded by truncation so far.
fn draw(sampler: &Sampler<'_>, rng: &mut ChaCha20Rng, rejected: &mut u64) -> Result<String, Kind> {
    Ok(match sampler {
        Sampler::Uniform(range) => uniform(range, rng).to_string(),
        Sampler::Normal(d, range) => truncated(|r| d.sample(r), *range, rng, rejected)?.to_string(),
        Sampler::LogNormal(d, range) => {
            truncated(|r| d.sample(r), *range, rng, rejected)?.to_string()
        }
        // Poisson samples are integral doubles; `{}` writes them without a fraction.
        Sampler::Poisson(d, range) => {
            truncated(|r| d.sample(r), *range, rng, rejected)?.to_string()
        }
        Sampler::Histogram(index, bins) => uniform(&bins[index.sample(rng)].0, rng).to_string(),
        Sampler::Set(index, elements) => elements[index.sample(rng)].0.clone(),
    })
}

fn uniform(range: &Range, rng: &mut ChaCha20Rng) -> f64 {
    let u: f64 = rng.gen();
    range.lower_limit + (range.upper_limit - range.lower_limit) * u
}

/// Draws until the value lies in `range` (if any), at most [`MAX_ATTEMPTS`] times, and while
/// the plan's discarded draws (`rejected`) stay within [`MAX_REJECTED_DRAWS`].
fn truncated(
    mut draw: impl FnMut(&mut ChaCha20Rng) -> f64,
    range: Option<Range>,
    rng: &mut ChaCha20Rng,
    rejected: &mut u64,
) -> Result<f64, Kind> {
    let Some(range) = range else {
        return Ok(draw(rng));
    };
    for _ in 0..MAX_ATTEMPTS {
        let x = draw(rng);
        if (range.lower_limit..=range.upper_limit).contains(&x) {
            return Ok(x);
        }
        *rejected += 1;
        if *rejected > MAX_REJECTED_DRAWS {
            return Err(Kind::RangeRarelyReached {
                limit: MAX_REJECTED_DRAWS,
            });
        }
    }
    Err(Kind::RangeUnreachable {
        attempts: MAX_ATTEMPTS,
    })
}
