//! Shared test harness for the storyboard tests: scripted conditions and actions on a fixed
//! step of 0.1 s, small builders, and the run loop. Times are t_k = k · 0.1 s; scripts are
//! written in step numbers k so that no float comparison decides a test.

#![allow(dead_code)] // each test file uses a different part

use std::collections::{BTreeMap, HashMap};

use engine::storyboard::{
    ActDesc, ActionDesc, ActionHost, ActionId, ActionStatus, ConditionDesc, ConditionEdge,
    ConditionId, ConditionSource, ElementKind, EventDesc, ManeuverDesc, ManeuverGroupDesc,
    Priority, StateView, StoryDesc, Storyboard, StoryboardDesc, StoryboardElementState,
    TransitionRecord, TriggerDesc,
};

/// The step length of every test, in seconds.
pub const DT: f64 = 0.1;

/// The step number of time `t` on the 0.1 s grid.
pub fn step_of(t: f64) -> i64 {
    (t / DT).round() as i64
}

type Script = Box<dyn FnMut(i64, &StateView<'_>) -> bool>;

/// Condition values given per condition as a function of the step number.
pub struct ScriptedConditions {
    scripts: HashMap<ConditionId, Script>,
    /// The step length that turns times into step numbers.
    pub dt: f64,
    /// Every query, as (condition, step).
    pub asked: Vec<(u32, i64)>,
}

impl Default for ScriptedConditions {
    fn default() -> Self {
        ScriptedConditions {
            scripts: HashMap::new(),
            dt: DT,
            asked: Vec::new(),
        }
    }
}

impl ScriptedConditions {
    /// Condition `id` is true at the steps where `f(k)` is.
    pub fn set(&mut self, id: u32, f: impl Fn(i64) -> bool + 'static) -> &mut Self {
        self.scripts
            .insert(ConditionId(id), Box::new(move |k, _view| f(k)));
        self
    }

    /// Condition `id` computed from the storyboard's states (StoryboardElementStateCondition).
    pub fn set_with_view(
        &mut self,
        id: u32,
        f: impl FnMut(i64, &StateView<'_>) -> bool + 'static,
    ) -> &mut Self {
        self.scripts.insert(ConditionId(id), Box::new(f));
        self
    }
}

impl ScriptedConditions {
    /// Condition `id` is a StoryboardElementStateCondition on the first element of `kind`
    /// named `name`, with the XSD literals of `storyboardElementType` and `state`.
    pub fn element_state(
        &mut self,
        id: u32,
        kind: &str,
        name: &'static str,
        state: &str,
    ) -> &mut Self {
        let (Some(kind), Some(state)) = (
            ElementKind::from_xsd(kind),
            StoryboardElementState::from_xsd(state),
        ) else {
            panic!("bad StoryboardElementStateCondition literals {kind:?} {state:?}");
        };
        self.set_with_view(id, move |_, view| match view.find_kind(kind, name) {
            Some(element) => view.is(element, state),
            None => panic!("no {kind} {name}"),
        })
    }

    /// The steps at which condition `id` was asked for, in order.
    pub fn asked_steps(&self, id: u32) -> Vec<i64> {
        self.asked
            .iter()
            .filter(|&&(c, _)| c == id)
            .map(|&(_, k)| k)
            .collect()
    }
}

impl ConditionSource for ScriptedConditions {
    fn value(&mut self, id: ConditionId, time: f64, storyboard: &StateView<'_>) -> bool {
        let k = (time / self.dt).round() as i64;
        self.asked.push((id.0, k));
        match self.scripts.get_mut(&id) {
            Some(script) => script(k, storyboard),
            None => panic!("test asked for unscripted condition {id:?}"),
        }
    }
}

/// Actions that end a given number of steps after they start (0: instantaneous).
#[derive(Default)]
pub struct ScriptedActions {
    durations: HashMap<ActionId, i64>,
    started_at: HashMap<ActionId, i64>,
    stopped: Vec<ActionId>,
    /// The current step number, set by [`run`].
    pub now: i64,
    /// Every call, e.g. "start 1 @3", "stop 1 @5".
    pub calls: Vec<String>,
}

impl ScriptedActions {
    /// Action `id` takes `steps` steps.
    pub fn set(&mut self, id: u32, steps: i64) -> &mut Self {
        self.durations.insert(ActionId(id), steps);
        self
    }
}

impl ActionHost for ScriptedActions {
    fn start(&mut self, id: ActionId) {
        self.calls.push(format!("start {} @{}", id.0, self.now));
        self.started_at.insert(id, self.now);
        self.stopped.retain(|&s| s != id);
    }

    fn stop(&mut self, id: ActionId) {
        self.calls.push(format!("stop {} @{}", id.0, self.now));
        self.stopped.push(id);
    }

    fn status(&self, id: ActionId) -> ActionStatus {
        let duration = self.durations.get(&id).copied().unwrap_or(0);
        match self.started_at.get(&id) {
            Some(&start) if self.now >= start + duration => ActionStatus::Ended,
            _ => ActionStatus::Running,
        }
    }
}

/// Runs steps k = 0..steps at t = k · DT and returns the transitions.
pub fn run(
    storyboard: &mut Storyboard,
    steps: i64,
    conditions: &mut ScriptedConditions,
    actions: &mut ScriptedActions,
) -> Vec<TransitionRecord> {
    conditions.dt = DT;
    run_dt(storyboard, steps, DT, conditions, actions)
}

/// Runs steps k = 0..steps at t = k · dt and returns the transitions (conditions must use the
/// same `dt`).
pub fn run_dt(
    storyboard: &mut Storyboard,
    steps: i64,
    dt: f64,
    conditions: &mut ScriptedConditions,
    actions: &mut ScriptedActions,
) -> Vec<TransitionRecord> {
    let mut log = Vec::new();
    for k in 0..steps {
        actions.now = k;
        if let Err(error) = storyboard.step(k as f64 * dt, dt, conditions, actions, &mut log) {
            panic!("step {k} failed: {error}");
        }
    }
    log
}

/// The records as esmini-style lines, "0.300 E1 standbyState -> startTransition -> runningState".
pub fn lines(log: &[TransitionRecord]) -> Vec<String> {
    log.iter().map(ToString::to_string).collect()
}

/// The records of one element, as lines.
pub fn lines_of(log: &[TransitionRecord], name: &str) -> Vec<String> {
    log.iter()
        .filter(|r| r.name == name)
        .map(ToString::to_string)
        .collect()
}

/// A condition slot with `edge` and `delay` on runtime condition `id`.
pub fn cond(id: u32, edge: ConditionEdge, delay: f64) -> ConditionDesc {
    ConditionDesc::new(&format!("C{id}"), ConditionId(id), edge, delay)
}

/// A trigger of one condition with edge `none` and no delay.
pub fn when(id: u32) -> Option<TriggerDesc> {
    Some(TriggerDesc::single(cond(id, ConditionEdge::None, 0.0)))
}

/// An action named `A{id}`.
pub fn action(id: u32) -> ActionDesc {
    ActionDesc {
        name: format!("A{id}"),
        id: ActionId(id),
    }
}

/// An Event with one action.
pub fn event(
    name: &str,
    priority: Priority,
    maximum_execution_count: u32,
    start_trigger: Option<TriggerDesc>,
    action_id: u32,
) -> EventDesc {
    EventDesc {
        name: name.to_owned(),
        priority,
        maximum_execution_count,
        start_trigger,
        actions: vec![action(action_id)],
    }
}

/// A ManeuverGroup `MG` (count `maximum_execution_count`) with one Maneuver `M` of `events`.
pub fn group(maximum_execution_count: u32, events: Vec<EventDesc>) -> ManeuverGroupDesc {
    ManeuverGroupDesc {
        name: "MG".to_owned(),
        maximum_execution_count,
        maneuvers: vec![ManeuverDesc {
            name: "M".to_owned(),
            events,
        }],
    }
}

/// Act `Act` with the given triggers and one group.
pub fn act(
    start_trigger: Option<TriggerDesc>,
    stop_trigger: Option<TriggerDesc>,
    group: ManeuverGroupDesc,
) -> ActDesc {
    ActDesc {
        name: "Act".to_owned(),
        start_trigger,
        stop_trigger,
        maneuver_groups: vec![group],
    }
}

/// Storyboard `SB` with Story `S` holding `act`, no Init actions and no stop trigger.
pub fn storyboard(act: ActDesc) -> StoryboardDesc {
    StoryboardDesc {
        name: "SB".to_owned(),
        init_actions: Vec::new(),
        stories: vec![StoryDesc {
            name: "S".to_owned(),
            acts: vec![act],
        }],
        stop_trigger: None,
    }
}

/// Builds the storyboard; a test description is valid by construction.
pub fn build(desc: &StoryboardDesc) -> Storyboard {
    match Storyboard::new(desc) {
        Ok(storyboard) => storyboard,
        Err(error) => panic!("test storyboard rejected: {error}"),
    }
}

/// Runs a storyboard whose Act waits for `trigger` (one Event, no trigger, action 1 lasting 100
/// steps) for `steps` steps and returns the step at which the Act started, if it did.
pub fn act_start_step(
    trigger: TriggerDesc,
    conditions: &mut ScriptedConditions,
    steps: i64,
) -> Option<i64> {
    let desc = storyboard(act(
        Some(trigger),
        None,
        group(1, vec![event("E", Priority::Parallel, 1, None, 1)]),
    ));
    let mut sb = build(&desc);
    let mut actions = ScriptedActions::default();
    actions.set(1, 100);
    let log = run(&mut sb, steps, conditions, &mut actions);
    log.iter()
        .find(|r| r.name == "Act")
        .map(|r| step_of(r.time))
}

/// Act `Act` without triggers whose group `MG` (count 1) has one Maneuver `M` with one Event
/// `E` (parallel, count 1, no trigger) running action 1.
pub fn simple_act() -> ActDesc {
    act(
        None,
        None,
        group(1, vec![event("E", Priority::Parallel, 1, None, 1)]),
    )
}

/// esmini 3.6.0's reference transition log `NAME.events.txt` from the shared corpus.
pub fn esmini_events(name: &str) -> String {
    let path = crate::corpus::corpus(&format!("reference/esmini/{name}.events.txt"));
    match std::fs::read_to_string(&path) {
        Ok(text) => text,
        Err(error) => panic!("cannot read {}: {error}", path.display()),
    }
}

/// An action named `name` with runtime id `id`.
pub fn named_action(name: &str, id: u32) -> ActionDesc {
    ActionDesc {
        name: name.to_owned(),
        id: ActionId(id),
    }
}

/// An Event with priority override, count 1, one action.
pub fn override_event(
    name: &str,
    trigger: Option<TriggerDesc>,
    action_name: &str,
    action_id: u32,
) -> EventDesc {
    EventDesc {
        name: name.to_owned(),
        priority: Priority::Override,
        maximum_execution_count: 1,
        start_trigger: trigger,
        actions: vec![named_action(action_name, action_id)],
    }
}

/// Act `name` (no stop trigger) with one ManeuverGroup (count 1) of one Maneuver.
pub fn named_act(
    name: &str,
    start_trigger: Option<TriggerDesc>,
    groups: Vec<ManeuverGroupDesc>,
) -> ActDesc {
    ActDesc {
        name: name.to_owned(),
        start_trigger,
        stop_trigger: None,
        maneuver_groups: groups,
    }
}

/// ManeuverGroup `name` (count 1) with one Maneuver `maneuver` of `events`.
pub fn named_group(name: &str, maneuver: &str, events: Vec<EventDesc>) -> ManeuverGroupDesc {
    ManeuverGroupDesc {
        name: name.to_owned(),
        maximum_execution_count: 1,
        maneuvers: vec![ManeuverDesc {
            name: maneuver.to_owned(),
            events,
        }],
    }
}

/// Log lines grouped by their time stamp, each group sorted: esmini orders the transitions
/// within a step differently (e.g. it ends Init actions after the storyboard starts).
pub fn by_time<'a>(lines: impl Iterator<Item = &'a str>) -> BTreeMap<String, Vec<String>> {
    let mut groups: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for line in lines {
        let time = line.split(' ').next().unwrap_or("").to_owned();
        groups.entry(time).or_default().push(line.to_owned());
    }
    for group in groups.values_mut() {
        group.sort();
    }
    groups
}
