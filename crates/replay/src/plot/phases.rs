//! The phases chart of an OpenSCENARIO DSL run (ASAM OpenSCENARIO DSL 2.1 §7.3.9): one row per
//! phase in the order of the run's manifest (children before their composition, `do` last at
//! the bottom), a bar from the phase's start to its end (`crate::phases`), labelled by its path.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::charts::{color, time_range, DrawResult};
use super::Charts;

/// Draws the chart on `root`.
pub(crate) fn draw<DB: DrawingBackend>(
    c: &Charts<'_>,
    root: &DrawingArea<DB, Shift>,
) -> DrawResult {
    let spans = crate::phases::spans(c.run);
    let (t0, t1) = time_range(c);
    let rows = spans.len().max(1) as f64;
    let mut chart = ChartBuilder::on(root)
        .caption("phases of the do tree", ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(12)
        .build_cartesian_2d(t0..t1, 0.0..rows)
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_desc("time (s)")
        .disable_y_mesh()
        .disable_y_axis()
        .light_line_style(BLACK.mix(0.05))
        .draw()
        .map_err(|e| e.to_string())?;
    for (k, s) in spans.iter().enumerate() {
        let y = rows - k as f64 - 1.0;
        let col = color(s.depth);
        chart
            .draw_series([Rectangle::new(
                [(s.start, y + 0.15), (s.end.max(s.start), y + 0.85)],
                col.mix(0.6).filled(),
            )])
            .map_err(|e| e.to_string())?;
        chart
            .draw_series([Text::new(
                format!("{} ({:.2}–{:.2} s)", s.path, s.start, s.end),
                (s.start, y + 0.5),
                ("sans-serif", 13).into_font().color(&BLACK),
            )])
            .map_err(|e| e.to_string())?;
    }
    Ok(())
}
