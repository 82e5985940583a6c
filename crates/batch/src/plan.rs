//! What a batch runs: the variants of a ParameterValueDistribution file (OpenSCENARIO 1.3 §9.5)
//! on its ScenarioFile, checked before any variant runs.
//!
//! The variants are the parameter sets of `scenario::distribution::DistributionPlan`, numbered
//! from 0 in its order: for a Deterministic distribution the cross product with the first
//! distribution of the file varying slowest and the last fastest (ValueSetDistribution: each
//! ParameterValueSet one alternative); for a Stochastic one, run 1's draws then run 2's, all
//! from one ChaCha20 stream seeded by `randomSeed`. The numbering is therefore a property of
//! the file alone: variant 17 is the same parameter set on every machine, in every shard.
//!
//! Checked here, each an error naming the distribution file's line:column: the ScenarioFile
//! exists and loads, and every parameter the distribution varies is a global parameter the
//! scenario declares. The distribution reader itself refuses empty sets, a stepWidth ≤ 0, an
//! inverted range, UserDefinedDistribution and the like, with their positions.
//!
//! A batch of seeds ([`Plan::seeds`]) varies an OpenSCENARIO DSL scenario instead: variant i
//! re-solves its constraints with the i-th seed (ASAM OpenSCENARIO DSL 2.1 §7.3.6), the file
//! and its road network read once (`load::Source`). Its columns are `seed` and the resolved
//! values `load` reports (the scenario's top-level parameters and constrained fields). An XML
//! scenario has no constraints to re-solve: an error.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use engine::load::RoadNetworks;
use opendrive::RoadNetwork;

use crate::error::{Error, PlanErrorKind};
use scenario::distribution::model::{
    DeterministicKind, DistributionDefinition, ParameterValueDistribution,
};
use scenario::distribution::DistributionPlan;
use scenario::Scenario;
use scenario::SourcePos;

/// A batch ready to run.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The distribution file.
    pub distribution: PathBuf,
    /// The scenario it names, loaded with its declared parameter values.
    pub scenario: Scenario,
    /// Its road network (with its declared parameter values), read once: every variant that
    /// names the same file shares it ([`Plan::network_for`]).
    pub network: Arc<RoadNetwork>,
    /// The road networks read so far, by file: a variant whose parameters name another road
    /// (`RoadNetwork/LogicFile` written with a parameter) gets its own, read once and shared
    /// with every variant naming that file.
    networks: Arc<Mutex<RoadNetworks>>,
    /// The varied parameters, in the order the distribution first names them.
    pub parameters: Vec<String>,
    /// Each variant's parameter values, by name; variant i is `variants[i]` (a batch of
    /// seeds: its `seed`; the resolved values are known when it runs).
    pub variants: Vec<BTreeMap<String, String>>,
    /// A batch of seeds: the DSL scenario they re-solve (`None`: a distribution).
    pub seeds: Option<Seeds>,
    /// The scenario's `cover(…)`/`record(…)` items (a DSL scenario's; none for XML): the
    /// results table's coverage columns and the buckets of the coverage report.
    pub coverage: Vec<load::CoverItem>,
    /// What the plan found but runs anyway: a varied parameter the scenario does not declare
    /// (its values change nothing: they stay in the results table and are given to no variant).
    pub warnings: Vec<scenario::Warning>,
}

/// An OpenSCENARIO DSL scenario varied by seed: variant i is the scenario resolved, planned
/// and lowered with `seeds[i]`.
#[derive(Debug, Clone)]
pub struct Seeds {
    /// The scenario file, checked, and its road network, read once.
    pub source: Arc<load::Source>,
    /// Each variant's seed.
    pub seeds: Vec<u64>,
}

/// At most this many seeds in one batch (a list of them is held in memory).
pub const MAX_SEEDS: u64 = 100_000_000;

