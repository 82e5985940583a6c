//! A crate's module tree and which sibling modules use each other, at every depth (The Rust
//! Reference, "Modules" and "Paths": `crate::`, `super::`, `self::`, and `use` trees with
//! braces).
//!
//! The tree is read from the `mod NAME;` declarations: the root (`src/lib.rs` or
//! `src/main.rs`) declares the top-level modules; module `a::b` is `src/a/b.rs` or
//! `src/a/b/mod.rs`, and the modules it declares are in `src/a/b/`. Every module that
//! declares file modules is a *folder* (the root is the folder `[]`), and its graph has one
//! node per module it declares.
//!
//! Each path in a file that starts at `crate::`, `self::` or `super::` is resolved to the
//! deepest module it names, following the re-exports of each folder's own file (`crate::Engine`
//! when the root has `pub use runtime::Engine` names `runtime`). A path written in module `P`
//! that names module `M` is a use between siblings of their deepest common folder `C`:
//! `P`'s and `M`'s next segments below `C`, when both are modules `C` declares and differ.
//! So `use super::y` in `a/x.rs` is `x → y` in folder `a`, and `use crate::b::z` there is
//! `a → b` in the root. A parent using its own child is no edge (nothing can cycle through
//! it without a child naming the parent's sibling). Paths inside inline modules
//! (`mod tests { … }`) and macro calls count; `$crate` and plain relative paths (`use child::…`,
//! which can only go down) do not.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;
use std::str::FromStr;

use proc_macro2::{Delimiter, Spacing, TokenStream, TokenTree};

/// The modules one folder declares and the uses between them.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct CrateModules {
    /// The folder's path from the crate root (empty for the root itself).
    pub folder: Vec<String>,
    /// Every module the folder declares, by name.
    pub modules: BTreeSet<String>,
    /// `(a, b)`: module `a` (or one below it) uses module `b` (or one below it); never `a == b`.
    pub edges: BTreeSet<(String, String)>,
}

/// The top-level modules of the crate whose sources are in `src` (holding `lib.rs` or
/// `main.rs`) and the uses between them.
pub fn crate_modules(src: &Path) -> Result<CrateModules, String> {
    let mut folders = module_folders(src)?;
    // The root is always the first folder (`[]` sorts first).
    Ok(folders.remove(0))
}

/// Every folder of the crate in `src`, the root first, then by path: the modules each
/// declares and the uses between them.
pub fn module_folders(src: &Path) -> Result<Vec<CrateModules>, String> {
    let root_file = ["lib.rs", "main.rs"]
        .iter()
        .map(|f| src.join(f))
        .find(|p| p.is_file())
        .ok_or_else(|| format!("expected lib.rs or main.rs in {}", src.display()))?;
    let mut tree = BTreeMap::new();
    let mut files = Vec::new();
    read_module(src, &root_file, Vec::new(), &mut tree, &mut files)?;
    let mut folders: BTreeMap<Vec<String>, CrateModules> = tree
        .iter()
        .filter(|(_, m)| !m.children.is_empty())
        .map(|(path, m)| {
            let folder = CrateModules {
                folder: path.clone(),
                modules: m.children.clone(),
                edges: BTreeSet::new(),
            };
            (path.clone(), folder)
        })
        .collect();
    for (stream, here) in files {
        let mut paths = Vec::new();
        scan(stream, &here, &mut paths);
        for p in paths {
            let target = resolve(&tree, &p);
            if let Some((folder, a, b)) = sibling_use(&here, &target) {
                if let Some(f) = folders.get_mut(&folder) {
                    if f.modules.contains(&a) && f.modules.contains(&b) {
                        f.edges.insert((a, b));
                    }
                }
            }
        }
    }
    Ok(folders.into_values().collect())
}

/// One module of the tree: the file modules it declares and the names its own file brings
/// in from them with `use`.
#[derive(Default)]
struct Module {
    children: BTreeSet<String>,
    reexports: BTreeMap<String, String>,
}

