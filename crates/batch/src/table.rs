//! The results table of a batch: one row per variant, and its CSV form (`results.csv`).
//!
//! Columns, in this order: `variant`, one column per varied parameter (its name, in the order
//! the distribution file first names it), `stop_reason`, `end_time`, `collision`,
//! `first_collision_time`, `min_ttc`, `min_headway`, `min_gap`, `events_started`, `error`, then
//! one `monitor:<name>` column per MonitorDeclaration of the scenario (OpenSCENARIO 1.3), in
//! name order, then one `cover:<name>` or `record:<name>` column per coverage item of an
//! OpenSCENARIO DSL scenario (§7.3.12), in source order: the item's samples in time order,
//! separated by `;` (a number in the item's unit with 6 decimals, an enum member, `true` or
//! `false`, or `no value`); empty when its event never occurred.
//!
//! Numbers are written at a fixed precision — times (`end_time`, `first_collision_time`) to the
//! millisecond, `min_ttc` (s), `min_headway` (s) and `min_gap` (m) to 1e-6 — and the table keeps
//! the numbers *as written*: a row's values are rounded through their text when the row is made
//! ([`quantize_time`], [`quantize`]). So the CSV read back gives the very same values, and a
//! Parquet file written from a merged CSV equals the one written by an unsharded run, byte for
//! byte. An empty cell is a value that was never defined (no collision, no time to collision at
//! any step, …); a failed variant has only `variant`, its parameters and `error`, a variant
//! its scenario's constraints refused also `stop_reason` `refused_by_constraints` (its error
//! starts with [`REFUSED`]).
//!
//! Written by hand: the layout is fixed and the only quoting needed is RFC 4180's for text
//! cells (parameter values, the error message), which [`field`] and [`split_line`] do.

use std::fmt::Write as _;

use crate::error::{CsvErrorKind, Error};
use engine::StopReason;
use load::Sample;

/// One bucket of a cover item (coverage.rs counts the samples into them).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum BucketDef {
    /// [low, high) in millionths of the item's unit; `closed`: [low, high].
    Range {
        /// Lower bound (µ-units).
        low: i64,
        /// Upper bound (µ-units).
        high: i64,
        /// Whether `high` belongs to the bucket (the last one of a range).
        closed: bool,
    },
    /// An enum member, `true` or `false`.
    Member(String),
}

/// The buckets of one cover item.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CoverDef {
    /// The item's results column, `cover:<name>`.
    pub column: String,
    /// Its buckets, in order.
    pub buckets: Vec<BucketDef>,
}

/// What one run of a variant gave.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Outcome {
    /// Why it ended.
    pub stop: Option<StopReason>,
    /// Simulated time at the end (s).
    pub end_time: f64,
    /// The host's box touched another entity's at some frame.
    pub collision: bool,
    /// Time of the first frame with a collision (s).
    pub first_collision_time: Option<f64>,
    /// Smallest time to collision of the host against any other entity (s).
    pub min_ttc: Option<f64>,
    /// Smallest positive time headway of the host behind any other entity (s).
    pub min_headway: Option<f64>,
    /// Smallest freespace distance between the host's box and any other entity's (m).
    pub min_gap: Option<f64>,
    /// Storyboard Events started (each start transition counts).
    pub events_started: u64,
    /// The monitors' values at the end, by name.
    pub monitors: Vec<(String, bool)>,
    /// Each coverage column's samples, in column order (empty without coverage items).
    pub samples: Vec<Vec<Sample>>,
}

/// The start of the error message of a variant whose parameter values break the
/// ConstraintGroups of the scenario's own ParameterDeclarations (OpenSCENARIO 1.3 §9.1): the
/// scenario refuses it, it did not fail. Its `stop_reason` is [`REFUSED_STOP`].
pub const REFUSED: &str = "refused by constraints: ";

