//! What a person reads after a batch: a summary line set for the terminal ([`summary`]) and
//! `report.html` ([`report_html`]): one self-contained page (no network, no external scripts)
//! with the results table, sortable by any column with a click on its header, and — when the
//! batch varies one or two numeric parameters — a map of the parameter space: each variant a
//! cell (two parameters: a heat map; one: a strip along the parameter) coloured by `min_ttc`
//! (red 0 s → green ≥ 4 s, grey when undefined), collisions crossed out, the value on hover.
//!
//! With cover items (an OpenSCENARIO DSL scenario's `cover(…)`, coverage.rs) the page has a
//! coverage section: per item a bar chart of the hits per bucket (holes in red), the share of
//! buckets hit and the holes; overall the share of all buckets hit.
//!
//! The page is a function of the table alone (no date, no path), so merged shards and an
//! unsharded run write the same bytes.

use std::fmt::Write as _;

use crate::table::{Row, Table};

/// TTC at and above which a cell is fully green (s).
const TTC_GREEN: f64 = 4.0;

/// Lines summing a batch up: variants, failures, refusals by the scenario's constraints (when
/// any), collisions, the worst min_ttc and where.
pub fn summary(table: &Table) -> String {
    let total = table.rows.len();
    let refused = table.rows.iter().filter(|r| r.refused()).count();
    let failed = table.rows.iter().filter(|r| r.failed()).count();
    let collisions = table
        .rows
        .iter()
        .filter(|r| r.result.as_ref().is_ok_and(|o| o.collision))
        .count();
    let worst = table
        .rows
        .iter()
        .filter_map(|r| Some((r.result.as_ref().ok()?.min_ttc?, r)))
        .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.variant.cmp(&b.1.variant)));
    let mut out = format!("{total} variants, {failed} failed, ");
    if refused > 0 {
        let _ = write!(out, "{refused} refused by constraints, ");
    }
    let _ = write!(out, "{collisions} with a collision");
    match worst {
        Some((ttc, row)) => {
            let _ = write!(
                out,
                "\nworst min_ttc {ttc:.3} s in variant {}{}",
                row.variant,
                describe(table, row)
            );
        }
        None => out.push_str("\nno time to collision was defined in any variant"),
    }
    if let Some(line) = crate::coverage::summary_line(&crate::coverage::count(table)) {
        out.push('\n');
        out.push_str(&line);
    }
    out
}

/// The coverage section (module doc); empty without cover items.
fn coverage_html(table: &Table) -> String {
    let items = crate::coverage::count(table);
    let Some(overall) = crate::coverage::summary_line(&items) else {
        return String::new();
    };
    let mut html = format!("<h2>Coverage</h2><p>{}</p>\n", escape(&overall));
    for item in &items {
        let total = item.buckets.len();
        let _ = writeln!(
            html,
            "<h3>cover({})</h3><p>{} of {total} buckets hit ({:.1} %); holes: {}; samples outside the buckets: {}; without value: {}</p>",
            escape(&item.name),
            item.hit(),
            100.0 * item.hit() as f64 / total.max(1) as f64,
            {
                let holes: Vec<String> = item.holes().iter().map(|b| escape(&b.label())).collect();
                if holes.is_empty() { "none".to_owned() } else { holes.join(", ") }
            },
            item.outside,
            item.no_value
        );
        html.push_str(&bars_svg(item));
        html.push('\n');
    }
    html
}

/// A bar per bucket, height by hits (holes as a red mark on the axis), labels below.
fn bars_svg(item: &crate::coverage::ItemCoverage) -> String {
    let (bar, gap, left, top, plot_h) = (28.0, 6.0, 40.0, 10.0, 120.0);
    let n = item.buckets.len() as f64;
    let w = left + n * (bar + gap) + 20.0;
    let h = top + plot_h + 70.0;
    let max = item
        .buckets
        .iter()
        .map(|(_, h)| *h)
        .max()
        .unwrap_or(0)
        .max(1) as f64;
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" font-family=\"sans-serif\" font-size=\"10\">"
    );
    let base = top + plot_h;
    let _ = write!(
        svg,
        "<line x1=\"{left}\" y1=\"{base}\" x2=\"{}\" y2=\"{base}\" stroke=\"#444444\"/><text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>",
        w - 20.0,
        left - 4.0,
        top + 8.0,
        max as u64
    );
    for (i, (b, hits)) in item.buckets.iter().enumerate() {
        let x = left + i as f64 * (bar + gap) + gap / 2.0;
        let label = escape(&b.label());
        if *hits == 0 {
            let _ = write!(
                svg,
                "<rect x=\"{x}\" y=\"{}\" width=\"{bar}\" height=\"4\" fill=\"#d62728\"><title>{label}: hole</title></rect>",
                base - 4.0
            );
        } else {
            let bh = plot_h * *hits as f64 / max;
            let _ = write!(
                svg,
                "<rect x=\"{x}\" y=\"{}\" width=\"{bar}\" height=\"{bh}\" fill=\"#4e79a7\"><title>{label}: {hits}</title></rect><text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{hits}</text>",
                base - bh,
                x + bar / 2.0,
                base - bh - 2.0
            );
        }
        let (tx, ty) = (x + bar / 2.0, base + 8.0);
        let _ = write!(
            svg,
            "<text x=\"{tx}\" y=\"{ty}\" transform=\"rotate(45 {tx} {ty})\">{label}</text>"
        );
    }
    svg.push_str("</svg>");
    svg
}

