//! A scenario file opened once, in either language, and made into what the engine runs:
//! OpenSCENARIO XML 1.x (`.xosc`, with its catalogs and parameter overrides, OpenSCENARIO 1.3
//! §9.1) read by the `scenario` crate; OpenSCENARIO DSL 2.x (`.osc`, ASAM OpenSCENARIO DSL 2.1)
//! checked by `dsl`, resolved with a seed, planned and lowered to the same model by
//! `dsl_runtime`. The road network is read once and shared ([`Arc`]) by every load of the
//! source: a batch of seeds re-solves the constraints without reading a file again.
//!
//! The language is the file's extension: `.osc` (any case) is the DSL, anything else XML.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use opendrive::RoadNetwork;
use scenario::Scenario;
use source::SourcePos;

use crate::error::{Error, ErrorKind};
use crate::external::Bindings;

/// Which language a scenario is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Language {
    /// OpenSCENARIO XML 1.x (`.xosc`).
    Xml,
    /// OpenSCENARIO DSL 2.x (`.osc`).
    Dsl,
}

/// How to load a scenario.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// The OpenDRIVE road network of a DSL scenario (default: the file its
    /// `map.set_map_file(…)` names). An XML scenario names its own
    /// (`RoadNetwork/LogicFile`): giving one is an error.
    pub road: Option<PathBuf>,
    /// The seed of a DSL scenario's constraint solver, `one_of` choices and duration ranges
    /// (an XML scenario has none; the engine's random streams have their own seed).
    pub seed: u64,
    /// Global parameter overrides of an XML scenario (name, value as text). A DSL scenario
    /// varies by seed: giving one is an error.
    pub params: Vec<(String, String)>,
    /// The engine's step (s), which a DSL plan counts run-time phase ends in.
    pub dt: f64,
    /// Whether the run is bounded from outside (a duration), so a DSL phase may have no end.
    pub open_end: bool,
    /// The scenario of a DSL file to run (`--scenario NAME`); `None`: the one scenario with a
    /// `do` that no other invokes (`dsl_runtime::entry_scenario`). An XML file has one.
    pub scenario: Option<String>,
    /// The host's functions for a DSL scenario's external methods (`crate::external`):
    /// with `Some`, every method the scenario calls or reads must be bound, else the load
    /// fails at its place; `None`: the host binds after loading and checks itself.
    pub bindings: Option<Bindings>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            road: None,
            seed: engine::runtime::DEFAULT_SEED,
            params: Vec::new(),
            dt: engine::runtime::DEFAULT_DT,
            open_end: false,
            scenario: None,
            bindings: None,
        }
    }
}

/// A scenario ready to run: the model the engine runs and its road network.
#[derive(Debug, Clone)]
pub struct Loaded {
    /// The scenario model (for a DSL scenario, its plan lowered to the 1.x model).
    pub scenario: Scenario,
    /// The road network, read once for every load of the source.
    pub network: Arc<RoadNetwork>,
    /// The language of the file.
    pub language: Language,
    /// The phases of a DSL scenario's `do` tree, children before their composition, by
    /// path (the Acts of the lowered storyboard); empty for XML.
    pub phases: Vec<dsl_runtime::PhaseInfo>,
    /// A DSL scenario's resolved values for its seed: (column, value) for each of
    /// [`Source::columns`] (`columns.rs`: top-level parameters and constrained fields, numbers
    /// in SI units); empty for XML.
    pub resolved: Vec<(String, String)>,
    /// A DSL scenario's `cover(…)` and `record(…)` items, to sample with
    /// [`crate::Sampler`]; empty for XML.
    pub coverage: Vec<dsl_runtime::CoverItem>,
    /// A DSL scenario's calls of external methods with their places (`call m(…)`), which the
    /// host binds (the Python package's `Simulation.bind`) or refuses (the command line binds
    /// none); empty for XML. Each with a `value` is read in a condition.
    pub calls: Vec<dsl_runtime::ExternalCall>,
    /// The functions bound to them ([`Options::bindings`]; empty when none were given), which
    /// a [`crate::Host`] runs.
    pub bindings: Bindings,
}

impl Loaded {
    /// The host that runs its external methods with its bindings around the engine's steps:
    /// an error at the first method it calls or reads that none is bound to.
    pub fn host(&self) -> Result<crate::external::Host, Error> {
        crate::external::Host::new(&self.bindings, &self.calls)
    }
}

/// What was read of the file.
#[derive(Debug)]
enum Program {
    Xml(Box<Scenario>),
    Dsl {
        program: Box<dsl::CheckedProgram>,
        road: PathBuf,
        /// The scenario that runs and its resolved columns (`columns.rs`).
        columns: Option<(String, Vec<String>)>,
    },
}

/// A scenario file opened once: checked (DSL) or read with its catalogs and overrides (XML),
/// its road network read. [`Source::load`] makes a runnable scenario of it for a seed.
#[derive(Debug)]
pub struct Source {
    path: PathBuf,
    program: Program,
    network: Arc<RoadNetwork>,
    options: Options,
}

/// Whether `path` is an OpenSCENARIO DSL file (`.osc`, any case).
pub fn is_dsl(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("osc"))
}

