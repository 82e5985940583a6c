//! Shared helpers of the integration tests: corpus paths and the reference CSV readers.
#![allow(dead_code)]

use std::path::PathBuf;

use opendrive::{GeometryKind, ParamRange, RoadNetwork};

/// The shared test corpus (read-only), relative to this crate.
pub fn corpus() -> PathBuf {
    PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus"
    ))
}

/// A road file of the corpus and its reference data.
pub struct RoadFile {
    /// File stem, e.g. `mixed_geometry`.
    pub name: String,
    /// The `.xodr` file.
    pub xodr: PathBuf,
    /// Reference path without extension (`.csv`, `.lookup.csv` are added).
    pub stem: PathBuf,
}

impl RoadFile {
    /// Loads the network (panics with the loader's message: corpus files must load).
    pub fn load(&self) -> RoadNetwork {
        RoadNetwork::from_file(&self.xodr).unwrap_or_else(|e| panic!("{e}"))
    }
}

/// Every road file of the corpus (`esmini/xodr`, `generated/xodr`), sorted by name.
pub fn road_files() -> Vec<RoadFile> {
    let mut out = Vec::new();
    for group in ["esmini", "generated"] {
        let dir = corpus().join(group).join("xodr");
        let mut names: Vec<_> = std::fs::read_dir(&dir)
            .unwrap_or_else(|e| panic!("corpus folder {} unreadable: {e}", dir.display()))
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "xodr"))
            .collect();
        names.sort();
        for xodr in names {
            let name = xodr
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default();
            let stem = corpus().join("reference/opendrive").join(group).join(&name);
            out.push(RoadFile { name, xodr, stem });
        }
    }
    out
}

/// Rows of a reference CSV (the `#` comment line and the header skipped), split on commas.
pub fn csv_rows(path: &std::path::Path) -> Vec<Vec<String>> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.is_empty())
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

/// A CSV field as f64 (panics with the field on a malformed reference file).
pub fn num(field: &str) -> f64 {
    field
        .parse()
        .unwrap_or_else(|_| panic!("reference field {field:?} is not a number"))
}

/// Simpson steps per paramPoly3 for the arc-length table.
const STEPS: usize = 1000;

/// The s at which oscsim's linear p equals esmini's arc-length p for road `road` at `s`
/// (identity off paramPoly3 geometries).
pub fn esmini_s(net: &RoadNetwork, road: &str, s: f64) -> f64 {
    let Some(r) = net.road(road) else { return s };
    let geoms = r.plan_view.geometries();
    let i = geoms.partition_point(|g| g.s <= s).saturating_sub(1);
    let g = &geoms[i];
    let GeometryKind::ParamPoly3(pp) = &g.kind else {
        return s;
    };
    let p_end = match pp.range {
        ParamRange::ArcLength => g.length,
        ParamRange::Normalized => 1.0,
    };
    let speed = |p: f64| {
        let du = pp.u[1] + p * (2.0 * pp.u[2] + 3.0 * pp.u[3] * p);
        let dv = pp.v[1] + p * (2.0 * pp.v[2] + 3.0 * pp.v[3] * p);
        du.hypot(dv)
    };
    // Cumulative arc length at STEPS nodes by Simpson's rule on each step.
    let h = p_end / STEPS as f64;
    let mut cum = vec![0.0; STEPS + 1];
    for k in 0..STEPS {
        let a = k as f64 * h;
        cum[k + 1] = cum[k] + h / 6.0 * (speed(a) + 4.0 * speed(a + 0.5 * h) + speed(a + h));
    }
    let target = (s - g.s) / g.length * cum[STEPS];
    let k = cum.partition_point(|&c| c <= target).clamp(1, STEPS);
    let (c0, c1) = (cum[k - 1], cum[k]);
    let p = (k - 1) as f64 * h
        + if c1 > c0 {
            (target - c0) / (c1 - c0) * h
        } else {
            0.0
        };
    g.s + p / p_end * g.length
}
