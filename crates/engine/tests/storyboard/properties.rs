//! Properties of the state machine on random storyboards (OpenSCENARIO 1.3 §8.1–8.4), with
//! random condition values and action durations:
//!
//! - every transition is one the standard's state diagrams allow: start from init or standby
//!   into running; end from running into standby or complete; stop from standby or running into
//!   complete; skip from standby into standby or complete (§8.2, §8.4.2);
//! - an Event starts or skips at most `maximumExecutionCount` times per start of its Maneuver
//!   (§8.4.2.1; a count of 0 allows the one skip into completeState);
//! - the runtime is only told to stop actions that run, and nothing happens after the
//!   storyboard's stop;
//! - two runs of the same input give the same log (determinism).

use crate::storyboard_support;

use std::collections::{HashMap, HashSet};

use engine::storyboard::{
    ActDesc, ActionDesc, ActionHost, ActionId, ActionStatus, ConditionEdge, ConditionGroupDesc,
    ElementKind, ElementState, EventDesc, ManeuverDesc, ManeuverGroupDesc, Priority, StoryDesc,
    Storyboard, StoryboardDesc, Transition, TransitionRecord, TriggerDesc,
};
use proptest::prelude::*;
use storyboard_support::*;

const CONDITIONS: u32 = 6;
const STEPS: i64 = 40;

/// Reads small numbers off a byte tape; past its end it reads zeros.
struct Tape<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Tape<'_> {
    fn next(&mut self, below: u8) -> u8 {
        let byte = self.bytes.get(self.at).copied().unwrap_or(0);
        self.at += 1;
        byte % below
    }

    fn trigger(&mut self) -> Option<TriggerDesc> {
        if self.next(3) == 0 {
            return None;
        }
        let groups = (0..1 + self.next(2))
            .map(|_| ConditionGroupDesc {
                conditions: (0..1 + self.next(2))
                    .map(|_| {
                        let edge = [
                            ConditionEdge::None,
                            ConditionEdge::Rising,
                            ConditionEdge::Falling,
                            ConditionEdge::RisingOrFalling,
                        ][usize::from(self.next(4))];
                        let delay = [0.0, 0.1, 0.25][usize::from(self.next(3))];
                        cond(u32::from(self.next(CONDITIONS as u8)), edge, delay)
                    })
                    .collect(),
            })
            .collect();
        Some(TriggerDesc {
            condition_groups: groups,
        })
    }
}

/// A storyboard read off `tape`; action ids are numbered from 0.
fn storyboard_from(tape: &mut Tape<'_>) -> (StoryboardDesc, u32) {
    let mut actions = 0u32;
    let mut action = || {
        actions += 1;
        ActionDesc {
            name: format!("A{}", actions - 1),
            id: ActionId(actions - 1),
        }
    };
    let mut stories = Vec::new();
    for s in 0..1 + tape.next(2) {
        let mut acts = Vec::new();
        for a in 0..1 + tape.next(2) {
            let mut groups = Vec::new();
            for g in 0..1 + tape.next(2) {
                let mut maneuvers = Vec::new();
                for m in 0..1 + tape.next(2) {
                    let mut events = Vec::new();
                    for e in 0..1 + tape.next(3) {
                        let priority = [Priority::Override, Priority::Skip, Priority::Parallel]
                            [usize::from(tape.next(3))];
                        let maximum_execution_count = u32::from(tape.next(4));
                        let start_trigger = tape.trigger();
                        let event_actions = (0..1 + tape.next(2)).map(|_| action()).collect();
                        events.push(EventDesc {
                            name: format!("E{s}.{a}.{g}.{m}.{e}"),
                            priority,
                            maximum_execution_count,
                            start_trigger,
                            actions: event_actions,
                        });
                    }
                    maneuvers.push(ManeuverDesc {
                        name: format!("M{s}.{a}.{g}.{m}"),
                        events,
                    });
                }
                groups.push(ManeuverGroupDesc {
                    name: format!("MG{s}.{a}.{g}"),
                    maximum_execution_count: 1 + u32::from(tape.next(2)),
                    maneuvers,
                });
            }
            acts.push(ActDesc {
                name: format!("Act{s}.{a}"),
                start_trigger: tape.trigger(),
                stop_trigger: tape.trigger(),
                maneuver_groups: groups,
            });
        }
        stories.push(StoryDesc {
            name: format!("S{s}"),
            acts,
        });
    }
    let init_actions = (0..tape.next(2)).map(|_| action()).collect();
    let stop_trigger = tape.trigger();
    (
        StoryboardDesc {
            name: "SB".to_owned(),
            init_actions,
            stories,
            stop_trigger,
        },
        actions,
    )
}

/// Actions with given durations that check they are stopped only while running.
struct CheckedActions {
    durations: Vec<i64>,
    started_at: HashMap<u32, i64>,
    running: HashSet<u32>,
    now: i64,
    misuse: Vec<String>,
}