/// The seeds of `--seeds`: `A..B` (inclusive, A ≤ B) or a count `N` (the seeds 1 … N).
pub fn parse_seeds(text: &str) -> Result<Vec<u64>, String> {
    let bad = || format!("expected A..B (0 ≤ A ≤ B) or a count N ≥ 1 of seeds, found '{text}'");
    let (first, last) = match text.split_once("..") {
        Some((a, b)) => (
            a.trim().parse::<u64>().map_err(|_| bad())?,
            b.trim().parse::<u64>().map_err(|_| bad())?,
        ),
        None => match text.trim().parse::<u64>() {
            Ok(n) if n >= 1 => (1, n),
            _ => return Err(bad()),
        },
    };
    if last < first {
        return Err(bad());
    }
    if last - first >= MAX_SEEDS {
        return Err(format!(
            "expected at most {MAX_SEEDS} seeds, found {} in '{text}'",
            u128::from(last - first) + 1
        ));
    }
    Ok((first..=last).collect())
}

impl Plan {
    /// Reads `path`, expands it and checks it against its ScenarioFile.
    pub fn load(path: &Path) -> Result<Plan, Error> {
        let text = std::fs::read_to_string(path).map_err(|e| PlanErrorKind::Io {
            file: path.display().to_string(),
            message: e.to_string(),
        })?;
        let distribution =
            scenario::distribution::read(&text, path).map_err(PlanErrorKind::from)?;
        let expanded = DistributionPlan::from_distribution(&distribution, path)
            .map_err(PlanErrorKind::from)?;
        if !expanded.scenario_file.is_file() {
            return Err(PlanErrorKind::MissingScenario {
                pos: distribution.scenario_file_pos.clone(),
                path: expanded.scenario_file.display().to_string(),
            }
            .into());
        }
        // Through the front door, with the ScenarioFile's own road network and parameters.
        let source = load::Source::open(&expanded.scenario_file, &load::Options::default())
            .map_err(|e| match e.into_kind() {
                load::ErrorKind::Scenario(s) => PlanErrorKind::Scenario(s),
                load::ErrorKind::RoadNetwork(r) => PlanErrorKind::RoadNetwork(r),
                other => PlanErrorKind::Load(other.into()),
            })?;
        let network = Arc::clone(source.network());
        let scenario = source.load(0).map_err(PlanErrorKind::Load)?.scenario;
        let mut networks = RoadNetworks::new();
        networks.keep(&scenario, Arc::clone(&network));
        let named = varied(&distribution);
        let warnings = undeclared(&scenario, &named);
        let mut parameters: Vec<String> = Vec::new();
        for (name, _) in named {
            if !parameters.contains(&name) {
                parameters.push(name);
            }
        }
        Ok(Plan {
            distribution: path.to_path_buf(),
            scenario,
            network,
            networks: Arc::new(Mutex::new(networks)),
            parameters,
            variants: expanded.runs,
            seeds: None,
            coverage: Vec::new(),
            warnings,
        })
    }

    /// A batch of `seeds` over the OpenSCENARIO DSL scenario `path`, loaded with `options`
    /// (its road network; the options' seed is not used): module doc. The plan's scenario is
    /// that of the first seed that plans; when none does, the first seed's error.
    pub fn seeds(path: &Path, options: &load::Options, seeds: Vec<u64>) -> Result<Plan, Error> {
        let source = load::Source::open(path, options).map_err(PlanErrorKind::Load)?;
        let at_start = || SourcePos::start_of(path.into());
        if source.language() == load::Language::Xml {
            return Err(PlanErrorKind::Seeds {
                message: "expected an OpenSCENARIO DSL scenario (.osc) whose constraints the seeds re-solve, found an XML scenario, which has none (vary it with a ParameterValueDistribution)".into(),
                pos: at_start(),
            }.into());
        }
        let Some(&first) = seeds.first() else {
            return Err(PlanErrorKind::Seeds {
                message: "expected at least one seed, found none".into(),
                pos: at_start(),
            }
            .into());
        };
        let loaded = first_planned(&source, first, &seeds[1..]).map_err(PlanErrorKind::Load)?;
        let mut parameters = vec!["seed".to_owned()];
        parameters.extend(source.columns().iter().cloned());
        Ok(Plan {
            distribution: path.to_path_buf(),
            scenario: loaded.scenario,
            coverage: loaded.coverage,
            network: Arc::clone(source.network()),
            // Unused: every seed runs on the DSL scenario's road network (run.rs).
            networks: Arc::new(Mutex::new(RoadNetworks::new())),
            parameters,
            variants: seeds
                .iter()
                .map(|s| BTreeMap::from([("seed".to_owned(), s.to_string())]))
                .collect(),
            warnings: Vec::new(),
            seeds: Some(Seeds {
                source: Arc::new(source),
                seeds,
            }),
        })
    }

