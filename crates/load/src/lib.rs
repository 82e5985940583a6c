//! The one front door of oscsim: a scenario file in either language — OpenSCENARIO XML 1.x
//! (`.xosc`) or OpenSCENARIO DSL 2.x (`.osc`, with its road network and seed) — loaded into
//! what the engine runs (`scenario::Scenario` and an `Arc<RoadNetwork>`), with one error type
//! whose [`Error::pos`] is the place in the file (`FILE:LINE:COL`). The command line, the
//! Python and C bindings, batches and the replay all load through it, and none of them needs
//! to know which language it was given.
//!
//! ```no_run
//! use std::path::Path;
//! let options = load::Options {
//!     road: Some("examples/roads/highway.xodr".into()),
//!     seed: 7,
//!     ..load::Options::default()
//! };
//! let loaded = load::load(Path::new("examples/scenarios/cut_in_highway.osc"), &options)?;
//! let mut engine = engine::Engine::new(&loaded.scenario, loaded.network, Default::default())?;
//! engine.run(&mut (), &mut ())?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! | module | job |
//! | --- | --- |
//! | `source` | a file opened once (either language), loaded for a seed: [`Source`], [`load`] |
//! | `columns` | a DSL scenario's resolved top-level parameters and constrained fields, for the results table of a batch of seeds |
//! | `sample` | a DSL scenario's `cover(…)`/`record(…)` sampled on the run's frames with the §8.7 methods |
//! | `external` | the host's functions for a DSL scenario's external methods ([`Bindings`]), checked at load and run around the engine's steps ([`Host`]) |
//! | `error` | the one error, with the place in the file |
//!
//! It sits after `dsl_runtime` and `engine` (the engine never depends on the DSL crates) and
//! before the sinks and programs (docs/architecture.md).
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod columns;
mod error;
mod external;
mod sample;
mod source;

pub use dsl_runtime::{
    Buckets, CoverItem, CoverUnit, CoverageKind, ExternalCall, PhaseInfo, SampleAt,
};
pub use error::{Error, ErrorKind};
pub use external::{Bindings, ExternalError, ExternalFn, Host, HostError};
pub use sample::{Emits, Sample, Sampler, NO_VALUE};
pub use source::{is_dsl, load, Language, Loaded, Options, Source};
