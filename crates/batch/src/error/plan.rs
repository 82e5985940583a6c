//! The kinds of a plan's errors (plan.rs: a distribution file or a DSL scenario's seeds into
//! numbered variants).

use scenario::SourcePos;

/// Why a batch cannot start.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PlanErrorKind {
    /// The distribution file cannot be read.
    #[error("expected a readable distribution file, found {message} at {file}")]
    Io {
        /// The file.
        file: String,
        /// The I/O error.
        message: String,
    },
    /// The distribution file is not a valid ParameterValueDistribution (its own position).
    #[error(transparent)]
    Distribution(#[from] scenario::distribution::DistributionError),
    /// The ScenarioFile does not exist.
    #[error("expected an existing ScenarioFile, found none at {path} (ScenarioFile at {pos})")]
    MissingScenario {
        /// The ScenarioFile element: the distribution file and where in it.
        pos: SourcePos,
        /// The path tried.
        path: String,
    },
    /// The ScenarioFile does not load (its own position in its own file).
    #[error("the ScenarioFile does not load: {0}")]
    Scenario(scenario::Error),
    /// The scenario of a batch of seeds does not load (its own position in its own file).
    #[error("the scenario does not load: {0}")]
    Load(load::Error),
    /// Seeds for a scenario without constraints to re-solve (an XML one), or no seeds.
    #[error("{message} at {pos}")]
    Seeds {
        /// Lowercase "expected …, found …".
        message: String,
        /// The scenario file (1:1).
        pos: SourcePos,
    },
    /// The scenario's road network does not load (its own file and position).
    #[error("the ScenarioFile's road network does not load: {0}")]
    RoadNetwork(opendrive::Error),
}
