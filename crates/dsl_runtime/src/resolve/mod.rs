//! Stage 1 of the pipeline, **resolve**: a checked program and the solver's values become plain
//! data the planner reads without going back to the program (ASAM OpenSCENARIO DSL 2.1 §7.3.9
//! behavior specification, §7.3.10 events, §8.7 actors, §8.9 modifiers): the scenario to run,
//! its phase tree with every invocation's action, arguments and modifiers evaluated to SI values
//! and instance paths, its event conditions, and the physical objects the tree names.
//!
//! | module | reads |
//! | --- | --- |
//! | `value` | evaluated values and arguments; the run's draws |
//! | `eval` | expressions of the program, with the solver's values (private to this stage) |
//! | `objects` | vehicles and vehicle groups with their fields (§8.7.6, §8.7.18) |
//! | `route` | `along(…)` routes (§8.9, §8.12) |
//! | `modifier` | movement modifiers (§8.9) |
//! | `cond` | conditions and event specifications (§7.3.10, §8.7 methods) |
//! | `tree` | the `do` tree as phases with paths (§7.3.9) |

mod cond;
mod eval;
mod modifier;
mod objects;
mod route;
mod tree;
mod value;

use std::collections::BTreeMap;
use std::path::Path;

use dsl::semantics::hir::{Behavior, CompoundKind, Member};
use dsl::CheckedProgram;

pub(crate) use cond::{Cond, Timed};
pub(crate) use modifier::{At, ModKind, Modifier};
pub(crate) use objects::{Object, VehicleData};
pub(crate) use route::{Along, Route};
pub(crate) use tree::{Invoke, Kind, Phase};
pub(crate) use value::{Arg, Draws, Val};

use crate::error::{Error, ErrorKind, Files, Site};

/// A scenario ready to plan.
#[derive(Debug, Clone)]
pub(crate) struct Resolved {
    /// The scenario's name.
    pub name: String,
    /// Its declaration.
    pub site: Site,
    /// Its `do` tree.
    pub root: Phase,
    /// What each actor path the tree names is (`None`: no vehicle or vehicle group).
    pub objects: BTreeMap<String, Option<Object>>,
    /// The scenario's event conditions: its `event e is c` declarations and the events its
    /// `on` handlers emit.
    pub events: Vec<EventSpec>,
    /// The draws left for the planner (choices the standard leaves random).
    pub draws: Draws,
}

/// An event's condition.
#[derive(Debug, Clone)]
pub(crate) struct EventSpec {
    /// The event's name.
    pub name: String,
    /// Its condition (or why it cannot be run, reported when the event is used).
    pub cond: Result<Cond, Error>,
    /// Where the condition is written.
    pub site: Site,
    /// For an `on` handler's `emit`: the handler's index among the scenario's `on` directives
    /// and the `emit`.
    pub handler: Option<(usize, Site)>,
}

/// Why a program has no scenario to run, or cannot be resolved.
#[derive(Debug)]
pub(crate) enum Failure {
    /// The solver found no values (or the check failed).
    Check(dsl::Diagnostics),
    /// The scenario cannot be run.
    Plan(Error),
}

/// Resolves the one scenario of `program`'s main file that has a `do`, with `seed`.
pub(crate) fn resolve(
    program: &CheckedProgram,
    osc: &Path,
    seed: u64,
) -> Result<Resolved, Failure> {
    let files = Files(program.files());
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
            return Err(Failure::Plan(Error {
                kind: ErrorKind::NoScenario,
                message: "expected a scenario with a `do` to run, found none".into(),
                at: format!("{}:1:1", osc.display()),
            }))
        }
        [_, second, ..] => {
            return Err(Failure::Plan(files.err(
                ErrorKind::NoScenario,
                second.0.span,
                "expected one scenario with a `do` to run, found several",
            )))
        }
    };
    let resolution = program.resolve(seed).map_err(Failure::Check)?;
    let ev = eval::Eval::new(
        model,
        &resolution,
        decl.name.clone(),
        files,
        Draws::new(seed),
    );
    let root = tree::build(&ev, root, "do".into()).map_err(Failure::Plan)?;
    let events = events(&ev, &decl.members).map_err(Failure::Plan)?;
    let objects = objects(&ev, &root);
    Ok(Resolved {
        name: decl.name.clone(),
        site: ev.site(decl.span),
        root,
        objects,
        events,
        draws: ev.into_draws(),
    })
}

/// Events the scenario declares with a condition (`event e is c`), and the events `on`
/// handlers emit, each with the condition that makes it occur.
fn events(ev: &eval::Eval<'_>, members: &[Member]) -> Result<Vec<EventSpec>, Error> {
    let mut events = Vec::new();
    let mut handlers = 0;
    for m in members {
        match m {
            Member::Event(e) => {
                if let Some(spec) = &e.spec {
                    events.push(EventSpec {
                        name: e.name.text.clone(),
                        cond: cond::read(ev, spec),
                        site: ev.site(spec.span),
                        handler: None,
                    });
                }
            }
            // `m.set_map_file(f)` names the road network (see `crate::map_file`); other
            // modifiers of the scenario itself are not run.
            Member::Modifier(app) if app.name.text != "set_map_file" => {
                return Err(ev.files.err(
                    ErrorKind::Modifier,
                    app.span,
                    format!(
                        "expected modifiers on the actions of the `do` (the runtime plans those), found `{}(…)` applied to the scenario",
                        app.name.text
                    ),
                ))
            }
            // `on e: emit f`: f occurs whenever e does; a `call` runs a method for its side
            // effects, which the runtime has none of (methods are expressions or external).
            Member::On(spec, body, on_span) => {
                let index = handlers;
                handlers += 1;
                for b in body {
                    match &b.behavior {
                        Behavior::Emit(name, _, span) => events.push(EventSpec {
                            name: name.text.clone(),
                            cond: cond::read(ev, spec),
                            site: ev.site(spec.span),
                            handler: Some((index, ev.site(*span))),
                        }),
                        Behavior::Call(_, span) => {
                            return Err(ev.files.err(
                                ErrorKind::Unsupported,
                                *span,
                                "expected `emit` in an `on` handler, found `call` (methods with side effects are not run)",
                            ))
                        }
                        _ => {
                            return Err(ev.files.err(
                                ErrorKind::Unsupported,
                                *on_span,
                                "expected `emit` or `call` in an `on` handler, found another member",
                            ))
                        }
                    }
                }
            }
            _ => {}
        }
    }
    Ok(events)
}

/// Parameters of movement modifiers that name another object.
pub(crate) const REFERENCES: [&str; 8] = [
    "ahead_of",
    "behind",
    "same_as",
    "side_of",
    "left_of",
    "right_of",
    "faster_than",
    "slower_than",
];

/// What each actor path the tree invokes or its modifiers refer to is.
fn objects(ev: &eval::Eval<'_>, root: &Phase) -> BTreeMap<String, Option<Object>> {
    let mut paths = Vec::new();
    root.walk(&mut |p| {
        if let Kind::Invoke(inv) = &p.kind {
            paths.push(inv.actor.clone());
            for m in &inv.modifiers {
                paths.extend(
                    REFERENCES
                        .iter()
                        .filter_map(|k| m.arg(k).and_then(|a| a.path.clone())),
                );
            }
        }
    });
    paths
        .into_iter()
        .map(|p| {
            let o = objects::classify(ev, &p);
            (p, o)
        })
        .collect()
}
