//! A crate's top-level modules and which of them each one uses (The Rust Reference, "Paths":
//! `crate::`, `super::`, and `use` trees with braces).
//!
//! A top-level module is one the crate root (`src/lib.rs` or `src/main.rs`) declares as
//! `mod NAME;`; its files are `src/NAME.rs` and every `.rs` file under `src/NAME/`. Module
//! `a` uses module `b` when a file of `a` names a path that starts at `b`: `crate::b…`,
//! `super::…` climbing out of `a` to the root and down into `b`, or an item the root
//! re-exports from `b` (`crate::Engine` when the root has `pub use runtime::Engine`). Paths
//! inside inline modules (`mod tests { … }`) and macro calls count too; `$crate` does not.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};
use std::str::FromStr;

use proc_macro2::{Delimiter, Spacing, TokenStream, TokenTree};

/// The top-level modules of a crate and the uses between them.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct CrateModules {
    /// Every top-level module, by name.
    pub modules: BTreeSet<String>,
    /// `(a, b)`: module `a` uses module `b` (never `a == b`).
    pub edges: BTreeSet<(String, String)>,
}

/// The modules of the crate whose sources are in `src` (holding `lib.rs` or `main.rs`).
pub fn crate_modules(src: &Path) -> Result<CrateModules, String> {
    let root_file = ["lib.rs", "main.rs"]
        .iter()
        .map(|f| src.join(f))
        .find(|p| p.is_file())
        .ok_or_else(|| format!("expected lib.rs or main.rs in {}", src.display()))?;
    let root = tokens(&root_file)?;
    let modules = declared_modules(&root);
    let reexports = reexports(&root, &modules);
    let mut edges = BTreeSet::new();
    for module in &modules {
        for (file, path) in module_files(src, module)? {
            let mut used = BTreeSet::new();
            scan(tokens(&file)?, &path, &mut used);
            for name in used {
                let target = if modules.contains(&name) {
                    Some(&name)
                } else {
                    reexports.get(&name)
                };
                if let Some(target) = target.filter(|t| *t != module) {
                    edges.insert((module.clone(), target.clone()));
                }
            }
        }
    }
    Ok(CrateModules { modules, edges })
}

fn tokens(file: &Path) -> Result<TokenStream, String> {
    let text = fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
    TokenStream::from_str(&text).map_err(|e| format!("{}: {e}", file.display()))
}

/// The `mod NAME;` declarations of the crate root (file modules; inline ones are not files).
fn declared_modules(root: &TokenStream) -> BTreeSet<String> {
    let t: Vec<TokenTree> = root.clone().into_iter().collect();
    let mut out = BTreeSet::new();
    for i in 0..t.len() {
        if let (TokenTree::Ident(kw), Some(TokenTree::Ident(name)), Some(TokenTree::Punct(p))) =
            (&t[i], t.get(i + 1), t.get(i + 2))
        {
            if kw == "mod" && p.as_char() == ';' {
                out.insert(name.to_string());
            }
        }
    }
    out
}

/// Names the crate root brings in from its modules with `use` (`pub use runtime::{Engine,
/// StopReason as Why}` gives `Engine` and `Why` → `runtime`).
fn reexports(root: &TokenStream, modules: &BTreeSet<String>) -> BTreeMap<String, String> {
    let t: Vec<TokenTree> = root.clone().into_iter().collect();
    let mut out = BTreeMap::new();
    let mut i = 0;
    while i < t.len() {
        if matches!(&t[i], TokenTree::Ident(kw) if kw == "use") {
            let end = (i..t.len())
                .find(|&j| matches!(&t[j], TokenTree::Punct(p) if p.as_char() == ';'))
                .unwrap_or(t.len());
            let mut tree = &t[i + 1..end];
            // `crate::x` and `self::x` in the root both mean module `x`.
            if tree.len() > 2 && is_ident(&tree[0], &["crate", "self"]) && is_path_sep(tree, 1) {
                tree = &tree[3..];
            }
            if let Some(TokenTree::Ident(first)) = tree.first() {
                let first = first.to_string();
                if modules.contains(&first) {
                    for leaf in leaves(tree) {
                        out.insert(leaf, first.clone());
                    }
                }
            }
            i = end;
        }
        i += 1;
    }
    out
}

