//! `oscsim plot` on the bundled cut-in: the trajectory SVG parses and holds one line per
//! entity with one point per frame, the speed chart one line per entity; PNGs are written.

use std::path::Path;
use std::process::Command;

fn repo(path: &str) -> String {
    format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"))
}

/// The `points` of every data `<polyline>` of an SVG file: those not black (plotters draws
/// axes and ticks as black polylines; entity lines have the chart palette's colours).
fn polylines(path: &Path) -> Vec<Vec<(f64, f64)>> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let doc =
        roxmltree::Document::parse(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    doc.descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke") != Some("#000000"))
        .map(|n| {
            n.attribute("points")
                .unwrap_or("")
                .split_whitespace()
                .map(|p| {
                    let (x, y) = p.split_once(',').expect("x,y");
                    (x.parse().expect("x"), y.parse().expect("y"))
                })
                .collect()
        })
        .collect()
}

#[test]
fn cut_in_plots_hold_one_line_per_entity() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("replay_plot");
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(env!("CARGO_BIN_EXE_oscsim"))
        .args([
            "plot",
            &repo("examples/scenarios/cut_in_highway.xosc"),
            "-o",
        ])
        .arg(&dir)
        .output()
        .expect("oscsim starts");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // The cut-in runs 10 s at 0.05 s: 201 frames, Ego and OverTaker in every one.
    let lines = polylines(&dir.join("trajectories.svg"));
    assert_eq!(lines.len(), 2, "one line per entity");
    for line in &lines {
        assert!(
            line.len() > 150 && line.len() <= 201,
            "{} points",
            line.len()
        );
    }
    // Both drive left to right on the highway (x grows from 29.5 and 5.0 m to beyond 250 m).
    assert!(lines.iter().all(|l| l.last().expect("points").0 > l[0].0));
    assert_eq!(polylines(&dir.join("speed.svg")).len(), 2);
    // Host chart: distance and TTC from Ego to OverTaker, each drawn (maybe in pieces).
    assert!(!polylines(&dir.join("host.svg")).is_empty());
    for name in ["trajectories", "speed", "host", "conditions"] {
        let png = std::fs::read(dir.join(format!("{name}.png"))).expect("a PNG per chart");
        assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"), "{name}.png");
    }
}

#[test]
fn an_unknown_host_is_an_error_naming_the_entities() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("replay_plot_host");
    let out = Command::new(env!("CARGO_BIN_EXE_oscsim"))
        .args([
            "plot",
            &repo("examples/scenarios/cut_in_highway.xosc"),
            "--no-png",
            "--host",
            "Nobody",
            "-o",
        ])
        .arg(&dir)
        .output()
        .expect("oscsim starts");
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("expected a host among the run's entities (Ego, OverTaker), found 'Nobody'"),
        "{err}"
    );
}
