//! The top level of a scenario file (OpenSCENARIO 1.3 §7.1, XSD `OpenScenario`,
//! `FileHeader`, group `ScenarioDefinition`, `ParameterValueDistribution`/`ScenarioFile`,
//! `CatalogLocations`, `RoadNetwork`, `VariableDeclarations`, `MonitorDeclarations`) and the
//! load sequence:
//!
//! 1. read the file (at most [`MAX_FILE_BYTES`]) and parse it with roxmltree (no DTD, so no
//!    entity expansion);
//! 2. FileHeader, global ParameterDeclarations (with `--param` overrides), CatalogLocations;
//! 3. parse every `.xosc` of the catalog directories;
//! 4. RoadNetwork, Entities, Storyboard, reading catalog entries where referenced;
//! 5. check entity names and expand entity selections.

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::error::{Error, ErrorKind, Result};
use crate::expr::Value;
use crate::model::{
    FileHeader, License, MonitorDeclaration, ParameterDeclaration, Phase, RoadNetwork, Scenario,
    TrafficSignalController, VariableDeclaration,
};
use crate::reader::catalog::{CatalogFile, CatalogIndex};
use crate::reader::context::{Ctx, Doc, Node, Scope};
use crate::reader::entities::read_entities;
use crate::reader::params::{declare, read_parameter_type};
use crate::reader::positions::read_position;
use crate::reader::references::check_references;
use crate::reader::selections::{check_entity_names, expand_selections};
use crate::reader::storyboard::read_storyboard;
use crate::source::{LineIndex, SourcePos};

/// Largest scenario or catalog file read, bytes (64 MiB; the largest real scenarios are a
/// few hundred kB). Larger files are refused before reading.
pub const MAX_FILE_BYTES: u64 = 64 * 1024 * 1024;

/// The children of XSD `CatalogLocations`, one per catalog kind.
const CATALOG_KINDS: [&str; 8] = [
    "VehicleCatalog",
    "ControllerCatalog",
    "PedestrianCatalog",
    "MiscObjectCatalog",
    "EnvironmentCatalog",
    "ManeuverCatalog",
    "TrajectoryCatalog",
    "RouteCatalog",
];

/// A file's path and text.
struct Source {
    path: Arc<Path>,
    text: String,
}

/// Reads `path` for `what`, refusing files over [`MAX_FILE_BYTES`].
fn read_source(path: &Path, what: &'static str) -> Result<Source> {
    let arc: Arc<Path> = Arc::from(path);
    let io_err = |e: std::io::Error| {
        Error::new(
            ErrorKind::Io {
                what,
                path: path.to_path_buf(),
                message: e.to_string(),
            },
            SourcePos::start_of(arc.clone()),
        )
    };
    let size = std::fs::metadata(path).map_err(io_err)?.len();
    if size > MAX_FILE_BYTES {
        return Err(Error::new(
            ErrorKind::FileTooLarge {
                path: path.to_path_buf(),
                size,
                limit: MAX_FILE_BYTES,
            },
            SourcePos::start_of(arc),
        ));
    }
    let bytes = std::fs::read(path).map_err(io_err)?;
    // A UTF-8 byte order mark is allowed before the XML declaration; roxmltree wants text.
    let text = String::from_utf8(bytes).map_err(|e| {
        let offset = e.utf8_error().valid_up_to();
        Error::new(
            ErrorKind::Xml {
                message: format!("invalid UTF-8 at byte {offset}"),
            },
            SourcePos::start_of(arc.clone()),
        )
    })?;
    Ok(Source { path: arc, text })
}

/// Parses `source` into a document.
fn parse(source: &Source) -> Result<Doc<'_>> {
    let text = source.text.strip_prefix('\u{feff}').unwrap_or(&source.text);
    let lines = LineIndex::new(text);
    let doc = roxmltree::Document::parse(text).map_err(|e| {
        let p = e.pos();
        let message = e.to_string();
        let suffix = format!(" at {}:{}", p.row, p.col);
        let message = message.strip_suffix(&suffix).unwrap_or(&message).to_owned();
        Error::new(
            ErrorKind::Xml { message },
            SourcePos {
                file: source.path.clone(),
                line: p.row,
                col: p.col,
            },
        )
    })?;
    Ok(Doc {
        path: source.path.clone(),
        text,
        lines,
        doc,
    })
}

