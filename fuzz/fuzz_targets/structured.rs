//! The engine on valid scenarios: a small OpenSCENARIO 1.3 scenario built from the fuzzer's
//! bytes (`structured/gen.rs`: entities on the bundled highway, events of speed, lane change,
//! lane offset, teleport, distance-keeping, speed-profile and visibility actions under time,
//! speed, distance, headway, time-to-collision, travelled-distance, standstill, end-of-road and
//! storyboard-state conditions) is loaded, built and run for at most `MAX_STEPS` steps.
//!
//! Invariants checked after every step (a violation is a finding, as is a panic or a hang):
//! - the state is finite: every entity's pose, speed and odometer;
//! - entity ids are stable: an id keeps its name, and the entities come in id order;
//! - the odometer never decreases;
//! - every storyboard transition is legal (OpenSCENARIO 1.3 §8.2): start from init or standby
//!   into running; end from running into standby or complete; skip from standby into standby or
//!   complete; stop from standby or running into complete; its time is the step's.
//!
//! Loading and building must succeed: the generator writes only valid scenarios, so a rejection
//! is a finding too (in the generator or in the reader).
#![no_main]

use std::collections::BTreeMap;
use std::path::Path;
use std::sync::{Arc, OnceLock};

use arbitrary::{Arbitrary, Unstructured};
use engine::storyboard::{ElementState as S, Transition as T};
use engine::{Engine, EngineConfig, EventRecord};
use libfuzzer_sys::fuzz_target;
use opendrive::RoadNetwork;
use scenario::{MemoryFiles, Scenario};

#[path = "structured/gen.rs"]
mod gen;
mod support;

/// Most steps run per input (30 s at the default 0.05 s step).
const MAX_STEPS: u64 = 600;

const ROAD_PATH: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../examples/roads/highway.xodr"
);
const ROAD: &str = include_str!("../../examples/roads/highway.xodr");

#[derive(Debug, Arbitrary)]
struct Input {
    plan: gen::Plan,
    dt: u8,
}

fn legal(from: S, t: T, to: S) -> bool {
    match t {
        T::Start => matches!(from, S::Init | S::Standby) && to == S::Running,
        T::End => from == S::Running && matches!(to, S::Standby | S::Complete),
        T::Skip => from == S::Standby && matches!(to, S::Standby | S::Complete),
        T::Stop => matches!(from, S::Standby | S::Running) && to == S::Complete,
    }
}

/// The road's path without `..` (as the loader resolves it), which the scenario names.
fn road_path() -> &'static str {
    static PATH: OnceLock<String> = OnceLock::new();
    PATH.get_or_init(|| {
        let p = std::fs::canonicalize(ROAD_PATH).expect("examples/roads/highway.xodr exists");
        p.to_str().expect("a UTF-8 path").to_owned()
    })
}

/// The bundled highway, read once and shared by every run.
fn network() -> Arc<RoadNetwork> {
    static NETWORK: OnceLock<Arc<RoadNetwork>> = OnceLock::new();
    NETWORK
        .get_or_init(|| {
            let network = RoadNetwork::from_str(ROAD, Path::new(road_path()));
            Arc::new(network.expect("examples/roads/highway.xodr loads"))
        })
        .clone()
}

fuzz_target!(|data: &[u8]| {
    support::watchdog::start(data);
    support::on_this_thread(|| scenario_run(data));
});

/// One input, checked as the module doc says.
fn scenario_run(data: &[u8]) {
    let Ok(input) = Input::arbitrary_take_rest(Unstructured::new(data)) else {
        return;
    };
    let text = gen::scenario_xml(&input.plan, road_path());
    let main = Path::new("/fuzz/xosc/structured.xosc");
    let mut files = MemoryFiles::new();
    files
        .insert(main, text.as_bytes())
        .insert(road_path(), ROAD);
    let scenario = match Scenario::load_with_files(&files, main, &[]) {
        Ok(s) => s,
        Err(e) => panic!("generated scenario rejected: {e}\n{text}"),
    };
    // dt from 0.001 s to 0.256 s.
    let dt = f64::from(input.dt.max(1)) / 1000.0;
    let config = EngineConfig {
        dt,
        ..EngineConfig::default()
    };
    let mut engine = match Engine::new(&scenario, network(), config) {
        Ok(e) => e,
        Err(e) => panic!("generated scenario not built: {e}\n{text}"),
    };
    let mut names: BTreeMap<u32, String> = BTreeMap::new();
    let mut odometers: BTreeMap<u32, f64> = BTreeMap::new();
    let mut events: Vec<EventRecord> = Vec::new();
    for _ in 0..MAX_STEPS {
        events.clear();
        let time = engine.time();
        let done = match engine.step(&mut (), &mut events) {
            Ok(done) => done.is_some(),
            // A runtime error is a reported failure, not a crash; the run stops there.
            Err(_) => true,
        };
        let entities = engine.entities();
        assert!(
            entities.windows(2).all(|w| w[0].id < w[1].id),
            "entities out of id order"
        );
        for e in &entities {
            let name = names.entry(e.id.0).or_insert_with(|| e.name.clone());
            assert_eq!(&e.name, name, "entity renamed");
            let p = &e.pose;
            assert!(
                [p.x, p.y, p.z, p.h, p.p, p.r, e.speed, e.odometer]
                    .iter()
                    .all(|v| v.is_finite()),
                "{} not finite at t={time}: {p:?} speed {} odometer {}\n{text}",
                e.name,
                e.speed,
                e.odometer
            );
            let before = odometers.entry(e.id.0).or_insert(0.0);
            assert!(
                e.odometer >= *before - 1e-9,
                "{} odometer fell from {} to {} at t={time}\n{text}",
                e.name,
                before,
                e.odometer
            );
            *before = e.odometer;
        }
        for r in &events {
            if let EventRecord::Transition(r) = r {
                assert!(
                    legal(r.from, r.transition, r.to),
                    "illegal transition {r:?}\n{text}"
                );
                assert!((r.time - time).abs() <= 1e-9, "{r:?} in the step at {time}");
            }
        }
        if done {
            break;
        }
    }
}
