//! Running OpenSCENARIO DSL 2.x scenarios (ASAM OpenSCENARIO DSL 2.1 §7.3.9 behavior, §8.8
//! movement actions, §8.9 movement modifiers) on the oscsim engine.
//!
//! A checked `.osc` program goes through three stages, each handing plain data to the next:
//!
//! 1. **resolve** (`resolve`): the program and the constraint solver's values (`--seed`) become
//!    the scenario's phase tree, every invocation's action, arguments and modifiers evaluated
//!    to SI values and instance paths, its event conditions, and the physical objects it names;
//! 2. **plan** (`plan`): when each phase starts and ends, where each vehicle starts, and which
//!    speed and lane changes meet the modifiers (`at: start`, `end`, `all`) within the
//!    vehicles' limits, on the road (`road`);
//! 3. **lower** (`lower`): the plan as the OpenSCENARIO 1.x model the engine already runs
//!    (`scenario::Scenario`), so a DSL scenario gives the same outputs (CSV, event log, OSI)
//!    as an XML one.
//!
//! Everything that cannot be run is an [`Error`] with `FILE:LINE:COL` before the run: its
//! [`kind`](Error::kind) keeps `dsl`'s and `opendrive`'s errors typed
//! ([`ErrorKind::Check`], [`ErrorKind::RoadNetwork`]) beside the planner's own kinds. `docs/dsl.md`
//! has the decision and the mapping table.
//!
//! | module | implements |
//! | --- | --- |
//! | `error` | the crate's one error (a check's, a road network's or the planner's, with positions); where each construct is written |
//! | `resolve` | stage 1: the program as plain data (§7.3.9, §7.3.10, §8.7, §8.9) |
//! | `road` | the roads of the plan (a start road and those after it) and the DSL's lane numbering |
//! | `track` | planned speed profile, lanes, offsets and sideways moves of an actor |
//! | `trigger` | the 1.x conditions triggers are built from |
//! | `plan` | stage 2: phase timing and motion planning |
//! | `lower` | stage 3: the plan as a 1.x Storyboard |
//! | `traffic_lights` | `map.set_traffic_lights_control_file`: the 1.x traffic signal controllers of a file, checked against the map |
//!
//! Each module uses only those above it in this table (and `plan`'s and `resolve`'s own tables
//! order their modules the same way): no module cycles. This crate depends on `dsl` and
//! `scenario` (never on `engine`); the cli joins it to the engine.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod error;
mod lower;
mod plan;
mod resolve;
mod road;
mod track;
mod traffic_lights;
mod trigger;

use std::path::Path;

use dsl::semantics::hir::Member;
use dsl::CheckedProgram;

pub use dsl::semantics::hir::CoverageKind;
pub use error::{Error, ErrorKind};
pub use plan::POSITION_TOLERANCE;
pub use resolve::coverage::{Buckets, CoverItem, CoverUnit, Direction, RunExpr, RunOp, SampleAt};

/// How to plan.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Seed of the solver's values, `one_of` choices and duration ranges.
    pub seed: u64,
    /// The engine's step (s): a duration that starts on a run-time condition is counted from
    /// the step the phase started in.
    pub dt: f64,
    /// Whether the run is bounded from outside (`--duration`), so a phase may have no end.
    pub open_end: bool,
    /// The scenario to run (`--scenario`); `None`: the one scenario no other invokes.
    pub scenario: Option<String>,
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

/// A `call` of an external method the scenario makes: the host must bind a function to the
/// method's name before the run (the Python package's `Simulation.bind`). The engine logs each
/// call as a `customCommand` of type `call` whose content is `METHOD(ARGS)`, the arguments a
/// comma-separated list of JSON values.
#[derive(Debug, Clone, PartialEq)]
pub struct ExternalCall {
    /// The method's name.
    pub method: String,
    /// Where the `call` (or the comparison reading the method) is written.
    pub pos: scenario::SourcePos,
    /// `Some(name)`: the method's result is read in a condition (`until m(…) > 3`), a 1.x
    /// UserDefinedValueCondition on the value `name` (the call's text, `m(args as JSON
    /// values)`), which the host sets to its function's result before each step; `None`: a
    /// `call` statement, run for its effect when the `customCommand` of type `call` with this
    /// method's content is logged.
    pub value: Option<String>,
}