    /// The road network of `variant` (a scenario derived from [`Plan::scenario`]): the one its
    /// own `RoadNetwork/LogicFile` names, read the first time a variant names that file and
    /// shared from then on.
    pub fn network_for(&self, variant: &Scenario) -> Result<Arc<RoadNetwork>, engine::Error> {
        // A poisoned lock only means another variant panicked while reading a road: the
        // networks already read are whole (inserted after a complete read).
        let mut networks = self
            .networks
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        networks.get(variant)
    }

    /// The values of variant `i` in the order of [`Plan::parameters`] (empty text for a
    /// parameter the variant does not set, which a ValueSetDistribution may leave out).
    pub fn values(&self, i: usize) -> Vec<String> {
        self.parameters
            .iter()
            .map(|p| self.variants[i].get(p).cloned().unwrap_or_default())
            .collect()
    }
}

/// The first of `first`, `rest` that plans; else `first`'s error.
fn first_planned(
    source: &load::Source,
    first: u64,
    rest: &[u64],
) -> Result<load::Loaded, load::Error> {
    let error = match source.load(first) {
        Ok(loaded) => return Ok(loaded),
        Err(e) => e,
    };
    rest.iter().find_map(|&s| source.load(s).ok()).ok_or(error)
}

/// Every parameter the distribution varies, with the position of the distribution naming it,
/// in document order.
/// A warning per varied parameter `scenario` does not declare globally. OpenSCENARIO XML 1.3
/// §9.3: a distribution gives a value "not taken out of the ParameterDeclaration but
/// computed at load time", so a name no ParameterDeclaration has replaces nothing. ASAM's own
/// 1.3 EndOfTrafficJamParameterSet varies `Road_SceneGraph`, which its 1.3 scenario no longer
/// declares (its 1.2 one did): refusing it would refuse one of the standard's examples, while
/// nothing is lost by running it (issue 34: accept what ASAM's examples do, with a warning).
/// A typo (`Speed` for `EgoSpeed`) is the same case, so the warning names the declared ones.
fn undeclared(scenario: &Scenario, named: &[(String, SourcePos)]) -> Vec<scenario::Warning> {
    let declared: Vec<&str> = scenario
        .parameter_declarations
        .iter()
        .map(|p| p.name.as_str())
        .collect();
    let mut warnings: Vec<scenario::Warning> = Vec::new();
    for (i, (name, pos)) in named.iter().enumerate() {
        let again = named[..i].iter().any(|(n, _)| n == name);
        if again || declared.contains(&name.as_str()) {
            continue;
        }
        warnings.push(scenario::Warning {
            message: format!(
                "the scenario declares no global parameter '{name}' ({}): its values vary nothing",
                if declared.is_empty() {
                    "it declares none".to_owned()
                } else {
                    declared.join(", ")
                }
            ),
            pos: pos.clone(),
        });
    }
    warnings
}

/// Whether `scenario` declares the global parameter `name` (a variant is given only those).
pub(crate) fn declares(scenario: &Scenario, name: &str) -> bool {
    scenario
        .parameter_declarations
        .iter()
        .any(|p| p.name == name)
}

fn varied(d: &ParameterValueDistribution) -> Vec<(String, SourcePos)> {
    match &d.definition {
        DistributionDefinition::Deterministic(list) => list
            .iter()
            .flat_map(|dist| {
                let names: Vec<String> = match &dist.kind {
                    DeterministicKind::Single { parameter_name, .. } => {
                        vec![parameter_name.clone()]
                    }
                    DeterministicKind::ValueSetDistribution(sets) => {
                        sets.iter().flatten().map(|(n, _)| n.clone()).collect()
                    }
                };
                names.into_iter().map(move |n| (n, dist.pos.clone()))
            })
            .collect(),
        DistributionDefinition::Stochastic(s) => s
            .distributions
            .iter()
            .map(|dist| (dist.parameter_name.clone(), dist.pos.clone()))
            .collect(),
    }
}
