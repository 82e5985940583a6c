//! `Scenario::with_parameters`: a variant of a loaded scenario with other global parameter
//! values (OpenSCENARIO 1.3 §9.1), resolved again from the files kept in memory at the first
//! load — through catalog parameter assignments too (§9.4) — without reading a file: the
//! files are deleted before the variants are made.

use std::fs;
use std::path::{Path, PathBuf};

use scenario::{EntityObject, Scenario};

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/files")
}

fn copy_dir(from: &Path, to: &Path) {
    fs::create_dir_all(to).expect("temp dir");
    for entry in fs::read_dir(from).expect("fixture dir") {
        let path = entry.expect("entry").path();
        let target = to.join(path.file_name().expect("named"));
        if path.is_dir() {
            copy_dir(&path, &target);
        } else {
            fs::copy(&path, &target).expect("copy");
        }
    }
}

/// `MaxSpeed` of the Truck: its catalog entry's parameter, assigned `$TruckTop`.
fn truck_max_speed(s: &Scenario) -> f64 {
    match &s.entities.object("Truck").expect("declared").entity_object {
        EntityObject::Vehicle(v) => v.performance.max_speed,
        other => panic!("{other:?}"),
    }
}

fn pair(name: &str, value: &str) -> (String, String) {
    (name.to_owned(), value.to_owned())
}

#[test]
fn variants_are_resolved_from_memory_as_from_disk() {
    // Removed below to show that variants read no file; on a failure before, at the drop.
    let tmp = tempfile::Builder::new()
        .prefix("oscsim-with-parameters-")
        .tempdir()
        .expect("temp dir");
    let dir = tmp.path();
    copy_dir(&fixtures().join("catalogs"), &dir.join("catalogs"));
    let path = dir.join("catalog_kinds.xosc");
    fs::copy(fixtures().join("catalog_kinds.xosc"), &path).expect("copy");

    let base = Scenario::load(&path).expect("loads");
    let from_disk =
        Scenario::load_with_parameters(&path, &[pair("TruckTop", "42")]).expect("loads");
    fs::remove_dir_all(dir).expect("temp dir removed");
    assert!(!path.exists());

    // catalog_kinds.xosc declares TruckTop = 30; the Truck's MaxSpeed is assigned $TruckTop.
    assert_eq!(truck_max_speed(&base), 30.0);
    let variant = base
        .with_parameters(&[pair("TruckTop", "42")])
        .expect("resolved from memory");
    assert_eq!(truck_max_speed(&variant), 42.0);
    // The whole model, positions and sources included, as loaded from disk with the override.
    assert_eq!(variant, from_disk);
    assert_eq!(variant.sources.overrides(), [pair("TruckTop", "42")]);

    // Overrides stack: a name given again takes the new value.
    let again = variant
        .with_parameters(&[pair("TruckTop", "50")])
        .expect("resolved from memory");
    assert_eq!(truck_max_speed(&again), 50.0);
    assert_eq!(again.sources.overrides(), [pair("TruckTop", "50")]);

    // Errors are those of a load with the same overrides.
    let undeclared = base
        .with_parameters(&[pair("NoSuchParameter", "1")])
        .expect_err("undeclared");
    assert!(
        undeclared.to_string().contains("NoSuchParameter"),
        "{undeclared}"
    );
    // TruckTop = "fast" (a string where the catalog divides it) fails in the catalog file.
    let bad = base
        .with_parameters(&[pair("TruckTop", "fast")])
        .expect_err("not a number");
    assert!(bad.to_string().contains("TestVehicles.xosc:"), "{bad}");
}
