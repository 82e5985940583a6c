//! Per-variant outputs (`oscsim batch --save csv,events,osi`): a variant's trajectory CSV,
//! event log and ASAM OSI 3.8 ground-truth trace in `DIR/variants/NNNNN/`, each in the format
//! `oscsim run` writes with `--csv`, `--events` and `--osi`: `trajectories.csv`,
//! `events.jsonl`, and the trace as `--osi DIR` names it (the OSI trace file naming
//! convention, ASAM OSI 3.8 §2.2.6.2: `<UTC time>_gt_<OSI version>_<protobuf version>_<frames>_
//! <scenario>.osi`), written by the osi crate's [`OsiSink`] with the batch's host as the host
//! vehicle and the recording time the caller pins (`SOURCE_DATE_EPOCH` in the cli), so a
//! variant's trace is byte for byte that of `oscsim run SCENARIO --param … --osi DIR`.
//!
//! A variant's files are written into `variants/NNNNN.partial/` ([`staging_dir`]) and the
//! folder is renamed to `variants/NNNNN/` when the run ends ([`commit`]), before the variant's
//! row goes to the journal (journal.rs): a batch killed half-way leaves only whole folders
//! under their final names (a `.partial` folder is cleared when its variant runs again). A
//! variant that timed out or panicked keeps no folder (guard.rs); one whose run failed keeps
//! what it wrote up to the failure, as `oscsim run` does.

use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use engine::output::{CsvWriter, JsonlWriter};
use engine::Engine;
use osi::sink::{OsiSink, OsiSinkOptions};

/// Which per-variant outputs to keep in `DIR/variants/NNNNN/`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Save {
    /// `trajectories.csv` (the `oscsim run --csv` layout).
    pub csv: bool,
    /// `events.jsonl` (the `oscsim run --events` layout).
    pub events: bool,
    /// The OSI GroundTruth trace (`oscsim run --osi DIR`: a conventionally named `.osi`).
    pub osi: bool,
}

impl Save {
    /// The outputs named by `kinds` (`csv`, `events`, `osi`; repeats allowed); `Err` names the
    /// first other word ("expected csv, events or osi, found '…'").
    pub fn from_kinds<S: AsRef<str>>(kinds: &[S]) -> Result<Save, String> {
        let mut save = Save::default();
        for kind in kinds {
            match kind.as_ref() {
                "csv" => save.csv = true,
                "events" => save.events = true,
                "osi" => save.osi = true,
                other => return Err(format!("expected csv, events or osi, found '{other}'")),
            }
        }
        Ok(save)
    }

    /// Whether any output is kept.
    pub fn any(&self) -> bool {
        *self != Save::default()
    }
}

/// The folder of variant `v`'s outputs.
pub fn variant_dir(root: &Path, v: u64) -> PathBuf {
    root.join("variants").join(format!("{v:05}"))
}

/// The folder variant `v`'s outputs are written in while it runs (module doc).
pub(crate) fn staging_dir(root: &Path, v: u64) -> PathBuf {
    root.join("variants").join(format!("{v:05}.partial"))
}

/// Removes variant `v`'s staging folder, if there is one: what a killed run, a timeout or a
/// panic left.
pub(crate) fn discard(root: &Path, v: u64) -> Result<(), String> {
    let dir = staging_dir(root, v);
    match std::fs::remove_dir_all(&dir) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
            Err(format!("cannot remove {}: {e}", dir.display()))
        }
        _ => Ok(()),
    }
}

/// Renames variant `v`'s staging folder to its final name, replacing a folder of an earlier,
/// killed run that had renamed its own but not recorded its row (module doc).
pub(crate) fn commit(root: &Path, v: u64) -> Result<(), String> {
    let (from, to) = (staging_dir(root, v), variant_dir(root, v));
    if !from.is_dir() {
        return Ok(());
    }
    if to.exists() {
        std::fs::remove_dir_all(&to).map_err(|e| format!("cannot remove {}: {e}", to.display()))?;
    }
    std::fs::rename(&from, &to)
        .map_err(|e| format!("cannot rename {} to {}: {e}", from.display(), to.display()))
}

/// The open per-variant outputs of one variant.
#[derive(Default)]
pub(crate) struct Outputs {
    /// `trajectories.csv`.
    pub(crate) trajectories: Option<CsvWriter<BufWriter<File>>>,
    /// `events.jsonl`.
    pub(crate) events: Option<JsonlWriter<BufWriter<File>>>,
    /// The OSI trace.
    pub(crate) osi: Option<OsiSink>,
}

impl Outputs {
    /// Creates the outputs `save` asks for in `dir` for the run of `engine`; `host` is the
    /// OSI host vehicle, `recording_time` the trace's pinned recording time (Unix seconds).
    pub(crate) fn create(
        save: Save,
        dir: &Path,
        engine: &Engine,
        host: &str,
        recording_time: Option<i64>,
    ) -> Result<Outputs, String> {
        let mut outputs = Outputs::default();
        if save.csv {
            outputs.trajectories = Some(CsvWriter::new(create(&dir.join("trajectories.csv"))?));
        }
        if save.events {
            outputs.events = Some(JsonlWriter::new(create(&dir.join("events.jsonl"))?));
        }
        if save.osi {
            std::fs::create_dir_all(dir)
                .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
            let options = OsiSinkOptions {
                host: Some(host.to_owned()),
                pinned_time: recording_time,
                ..OsiSinkOptions::new(dir.to_path_buf())
            };
            let sink = OsiSink::create(engine, &options)
                .map_err(|e| format!("cannot create the OSI trace in {}: {e}", dir.display()))?;
            outputs.osi = Some(sink);
        }
        Ok(outputs)
    }
}

/// Creates the file `path` (and its folder).
fn create(path: &Path) -> Result<BufWriter<File>, String> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    }
    File::create(path)
        .map(BufWriter::new)
        .map_err(|e| format!("cannot create {}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::Save;

    #[test]
    fn kinds_name_the_outputs_and_other_words_are_errors() {
        let save = Save::from_kinds(&["osi", "csv", "osi"]).expect("known kinds");
        assert_eq!(
            save,
            Save {
                csv: true,
                events: false,
                osi: true
            }
        );
        assert!(save.any() && !Save::from_kinds::<&str>(&[]).expect("none").any());
        assert_eq!(
            Save::from_kinds(&["csv", "mcap"]),
            Err("expected csv, events or osi, found 'mcap'".to_owned())
        );
    }
}
