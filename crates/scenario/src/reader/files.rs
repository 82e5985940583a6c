//! Reading scenario and catalog files through a [`FileProvider`]: the size limit, UTF-8 and
//! XML parsing with positions, and the resolution of paths written in a scenario (relative paths
//! resolve against the directory of the file that names them).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::error::{Error, ErrorKind, Result};
use crate::provider::FileProvider;
use crate::reader::context::Doc;
use crate::source::{LineIndex, SourcePos};

/// Largest scenario or catalog file read, bytes (64 MiB; the largest real scenarios are a
/// few hundred kB). Larger files are refused before reading.
pub const MAX_FILE_BYTES: u64 = 64 * 1024 * 1024;

/// Most XML nodes (elements, text, comments) parsed from one file. The 68 kB
/// `parking_demo.xosc` has about 1 700; the limit keeps a hostile file within a few hundred
/// MB of memory.
pub(crate) const MAX_NODES: u32 = 4_000_000;

/// A file's path and text.
pub(crate) struct Source {
    /// The path as opened.
    pub path: Arc<Path>,
    /// The text.
    pub text: String,
}

/// Reads `path` for `what`, refusing files over [`MAX_FILE_BYTES`].
pub(crate) fn read_source(
    files: &dyn FileProvider,
    path: &Path,
    what: &'static str,
) -> Result<Source> {
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
    let size = files.size(path).map_err(io_err)?;
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
    let bytes = files.read(path).map_err(io_err)?;
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
pub(crate) fn parse(source: &Source) -> Result<Doc<'_>> {
    let text = source.text.strip_prefix('\u{feff}').unwrap_or(&source.text);
    let lines = LineIndex::new(text);
    let options = roxmltree::ParsingOptions {
        allow_dtd: false,
        nodes_limit: MAX_NODES,
        ..roxmltree::ParsingOptions::default()
    };
    let doc = roxmltree::Document::parse_with_options(text, options).map_err(|e| {
        let p = e.pos();
        let pos = SourcePos::new(source.path.clone(), p.row, p.col);
        let message = pos.strip_from(&e.to_string()).to_owned();
        Error::new(ErrorKind::Xml { message }, pos)
    })?;
    Ok(Doc {
        path: source.path.clone(),
        text,
        lines,
        doc,
    })
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

/// revMinor of a document's FileHeader, read without resolution (3 when absent or odd; the
/// scenario's own header is checked by the FileHeader reader).
pub(crate) fn declared_rev_minor(doc: &Doc<'_>) -> u32 {
    let root = doc.doc.root_element();
    root.children()
        .find(|c| c.is_element() && c.tag_name().name() == "FileHeader")
        .and_then(|h| h.attribute("revMinor"))
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(3)
}

/// Reads every `.xosc` of the catalog directories, in sorted order, each file once.
pub(crate) fn read_catalog_sources(
    provider: &dyn FileProvider,
    locations: &[(String, PathBuf)],
) -> Result<Vec<Source>> {
    let mut files: Vec<PathBuf> = Vec::new();
    for (_, dir) in locations {
        let Ok(entries) = provider.list_dir(dir) else {
            continue;
        };
        let mut found: Vec<PathBuf> = entries
            .into_iter()
            .filter(|p| p.extension().is_some_and(|x| x == "xosc") && provider.is_file(p))
            .collect();
        found.sort();
        for f in found {
            if !files.contains(&f) {
                files.push(f);
            }
        }
    }
    files
        .iter()
        .map(|f| read_source(provider, f, "catalog"))
        .collect()
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