/// " (P1 = v1, P2 = v2)" for a row with parameters.
fn describe(table: &Table, row: &Row) -> String {
    if table.parameters.is_empty() {
        return String::new();
    }
    let pairs: Vec<String> = table
        .parameters
        .iter()
        .zip(&row.params)
        .map(|(p, v)| format!("{p} = {v}"))
        .collect();
    format!(" ({})", pairs.join(", "))
}

/// Text with `<`, `>`, `&` and quotes escaped for HTML.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The colour of a min_ttc: red at 0 s through yellow to green at ≥ TTC_GREEN; grey when none.
fn ttc_colour(ttc: Option<f64>) -> String {
    match ttc {
        None => "#bbbbbb".into(),
        Some(t) => {
            let u = (t / TTC_GREEN).clamp(0.0, 1.0);
            let (r, g) = if u < 0.5 {
                (220.0, 60.0 + 320.0 * u)
            } else {
                (220.0 - 360.0 * (u - 0.5), 220.0)
            };
            format!("#{:02x}{:02x}3c", r as u8, g as u8)
        }
    }
}

/// The sorted distinct numeric values of parameter column `k`, or `None` if one is no number.
fn numeric_axis(table: &Table, k: usize) -> Option<Vec<f64>> {
    let mut values = Vec::new();
    for row in &table.rows {
        let v: f64 = row
            .params
            .get(k)?
            .trim()
            .parse()
            .ok()
            .filter(|v: &f64| v.is_finite())?;
        values.push(v);
    }
    values.sort_by(f64::total_cmp);
    values.dedup();
    (!values.is_empty()).then_some(values)
}

/// The parameter-space map (module doc) as inline SVG, when one or two numeric parameters vary.
fn map_svg(table: &Table) -> Option<String> {
    let n = table.parameters.len();
    if n == 0 || n > 2 || table.rows.is_empty() {
        return None;
    }
    let xs = numeric_axis(table, 0)?;
    let ys = if n == 2 {
        numeric_axis(table, 1)?
    } else {
        vec![0.0]
    };
    let (cell, left, top) = (36.0, 90.0, 20.0);
    let (w, h) = (
        left + cell * xs.len() as f64 + 20.0,
        top + cell * ys.len() as f64 + 60.0,
    );
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" font-family=\"sans-serif\" font-size=\"11\">"
    );
    let index = |axis: &[f64], v: &str| -> Option<usize> {
        let v: f64 = v.trim().parse().ok()?;
        axis.iter().position(|a| *a == v)
    };
    for row in &table.rows {
        let Some(i) = index(&xs, &row.params[0]) else {
            continue;
        };
        let j = if n == 2 {
            index(&ys, &row.params[1])
        } else {
            Some(0)
        };
        let Some(j) = j else { continue };
        // y grows upwards: the largest value on top.
        let (x, y) = (
            left + cell * i as f64,
            top + cell * (ys.len() - 1 - j) as f64,
        );
        let (fill, title) = match &row.result {
            Ok(o) => (
                ttc_colour(o.min_ttc),
                format!(
                    "variant {}{}: min_ttc {}{}",
                    row.variant,
                    describe(table, row),
                    o.min_ttc
                        .map_or("undefined".into(), |t| format!("{t:.3} s")),
                    if o.collision { ", collision" } else { "" }
                ),
            ),
            Err(e) => (
                "#ffffff".into(),
                format!("variant {} failed: {e}", row.variant),
            ),
        };
        let _ = write!(
            svg,
            "<rect x=\"{x}\" y=\"{y}\" width=\"{cell}\" height=\"{cell}\" fill=\"{fill}\" stroke=\"#ffffff\"><title>{}</title></rect>",
            escape(&title)
        );
        if row.result.as_ref().is_ok_and(|o| o.collision) {
            let (x1, y1, x2, y2) = (x + 8.0, y + 8.0, x + cell - 8.0, y + cell - 8.0);
            let _ = write!(
                svg,
                "<path d=\"M{x1} {y1}L{x2} {y2}M{x2} {y1}L{x1} {y2}\" stroke=\"#000000\" stroke-width=\"2\"/>"
            );
        }
    }
    for (i, v) in xs.iter().enumerate() {
        let x = left + cell * (i as f64 + 0.5);
        let y = top + cell * ys.len() as f64 + 14.0;
        let _ = write!(
            svg,
            "<text x=\"{x}\" y=\"{y}\" text-anchor=\"middle\">{v}</text>"
        );
    }
    let _ = write!(
        svg,
        "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
        left + cell * xs.len() as f64 / 2.0,
        top + cell * ys.len() as f64 + 34.0,
        escape(&table.parameters[0])
    );
    if n == 2 {
        for (j, v) in ys.iter().enumerate() {
            let y = top + cell * (ys.len() - 1 - j) as f64 + cell / 2.0 + 4.0;
            let _ = write!(
                svg,
                "<text x=\"{}\" y=\"{y}\" text-anchor=\"end\">{v}</text>",
                left - 6.0
            );
        }
        let _ = write!(
            svg,
            "<text x=\"12\" y=\"{}\" transform=\"rotate(-90 12 {})\" text-anchor=\"middle\">{}</text>",
            top + cell * ys.len() as f64 / 2.0,
            top + cell * ys.len() as f64 / 2.0,
            escape(&table.parameters[1])
        );
    }
    svg.push_str("</svg>");
    Some(svg)
}

