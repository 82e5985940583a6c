//! What identifies a sweep, so that an output folder never mixes the rows of two: a SHA-256
//! digest of everything that decides a variant's row and saved files, the selection of
//! variants this process runs, and the table's columns. It is the journal's header record
//! (journal.rs, resume.rs).
//!
//! The digest covers, each as a length-prefixed field in this order:
//! - the oscsim version and this format's name;
//! - the distribution file's bytes;
//! - the ScenarioFile, its catalog files and its road network: each file's name (not its
//!   folder, so a sweep moved to another folder or run from another working directory is the
//!   same sweep) and bytes, sorted by name and then bytes;
//! - the options that change a row or a saved file: seed, dt, duration, max time, traffic and
//!   vehicle models, stopping at red lights, the host, which outputs are saved, and the OSI
//!   recording time when traces are saved;
//! - a batch of seeds (plan.rs): the files of the DSL program (the scenario, the files it
//!   imports and the standard library's, among the files above, by name and text), the
//!   scenario that runs (`--scenario`) and every seed in variant order. Variant i is seed i of
//!   the list, so `--seeds 1..100` and `--seeds 2..101` are two sweeps although both have 100
//!   variants. A distribution's digest has none of these fields, so its journals stay valid.
//!
//! Left out on purpose: the number of jobs and the order variants finish in (the table is the
//! same for any), and `--variant-timeout`, which only decides whether a slow variant gives its
//! row or a timeout (guard.rs): a sweep resumed with a longer limit is the same sweep; the
//! rows already in its journal stand.
//!
//! The selection (`shard I/N`, and `only V`) is kept beside the digest, not in it: shards of
//! one sweep share the digest, which `oscsim batch merge` checks.

use std::fmt::Write as _;
use std::path::Path;

use sha2::{Digest, Sha256};

use crate::error::Error;
use crate::journal::{self, JOURNAL_FILE};
use crate::plan::Plan;
use crate::run::{selected, Options};
use crate::table::Table;

/// The identity of a sweep's run into one folder (module doc).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Sweep {
    /// SHA-256 of the inputs and options, lowercase hex.
    pub digest: String,
    /// This process's share: `shard I/N`, with `, only V` for `--only`.
    pub selection: String,
    /// How many variants the selection holds.
    pub variants: usize,
    /// The results table's header line.
    pub columns: String,
}

/// The first line of a journal's header record.
const TITLE: &str = "oscsim batch journal";

