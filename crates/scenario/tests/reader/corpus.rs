//! Every scenario of the shared corpus loads (OpenSCENARIO 1.0–1.3 files from esmini and
//! scenariogeneration), except the two broken upstream, which fail naming the missing file.
//! Catalog files (under `Catalogs/`) are loaded through the scenarios that reference them.

use std::path::{Path, PathBuf};

use scenario::{ErrorKind, Scenario};

fn corpus() -> PathBuf {
    Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus"
    ))
    .to_path_buf()
}

fn scenario_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            if p.file_name().is_some_and(|n| n != "Catalogs") {
                scenario_files(&p, out);
            }
        } else if p.extension().is_some_and(|x| x == "xosc") {
            out.push(p);
        }
    }
}

#[test]
fn every_corpus_scenario_loads_except_the_two_broken_ones() {
    let mut files = Vec::new();
    scenario_files(&corpus(), &mut files);
    // 57 esmini scenarios + 20 generated ones (README.md of the corpus lists 57 and 16; the
    // generated folder holds 20 .xosc files).
    assert!(files.len() >= 70, "found only {} scenarios", files.len());
    let mut failures = Vec::new();
    for f in &files {
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        let result = Scenario::load(f);
        match name.as_str() {
            "auto_light.xosc" | "car_walk.xosc" => assert!(result.is_err(), "{name} should fail"),
            _ => {
                if let Err(e) = result {
                    failures.push(format!("{name}: {e}"));
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn auto_light_names_the_missing_catalog_directory() {
    let path = corpus().join("esmini/xosc/auto_light.xosc");
    let err = Scenario::load(&path).unwrap_err();
    let ErrorKind::CatalogNotFound {
        catalog,
        searched,
        missing,
    } = err.kind()
    else {
        panic!("{err}")
    };
    assert_eq!(catalog, "VehicleCatalog");
    // The scenario's only VehicleCatalog directory is `../xosc/Vehicles`, which does not exist.
    assert!(
        searched.iter().any(|d| d.ends_with("xosc/Vehicles")),
        "{err}"
    );
    assert_eq!(missing.len(), 1, "{err}");
    assert!(missing[0].ends_with("esmini/xosc/Vehicles"), "{err}");
    assert!(err.to_string().contains("(no such directory: "), "{err}");
    // Line 20 of auto_light.xosc: `<CatalogReference catalogName="VehicleCatalog" entryName="car_white" />`.
    assert_eq!((err.pos().line, err.pos().col), (20, 10), "{err}");
}

#[test]
fn car_walk_names_the_missing_road_network() {
    let path = corpus().join("esmini/xosc/car_walk.xosc");
    let err = Scenario::load(&path).unwrap_err();
    let ErrorKind::FileNotFound {
        what,
        written,
        resolved,
    } = err.kind()
    else {
        panic!("{err}")
    };
    assert_eq!(*what, "road network");
    assert_eq!(
        written,
        "c:/eknabe1/GIT/esmini_dev/resources/xodr/straight_500m.xodr"
    );
    assert!(resolved.ends_with("c:/eknabe1/GIT/esmini_dev/resources/xodr/straight_500m.xodr"));
    assert!(
        err.to_string()
            .contains("expected road network file 'c:/eknabe1/"),
        "{err}"
    );
    assert_eq!(err.pos().line, 10, "{err}");
}
