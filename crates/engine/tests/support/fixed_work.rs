//! The fixed piece of work the engine's highway benchmarks time (issue 31; benches/scale.rs,
//! benches/controllers.rs): [`STEPS`] steps from t0 = [`WARM_STEPS`] × 0.05 s = 10 s to
//! t = 11 s of the scale highway (tests/support/scale.rs), the same steps in every criterion
//! iteration, so that builds compare. (A run continued from iteration to iteration reached
//! hundreds or thousands of simulated seconds, past the 20 km road's end, and a faster build
//! ran further into it.)
//!
//! The scenario is read once and kept in memory ([`Start`]); before each iteration, untimed
//! (criterion `iter_batched`, one engine per iteration), a new engine is built from it and
//! stepped to t0 ([`Start::at_t0`]); the iteration times [`steps`]. The engine has no cheap
//! copy of its state (the user controllers' table holds boxed models), so the state at t0 is
//! rebuilt; the run is deterministic, and [`check_fixed_work`], called before the timed part,
//! asserts that two rebuilds reach equal states at t = 11 s with every vehicle on the road.

#![allow(dead_code)] // each target uses a different part

use std::hint::black_box;
use std::path::Path;
use std::sync::Arc;

use engine::{Engine, EngineConfig, FrameSink};
use opendrive::RoadNetwork;
use scenario::Scenario;

/// Steps per measured iteration (1 s of simulated time at the default 0.05 s).
pub const STEPS: u64 = 20;
/// Untimed steps before each iteration: the timed steps start at t0 = 200 × 0.05 s = 10 s.
pub const WARM_STEPS: u64 = 200;
/// Simulated seconds of the scenario's stop trigger: past what the benchmarks reach.
pub const DURATION: f64 = 1e6;
/// Length of the highway's one road "1" (tests/support/scale.rs, `length="20000"`), m.
pub const ROAD_LENGTH: f64 = 20_000.0;

/// The engine configuration of the benchmarks: the defaults (dt = 0.05 s), no time cap
/// before [`DURATION`].
pub fn config() -> EngineConfig {
    EngineConfig {
        max_time: DURATION,
        ..EngineConfig::default()
    }
}

/// A scenario read once, from which an engine at t0 is rebuilt for each iteration.
pub struct Start {
    scenario: Scenario,
    network: Arc<RoadNetwork>,
    config: EngineConfig,
}

impl Start {
    /// Reads the scenario at `path` and its road network, with [`config`].
    pub fn load(path: &Path) -> Start {
        let scenario = Scenario::load(path).expect("scale scenario loads");
        let network = engine::load::road_network(&scenario).expect("the 20 km road loads");
        Start {
            scenario,
            network,
            config: config(),
        }
    }

    /// A new engine stepped to t0 with no output (untimed set-up of each iteration).
    pub fn at_t0(&self) -> Engine {
        let mut engine = Engine::new(&self.scenario, Arc::clone(&self.network), self.config)
            .expect("scale scenario builds");
        for _ in 0..WARM_STEPS {
            engine.step(&mut (), &mut ()).expect("steps to t0");
        }
        engine
    }
}

/// The timed part: [`STEPS`] steps, each frame written to `frames`. Returns the engine so that
/// criterion drops it untimed.
pub fn steps(mut engine: Engine, frames: &mut dyn FrameSink) -> Engine {
    for _ in 0..STEPS {
        black_box(engine.step(frames, &mut ()).expect("steps"));
    }
    engine
}

/// The furthest s any of the first `vehicles` vehicles can reach by t = 11 s, from the start
/// layout alone: the last row starts at s = 100 + 15·⌊(vehicles − 1)/4⌋ m, no vehicle is
/// faster than 20 + 6 = 26 m/s (the default controller keeps the Init speed; `idm` and `mobil`
/// do not exceed their desired speed, the start speed), so s ≤ that + 26 m/s × 11 s.
/// By hand: 1,000 vehicles 100 + 15 × 249 + 286 = 4,121 m; 4,000 vehicles
/// 100 + 15 × 999 + 286 = 15,371 m; both below the road's 20,000 m.
pub fn furthest_s(vehicles: usize) -> f64 {
    let last_row = vehicles.saturating_sub(1) / 4;
    100.0 + 15.0 * last_row as f64 + 26.0 * 11.0
}

/// Checks, once per benchmark and before its timed part, that every iteration does the same
/// work on the highway: two engines rebuilt to t0 and stepped [`STEPS`] reach t = 11 s in the
/// same states (`Engine::entities`), all `vehicles` of them placed on a lane of the road with
/// s below [`furthest_s`] (and so below [`ROAD_LENGTH`]). Panics naming what failed.
pub fn check_fixed_work(start: &Start, vehicles: usize) {
    let (a, b) = (steps(start.at_t0(), &mut ()), steps(start.at_t0(), &mut ()));
    let end = (WARM_STEPS + STEPS) as f64 * start.config.dt;
    assert_eq!(a.time(), end, "the timed steps end at t0 + 1 s = 11 s");
    let states = a.entities();
    assert_eq!(states, b.entities(), "two rebuilds at t0 step alike");
    assert_eq!(states.len(), vehicles);
    let furthest = furthest_s(vehicles);
    assert!(
        furthest < ROAD_LENGTH,
        "{vehicles} vehicles fit on the road"
    );
    for e in &states {
        let on_road = e.road_position.as_ref().is_some_and(|p| {
            p.road_id == "1" && p.distance == 0.0 && (0.0..furthest).contains(&p.s)
        });
        assert!(
            on_road,
            "{} at t = {end} s is not on road 1 at s < {furthest} m: {:?}",
            e.name, e.road_position
        );
    }
}