/// The names a `use` tree brings in: each path's last segment, or its `as` alias.
fn leaves(tree: &[TokenTree]) -> Vec<String> {
    let mut out = Vec::new();
    let mut last = None;
    let mut i = 0;
    while i < tree.len() {
        match &tree[i] {
            TokenTree::Ident(id) if id == "as" => {
                if let Some(TokenTree::Ident(alias)) = tree.get(i + 1) {
                    last = Some(alias.to_string());
                    i += 1;
                }
            }
            TokenTree::Ident(id) => last = Some(id.to_string()),
            TokenTree::Group(g) if g.delimiter() == Delimiter::Brace => {
                let inner: Vec<TokenTree> = g.stream().into_iter().collect();
                for item in split_commas(&inner) {
                    out.extend(leaves(item));
                }
                last = None;
            }
            _ => {}
        }
        i += 1;
    }
    out.extend(last.filter(|l| l != "self" && l != "_"));
    out
}

/// The files of top-level module `name`, each with its module path (`[name, …]`).
fn module_files(src: &Path, name: &str) -> Result<Vec<(PathBuf, Vec<String>)>, String> {
    let mut out = Vec::new();
    let file = src.join(format!("{name}.rs"));
    if file.is_file() {
        out.push((file, vec![name.to_owned()]));
    }
    let dir = src.join(name);
    if dir.is_dir() {
        walk(&dir, &mut vec![name.to_owned()], &mut out)?;
    }
    if out.is_empty() {
        return Err(format!(
            "expected {name}.rs or {name}/ in {} (declared as `mod {name};`)",
            src.display()
        ));
    }
    Ok(out)
}

