//! Batches that survive being killed: `oscsim batch DIST --out DIR` records every finished
//! variant's row in `DIR/batch.journal` (journal.rs) as the variant ends, and the same command
//! run again on the same `DIR` goes on from there. It runs only the variants the journal lacks
//! and ends with the `results.csv`, `results.parquet`, `report.html` (and, for a DSL scenario
//! with cover items, `coverage.csv`) an uninterrupted run writes, byte for byte: a journal row
//! is the row's line of `results.csv` with its coverage samples, and the table keeps its
//! numbers as written (table.rs), as `oscsim batch merge` relies on too; `coverage.csv` is
//! counted from the rows.
//!
//! **Resuming is running again, without a flag.** Slurm's `--requeue`, a Kubernetes Job's
//! retries and a spot instance's restart all run the same command line again; a flag the first
//! run must not have and later runs must would not fit them. A finished sweep run again runs
//! nothing and writes the same files.
//!
//! **Never a mix.** The journal's first record names the sweep (sweep.rs: a digest of the
//! inputs and options, and the selection of variants). A folder whose journal names another
//! sweep, or that holds results without a journal, is refused before anything runs; a
//! journal's rows are read with the columns its header names. A variant recorded twice (it
//! cannot be by this code) counts once.
//!
//! Order of work per variant: its saved outputs are renamed into place, then its row appended
//! (run.rs, save.rs). So a row in the journal means its folder is whole; a folder without a
//! row is replaced when the variant runs again. The final files are written to temporary names
//! and renamed (merge.rs [`write_outputs`]).

use std::collections::BTreeMap;
use std::path::Path;

use crate::error::{Error, JournalErrorKind, ResumeErrorKind};
use crate::journal::{self, Journal, JOURNAL_FILE};
use crate::merge::write_outputs;
use crate::plan::Plan;
use crate::run::{empty_table, run_each, selected, Options};
use crate::sweep::Sweep;
use crate::table::{Row, Table};

/// The rows a journal already holds and the journal, open for appending.
#[derive(Debug)]
pub struct Resumed {
    /// The journal.
    pub journal: Journal,
    /// The table's columns with the rows recorded so far, by variant number.
    pub table: Table,
}

impl Resumed {
    /// Appends `row`'s line to the journal (the caller runs only variants it lacks; a variant
    /// recorded twice would be read once).
    pub fn record(&self, row: &Row) -> Result<(), Error> {
        self.journal.append(&self.table.row_line(row))
    }

    /// Whether variant `v` is recorded.
    pub fn has(&self, v: u64) -> bool {
        self.table
            .rows
            .binary_search_by_key(&v, |r| r.variant)
            .is_ok()
    }
}

/// Opens the journal of `sweep` in `dir` (creating the folder and the journal when there is
/// none) and reads the rows it holds, with `columns`' parameters and monitors (module doc).
pub fn open(dir: &Path, sweep: &Sweep, columns: &Table) -> Result<Resumed, Error> {
    let path = dir.join(JOURNAL_FILE);
    let io = |what: &'static str| {
        move |e: std::io::Error| {
            Error::from(JournalErrorKind::Io {
                what,
                path: dir.display().to_string(),
                message: e.to_string(),
            })
        }
    };
    std::fs::create_dir_all(dir).map_err(io("create"))?;
    if !path.exists() {
        let found: Vec<&str> = [
            "results.csv",
            "results.parquet",
            "report.html",
            "coverage.csv",
            "variants",
        ]
        .into_iter()
        .filter(|f| dir.join(f).exists())
        .collect();
        if !found.is_empty() {
            return Err(ResumeErrorKind::Unjournaled {
                journal: JOURNAL_FILE,
                dir: dir.display().to_string(),
                found: found.join(", "),
            }
            .into());
        }
        return Ok(Resumed {
            journal: Journal::create(&path, &sweep.to_header())?,
            table: Table {
                rows: Vec::new(),
                ..columns.clone()
            },
        });
    }
    let contents = journal::read(&path)?;
    let found = Sweep::from_header(&contents.records[0]);
    if found.as_ref() != Some(sweep) {
        let describe = |s: &Sweep| format!("sweep {} with {}", s.digest, s.selection);
        return Err(ResumeErrorKind::OtherSweep {
            dir: dir.display().to_string(),
            expected: describe(sweep),
            found: found.map_or_else(|| "a header of another format".into(), |s| describe(&s)),
        }
        .into());
    }
    let mut rows = BTreeMap::new();
    for (i, line) in contents.records.iter().enumerate().skip(1) {
        let row =
            columns
                .parse_line(line)
                .map_err(|(expected, found)| ResumeErrorKind::BadRecord {
                    path: path.display().to_string(),
                    record: i + 1,
                    expected,
                    found,
                })?;
        rows.entry(row.variant).or_insert(row);
    }
    Ok(Resumed {
        journal: Journal::append_to(&path, contents.valid_len)?,
        table: Table {
            rows: rows.into_values().collect(),
            ..columns.clone()
        },
    })
}

/// A durable batch's end: the whole table, and how many of its rows came from the journal.
#[derive(Debug, Clone, PartialEq)]
pub struct Finished {
    /// Every selected variant's row, by variant number.
    pub table: Table,
    /// Rows read from the journal of an earlier run.
    pub resumed: usize,
}

/// Runs the selected variants of `plan` that the journal in `out` lacks, recording each as it
/// ends, then writes `results.csv`, `results.parquet` and `report.html` of them all into `out`
/// (module doc). `started(resumed, to_run)` is called once the journal is read;
/// `progress(done, to_run)` after each variant.
pub fn run_durable(
    plan: &Plan,
    options: &Options,
    out: &Path,
    started: &dyn Fn(usize, usize),
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Finished, Error> {
    let columns = empty_table(plan);
    let sweep = Sweep::of(plan, options, &columns).map_err(ResumeErrorKind::Inputs)?;
    let resumed = open(out, &sweep, &columns)?;
    let todo: Vec<u64> = selected(plan, options)
        .into_iter()
        .filter(|&v| !resumed.has(v))
        .collect();
    started(resumed.table.rows.len(), todo.len());
    let ran = run_each(plan, options, &todo, &|row, done, total| {
        resumed.record(row)?;
        progress(done, total);
        Ok(())
    })?;
    resumed.journal.sync()?;
    let Resumed { mut table, .. } = resumed;
    let count = table.rows.len();
    table.rows.extend(ran.rows);
    table.rows.sort_by_key(|r| r.variant);
    write_outputs(out, &table)?;
    Ok(Finished {
        table,
        resumed: count,
    })
}