/// Loads the scenario at `path`, overriding global parameters with `overrides`.
pub(crate) fn load(path: &Path, overrides: &[(String, String)]) -> Result<Scenario> {
    load_inner(path, overrides, true)
}

fn load_inner(
    path: &Path,
    overrides: &[(String, String)],
    follow_distribution: bool,
) -> Result<Scenario> {
    let main = read_source(path, "scenario")?;
    let mut docs = vec![parse(&main)?];
    let root = docs[0].doc.root_element();
    let mut ctx = new_ctx(&docs);
    // `OpenScenario` is the XSD's second global element of the same type.
    if !matches!(root.tag_name().name(), "OpenSCENARIO" | "OpenScenario") {
        return Err(ctx.err(
            root,
            ErrorKind::NotAScenario {
                found: format!("root element {}", root.tag_name().name()),
            },
        ));
    }
    let header = read_file_header(&mut ctx, root)?;
    if let Some(dist) = ctx.opt_child(root, "ParameterValueDistribution") {
        return load_distribution(&mut ctx, dist, path, overrides, follow_distribution);
    }
    if let Some(cat) = ctx.opt_child(root, "Catalog") {
        return Err(ctx.err(
            cat,
            ErrorKind::NotAScenario {
                found: "a Catalog".into(),
            },
        ));
    }
    // Phase 1: globals and catalog locations, to know which catalog files to read. The
    // globals are read again in phase 2, so their warnings are dropped here.
    let before = ctx.take_warnings();
    let (globals, _) = read_globals(&mut ctx, root, overrides)?;
    ctx.warnings = before;
    ctx.scopes.push(globals);
    let locations = read_catalog_locations(&mut ctx, root, path)?;
    let warnings = ctx.take_warnings();
    drop(ctx);
    let catalog_sources = read_catalog_sources(&locations)?;
    for s in &catalog_sources {
        docs.push(parse(s)?);
    }
    // Phase 2: everything, with the catalogs indexed.
    let root = docs[0].doc.root_element();
    let mut ctx = new_ctx(&docs);
    ctx.doc_rev_minor = docs.iter().map(declared_rev_minor).collect();
    ctx.warnings = warnings;
    ctx.catalogs = index_catalogs(&docs, &locations);
    let (globals, parameter_declarations) = read_globals(&mut ctx, root, overrides)?;
    ctx.scopes.push(globals);
    ctx.expect_children(
        root,
        &[
            "FileHeader",
            "ParameterDeclarations",
            "VariableDeclarations",
            "MonitorDeclarations",
            "CatalogLocations",
            "RoadNetwork",
            "Entities",
            "Storyboard",
        ],
    )?;
    let variable_declarations = read_variable_declarations(&mut ctx, root)?;
    let monitor_declarations = read_monitor_declarations(&mut ctx, root)?;
    let road = ctx.child(root, "RoadNetwork")?;
    let road_network = read_road_network(&mut ctx, road, path)?;
    let entities_node = ctx.child(root, "Entities")?;
    let mut entities = read_entities(&mut ctx, entities_node)?;
    let storyboard_node = ctx.child(root, "Storyboard")?;
    let storyboard = read_storyboard(&mut ctx, storyboard_node)?;
    check_entity_names(&entities, &ctx.entity_uses)?;
    expand_selections(&mut entities)?;
    check_references(&storyboard, &variable_declarations)?;
    Ok(Scenario {
        path: path.to_path_buf(),
        file_header: header,
        parameter_declarations,
        variable_declarations,
        monitor_declarations,
        catalog_locations: locations,
        road_network,
        entities,
        storyboard,
        parameter_value_distribution: None,
        warnings: ctx.take_warnings(),
    })
}

