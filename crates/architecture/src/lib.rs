//! The written map of the workspace checked against the code: `docs/architecture.md`'s crate
//! table and dependency rules against every `Cargo.toml`, each crate's module table against
//! its real top-level modules, and the `use` graph between the modules of each folder (the
//! crate root and every module that declares modules), for cycles.
//!
//! The checks themselves are the test `tests/architecture.rs` (part of
//! `cargo test --workspace`); this library only reads: manifests, sources and Markdown
//! tables. It reads the sources as tokens (`proc-macro2`), not with a regular expression, so
//! comments, strings and doc text never count as a use.
//!
//! | module | job |
//! | --- | --- |
//! | `manifest` | the workspace's members and each crate's dependencies from its `Cargo.toml` |
//! | `modules` | a crate's module tree and, in each folder (the root and every module that declares modules), which of its modules use each other (`crate::`, `super::`, `self::`, re-exports) |
//! | `graph` | cycles of a module graph: strongly connected components and two-way pairs |
//! | `tables` | Markdown tables in a document or a crate's `//!` doc, and the module names a table lists |
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod graph;
mod manifest;
mod modules;
mod tables;

pub use graph::{cycles, Cycle};
pub use manifest::{Dependency, DependencyKind, Manifest, Workspace};
pub use modules::{crate_modules, module_folders, CrateModules};
pub use tables::{backticked, crate_doc, markdown_tables, module_paths, Table};
