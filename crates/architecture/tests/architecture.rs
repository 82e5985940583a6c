//! `docs/architecture.md` and each crate's module table checked against the code, and the
//! ratchet on module cycles. Run with `--nocapture` to see every crate's module graph.
//!
//! The rules are stated in `docs/architecture.md` and read from its tables:
//! - "Crates and their main public types": each crate's layer and its workspace
//!   dependencies (tests' own after "tests:"). The test wants the table and the Cargo files
//!   to agree both ways, and every `[dependencies]`/`[build-dependencies]` edge to point to a
//!   lower layer (dev-dependencies may point anywhere: tests run a lowered scenario in the
//!   engine).
//! - "External crates in one place": each listed crates.io package only in the crates named.
//! - "Never, even through another crate": packages a crate must not reach through its
//!   normal dependencies.
//!
//! Each crate's module table (in its root's `//!` doc and in its README, whichever it has;
//! at least one) must name every top-level module and only modules that exist.
//!
//! The ratchet: [`KNOWN_CYCLES`] lists the module cycles there are today, with how many uses
//! each holds and its two-way pairs (modules that use each other directly). A new cycle, a
//! module joining one, a new two-way pair or a cycle gaining uses fails; so does a cycle that
//! shrank or went away until the list is lowered to match, so that it never allows more than
//! there is. (Splitting a module of a cycle in two while untangling it adds the new module to
//! the list, and the uses of both halves count: then the pairs must have gone down.)
//!
//! [`KNOWN_NESTED_CYCLES`] is the same ratchet one level down and deeper: in every folder (a
//! module that declares modules: `foo/mod.rs`, or `foo.rs` with `foo/`), the graph between
//! the modules it declares, where `super::x`, `self::x` and `crate::a::b::x` are uses of the
//! sibling they name (`architecture::module_folders`).

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

use architecture::{
    backticked, crate_doc, crate_modules, cycles, markdown_tables, module_folders, module_paths,
    CrateModules, Cycle, DependencyKind, Table, Workspace,
};

/// The module cycles allowed today: crate, the cycle's modules, the number of uses between
/// them, its two-way pairs. Lower it as cycles go; never raise it.
const KNOWN_CYCLES: &[(&str, &[&str], usize, &[&str])] = &[];

/// The same for the folders below the crate roots (every module that declares modules),
/// keyed `crate/folder/path`: the cycles between the modules one folder declares, as they
/// are today. Lower it as they go; never raise it.
const KNOWN_NESTED_CYCLES: &[(&str, &[&str], usize, &[&str])] = &[];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn workspace() -> Workspace {
    Workspace::read(&root()).unwrap_or_else(|e| panic!("reading the workspace: {e}"))
}

fn architecture_doc() -> Vec<Table> {
    let path = root().join("docs/architecture.md");
    let text = fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    markdown_tables(&text)
}

fn table_with<'a>(tables: &'a [Table], header: &str) -> &'a Table {
    tables
        .iter()
        .find(|t| t.header.iter().any(|h| h == header))
        .unwrap_or_else(|| {
            panic!("expected a table with a column '{header}' in docs/architecture.md")
        })
}

fn column(t: &Table, header: &str) -> usize {
    t.header
        .iter()
        .position(|h| h == header)
        .unwrap_or_else(|| panic!("expected a column '{header}'"))
}

/// A crate's row of the crate table: layer, normal dependencies, tests' dependencies.
struct Row {
    layer: u32,
    deps: BTreeSet<String>,
    dev_deps: BTreeSet<String>,
}

fn crate_rows() -> BTreeMap<String, Row> {
    let tables = architecture_doc();
    let t = table_with(&tables, "depends on (workspace)");
    let (c_crate, c_layer, c_deps) = (
        column(t, "crate"),
        column(t, "layer"),
        column(t, "depends on (workspace)"),
    );
    let mut out = BTreeMap::new();
    for r in &t.rows {
        let name = backticked(&r[c_crate])
            .into_iter()
            .next()
            .unwrap_or_default();
        let layer = r[c_layer].parse().unwrap_or_else(|_| {
            panic!(
                "expected a layer number for '{name}', found '{}'",
                r[c_layer]
            )
        });
        let (normal, tests) = r[c_deps]
            .split_once("tests:")
            .unwrap_or((r[c_deps].as_str(), ""));
        let row = Row {
            layer,
            deps: backticked(normal).into_iter().collect(),
            dev_deps: backticked(tests).into_iter().collect(),
        };
        assert!(
            out.insert(name.clone(), row).is_none(),
            "'{name}' has two rows in the crate table of docs/architecture.md"
        );
    }
    out
}

