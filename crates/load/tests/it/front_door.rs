//! The front door: either language through one function, errors at their file:line:col.

use std::path::{Path, PathBuf};

use crate::repo;

use engine::output::CsvWriter;
use engine::{Engine, EngineConfig};

fn scratch(name: &str, text: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("load_front_door");
    std::fs::create_dir_all(&dir).expect("scratch folder");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("scratch file");
    path
}

/// The trajectory CSV of a run of `loaded` (default step and seed).
fn csv(loaded: &load::Loaded) -> String {
    let mut engine = Engine::new(
        &loaded.scenario,
        loaded.network.clone(),
        EngineConfig::default(),
    )
    .expect("builds");
    let mut out = CsvWriter::new(Vec::new());
    engine.run(&mut out, &mut ()).expect("runs");
    String::from_utf8(out.into_inner()).expect("UTF-8")
}

fn dsl_options(seed: u64) -> load::Options {
    load::Options {
        road: Some(repo("examples/roads/highway.xodr")),
        seed,
        ..load::Options::default()
    }
}

#[test]
fn either_language_loads_through_one_function() {
    let xml = load::load(
        &repo("examples/scenarios/cut_in_highway.xosc"),
        &load::Options::default(),
    )
    .expect("the XML cut-in loads");
    assert_eq!(xml.language, load::Language::Xml);
    assert!(xml.phases.is_empty());
    let direct = scenario::Scenario::load(&repo("examples/scenarios/cut_in_highway.xosc"))
        .expect("loads directly");
    assert_eq!(
        xml.scenario, direct,
        "the front door reads XML as the reader does"
    );

    let osc = repo("examples/scenarios/cut_in_highway.osc");
    let dsl = load::load(&osc, &dsl_options(1)).expect("the DSL cut-in loads");
    assert_eq!(dsl.language, load::Language::Dsl);
    // The plan's phases by path: the do tree (docs/dsl.md), children before their composition.
    let paths: Vec<&str> = dsl.phases.iter().map(|p| p.path.as_str()).collect();
    for p in ["do", "do.get_ahead", "do.cut_in", "do.brake"] {
        assert!(paths.contains(&p), "{p} in {paths:?}");
    }
    assert_eq!(paths.last(), Some(&"do"));
    // The same program, seed and road through dsl_runtime's own loader: the same model.
    let runtime = dsl_runtime::load(
        &osc,
        Some(&repo("examples/roads/highway.xodr")),
        &dsl_runtime::Options {
            seed: 1,
            dt: engine::runtime::DEFAULT_DT,
            open_end: false,
            scenario: None,
        },
    )
    .expect("dsl_runtime loads it");
    assert_eq!(dsl.scenario, runtime.scenario);
    // Both cut-ins run two vehicles (the CSV's second column is the entity id).
    let ids = |text: String| {
        let mut ids: Vec<String> = text
            .lines()
            .skip(1)
            .filter_map(|l| l.split(',').nth(1).map(str::to_owned))
            .collect();
        ids.sort();
        ids.dedup();
        ids.len()
    };
    assert_eq!((ids(csv(&dsl)), ids(csv(&xml))), (2, 2));
}

#[test]
fn a_source_opened_once_loads_each_seed_as_a_fresh_load_does() {
    let osc = repo("examples/scenarios/cut_in_highway.osc");
    let source = load::Source::open(&osc, &dsl_options(1)).expect("opens");
    for seed in [1, 7, 12345] {
        let once = source.load(seed).expect("loads");
        let fresh = load::load(&osc, &dsl_options(seed)).expect("loads");
        assert_eq!(once.scenario, fresh.scenario, "seed {seed}");
        assert!(std::sync::Arc::ptr_eq(&once.network, source.network()));
    }
}

#[test]
fn bad_input_is_an_error_at_its_place() {
    let osc = repo("examples/scenarios/cut_in_highway.osc");
    // No road network: the .osc names none with set_map_file.
    let e = load::load(&osc, &load::Options::default()).expect_err("no road");
    assert!(
        e.to_string().starts_with("expected a road network")
            && e.to_string().ends_with("cut_in_highway.osc:1:1"),
        "{e}"
    );
    // Options of the other language.
    let xosc = repo("examples/scenarios/cut_in_highway.xosc");
    let e = load::load(&xosc, &dsl_options(1)).expect_err("an XML scenario names its road");
    assert!(matches!(e.kind(), load::ErrorKind::Option { .. }), "{e}");
    assert_eq!(e.pos().map(|p| (p.line, p.col)), Some((1, 1)));
    let e = load::load(
        &osc,
        &load::Options {
            params: vec![("EgoSpeed".into(), "20".into())],
            ..dsl_options(1)
        },
    )
    .expect_err("a DSL scenario takes no overrides");
    assert!(e.to_string().contains("found 'EgoSpeed'"), "{e}");
    // A check error: a plain number where a length is expected, at line 3, column 10.
    let bad = scratch(
        "plain_number.osc",
        "scenario s:\n    d: length\n    keep(d > 5)\n",
    );
    let e = load::load(&bad, &dsl_options(1)).expect_err("a type error");
    assert!(matches!(e.kind(), load::ErrorKind::Check(_)), "{e}");
    let pos = e.pos().expect("a place");
    assert_eq!((pos.file.as_ref(), pos.line), (bad.as_path(), 3), "{e}");
    // A plan error: nothing to run.
    let none = scratch("no_do.osc", "scenario s:\n    d: length\n");
    let e = load::load(&none, &dsl_options(1)).expect_err("no do");
    assert!(matches!(e.kind(), load::ErrorKind::Plan(_)), "{e}");
    assert!(e.to_string().contains("no_do.osc:1:1"), "{e}");
    // A road network that does not exist.
    let e = load::load(
        &osc,
        &load::Options {
            road: Some(repo("examples/roads/missing.xodr")),
            ..dsl_options(1)
        },
    )
    .expect_err("no such road file");
    assert!(matches!(e.kind(), load::ErrorKind::RoadNetwork(_)), "{e}");
    // A missing XML file.
    let e = load::load(
        &repo("examples/scenarios/missing.xosc"),
        &load::Options::default(),
    )
    .expect_err("no such scenario");
    assert!(matches!(e.kind(), load::ErrorKind::Scenario(_)), "{e}");
}
