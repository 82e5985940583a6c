//! Issue 17 "no allocation in the step for a scenario whose entity set does not change": the
//! step of the scale highway (tests/support/scale.rs) is run under a counting global
//! allocator. Speed itself is measured in the benchmarks (benches/scale.rs), not here.
//!
//! Its own test target because the counting allocator is the whole binary's: the tests of this
//! target run one at a time (a lock) so that each counts only its own steps.

#[path = "../support/scale.rs"]
mod scale;

#[path = "../support/counting.rs"]
mod counting;

use counting::{allocations, serial};
use engine::output::CsvWriter;
use engine::{Engine, EngineConfig};

/// Vehicles of the test's highway (enough for every lane to hold many; the per-entity work is
/// the same as with 1,000).
const VEHICLES: usize = 200;
/// Steps before counting: the first step runs the Init actions and writes the t = 0 frame, and
/// buffers reach their working size.
const WARM_UP: usize = 5;
/// Steps counted.
const COUNTED: usize = 100;

fn engine(what: &str) -> (Engine, tempfile::TempDir) {
    let dir = scale::scratch(what);
    let path = scale::write_scale(dir.path(), VEHICLES, 300.0);
    let engine = Engine::load(&path, &[], EngineConfig::default()).expect("the highway loads");
    (engine, dir)
}

/// The default controller's step over 200 vehicles on the highway, no output: not one
/// allocation in 100 steps once warm (before this issue: two strings per entity per step for
/// its road position, among others).
#[test]
fn the_step_allocates_nothing() {
    let _serial = serial();
    let (mut engine, _dir) = engine("alloc-step");
    for _ in 0..WARM_UP {
        engine.step(&mut (), &mut ()).expect("steps");
    }
    let n = allocations(|| {
        for _ in 0..COUNTED {
            assert_eq!(engine.step(&mut (), &mut ()).expect("steps"), None);
        }
    });
    assert_eq!(
        n, 0,
        "allocations in {COUNTED} steps of {VEHICLES} vehicles"
    );
    // The run went on: 105 steps at 0.05 s.
    assert!((engine.time() - 5.25).abs() < 1e-9, "{}", engine.time());
}

/// The driver models' step (issue 31): the 200 vehicles driven by `idm`, and by `mobil`, whose
/// lane index, gap searches and lane-change judgements reuse the storage of the steps before:
/// not one allocation in 100 steps once warm (before: the lane index's hash map and lists,
/// built anew at every step).
#[test]
fn the_driver_models_step_allocates_nothing() {
    let _serial = serial();
    for model in ["idm", "mobil"] {
        let dir = scale::scratch(&format!("alloc-{model}"));
        let path = scale::write_traffic(dir.path(), VEHICLES, 300.0, model);
        let mut engine = Engine::load(&path, &[], EngineConfig::default()).expect("loads");
        for _ in 0..WARM_UP {
            engine.step(&mut (), &mut ()).expect("steps");
        }
        let n = allocations(|| {
            for _ in 0..COUNTED {
                assert_eq!(engine.step(&mut (), &mut ()).expect("steps"), None);
            }
        });
        assert_eq!(
            n, 0,
            "allocations in {COUNTED} steps of {VEHICLES} {model} vehicles"
        );
    }
}

/// With the trajectory CSV (rows formatted in a reused buffer, output/fixed.rs) the step
/// allocates nothing either; the bytes go to a sink so that no growing buffer is counted.
#[test]
fn the_csv_writer_allocates_nothing() {
    let _serial = serial();
    let (mut engine, _dir) = engine("alloc-csv");
    let mut csv = CsvWriter::new(std::io::sink());
    for _ in 0..WARM_UP {
        engine.step(&mut csv, &mut ()).expect("steps");
    }
    let n = allocations(|| {
        for _ in 0..COUNTED {
            engine.step(&mut csv, &mut ()).expect("steps");
        }
    });
    assert_eq!(n, 0, "allocations in {COUNTED} steps with CSV");
}

/// The counter counts: building the engine allocates (so a zero above is not a counter that
/// never moves).
#[test]
fn the_counter_sees_allocations() {
    let _serial = serial();
    let dir = scale::scratch("alloc-load");
    let path = scale::write_scale(dir.path(), 4, 1.0);
    let mut engine = None;
    let count = allocations(|| {
        engine = Some(Engine::load(&path, &[], EngineConfig::default()).expect("loads"));
    });
    assert!(count > 100, "{count}");
    // It is the 4-vehicle highway: the Init places 4 vehicles.
    let mut engine = engine.expect("set above");
    engine.step(&mut (), &mut ()).expect("steps");
    assert_eq!(engine.entities().len(), 4);
}