impl ActionHost for CheckedActions {
    fn start(&mut self, id: ActionId) {
        if !self.running.insert(id.0) {
            self.misuse
                .push(format!("start of running action {}", id.0));
        }
        self.started_at.insert(id.0, self.now);
    }

    fn stop(&mut self, id: ActionId) {
        if !self.running.remove(&id.0) {
            self.misuse.push(format!("stop of idle action {}", id.0));
        }
    }

    fn status(&self, id: ActionId) -> ActionStatus {
        let duration = self.durations.get(id.0 as usize).copied().unwrap_or(0);
        match self.started_at.get(&id.0) {
            Some(&start) if self.now >= start + duration => ActionStatus::Ended,
            _ => ActionStatus::Running,
        }
    }
}

fn simulate(
    desc: &StoryboardDesc,
    action_count: u32,
    durations: &[u8],
    values: &[bool],
) -> (Storyboard, Vec<TransitionRecord>, Vec<String>) {
    let mut sb = build(desc);
    let mut conditions = ScriptedConditions::default();
    for c in 0..CONDITIONS {
        let column: Vec<bool> = (0..STEPS)
            .map(|k| values[(k as usize * CONDITIONS as usize + c as usize) % values.len()])
            .collect();
        conditions.set(c, move |k| column[k as usize]);
    }
    let mut actions = CheckedActions {
        durations: (0..action_count as usize)
            .map(|i| i64::from(durations[i % durations.len()] % 5))
            .collect(),
        started_at: HashMap::new(),
        running: HashSet::new(),
        now: 0,
        misuse: Vec::new(),
    };
    let mut log = Vec::new();
    for k in 0..STEPS {
        actions.now = k;
        let before = log.len();
        if let Err(error) = sb.step(k as f64 * DT, DT, &mut conditions, &mut actions, &mut log) {
            panic!("step {k}: {error}");
        }
        // An action that ended is no longer running for the host either.
        for record in &log[before..] {
            if record.kind == ElementKind::Action && record.transition == Transition::End {
                if let Some(action) = action_id(&record.name) {
                    actions.running.remove(&action);
                }
            }
        }
    }
    (sb, log, actions.misuse)
}

/// The id of action `A{id}`.
fn action_id(name: &str) -> Option<u32> {
    name.strip_prefix('A')?.parse().ok()
}

fn allowed(record: &TransitionRecord) -> bool {
    use ElementState::*;
    match record.transition {
        Transition::Start => matches!(record.from, Init | Standby) && record.to == Running,
        Transition::End => record.from == Running && matches!(record.to, Standby | Complete),
        Transition::Stop => matches!(record.from, Standby | Running) && record.to == Complete,
        Transition::Skip => record.from == Standby && matches!(record.to, Standby | Complete),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn random_storyboards_keep_the_rules(
        tape in proptest::collection::vec(any::<u8>(), 64..256),
        durations in proptest::collection::vec(any::<u8>(), 1..16),
        values in proptest::collection::vec(any::<bool>(), 1..256),
    ) {
        let (desc, action_count) = storyboard_from(&mut Tape { bytes: &tape, at: 0 });
        let (sb, log, misuse) = simulate(&desc, action_count, &durations, &values);

        for record in &log {
            prop_assert!(allowed(record), "forbidden transition {record}");
        }
        prop_assert!(misuse.is_empty(), "{misuse:?}");
        prop_assert!(log.windows(2).all(|w| w[0].time <= w[1].time));

        // Executions per Event between starts of its Maneuver.
        let view = sb.view();
        let mut executions: HashMap<String, u32> = HashMap::new();
        for record in &log {
            match (record.kind, record.transition) {
                (ElementKind::Maneuver, Transition::Start) => {
                    for &event in view.children(record.element) {
                        executions.insert(view.name(event).to_owned(), 0);
                    }
                }
                (ElementKind::Event, Transition::Start | Transition::Skip) => {
                    let count = executions.entry(record.name.clone()).or_insert(0);
                    *count += 1;
                    let maximum = desc_maximum(&desc, &record.name);
                    prop_assert!(*count <= maximum.max(1), "{} ran {count} > {maximum}", record.name);
                }
                _ => {}
            }
        }

        // Nothing after the storyboard's stop.
        if let Some(stop) = log.iter().position(|r| r.kind == ElementKind::Storyboard && r.transition == Transition::Stop) {
            let stop_time = log[stop].time;
            prop_assert!(log[stop..].iter().all(|r| r.time == stop_time));
            prop_assert!(sb.is_complete());
        }

        // Determinism.
        let (_, again, _) = simulate(&desc, action_count, &durations, &values);
        prop_assert_eq!(log, again);
    }
}

/// The Event's maximumExecutionCount (Event names are unique in these storyboards).
fn desc_maximum(desc: &StoryboardDesc, name: &str) -> u32 {
    desc.stories
        .iter()
        .flat_map(|s| &s.acts)
        .flat_map(|a| &a.maneuver_groups)
        .flat_map(|g| &g.maneuvers)
        .flat_map(|m| &m.events)
        .find(|e| e.name == name)
        .map_or(0, |e| e.maximum_execution_count)
}
