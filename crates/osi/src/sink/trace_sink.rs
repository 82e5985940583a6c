//! [`OsiSink`]: the engine's frames as an ASAM OSI 3.8 trace file — each frame's
//! GroundTruth ([`GroundTruthSink`]) offered to a [`TraceFile`] (`.osi` or `.mcap`, ASAM OSI
//! 3.8 §2.2.6.1; directory naming §2.2.6.2). `oscsim run --osi` is this sink plus its flags.
//!
//! Determinism: the trace bytes depend only on the inputs. The clock enters only where the
//! standard asks for a recording time: the `<UTC timestamp>` of the file name when the path is
//! a directory. [`OsiSinkOptions::pinned_time`] (the cli passes `SOURCE_DATE_EPOCH`) pins it,
//! and then also fills the MCAP `creation_time`, which stays unset otherwise.

use std::num::NonZeroU64;
use std::path::{Path, PathBuf};

use engine::output::Frame;
use engine::{Engine, FrameSink, SinkError};

use super::{GroundTruthSink, SinkOptions};
use crate::error::Error;
use crate::ground_truth::StaticData;
use crate::trace::{utc_extended_timestamp, McapTraceInfo, TraceFile, TraceFormat, TraceOptions};

/// The settings of an [`OsiSink`] (the cli's `--osi*` flags).
#[derive(Debug, Clone)]
pub struct OsiSinkOptions {
    /// A `.osi` / `.mcap` file, or an existing directory for a conventionally named `.osi`.
    pub path: PathBuf,
    /// The host vehicle's entity name (default [`crate::ground_truth::DEFAULT_HOST`]).
    pub host: Option<String>,
    /// In which frames lanes and lane boundaries go.
    pub static_data: StaticData,
    /// Keep every Nth frame.
    pub every: NonZeroU64,
    /// The recording time as Unix seconds, fixed for reproducible files; `None` takes the
    /// clock for the file name and leaves the MCAP `creation_time` unset.
    pub pinned_time: Option<i64>,
}

impl OsiSinkOptions {
    /// A trace at `path` as `oscsim run --osi PATH` writes it without further flags: the
    /// default host, lanes in the first frame, every frame, the recording time from the clock.
    pub fn new(path: PathBuf) -> Self {
        OsiSinkOptions {
            path,
            host: None,
            static_data: StaticData::First,
            every: NonZeroU64::MIN,
            pinned_time: None,
        }
    }
}

/// The OSI trace writer of one run (see the module doc).
pub struct OsiSink {
    sink: GroundTruthSink,
    trace: TraceFile,
    /// Where the trace went, once finished.
    finished: Option<PathBuf>,
}

impl OsiSink {
    /// Prepares the OSI trace of `engine` (its road network and scenario files), creating
    /// the trace file (the folder it goes in must exist).
    pub fn create(engine: &Engine, options: &OsiSinkOptions) -> Result<Self, Error> {
        let sink = GroundTruthSink::new(
            engine,
            &SinkOptions {
                host: options.host.clone(),
                static_data: options.static_data,
            },
        )?;
        let file = &engine.source().file;
        let start = options.pinned_time.unwrap_or_else(now_unix_seconds);
        let scenario_name = file.file_stem().map_or_else(
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
                    creation_time: options.pinned_time.map(utc_extended_timestamp),
                    description: Some(format!("oscsim ground truth of scenario {scenario_name}")),
                    data_sources: Some(file.display().to_string()),
                },
            },
        )?;
        Ok(OsiSink {
            sink,
            trace,
            finished: None,
        })
    }

    /// The warnings since the last call (an unknown host, an external object left out), for
    /// the caller to show.
    pub fn take_warnings(&mut self) -> Vec<String> {
        self.sink.take_warnings()
    }

    /// The trace's final path, once [`FrameSink::finish`] has run.
    pub fn finished_path(&self) -> Option<&Path> {
        self.finished.as_deref()
    }

    /// Frames written so far.
    pub fn frames(&self) -> u64 {
        self.trace.frames()
    }
}

impl FrameSink for OsiSink {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), SinkError> {
        let gt = self.sink.ground_truth(frame).map_err(SinkError::sink)?;
        self.trace.offer(gt).map_err(SinkError::sink)
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        let path = self.trace.finish().map_err(SinkError::sink)?;
        self.finished = Some(path);
        Ok(())
    }
}

/// The wall clock as Unix seconds (0 if the clock is before 1970).
fn now_unix_seconds() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| i64::try_from(d.as_secs()).unwrap_or(i64::MAX))
}
