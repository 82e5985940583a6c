//! Stage 1 of the pipeline, **resolve**: a checked program and the solver's values become plain
//! data the planner reads without going back to the program (ASAM OpenSCENARIO DSL 2.1 §7.3.9
//! behavior specification, §7.3.10 events, §8.7 actors, §8.9 modifiers): the scenario to run,
//! its phase tree with every invocation's action, arguments and modifiers evaluated to SI values
//! and instance paths, its event conditions, and the physical objects the tree names.
//!
//! | module | reads |
//! | --- | --- |
//! | `action` | the standard library's movement actions by name (§8.8) |
//! | `value` | evaluated values and arguments; the run's draws |
//! | `eval` | expressions of the program, with the solver's values (private to this stage) |
//! | `objects` | physical objects (vehicles, persons, animals, located stationary objects) and vehicle groups with their fields (§8.7, §8.7.18) |
//! | `route` | `along(…)` routes (§8.9, §8.12) |
//! | `along_path` | a path as `along(…)`'s route: followed as `follow_path` follows one (§8.9, §8.12, §8.8.2.16) |
//! | `shape` | a modifier's `shape:`, a common shape read as its action's arguments (§8.9.1.2) |
//! | `modifier` | movement modifiers (§8.9) |
//! | `map_modifiers` | the map's modifiers in the scenario's body, as bindings and checks for the planner (§8.12.2.2) |
//! | `position` | places and orientations of the position actions (§8.8.2.4, §8.8.2.5, §8.8.2.11) |
//! | `call` | `call` of external methods as commands to the host (§7.3.9) |
//! | `cond` | conditions and event specifications (§7.3.10, §8.7 methods) |
//! | `overlap` | a parallel's `overlap:` argument (§7.3.9 composition operators) |
//! | `tree` | the `do` tree as phases with paths (§7.3.9) |
//! | `coverage` | `cover(…)`/`record(…)` for the runtime to sample (§7.3.12); not planned |

mod action;
mod along_path;
mod call;
mod cond;
pub(crate) mod coverage;
mod eval;
mod map_modifiers;
mod modifier;
mod objects;
mod overlap;
mod position;
mod route;
mod shape;
mod tree;
mod value;

use std::cell::RefCell;
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use dsl::semantics::hir::{Behavior, CompoundKind, Member};
use dsl::semantics::types::CompoundId;
use dsl::CheckedProgram;

pub(crate) use action::Action;
pub(crate) use call::Call;
pub(crate) use cond::{Cond, Timed};
pub(crate) use map_modifiers::{EndKind, JunctionRoads, MapKind, MapModifier, SeqEnd};
pub(crate) use modifier::{At, ModKind, Modifier};
pub(crate) use objects::{ActorData, ActorKind, Object};
pub(crate) use overlap::{Overlap, OverlapArg};
pub(crate) use position::{Place, PlaceArg, RelativePoints};
pub(crate) use route::{one_way, Along, LaneField, MapRoad, MapRoute, Route, Waypoint};
pub(crate) use shape::ShapeKind;
pub(crate) use tree::{Invoke, Kind, Phase};
pub(crate) use value::{arg, Arg, Draws, Val};

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
    /// What each actor path the tree names, and each located stationary object, is (`None`: no
    /// physical object or vehicle group).
    pub objects: BTreeMap<String, Option<Object>>,
    /// The scenario's event conditions: its `event e is c` declarations and the events its
    /// `on` handlers emit.
    pub events: Vec<EventSpec>,
    /// The map's modifiers in the scenario's body (§8.12.2.2), in the order written.
    pub map: Vec<MapModifier>,
    /// The draws left for the planner (choices the standard leaves random).
    pub draws: Draws,
    /// The scenario's coverage items (read past the planner, which does not use them).
    pub coverage: Vec<coverage::CoverItem>,
    /// The solver's values for the seed.
    pub resolution: dsl::Resolution,
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
    /// For an `on` handler's `emit` or `call`: the handler's index among the scenario's `on`
    /// directives and the directive.
    pub handler: Option<(usize, Site)>,
    /// For an `on` handler's `call`: the call (the spec is then no event of the scenario).
    pub call: Option<Call>,
    /// For an `on` handler of an invoked behavior: the invocation's phase path (`do.round_two`);
    /// the handler is active from that phase's start to its end (§7.3.10). `None`: the entry
    /// scenario's, active for the whole run.
    pub within: Option<String>,
}

