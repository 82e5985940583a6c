//! Where the loader gets its files: the scenario, the catalog directories' `.xosc` files, and
//! the existence checks of the files a scenario names (`RoadNetwork/LogicFile`,
//! `ParameterValueDistribution/ScenarioFile`; OpenSCENARIO 1.3 §9.4 "catalogs" and §9.5).
//!
//! [`DiskFiles`] reads the file system (what [`Scenario::load`](crate::Scenario::load) uses);
//! [`MemoryFiles`] holds files in memory, for tools, tests and fuzzing that load a scenario
//! with its catalogs without touching the disk
//! ([`Scenario::load_with_files`](crate::Scenario::load_with_files)). Paths reach a provider
//! as the loader resolved them: relative paths written in a file are joined to its directory
//! and `..` steps folded as text, so `xosc/../Catalogs/V` arrives as `Catalogs/V`.

use std::cell::RefCell;
use std::collections::{BTreeMap, BTreeSet};
use std::io;
use std::path::{Path, PathBuf};

/// A source of files for the scenario loader.
pub trait FileProvider {
    /// Size of the file at `path` in bytes (checked against
    /// [`MAX_FILE_BYTES`](crate::MAX_FILE_BYTES) before reading).
    fn size(&self, path: &Path) -> io::Result<u64>;
    /// The bytes of the file at `path`.
    fn read(&self, path: &Path) -> io::Result<Vec<u8>>;
    /// Whether `path` names a file.
    fn is_file(&self, path: &Path) -> bool;
    /// Whether `path` names a directory.
    fn is_dir(&self, path: &Path) -> bool;
    /// The paths of the entries directly in directory `dir`, in any order.
    fn list_dir(&self, dir: &Path) -> io::Result<Vec<PathBuf>>;
}

/// The file system.
#[derive(Debug, Clone, Copy, Default)]
pub struct DiskFiles;

impl FileProvider for DiskFiles {
    fn size(&self, path: &Path) -> io::Result<u64> {
        Ok(std::fs::metadata(path)?.len())
    }

    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        std::fs::read(path)
    }

    fn is_file(&self, path: &Path) -> bool {
        path.is_file()
    }

    fn is_dir(&self, path: &Path) -> bool {
        path.is_dir()
    }

    fn list_dir(&self, dir: &Path) -> io::Result<Vec<PathBuf>> {
        std::fs::read_dir(dir)?
            .map(|e| e.map(|e| e.path()))
            .collect()
    }
}

/// Files held in memory, keyed by path. A directory exists when some file lies under it, or
/// when it was added with [`MemoryFiles::insert_dir`].
///
/// ```
/// use scenario::{MemoryFiles, FileProvider};
/// use std::path::Path;
/// let mut files = MemoryFiles::new();
/// files.insert("s/Catalogs/Vehicles/cars.xosc", "<OpenSCENARIO/>");
/// assert!(files.is_dir(Path::new("s/Catalogs")));
/// assert!(files.is_file(Path::new("s/Catalogs/Vehicles/cars.xosc")));
/// let held: Vec<_> = files.iter().collect();
/// assert_eq!(held, [(Path::new("s/Catalogs/Vehicles/cars.xosc"), &b"<OpenSCENARIO/>"[..])]);
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MemoryFiles {
    files: BTreeMap<PathBuf, Vec<u8>>,
    dirs: BTreeSet<PathBuf>,
}

impl MemoryFiles {
    /// No files.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds (or replaces) the file at `path`.
    pub fn insert(&mut self, path: impl Into<PathBuf>, contents: impl Into<Vec<u8>>) -> &mut Self {
        self.files.insert(path.into(), contents.into());
        self
    }

    /// Adds the directory `path`, which then exists even with no file under it.
    pub fn insert_dir(&mut self, path: impl Into<PathBuf>) -> &mut Self {
        self.dirs.insert(path.into());
        self
    }

    /// The contents of the file at `path`, if there is one.
    pub fn get(&self, path: &Path) -> Option<&[u8]> {
        self.files.get(path).map(Vec::as_slice)
    }

