//! OpenSCENARIO 1.3 §9.5 "Parameter value distributions": files that name a scenario and
//! vary its parameters, deterministically (cross product of value sets and ranges) or
//! stochastically (seeded draws), expanded into a [`DistributionPlan`].
//!
//! | module | job |
//! | --- | --- |
//! | `reader` | XML (roxmltree) → [`model`] types, every value's domain checked |
//! | `model` | the XSD's elements as Rust types |
//! | `deterministic` | cross product of `DistributionSet`, `DistributionRange`, `ValueSetDistribution` |
//! | `stochastic` | seeded ChaCha20 draws of Normal, LogNormal, Uniform, Poisson, Histogram, ProbabilityDistributionSet |
//! | `plan` | [`DistributionPlan`]: the front door |
//! | `error` | [`DistributionError`] with file:line:col |

mod deterministic;
mod error;
pub mod model;
mod plan;
mod reader;
mod stochastic;

pub use error::{DistributionError, DistributionErrorKind, MAX_RUNS};
pub use plan::{read, DistributionPlan};
pub use stochastic::{seed_for, MAX_ATTEMPTS, MAX_REJECTED_DRAWS};
