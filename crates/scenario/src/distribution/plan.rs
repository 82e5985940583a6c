//! The front door of OpenSCENARIO 1.3 §9.5: a parameter value distribution file → the list of
//! concrete parameter sets to run the scenario with.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::error::{DistributionError, DistributionErrorKind};
use super::model::{DistributionDefinition, ParameterValueDistribution};
use super::reader::read_distribution;
use super::{deterministic, stochastic};
use crate::SourcePos;

/// What a distribution file asks for: one scenario, run once per parameter set.
#[derive(Debug, Clone, PartialEq)]
pub struct DistributionPlan {
    /// `ScenarioFile@filepath`, resolved against the distribution file's directory when
    /// relative.
    pub scenario_file: PathBuf,
    /// The parameter sets, in order: parameter name (as in the scenario's
    /// `ParameterDeclaration@name`, without `$`) → value as text, to override the declared
    /// default. Parameters a set does not name keep their declared defaults.
    pub runs: Vec<BTreeMap<String, String>>,
}

impl DistributionPlan {
    /// Reads and expands the distribution file at `path`.
    pub fn load(path: &Path) -> Result<Self, DistributionError> {
        let text = std::fs::read_to_string(path).map_err(|e| {
            let kind = DistributionErrorKind::Io {
                message: e.to_string(),
            };
            DistributionError::new(kind, SourcePos::start_of(Arc::from(path)))
        })?;
        Self::from_text(&text, path)
    }

    /// Reads and expands distribution-file `text`; `path` names the file in errors and is the
    /// base for a relative `ScenarioFile`.
    pub fn from_text(text: &str, path: &Path) -> Result<Self, DistributionError> {
        let distribution = read_distribution(text, path)?;
        Self::from_distribution(&distribution, path)
    }

    /// Expands an already read distribution; `path` as in [`from_text`](Self::from_text).
    pub fn from_distribution(
        distribution: &ParameterValueDistribution,
        path: &Path,
    ) -> Result<Self, DistributionError> {
        let runs = match &distribution.definition {
            DistributionDefinition::Deterministic(list) => deterministic::expand(list),
            DistributionDefinition::Stochastic(s) => stochastic::sample(s),
        }
        .map_err(|(kind, pos)| DistributionError::new(kind, pos))?;
        let base = path.parent().unwrap_or_else(|| Path::new(""));
        Ok(Self {
            scenario_file: base.join(&distribution.scenario_file),
            runs,
        })
    }
}

/// Reads a distribution file without expanding it (for validation and tools).
pub fn read(text: &str, path: &Path) -> Result<ParameterValueDistribution, DistributionError> {
    read_distribution(text, path)
}
