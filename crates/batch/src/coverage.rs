//! The coverage of a batch (ASAM OpenSCENARIO DSL 2.1 §7.3.12 `cover(…)`): each cover item's
//! buckets, the hits counted from the results table's samples (table.rs), the holes (buckets
//! no sample fell in) and the share of buckets hit, per item and overall; `coverage.csv` and
//! the report's section.
//!
//! Buckets of `range: [low..high], every: w` (in the item's unit): [low + k·w, low + (k+1)·w)
//! for k = 0 … ⌈(high − low)/w⌉ − 1, the last one ending at `high` and including it; without
//! `every`, one bucket [low..high]. A cover over an enum (or a boolean) has one bucket per
//! member. Bounds are kept to 1e-6, as the samples are, and a sample is placed by integer
//! arithmetic in millionths, so that a count made from `results.csv` finds the same bucket.
//! A sample outside the range, or without value, is counted apart (not a hit).
//!
//! `coverage.csv`: `item,bucket,low,high,hits`, one row per bucket of every cover item in
//! column order (holes with 0 hits): a range bucket as `[low..high)` (the last `[low..high]`)
//! with `low`, `high` its bounds; an enum member in `bucket` with `low`, `high` empty. Shard
//! outputs carry their buckets in their `coverage.csv`, from which `batch merge` recounts the
//! merged table: exactly the unsharded run's file.

use std::fmt::Write as _;

use load::{Buckets, CoverItem, CoverageKind, Sample};

use crate::error::{CsvErrorKind, Error};
use crate::table::{field, split_line, BucketDef, CoverDef, Table};

/// `x` (a value in the item's unit, kept to 1e-6) in millionths.
fn micro(x: f64) -> i64 {
    (x * 1e6).round() as i64
}

/// Millionths as the shortest decimal text (`10`, `2.5`, `-0.000001`).
fn decimal(m: i64) -> String {
    let sign = if m < 0 { "-" } else { "" };
    let (whole, frac) = (m.unsigned_abs() / 1_000_000, m.unsigned_abs() % 1_000_000);
    if frac == 0 {
        return format!("{sign}{whole}");
    }
    let digits = format!("{frac:06}");
    format!("{sign}{whole}.{}", digits.trim_end_matches('0'))
}

impl BucketDef {
    /// Its `bucket` cell.
    pub fn label(&self) -> String {
        match self {
            BucketDef::Range { low, high, closed } => format!(
                "[{}..{}{}",
                decimal(*low),
                decimal(*high),
                if *closed { "]" } else { ")" }
            ),
            BucketDef::Member(m) => m.clone(),
        }
    }

    fn holds(&self, s: &Sample) -> bool {
        match (self, s) {
            (BucketDef::Range { low, high, closed }, Sample::Number(x)) => {
                let x = micro(*x);
                *low <= x && (x < *high || (*closed && x == *high))
            }
            (BucketDef::Member(m), Sample::Text(t)) => m == t,
            _ => false,
        }
    }
}

impl CoverDef {
    /// The bucket `s` falls in, if any (none: outside the range, another member, no value).
    pub fn bucket_of(&self, s: &Sample) -> Option<&BucketDef> {
        self.bucket_index(s).map(|k| &self.buckets[k])
    }

    fn bucket_index(&self, s: &Sample) -> Option<usize> {
        self.buckets.iter().position(|b| b.holds(s))
    }
}

/// The bucket definitions of the cover items among `items` (the plan's), in column order.
pub fn definitions(items: &[CoverItem]) -> Vec<CoverDef> {
    items
        .iter()
        .filter(|i| i.kind == CoverageKind::Cover)
        .filter_map(|i| {
            let buckets = match &i.buckets {
                Buckets::None => return None,
                Buckets::Members(m) => m.iter().cloned().map(BucketDef::Member).collect(),
                Buckets::Range { low, high, every } => {
                    let (low, high) = (micro(*low), micro(*high));
                    let width = every.map_or(high - low, micro).max(1);
                    let mut out = Vec::new();
                    let mut start = low;
                    while start < high {
                        let end = start.saturating_add(width).min(high);
                        out.push(BucketDef::Range {
                            low: start,
                            high: end,
                            closed: end == high,
                        });
                        start = end;
                    }
                    out
                }
            };
            Some(CoverDef {
                column: column(i),
                buckets,
            })
        })
        .collect()
}

/// The results column of an item: `cover:<name>` or `record:<name>`.
pub fn column(item: &CoverItem) -> String {
    match item.kind {
        CoverageKind::Cover => format!("cover:{}", item.name),
        _ => format!("record:{}", item.name),
    }
}

/// One cover item's counts.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ItemCoverage {
    /// The item's name.
    pub name: String,
    /// Each bucket with its hits.
    pub buckets: Vec<(BucketDef, u64)>,
    /// Samples outside every bucket (outside the range, or another member).
    pub outside: u64,
    /// Samples without a value.
    pub no_value: u64,
}

impl ItemCoverage {
    /// Buckets with at least one hit.
    pub fn hit(&self) -> usize {
        self.buckets.iter().filter(|(_, h)| *h > 0).count()
    }

