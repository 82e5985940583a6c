//! The driver models' commands of a step worked out on several threads (OpenSCENARIO 1.3
//! §7.2.2.1 motion control; issue 31: "parallelising one scenario's controller stage across
//! cores for large N", run option [`EngineConfig::controller_threads`](crate::EngineConfig)).
//!
//! **The same bits for any thread count.** Every command of a step is worked out from the
//! world at the step's start, before any entity moves (controller/stage.rs): a command reads
//! the entities, the step's lane index, the road network and the signals, none of which a
//! command changes, and writes only its own model (a `mobil` controller's pending lane, time
//! of its last change and kept road answers). The lane index's search hints, which a search
//! updates, are per searching entity and kind of search (store/lane_index.rs "Hints"), and a
//! hint changes where a walk starts, never where it ends. So each command gives the same
//! numbers on whichever thread and in whichever order it is worked out. They are kept per
//! model place here, and the stage's walk merges them in its usual order (entity index, then
//! assignment order), as if it had worked each out where it meets it.
//!
//! Only the `idm` and `mobil` models (the driver models, by value in the table's `Drivers`)
//! are worked out here: each is one place of that table, named by one run at most, so each
//! thread holds its own models mutably. The other models (`acc`, `vehicle_dynamics`,
//! `external`) stay on the calling thread.

use opendrive::{Real, RoadNetwork};
use rayon::prelude::*;

use super::drivers::{DriverModel, Model, Run};
use super::view::ControllerView;
use crate::signals::Signals;
use crate::store::lane_index::LaneIndex;
use crate::world::Entity;

/// Fewest driver models a step works out on threads: with fewer, handing the work to the pool
/// costs more than it saves.
pub const PARALLEL_MIN: usize = 256;

/// Models handed to one thread at a time (a command is ~1 µs: a task of 64 is worth a hand-over).
const MIN_CHUNK: usize = 64;

/// No entity's run names the place this step.
const NONE: u32 = u32::MAX;

/// The pool and the storage of the threaded commands, kept from step to step.
#[derive(Debug, Default)]
pub(crate) struct ParallelCommands {
    /// The pool, built at the first step with more than one thread asked.
    pool: Option<rayon::ThreadPool>,
    /// Per driver-model place: the entity whose run names it this step, or [`NONE`].
    entity_of: Vec<u32>,
    /// Per driver-model place: its command this step (acceleration, lane to change to).
    commands: Vec<(Real, Option<i32>)>,
}

/// What the commands read: the world at the step's start.
#[derive(Clone, Copy)]
pub(crate) struct StepWorld<'a> {
    /// Simulation time at the step's start (s).
    pub time: Real,
    /// The step's length (s).
    pub dt: Real,
    /// Every entity.
    pub entities: &'a [Entity],
    /// The road network.
    pub network: &'a RoadNetwork,
    /// The step's lane index.
    pub index: &'a LaneIndex,
    /// The signal states.
    pub signals: &'a Signals,
}

impl<'a> StepWorld<'a> {
    /// The view of entity `i` for its driver model, if it is placed (the stage's own test).
    #[inline]
    pub fn view(&self, i: usize) -> Option<ControllerView<'a>> {
        let e = self.entities.get(i)?;
        let input = self.index.input(i).filter(|r| r.placed)?;
        Some(
            ControllerView::new(
                self.time,
                e,
                input,
                self.entities,
                self.network,
                self.index,
                None,
                self.signals,
            )
            .stepping(self.dt),
        )
    }
}

impl ParallelCommands {
    /// Works out the command of every driver model a run names, for placed entities, on
    /// `threads` threads when there are at least [`PARALLEL_MIN`] models; returns whether it
    /// did (else the stage works them out as it walks, and so when the pool cannot be built).
    pub fn work_out(
        &mut self,
        threads: usize,
        runs: &[Run],
        drivers: &mut [DriverModel],
        world: StepWorld<'_>,
    ) -> bool {
        if threads <= 1 || drivers.len() < PARALLEL_MIN {
            return false;
        }
        if self.pool.as_ref().map(|p| p.current_num_threads()) != Some(threads) {
            self.pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .ok();
        }
        let Some(pool) = self.pool.as_ref() else {
            return false;
        };
        self.entity_of.clear();
        self.entity_of.resize(drivers.len(), NONE);
        for run in runs {
            if let Model::Driver(k) = run.model {
                if let Some(slot) = self.entity_of.get_mut(k) {
                    *slot = run.entity as u32;
                }
            }
        }
        self.commands.clear();
        self.commands.resize(drivers.len(), (0.0, None));
        let (entity_of, commands) = (&self.entity_of, &mut self.commands);
        pool.install(|| {
            drivers
                .par_iter_mut()
                .zip(commands.par_iter_mut())
                .zip(entity_of.par_iter())
                .with_min_len(MIN_CHUNK)
                .for_each(|((model, out), &i)| {
                    if i == NONE {
                        return;
                    }
                    if let Some(view) = world.view(i as usize) {
                        *out = model.command(&view);
                    }
                });
        });
        true
    }