/// A planned, lowered DSL scenario.
#[derive(Debug, Clone)]
pub struct Lowered {
    /// The scenario model the engine runs.
    pub scenario: scenario::Scenario,
    /// The phases, children before their composition.
    pub phases: Vec<PhaseInfo>,
    /// The scenario's calls of external methods, in the order they are written (a `do`'s
    /// before its `on` handlers').
    pub calls: Vec<ExternalCall>,
    /// The constraint solver's values for the seed the scenario was planned with.
    pub resolution: dsl::Resolution,
    /// The scenario's `cover(…)` and `record(…)` members, for the runtime to sample
    /// (§7.3.12; resolved beside the plan, not planned).
    pub coverage: Vec<CoverItem>,
}

/// Checks `osc`, resolves it with the seed, reads the road network and plans and lowers the
/// scenario. The road network is `road` when given, else the file the program names with the
/// standard library's `map.set_map_file(file)` (relative to the `.osc` file).
pub fn load(osc: &Path, road: Option<&Path>, options: &Options) -> Result<Lowered, Error> {
    let program = dsl::check(osc)?;
    let road = match road {
        Some(r) => r.to_path_buf(),
        None => map_file(&program, osc).ok_or_else(|| {
            Error::at_start_of(
                ErrorKind::Road,
                "expected a road network (--road FILE.xodr, or map.set_map_file(\"FILE.xodr\") in the scenario), found none",
                osc,
            )
        })?,
    };
    let net = opendrive::RoadNetwork::from_file(&road)?;
    lower_program(&program, osc, &road, &net, options)
}