    /// Every file held, with its contents, in path order.
    pub fn iter(&self) -> impl Iterator<Item = (&Path, &[u8])> {
        self.files.iter().map(|(p, b)| (p.as_path(), b.as_slice()))
    }

    fn not_found(path: &Path) -> io::Error {
        io::Error::new(
            io::ErrorKind::NotFound,
            format!("no file {} in memory", path.display()),
        )
    }
}

impl FileProvider for MemoryFiles {
    fn size(&self, path: &Path) -> io::Result<u64> {
        self.get(path)
            .map(|b| b.len() as u64)
            .ok_or_else(|| Self::not_found(path))
    }

    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        self.get(path)
            .map(<[u8]>::to_vec)
            .ok_or_else(|| Self::not_found(path))
    }

    fn is_file(&self, path: &Path) -> bool {
        self.files.contains_key(path)
    }

    fn is_dir(&self, path: &Path) -> bool {
        self.dirs.contains(path)
            || self
                .files
                .keys()
                .any(|f| f.starts_with(path) && f.as_path() != path)
    }

    fn list_dir(&self, dir: &Path) -> io::Result<Vec<PathBuf>> {
        if !self.is_dir(dir) {
            return Err(Self::not_found(dir));
        }
        let mut out: Vec<PathBuf> = Vec::new();
        for f in self.files.keys().filter(|f| f.starts_with(dir)) {
            // The first component below `dir`: a file, or a subdirectory listed once.
            let rest = f.strip_prefix(dir).unwrap_or(f);
            if let Some(first) = rest.components().next() {
                let entry = dir.join(first);
                if out.last() != Some(&entry) {
                    out.push(entry);
                }
            }
        }
        Ok(out)
    }
}

/// The files a scenario was loaded from, kept in memory with the parameter overrides it was
/// loaded with, so that [`Scenario::with_parameters`](crate::Scenario::with_parameters) loads
/// it again with other values without reading a file. Shared (an `Arc`) by every scenario
/// derived from the same load.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Sources {
    /// The path the scenario (or its ParameterValueDistribution) was opened at.
    pub(crate) opened: PathBuf,
    pub(crate) files: std::sync::Arc<MemoryFiles>,
    pub(crate) overrides: Vec<(String, String)>,
}

impl Sources {
    /// The files as the loader read them: the scenario, its catalog files (and, for a
    /// ParameterValueDistribution, the scenario it names); the road network only as an
    /// (empty) entry that exists, since the scenario loader does not read it.
    pub fn files(&self) -> &MemoryFiles {
        &self.files
    }

    /// The path the scenario was opened at, as given to the loader (for a
    /// ParameterValueDistribution, the distribution file); empty for a scenario not loaded
    /// from files (built in memory, e.g. lowered from the DSL).
    pub fn opened(&self) -> &Path {
        &self.opened
    }

    /// The global parameter overrides the scenario was loaded with, in order.
    pub fn overrides(&self) -> &[(String, String)] {
        &self.overrides
    }

    /// The overrides of this load with `more` applied on top (a name given again takes the
    /// new value).
    pub(crate) fn merged(&self, more: &[(String, String)]) -> Vec<(String, String)> {
        let mut out = self.overrides.clone();
        for (name, value) in more {
            match out.iter_mut().find(|(n, _)| n == name) {
                Some(slot) => slot.1.clone_from(value),
                None => out.push((name.clone(), value.clone())),
            }
        }
        out
    }
}

/// The files kept at a first load, then `more` for what they do not hold: what a variant
/// reads when its own parameter values name a file the first load never saw (a road network
/// or catalog directory chosen by a parameter, OpenSCENARIO 1.3 §9.1).
pub(crate) struct Overlay<'a> {
    pub(crate) kept: &'a MemoryFiles,
    pub(crate) more: &'a dyn FileProvider,
}

