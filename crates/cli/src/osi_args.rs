//! `oscsim run … --osi PATH`: the `--osi*` flags and what the command line adds around
//! `osi::sink::OsiSink` (the OSI mapping lives in the `osi` crate): the folder the trace goes
//! in, and `SOURCE_DATE_EPOCH` (Unix seconds, the reproducible-builds convention) as the
//! recording time. The sink's warnings go to stderr as they come, the trace's path and frame
//! count to stdout at the end.

use std::num::NonZeroU64;
use std::path::{Path, PathBuf};

use anyhow::Context;
use engine::output::Frame;
use engine::{Engine, FrameSink, SinkError};
use osi::ground_truth::StaticData;
use osi::sink::{OsiSink, OsiSinkOptions};

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

/// The OSI sink of one run, its warnings printed on stderr as they come.
pub struct Osi(OsiSink);

/// The OSI sink of `engine` for `options`, its folder made first.
pub fn create(engine: &Engine, options: &OsiOptions) -> anyhow::Result<Osi> {
    make_room(&options.path)?;
    let sink_options = OsiSinkOptions {
        path: options.path.clone(),
        host: options.host.clone(),
        static_data: match options.static_data {
            OsiStatic::First => StaticData::First,
            OsiStatic::Every => StaticData::Every,
        },
        every: options.every,
        pinned_time: source_date_epoch()?,
    };
    let mut sink = Osi(OsiSink::create(engine, &sink_options)
        .with_context(|| format!("cannot create the OSI trace {}", options.path.display()))?);
    sink.warn();
    Ok(sink)
}

impl Osi {
    /// Prints the sink's warnings since the last call on stderr.
    fn warn(&mut self) {
        for warning in self.0.take_warnings() {
            eprintln!("warning: {warning}");
        }
    }
}

impl FrameSink for Osi {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), SinkError> {
        let taken = self.0.frame(frame);
        self.warn();
        taken
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        self.0.finish()?;
        if let Some(path) = self.0.finished_path() {
            println!("OSI trace {} ({} frames)", path.display(), self.0.frames());
        }
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

/// `SOURCE_DATE_EPOCH` as Unix seconds, if set (also the recording time of
/// `oscsim batch --save osi`).
pub fn source_date_epoch() -> anyhow::Result<Option<i64>> {
    match std::env::var("SOURCE_DATE_EPOCH") {
        Ok(text) => {
            text.trim().parse().map(Some).with_context(|| {
                format!("expected Unix seconds in SOURCE_DATE_EPOCH, found '{text}'")
            })
        }
        Err(_) => Ok(None),
    }
}
