//! Running OpenSCENARIO DSL 2.x scenarios (ASAM OpenSCENARIO DSL 2.1 §7.3.9 behavior, §8.8
//! movement actions, §8.9 movement modifiers) on the oscsim engine.
//!
//! A checked and resolved `.osc` program is **planned** — when each phase of the scenario's
//! `do` tree starts and ends, where each vehicle starts, and which speed and lane changes meet
//! its modifiers (`at: start`, `end`, `all`) within the vehicles' limits — and the plan is
//! **lowered** to the OpenSCENARIO 1.x model the engine already runs (`scenario::Scenario`), so
//! a DSL scenario gives the same outputs (CSV, event log, OSI) as an XML one. Everything that
//! cannot be planned is an error with `FILE:LINE:COL` before the run. `docs/dsl.md` has the
//! decision and the mapping table.
//!
//! | module | implements |
//! | --- | --- |
//! | `value` | constant values: units to SI, ranges drawn from the seed, resolved fields |
//! | `phase` | the `do` tree as phases with paths (§7.3.9) |
//! | `modifier` | movement modifiers read (§8.9) |
//! | `actors` | vehicles and vehicle groups of the plan, their 1.x Vehicle (§8.7.6, §8.7.18) |
//! | `road` | the road of the plan and the DSL's lane numbering |
//! | `route` | routes of `along(…)` on the plan's road (§8.9, §8.12) |
//! | `lateral` | `lateral(…)` as an offset in the lane or beside another actor (§8.9) |
//! | `place` | initial placement from `at: start`/`all` constraints |
//! | `track` | planned speed profile, lanes, offsets and sideways moves of an actor |
//! | `plan` | phase timing and motion planning |
//! | `condition` | `until`/`wait` conditions with §8.7 methods as 1.x conditions |
//! | `lower` | the plan as a 1.x Storyboard |
//! | `error` | errors with positions |
//!
//! This crate depends on `dsl` and `scenario` (never on `engine`); the cli joins it to the engine.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod actors;
mod condition;
mod error;
mod lateral;
mod lower;
mod modifier;
mod phase;
mod place;
mod plan;
mod road;
mod route;
mod track;
mod value;

use std::path::Path;

use dsl::semantics::hir::{Behavior, CompoundKind, Member};
use dsl::CheckedProgram;

pub use error::{Error, ErrorKind};
pub use plan::POSITION_TOLERANCE;

/// How to plan.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Seed of the solver's values, `one_of` choices and duration ranges.
    pub seed: u64,
    /// The engine's step (s): a duration that starts on a run-time condition is counted from
    /// the step the phase started in.
    pub dt: f64,
    /// Whether the run is bounded from outside (`--duration`), so a phase may have no end.
    pub open_end: bool,
}

/// A phase of the plan, for reports and tests.
#[derive(Debug, Clone, PartialEq)]
pub struct PhaseInfo {
    /// Its path, the Act's name in the event log.
    pub path: String,
    /// Its start time (s) when the plan knows it.
    pub start: Option<f64>,
    /// Its end time (s) when the plan knows it.
    pub end: Option<f64>,
}

/// A planned, lowered DSL scenario.
#[derive(Debug, Clone)]
pub struct Lowered {
    /// The scenario model the engine runs.
    pub scenario: scenario::Scenario,
    /// The phases, children before their composition.
    pub phases: Vec<PhaseInfo>,
}

/// Why a DSL scenario could not be made ready to run.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum LoadError {
    /// The file did not pass the language checks (or its constraints have no solution).
    #[error("{0}")]
    Check(dsl::Diagnostics),
    /// The road network could not be read.
    #[error("{0}")]
    Road(opendrive::Error),
    /// The scenario could not be planned.
    #[error("{0}")]
    Plan(Error),
}

/// Checks `osc`, resolves it with the seed, reads the road network and plans and lowers the
/// scenario. The road network is `road` when given, else the file the program names with the
/// standard library's `map.set_map_file(file)` (relative to the `.osc` file).
pub fn load(osc: &Path, road: Option<&Path>, options: &Options) -> Result<Lowered, LoadError> {
    let program = dsl::check(osc).map_err(LoadError::Check)?;
    let road = match road {
        Some(r) => r.to_path_buf(),
        None => map_file(&program, osc).ok_or_else(|| {
            LoadError::Plan(Error {
                kind: ErrorKind::Road,
                message: "expected a road network (--road FILE.xodr, or map.set_map_file(\"FILE.xodr\") in the scenario), found none".into(),
                at: format!("{}:1:1", osc.display()),
            })
        })?,
    };
    let net = opendrive::RoadNetwork::from_file(&road).map_err(LoadError::Road)?;
    lower_program(&program, osc, &road, &net, options)
}

/// The OpenDRIVE file the program names with `set_map_file(file)` on a `map` (ASAM
/// OpenSCENARIO DSL 2.1 domain model, map), at top level or in a scenario of the main file,
/// resolved against the `.osc` file's folder.
pub fn map_file(program: &CheckedProgram, osc: &Path) -> Option<std::path::PathBuf> {
    use dsl::semantics::hir::ExprKind;
    let model = &program.model;
    let main = dsl::semantics::hir::FileId(model.library_files);
    let members = model.top.iter().chain(
        model
            .compounds
            .iter()
            .filter(|c| c.span.file >= main)
            .flat_map(|c| c.members.iter()),
    );
    members
        .into_iter()
        .find_map(|m| match m {
            Member::Modifier(app) if app.name.text == "set_map_file" => {
                app.args
                    .iter()
                    .find_map(|a| match (&a.name, &a.value.kind) {
                        (None, ExprKind::Str(f)) => Some(f.clone()),
                        (Some(n), ExprKind::Str(f)) if n.text == "file" => Some(f.clone()),
                        _ => None,
                    })
            }
            _ => None,
        })
        .map(|f| osc.parent().unwrap_or(Path::new("")).join(f))
}