impl FileProvider for Overlay<'_> {
    fn size(&self, path: &Path) -> io::Result<u64> {
        self.kept.size(path).or_else(|_| self.more.size(path))
    }

    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        self.kept.read(path).or_else(|_| self.more.read(path))
    }

    fn is_file(&self, path: &Path) -> bool {
        self.kept.is_file(path) || self.more.is_file(path)
    }

    fn is_dir(&self, path: &Path) -> bool {
        self.kept.is_dir(path) || self.more.is_dir(path)
    }

    fn list_dir(&self, dir: &Path) -> io::Result<Vec<PathBuf>> {
        // A directory the first load listed keeps that listing (its files were all read).
        if self.kept.is_dir(dir) {
            self.kept.list_dir(dir)
        } else {
            self.more.list_dir(dir)
        }
    }
}

/// A provider that answers from `inner` and keeps what it answered: the bytes of every file
/// read, the files and directories found to exist. [`Recording::into_memory`] then gives a
/// [`MemoryFiles`] that answers the loader's questions as `inner` did, so that the same
/// scenario loads again without `inner` (OpenSCENARIO 1.3 §9.1: other parameter values,
/// [`Scenario::with_parameters`](crate::Scenario::with_parameters)).
pub(crate) struct Recording<'a> {
    inner: &'a dyn FileProvider,
    kept: RefCell<MemoryFiles>,
}

impl<'a> Recording<'a> {
    pub(crate) fn new(inner: &'a dyn FileProvider) -> Self {
        Recording {
            inner,
            kept: RefCell::new(MemoryFiles::new()),
        }
    }

    /// Keeps `text` as the file at `path` (a scenario given as text).
    pub(crate) fn keep(&self, path: &Path, text: &str) {
        self.kept.borrow_mut().insert(path, text.as_bytes());
    }

    pub(crate) fn into_memory(self) -> MemoryFiles {
        self.kept.into_inner()
    }
}

impl FileProvider for Recording<'_> {
    fn size(&self, path: &Path) -> io::Result<u64> {
        self.inner.size(path)
    }

    fn read(&self, path: &Path) -> io::Result<Vec<u8>> {
        let bytes = self.inner.read(path)?;
        self.kept.borrow_mut().insert(path, bytes.clone());
        Ok(bytes)
    }

    fn is_file(&self, path: &Path) -> bool {
        let found = self.inner.is_file(path);
        let mut kept = self.kept.borrow_mut();
        // A file only checked to exist (the road network) is kept empty; one read later
        // replaces it with its bytes.
        if found && kept.get(path).is_none() {
            kept.insert(path, Vec::new());
        }
        found
    }

    fn is_dir(&self, path: &Path) -> bool {
        let found = self.inner.is_dir(path);
        if found {
            self.kept.borrow_mut().insert_dir(path);
        }
        found
    }

    fn list_dir(&self, dir: &Path) -> io::Result<Vec<PathBuf>> {
        let entries = self.inner.list_dir(dir)?;
        self.kept.borrow_mut().insert_dir(dir);
        Ok(entries)
    }
}

#[cfg(test)]
mod tests {
    use super::{FileProvider, MemoryFiles};
    use std::path::{Path, PathBuf};

    #[test]
    fn memory_directories_list_files_and_subdirectories_once() {
        let mut m = MemoryFiles::new();
        m.insert("c/V/a.xosc", "a")
            .insert("c/V/b.xosc", "bb")
            .insert("c/V/sub/x.xosc", "x")
            .insert("c/V/sub/y.xosc", "y");
        let listed = m.list_dir(Path::new("c/V")).unwrap();
        let expected: Vec<PathBuf> = ["c/V/a.xosc", "c/V/b.xosc", "c/V/sub"]
            .iter()
            .map(PathBuf::from)
            .collect();
        assert_eq!(listed, expected);
        assert!(m.is_dir(Path::new("c/V/sub")));
        assert!(!m.is_file(Path::new("c/V/sub")));
        assert!(!m.is_dir(Path::new("c/V/a.xosc")));
        assert_eq!(m.size(Path::new("c/V/b.xosc")).unwrap(), 2);
        assert!(m.list_dir(Path::new("c/W")).is_err());
        assert!(m.read(Path::new("c/V/none.xosc")).is_err());
    }
}
