//! The driver models' commands worked out on several threads (issue 31, engine
//! controller/parallel.rs, run option `EngineConfig::controller_threads`): the scale highway's
//! traffic (tests/support/scale.rs) with every vehicle driven by `idm`, and by `mobil`, gives
//! the same trajectory CSV bytes on 1, 2 and 3 threads.

use engine::output::CsvWriter;
use engine::{Engine, EngineConfig};

use crate::scale;

/// Vehicles: above the 256 driver models from which a step uses its threads.
const VEHICLES: usize = 300;
/// Steps (20 s at 0.05 s).
const STEPS: usize = 400;

/// The trajectory CSV of `STEPS` steps of `path` with the commands on `threads` threads.
fn csv(path: &std::path::Path, threads: usize) -> String {
    let config = EngineConfig {
        controller_threads: threads,
        ..EngineConfig::default()
    };
    let mut engine = Engine::load(path, &[], config).expect("the highway loads");
    let mut csv = CsvWriter::new(Vec::new());
    for _ in 0..STEPS {
        engine.step(&mut csv, &mut ()).expect("steps");
    }
    String::from_utf8(csv.into_inner()).expect("the CSV is UTF-8")
}

/// The same bytes on 1, 2 and 3 threads, for `idm` and for `mobil`. (The commands' lane
/// changes on threads, many of them, are compared one by one with the commands worked out in
/// turn by the engine's unit test
/// `controller::mobil::tests::the_commands_on_threads_are_the_commands_in_turn`.)
#[test]
fn the_driver_models_commands_on_threads_give_the_same_bytes() {
    for model in ["idm", "mobil"] {
        let dir = scale::scratch(&format!("threads-{model}"));
        let path = scale::write_traffic(dir.path(), VEHICLES, 300.0, model);
        let one = csv(&path, 1);
        // A row per vehicle per frame, the t = 0 frame too.
        assert_eq!(one.lines().count(), 1 + VEHICLES * (STEPS + 1), "{model}");
        for threads in [2, 3] {
            assert!(csv(&path, threads) == one, "{model} on {threads} threads");
        }
    }
}