/// The `stop_reason` of a refused variant ([`REFUSED`]).
pub const REFUSED_STOP: &str = "refused_by_constraints";

/// One row of the results table.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The variant's number (0-based, the distribution's documented order).
    pub variant: u64,
    /// The varied parameters' values, in the table's parameter order.
    pub params: Vec<String>,
    /// The run's results, or why the variant failed.
    pub result: Result<Outcome, String>,
}

impl Row {
    /// Whether the scenario's constraints refused the variant's values ([`REFUSED`]).
    pub fn refused(&self) -> bool {
        matches!(&self.result, Err(m) if m.starts_with(REFUSED))
    }

    /// Whether the variant failed: it has no outcome and was not refused.
    pub fn failed(&self) -> bool {
        self.result.is_err() && !self.refused()
    }

    /// The `stop_reason` cell: why the run ended, [`REFUSED_STOP`] for a refused variant,
    /// nothing for a failed one.
    pub fn stop_reason(&self) -> Option<&'static str> {
        match &self.result {
            Ok(o) => o.stop.map(StopReason::name),
            Err(_) if self.refused() => Some(REFUSED_STOP),
            Err(_) => None,
        }
    }
}

/// The results of a batch (or of a shard of one).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Table {
    /// Names of the varied parameters, in column order.
    pub parameters: Vec<String>,
    /// Names of the scenario's monitors, in column order.
    pub monitors: Vec<String>,
    /// The coverage columns, `cover:<name>` or `record:<name>`, in column order.
    pub coverage: Vec<String>,
    /// The buckets of the `cover` items (coverage.rs); not in the CSV: the batch's plan, or
    /// a shard's `coverage.csv`, gives them.
    pub buckets: Vec<CoverDef>,
    /// The rows, by variant number.
    pub rows: Vec<Row>,
}

/// The fixed columns after the parameters and before the monitors.
pub const FIXED_COLUMNS: [&str; 9] = [
    "stop_reason",
    "end_time",
    "collision",
    "first_collision_time",
    "min_ttc",
    "min_headway",
    "min_gap",
    "events_started",
    "error",
];

/// `x` rounded to the millisecond through its text (module doc).
pub fn quantize_time(x: f64) -> f64 {
    format!("{x:.3}").parse().unwrap_or(x)
}

/// `x` rounded to 1e-6 through its text (module doc).
pub fn quantize(x: f64) -> f64 {
    format!("{x:.6}").parse().unwrap_or(x)
}

/// `text` as a CSV cell: quoted (RFC 4180) when it holds a comma, quote or line break.
pub fn field(text: &str) -> std::borrow::Cow<'_, str> {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\"")).into()
    } else {
        text.into()
    }
}

impl Outcome {
    /// Rounds every number to the precision of the CSV (module doc).
    pub fn quantized(mut self) -> Outcome {
        self.end_time = quantize_time(self.end_time);
        self.first_collision_time = self.first_collision_time.map(quantize_time);
        self.min_ttc = self.min_ttc.map(quantize);
        self.min_headway = self.min_headway.map(quantize);
        self.min_gap = self.min_gap.map(quantize);
        self
    }
}

impl Table {
    /// The header line (without line break).
    pub fn header(&self) -> String {
        let mut cells: Vec<String> = vec!["variant".into()];
        cells.extend(self.parameters.iter().map(|p| field(p).into_owned()));
        cells.extend(FIXED_COLUMNS.iter().map(|c| c.to_string()));
        cells.extend(
            self.monitors
                .iter()
                .map(|m| field(&format!("monitor:{m}")).into_owned()),
        );
        cells.extend(self.coverage.iter().map(|c| field(c).into_owned()));
        cells.join(",")
    }

    /// The CSV text of the table: header and one line per row, `\n` line ends.
    pub fn to_csv(&self) -> String {
        let mut out = self.header();
        out.push('\n');
        for row in &self.rows {
            self.write_row(&mut out, row);
            out.push('\n');
        }
        out
    }

