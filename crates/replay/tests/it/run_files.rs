//! A run opened from what `oscsim run` writes equals the same run made in memory, and the
//! conditions' series agree with the event log: the cut-in's OverTakerAhead
//! (RelativeDistanceCondition, road, longitudinal, freespace, greaterThan 10, rising edge)
//! starts CutInEvent at 5.650 s, so its distance is above 10 m at 5.65 s and not at 5.60 s.

use std::path::{Path, PathBuf};

use engine::output::{CsvWriter, JsonlWriter};
use engine::{Engine, EngineConfig};
use replay::recorder::EntityCatalog;
use replay::{manifest_for, OpenOptions, Run, RunManifest};

fn cut_in() -> PathBuf {
    PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/scenarios/cut_in_highway.xosc"
    ))
}

/// Writes the cut-in's CSV, log and manifest into `dir` as `oscsim run --csv --events` does.
fn write_run(dir: &Path) -> PathBuf {
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir).expect("scratch folder");
    let loaded = load::load(&cut_in(), &load::Options::default()).expect("the cut-in loads");
    let config = EngineConfig::default();
    let mut engine = Engine::new(&loaded.scenario, loaded.network.clone(), config).expect("builds");
    let csv = dir.join("cut_in.csv");
    let mut frames: Vec<Box<dyn engine::FrameSink>> = vec![Box::new(CsvWriter::new(
        std::fs::File::create(&csv).expect("csv"),
    ))];
    let catalog = std::rc::Rc::new(std::cell::RefCell::new(EntityCatalog::new()));
    struct Shared(std::rc::Rc<std::cell::RefCell<EntityCatalog>>);
    impl engine::FrameSink for Shared {
        fn frame(&mut self, f: &engine::Frame<'_>) -> Result<(), engine::SinkError> {
            self.0.borrow_mut().frame(f)
        }
    }
    frames.push(Box::new(Shared(catalog.clone())));
    let mut log = JsonlWriter::new(std::fs::File::create(dir.join("cut_in.jsonl")).expect("log"));
    engine.run(&mut frames, &mut log).expect("runs");
    drop(frames);
    let entities = std::rc::Rc::try_unwrap(catalog)
        .expect("the run dropped its sinks")
        .into_inner()
        .into_entities();
    let mut m = manifest_for(&loaded, &cut_in(), &[], &config, entities, dir);
    m.trajectories = Some("cut_in.csv".into());
    m.events = Some("cut_in.jsonl".into());
    m.write(&RunManifest::beside(&csv)).expect("manifest");
    csv
}

#[test]
fn a_run_from_files_equals_the_run_in_memory() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("replay_run_files");
    let csv = write_run(&dir);
    let from_files = Run::open(&csv, &OpenOptions::default()).expect("opens");
    let in_memory = Run::simulate(
        &cut_in(),
        &load::Options::default(),
        EngineConfig::default(),
    )
    .expect("runs");
    assert_eq!(from_files.trajectories, in_memory.trajectories);
    assert_eq!(from_files.events, in_memory.events);
    assert_eq!(from_files.manifest.entities, in_memory.manifest.entities);
    assert_eq!(
        replay::html::render(&from_files),
        replay::html::render(&in_memory)
    );
    // Manifest paths are relative to its folder.
    let m = RunManifest::read(&RunManifest::beside(&csv)).expect("reads");
    assert!(
        m.scenario.as_ref().is_some_and(|p| p.is_relative()),
        "{:?}",
        m.scenario
    );
    assert_eq!(m.entities[0].box_size, [5.0, 2.0, 1.5]);
    assert_eq!(m.entities[1].color, Some([255, 0, 0]));
}

#[test]
fn the_cut_in_condition_series_crosses_its_threshold_when_the_event_starts() {
    let run = Run::simulate(
        &cut_in(),
        &load::Options::default(),
        EngineConfig::default(),
    )
    .expect("runs");
    let start = run
        .events
        .iter()
        .find(|e| e.element == "CutInEvent" && e.transition.as_deref() == Some("start"))
        .expect("CutInEvent starts");
    assert_eq!(start.time, 5.65);
    let series = replay::measures::series(&run);
    assert_eq!(series.len(), 1);
    let s = &series[0];
    assert_eq!(
        (s.spec.entity.as_str(), s.spec.reference.as_str()),
        ("OverTaker", "Ego")
    );
    assert_eq!(
        s.thresholds,
        vec![("OverTakerAhead".to_owned(), "greaterThan".to_owned(), 10.0)]
    );
    let frame = |t: f64| {
        run.trajectories
            .times
            .iter()
            .position(|&x| (x - t).abs() < 1e-9)
            .expect("a frame")
    };
    let at = |t: f64| s.values[frame(t)].expect("both on the road");
    assert!(at(5.65) > 10.0, "{}", at(5.65));
    assert!(at(5.60) <= 10.0, "{}", at(5.60));
}

