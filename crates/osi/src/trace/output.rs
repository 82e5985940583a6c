//! The trace behind `oscsim run … --osi PATH [--osi-every N]`: picks the format from the
//! extension (`.mcap`, else `.osi`), names the file by the OSI convention
//! (ASAM OSI 3.8 §2.2.6.2) when `PATH` is a directory, and keeps every Nth frame.
//!
//! In the directory case the frame count, part of the name, is known only at the end, so
//! the trace is written to a hidden part file in that directory and renamed by
//! [`TraceFile::finish`].

use std::num::NonZeroU64;
use std::path::{Path, PathBuf};

use crate::error::{Error, ErrorKind};
use crate::osi3::GroundTruth;
use crate::trace::file_name::trace_file_name;
use crate::trace::mcap_file::{McapTraceInfo, McapTraceWriter};
use crate::trace::osi_file::OsiFileWriter;
use crate::trace::writer::TraceWriter;
use crate::version::{OSI_VERSION, PROTOBUF_VERSION};

/// Trace container format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TraceFormat {
    /// Length-prefixed binary `.osi`.
    Osi,
    /// OSI multi-channel `.mcap`.
    Mcap,
}

impl TraceFormat {
    /// File extension without the dot.
    pub fn extension(self) -> &'static str {
        match self {
            TraceFormat::Osi => "osi",
            TraceFormat::Mcap => "mcap",
        }
    }

    /// The format a path's extension names: `.mcap` is MCAP, anything else `.osi`.
    pub fn from_path(path: &Path) -> Self {
        match path.extension().and_then(|e| e.to_str()) {
            Some(e) if e.eq_ignore_ascii_case("mcap") => TraceFormat::Mcap,
            _ => TraceFormat::Osi,
        }
    }
}

/// Settings of a [`TraceFile`].
#[derive(Debug, Clone)]
pub struct TraceOptions {
    /// Custom trace name of the convention (the scenario's name).
    pub scenario_name: String,
    /// Format when the path is a directory.
    pub directory_format: TraceFormat,
    /// Keep frames 0, N, 2N, … of those offered.
    pub every: NonZeroU64,
    /// Recording start as Unix seconds (UTC), for the convention's timestamp.
    pub start_unix_seconds: i64,
    /// MCAP metadata besides the versions.
    pub mcap_info: McapTraceInfo,
}

/// A trace file being written (see the module doc). Call [`TraceFile::finish`] at the
/// end: a trace dropped unfinished keeps its part-file name in the directory case.
pub struct TraceFile {
    writer: Box<dyn TraceWriter>,
    /// Where the bytes go now.
    path: PathBuf,
    /// `Some((directory, format))` when the final name is made at the end.
    rename_into: Option<(PathBuf, TraceFormat)>,
    options: TraceOptions,
    offered: u64,
    final_path: Option<PathBuf>,
}

impl TraceFile {
    /// Creates the trace at `path`, a file or an existing directory.
    pub fn create(path: &Path, options: TraceOptions) -> Result<Self, Error> {
        let (file, format, rename_into) = if path.is_dir() {
            let format = options.directory_format;
            let part = path.join(format!(
                ".oscsim-{}-{}.{}.part",
                std::process::id(),
                options.start_unix_seconds,
                format.extension()
            ));
            (part, format, Some((path.to_path_buf(), format)))
        } else {
            (path.to_path_buf(), TraceFormat::from_path(path), None)
        };
        let writer: Box<dyn TraceWriter> = match format {
            TraceFormat::Osi => Box::new(OsiFileWriter::create(&file)?),
            TraceFormat::Mcap => Box::new(McapTraceWriter::create(&file, &options.mcap_info)?),
        };
        Ok(TraceFile {
            writer,
            path: file,
            rename_into,
            options,
            offered: 0,
            final_path: None,
        })
    }

    /// Offers one step's GroundTruth; it is written if its index is a multiple of N.
    pub fn offer(&mut self, ground_truth: &GroundTruth) -> Result<(), Error> {
        let keep = self.offered % self.options.every.get() == 0;
        self.offered += 1;
        if keep {
            self.writer.write(ground_truth)?;
        }
        Ok(())
    }

    /// Frames written so far.
    pub fn frames(&self) -> u64 {
        self.writer.frames()
    }

    /// Finishes the trace and returns its final path.
    pub fn finish(&mut self) -> Result<PathBuf, Error> {
        if let Some(done) = &self.final_path {
            return Ok(done.clone());
        }
        self.writer.finish()?;
        let done = match &self.rename_into {
            None => self.path.clone(),
            Some((dir, format)) => {
                let name = trace_file_name(
                    self.options.start_unix_seconds,
                    OSI_VERSION,
                    PROTOBUF_VERSION,
                    self.writer.frames(),
                    &self.options.scenario_name,
                    format.extension(),
                );
                let target = dir.join(name);
                std::fs::rename(&self.path, &target)
                    .map_err(|e| Error::in_file(ErrorKind::Io(e), &target))?;
                target
            }
        };
        self.final_path = Some(done.clone());
        Ok(done)
    }
}
