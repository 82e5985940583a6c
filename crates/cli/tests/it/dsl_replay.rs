//! `oscsim view` and `oscsim plot` of an OpenSCENARIO DSL scenario (`X.osc --road R.xodr`),
//! loaded through the front door: the page's data and the phases chart name the phases of the
//! `do` tree by their paths (the Acts of the event log), with the intervals the log gives.

use std::path::{Path, PathBuf};
use std::process::Command;

fn repo(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel)
}

fn oscsim(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_oscsim"))
        .args(args)
        .output()
        .expect("oscsim starts");
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn view_and_plot_show_the_phases_of_a_dsl_scenario() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("dsl_replay");
    let _ = std::fs::remove_dir_all(&dir);
    let osc = repo("examples/scenarios/cut_in_highway.osc")
        .display()
        .to_string();
    let road = repo("examples/roads/highway.xodr").display().to_string();
    let page = dir.join("cut_in.html").display().to_string();
    oscsim(&["view", &osc, "--road", &road, "-o", &page]);
    let html = std::fs::read_to_string(&page).expect("the page");
    // The data container's header lists the phases, children before their composition.
    let start = html
        .find(r#"<script id="oscsim-data" type="application/octet-stream">"#)
        .expect("data");
    let data = &html[start..];
    let data = &data[data.find('>').expect("tag") + 1..data.find("</script>").expect("end")];
    let (header, _) = replay::pack::unpack(data).expect("the container reads");
    let phases: Vec<&str> = header["phases"]
        .as_array()
        .expect("phases")
        .iter()
        .filter_map(|p| p.as_str())
        .collect();
    for p in ["do.get_ahead", "do.cut_in", "do.brake"] {
        assert!(phases.contains(&p), "{p} in {phases:?}");
    }
    assert_eq!(phases.last(), Some(&"do"));
    let plots = dir.join("plots").display().to_string();
    let files = oscsim(&["plot", &osc, "--road", &road, "-o", &plots, "--no-png"]);
    assert!(files.contains("phases.svg"), "{files}");
    let svg = std::fs::read_to_string(dir.join("plots/phases.svg")).expect("the chart");
    // The planned times of docs/dsl.md's cut-in: get ahead until the gap rises through 10 m
    // (5.65 s, as the XML cut-in's trigger), the 2 s cut-in, 0.5 s, the 4.25 s brake.
    for label in [
        "do.get_ahead (0.00–5.65 s)",
        "do.cut_in (5.65–7.65 s)",
        "do.brake (8.15–12.40 s)",
        "do (0.00–12.40 s)",
    ] {
        assert!(svg.contains(label), "{label} in the phases chart");
    }
    // An XML run has no phases chart.
    let xosc = repo("examples/scenarios/cut_in_highway.xosc")
        .display()
        .to_string();
    let xml_plots = dir.join("xml_plots").display().to_string();
    let files = oscsim(&["plot", &xosc, "-o", &xml_plots, "--no-png"]);
    assert!(!files.contains("phases"), "{files}");
}