const NORMAL: &[DependencyKind] = &[DependencyKind::Normal, DependencyKind::Build];

#[test]
fn the_crate_table_lists_every_crate_and_its_workspace_dependencies() {
    let ws = workspace();
    let rows = crate_rows();
    let documented: BTreeSet<&String> = rows.keys().collect();
    let members: BTreeSet<&String> = ws.members.keys().collect();
    assert_eq!(
        documented, members,
        "the crate table of docs/architecture.md and the workspace members differ"
    );
    let mut wrong = Vec::new();
    for (name, m) in &ws.members {
        let row = &rows[name];
        let deps: BTreeSet<String> = m.members(NORMAL).into_iter().map(str::to_owned).collect();
        let dev: BTreeSet<String> = m
            .members(&[DependencyKind::Dev])
            .into_iter()
            .map(str::to_owned)
            .filter(|d| !deps.contains(d))
            .collect();
        if deps != row.deps {
            wrong.push(format!(
                "{name}: expected the dependencies the table states {:?}, found {:?} in Cargo.toml",
                row.deps, deps
            ));
        }
        if dev != row.dev_deps {
            wrong.push(format!(
                "{name}: expected the tests' dependencies the table states {:?}, found {:?} in Cargo.toml",
                row.dev_deps, dev
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn every_dependency_points_to_a_lower_layer() {
    let ws = workspace();
    let rows = crate_rows();
    let mut wrong = Vec::new();
    for (name, m) in &ws.members {
        for dep in m.members(NORMAL) {
            let (from, to) = (rows[name].layer, rows[dep].layer);
            if to >= from {
                wrong.push(format!(
                    "{name} (layer {from}) depends on {dep} (layer {to}): expected a lower layer"
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn external_crates_stay_where_the_table_puts_them() {
    let ws = workspace();
    let tables = architecture_doc();
    let t = table_with(&tables, "only in");
    let (c_pkg, c_only) = (column(t, "external crate"), column(t, "only in"));
    let mut wrong = Vec::new();
    for r in &t.rows {
        let allowed: BTreeSet<String> = backticked(&r[c_only]).into_iter().collect();
        for pkg in backticked(&r[c_pkg]) {
            for (name, m) in &ws.members {
                let all = [
                    DependencyKind::Normal,
                    DependencyKind::Build,
                    DependencyKind::Dev,
                ];
                if m.external(&all).contains(&pkg.as_str()) && !allowed.contains(name) {
                    wrong.push(format!(
                        "{name} depends on {pkg}: expected it only in {allowed:?}"
                    ));
                }
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn no_crate_reaches_what_it_must_never_depend_on() {
    let ws = workspace();
    let tables = architecture_doc();
    let t = table_with(&tables, "never depends on, even through another crate");
    let (c_crate, c_never) = (
        column(t, "crate"),
        column(t, "never depends on, even through another crate"),
    );
    let mut wrong = Vec::new();
    for r in &t.rows {
        let name = backticked(&r[c_crate])
            .into_iter()
            .next()
            .unwrap_or_default();
        let m = ws
            .members
            .get(&name)
            .unwrap_or_else(|| panic!("'{name}' of the 'never' table is no workspace member"));
        // Everything `name` builds with: its normal dependencies and theirs, members and
        // crates.io packages (the direct ones of each member reached).
        let mut reached: BTreeSet<String> = BTreeSet::new();
        let mut todo = vec![m];
        let mut seen = BTreeSet::new();
        while let Some(m) = todo.pop() {
            if !seen.insert(m.name.clone()) {
                continue;
            }
            for d in m.dependencies.iter().filter(|d| NORMAL.contains(&d.kind)) {
                reached.insert(d.name.clone());
                if d.member {
                    todo.push(&ws.members[&d.name]);
                }
            }
        }
        for never in backticked(&r[c_never]) {
            if reached.contains(&never) {
                wrong.push(format!("{name} reaches {never}: expected never"));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The module tables of crate `name`: from its root's `//!` doc and its README.
fn module_tables(dir: &Path) -> Vec<(String, Table)> {
    let mut out = Vec::new();
    for root in ["src/lib.rs", "src/main.rs"] {
        if let Ok(text) = fs::read_to_string(dir.join(root)) {
            for t in markdown_tables(&crate_doc(&text)) {
                out.push((root.to_owned(), t));
            }
        }
    }
    if let Ok(text) = fs::read_to_string(dir.join("README.md")) {
        for t in markdown_tables(&text) {
            out.push(("README.md".to_owned(), t));
        }
    }
    out.retain(|(_, t)| t.header.first().is_some_and(|h| h == "module"));
    out
}

fn module_exists(src: &Path, path: &[String]) -> bool {
    let rel: PathBuf = path.iter().collect();
    src.join(&rel).with_extension("rs").is_file() || src.join(&rel).is_dir()
}

#[test]
fn every_crates_module_table_names_its_modules() {
    let ws = workspace();
    let mut wrong = Vec::new();
    for (name, m) in &ws.members {
        let src = m.dir.join("src");
        let modules = crate_modules(&src)
            .unwrap_or_else(|e| panic!("{name}: {e}"))
            .modules;
        let tables = module_tables(&m.dir);
        if tables.is_empty() && !modules.is_empty() {
            wrong.push(format!(
                "{name}: expected a module table (| module | … |) in its crate doc or README"
            ));
        }
        for (file, t) in tables {
            let mut listed = BTreeSet::new();
            for row in &t.rows {
                for path in module_paths(&row[0]) {
                    if !module_exists(&src, &path) {
                        wrong.push(format!(
                            "{name} {file}: `{}` is listed but src/{0}.rs or src/{0}/ does not exist",
                            path.join("/")
                        ));
                    }
                    if path.len() == 1 && !listed.insert(path[0].clone()) {
                        wrong.push(format!("{name} {file}: `{}` is listed twice", path[0]));
                    }
                    listed.insert(path[0].clone());
                }
            }
            for missing in modules.difference(&listed) {
                wrong.push(format!(
                    "{name} {file}: module `{missing}` is not in the table"
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

fn describe(c: &Cycle) -> String {
    let pairs: Vec<String> = c.two_way.iter().map(|(a, b)| format!("{a}↔{b}")).collect();
    format!(
        "{} modules {:?}, {} uses, {} two-way pairs [{}]",
        c.modules.len(),
        c.modules,
        c.edges.len(),
        c.two_way.len(),
        pairs.join(", ")
    )
}

/// Checks the cycles `measured` (each keyed by crate, or crate and folder) against the list
/// `known` (named `list` in messages): exact, both ways.
fn ratchet(
    measured: &[(String, Cycle)],
    known: &[(&str, &[&str], usize, &[&str])],
    list: &str,
) -> Vec<String> {
    let mut wrong = Vec::new();
    type Known<'a> = (&'a str, BTreeSet<String>, usize, BTreeSet<String>);
    let known: Vec<Known> = known
        .iter()
        .map(|(k, mods, n, pairs)| {
            let set = |l: &[&str]| l.iter().map(|s| (*s).to_owned()).collect();
            (*k, set(mods), *n, set(pairs))
        })
        .collect();
    for (name, c) in measured {
        let pairs: BTreeSet<String> = c.two_way.iter().map(|(a, b)| format!("{a}↔{b}")).collect();
        match known
            .iter()
            .find(|(k, mods, _, _)| k == name && c.modules.is_subset(mods))
        {
            None => wrong.push(format!(
                "{name}: a new module cycle: {} (expected none; break it)",
                describe(c)
            )),
            Some((_, mods, n, p)) if c.modules == *mods && c.edges.len() == *n && pairs == *p => {}
            Some((_, mods, n, p)) if c.edges.len() > *n || !pairs.is_subset(p) => {
                wrong.push(format!(
                    "{name}: the cycle {mods:?} grew (allowed {n} uses, two-way pairs {p:?}): {}",
                    describe(c)
                ))
            }
            Some((_, mods, n, _)) => wrong.push(format!(
                "{name}: the cycle {mods:?} ({n} uses) shrank to {}: lower {list} in {}",
                describe(c),
                file!()
            )),
        }
    }
    for (k, mods, n, _) in &known {
        let still = measured
            .iter()
            .any(|(name, c)| name == k && c.modules.is_subset(mods));
        if !still {
            wrong.push(format!(
                "{k}: the cycle {mods:?} ({n} uses) is gone: remove it from {list} in {}",
                file!()
            ));
        }
    }
    wrong
}

/// Every folder's graph of every crate: (crate, the folder's graph).
fn folders() -> Vec<(String, CrateModules)> {
    let ws = workspace();
    let mut out = Vec::new();
    for (name, m) in &ws.members {
        let all = module_folders(&m.dir.join("src")).unwrap_or_else(|e| panic!("{name}: {e}"));
        out.extend(all.into_iter().map(|f| (name.clone(), f)));
    }
    out
}

/// The cycles of the folders that `top` selects (the crate roots, or the folders below),
/// keyed by crate (roots) or `crate/folder/path` (below), printed as they are measured.
fn measured_cycles(top: bool) -> Vec<(String, Cycle)> {
    let mut measured = Vec::new();
    for (name, g) in folders() {
        if g.folder.is_empty() != top {
            continue;
        }
        let key = if top {
            name.clone()
        } else {
            format!("{name}/{}", g.folder.join("/"))
        };
        let found = cycles(&g.modules, &g.edges);
        println!(
            "{key}: {} modules, {} uses, {} cycle(s)",
            g.modules.len(),
            g.edges.len(),
            found.len()
        );
        for c in found {
            println!("  cycle: {}", describe(&c));
            measured.push((key.clone(), c));
        }
    }
    measured
}

#[test]
fn module_cycles_never_grow_and_the_ratchet_is_tight() {
    let wrong = ratchet(&measured_cycles(true), KNOWN_CYCLES, "KNOWN_CYCLES");
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn nested_module_cycles_never_grow_and_their_ratchet_is_tight() {
    let wrong = ratchet(
        &measured_cycles(false),
        KNOWN_NESTED_CYCLES,
        "KNOWN_NESTED_CYCLES",
    );
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The graph builder on the fixture crate `tests/files/module_tree` (its files say which use
/// each line makes): folder `a`'s `x` and `y` use each other (one through `a`'s re-export of
/// `y::Why`), folder `b` (`b.rs` + `b/`) is a chain `p → q`, `p → r` (from an inline module),
/// `r → q` (from `r`'s `#[path]` module), and at the root only `b → a`.
#[test]
fn the_graph_builder_finds_the_fixtures_cycle_and_no_other() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files/module_tree/src");
    let folders = module_folders(&src).unwrap_or_else(|e| panic!("{e}"));
    let summary: Vec<(String, Vec<String>, Vec<String>)> = folders
        .iter()
        .map(|f| {
            let edges = f.edges.iter().map(|(a, b)| format!("{a}→{b}")).collect();
            (
                f.folder.join("/"),
                f.modules.iter().cloned().collect(),
                edges,
            )
        })
        .collect();
    let s = |l: &[&str]| l.iter().map(|x| (*x).to_owned()).collect::<Vec<String>>();
    assert_eq!(
        summary,
        vec![
            (String::new(), s(&["a", "b"]), s(&["b→a"])),
            ("a".to_owned(), s(&["x", "y"]), s(&["x→y", "y→x"])),
            (
                "b".to_owned(),
                s(&["p", "q", "r"]),
                s(&["p→q", "p→r", "r→q"])
            ),
            ("b/r".to_owned(), s(&["imp"]), s(&[])),
        ]
    );
    let found: Vec<(String, Vec<String>)> = folders
        .iter()
        .flat_map(|f| {
            cycles(&f.modules, &f.edges)
                .into_iter()
                .map(|c| (f.folder.join("/"), c.modules.into_iter().collect()))
        })
        .collect();
    assert_eq!(found, vec![("a".to_owned(), s(&["x", "y"]))]);
    // The crate root's graph is the first folder's.
    assert_eq!(
        crate_modules(&src).unwrap_or_else(|e| panic!("{e}")),
        folders[0]
    );
}