fn new_ctx<'a>(docs: &'a [Doc<'a>]) -> Ctx<'a> {
    Ctx {
        docs,
        cur: 0,
        scopes: Vec::new(),
        warnings: Vec::new(),
        doc_rev_minor: Vec::new(),
        catalogs: CatalogIndex::default(),
        entity_uses: Vec::new(),
        entry_scoped: None,
        warnings_later: RefCell::new(Vec::new()),
    }
}

/// ParameterValueDistribution: loads its ScenarioFile (relative to the distribution file).
fn load_distribution<'a>(
    ctx: &mut Ctx<'a>,
    dist: Node<'a>,
    path: &Path,
    overrides: &[(String, String)],
    follow: bool,
) -> Result<Scenario> {
    let file = ctx.child(dist, "ScenarioFile")?;
    if !follow {
        return Err(ctx.err(
            dist,
            ErrorKind::NotAScenario {
                found: "a ParameterValueDistribution referring to another".into(),
            },
        ));
    }
    let written: String = ctx.req(file, "filepath")?;
    let resolved = resolve_path(path, &written);
    if !resolved.is_file() {
        let pos = ctx
            .raw_attr(file, "filepath")
            .map_or_else(|| ctx.pos(file), |a| ctx.attr_pos(&a));
        return Err(Error::new(
            ErrorKind::FileNotFound {
                what: "scenario",
                written,
                resolved,
            },
            pos,
        ));
    }
    let mut scenario = load_inner(&resolved, overrides, false)?;
    scenario.parameter_value_distribution = Some(path.to_path_buf());
    Ok(scenario)
}

/// `written` relative to the directory of `base` (absolute paths stay as they are).
/// `..` steps are folded into the path as text (no file system access, so links are not
/// followed), which keeps messages short: `xosc/../xodr/a.xodr` reads `xodr/a.xodr`.
pub(crate) fn resolve_path(base: &Path, written: &str) -> PathBuf {
    use std::path::Component;
    let dir = base.parent().unwrap_or_else(|| Path::new(""));
    let mut out = PathBuf::new();
    for c in dir.join(written.trim()).components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir
                if matches!(out.components().next_back(), Some(Component::Normal(_))) =>
            {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}

/// Reads XSD `FileHeader`.
fn read_file_header<'a>(ctx: &mut Ctx<'a>, root: Node<'a>) -> Result<FileHeader> {
    let h = ctx.child(root, "FileHeader")?;
    let rev_major: u16 = ctx.req(h, "revMajor")?;
    let rev_minor: u16 = ctx.req(h, "revMinor")?;
    if rev_major != 1 {
        return Err(ctx.err(
            h,
            ErrorKind::UnsupportedVersion {
                found: format!("{rev_major}.{rev_minor}"),
            },
        ));
    }
    ctx.doc_rev_minor = vec![u32::from(rev_minor)];
    if rev_minor > 3 {
        ctx.warn(
            h,
            format!("revision 1.{rev_minor} is newer than 1.3; read as 1.3"),
        );
    }
    let license = match ctx.opt_child(h, "License") {
        Some(l) => Some(License {
            name: ctx.req(l, "name")?,
            resource: ctx.opt(l, "resource")?,
            spdx_id: ctx.opt(l, "spdxId")?,
        }),
        None => None,
    };
    Ok(FileHeader {
        rev_major,
        rev_minor,
        date: ctx.opt(h, "date")?.unwrap_or_default(),
        description: ctx.opt(h, "description")?.unwrap_or_default(),
        author: ctx.opt(h, "author")?.unwrap_or_default(),
        license,
    })
}

/// revMinor of a document's FileHeader, read without resolution (3 when absent or odd; the
/// scenario's own header is checked by [`read_file_header`]).
fn declared_rev_minor(doc: &Doc<'_>) -> u32 {
    let root = doc.doc.root_element();
    root.children()
        .find(|c| c.is_element() && c.tag_name().name() == "FileHeader")
        .and_then(|h| h.attribute("revMinor"))
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(3)
}

