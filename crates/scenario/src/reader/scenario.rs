//! The top level of a scenario file (OpenSCENARIO 1.3, XSD `OpenScenario`, `FileHeader`,
//! group `ScenarioDefinition`, `ParameterValueDistribution`/`ScenarioFile`,
//! `CatalogLocations`, `RoadNetwork`, `VariableDeclarations`, `MonitorDeclarations`) and the
//! load sequence:
//!
//! 1. read the file (at most [`MAX_FILE_BYTES`](crate::MAX_FILE_BYTES)) and parse it with
//!    roxmltree (no DTD, so no entity expansion; at most 4 million nodes);
//! 2. FileHeader, global ParameterDeclarations (with `--param` overrides), CatalogLocations;
//! 3. parse every `.xosc` of the catalog directories;
//! 4. RoadNetwork, Entities, Storyboard, reading catalog entries where referenced;
//! 5. check entity names, expand entity selections, check storyboard element, variable and
//!    monitor references.

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::error::{Error, ErrorKind, Result};
use crate::expr::Value;
use crate::model::{
    FileHeader, License, MonitorDeclaration, ParameterDeclaration, Scenario, VariableDeclaration,
};
use crate::provider::FileProvider;
use crate::reader::context::{CatalogFile, CatalogIndex};
use crate::reader::context::{Ctx, Doc, Node, Scope};
use crate::reader::entities::read_entities;
use crate::reader::files::{
    declared_rev_minor, parse, read_catalog_sources, read_source, resolve_path, Source,
};
use crate::reader::params::{declare, read_parameter_type};
use crate::reader::references::check_references;
use crate::reader::road_network::read_road_network;
use crate::reader::selections::{check_entity_names, expand_selections};
use crate::reader::storyboard::read_storyboard;

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

/// Loads the scenario at `path` from `files`, overriding global parameters with `overrides`.
pub(crate) fn load(
    files: &dyn FileProvider,
    path: &Path,
    overrides: &[(String, String)],
) -> Result<Scenario> {
    load_source(
        files,
        read_source(files, path, "scenario")?,
        overrides,
        true,
    )
}

/// Loads scenario `text` as if read from `path` (positions name `path`; relative paths in
/// the scenario resolve against its directory).
pub(crate) fn load_text(
    files: &dyn FileProvider,
    text: &str,
    path: &Path,
    overrides: &[(String, String)],
) -> Result<Scenario> {
    let source = Source {
        path: Arc::from(path),
        text: text.to_owned(),
    };
    load_source(files, source, overrides, true)
}

fn load_source(
    files: &dyn FileProvider,
    main: Source,
    overrides: &[(String, String)],
    follow_distribution: bool,
) -> Result<Scenario> {
    let path: &Path = &main.path.clone();
    let mut docs = vec![parse(&main)?];
    let root = docs[0].doc.root_element();
    let mut ctx = new_ctx(files, &docs);
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
    let catalog_sources = read_catalog_sources(files, &locations)?;
    for s in &catalog_sources {
        docs.push(parse(s)?);
    }
    // Phase 2: everything, with the catalogs indexed.
    let root = docs[0].doc.root_element();
    let mut ctx = new_ctx(files, &docs);
    ctx.doc_rev_minor = docs.iter().map(declared_rev_minor).collect();
    ctx.warnings = warnings;
    ctx.catalogs = index_catalogs(files, &docs, &locations);
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
    let mut storyboard = read_storyboard(&mut ctx, storyboard_node)?;
    check_entity_names(&entities, &ctx.entity_uses)?;
    expand_selections(&mut entities)?;
    check_references(
        &mut storyboard,
        &variable_declarations,
        &monitor_declarations,
    )?;
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
        sources: crate::Sources::default(),
    })
}

fn new_ctx<'a>(files: &'a dyn FileProvider, docs: &'a [Doc<'a>]) -> Ctx<'a> {
    Ctx {
        files,
        docs,
        cur: 0,
        scopes: Vec::new(),
        warnings: Vec::new(),
        doc_rev_minor: Vec::new(),
        catalogs: CatalogIndex::default(),
        entity_uses: Vec::new(),
        entry_scoped: None,
        entry_stack: Vec::new(),
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
    if !ctx.files.is_file(&resolved) {
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
    let files = ctx.files;
    let source = read_source(files, &resolved, "scenario")?;
    let mut scenario = load_source(files, source, overrides, false)?;
    scenario.parameter_value_distribution = Some(path.to_path_buf());
    Ok(scenario)
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
            pos: ctx.pos(d),
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
        if !ctx.files.is_dir(&resolved) {
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

/// Indexes the `Catalog` elements of documents 1.. by name.
fn index_catalogs<'a>(
    files: &dyn FileProvider,
    docs: &'a [Doc<'a>],
    locations: &[(String, PathBuf)],
) -> CatalogIndex<'a> {
    let mut index = CatalogIndex {
        dirs: locations.iter().map(|(_, d)| d.clone()).collect(),
        missing_dirs: locations
            .iter()
            .filter(|(_, d)| !files.is_dir(d))
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