impl Source {
    /// Opens `path` with `options` (module doc). The options' seed is the default of
    /// [`Source::load`]'s.
    pub fn open(path: &Path, options: &Options) -> Result<Source, Error> {
        let at_start = || SourcePos::start_of(path.into());
        let (program, network) = if is_dsl(path) {
            if let Some((name, _)) = options.params.first() {
                return Err(Error::option(
                    format!("expected no parameter overrides for an OpenSCENARIO DSL scenario (it varies by seed), found '{name}'"),
                    at_start(),
                ));
            }
            let program = dsl::check(path).map_err(ErrorKind::Check)?;
            let road = match &options.road {
                Some(r) => r.clone(),
                None => dsl_runtime::map_file(&program, path).ok_or_else(|| {
                    Error::option(
                        "expected a road network (--road FILE.xodr, or map.set_map_file(\"FILE.xodr\") in the scenario), found none".into(),
                        at_start(),
                    )
                })?,
            };
            let network = RoadNetwork::from_file(&road).map_err(ErrorKind::RoadNetwork)?;
            // The columns are a property of the program and its entry point; seed 0's
            // resolution (the one the check solved) tells which paths hold scalars. Without
            // an entry point the first load reports why.
            let columns = dsl_runtime::entry_scenario(&program, path, options.scenario.as_deref())
                .ok()
                .and_then(|entry| {
                    let res = program.resolve(0).ok()?;
                    Some(crate::columns::columns(&program, &res, entry))
                });
            let program = Program::Dsl {
                program: Box::new(program),
                road,
                columns,
            };
            (program, Arc::new(network))
        } else {
            if let Some(road) = &options.road {
                return Err(Error::option(
                    format!(
                        "expected no road network for an OpenSCENARIO XML scenario (it names its own in RoadNetwork/LogicFile), found {}",
                        road.display()
                    ),
                    at_start(),
                ));
            }
            let scenario = Scenario::load_with_parameters(path, &options.params)
                .map_err(ErrorKind::Scenario)?;
            let network = engine::load::road_network(&scenario).map_err(ErrorKind::RoadNetwork)?;
            (Program::Xml(Box::new(scenario)), network)
        };
        Ok(Source {
            path: path.to_path_buf(),
            program,
            network,
            options: options.clone(),
        })
    }

    /// The scenario file.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Its language.
    pub fn language(&self) -> Language {
        match self.program {
            Program::Xml(_) => Language::Xml,
            Program::Dsl { .. } => Language::Dsl,
        }
    }

    /// The options it was opened with.
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// The road network, read once.
    pub fn network(&self) -> &Arc<RoadNetwork> {
        &self.network
    }

    /// The XML scenario as read (with the overrides), for variants by parameters
    /// ([`Scenario::with_parameters`]); `None` for a DSL scenario.
    pub fn xml(&self) -> Option<&Scenario> {
        match &self.program {
            Program::Xml(s) => Some(s),
            Program::Dsl { .. } => None,
        }
    }

    /// The resolved values a DSL scenario's loads report ([`Loaded::resolved`], `columns.rs`),
    /// in column order; empty for XML.
    pub fn columns(&self) -> &[String] {
        match &self.program {
            Program::Dsl {
                columns: Some((_, c)),
                ..
            } => c,
            _ => &[],
        }
    }

    /// The checked DSL program; `None` for an XML scenario.
    pub fn dsl(&self) -> Option<&dsl::CheckedProgram> {
        match &self.program {
            Program::Dsl { program, .. } => Some(program),
            Program::Xml(_) => None,
        }
    }

    /// The scenario to run with `seed`: a DSL scenario resolved with it, planned and lowered
    /// (errors at their `FILE:LINE:COL`); the XML scenario as read (the seed is the engine's).
    pub fn load(&self, seed: u64) -> Result<Loaded, Error> {
        match &self.program {
            Program::Xml(scenario) => Ok(Loaded {
                scenario: scenario.as_ref().clone(),
                network: Arc::clone(&self.network),
                language: Language::Xml,
                phases: Vec::new(),
                resolved: Vec::new(),
                coverage: Vec::new(),
                calls: Vec::new(),
                bindings: Bindings::default(),
            }),
            Program::Dsl {
                program,
                road,
                columns,
            } => {
                let options = dsl_runtime::Options {
                    seed,
                    dt: self.options.dt,
                    open_end: self.options.open_end,
                    scenario: self.options.scenario.clone(),
                };
                let lowered =
                    dsl_runtime::lower_program(program, &self.path, road, &self.network, &options)
                        .map_err(|e| match e.kind() {
                            // The program checked; the constraints may have no solution for
                            // this seed.
                            dsl_runtime::ErrorKind::Check(d) => ErrorKind::Check(d.clone()),
                            dsl_runtime::ErrorKind::RoadNetwork(r) => {
                                ErrorKind::RoadNetwork(r.clone())
                            }
                            _ => ErrorKind::Plan(e),
                        })?;
                let resolved = columns.as_ref().map_or_else(Vec::new, |(root, names)| {
                    names
                        .iter()
                        .map(|n| {
                            let v = crate::columns::value_text(&lowered.resolution, root, n);
                            (n.clone(), v.unwrap_or_default())
                        })
                        .collect()
                });
                let bindings = self.options.bindings.clone();
                if let Some(b) = &bindings {
                    b.check(&lowered.calls)?;
                }
                Ok(Loaded {
                    bindings: bindings.unwrap_or_default(),
                    scenario: lowered.scenario,
                    network: Arc::clone(&self.network),
                    language: Language::Dsl,
                    phases: lowered.phases,
                    resolved,
                    coverage: lowered.coverage,
                    calls: lowered.calls,
                })
            }
        }
    }
}

/// Loads `path` (either language) with `options`: [`Source::open`], then [`Source::load`]
/// with the options' seed.
pub fn load(path: &Path, options: &Options) -> Result<Loaded, Error> {
    Source::open(path, options)?.load(options.seed)
}