    /// The buckets without a hit.
    pub fn holes(&self) -> Vec<&BucketDef> {
        self.buckets
            .iter()
            .filter(|(_, h)| *h == 0)
            .map(|(b, _)| b)
            .collect()
    }
}

/// Every cover item's counts over the rows of `table` (its `buckets` and samples).
pub fn count(table: &Table) -> Vec<ItemCoverage> {
    table
        .buckets
        .iter()
        .map(|def| {
            let k = table.coverage.iter().position(|c| *c == def.column);
            let mut item = ItemCoverage {
                name: def.column.trim_start_matches("cover:").to_owned(),
                buckets: def.buckets.iter().map(|b| (b.clone(), 0)).collect(),
                outside: 0,
                no_value: 0,
            };
            let samples = table
                .rows
                .iter()
                .filter_map(|r| r.result.as_ref().ok())
                .filter_map(|o| o.samples.get(k?));
            for s in samples.flatten() {
                match def.bucket_index(s) {
                    Some(b) => item.buckets[b].1 += 1,
                    None if *s == Sample::NoValue => item.no_value += 1,
                    None => item.outside += 1,
                }
            }
            item
        })
        .collect()
}

/// `coverage.csv` of `items` (module doc).
pub fn to_csv(items: &[ItemCoverage]) -> String {
    let mut out = String::from("item,bucket,low,high,hits\n");
    for item in items {
        for (b, hits) in &item.buckets {
            let (low, high) = match b {
                BucketDef::Range { low, high, .. } => (decimal(*low), decimal(*high)),
                BucketDef::Member(_) => (String::new(), String::new()),
            };
            let _ = writeln!(
                out,
                "{},{},{low},{high},{hits}",
                field(&item.name),
                field(&b.label())
            );
        }
    }
    out
}

/// The bucket definitions a `coverage.csv` lists (its hits are recounted, not read).
pub fn definitions_from_csv(text: &str, file: &str) -> Result<Vec<CoverDef>, Error> {
    let err =
        |line: usize, expected: &str, found: &str| CsvErrorKind::at(file, line, expected, found);
    let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l));
    match lines.next() {
        Some((_, "item,bucket,low,high,hits")) => {}
        other => {
            return Err(err(
                1,
                "the header item,bucket,low,high,hits",
                other.map_or("an empty file", |(_, l)| l),
            )
            .into())
        }
    }
    let mut defs: Vec<CoverDef> = Vec::new();
    for (n, line) in lines.filter(|(_, l)| !l.is_empty()) {
        let c = split_line(line).map_err(|e| err(n, "a CSV line", &e))?;
        let [item, bucket, low, high, _hits] = c.as_slice() else {
            return Err(err(n, "5 cells", &c.len().to_string()).into());
        };
        let number = |t: &str| -> Result<i64, CsvErrorKind> {
            t.parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .map(micro)
                .ok_or_else(|| err(n, "a bucket bound", t))
        };
        let def = if low.is_empty() && high.is_empty() {
            BucketDef::Member(bucket.clone())
        } else {
            BucketDef::Range {
                low: number(low)?,
                high: number(high)?,
                closed: bucket.ends_with(']'),
            }
        };
        let column = format!("cover:{item}");
        match defs.last_mut() {
            Some(d) if d.column == column => d.buckets.push(def),
            _ => defs.push(CoverDef {
                column,
                buckets: vec![def],
            }),
        }
    }
    Ok(defs)
}

/// The summary line: buckets hit of all, over every cover item; `None` without buckets.
pub fn summary_line(items: &[ItemCoverage]) -> Option<String> {
    let total: usize = items.iter().map(|i| i.buckets.len()).sum();
    let hit: usize = items.iter().map(ItemCoverage::hit).sum();
    (total > 0).then(|| {
        format!(
            "coverage: {hit} of {total} buckets hit ({:.1} %) over {} cover item(s)",
            100.0 * hit as f64 / total as f64,
            items.len()
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn range_buckets_cut_every_width_and_close_the_last() {
        // [0..25] every 10: [0..10), [10..20), [20..25].
        let b = |low: i64, high: i64, closed| BucketDef::Range {
            low: low * 1_000_000,
            high: high * 1_000_000,
            closed,
        };
        let x = |v: f64| Sample::Number(v);
        let defs = [b(0, 10, false), b(10, 20, false), b(20, 25, true)];
        assert_eq!(
            defs.clone().map(|d| d.label()),
            ["[0..10)", "[10..20)", "[20..25]"]
        );
        assert!(defs[0].holds(&x(0.0)) && defs[0].holds(&x(9.999999)));
        assert!(!defs[0].holds(&x(10.0)) && defs[1].holds(&x(10.0)));
        assert!(defs[2].holds(&x(25.0)) && !defs[2].holds(&x(25.000001)));
        // 0.3 in buckets of 0.1 from 0: bucket [0.3..0.4), by integers (0.3/0.1 is
        // 2.9999999999999996 in doubles).
        let tenth = BucketDef::Range {
            low: 300_000,
            high: 400_000,
            closed: false,
        };
        assert!(tenth.holds(&x(0.3)));
        assert_eq!(decimal(-1), "-0.000001");
        assert_eq!(decimal(2_500_000), "2.5");
    }
}