/// The scenario that runs (ASAM OpenSCENARIO DSL 2.1 §7.3.9 leaves the entry point to the
/// tool): the one named `scenario` (`--scenario`), else the one scenario with a `do` in the
/// user's files that no invocation names; an error lists the candidates.
pub fn entry_scenario(
    program: &CheckedProgram,
    osc: &Path,
    scenario: Option<&str>,
) -> Result<dsl::semantics::types::CompoundId, Error> {
    resolve::entry(program, osc, scenario).map(|(id, _)| id)
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

/// The external methods condition `cond` reads, as [`ExternalCall`]s with their values.
fn read_externals(cond: &resolve::Cond) -> Vec<ExternalCall> {
    let mut found = Vec::new();
    cond.externals(&mut found);
    found
        .into_iter()
        .map(|(c, pos)| ExternalCall {
            method: c.method,
            pos,
            value: Some(c.content),
        })
        .collect()
}

/// Plans and lowers the entry scenario of `program` (see [`Options::scenario`]).
pub fn lower_program(
    program: &CheckedProgram,
    osc: &Path,
    road_path: &Path,
    road: &opendrive::RoadNetwork,
    options: &Options,
) -> Result<Lowered, Error> {
    let mut resolved = resolve::resolve(program, osc, options.seed, options.scenario.as_deref())?;
    // Route points given in world coordinates are placed on the network's roads.
    plan::locate_points(&mut resolved, road)?;
    // Paths through points of the network become the paths of their world points.
    plan::locate_paths(&mut resolved, road)?;
    // The plan drives from the road of its named routes (the first of them whose roads hold
    // all the others; a route through points over its own roads), else from the first road,
    // onto the roads after it (`road`).
    let named = plan::named_routes(&resolved.root);
    let mut chains = Vec::new();
    let mut wanted: Vec<String> = Vec::new();
    for (k, a) in named.iter().enumerate() {
        // `named_routes` gives only routes with points.
        let Some(points) = plan::route_points(&a.route) else {
            continue;
        };
        let (id, _, _) = &points[0];
        if points.len() == 1 {
            // The first route's road must exist; a later one off the plan is an error at it
            // (`plan::route::on_plan_road`).
            match road::PlanRoad::by_id(road, id) {
                Some(chain) => chains.push(chain),
                None if k == 0 => {
                    return Err(a.site.err(
                        ErrorKind::Road,
                        format!(
                            "expected road {id} with driving lanes in {}, found none",
                            road_path.display()
                        ),
                    ))
                }
                None => {}
            }
            wanted.push(id.clone());
        } else {
            let roads =
                road::route_roads(road, &points).map_err(|m| a.site.err(ErrorKind::Road, m))?;
            wanted.extend(roads.iter().map(|&i| road.roads()[i].id.clone()));
            chains.push(road::PlanRoad::through(road, &roads));
        }
    }
    // Routes the map makes in sequence (`routes_are_in_sequence`): the roads through both, in
    // order (the map's check says what is wrong when no path joins them).
    for m in &resolved.map {
        if let resolve::MapKind::NamedInSequence {
            preceding,
            succeeding,
        } = &m.kind
        {
            if let (Some(mut a), Some(b)) = (
                plan::route_points(preceding),
                plan::route_points(succeeding),
            ) {
                let same_lane = a.last().map(|p| p.1) == b.first().map(|p| p.1);
                a.extend(b);
                if let (true, Ok(roads)) = (same_lane, road::route_roads(road, &a)) {
                    wanted.extend(roads.iter().map(|&i| road.roads()[i].id.clone()));
                    chains.push(road::PlanRoad::through(road, &roads));
                }
            }
        }
    }
    // A route the map makes in sequence with a field: its roads, and before or after them the
    // field's road the map's modifier binds it to (the first way the network's order gives).
    for m in &resolved.map {
        let resolve::MapKind::RoutesInSequence {
            preceding,
            succeeding,
        } = &m.kind
        else {
            continue;
        };
        let Some(made) = preceding.made.as_ref().or(succeeding.made.as_ref()) else {
            continue;
        };
        let way = plan::junction_roads(road, std::slice::from_ref(m));
        let own = plan::route_points(made).and_then(|points| road::route_roads(road, &points).ok());
        if let (Some(way), Some(own)) = (way, own) {
            // The way runs from the made route's last road to the field's, or from the
            // field's road to the made route's first.
            let roads: Vec<usize> = if preceding.made.is_some() {
                own.into_iter().chain(way.into_iter().skip(1)).collect()
            } else {
                let n = way.len().saturating_sub(1);
                way.into_iter().take(n).chain(own).collect()
            };
            wanted.extend(roads.iter().map(|&i| road.roads()[i].id.clone()));
            chains.push(road::PlanRoad::through(road, &roads));
        }
    }
    let holds_all = |c: &road::PlanRoad<'_>| wanted.iter().all(|r| c.plan_s(r, 0.0).is_some());
    // Without named routes, a way through a junction the map's modifiers bind
    // (`roads_follow_in_junction`) gives the roads.
    if chains.is_empty() {
        if let Some(roads) = plan::junction_roads(road, &resolved.map) {
            chains.push(road::PlanRoad::through(road, &roads));
        }
    }
    let plan_road = match chains.iter().position(holds_all) {
        Some(i) => chains.swap_remove(i),
        None if !chains.is_empty() => chains.swap_remove(0),
        None => road::PlanRoad::pick(road).ok_or_else(|| {
            resolved.site.err(
                ErrorKind::Road,
                format!(
                    "expected a road with driving lanes in {}, found none",
                    road_path.display()
                ),
            )
        })?,
    };
    let settings = plan::Settings {
        dt: options.dt,
        open_end: options.open_end,
    };
    let plan = plan::plan(&resolved, &plan_road, settings)?;
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
    let mut calls = Vec::new();
    let mut reads = Vec::new();
    resolved.root.walk(&mut |p| {
        if let resolve::Kind::Call(c @ resolve::Call { external: true, .. }) = &p.kind {
            calls.push(ExternalCall {
                method: c.method.clone(),
                pos: p.site.pos.clone(),
                value: None,
            });
        }
        if let Some(Ok(cond)) = &p.until {
            reads.extend(read_externals(cond));
        }
    });
    for spec in &resolved.events {
        if let (Some(c @ resolve::Call { external: true, .. }), Some((_, site))) =
            (&spec.call, &spec.handler)
        {
            calls.push(ExternalCall {
                method: c.method.clone(),
                pos: site.pos.clone(),
                value: None,
            });
        }
        if let Ok(cond) = &spec.cond {
            reads.extend(read_externals(cond));
        }
    }
    // Each value read once (the first place it is read), after the calls.
    for r in reads {
        if !calls.iter().any(|c| c.value == r.value) {
            calls.push(r);
        }
    }
    let mut scenario = lower::lower(&plan, &resolved.name, osc, road_path);
    for m in &resolved.map {
        if let resolve::MapKind::TrafficLightControl(file) = &m.kind {
            let found = traffic_lights::controllers(file, road, &m.site)?;
            let signals = &mut scenario.road_network.traffic_signal_controllers;
            signals.extend(found);
        }
    }
    Ok(Lowered {
        scenario,
        phases: info,
        calls,
        resolution: resolved.resolution,
        coverage: resolved.coverage,
    })
}