fn walk(
    dir: &Path,
    path: &mut Vec<String>,
    out: &mut Vec<(PathBuf, Vec<String>)>,
) -> Result<(), String> {
    let mut entries: Vec<PathBuf> = fs::read_dir(dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    entries.sort();
    for p in entries {
        let stem = p
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        if p.is_dir() {
            path.push(stem);
            walk(&p, path, out)?;
            path.pop();
        } else if p.extension().is_some_and(|e| e == "rs") {
            let mut module = path.clone();
            if stem != "mod" {
                module.push(stem);
            }
            out.push((p, module));
        }
    }
    Ok(())
}

fn is_ident(t: &TokenTree, names: &[&str]) -> bool {
    matches!(t, TokenTree::Ident(id) if names.iter().any(|n| id == n))
}

/// `::` at `t[i]`, `t[i + 1]`.
fn is_path_sep(t: &[TokenTree], i: usize) -> bool {
    matches!((t.get(i), t.get(i + 1)),
        (Some(TokenTree::Punct(a)), Some(TokenTree::Punct(b)))
            if a.as_char() == ':' && a.spacing() == Spacing::Joint && b.as_char() == ':')
}

fn split_commas(t: &[TokenTree]) -> Vec<&[TokenTree]> {
    t.split(|x| matches!(x, TokenTree::Punct(p) if p.as_char() == ','))
        .filter(|s| !s.is_empty())
        .collect()
}

/// The crate-root children named by the path tail at `t[i..]` (after `crate::` or enough
/// `super::` to reach the root): one identifier, or each item of a `{…}` group.
fn root_children(t: &[TokenTree], i: usize, out: &mut BTreeSet<String>) {
    match t.get(i) {
        Some(TokenTree::Ident(id)) if id != "self" && id != "super" && id != "crate" => {
            out.insert(id.to_string());
        }
        Some(TokenTree::Group(g)) if g.delimiter() == Delimiter::Brace => {
            let inner: Vec<TokenTree> = g.stream().into_iter().collect();
            for item in split_commas(&inner) {
                root_children(item, 0, out);
            }
        }
        _ => {}
    }
}

/// Adds to `used` the crate-root children that the paths in `stream`, written in module
/// `here` (a path from the root), start at; recurses into groups and inline modules.
fn scan(stream: TokenStream, here: &[String], used: &mut BTreeSet<String>) {
    let t: Vec<TokenTree> = stream.into_iter().collect();
    let mut i = 0;
    while i < t.len() {
        match &t[i] {
            TokenTree::Ident(kw) if kw == "mod" => {
                if let (Some(TokenTree::Ident(name)), Some(TokenTree::Group(g))) =
                    (t.get(i + 1), t.get(i + 2))
                {
                    if g.delimiter() == Delimiter::Brace {
                        let mut inner = here.to_vec();
                        inner.push(name.to_string());
                        scan(g.stream(), &inner, used);
                        i += 3;
                        continue;
                    }
                }
            }
            TokenTree::Ident(kw) if kw == "crate" && is_path_sep(&t, i + 1) => {
                let dollar =
                    i > 0 && matches!(&t[i - 1], TokenTree::Punct(p) if p.as_char() == '$');
                if !dollar {
                    root_children(&t, i + 3, used);
                }
            }
            TokenTree::Ident(kw) if kw == "super" && is_path_sep(&t, i + 1) => {
                let mut ups = 0;
                let mut j = i;
                while is_ident_at(&t, j, "super") && is_path_sep(&t, j + 1) {
                    ups += 1;
                    j += 3;
                }
                if ups < here.len() {
                    // Still inside a top-level module: `here[0]` itself (not a use of another).
                } else if ups == here.len() {
                    root_children(&t, j, used);
                }
                i = j;
                continue;
            }
            TokenTree::Group(g) => scan(g.stream(), here, used),
            _ => {}
        }
        i += 1;
    }
}

fn is_ident_at(t: &[TokenTree], i: usize, name: &str) -> bool {
    t.get(i).is_some_and(|x| is_ident(x, &[name]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Module uses of one source text as module `path` (for unit tests and single files): the
    /// names of the crate root's children that its paths start at.
    fn uses_in(text: &str, path: &[&str]) -> BTreeSet<String> {
        let path: Vec<String> = path.iter().map(|s| (*s).to_owned()).collect();
        let mut used = BTreeSet::new();
        if let Ok(stream) = TokenStream::from_str(text) {
            scan(stream, &path, &mut used);
        }
        used
    }

    fn set(names: &[&str]) -> BTreeSet<String> {
        names.iter().map(|s| (*s).to_owned()).collect()
    }

    #[test]
    fn crate_paths_and_use_groups_name_their_first_segment() {
        let text = "use crate::a::X; use crate::{b::{c, d}, e}; fn f() { crate::g::h(); }";
        assert_eq!(uses_in(text, &["m"]), set(&["a", "b", "e", "g"]));
    }

    #[test]
    fn super_reaches_the_root_only_from_the_right_depth() {
        // In m/x.rs (path m::x) one `super` is m itself; two reach the root.
        let text = "use super::y; use super::super::{p, q::r};";
        assert_eq!(uses_in(text, &["m", "x"]), set(&["p", "q"]));
        // In m.rs or m/mod.rs one `super` reaches the root.
        assert_eq!(uses_in("use super::z;", &["m"]), set(&["z"]));
    }

    #[test]
    fn inline_modules_add_a_level_and_comments_strings_and_dollar_crate_do_not_count() {
        let text = r#"
            // crate::commented
            /// Doc: crate::doc_text
            const S: &str = "crate::in_string";
            macro_rules! m { () => { $crate::macro_path } }
            mod tests { use super::super::t; use super::*; }
        "#;
        assert_eq!(uses_in(text, &["m"]), set(&["t"]));
    }

    #[test]
    fn reexports_of_the_root_map_names_to_modules() {
        let root = TokenStream::from_str(
            "mod a; mod b; pub use a::{X, y::Y as Z}; pub use crate::b::W; pub use other::V;",
        )
        .expect("valid tokens");
        let modules = declared_modules(&root);
        assert_eq!(modules, set(&["a", "b"]));
        let map = reexports(&root, &modules);
        let want: BTreeMap<String, String> = [("X", "a"), ("Z", "a"), ("W", "b")]
            .iter()
            .map(|(k, v)| ((*k).to_owned(), (*v).to_owned()))
            .collect();
        assert_eq!(map, want);
    }
}