/// Sorting by a header click: numbers numerically, empty cells last, text by text.
const SORT_SCRIPT: &str = r#"
document.querySelectorAll('th').forEach(function (th, col) {
  th.addEventListener('click', function () {
    var body = th.closest('table').tBodies[0];
    var rows = Array.prototype.slice.call(body.rows);
    var dir = th.dataset.dir === 'asc' ? -1 : 1;
    th.dataset.dir = dir === 1 ? 'asc' : 'desc';
    rows.sort(function (a, b) {
      var x = a.cells[col].textContent, y = b.cells[col].textContent;
      if (x === '' || y === '') return (x === '') - (y === '');
      var p = parseFloat(x), q = parseFloat(y);
      var c = (!isNaN(p) && !isNaN(q) && String(p) !== 'NaN') ? p - q : x.localeCompare(y);
      return dir * c;
    });
    rows.forEach(function (r) { body.appendChild(r); });
  });
});
"#;

/// The page (module doc).
pub fn report_html(table: &Table) -> String {
    let mut html = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>oscsim batch results</title>\n<style>body{font-family:sans-serif;margin:1.5em}table{border-collapse:collapse;font-size:13px}th,td{border:1px solid #ccc;padding:2px 6px;text-align:right}th{cursor:pointer;background:#f0f0f0}td.err{text-align:left;color:#a00}tr.collision td{background:#fde8e8}</style></head><body>\n<h1>oscsim batch results</h1>\n",
    );
    let _ = writeln!(html, "<pre>{}</pre>", escape(&summary(table)));
    if let Some(svg) = map_svg(table) {
        let _ = writeln!(
            html,
            "<h2>min_ttc over the parameter space</h2><p>red 0 s to green ≥ {TTC_GREEN} s; grey: no time to collision; crossed: collision.</p>\n{svg}"
        );
    }
    html.push_str(&coverage_html(table));
    html.push_str("<h2>Variants</h2><table><thead><tr>");
    for h in table.header().split(',') {
        let _ = write!(html, "<th>{}</th>", escape(h));
    }
    html.push_str("</tr></thead><tbody>\n");
    // The CSV lines as table rows (the same cells, quoting undone).
    let csv = table.to_csv();
    for (row, line) in table.rows.iter().zip(csv.lines().skip(1)) {
        let collision = row.result.as_ref().is_ok_and(|o| o.collision);
        html.push_str(if collision {
            "<tr class=\"collision\">"
        } else {
            "<tr>"
        });
        let cells = crate::table::split_line(line).unwrap_or_default();
        for (k, cell) in cells.iter().enumerate() {
            let class = if k == 1 + table.parameters.len() + 8 && !cell.is_empty() {
                " class=\"err\""
            } else {
                ""
            };
            let _ = write!(html, "<td{class}>{}</td>", escape(cell));
        }
        html.push_str("</tr>\n");
    }
    let _ = write!(
        html,
        "</tbody></table>\n<script>{SORT_SCRIPT}</script>\n</body></html>\n"
    );
    html
}
