//! Markdown tables (GitHub Flavored Markdown, "Tables (extension)"): the pipe tables of a
//! document or of a crate's `//!` doc, their cells, the `code` spans in a cell, and the module
//! paths a module table's first column names.

/// One pipe table: the header's cells and each row's.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Table {
    /// The header row's cells, trimmed.
    pub header: Vec<String>,
    /// The body rows' cells, trimmed.
    pub rows: Vec<Vec<String>>,
}

/// Every pipe table of `text`: runs of lines that start with `|`, the second being the
/// delimiter row (`| --- | --- |`).
pub fn markdown_tables(text: &str) -> Vec<Table> {
    let mut out = Vec::new();
    let mut run: Vec<&str> = Vec::new();
    for line in text.lines().chain(std::iter::once("")) {
        let line = line.trim();
        if line.starts_with('|') {
            run.push(line);
            continue;
        }
        if run.len() >= 2 && is_delimiter_row(run[1]) {
            out.push(Table {
                header: cells(run[0]),
                rows: run[2..].iter().map(|r| cells(r)).collect(),
            });
        }
        run.clear();
    }
    out
}

/// The crate doc of a crate root's source: its `//!` lines without the marker.
pub fn crate_doc(source: &str) -> String {
    source
        .lines()
        .filter_map(|l| l.trim_start().strip_prefix("//!"))
        .map(|l| l.strip_prefix(' ').unwrap_or(l))
        .collect::<Vec<_>>()
        .join("\n")
}

fn is_delimiter_row(line: &str) -> bool {
    cells(line)
        .iter()
        .all(|c| !c.is_empty() && c.chars().all(|ch| matches!(ch, '-' | ':')))
}

/// The cells of a row; a `|` inside a code span does not split.
fn cells(line: &str) -> Vec<String> {
    let inner = line.trim().trim_start_matches('|');
    let inner = inner.strip_suffix('|').unwrap_or(inner);
    let mut out = Vec::new();
    let mut cell = String::new();
    let mut code = false;
    for ch in inner.chars() {
        match ch {
            '`' => {
                code = !code;
                cell.push(ch);
            }
            '|' if !code => out.push(std::mem::take(&mut cell).trim().to_owned()),
            _ => cell.push(ch),
        }
    }
    out.push(cell.trim().to_owned());
    out
}

/// The code spans of a cell, in order, without their backticks.
pub fn backticked(cell: &str) -> Vec<String> {
    cell.split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_owned)
        .collect()
}

/// The module paths the first cell of a module table names, each as path segments from the
/// crate root: `` `model/header` `` is `[model, header]`, `` `source.rs` `` is `[source]`,
/// `` `expr/` `` is `[expr]`, `` `reader/{a,b}` `` is `[reader, a]` and `[reader, b]`; a name
/// without `/` after one with shares its folder (`` `geometry/line`, `arc` `` is
/// `geometry/line` and `geometry/arc`).
pub fn module_paths(cell: &str) -> Vec<Vec<String>> {
    let mut out: Vec<Vec<String>> = Vec::new();
    let mut folder: Vec<String> = Vec::new();
    for span in backticked(cell) {
        let span = span.trim().trim_end_matches('/');
        let (stem, alternatives) = match (span.find('{'), span.rfind('}')) {
            (Some(open), Some(close)) if open < close => (
                &span[..open],
                span[open + 1..close]
                    .split(',')
                    .map(|s| s.trim().to_owned())
                    .collect::<Vec<_>>(),
            ),
            _ => (span, vec![String::new()]),
        };
        let stem: Vec<String> = stem
            .split('/')
            .filter(|s| !s.is_empty())
            .map(|s| s.trim_end_matches(".rs").to_owned())
            .collect();
        let base = if span.contains('/') {
            // A folder named here is the folder of the names without one that follow.
            let braced = !alternatives[0].is_empty();
            folder = if braced {
                stem.clone()
            } else {
                stem[..stem.len().saturating_sub(1)].to_vec()
            };
            stem
        } else {
            folder.iter().chain(&stem).cloned().collect()
        };
        for alt in alternatives {
            let mut p = base.clone();
            if !alt.is_empty() {
                p.push(alt.trim_end_matches(".rs").to_owned());
            }
            if !p.is_empty() {
                out.push(p);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn paths(cell: &str) -> Vec<String> {
        module_paths(cell).iter().map(|p| p.join("/")).collect()
    }

    #[test]
    fn a_table_in_a_crate_doc_is_found_with_its_rows() {
        let src = "//! Crate.\n//!\n//! | module | job |\n//! | --- | --- |\n//! | `a` | x `|` y |\n//! | `b`, `c` | z |\n#![forbid(unsafe_code)]\n";
        let t = markdown_tables(&crate_doc(src));
        assert_eq!(t.len(), 1);
        assert_eq!(t[0].header, vec!["module", "job"]);
        assert_eq!(t[0].rows.len(), 2);
        assert_eq!(t[0].rows[0][1], "x `|` y");
        assert_eq!(backticked(&t[0].rows[1][0]), vec!["b", "c"]);
    }

    #[test]
    fn module_paths_follow_the_tables_shorthands() {
        assert_eq!(paths("`source.rs`, `error.rs`"), vec!["source", "error"]);
        assert_eq!(
            paths("`expr/`, `distribution/`"),
            vec!["expr", "distribution"]
        );
        assert_eq!(
            paths("`geometry/line`, `arc`, `spiral`"),
            vec!["geometry/line", "geometry/arc", "geometry/spiral"]
        );
        assert_eq!(
            paths("`reader/{entities,storyboard}`"),
            vec!["reader/entities", "reader/storyboard"]
        );
        assert_eq!(paths("`model/scenario.rs`"), vec!["model/scenario"]);
    }
}
