//! oscsim replay: a run shown in a browser, and charted for reports.
//!
//! A [`Run`] is what `oscsim run` wrote (trajectory CSV, event log and the run manifest
//! beside the CSV, see [`RunManifest`]) or a scenario run here ([`Run::simulate`]).
//! [`html::render`] turns it into one self-contained HTML page (road network from
//! OpenDRIVE, every entity's oriented bounding box, time slider, event timeline, charts of
//! speed and of the gaps and times the scenario's conditions measure); [`plot::plot`] draws
//! static SVG and PNG charts of it with plotters.
//!
//! ```no_run
//! use std::path::Path;
//! let run = replay::Run::simulate(
//!     Path::new("examples/scenarios/cut_in_highway.xosc"),
//!     &load::Options::default(),
//!     engine::EngineConfig::default(),
//! )?;
//! replay::html::write(&run, Path::new("out/cut_in.html"))?;
//! replay::plot::plot(&run, Path::new("out/plots"), &replay::plot::PlotOptions::default())?;
//! # Ok::<(), replay::Error>(())
//! ```
//!
//! | module | job |
//! | --- | --- |
//! | `manifest` | the run manifest `NAME.run.json` beside the CSV |
//! | `recorder` | frame and event sinks that record a run (entity catalog, in-memory CSV and log) |
//! | `scenario_info` | measured quantities, action actors and controllers from the scenario model |
//! | `trajectories`, `events` | readers of the trajectory CSV and the event log |
//! | `run` | the front door: a run opened from files or simulated here |
//! | `activity` | when each action ran for each actor |
//! | `phases` | when each phase of a DSL scenario's `do` tree ran |
//! | `measures` | the conditions' gaps and times as series, by the OpenSCENARIO 2.0 §8.7 methods |
//! | `road` | the road network as lane polygons, borders and road marks (OpenDRIVE 1.8 §9, §11) |
//! | `pack`, `page_data` | the page's compact data container |
//! | `html` | the self-contained page (`web/` holds its scripts and style) |
//! | `plot` | SVG and PNG charts |
//! | `error` | `Error`: kind, file and 1-based line:col; "expected X, found Y at file:line:col" |
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod activity;
mod error;
pub mod events;
pub mod html;
pub mod manifest;
pub mod measures;
pub mod pack;
mod page_data;
pub mod phases;
pub mod plot;
pub mod recorder;
pub mod road;
mod run;
pub mod scenario_info;
pub mod trajectories;

pub use error::{Error, ErrorKind, Result};
pub use manifest::RunManifest;
pub use run::{manifest_for, OpenOptions, Run, DEFAULT_BOX_SIZE};