#[test]
fn a_csv_without_manifest_needs_the_scenario() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("replay_no_manifest");
    let csv = write_run(&dir);
    std::fs::remove_file(RunManifest::beside(&csv)).expect("remove the manifest");
    let err = Run::open(&csv, &OpenOptions::default()).expect_err("no manifest");
    assert!(err.to_string().starts_with("no run manifest"), "{err}");
    let run = Run::open(
        &csv,
        &OpenOptions {
            scenario: Some(cut_in()),
            events: None,
        },
    )
    .expect("opens with the scenario");
    assert_eq!(run.manifest.entities[0].box_size, [5.0, 2.0, 1.5]);
    assert!(run.network.is_some());
}

/// The shared corpus beside the repository.
fn corpus(path: &str) -> PathBuf {
    PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus"
    ))
    .join(path)
}

#[test]
fn spawned_traffic_appears_and_leaves() {
    // esmini's swarm.xosc: a TrafficSwarmAction spawns vehicles around Ego and removes those
    // that fall outside its radius.
    let config = EngineConfig {
        duration: Some(20.0),
        ..EngineConfig::default()
    };
    let run = Run::simulate(
        &corpus("esmini/xosc/swarm.xosc"),
        &load::Options::default(),
        config,
    )
    .expect("runs");
    let last = run.trajectories.times.len() as u32 - 1;
    let tracks = &run.trajectories.tracks;
    let late = tracks.iter().filter(|t| t.samples[0].frame > 0).count();
    let gone = tracks
        .iter()
        .filter(|t| t.samples.last().is_some_and(|s| s.frame < last))
        .count();
    assert!(
        late > 0 && gone > 0,
        "{late} appear later, {gone} leave early"
    );
    // Every entity that appeared has its box in the manifest.
    for t in tracks {
        let info = run
            .manifest
            .entities
            .iter()
            .find(|e| e.id == t.id)
            .expect("in the manifest");
        assert!(info.box_size[0] > 0.0, "{}", info.name);
    }
    assert!(run.events.iter().any(|e| e.kind == "entity"));
}

#[test]
fn trailers_are_linked_in_the_manifest() {
    let config = EngineConfig {
        duration: Some(2.0),
        ..EngineConfig::default()
    };
    let run = Run::simulate(
        &corpus("esmini/xosc/trailers.xosc"),
        &load::Options::default(),
        config,
    )
    .expect("runs");
    let linked: Vec<_> = run
        .manifest
        .entities
        .iter()
        .filter(|e| e.trailer.is_some())
        .collect();
    assert!(!linked.is_empty());
    for tow in linked {
        let trailer = tow.trailer.expect("filtered");
        assert!(
            run.manifest.entities.iter().any(|e| e.id == trailer),
            "{} tows a known entity",
            tow.name
        );
    }
}

/// Issue 33: a scenario that does not build reaches the caller as the engine's own error
/// (`ErrorKind::Run(engine::Error)`, with `source()`), not as text: bad_model.xosc names the
/// controller model "idm2", an error at its `<Property name="model"` on line 20 (the engine's
/// test `bad_controller_properties_are_load_errors_at_the_property` has the message).
#[test]
fn a_scenario_that_does_not_build_keeps_the_engines_error() {
    let file = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../engine/tests/files/controller/bad_model.xosc"
    ));
    let err = match Run::simulate(&file, &load::Options::default(), EngineConfig::default()) {
        Ok(_) => panic!("bad_model.xosc runs"),
        Err(e) => e,
    };
    let replay::ErrorKind::Run(inner) = err.kind() else {
        panic!("expected ErrorKind::Run, found {:?}", err.kind());
    };
    let line = std::fs::read_to_string(&file)
        .expect("fixture")
        .lines()
        .nth(19)
        .expect("line 20")
        .to_owned();
    let col = line
        .find(r#"<Property name="model""#)
        .expect("the Property")
        + 1;
    let pos = inner.pos().expect("a load error has its place");
    // Columns count characters; the line is ASCII up to the element.
    assert_eq!((pos.line, pos.col as usize), (20, col));
    assert_eq!(
        err.to_string(),
        format!("run: {inner}"),
        "Display is the engine's message after 'run: '"
    );
    assert!(std::error::Error::source(&err).is_some());
}