/// Plans and lowers the one scenario of `program`'s main file that has a `do`.
pub fn lower_program(
    program: &CheckedProgram,
    osc: &Path,
    road_path: &Path,
    road: &opendrive::RoadNetwork,
    options: &Options,
) -> Result<Lowered, LoadError> {
    let files = error::Files(program.files());
    let model = &program.model;
    let main = dsl::semantics::hir::FileId(model.library_files);
    let scenarios: Vec<_> = model
        .compounds
        .iter()
        .filter(|c| c.kind == CompoundKind::Scenario && c.span.file >= main)
        .filter_map(|c| {
            c.members.iter().find_map(|m| match m {
                Member::Do(d, _) => Some((c, d)),
                _ => None,
            })
        })
        .collect();
    let (decl, root) = match scenarios.as_slice() {
        [one] => *one,
        [] => {
            return Err(LoadError::Plan(Error {
                kind: ErrorKind::NoScenario,
                message: "expected a scenario with a `do` to run, found none".into(),
                at: format!("{}:1:1", osc.display()),
            }))
        }
        [_, second, ..] => {
            return Err(LoadError::Plan(files.err(
                ErrorKind::NoScenario,
                second.0.span,
                "expected one scenario with a `do` to run, found several",
            )))
        }
    };
    let resolution = program.resolve(options.seed).map_err(LoadError::Check)?;
    let ctx = value::Ctx::new(model, &resolution, decl.name.clone(), files, options.seed);
    let phases = phase::build(&ctx, root, "do".into()).map_err(LoadError::Plan)?;
    // The plan drives on the road its named routes are on, else on the first road.
    let mut apps = Vec::new();
    phases.walk(&mut |p| {
        if let phase::Kind::Invoke(inv) = &p.kind {
            apps.extend(inv.modifiers.iter().copied());
        }
    });
    let plan_road = match route::named_road(&ctx, &apps).map_err(LoadError::Plan)? {
        Some((id, span)) => road::PlanRoad::by_id(road, &id).ok_or_else(|| {
            LoadError::Plan(files.err(
                ErrorKind::Road,
                span,
                format!(
                    "expected road {id} with driving lanes in {}, found none",
                    road_path.display()
                ),
            ))
        })?,
        None => road::PlanRoad::pick(road).ok_or_else(|| {
            LoadError::Plan(files.err(
                ErrorKind::Road,
                decl.span,
                format!(
                    "expected a road with driving lanes in {}, found none",
                    road_path.display()
                ),
            ))
        })?,
    };
    let settings = plan::Settings {
        dt: options.dt,
        open_end: options.open_end,
    };
    // Events the scenario declares with a condition (`event e is c`), and the events `on`
    // handlers emit, each with the condition that makes it occur.
    let mut events = Vec::new();
    let mut handlers = 0;
    for m in &decl.members {
        match m {
            Member::Event(e) => {
                if let Some(spec) = &e.spec {
                    events.push((e.name.text.clone(), spec, None));
                }
            }
            // `m.set_map_file(f)` names the road network (see `map_file`); other modifiers of
            // the scenario itself are not run.
            Member::Modifier(app) if app.name.text != "set_map_file" => {
                return Err(LoadError::Plan(files.err(
                    ErrorKind::Modifier,
                    app.span,
                    format!(
                        "expected modifiers on the actions of the `do` (the runtime plans those), found `{}(…)` applied to the scenario",
                        app.name.text
                    ),
                )))
            }
            // `on e: emit f`: f occurs whenever e does; a `call` runs a method for its side
            // effects, which the runtime has none of (methods are expressions or external).
            Member::On(spec, body, on_span) => {
                let index = handlers;
                handlers += 1;
                for b in body {
                    match &b.behavior {
                        Behavior::Emit(name, _, span) => {
                            events.push((name.text.clone(), spec, Some((index, *span))))
                        }
                        Behavior::Call(_, span) => {
                            return Err(LoadError::Plan(files.err(
                                ErrorKind::Unsupported,
                                *span,
                                "expected `emit` in an `on` handler, found `call` (methods with side effects are not run)",
                            )))
                        }
                        _ => {
                            return Err(LoadError::Plan(files.err(
                                ErrorKind::Unsupported,
                                *on_span,
                                "expected `emit` or `call` in an `on` handler, found another member",
                            )))
                        }
                    }
                }
            }
            _ => {}
        }
    }
    let plan = plan::plan(&ctx, &plan_road, &phases, events, settings).map_err(LoadError::Plan)?;
    let info = plan
        .phases
        .iter()
        .map(|p| PhaseInfo {
            path: p.path.clone(),
            start: match p.start {
                plan::When::At(t) => Some(t),
                _ => None,
            },
            end: match p.end {
                plan::When::At(t) => Some(t),
                _ => None,
            },
        })
        .collect();
    Ok(Lowered {
        scenario: lower::lower(&plan, &decl.name, osc, road_path, files),
        phases: info,
    })
}