/// Global ParameterDeclarations with overrides; an override of an undeclared name is an error.
fn read_globals<'a>(
    ctx: &mut Ctx<'a>,
    root: Node<'a>,
    overrides: &[(String, String)],
) -> Result<(Scope, Vec<ParameterDeclaration>)> {
    let decls = ctx.opt_child(root, "ParameterDeclarations");
    let (scope, records) = match decls {
        Some(d) => declare(ctx, d, overrides)?,
        None => (Scope::default(), Vec::new()),
    };
    if let Some((name, _)) = overrides
        .iter()
        .find(|(n, _)| !records.iter().any(|r| &r.name == n))
    {
        return Err(ctx.err(root, ErrorKind::UnknownOverride { name: name.clone() }));
    }
    Ok((scope, records))
}

/// Reads XSD `VariableDeclarations` (1.2+).
fn read_variable_declarations<'a>(
    ctx: &mut Ctx<'a>,
    root: Node<'a>,
) -> Result<Vec<VariableDeclaration>> {
    let mut out = Vec::new();
    let Some(v) = ctx.opt_child(root, "VariableDeclarations") else {
        return Ok(out);
    };
    ctx.since(v, 2);
    for d in ctx.children(v, "VariableDeclaration") {
        let ty = read_parameter_type(ctx, d, "variableType")?;
        let text: String = ctx.req(d, "value")?;
        let pos = ctx
            .raw_attr(d, "value")
            .map_or_else(|| ctx.pos(d), |a| ctx.attr_pos(&a));
        let value = Value::parse(ty, &text).map_err(|_| {
            Error::new(
                ErrorKind::InvalidValue {
                    element: "VariableDeclaration".into(),
                    attribute: "value".into(),
                    expected: format!("a {}", ty.xsd_name()),
                    found: text.clone(),
                },
                pos.clone(),
            )
        })?;
        out.push(VariableDeclaration {
            name: ctx.req(d, "name")?,
            variable_type: ty,
            value,
            pos,
        });
    }
    Ok(out)
}

/// Reads XSD `MonitorDeclarations` (1.3).
fn read_monitor_declarations<'a>(
    ctx: &mut Ctx<'a>,
    root: Node<'a>,
) -> Result<Vec<MonitorDeclaration>> {
    let mut out = Vec::new();
    let Some(m) = ctx.opt_child(root, "MonitorDeclarations") else {
        return Ok(out);
    };
    ctx.since(m, 3);
    for d in ctx.children(m, "MonitorDeclaration") {
        out.push(MonitorDeclaration {
            name: ctx.req(d, "name")?,
            value: ctx.req(d, "value")?,
        });
    }
    Ok(out)
}

/// Reads XSD `CatalogLocations`: (kind element, directory resolved against the scenario).
fn read_catalog_locations<'a>(
    ctx: &mut Ctx<'a>,
    root: Node<'a>,
    path: &Path,
) -> Result<Vec<(String, PathBuf)>> {
    let mut out = Vec::new();
    let Some(c) = ctx.opt_child(root, "CatalogLocations") else {
        return Ok(out);
    };
    for kind in c.children().filter(Node::is_element) {
        if !CATALOG_KINDS.contains(&kind.tag_name().name()) {
            return Err(ctx.unexpected(c, kind, &CATALOG_KINDS.join(", ")));
        }
        let dir = ctx.child(kind, "Directory")?;
        let written: String = ctx.req(dir, "path")?;
        let resolved = resolve_path(path, &written);
        if !resolved.is_dir() {
            ctx.warn(
                dir,
                format!(
                    "catalog directory '{written}' not found at {}",
                    resolved.display()
                ),
            );
        }
        out.push((kind.tag_name().name().to_owned(), resolved));
    }
    Ok(out)
}

/// Reads every `.xosc` of the catalog directories, in sorted order, each file once.
fn read_catalog_sources(locations: &[(String, PathBuf)]) -> Result<Vec<Source>> {
    let mut files: Vec<PathBuf> = Vec::new();
    for (_, dir) in locations {
        let Ok(entries) = std::fs::read_dir(dir) else {
            continue;
        };
        let mut found: Vec<PathBuf> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "xosc") && p.is_file())
            .collect();
        found.sort();
        for f in found {
            if !files.contains(&f) {
                files.push(f);
            }
        }
    }
    files.iter().map(|f| read_source(f, "catalog")).collect()
}

