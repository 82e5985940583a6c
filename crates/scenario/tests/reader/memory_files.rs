//! Loading through a [`FileProvider`]: the same files from memory give the same scenario as
//! from disk, and a scenario whose files exist only in memory (catalogs, road network, a
//! distribution's ScenarioFile) loads without touching the disk.

use std::path::{Path, PathBuf};

use scenario::{EntityObject, ErrorKind, MemoryFiles, Scenario};

fn files_dir() -> PathBuf {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/files")).to_path_buf()
}

/// `catalog_kinds.xosc` and every catalog file, read from disk, inserted under `root`.
fn catalog_kinds_in_memory(root: &Path) -> MemoryFiles {
    let dir = files_dir();
    let mut m = MemoryFiles::new();
    let main = std::fs::read(dir.join("catalog_kinds.xosc")).unwrap();
    m.insert(root.join("catalog_kinds.xosc"), main);
    for kind in std::fs::read_dir(dir.join("catalogs")).unwrap() {
        let kind = kind.unwrap().path();
        for f in std::fs::read_dir(&kind).unwrap() {
            let f = f.unwrap().path();
            let rel = f.strip_prefix(&dir).unwrap();
            m.insert(root.join(rel), std::fs::read(&f).unwrap());
        }
    }
    m
}

#[test]
fn memory_files_at_the_disk_paths_load_the_same_scenario_as_the_disk() {
    let dir = files_dir();
    let from_disk = Scenario::load(&dir.join("catalog_kinds.xosc")).unwrap();
    let m = catalog_kinds_in_memory(&dir);
    let from_memory = Scenario::load_with_files(&m, &dir.join("catalog_kinds.xosc"), &[]).unwrap();
    assert_eq!(from_disk, from_memory);
}

#[test]
fn catalogs_that_exist_only_in_memory_are_read() {
    let root = Path::new("/nowhere-on-disk/oscsim");
    let m = catalog_kinds_in_memory(root);
    let s = Scenario::load_with_files(&m, &root.join("catalog_kinds.xosc"), &[]).unwrap();
    let truck = match &s.entities.object("Truck").unwrap().entity_object {
        EntityObject::Vehicle(v) => v.clone(),
        other => panic!("{other:?}"),
    };
    // catalog_kinds.xosc assigns MaxSpeed := $TruckTop = 30 (tests/catalogs.rs).
    assert!((truck.performance.max_speed - 30.0).abs() < 1e-12);
}

const MINIMAL: &str = r#"<?xml version="1.0"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="3" date="2026-01-01" description="m" author="t"/>
  <RoadNetwork><LogicFile filepath="../roads/r.xodr"/></RoadNetwork>
  <Entities/>
  <Storyboard><Init><Actions/></Init><StopTrigger/></Storyboard>
</OpenSCENARIO>"#;

#[test]
fn the_road_network_must_exist_in_the_provider() {
    let mut m = MemoryFiles::new();
    m.insert("/mem/xosc/s.xosc", MINIMAL);
    let e = Scenario::load_with_files(&m, Path::new("/mem/xosc/s.xosc"), &[]).unwrap_err();
    match e.kind() {
        ErrorKind::FileNotFound { resolved, .. } => {
            assert_eq!(resolved, Path::new("/mem/roads/r.xodr"))
        }
        other => panic!("{other:?}"),
    }
    // Line 4: 2 spaces, `<RoadNetwork>` (13), `<LogicFile ` (11), `filepath="` (10), so the
    // value starts at column 37.
    assert_eq!((e.pos().line, e.pos().col), (4, 37));
    m.insert("/mem/roads/r.xodr", "<OpenDRIVE/>");
    let s = Scenario::load_with_files(&m, Path::new("/mem/xosc/s.xosc"), &[]).unwrap();
    assert_eq!(
        s.road_network.logic_file.as_deref(),
        Some(Path::new("/mem/roads/r.xodr"))
    );
}

#[test]
fn a_distribution_loads_its_scenario_file_from_memory() {
    let dist = r#"<?xml version="1.0"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="3" date="2026-01-01" description="d" author="t"/>
  <ParameterValueDistribution>
    <ScenarioFile filepath="s.xosc"/>
    <Deterministic/>
  </ParameterValueDistribution>
</OpenSCENARIO>"#;
    let mut m = MemoryFiles::new();
    m.insert("/mem/xosc/d.xosc", dist)
        .insert("/mem/xosc/s.xosc", MINIMAL)
        .insert("/mem/roads/r.xodr", "<OpenDRIVE/>");
    let s = Scenario::load_with_files(&m, Path::new("/mem/xosc/d.xosc"), &[]).unwrap();
    assert_eq!(s.path, Path::new("/mem/xosc/s.xosc"));
    assert_eq!(
        s.parameter_value_distribution.as_deref(),
        Some(Path::new("/mem/xosc/d.xosc"))
    );
}