/// Resolves the scenario to run (the entry point: `scenario` when named, else the one
/// scenario with a `do` of the user's files that no other invokes), with `seed`. The solver
/// finding no values is [`ErrorKind::Check`](crate::ErrorKind::Check).
pub(crate) fn resolve(
    program: &CheckedProgram,
    osc: &Path,
    seed: u64,
    scenario: Option<&str>,
) -> Result<Resolved, Error> {
    let files = Files(program.files());
    let model = &program.model;
    let (id, root) = entry(program, osc, scenario)?;
    let decl = model.compound(id);
    let resolution = program.resolve(seed)?;
    let draws = RefCell::new(Draws::new(seed));
    let ev = eval::Eval::new(model, &resolution, decl.name.clone(), files, &draws);
    let mut entered = Vec::new();
    let root = tree::build_root(&ev, root, &mut entered)?;
    let mut events = events(&ev, &decl.members, None)?;
    for e in entered {
        let inner = ev.enter(e.frame.clone());
        let members = &model.compound(e.behavior).members;
        events.extend(self::events(&inner, members, Some(&e.path))?);
    }
    let located = objects::locations(&ev, &decl.members)?;
    let map = decl
        .members
        .iter()
        .filter_map(|m| match m {
            Member::Modifier(app) => map_modifiers::read(&ev, app),
            _ => None,
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut objects = objects(&ev, &root, &located);
    // The scenario's stationary objects that no location(…) puts anywhere: an error where the
    // plan uses one.
    for m in &decl.members {
        if let Member::Field(f) = m {
            for n in &f.names {
                if let Some(o @ Object::Unlocated) = objects::classify(&ev, &n.text, &located) {
                    objects.entry(n.text.clone()).or_insert(Some(o));
                }
            }
        }
    }
    // The entities the runtime measures: the tree's actors (vehicles, persons, animals, located
    // stationary objects) and vehicle groups' members.
    let entities: Vec<String> = objects
        .iter()
        .flat_map(|(path, o)| match o {
            Some(Object::Actor(_)) => vec![path.clone()],
            Some(Object::Group(members, _) | Object::RandomTraffic(members)) => {
                members.iter().map(|(p, _)| p.clone()).collect()
            }
            _ => Vec::new(),
        })
        .collect();
    let coverage = coverage::items(&ev, &decl.members, &entities)?;
    let site = ev.site(decl.span);
    Ok(Resolved {
        name: decl.name.clone(),
        site,
        root,
        objects,
        events,
        map,
        draws: draws.into_inner(),
        coverage,
        resolution,
    })
}

/// The entry point (ASAM OpenSCENARIO DSL 2.1 §7.3.9 leaves it to the tool): the scenario
/// named `scenario`, else the one scenario with a `do` in the user's files that no
/// invocation names; its declaration and `do`.
pub(crate) fn entry<'p>(
    program: &'p CheckedProgram,
    osc: &Path,
    scenario: Option<&str>,
) -> Result<(CompoundId, &'p dsl::semantics::hir::Labeled), Error> {
    let files = Files(program.files());
    let model = &program.model;
    let main = dsl::semantics::hir::FileId(model.library_files);
    let with_do: Vec<(CompoundId, &dsl::semantics::hir::Labeled)> = (0..model.compounds.len())
        .map(|i| CompoundId(i as u32))
        .filter(|c| {
            let d = model.compound(*c);
            d.kind == CompoundKind::Scenario && d.span.file >= main
        })
        .filter_map(|c| {
            model.compound(c).members.iter().find_map(|m| match m {
                Member::Do(d, _) => Some((c, d)),
                _ => None,
            })
        })
        .collect();
    let listed = |list: &[(CompoundId, &dsl::semantics::hir::Labeled)]| {
        list.iter()
            .map(|(c, _)| {
                let d = model.compound(*c);
                format!("`{}` at {}", d.name, files.site(d.span).at())
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    if let Some(name) = scenario {
        return with_do
            .iter()
            .find(|(c, _)| model.compound(*c).name == name)
            .copied()
            .ok_or_else(|| Error::at_start_of(ErrorKind::NoScenario, format!(
                    "expected a scenario `{name}` with a `do` (--scenario), found none; scenarios with a `do`: {}",
                    if with_do.is_empty() { "none".to_string() } else { listed(&with_do) }
                ), osc));
    }
    let invoked: BTreeSet<CompoundId> = program.invocations.iter().map(|i| i.callee).collect();
    let candidates: Vec<_> = with_do
        .iter()
        .copied()
        .filter(|(c, _)| !invoked.contains(c))
        .collect();
    match candidates.as_slice() {
        [one] => Ok(*one),
        [] if with_do.is_empty() => Err(Error::at_start_of(ErrorKind::NoScenario, "expected a scenario with a `do` to run, found none", osc)),
        [] => Err(Error::at_start_of(ErrorKind::NoScenario, format!(
                "expected a scenario that no other invokes (the entry point), found every scenario invoked: {}; name one with --scenario NAME",
                listed(&with_do)
            ), osc)),
        [first, ..] => Err(files.err(
            ErrorKind::NoScenario,
            model.compound(first.0).span,
            format!(
                "expected one scenario that no other invokes (the entry point), found several: {}; name one with --scenario NAME",
                listed(&candidates)
            ),
        )),
    }
}

/// Events the scenario (or the behavior invoked at phase `within`) declares with a condition
/// (`event e is c`), and the events its `on` handlers emit, each with the condition that makes
/// it occur; names are keyed by the frame's invocation prefix (an invocation's events are its
/// own, §7.3.10), and an invocation's handlers are active while it runs.
fn events(
    ev: &eval::Eval<'_>,
    members: &[Member],
    within: Option<&str>,
) -> Result<Vec<EventSpec>, Error> {
    let within = within.map(str::to_string);
    let mut events = Vec::new();
    let mut handlers = 0;
    for m in members {
        match m {
            Member::Event(e) => {
                if let Some(spec) = &e.spec {
                    events.push(EventSpec {
                        name: ev.event_key(&e.name.text),
                        cond: cond::read(ev, spec),
                        site: ev.site(spec.span),
                        handler: None,
                        call: None,
                        within: None,
                    });
                }
            }
            // `m.set_map_file(f)` names the road network (see `crate::map_file`),
            // `x.location(pose)` places a stationary object (`objects::locations`), the
            // entry scenario's map modifiers are read by `map_modifiers`.
            Member::Modifier(app)
                if app.name.text == "set_map_file"
                    || app.name.text == "location"
                    || (within.is_none()
                        && map_modifiers::MAP_MODIFIERS.contains(&app.name.text.as_str())) => {}
            Member::Modifier(app) => {
                let what = if map_modifiers::MAP_MODIFIERS.contains(&app.name.text.as_str()) {
                    "a map modifier in an invoked scenario (the map is the run's: write it in the scenario that runs)"
                } else {
                    "a modifier applied to the scenario itself (§7.3.9: a scenario's modifiers constrain its behavior's invocations; oscsim plans movement modifiers in an action's with:, where they name the actor they move)"
                };
                return Err(ev.files.err(
                    ErrorKind::Modifier,
                    app.span,
                    format!(
                        "expected modifiers on the actions of the `do` (the runtime plans those) or the map's modifiers, found `{}(…)`, {what}",
                        app.name.text
                    ),
                ));
            }
            // `on e: emit f`: f occurs whenever e does; `on e: call m(…)`: the host runs m
            // whenever e occurs (`call`).
            Member::On(spec, body, on_span) => {
                let index = handlers;
                handlers += 1;
                for b in body {
                    match &b.behavior {
                        Behavior::Emit(name, _, span) => events.push(EventSpec {
                            name: ev.event_key(&name.text),
                            cond: cond::read(ev, spec),
                            site: ev.site(spec.span),
                            handler: Some((index, ev.site(*span))),
                            call: None,
                            within: within.clone(),
                        }),
                        // A method defined by an expression has no side effect: its call
                        // runs nothing (its arguments and the condition read, for errors).
                        Behavior::Call(e, _) if !call::read(ev, e)?.external => {
                            cond::read(ev, spec)?;
                        }
                        Behavior::Call(e, span) => {
                            let c = call::read(ev, e)?;
                            events.push(EventSpec {
                                name: c.content.clone(),
                                cond: cond::read(ev, spec),
                                site: ev.site(spec.span),
                                handler: Some((index, ev.site(*span))),
                                call: Some(c),
                                within: within.clone(),
                            })
                        }
                        _ => return Err(ev.files.err(
                            ErrorKind::Call,
                            *on_span,
                            "expected `emit` or `call` in an `on` handler, found another member",
                        )),
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

/// What each actor path the tree invokes or its modifiers refer to, and each stationary object
/// `located` places, is.
fn objects(
    ev: &eval::Eval<'_>,
    root: &Phase,
    located: &[objects::Located],
) -> BTreeMap<String, Option<Object>> {
    let mut paths: Vec<String> = located.iter().map(|l| l.path.clone()).collect();
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
            let o = objects::classify(ev, &p, located);
            (p, o)
        })
        .collect()
}