impl Sweep {
    /// The sweep of `plan` run with `options` (reads the distribution file and the road
    /// network again to digest them; `Err` names the file that cannot be read).
    pub fn of(plan: &Plan, options: &Options, columns: &Table) -> Result<Sweep, String> {
        let read = |path: &Path| {
            std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))
        };
        let mut hash = Sha256::new();
        let mut field = |bytes: &[u8]| {
            hash.update((bytes.len() as u64).to_le_bytes());
            hash.update(bytes);
        };
        field(concat!("oscsim ", env!("CARGO_PKG_VERSION"), " batch sweep 1").as_bytes());
        field(&read(&plan.distribution)?);
        let mut files: Vec<(String, Vec<u8>)> = Vec::new();
        for (path, bytes) in plan.scenario.sources.files().iter() {
            // An empty entry is a file the loader only checked to exist (the road network).
            if !bytes.is_empty() {
                files.push((file_name(path), bytes.to_vec()));
            }
        }
        if let Some(road) = &plan.scenario.road_network.logic_file {
            files.push((file_name(road), read(road)?));
        }
        if let Some(seeds) = &plan.seeds {
            let program = seeds.source.dsl().map_or(&[][..], |p| p.files());
            for f in program {
                files.push((file_name(Path::new(&f.name)), f.text.clone().into_bytes()));
            }
        }
        files.sort();
        files.dedup();
        for (name, bytes) in &files {
            field(name.as_bytes());
            field(bytes);
        }
        let o = options;
        let save = o.save.as_ref().map(|(save, _)| *save).unwrap_or_default();
        let recording = if save.osi { o.recording_time } else { None };
        let options_text = format!(
            "seed {} dt {:?} duration {:?} max_time {:?} traffic {:?} vehicles {:?} red {} host {:?} save {:?} recording {:?}",
            o.seed, o.dt, o.duration, o.max_time, o.traffic_model, o.vehicle_model,
            o.stop_at_red_lights, o.host, save, recording
        );
        field(options_text.as_bytes());
        if let Some(seeds) = &plan.seeds {
            let entry = seeds.source.options().scenario.as_deref().unwrap_or("");
            field(format!("seeds of scenario {entry:?}").as_bytes());
            // Length-prefixed as a field, the seeds hashed one by one (a list of 10^8 is not
            // copied into one buffer).
            hash.update(((seeds.seeds.len() * 8) as u64).to_le_bytes());
            for s in &seeds.seeds {
                hash.update(s.to_le_bytes());
            }
        }
        let mut digest = String::with_capacity(64);
        for byte in hash.finalize() {
            let _ = write!(digest, "{byte:02x}");
        }
        let mut selection = format!("shard {}/{}", o.shard.index, o.shard.count);
        if let Some(v) = o.only {
            let _ = write!(selection, ", only {v}");
        }
        Ok(Sweep {
            digest,
            selection,
            variants: selected(plan, options).len(),
            columns: columns.header(),
        })
    }

    /// The journal's header record.
    pub fn to_header(&self) -> String {
        format!(
            "{TITLE}\nsweep: {}\nselection: {}\nvariants: {}\ncolumns: {}",
            self.digest, self.selection, self.variants, self.columns
        )
    }

    /// The sweep of a journal's header record, if it is one.
    pub fn from_header(text: &str) -> Option<Sweep> {
        let mut lines = text.split('\n');
        if lines.next()? != TITLE {
            return None;
        }
        let mut value = |key: &str| {
            lines
                .next()?
                .strip_prefix(key)?
                .strip_prefix(": ")
                .map(str::to_owned)
        };
        Some(Sweep {
            digest: value("sweep")?,
            selection: value("selection")?,
            variants: value("variants")?.parse().ok()?,
            columns: value("columns")?,
        })
    }
}

/// The sweep of the journal in `dir`, the journal's path and how many variants it records, when
/// `dir` holds a journal (`oscsim batch merge` checks shards with it).
pub(crate) fn recorded(dir: &Path) -> Result<Option<(Sweep, String, usize)>, Error> {
    let path = dir.join(JOURNAL_FILE);
    if !path.is_file() {
        return Ok(None);
    }
    let contents = journal::read(&path)?;
    let name = path.display().to_string();
    let sweep = Sweep::from_header(&contents.records[0])
        .ok_or_else(|| journal::not_a_journal(name.clone(), "a header of another format".into()))?;
    // A row's record starts with its variant number; one recorded twice counts once.
    let variants: std::collections::BTreeSet<&str> = contents.records[1..]
        .iter()
        .filter_map(|r| r.split(',').next())
        .collect();
    Ok(Some((sweep, name, variants.len())))
}

fn file_name(path: &Path) -> String {
    path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_header_reads_back() {
        let sweep = Sweep {
            digest: "ab".repeat(32),
            selection: "shard 1/3, only 4".into(),
            variants: 1,
            columns: "variant,\"a: b\",stop_reason".into(),
        };
        let text = sweep.to_header();
        assert_eq!(
            text,
            format!(
                "oscsim batch journal\nsweep: {}\nselection: shard 1/3, only 4\nvariants: 1\ncolumns: variant,\"a: b\",stop_reason",
                "ab".repeat(32)
            )
        );
        assert_eq!(Sweep::from_header(&text), Some(sweep));
        assert_eq!(Sweep::from_header("variant,stop_reason"), None);
    }
}