    /// The CSV line of `row` in this table (without line break), as [`Table::to_csv`] writes
    /// it: the form a row has in the batch journal (resume.rs).
    pub fn row_line(&self, row: &Row) -> String {
        let mut out = String::new();
        self.write_row(&mut out, row);
        out
    }

    fn write_row(&self, out: &mut String, row: &Row) {
        let _ = write!(out, "{}", row.variant);
        for p in &row.params {
            let _ = write!(out, ",{}", field(p));
        }
        let opt = |x: Option<f64>, decimals: usize| {
            x.map_or(String::new(), |x| format!("{x:.decimals$}"))
        };
        match &row.result {
            Ok(o) => {
                let _ = write!(
                    out,
                    ",{},{:.3},{},{},{},{},{},{},",
                    o.stop.map_or("", StopReason::name),
                    o.end_time,
                    o.collision,
                    opt(o.first_collision_time, 3),
                    opt(o.min_ttc, 6),
                    opt(o.min_headway, 6),
                    opt(o.min_gap, 6),
                    o.events_started
                );
                for m in &self.monitors {
                    let value = o.monitors.iter().find(|(n, _)| n == m).map(|(_, v)| v);
                    let _ = write!(out, ",{}", value.map_or(String::new(), |v| v.to_string()));
                }
                for k in 0..self.coverage.len() {
                    let cell: Vec<String> = o
                        .samples
                        .get(k)
                        .map(|s| s.iter().map(Sample::text).collect())
                        .unwrap_or_default();
                    let _ = write!(out, ",{}", field(&cell.join(";")));
                }
            }
            Err(message) => {
                let stop = row.stop_reason().unwrap_or_default();
                let _ = write!(out, ",{stop},,,,,,,,{}", field(message));
                for _ in self.monitors.iter().chain(&self.coverage) {
                    out.push(',');
                }
            }
        }
    }

