//! The trajectories, speed, host and conditions charts, drawn on any plotters backend (SVG
//! or bitmap), and what the charts share (line colours, the run's time range). Entity lines are the only
//! coloured polylines of the trajectory chart (axes and ticks are black ones, road lane areas
//! polygons, legend marks rectangles), so a reader of the SVG finds one per entity.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::Charts;
use crate::measures::Series;

/// Line colours, one per entity in track order (Tableau 10).
const COLORS: [RGBColor; 10] = [
    RGBColor(78, 121, 167),
    RGBColor(242, 142, 43),
    RGBColor(225, 87, 89),
    RGBColor(118, 183, 178),
    RGBColor(89, 161, 79),
    RGBColor(237, 201, 72),
    RGBColor(176, 122, 161),
    RGBColor(255, 157, 167),
    RGBColor(156, 117, 95),
    RGBColor(186, 176, 172),
];

/// The colour of line number `k`.
pub(crate) fn color(k: usize) -> RGBColor {
    COLORS[k % COLORS.len()]
}

/// Legends list at most this many entries (a 200-entity run would bury the chart).
const LEGEND_MAX: usize = 12;

pub(crate) type DrawResult = Result<(), String>;

/// A line of a time chart: label, colour, and its defined stretches of (t, value) points.
type Line = (String, RGBColor, Vec<Vec<(f64, f64)>>);

/// Extent of `values` with a margin; (0, 1) when empty.
fn extent(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = ((hi - lo) * 0.05).max(0.5);
    (lo - pad, hi + pad)
}

/// Paths of every entity over the road's lane areas, with equal scales on x and y.
pub(super) fn trajectories<DB: DrawingBackend>(
    c: &Charts<'_>,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let tracks = &c.run.trajectories.tracks;
    let xs = tracks
        .iter()
        .flat_map(|t| t.samples.iter().map(|s| s.pose[0]));
    let ys = tracks
        .iter()
        .flat_map(|t| t.samples.iter().map(|s| s.pose[1]));
    let (mut x0, mut x1) = extent(xs);
    let (mut y0, mut y1) = extent(ys);
    // Equal metres per pixel on both axes: widen the narrower range.
    let (w, h) = root.dim_in_pixel();
    let (pw, ph) = (
        f64::from(w.saturating_sub(120)),
        f64::from(h.saturating_sub(110)),
    );
    let scale = ((x1 - x0) / pw).max((y1 - y0) / ph);
    let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
    (x0, x1) = (cx - scale * pw / 2.0, cx + scale * pw / 2.0);
    (y0, y1) = (cy - scale * ph / 2.0, cy + scale * ph / 2.0);
    let mut chart = ChartBuilder::on(root)
        .caption(format!("{}: trajectories", c.run.title), ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_desc("x (m)")
        .y_desc("y (m)")
        .disable_mesh()
        .draw()
        .map_err(|e| e.to_string())?;
    let lane_fill = RGBColor(214, 214, 214).filled();
    for sec in c.roads.roads.iter().flat_map(|r| &r.sections) {
        for lane in &sec.lanes {
            let outer = &sec.borders[lane.outer];
            let inner = &sec.borders[lane.inner];
            let ring: Vec<(f64, f64)> = outer
                .iter()
                .chain(inner.iter().rev())
                .map(|p| (p[0], p[1]))
                .filter(|p| p.0 >= x0 - scale * pw && p.0 <= x1 + scale * pw)
                .collect();
            if ring.len() >= 3 {
                chart
                    .draw_series(std::iter::once(Polygon::new(ring, lane_fill)))
                    .map_err(|e| e.to_string())?;
            }
        }
    }
    for (k, t) in tracks.iter().enumerate() {
        let style = color(k).stroke_width(2);
        let series = chart
            .draw_series(LineSeries::new(
                t.samples.iter().map(|s| (s.pose[0], s.pose[1])),
                style,
            ))
            .map_err(|e| e.to_string())?;
        if k < LEGEND_MAX {
            series.label(t.name.clone()).legend(move |(x, y)| {
                Rectangle::new([(x, y - 4), (x + 16, y + 4)], color(k).filled())
            });
        }
    }
    legend(&mut chart)
}

/// Draws the legend box in the upper right.
fn legend<'a, DB: DrawingBackend + 'a, X: Ranged, Y: Ranged>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<X, Y>>,
) -> DrawResult {
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.3))
        .label_font(("sans-serif", 14))
        .draw()
        .map_err(|e| e.to_string())
}

/// Time range of the run.
pub(crate) fn time_range(c: &Charts<'_>) -> (f64, f64) {
    let t = &c.run.trajectories.times;
    let (a, b) = (
        t.first().copied().unwrap_or(0.0),
        t.last().copied().unwrap_or(1.0),
    );
    (a, if b > a { b } else { a + 1.0 })
}

