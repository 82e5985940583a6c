//! The typed content of an OpenSCENARIO 1.3 §9.5 parameter value distribution file, element
//! for element as the XSD (`ParameterValueDistribution` and below) names it.

use crate::SourcePos;

/// XSD `ParameterValueDistribution`: the scenario to run and how to vary its parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct ParameterValueDistribution {
    /// `ScenarioFile@filepath` as written.
    pub scenario_file: String,
    /// Position of the `ScenarioFile` element.
    pub scenario_file_pos: SourcePos,
    /// `Deterministic` or `Stochastic`.
    pub definition: DistributionDefinition,
}

/// XSD group `DistributionDefinition`.
#[derive(Debug, Clone, PartialEq)]
pub enum DistributionDefinition {
    /// XSD `Deterministic`: its distributions in document order.
    Deterministic(Vec<DeterministicParameterDistribution>),
    /// XSD `Stochastic`.
    Stochastic(Stochastic),
}

/// XSD group `DeterministicParameterDistribution`, with its element's position.
#[derive(Debug, Clone, PartialEq)]
pub struct DeterministicParameterDistribution {
    /// Single- or multi-parameter.
    pub kind: DeterministicKind,
    /// Position of the `Deterministic…Distribution` element.
    pub pos: SourcePos,
}

/// The two deterministic kinds.
#[derive(Debug, Clone, PartialEq)]
pub enum DeterministicKind {
    /// XSD `DeterministicSingleParameterDistribution`.
    Single {
        /// `parameterName`.
        parameter_name: String,
        /// Its values.
        values: DeterministicSingleParameterDistributionType,
    },
    /// XSD `DeterministicMultiParameterDistribution` / `ValueSetDistribution`: each
    /// `ParameterValueSet` is one alternative, a list of (`parameterRef`, `value`).
    ValueSetDistribution(Vec<Vec<(String, String)>>),
}

/// XSD group `DeterministicSingleParameterDistributionType` (without
/// `UserDefinedDistribution`, which the reader refuses).
#[derive(Debug, Clone, PartialEq)]
pub enum DeterministicSingleParameterDistributionType {
    /// XSD `DistributionSet`: the `Element@value`s.
    DistributionSet(Vec<String>),
    /// XSD `DistributionRange`.
    DistributionRange {
        /// `Range`.
        range: Range,
        /// `stepWidth` (> 0).
        step_width: f64,
    },
}

/// XSD `Range` (lowerLimit ≤ upperLimit, both finite).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// `lowerLimit`.
    pub lower_limit: f64,
    /// `upperLimit`.
    pub upper_limit: f64,
}

/// XSD `Stochastic`.
#[derive(Debug, Clone, PartialEq)]
pub struct Stochastic {
    /// `numberOfTestRuns`.
    pub number_of_test_runs: u32,
    /// `randomSeed` (an XSD double).
    pub random_seed: Option<f64>,
    /// The `StochasticDistribution`s in document order.
    pub distributions: Vec<StochasticDistribution>,
    /// Position of the `numberOfTestRuns` attribute.
    pub pos: SourcePos,
}

/// XSD `StochasticDistribution`, with its element's position.
#[derive(Debug, Clone, PartialEq)]
pub struct StochasticDistribution {
    /// `parameterName`.
    pub parameter_name: String,
    /// The distribution.
    pub kind: StochasticDistributionType,
    /// Position of the `StochasticDistribution` element.
    pub pos: SourcePos,
}

/// XSD group `StochasticDistributionType` (without `UserDefinedDistribution`).
#[derive(Debug, Clone, PartialEq)]
pub enum StochasticDistributionType {
    /// XSD `NormalDistribution`: mean and variance (≥ 0), optionally truncated to `range`.
    NormalDistribution {
        /// `expectedValue`.
        expected_value: f64,
        /// `variance`.
        variance: f64,
        /// `Range`.
        range: Option<Range>,
    },
    /// XSD `LogNormalDistribution`: mean (> 0) and variance (≥ 0) of the log-normal values
    /// themselves, optionally truncated to `range`.
    LogNormalDistribution {
        /// `expectedValue`.
        expected_value: f64,
        /// `variance`.
        variance: f64,
        /// `Range`.
        range: Option<Range>,
    },
    /// XSD `UniformDistribution`.
    UniformDistribution(Range),
    /// XSD `PoissonDistribution`: mean (> 0), optionally truncated to `range`.
    PoissonDistribution {
        /// `expectedValue`.
        expected_value: f64,
        /// `Range`.
        range: Option<Range>,
    },
    /// XSD `Histogram`: bins of (`Range`, `weight` ≥ 0), total weight > 0.
    Histogram(Vec<(Range, f64)>),
    /// XSD `ProbabilityDistributionSet`: (`value`, `weight` ≥ 0), total weight > 0.
    ProbabilityDistributionSet(Vec<(String, f64)>),
}