    /// Reads the CSV text of a table (as [`Table::to_csv`] writes it); `file` names it in
    /// errors.
    pub fn from_csv(text: &str, file: &str) -> Result<Table, Error> {
        let err = |line: usize, expected: &str, found: &str| {
            CsvErrorKind::at(file, line, expected, found)
        };
        let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l));
        let (_, header) = lines
            .next()
            .ok_or_else(|| err(1, "a header line", "an empty file"))?;
        let cells = split_line(header).map_err(|e| err(1, "a CSV header", &e))?;
        let fixed_at = cells
            .iter()
            .position(|c| c == FIXED_COLUMNS[0])
            .ok_or_else(|| err(1, "a stop_reason column", header))?;
        if cells.first().map(String::as_str) != Some("variant")
            || cells.len() < fixed_at + FIXED_COLUMNS.len()
            || cells[fixed_at..fixed_at + FIXED_COLUMNS.len()] != FIXED_COLUMNS
        {
            return Err(err(
                1,
                "the results header (variant, parameters, stop_reason … error, monitors)",
                header,
            )
            .into());
        }
        let parameters = cells[1..fixed_at].to_vec();
        let rest = &cells[fixed_at + FIXED_COLUMNS.len()..];
        let is_coverage = |c: &String| c.starts_with("cover:") || c.starts_with("record:");
        let first_coverage = rest.iter().position(is_coverage).unwrap_or(rest.len());
        let monitors = rest[..first_coverage]
            .iter()
            .map(|c| {
                c.strip_prefix("monitor:")
                    .map(str::to_owned)
                    .ok_or_else(|| err(1, "monitor:<name> columns after error", c))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let coverage = rest[first_coverage..].to_vec();
        if let Some(c) = coverage.iter().find(|c| !is_coverage(c)) {
            return Err(err(
                1,
                "cover:<name> or record:<name> columns after the monitors",
                c,
            )
            .into());
        }
        let mut table = Table {
            parameters,
            monitors,
            coverage,
            buckets: Vec::new(),
            rows: Vec::new(),
        };
        for (n, line) in lines {
            if line.is_empty() {
                continue;
            }
            let row = table
                .parse_line(line)
                .map_err(|(what, found)| err(n, &what, &found))?;
            table.rows.push(row);
        }
        Ok(table)
    }

    /// The row of one data line of this table's CSV (as [`Table::row_line`] writes it), or
    /// what was expected and what was found.
    pub fn parse_line(&self, line: &str) -> Result<Row, (String, String)> {
        let c = split_line(line).map_err(|e| ("a CSV line".to_owned(), e))?;
        let fixed_at = 1 + self.parameters.len();
        let width = fixed_at + FIXED_COLUMNS.len() + self.monitors.len() + self.coverage.len();
        if c.len() != width {
            return Err((format!("{width} cells"), c.len().to_string()));
        }
        self.parse_row(&c, fixed_at)
            .map_err(|(what, found)| (what.to_owned(), found))
    }

    fn parse_row(&self, c: &[String], at: usize) -> Result<Row, (&'static str, String)> {
        let num = |i: usize, what: &'static str| -> Result<Option<f64>, (&'static str, String)> {
            if c[i].is_empty() {
                return Ok(None);
            }
            c[i].parse::<f64>()
                .map(Some)
                .map_err(|_| (what, c[i].clone()))
        };
        let variant = c[0]
            .parse::<u64>()
            .map_err(|_| ("a variant number", c[0].clone()))?;
        let params = c[1..at].to_vec();
        let error = &c[at + 8];
        if !error.is_empty() {
            return Ok(Row {
                variant,
                params,
                result: Err(error.clone()),
            });
        }
        let stop = match c[at].as_str() {
            "" => None,
            s => Some(StopReason::from_name(s).ok_or(("a stop_reason", s.to_owned()))?),
        };
        let collision = match c[at + 2].as_str() {
            "true" => true,
            "false" => false,
            other => return Err(("true or false for collision", other.to_owned())),
        };
        let mut monitors = Vec::new();
        for (k, name) in self.monitors.iter().enumerate() {
            match c[at + 9 + k].as_str() {
                "true" => monitors.push((name.clone(), true)),
                "false" => monitors.push((name.clone(), false)),
                "" => {}
                other => return Err(("true, false or empty for a monitor", other.to_owned())),
            }
        }
        let first_coverage = at + 9 + self.monitors.len();
        let samples = (0..self.coverage.len())
            .map(|k| match c[first_coverage + k].as_str() {
                "" => Vec::new(),
                cell => cell.split(';').map(Sample::parse).collect(),
            })
            .collect();
        Ok(Row {
            variant,
            params,
            result: Ok(Outcome {
                stop,
                end_time: num(at + 1, "an end_time")?.unwrap_or(0.0),
                collision,
                first_collision_time: num(at + 3, "a first_collision_time")?,
                min_ttc: num(at + 4, "a min_ttc")?,
                min_headway: num(at + 5, "a min_headway")?,
                min_gap: num(at + 6, "a min_gap")?,
                events_started: c[at + 7]
                    .parse()
                    .map_err(|_| ("an events_started count", c[at + 7].clone()))?,
                monitors,
                samples,
            }),
        })
    }
}

