//! Static charts of a run for reports and CI artifacts, drawn with plotters, each as SVG and
//! (optionally) PNG:
//!
//! | file | chart |
//! | --- | --- |
//! | `trajectories` | every entity's path (one line each) over the road's lane areas |
//! | `speed` | speed over time, one line per entity |
//! | `host` | bounding-box distance and time to collision from the host to every other entity |
//! | `conditions` | the gaps and times the scenario's conditions measure, with their thresholds (only when it has such conditions) |
//! | `phases` | an OpenSCENARIO DSL run's phases of the `do` tree over time, a bar per phase labelled by its path (only for DSL runs) |
//!
//! Text in both formats is laid out with the DejaVu Sans subset bundled in `fonts/`, so the
//! charts look the same on every machine and need no system fonts.
//!
//! | module | job |
//! | --- | --- |
//! | `charts` | the trajectories, speed, host and conditions charts on any plotters backend; line colours and the time range |
//! | `phases` | the phases chart |
//! | `bitmap` | the font and the PNG encoding |

mod bitmap;
mod charts;
mod phases;

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

use self::charts::DrawResult;
use crate::error::{Error, ErrorKind, Result};
use crate::manifest::MeasureSpec;
use crate::measures::{self, Series};
use crate::road::RoadDrawing;
use crate::run::Run;

/// What to draw.
#[derive(Debug, Clone)]
pub struct PlotOptions {
    /// The host of the `host` chart (default `Ego`, else the first entity).
    pub host: Option<String>,
    /// Also write PNG files.
    pub png: bool,
    /// Size in pixels.
    pub size: (u32, u32),
}

impl Default for PlotOptions {
    fn default() -> Self {
        PlotOptions {
            host: None,
            png: true,
            size: (1200, 800),
        }
    }
}

/// The host's name and, per other entity, its name, distance and TTC series.
pub(crate) type HostSeries = (String, Vec<(String, Series, Series)>);

/// What the charts show, computed once for both formats.
pub(crate) struct Charts<'a> {
    pub run: &'a Run,
    pub roads: RoadDrawing,
    /// The host's name and its distance and TTC series to every other entity.
    pub host: Option<HostSeries>,
    pub conditions: Vec<Series>,
}

/// The charts, in the order they are written.
pub(crate) const ALL: [Chart; 5] = [
    Chart::Trajectories,
    Chart::Speed,
    Chart::Host,
    Chart::Conditions,
    Chart::Phases,
];

/// One chart.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Chart {
    Trajectories,
    Speed,
    Host,
    Conditions,
    Phases,
}

impl Chart {
    /// The file stem.
    pub(crate) fn name(self) -> &'static str {
        match self {
            Chart::Trajectories => "trajectories",
            Chart::Speed => "speed",
            Chart::Host => "host",
            Chart::Conditions => "conditions",
            Chart::Phases => "phases",
        }
    }

    /// Whether the run has anything to show in this chart.
    pub(crate) fn applies(self, c: &Charts<'_>) -> bool {
        match self {
            Chart::Host => c.host.as_ref().is_some_and(|(_, p)| !p.is_empty()),
            Chart::Conditions => !c.conditions.is_empty(),
            Chart::Phases => !c.run.manifest.phases.is_empty(),
            _ => true,
        }
    }

    /// Draws the chart on `root`.
    pub(crate) fn draw<DB: DrawingBackend>(
        self,
        c: &Charts<'_>,
        root: DrawingArea<DB, Shift>,
    ) -> DrawResult {
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        match self {
            Chart::Trajectories => charts::trajectories(c, &root),
            Chart::Speed => charts::speed(c, &root),
            Chart::Host => charts::host(c, &root),
            Chart::Conditions => charts::conditions(c, &root),
            Chart::Phases => phases::draw(c, &root),
        }?;
        root.present().map_err(|e| e.to_string())
    }
}

/// A spec measuring `quantity` from `host` to `other` between boxes.
fn host_spec(quantity: &str, host: &str, other: &str) -> MeasureSpec {
    MeasureSpec {
        condition: String::new(),
        quantity: quantity.to_owned(),
        entity: host.to_owned(),
        reference: other.to_owned(),
        freespace: true,
        coordinate_system: "entity".to_owned(),
        relative_distance_type: "euclidianDistance".to_owned(),
        rule: String::new(),
        value: 0.0,
    }
}

/// Draws every chart of `run` into folder `dir` (created if needed); returns the files
/// written.
pub fn plot(run: &Run, dir: &Path, options: &PlotOptions) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).map_err(|e| Error::io("cannot create", dir, e))?;
    bitmap::register_font()?;
    let names: Vec<&str> = run
        .trajectories
        .tracks
        .iter()
        .map(|t| t.name.as_str())
        .collect();
    let host = match &options.host {
        Some(h) if names.contains(&h.as_str()) => Some(h.clone()),
        Some(h) => {
            return Err(Error::new(ErrorKind::Plot(format!(
                "expected a host among the run's entities ({}), found '{h}'",
                names.join(", ")
            ))))
        }
        None => names
            .iter()
            .find(|n| **n == "Ego")
            .or(names.first())
            .map(|n| n.to_string()),
    };
    let host = host.map(|h| {
        let pairs = names
            .iter()
            .filter(|n| **n != h)
            .map(|other| {
                let d = measures::series_of(run, &host_spec("relativeDistance", &h, other));
                let ttc = measures::series_of(run, &host_spec("timeToCollision", &h, other));
                (other.to_string(), d, ttc)
            })
            .collect();
        (h, pairs)
    });
    let charts = Charts {
        run,
        roads: run
            .network
            .as_ref()
            .map(|n| RoadDrawing::new(n))
            .unwrap_or_default(),
        host,
        conditions: measures::series(run),
    };
    let mut written = Vec::new();
    for chart in ALL {
        if !chart.applies(&charts) {
            continue;
        }
        let svg = dir.join(format!("{}.svg", chart.name()));
        {
            let root = SVGBackend::new(&svg, options.size).into_drawing_area();
            chart
                .draw(&charts, root)
                .map_err(|e| Error::new(ErrorKind::Plot(format!("{}: {e}", svg.display()))))?;
        }
        written.push(svg);
        if options.png {
            let png = dir.join(format!("{}.png", chart.name()));
            bitmap::write_png(&png, options.size, |root| chart.draw(&charts, root))?;
            written.push(png);
        }
    }
    Ok(written)
}