/// Reads module `path` from `file` and, recursively, the modules it declares (in `dir`).
fn read_module(
    dir: &Path,
    file: &Path,
    path: Vec<String>,
    tree: &mut BTreeMap<Vec<String>, Module>,
    files: &mut Vec<(TokenStream, Vec<String>)>,
) -> Result<(), String> {
    let stream = tokens(file)?;
    let declared = declared_modules(&stream);
    let children: BTreeSet<String> = declared.keys().cloned().collect();
    let reexports = reexports(&stream, &children);
    for (c, attribute) in &declared {
        let (flat, nested) = (dir.join(format!("{c}.rs")), dir.join(c).join("mod.rs"));
        // `#[path]` on a file module is relative to the directory of the file declaring it.
        let by_attribute = attribute
            .as_ref()
            .and_then(|a| Some(file.parent()?.join(a)));
        let child_file = if let Some(f) = by_attribute {
            f
        } else if flat.is_file() {
            flat
        } else if nested.is_file() {
            nested
        } else {
            return Err(format!(
                "expected {c}.rs or {c}/mod.rs in {} (declared as `mod {c};`)",
                dir.display()
            ));
        };
        let mut child = path.clone();
        child.push(c.clone());
        read_module(&dir.join(c), &child_file, child, tree, files)?;
    }
    tree.insert(
        path.clone(),
        Module {
            children,
            reexports,
        },
    );
    files.push((stream, path));
    Ok(())
}

/// The deepest module an absolute path names: down through declared modules and the
/// re-exports of each module's file (a re-exported name is looked up again in the module it
/// comes from, at most a few times).
fn resolve(tree: &BTreeMap<Vec<String>, Module>, path: &[String]) -> Vec<String> {
    let mut at: Vec<String> = Vec::new();
    let mut i = 0;
    let mut hops = 0;
    while let (Some(seg), Some(m)) = (path.get(i), tree.get(&at)) {
        if m.children.contains(seg) {
            at.push(seg.clone());
            i += 1;
        } else if let Some(c) = m.reexports.get(seg).filter(|_| hops < 8) {
            at.push(c.clone());
            hops += 1;
        } else {
            break;
        }
    }
    at
}

/// The folder and the two of its modules that a path written in module `here` naming module
/// `target` joins, when it joins two different siblings.
fn sibling_use(here: &[String], target: &[String]) -> Option<(Vec<String>, String, String)> {
    let common = here.iter().zip(target).take_while(|(a, b)| a == b).count();
    let (a, b) = (here.get(common)?, target.get(common)?);
    Some((here[..common].to_vec(), a.clone(), b.clone()))
}

fn tokens(file: &Path) -> Result<TokenStream, String> {
    let text = fs::read_to_string(file).map_err(|e| format!("{}: {e}", file.display()))?;
    TokenStream::from_str(&text).map_err(|e| format!("{}: {e}", file.display()))
}

/// The `mod NAME;` declarations of a module's file (file modules; inline ones are not
/// files), each with the file its `#[path = "…"]` attribute names, if it has one.
fn declared_modules(file: &TokenStream) -> BTreeMap<String, Option<String>> {
    let t: Vec<TokenTree> = file.clone().into_iter().collect();
    let mut out = BTreeMap::new();
    for i in 0..t.len() {
        if let (TokenTree::Ident(kw), Some(TokenTree::Ident(name)), Some(TokenTree::Punct(p))) =
            (&t[i], t.get(i + 1), t.get(i + 2))
        {
            if kw == "mod" && p.as_char() == ';' {
                out.insert(name.to_string(), path_attribute(&t[..i]));
            }
        }
    }
    out
}