/// The cells of one CSV line (RFC 4180 quoting; no line breaks inside cells, which this
/// table never writes).
pub fn split_line(line: &str) -> Result<Vec<String>, String> {
    let mut cells = Vec::new();
    let mut cell = String::new();
    let mut chars = line.chars().peekable();
    let mut quoted = false;
    let mut at_start = true;
    while let Some(ch) = chars.next() {
        match (quoted, ch) {
            (false, '"') if at_start => quoted = true,
            (true, '"') if chars.peek() == Some(&'"') => {
                chars.next();
                cell.push('"');
            }
            (true, '"') => {
                quoted = false;
                if !matches!(chars.peek(), None | Some(',')) {
                    return Err(format!("text after a closing quote in '{line}'"));
                }
            }
            (false, ',') => {
                cells.push(std::mem::take(&mut cell));
                at_start = true;
                continue;
            }
            (_, c) => cell.push(c),
        }
        at_start = false;
    }
    if quoted {
        return Err(format!("an unclosed quote in '{line}'"));
    }
    cells.push(cell);
    Ok(cells)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table() -> Table {
        Table {
            parameters: vec!["EgoSpeed".into(), "Name, quoted".into()],
            monitors: vec!["Safe".into()],
            coverage: vec!["cover:gap".into(), "record:side".into()],
            buckets: Vec::new(),
            rows: vec![
                Row {
                    variant: 0,
                    params: vec!["20".into(), "a \"b\"".into()],
                    result: Ok(Outcome {
                        stop: Some(StopReason::StopTrigger),
                        end_time: 22.0,
                        collision: true,
                        first_collision_time: Some(4.25),
                        min_ttc: Some(0.0),
                        min_headway: None,
                        min_gap: Some(0.0),
                        events_started: 3,
                        monitors: vec![("Safe".into(), false)],
                        samples: vec![
                            vec![Sample::Number(12.5), Sample::NoValue],
                            vec![Sample::Text("left".into())],
                        ],
                    }),
                },
                Row {
                    variant: 1,
                    params: vec!["25".into(), "x".into()],
                    result: Err("expected a lane, found none at a.xosc:3:4".into()),
                },
            ],
        }
    }

    #[test]
    fn the_csv_has_the_documented_columns_and_reads_back_equal() {
        let t = table();
        let csv = t.to_csv();
        let expected = [
            "variant,EgoSpeed,\"Name, quoted\",stop_reason,end_time,collision,first_collision_time,min_ttc,min_headway,min_gap,events_started,error,monitor:Safe,cover:gap,record:side",
            "0,20,\"a \"\"b\"\"\",stop_trigger,22.000,true,4.250,0.000000,,0.000000,3,,false,12.500000;no value,left",
            "1,25,x,,,,,,,,,\"expected a lane, found none at a.xosc:3:4\",,,",
        ];
        assert_eq!(csv, expected.join("\n") + "\n");
        assert_eq!(Table::from_csv(&csv, "r.csv").unwrap(), t);
    }

    #[test]
    fn quantized_values_survive_their_text() {
        let o = Outcome {
            end_time: 22.000000000000004,
            min_ttc: Some(1.0 / 3.0),
            ..Outcome::default()
        }
        .quantized();
        assert_eq!(o.end_time, 22.0);
        assert_eq!(o.min_ttc, Some(0.333333));
    }

    #[test]
    fn bad_csv_names_the_line() {
        let e = Table::from_csv("variant,stop_reason\n", "r.csv").unwrap_err();
        assert!(
            e.to_string().starts_with("expected the results header"),
            "{e}"
        );
        let csv = table().to_csv().replace("stop_trigger", "exploded");
        let e = Table::from_csv(&csv, "r.csv").unwrap_err();
        assert_eq!(
            e.to_string(),
            "expected a stop_reason, found exploded at r.csv:2"
        );
        // The crate's one error: a results.csv error is kind Csv, its place line 2, column 1.
        assert!(matches!(e.kind(), crate::ErrorKind::Csv(c) if c.line == 2));
        assert_eq!(e.pos().map(|p| p.to_string()).as_deref(), Some("r.csv:2:1"));
    }

    #[test]
    fn split_line_follows_rfc_4180() {
        assert_eq!(
            split_line("a,\"b,c\",\"d\"\"e\",").unwrap(),
            ["a", "b,c", "d\"e", ""]
        );
        assert!(split_line("\"open").is_err());
        assert!(split_line("\"a\"b").is_err());
    }
}