    /// The command worked out for the model at place `k` ([`work_out`](Self::work_out)).
    #[inline]
    pub fn command(&self, k: usize) -> (Real, Option<i32>) {
        self.commands.get(k).copied().unwrap_or((0.0, None))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::controller::command::{Controller, Strategy};
    use crate::controller::drivers::{DriverModel, Model, Run};
    use crate::controller::mobil::MobilController;
    use crate::controller::properties::MotionDomains;
    use crate::controller::test_world::crowded;
    use crate::models::idm::IdmParameters;
    use crate::models::mobil::MobilParameters;

    /// The commands worked out on threads (controller/parallel.rs) are, for every car of 6
    /// crowded highways of 300 cars (above the 256 models from which a step uses threads), with
    /// four MOBIL parameter sets and two desired speeds, the commands worked out in turn, bit for
    /// bit, and each model's state after them is the same (the pending lane taken, the last
    /// change's time); on 2 and 3 threads. Lane changes occur many times.
    #[test]
    fn the_commands_on_threads_are_the_commands_in_turn() {
        let mut changes = 0;
        for seed in 1..=6u64 {
            let w = crowded(300, seed);
            assert!(w.entities().len() >= PARALLEL_MIN);
            let index = LaneIndex::build(&w.network, w.entities());
            let at_start = StepWorld {
                time: 10.0,
                dt: 0.05,
                entities: w.entities(),
                network: &w.network,
                index: &index,
                signals: &w.signals,
            };
            // Car i has model i (parameters varied by car), and car 7's model has a pending lane.
            let models: Vec<DriverModel> = (0..w.entities().len())
                .map(|i| {
                    let idm = IdmParameters {
                        desired_speed: [20.0, 36.0][i % 2],
                        ..IdmParameters::default()
                    };
                    let mobil = MobilParameters {
                        politeness: [0.5, 0.0, 0.5, 0.2][i / 2 % 4],
                        change_threshold: [0.1, 0.0, 0.1, 0.1][i / 2 % 4],
                        ..MobilParameters::default()
                    };
                    let mut c = MobilController::new(idm, true, mobil);
                    if i == 7 {
                        // A LaneChangeAction handed to the controller: its pending lane.
                        c.strategy(Strategy::Lane(-2));
                    }
                    DriverModel::Mobil(c)
                })
                .collect();
            let runs: Vec<Run> = (0..models.len())
                .map(|i| Run {
                    entity: i,
                    held: MotionDomains::BOTH,
                    model: Model::Driver(i),
                })
                .collect();
            let mut in_turn = models.clone();
            let expected: Vec<_> = in_turn
                .iter_mut()
                .enumerate()
                .map(|(i, m)| at_start.view(i).map(|v| m.command(&v)))
                .collect();
            changes += expected
                .iter()
                .filter(|c| c.is_some_and(|(_, lane)| lane.is_some()))
                .count();
            for threads in [2, 3] {
                let mut threaded = models.clone();
                let mut parallel = ParallelCommands::default();
                assert!(parallel.work_out(threads, &runs, &mut threaded, at_start));
                for (k, e) in expected.iter().enumerate() {
                    let (a, lane) = e.expect("every car is placed");
                    let (ta, tlane) = parallel.command(k);
                    assert_eq!(
                        (ta.to_bits(), tlane),
                        (a.to_bits(), lane),
                        "seed {seed} car {k}"
                    );
                }
                assert_eq!(
                    format!("{threaded:?}"),
                    format!("{in_turn:?}"),
                    "seed {seed}"
                );
            }
            // One thread, or fewer models than the threshold: worked out in turn by the stage.
            let mut parallel = ParallelCommands::default();
            assert!(!parallel.work_out(1, &runs, &mut models.clone(), at_start));
            let few = &mut models[..PARALLEL_MIN - 1].to_vec();
            assert!(!parallel.work_out(2, &runs[..PARALLEL_MIN - 1], few, at_start));
        }
        assert!(changes > 100, "{changes} lane changes");
    }
}
