//! The workspace's members and each one's dependencies, read from the `Cargo.toml` files
//! (the Cargo reference, "The Manifest Format" and "Specifying Dependencies": the
//! `[dependencies]`, `[build-dependencies]` and `[dev-dependencies]` tables, also under
//! `[target.'cfg(…)']`, and `[workspace.dependencies]` inherited by `name.workspace = true`).

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

use toml::{Table, Value};

/// Which table a dependency is declared in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum DependencyKind {
    /// `[dependencies]`.
    Normal,
    /// `[build-dependencies]`.
    Build,
    /// `[dev-dependencies]`: tests, examples and benchmarks only.
    Dev,
}

/// One dependency of a member.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Dependency {
    /// For a workspace member, its short name (the folder under `crates/`, e.g. `engine`);
    /// otherwise the package's name on crates.io (`prost`, `arrow-array`).
    pub name: String,
    /// True when the dependency is a member of this workspace.
    pub member: bool,
    /// The table it is declared in.
    pub kind: DependencyKind,
}

/// One member of the workspace.
#[derive(Debug, Clone)]
pub struct Manifest {
    /// Short name: the member's folder name (`crates/NAME`).
    pub name: String,
    /// `package.name` (e.g. `oscsim-engine`).
    pub package: String,
    /// The member's folder.
    pub dir: PathBuf,
    /// Its dependencies, in the order of the tables.
    pub dependencies: Vec<Dependency>,
}

impl Manifest {
    /// The short names of the workspace members this one depends on in `kinds`.
    pub fn members(&self, kinds: &[DependencyKind]) -> Vec<&str> {
        self.dependencies
            .iter()
            .filter(|d| d.member && kinds.contains(&d.kind))
            .map(|d| d.name.as_str())
            .collect()
    }

    /// The crates.io packages this one depends on in `kinds`.
    pub fn external(&self, kinds: &[DependencyKind]) -> Vec<&str> {
        self.dependencies
            .iter()
            .filter(|d| !d.member && kinds.contains(&d.kind))
            .map(|d| d.name.as_str())
            .collect()
    }
}

/// The workspace: its members by short name.
#[derive(Debug, Clone)]
pub struct Workspace {
    /// The folder of the root `Cargo.toml`.
    pub root: PathBuf,
    /// Every member, by short name.
    pub members: BTreeMap<String, Manifest>,
}

impl Workspace {
    /// Reads the root `Cargo.toml` under `root` and every member's.
    pub fn read(root: &Path) -> Result<Workspace, String> {
        let top = read_table(&root.join("Cargo.toml"))?;
        let ws = top
            .get("workspace")
            .and_then(Value::as_table)
            .ok_or("expected a [workspace] table in the root Cargo.toml")?;
        let member_dirs: Vec<PathBuf> = ws
            .get("members")
            .and_then(Value::as_array)
            .ok_or("expected workspace.members")?
            .iter()
            .filter_map(Value::as_str)
            .map(|m| root.join(m))
            .collect();
        // A member's short name is its folder's name; workspace dependencies name a folder.
        let short = |dir: &Path| {
            dir.components()
                .next_back()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .unwrap_or_default()
        };
        let mut inherited = BTreeMap::new();
        if let Some(deps) = ws.get("dependencies").and_then(Value::as_table) {
            for (key, spec) in deps {
                inherited.insert(key.clone(), resolve(key, spec, root, &member_dirs, short));
            }
        }
        let mut members = BTreeMap::new();
        for dir in &member_dirs {
            let table = read_table(&dir.join("Cargo.toml"))?;
            let package = table
                .get("package")
                .and_then(|p| p.get("name"))
                .and_then(Value::as_str)
                .ok_or_else(|| format!("expected package.name in {}", dir.display()))?
                .to_owned();
            let mut dependencies = Vec::new();
            let mut tables = vec![&table];
            if let Some(targets) = table.get("target").and_then(Value::as_table) {
                tables.extend(targets.values().filter_map(Value::as_table));
            }
            for t in tables {
                for (section, kind) in [
                    ("dependencies", DependencyKind::Normal),
                    ("build-dependencies", DependencyKind::Build),
                    ("dev-dependencies", DependencyKind::Dev),
                ] {
                    let Some(deps) = t.get(section).and_then(Value::as_table) else {
                        continue;
                    };
                    for (key, spec) in deps {
                        let inherits = spec.get("workspace").and_then(Value::as_bool) == Some(true);
                        let (name, member) = if inherits {
                            inherited.get(key).cloned().ok_or_else(|| {
                                format!(
                                    "expected '{key}' in [workspace.dependencies] (used by {})",
                                    dir.display()
                                )
                            })?
                        } else {
                            resolve(key, spec, dir, &member_dirs, short)
                        };
                        dependencies.push(Dependency { name, member, kind });
                    }
                }
            }
            members.insert(
                short(dir),
                Manifest {
                    name: short(dir),
                    package,
                    dir: dir.clone(),
                    dependencies,
                },
            );
        }
        Ok(Workspace {
            root: root.to_owned(),
            members,
        })
    }
}

/// The dependency declared as `key = spec` in a manifest in `base`: a member's short name when
/// its `path` is a member's folder, else the package name (`package = …` or the key).
fn resolve(
    key: &str,
    spec: &Value,
    base: &Path,
    members: &[PathBuf],
    short: impl Fn(&Path) -> String,
) -> (String, bool) {
    if let Some(path) = spec.get("path").and_then(Value::as_str) {
        let dir = normalize(&base.join(path));
        if members.iter().any(|m| normalize(m) == dir) {
            return (short(&dir), true);
        }
    }
    let package = spec.get("package").and_then(Value::as_str).unwrap_or(key);
    (package.to_owned(), false)
}

/// `path` with `.` and `..` components worked out (the folders need not exist).
fn normalize(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            std::path::Component::CurDir => {}
            std::path::Component::ParentDir => {
                out.pop();
            }
            c => out.push(c),
        }
    }
    out
}

fn read_table(path: &Path) -> Result<Table, String> {
    let text = fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    text.parse::<Table>()
        .map_err(|e| format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalize_works_out_parent_folders() {
        assert_eq!(
            normalize(Path::new("/w/crates/cli/../engine/./src")),
            PathBuf::from("/w/crates/engine/src")
        );
    }
}