/// The `#[path = "…"]` among the attributes that end `t` (before a `mod`, past any `pub`,
/// `pub(crate)`).
fn path_attribute(t: &[TokenTree]) -> Option<String> {
    let mut end = t.len();
    while end > 0 {
        match &t[end - 1] {
            TokenTree::Ident(id) if id == "pub" => end -= 1,
            TokenTree::Group(g)
                if g.delimiter() == Delimiter::Parenthesis
                    && end >= 2
                    && is_ident(&t[end - 2], &["pub"]) =>
            {
                end -= 1
            }
            TokenTree::Group(g)
                if g.delimiter() == Delimiter::Bracket
                    && end >= 2
                    && matches!(&t[end - 2], TokenTree::Punct(p) if p.as_char() == '#') =>
            {
                let a: Vec<TokenTree> = g.stream().into_iter().collect();
                if let (Some(id), Some(TokenTree::Punct(eq)), Some(TokenTree::Literal(lit))) =
                    (a.first(), a.get(1), a.get(2))
                {
                    if is_ident(id, &["path"]) && eq.as_char() == '=' {
                        return Some(lit.to_string().trim_matches('"').to_owned());
                    }
                }
                end -= 2;
            }
            _ => break,
        }
    }
    None
}

/// Names a module's file brings in from the modules it declares with `use` (`pub use
/// runtime::{Engine, StopReason as Why}` gives `Engine` and `Why` → `runtime`).
fn reexports(file: &TokenStream, modules: &BTreeSet<String>) -> BTreeMap<String, String> {
    let t: Vec<TokenTree> = file.clone().into_iter().collect();
    let mut out = BTreeMap::new();
    let mut i = 0;
    while i < t.len() {
        if matches!(&t[i], TokenTree::Ident(kw) if kw == "use") {
            let end = (i..t.len())
                .find(|&j| matches!(&t[j], TokenTree::Punct(p) if p.as_char() == ';'))
                .unwrap_or(t.len());
            let mut tree = &t[i + 1..end];
            // `self::x` means the child `x` (and `crate::x` in the root).
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

/// The absolute paths named by the path tail at `t[i..]`, each `base` followed by its
/// segments (`a::b::{c, d::e}` gives `base::a::b::c` and `base::a::b::d::e`; `self` in a
/// group is the path so far).
fn tails(t: &[TokenTree], i: usize, base: &[String], out: &mut Vec<Vec<String>>) {
    match t.get(i) {
        Some(TokenTree::Ident(id)) if id != "super" && id != "crate" && id != "self" => {
            let mut p = base.to_vec();
            p.push(id.to_string());
            if is_path_sep(t, i + 1) {
                tails(t, i + 3, &p, out);
            } else {
                out.push(p);
            }
        }
        Some(TokenTree::Group(g)) if g.delimiter() == Delimiter::Brace => {
            let inner: Vec<TokenTree> = g.stream().into_iter().collect();
            for item in split_commas(&inner) {
                tails(item, 0, base, out);
            }
        }
        _ => out.push(base.to_vec()),
    }
}

/// Adds to `paths` the absolute paths that the `crate::`, `self::` and `super::` paths in
/// `stream`, written in module `here` (a path from the root), name; recurses into groups
/// and inline modules.
fn scan(stream: TokenStream, here: &[String], paths: &mut Vec<Vec<String>>) {
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
                        scan(g.stream(), &inner, paths);
                        i += 3;
                        continue;
                    }
                }
            }
            TokenTree::Ident(kw) if kw == "crate" && is_path_sep(&t, i + 1) => {
                let dollar =
                    i > 0 && matches!(&t[i - 1], TokenTree::Punct(p) if p.as_char() == '$');
                if !dollar {
                    tails(&t, i + 3, &[], paths);
                }
            }
            TokenTree::Ident(kw) if kw == "self" && is_path_sep(&t, i + 1) => {
                // Not the `self` of a `use a::{self, …}` group: that one follows no `::`.
                tails(&t, i + 3, here, paths);
                i += 3;
                continue;
            }
            TokenTree::Ident(kw) if kw == "super" && is_path_sep(&t, i + 1) => {
                let mut ups = 0;
                let mut j = i;
                while is_ident_at(&t, j, "super") && is_path_sep(&t, j + 1) {
                    ups += 1;
                    j += 3;
                }
                if ups <= here.len() {
                    tails(&t, j, &here[..here.len() - ups], paths);
                }
                i = j;
                continue;
            }
            TokenTree::Group(g) => scan(g.stream(), here, paths),
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

    /// The absolute paths one source text names, written as module `path`.
    fn paths_in(text: &str, path: &[&str]) -> BTreeSet<String> {
        let path: Vec<String> = path.iter().map(|s| (*s).to_owned()).collect();
        let mut out = Vec::new();
        if let Ok(stream) = TokenStream::from_str(text) {
            scan(stream, &path, &mut out);
        }
        out.into_iter().map(|p| p.join("::")).collect()
    }

    fn set(names: &[&str]) -> BTreeSet<String> {
        names.iter().map(|s| (*s).to_owned()).collect()
    }

    #[test]
    fn crate_paths_and_use_groups_give_every_path() {
        let text = "use crate::a::X; use crate::{b::{c, d}, e}; fn f() { crate::g::h(); }";
        assert_eq!(
            paths_in(text, &["m"]),
            set(&["a::X", "b::c", "b::d", "e", "g::h"])
        );
    }

    #[test]
    fn super_and_self_climb_from_the_module_they_are_written_in() {
        // In m/x.rs (path m::x) one `super` is m; two reach the root; three are no path.
        let text = "use super::y; use super::super::{p, q::r}; use self::z::{self, W};";
        assert_eq!(
            paths_in(text, &["m", "x"]),
            set(&["m::y", "p", "q::r", "m::x::z", "m::x::z::W"])
        );
        assert_eq!(
            paths_in("use super::super::super::n;", &["m", "x"]),
            set(&[])
        );
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
        assert_eq!(paths_in(text, &["m"]), set(&["t", "m"]));
    }

    #[test]
    fn reexports_of_a_module_map_names_to_its_children() {
        let root = TokenStream::from_str(
            "mod a; mod b; pub use a::{X, y::Y as Z}; pub use crate::b::W; pub use other::V;",
        )
        .expect("valid tokens");
        let modules: BTreeSet<String> = declared_modules(&root).into_keys().collect();
        assert_eq!(modules, set(&["a", "b"]));
        let map = reexports(&root, &modules);
        let want: BTreeMap<String, String> = [("X", "a"), ("Z", "a"), ("W", "b")]
            .iter()
            .map(|(k, v)| ((*k).to_owned(), (*v).to_owned()))
            .collect();
        assert_eq!(map, want);
    }

    #[test]
    fn a_path_attribute_names_the_file_of_its_module() {
        let file = TokenStream::from_str(
            "mod a; #[cfg(test)] #[path = \"a_tests.rs\"] mod tests; #[path = \"x.rs\"] pub(crate) mod b;",
        )
        .expect("valid tokens");
        let d = declared_modules(&file);
        assert_eq!(d["a"], None);
        assert_eq!(d["tests"].as_deref(), Some("a_tests.rs"));
        assert_eq!(d["b"].as_deref(), Some("x.rs"));
    }

    #[test]
    fn a_use_joins_the_siblings_below_the_deepest_common_folder() {
        let v = |l: &[&str]| l.iter().map(|s| (*s).to_owned()).collect::<Vec<_>>();
        let edge = |f: &[&str], a: &str, b: &str| Some((v(f), a.to_owned(), b.to_owned()));
        assert_eq!(
            sibling_use(&v(&["a", "x"]), &v(&["a", "y"])),
            edge(&["a"], "x", "y")
        );
        assert_eq!(
            sibling_use(&v(&["a", "x", "t"]), &v(&["b"])),
            edge(&[], "a", "b")
        );
        // A parent naming its child, or a module itself: no sibling edge.
        assert_eq!(sibling_use(&v(&["a"]), &v(&["a", "y"])), None);
        assert_eq!(sibling_use(&v(&["a", "y"]), &v(&["a"])), None);
    }
}
