//! `oscsim run … --osi PATH`: writes the GroundTruth that `osi::sink::GroundTruthSink` makes
//! of each engine frame (the mapping, OpenSCENARIO 1.3 §7.2 onto ASAM OSI 3.8.0, is documented
//! there) to an `osi::trace::TraceFile` (`.osi` or `.mcap`, ASAM OSI 3.8 §2.2.6.1; directory
//! naming §2.2.6.2), and prints the sink's warnings on stderr.
//!
//! The OSI sink reads pedestrian and misc-object categories from the scenario model the
//! engine was built from.
//!
//! Determinism: the trace bytes depend only on the inputs. The clock enters only where the
//! standard asks for a recording time: the `<UTC timestamp>` of the file name when PATH is a
//! directory. `SOURCE_DATE_EPOCH` (Unix seconds, the reproducible-builds convention) pins
//! it, and then also fills the MCAP `creation_time`, which stays unset otherwise.

use std::num::NonZeroU64;
use std::path::{Path, PathBuf};

use anyhow::Context;
use engine::output::Frame;
use engine::{Engine, FrameSink};
use osi::ground_truth::StaticData;
use osi::sink::{GroundTruthSink, SinkOptions};
use osi::trace::{utc_basic_timestamp, McapTraceInfo, TraceFile, TraceFormat, TraceOptions};
use scenario::Scenario;

/// In which frames lanes and lane boundaries go (`--osi-static`).
#[derive(clap::ValueEnum, Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OsiStatic {
    /// Only in the first frame.
    #[default]
    First,
    /// In every frame.
    Every,
}

/// The `--osi*` settings of `oscsim run`.
#[derive(Debug, Clone)]
pub struct OsiOptions {
    /// `--osi PATH`: a `.osi` / `.mcap` file, or a directory for a conventionally named `.osi`.
    pub path: PathBuf,
    /// `--osi-host NAME`: the host vehicle (default `Ego`).
    pub host: Option<String>,
    /// `--osi-static`.
    pub static_data: OsiStatic,
    /// `--osi-every N`: keep every Nth step.
    pub every: NonZeroU64,
}

/// The OSI writer of one run (see the module doc).
pub struct OsiSink {
    sink: GroundTruthSink,
    trace: TraceFile,
}

impl OsiSink {
    /// Prepares the OSI output of `engine`, built from `scenario` (read from `scenario_path`).
    pub fn create(
        engine: &Engine,
        scenario: &Scenario,
        scenario_path: &Path,
        options: &OsiOptions,
    ) -> anyhow::Result<Self> {
        let sink_options = SinkOptions {
            host: options.host.clone(),
            static_data: match options.static_data {
                OsiStatic::First => StaticData::First,
                OsiStatic::Every => StaticData::Every,
            },
            scenario_file: Some(scenario_path.display().to_string()),
        };
        let mut sink = GroundTruthSink::new(scenario, engine.road_network(), &sink_options)
            .context("cannot build the OSI lanes of the road network")?;
        for warning in sink.take_warnings() {
            eprintln!("warning: {warning}");
        }
        make_room(&options.path)?;
        let pinned = source_date_epoch()?;
        let start = pinned.unwrap_or_else(now_unix_seconds);
        let scenario_name = scenario_path.file_stem().map_or_else(
            || "scenario".to_owned(),
            |s| s.to_string_lossy().into_owned(),
        );
        let trace = TraceFile::create(
            &options.path,
            TraceOptions {
                scenario_name: scenario_name.clone(),
                directory_format: TraceFormat::Osi,
                every: options.every,
                start_unix_seconds: start,
                mcap_info: McapTraceInfo {
                    creation_time: pinned.map(iso8601),
                    description: Some(format!("oscsim ground truth of scenario {scenario_name}")),
                    data_sources: Some(scenario_path.display().to_string()),
                },
            },
        )
        .with_context(|| format!("cannot create the OSI trace {}", options.path.display()))?;
        Ok(OsiSink { sink, trace })
    }
}

impl FrameSink for OsiSink {
    fn frame(&mut self, frame: &Frame<'_>) -> std::io::Result<()> {
        let gt = self.sink.ground_truth(frame).map_err(std::io::Error::other);
        for warning in self.sink.take_warnings() {
            eprintln!("warning: {warning}");
        }
        self.trace.offer(&gt?).map_err(std::io::Error::other)
    }

    fn finish(&mut self) -> std::io::Result<()> {
        let path = self.trace.finish().map_err(std::io::Error::other)?;
        println!(
            "OSI trace {} ({} frames)",
            path.display(),
            self.trace.frames()
        );
        Ok(())
    }
}

/// Creates the folder `path` names when it ends in a separator (directory mode), else the
/// folder the trace file goes in.
fn make_room(path: &Path) -> anyhow::Result<()> {
    let as_dir = path
        .as_os_str()
        .to_string_lossy()
        .ends_with(std::path::MAIN_SEPARATOR);
    let dir = if as_dir { Some(path) } else { path.parent() };
    match dir.filter(|d| !d.as_os_str().is_empty()) {
        Some(d) => std::fs::create_dir_all(d)
            .with_context(|| format!("cannot create folder {}", d.display())),
        None => Ok(()),
    }
}

/// `SOURCE_DATE_EPOCH` as Unix seconds, if set.
fn source_date_epoch() -> anyhow::Result<Option<i64>> {
    match std::env::var("SOURCE_DATE_EPOCH") {
        Ok(text) => {
            text.trim().parse().map(Some).with_context(|| {
                format!("expected Unix seconds in SOURCE_DATE_EPOCH, found '{text}'")
            })
        }
        Err(_) => Ok(None),
    }
}

/// The wall clock as Unix seconds (0 if the clock is before 1970).
fn now_unix_seconds() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| i64::try_from(d.as_secs()).unwrap_or(i64::MAX))
}

/// ISO 8601 extended UTC time (`2026-11-21T05:00:00Z`) for the MCAP `creation_time`.
fn iso8601(unix_seconds: i64) -> String {
    // `utc_basic_timestamp` gives YYYYMMDDTHHMMSSZ (ASCII; four-digit years up to 9999).
    let b = utc_basic_timestamp(unix_seconds);
    if b.len() != 16 {
        return b;
    }
    format!(
        "{}-{}-{}T{}:{}:{}Z",
        &b[0..4],
        &b[4..6],
        &b[6..8],
        &b[9..11],
        &b[11..13],
        &b[13..15]
    )
}
