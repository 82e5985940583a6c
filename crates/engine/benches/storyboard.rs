//! Storyboard step cost (OpenSCENARIO 1.3 §8 state machine): a storyboard of 10 Acts × 5
//! Maneuvers × 10 Events (500 Events, 500 actions, 1 000 conditions with edges and delays)
//! stepped 1 000 times at dt = 0.05 s, with deterministic scripted conditions and actions.
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use engine::storyboard::{
    ActDesc, ActionDesc, ActionHost, ActionId, ActionStatus, ConditionDesc, ConditionEdge,
    ConditionId, ConditionSource, EventDesc, ManeuverDesc, ManeuverGroupDesc, Priority, StateView,
    StoryDesc, Storyboard, StoryboardDesc, TransitionRecord, TriggerDesc,
};
use std::hint::black_box;
use std::time::Duration;

const DT: f64 = 0.05;
const STEPS: u32 = 1_000;

/// Condition i is true on steps where (i + step) mod 7 is 0 or 1.
struct Conditions;

impl ConditionSource for Conditions {
    fn value(&mut self, id: ConditionId, time: f64, _: &StateView<'_>) -> bool {
        let step = (time / DT).round() as u64;
        (u64::from(id.0) + step) % 7 < 2
    }
}

/// Every action takes 3 steps.
struct Actions {
    now: u64,
    started: Vec<u64>,
}

impl ActionHost for Actions {
    fn start(&mut self, id: ActionId) {
        self.started[id.0 as usize] = self.now;
    }
    fn stop(&mut self, _: ActionId) {}
    fn status(&self, id: ActionId) -> ActionStatus {
        if self.now >= self.started[id.0 as usize] + 3 {
            ActionStatus::Ended
        } else {
            ActionStatus::Running
        }
    }
}

fn description() -> StoryboardDesc {
    let priorities = [Priority::Parallel, Priority::Override, Priority::Skip];
    let mut next = 0u32;
    let mut id = || {
        next += 1;
        next
    };
    let acts = (0..10)
        .map(|a| ActDesc {
            name: format!("Act{a}"),
            start_trigger: None,
            stop_trigger: None,
            maneuver_groups: vec![ManeuverGroupDesc {
                name: format!("MG{a}"),
                maximum_execution_count: 2,
                maneuvers: (0..5)
                    .map(|m| ManeuverDesc {
                        name: format!("M{a}.{m}"),
                        events: (0..10)
                            .map(|e| {
                                let n = id();
                                EventDesc {
                                    name: format!("E{n}"),
                                    priority: priorities[e % 3],
                                    maximum_execution_count: 3,
                                    start_trigger: Some(TriggerDesc::all_of(vec![
                                        ConditionDesc::new(
                                            "rising",
                                            ConditionId(n),
                                            ConditionEdge::Rising,
                                            0.0,
                                        ),
                                        ConditionDesc::new(
                                            "delayed",
                                            ConditionId(n + 3),
                                            ConditionEdge::None,
                                            0.1,
                                        ),
                                    ])),
                                    actions: vec![ActionDesc {
                                        name: format!("A{n}"),
                                        id: ActionId(n),
                                    }],
                                }
                            })
                            .collect(),
                    })
                    .collect(),
            }],
        })
        .collect();
    StoryboardDesc {
        name: "SB".to_owned(),
        init_actions: Vec::new(),
        stories: vec![StoryDesc {
            name: "S".to_owned(),
            acts,
        }],
        stop_trigger: None,
    }
}

fn bench_step(c: &mut Criterion) {
    let storyboard = match Storyboard::new(&description()) {
        Ok(storyboard) => storyboard,
        Err(error) => panic!("benchmark storyboard rejected: {error}"),
    };
    let mut group = c.benchmark_group("storyboard");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(3));
    group.bench_function("step_500_events_x1000", |b| {
        b.iter(|| {
            let mut sb = storyboard.clone();
            let mut actions = Actions {
                now: 0,
                started: vec![0; 1_000],
            };
            let mut log: Vec<TransitionRecord> = Vec::new();
            for k in 0..STEPS {
                actions.now = u64::from(k);
                let result = sb.step(
                    f64::from(k) * DT,
                    DT,
                    &mut Conditions,
                    &mut actions,
                    &mut log,
                );
                if let Err(error) = result {
                    panic!("{error}");
                }
            }
            black_box(log.len())
        })
    });
    group.finish();
}

criterion_group!(benches, bench_step);
criterion_main!(benches);
