//! ASAM OpenSCENARIO 1.0–1.3 (XML) scenario model for oscsim.
//!
//! [`Scenario::load`] parses a `.xosc` file (on roxmltree) into typed data: every `$name`
//! parameter and `${…}` expression resolved (OpenSCENARIO 1.3 §9.1–9.2), every catalog
//! reference replaced by its entry with the reference's parameter assignments (§9.4), entity
//! selections expanded and every entity reference checked (§7.2.2 "Entities"), deprecated
//! 1.0–1.2 forms mapped onto the 1.3 model with a [`Warning`]. Every action, condition and position
//! of 1.3 is typed data with units; model elements the runtime reports on carry a
//! [`SourcePos`]. The runtime reads only this model, never XML.
//!
//! Errors ([`Error`], kind [`ErrorKind`]) read "expected X, found Y at file:line:col".
//!
//! Hostile input is bounded: files over [`MAX_FILE_BYTES`] are refused unread, XML with a DTD
//! is refused, at most 4 million XML nodes are parsed per file, recursive elements (positions
//! within routes, trailers) nest at most 256 deep, chains of parameters referring to each
//! other at most 256 long, and catalog entries that refer to themselves are reported as
//! cycles.
//!
//! ```no_run
//! let scenario = scenario::Scenario::load(std::path::Path::new("cut-in.xosc"))?;
//! for w in &scenario.warnings {
//!     eprintln!("warning: {w}");
//! }
//! # Ok::<(), scenario::Error>(())
//! ```
//!
//! | module | job |
//! | --- | --- |
//! | `model` | the typed scenario, grouped by the standard's chapters |
//! | `reader` | XML → model, one reader per XSD element |
//! | `attr` | XSD simple types read from attribute text, and the `xsd_enum!` macro the model's enumerations are declared with |
//! | `expr` | `${…}` expressions (§9.2) |
//! | `distribution` | parameter value distributions (§9.5) |
//! | `names` | `::`-qualified storyboard element references and how they match |
//! | `init_order` | the order in which the Init's private actions take effect: positions and speeds relative to other entities after those entities' own ([`init_order()`]) |
//! | `provider` | where files come from: [`DiskFiles`], [`MemoryFiles`], or your [`FileProvider`]; the [`Sources`] a scenario keeps |
//! | `traffic_deal` | oscsim's rule dealing random traffic over the free stretches of the driving lanes, shared by the DSL plan and the engine |
//! | `source`, `error`, `warning` | positions, errors and warnings |
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod attr;
pub mod distribution;
mod error;
pub mod expr;
mod init_order;
mod model;
pub mod names;
mod provider;
mod reader;
mod source;
pub mod traffic_deal;
mod warning;

use std::path::Path;

pub use error::{Error, ErrorKind, Result};
pub use init_order::{init_order, InitStep};
pub use model::*;
pub use provider::{DiskFiles, FileProvider, MemoryFiles, Sources};
pub use reader::files::MAX_FILE_BYTES;
pub use source::SourcePos;
pub use warning::Warning;

impl Scenario {
    /// Loads the scenario at `path` with its catalogs, checking that its road network file
    /// exists. A ParameterValueDistribution file loads its ScenarioFile.
    pub fn load(path: &Path) -> Result<Scenario> {
        Scenario::load_with_files(&DiskFiles, path, &[])
    }

    /// As [`Scenario::load`], with global parameters overridden by (name, value) pairs (the
    /// values are parsed as the declared types; an undeclared name is an error).
    pub fn load_with_parameters(path: &Path, overrides: &[(String, String)]) -> Result<Scenario> {
        Scenario::load_with_files(&DiskFiles, path, overrides)
    }

    /// As [`Scenario::load_with_parameters`], reading the scenario, its catalogs and the
    /// scenario a ParameterValueDistribution names from `files`, where the road network's
    /// LogicFile must exist too (e.g. a [`MemoryFiles`], so nothing touches the disk).
    pub fn load_with_files(
        files: &dyn FileProvider,
        path: &Path,
        overrides: &[(String, String)],
    ) -> Result<Scenario> {
        let recording = provider::Recording::new(files);
        let scenario = reader::scenario::load(&recording, path, overrides)?.checked()?;
        Ok(scenario.keeping(recording, path, overrides.to_vec()))
    }

    /// Loads scenario `text` as if it had been read from `path`: positions name `path` and
    /// relative paths in the scenario (road network, catalogs) resolve against its directory.
    /// For tests and tools that build scenarios in memory.
    pub fn load_from_str(
        text: &str,
        path: &Path,
        overrides: &[(String, String)],
    ) -> Result<Scenario> {
        let recording = provider::Recording::new(&DiskFiles);
        recording.keep(path, text);
        let scenario = reader::scenario::load_text(&recording, text, path, overrides)?.checked()?;
        Ok(scenario.keeping(recording, path, overrides.to_vec()))
    }

    /// This scenario with global parameters overridden by (name, value) pairs on top of the
    /// overrides it was loaded with (OpenSCENARIO 1.3 §9.1; a name given again takes the new
    /// value): the same files, kept in memory at the first load ([`Sources`]), read and
    /// resolved again, so a batch of variants costs one parse and resolution each. Only a file
    /// the first load never saw — a road network or catalog directory that these parameter
    /// values name and the first ones did not — is looked for on the disk, each variant
    /// resolving its own files from its own values.
    ///
    /// ```no_run
    /// # use std::path::Path;
    /// let base = scenario::Scenario::load(Path::new("cut-in.xosc"))?;
    /// for speed in [20, 25, 30] {
    ///     let variant = base.with_parameters(&[("EgoSpeed".into(), speed.to_string())])?;
    ///     assert_eq!(variant.sources.overrides(), [("EgoSpeed".to_owned(), speed.to_string())]);
    /// }
    /// # Ok::<(), scenario::Error>(())
    /// ```
    pub fn with_parameters(&self, overrides: &[(String, String)]) -> Result<Scenario> {
        let merged = self.sources.merged(overrides);
        let files = provider::Overlay {
            kept: &self.sources.files,
            more: &DiskFiles,
        };
        let mut scenario =
            reader::scenario::load(&files, &self.sources.opened, &merged)?.checked()?;
        scenario.sources = Sources {
            opened: self.sources.opened.clone(),
            files: self.sources.files.clone(),
            overrides: merged,
        };
        Ok(scenario)
    }

    /// The checks of the model as a whole, after reading: the Init's actions can be resolved
    /// in some order ([`init_order()`]).
    fn checked(self) -> Result<Scenario> {
        init_order(&self.storyboard.init)?;
        Ok(self)
    }

    /// Keeps what `recording` saw as this scenario's [`Sources`].
    fn keeping(
        mut self,
        recording: provider::Recording<'_>,
        opened: &Path,
        overrides: Vec<(String, String)>,
    ) -> Scenario {
        self.sources = Sources {
            opened: opened.to_path_buf(),
            files: std::sync::Arc::new(recording.into_memory()),
            overrides,
        };
        self
    }
}