/// Draws `lines` (label, colour, (t, value) points) as a time chart.
fn time_chart<DB: DrawingBackend>(
    c: &Charts<'_>,
    area: &DrawingArea<DB, Shift>,
    caption: &str,
    y_desc: &str,
    lines: &[Line],
    thresholds: &[(String, f64)],
) -> DrawResult {
    let (t0, t1) = time_range(c);
    let values = lines
        .iter()
        .flat_map(|l| l.2.iter().flatten().map(|p| p.1))
        .chain(thresholds.iter().map(|t| t.1));
    let (y0, y1) = extent(values);
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(60)
        .build_cartesian_2d(t0..t1, y0..y1)
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_desc("time (s)")
        .y_desc(y_desc)
        .light_line_style(BLACK.mix(0.05))
        .draw()
        .map_err(|e| e.to_string())?;
    for (k, (label, col, runs)) in lines.iter().enumerate() {
        let col = *col;
        for (j, run) in runs.iter().enumerate() {
            let s = chart
                .draw_series(LineSeries::new(run.iter().copied(), col.stroke_width(2)))
                .map_err(|e| e.to_string())?;
            if j == 0 && k < LEGEND_MAX {
                s.label(label.clone()).legend(move |(x, y)| {
                    Rectangle::new([(x, y - 4), (x + 16, y + 4)], col.filled())
                });
            }
        }
    }
    for (label, v) in thresholds {
        chart
            .draw_series(DashedLineSeries::new(
                [(t0, *v), (t1, *v)],
                6,
                4,
                BLACK.mix(0.6).stroke_width(1),
            ))
            .map_err(|e| e.to_string())?
            .label(label.clone())
            .legend(|(x, y)| {
                Rectangle::new([(x, y - 1), (x + 16, y + 1)], BLACK.mix(0.6).filled())
            });
    }
    if lines.iter().any(|l| !l.2.is_empty()) || !thresholds.is_empty() {
        legend(&mut chart)?;
    }
    Ok(())
}

/// Speed over time, one line per entity.
pub(super) fn speed<DB: DrawingBackend>(
    c: &Charts<'_>,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let times = &c.run.trajectories.times;
    let lines: Vec<_> = c
        .run
        .trajectories
        .tracks
        .iter()
        .enumerate()
        .map(|(k, t)| {
            let pts = t
                .samples
                .iter()
                .map(|s| (times[s.frame as usize], s.speed))
                .collect();
            (t.name.clone(), color(k), vec![pts])
        })
        .collect();
    let caption = format!("{}: speed", c.run.title);
    time_chart(c, root, &caption, "speed (m/s)", &lines, &[])
}

/// The defined stretches of a series as (t, value) runs.
fn runs(c: &Charts<'_>, s: &Series) -> Vec<Vec<(f64, f64)>> {
    let times = &c.run.trajectories.times;
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut current = Vec::new();
    for (k, v) in s.values.iter().enumerate() {
        match v {
            Some(v) => current.push((times[k], *v)),
            None if !current.is_empty() => out.push(std::mem::take(&mut current)),
            None => {}
        }
    }
    if !current.is_empty() {
        out.push(current);
    }
    out
}

/// Box distance (top) and time to collision (bottom) from the host to the others.
pub(super) fn host<DB: DrawingBackend>(
    c: &Charts<'_>,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let Some((host, pairs)) = &c.host else {
        return Ok(());
    };
    let names: Vec<&str> = c
        .run
        .trajectories
        .tracks
        .iter()
        .map(|t| t.name.as_str())
        .collect();
    let col = |other: &str| color(names.iter().position(|n| *n == other).unwrap_or(0));
    let (top, bottom) = root.split_vertically(root.dim_in_pixel().1 / 2);
    let distances: Vec<_> = pairs
        .iter()
        .map(|(o, d, _)| (o.clone(), col(o), runs(c, d)))
        .collect();
    let ttcs: Vec<_> = pairs
        .iter()
        .map(|(o, _, t)| (o.clone(), col(o), runs(c, t)))
        .collect();
    time_chart(
        c,
        &top,
        &format!("{}: distance from {host} (bounding boxes)", c.run.title),
        "distance (m)",
        &distances,
        &[],
    )?;
    let none = if ttcs.iter().all(|l| l.2.is_empty()) {
        ": none in this run"
    } else {
        ""
    };
    time_chart(
        c,
        &bottom,
        &format!("time to collision from {host} (boxes, current velocities){none}"),
        "TTC (s)",
        &ttcs,
        &[],
    )
}

/// The conditions' quantities, one panel per series with its thresholds.
pub(super) fn conditions<DB: DrawingBackend>(
    c: &Charts<'_>,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let n = c.conditions.len().max(1);
    let panels = root.split_evenly((n, 1));
    for (k, (s, area)) in c.conditions.iter().zip(panels.iter()).enumerate() {
        let caption = format!(
            "{} → {}: {} ({}, {}{}) by {}",
            s.spec.entity,
            s.spec.reference,
            s.spec.quantity,
            s.spec.coordinate_system,
            s.spec.relative_distance_type,
            if s.spec.freespace { ", freespace" } else { "" },
            s.method
        );
        let thresholds: Vec<(String, f64)> = s
            .thresholds
            .iter()
            .map(|(cond, rule, v)| (format!("{cond}: {rule} {v}"), *v))
            .collect();
        let lines = vec![(s.spec.entity.clone(), color(k), runs(c, s))];
        time_chart(c, area, &caption, s.unit, &lines, &thresholds)?;
    }
    Ok(())
}
