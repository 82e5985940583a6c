//! Joining shard outputs (`oscsim batch merge DIR… --out DIR`) into exactly what one unsharded
//! run writes: the rows of every shard's `results.csv`, by variant number, then `results.csv`,
//! `results.parquet` and `report.html` written from that table by [`write_outputs`] — the same
//! function the unsharded run uses, on the same values (table.rs keeps numbers as written), so
//! the files are equal byte for byte; `coverage.csv` is recounted from the merged rows with
//! the buckets the shards' `coverage.csv` list (coverage.rs). Per-variant folders
//! (`variants/NNNNN`) are copied.
//!
//! A shard folder with a batch journal (resume.rs) is checked first: its sweep must be that of
//! the other shards (the digest of sweep.rs; shards differ only in their selection), and it
//! must have finished (every variant of its selection recorded); a killed shard is named with
//! how far it got, to be run again before merging.

use std::path::{Path, PathBuf};

use crate::error::{Error, MergeErrorKind};
use crate::parquet_file::to_parquet;
use crate::report::report_html;
use crate::sweep::recorded;
use crate::table::Table;

fn io<'a>(what: &'static str, path: &'a Path) -> impl Fn(std::io::Error) -> Error + 'a {
    move |e| {
        MergeErrorKind::Io {
            what,
            path: path.display().to_string(),
            message: e.to_string(),
        }
        .into()
    }
}

/// Writes `results.csv`, `results.parquet`, `report.html` (and `coverage.csv` when the table
/// has cover items) of `table` into `dir`, each to a
/// temporary name and renamed into place: a kill leaves each file whole, old or new. Not
/// synced: they are made from the batch's journal, which is (resume.rs); after a power loss
/// the batch run again writes them anew.
pub fn write_outputs(dir: &Path, table: &Table) -> Result<(), Error> {
    std::fs::create_dir_all(dir).map_err(io("cannot create", dir))?;
    let mut files = vec![
        ("results.csv", table.to_csv().into_bytes()),
        ("results.parquet", to_parquet(table)?),
        ("report.html", report_html(table).into_bytes()),
    ];
    if !table.buckets.is_empty() {
        let counts = crate::coverage::count(table);
        files.push((
            "coverage.csv",
            crate::coverage::to_csv(&counts).into_bytes(),
        ));
    }
    for (name, bytes) in files {
        let path = dir.join(name);
        let tmp = dir.join(format!("{name}.tmp"));
        std::fs::write(&tmp, bytes).map_err(io("cannot write", &tmp))?;
        std::fs::rename(&tmp, &path).map_err(io("cannot rename into place", &path))?;
    }
    Ok(())
}

/// Merges the shard folders `shards` into `out` (module doc); returns the merged table.
pub fn merge(shards: &[PathBuf], out: &Path) -> Result<Table, Error> {
    let mut parts = Vec::with_capacity(shards.len());
    let mut sweep: Option<(String, String)> = None;
    for dir in shards {
        if let Some((s, journal, done)) = recorded(dir)? {
            if done < s.variants {
                return Err(MergeErrorKind::Unfinished {
                    journal,
                    recorded: done,
                    variants: s.variants,
                }
                .into());
            }
            match &sweep {
                Some((digest, first)) if *digest != s.digest => {
                    return Err(MergeErrorKind::DifferentSweeps {
                        first: first.clone(),
                        other: journal,
                    }
                    .into())
                }
                Some(_) => {}
                None => sweep = Some((s.digest, journal)),
            }
        }
        let path = dir.join("results.csv");
        let name = path.display().to_string();
        let text = std::fs::read_to_string(&path).map_err(io("cannot read", &path))?;
        parts.push((Table::from_csv(&text, &name)?, name));
        copy_variants(&dir.join("variants"), &out.join("variants"))?;
    }
    let mut table = merge_tables(parts)?;
    // The cover items' buckets, from the first shard's coverage.csv (every shard writes the
    // plan's); the hits are recounted from the merged rows.
    if let Some(dir) = shards.first() {
        let path = dir.join("coverage.csv");
        if path.is_file() {
            let text = std::fs::read_to_string(&path).map_err(io("cannot read", &path))?;
            table.buckets =
                crate::coverage::definitions_from_csv(&text, &path.display().to_string())?;
        }
    }
    write_outputs(out, &table)?;
    Ok(table)
}

/// Joins the tables of disjoint shares of one batch, each with the name its errors give it,
/// into the table of the whole: rows by variant number. Refuses shares of different batches
/// (other parameters or monitors) and a variant in two shares.
pub fn merge_tables(parts: Vec<(Table, String)>) -> Result<Table, Error> {
    let mut merged: Option<(Table, String)> = None;
    let mut owner: std::collections::BTreeMap<u64, String> = Default::default();
    for (table, name) in parts {
        for row in &table.rows {
            if let Some(first) = owner.insert(row.variant, name.clone()) {
                return Err(MergeErrorKind::Overlap {
                    variant: row.variant,
                    first,
                    other: name,
                }
                .into());
            }
        }
        match &mut merged {
            None => merged = Some((table, name)),
            Some((m, first)) => {
                if m.parameters != table.parameters
                    || m.monitors != table.monitors
                    || m.coverage != table.coverage
                {
                    return Err(MergeErrorKind::DifferentBatches {
                        first: first.clone(),
                        other: name,
                    }
                    .into());
                }
                m.rows.extend(table.rows);
            }
        }
    }
    let mut table = merged.map(|(t, _)| t).unwrap_or_default();
    table.rows.sort_by_key(|r| r.variant);
    Ok(table)
}

/// Copies the variant folders under `from` into `to` (nothing when `from` does not exist or is
/// `to`).
fn copy_variants(from: &Path, to: &Path) -> Result<(), Error> {
    if !from.is_dir() || same(from, to) {
        return Ok(());
    }
    for entry in std::fs::read_dir(from).map_err(io("cannot read", from))? {
        let entry = entry.map_err(io("cannot read", from))?;
        let target = to.join(entry.file_name());
        std::fs::create_dir_all(&target).map_err(io("cannot create", &target))?;
        for file in std::fs::read_dir(entry.path()).map_err(io("cannot read", &entry.path()))? {
            let file = file.map_err(io("cannot read", &entry.path()))?;
            let dest = target.join(file.file_name());
            std::fs::copy(file.path(), &dest).map_err(io("cannot copy to", &dest))?;
        }
    }
    Ok(())
}

fn same(a: &Path, b: &Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    }
}