/// Indexes the `Catalog` elements of documents 1.. by name.
fn index_catalogs<'a>(docs: &'a [Doc<'a>], locations: &[(String, PathBuf)]) -> CatalogIndex<'a> {
    let mut index = CatalogIndex {
        dirs: locations.iter().map(|(_, d)| d.clone()).collect(),
        missing_dirs: locations
            .iter()
            .filter(|(_, d)| !d.is_dir())
            .map(|(_, d)| d.clone())
            .collect(),
        files: Vec::new(),
    };
    for (i, d) in docs.iter().enumerate().skip(1) {
        let root = d.doc.root_element();
        for c in root
            .children()
            .filter(|c| c.is_element() && c.tag_name().name() == "Catalog")
        {
            let name = c.attribute("name").unwrap_or_default().to_owned();
            index.files.push(CatalogFile {
                name,
                doc: i,
                node: c,
            });
        }
    }
    index
}

/// Reads XSD `RoadNetwork`; the LogicFile must exist (resolved against the scenario).
fn read_road_network<'a>(ctx: &mut Ctx<'a>, n: Node<'a>, path: &Path) -> Result<RoadNetwork> {
    ctx.expect_children(
        n,
        &["LogicFile", "SceneGraphFile", "TrafficSignals", "UsedArea"],
    )?;
    let mut road = RoadNetwork::default();
    if let Some(l) = ctx.opt_child(n, "LogicFile") {
        let written: String = ctx.req(l, "filepath")?;
        let resolved = resolve_path(path, &written);
        if !resolved.is_file() {
            let pos = ctx
                .raw_attr(l, "filepath")
                .map_or_else(|| ctx.pos(l), |a| ctx.attr_pos(&a));
            return Err(Error::new(
                ErrorKind::FileNotFound {
                    what: "road network",
                    written,
                    resolved,
                },
                pos,
            ));
        }
        road.logic_file = Some(resolved);
    }
    if let Some(s) = ctx.opt_child(n, "SceneGraphFile") {
        road.scene_graph_file = Some(ctx.req(s, "filepath")?);
    }
    if let Some(t) = ctx.opt_child(n, "TrafficSignals") {
        for c in ctx.children(t, "TrafficSignalController") {
            let mut phases = Vec::new();
            for p in ctx.children(c, "Phase") {
                let mut signal_states = Vec::new();
                for s in ctx.children(p, "TrafficSignalState") {
                    signal_states.push((ctx.req(s, "trafficSignalId")?, ctx.req(s, "state")?));
                }
                let group_state = match ctx.opt_child(p, "TrafficSignalGroupState") {
                    Some(g) => Some(ctx.req(g, "state")?),
                    None => None,
                };
                phases.push(Phase {
                    name: ctx.req(p, "name")?,
                    duration: ctx.req(p, "duration")?,
                    signal_states,
                    group_state,
                });
            }
            road.traffic_signal_controllers
                .push(TrafficSignalController {
                    name: ctx.req(c, "name")?,
                    delay: ctx.opt(c, "delay")?,
                    reference: ctx.opt(c, "reference")?,
                    phases,
                });
        }
    }
    if let Some(u) = ctx.opt_child(n, "UsedArea") {
        ctx.since(u, 1);
        for p in ctx.children(u, "Position") {
            road.used_area.push(read_position(ctx, p)?);
        }
    }
    Ok(road)
}

#[cfg(test)]
mod tests {
    use super::resolve_path;
    use std::path::Path;

    #[test]
    fn resolved_paths_fold_parent_steps_but_keep_leading_ones() {
        let base = Path::new("/c/esmini/xosc/cut-in.xosc");
        assert_eq!(
            resolve_path(base, "../xodr/e6mini.xodr"),
            Path::new("/c/esmini/xodr/e6mini.xodr")
        );
        assert_eq!(
            resolve_path(base, "./Catalogs/V"),
            Path::new("/c/esmini/xosc/Catalogs/V")
        );
        assert_eq!(
            resolve_path(Path::new("a.xosc"), "../../r.xodr"),
            Path::new("../../r.xodr")
        );
        assert_eq!(resolve_path(base, "/abs/r.xodr"), Path::new("/abs/r.xodr"));
    }
}
