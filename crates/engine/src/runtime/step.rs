//! The engine and its fixed step (OpenSCENARIO 1.3 §8 "Scenario at runtime";
//! semantics-pitfalls #6 for the order of work).

use std::cell::{Ref, RefCell};
use std::sync::Arc;
use std::time::{Duration, Instant};

use opendrive::RoadNetwork;
use scenario::Scenario;

use super::build::build;
use super::conditions::Conditions;
use super::config::EngineConfig;
use super::error::{RuntimeError, RuntimeErrorKind};
use super::trigger_view::TriggerView;
use super::world::World;
use crate::actions::{stop_domain, ActionTable, Domain, Host};
use crate::condition::ConditionStates;
use crate::output::{EventRecord, EventSink, Frame, FrameSink, SinkError};
use crate::snapshot::ScenarioSource;
use crate::storyboard::{Storyboard, TransitionRecord, TransitionSink};

/// Why a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StopReason {
    /// The storyboard's stop trigger fired.
    StopTrigger,
    /// Every Story completed and the storyboard has no stop trigger.
    StoriesComplete,
    /// The requested duration elapsed.
    Duration,
    /// The hard cap on simulated time was reached.
    TimeCap,
}

impl std::fmt::Display for StopReason {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            StopReason::StopTrigger => "the storyboard's stop trigger fired",
            StopReason::StoriesComplete => "every story completed",
            StopReason::Duration => "the requested duration elapsed",
            StopReason::TimeCap => "the hard cap on simulated time was reached",
        })
    }
}

/// Wall time spent in each stage of [`Engine::step`] since the engine was built.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct StageCounters {
    /// Stage 1, `triggers`.
    pub triggers: Duration,
    /// Stage 2, `actions`.
    pub actions: Duration,
    /// Stage 3, `controllers`.
    pub controllers: Duration,
    /// Stage 4, `measurements`.
    pub measurements: Duration,
    /// Stage 5, `output`.
    pub output: Duration,
}

/// A scenario ready to run: world, storyboard, action and condition tables.
#[derive(Debug)]
pub struct Engine {
    world: RefCell<World>,
    storyboard: Storyboard,
    actions: ActionTable,
    conditions: Vec<scenario::Condition>,
    condition_states: ConditionStates,
    reported: Vec<bool>,
    has_stop_trigger: bool,
    config: EngineConfig,
    step: u64,
    stopped: Option<StopReason>,
    counters: StageCounters,
    /// User-defined values still to be set, by time (user_values.rs).
    scheduled_values: std::collections::VecDeque<crate::user_values::TimedValue>,
    /// Records of changes the host program made between steps (a controller attached), written
    /// with the next step's records.
    host_events: Vec<EventRecord>,
    /// The scenario and road files (on every frame).
    source: ScenarioSource,
}

/// Collects transitions into the step's event list.
struct Transitions<'a>(&'a RefCell<Vec<EventRecord>>);

impl TransitionSink for Transitions<'_> {
    fn record(&mut self, record: TransitionRecord) {
        self.0.borrow_mut().push(EventRecord::Transition(record));
    }
}

impl Engine {
    /// Builds an engine for `scenario` on `network`, the road network its
    /// `RoadNetwork/LogicFile` names ([`load::road_network`](crate::load::road_network)). The
    /// network is shared, not copied: every engine of a batch can run on one `Arc`. Reads no
    /// file.
    pub fn new(
        scenario: &Scenario,
        network: Arc<RoadNetwork>,
        config: EngineConfig,
    ) -> Result<Engine, RuntimeError> {
        config.validate()?;
        // Places the road network does not have are refused now, not when first needed.
        crate::position::check_positions(scenario, &network)
            .map_err(|e| RuntimeError::new(RuntimeErrorKind::Position(e)))?;
        let mut built = build(scenario, network)?;
        built.world.traffic.seed = config.seed;
        built.world.traffic.model = config.traffic_model;
        built
            .world
            .signals
            .set_stop_at_red_lights(config.stop_at_red_lights);
        let mut host_events = Vec::new();
        if let Some(model) = config.vehicle_model {
            crate::traffic::equip_scenario_vehicles(&mut built.world, model, &mut host_events)?;
        }
        let storyboard = Storyboard::new(&built.desc)?;
        Ok(Engine {
            world: RefCell::new(built.world),
            storyboard,
            actions: built.actions,
            reported: vec![false; built.conditions.len()],
            conditions: built.conditions,
            condition_states: ConditionStates::new(),
            has_stop_trigger: built.desc.stop_trigger.is_some(),
            config,
            step: 0,
            stopped: None,
            counters: StageCounters::default(),
            scheduled_values: std::collections::VecDeque::new(),
            host_events,
            source: ScenarioSource::of(scenario),
        })
    }

    /// The scenario and road files the engine was built from.
    pub fn source(&self) -> &ScenarioSource {
        &self.source
    }

    /// The world (entities, road network, values) as it is now.
    pub(crate) fn world(&self) -> Ref<'_, World> {
        self.world.borrow()
    }

    /// The storyboard and its element states.
    pub fn storyboard(&self) -> &Storyboard {
        &self.storyboard
    }

    /// The settings.
    pub fn config(&self) -> &EngineConfig {
        &self.config
    }

    /// Simulation time of the next step (s).
    pub fn time(&self) -> f64 {
        self.step as f64 * self.config.dt
    }

    /// Number of steps run.
    pub fn steps(&self) -> u64 {
        self.step
    }

    /// Why the run ended, once it has.
    pub fn stop_reason(&self) -> Option<StopReason> {
        self.stopped
    }

    /// Sets the user-defined value `name` (UserDefinedValueCondition) from now on: conditions
    /// evaluated in the next step read it.
    pub fn set_user_value(&mut self, name: &str, value: scenario::expr::Value) {
        self.world.get_mut().user_values.set(name, value);
    }

    /// Sets global parameter `name` from outside between steps, as a ParameterSetAction would
    /// (OpenSCENARIO 1.3 §7.7.1): `value` is converted to the parameter's declared type without
    /// loss ([`scenario::expr::Value::convert_to`]; text is parsed as the type); conditions of
    /// the next step read it. Returns `Ok(false)`, changing nothing, when the scenario declares
    /// no global parameter `name`.
    pub fn set_parameter(
        &mut self,
        name: &str,
        value: &scenario::expr::Value,
    ) -> Result<bool, scenario::expr::ExprError> {
        use scenario::expr::Value;
        let parameters = &mut self.world.get_mut().parameters;
        let Some(old) = parameters.get(name) else {
            return Ok(false);
        };
        let ty = old.value_type();
        let new = match value {
            Value::String(text) => Value::parse(ty, text)?,
            v => v.convert_to(ty)?,
        };
        parameters.insert(name.to_owned(), new);
        Ok(true)
    }

    /// Sets each of `values` at the start of the first step at or after its time (before the
    /// step's triggers), in time order; values of equal time in the order given.
    pub fn schedule_user_values(&mut self, values: &[crate::user_values::TimedValue]) {
        let mut all: Vec<_> = self
            .scheduled_values
            .drain(..)
            .chain(values.iter().cloned())
            .collect();
        all.sort_by(|a, b| a.time.total_cmp(&b.time));
        self.scheduled_values = all.into();
    }

    /// The current value of every monitor (MonitorDeclaration), by name.
    pub fn monitors(&self) -> Vec<(String, bool)> {
        let world = self.world.borrow();
        world
            .monitors
            .iter()
            .map(|(k, v)| (k.clone(), *v))
            .collect()
    }

    /// The current state of every traffic signal that has one, by signal id.
    pub fn signal_states(&self) -> Vec<(String, String)> {
        let world = self.world.borrow();
        world
            .signals
            .states()
            .map(|(k, v)| (k.to_owned(), v.to_owned()))
            .collect()
    }

    /// Wall time per stage so far.
    pub fn counters(&self) -> &StageCounters {
        &self.counters
    }

    /// Hands entity `name` to the host program: assigns it an `external` controller (named
    /// "external") activated on the longitudinal and lateral domains, as an
    /// AssignControllerAction with both `activate*` flags would, and stops the motion actions
    /// running on it (engine module `controller`). Until the first
    /// [`set_external_input`](Self::set_external_input) the entity drives as under the default
    /// controller. Logged with the next step's records (element "host").
    pub fn attach_external(&mut self, name: &str) -> Result<(), RuntimeError> {
        let time = self.time();
        let world = self.world.get_mut();
        let id = world.id(name).ok_or_else(|| {
            RuntimeError::new(RuntimeErrorKind::NotExternal {
                found: format!("no entity named '{name}'"),
            })
        })?;
        let pos =
            scenario::SourcePos::start_of(std::sync::Arc::from(std::path::Path::new("<host>")));
        let controller = scenario::Controller {
            name: "external".to_owned(),
            controller_type: None,
            properties: scenario::Properties {
                properties: vec![("model".to_owned(), "external".to_owned())],
                ..scenario::Properties::default()
            },
            catalog: None,
            pos: pos.clone(),
        };
        let origin = crate::controller::Origin {
            element: "host",
            time,
            pos: &pos,
        };
        let both = scenario::ControllerDomains {
            longitudinal: Some(true),
            lateral: Some(true),
            ..scenario::ControllerDomains::default()
        };
        let taken = crate::controller::assign(
            world,
            id,
            &controller,
            None,
            &both,
            &origin,
            &mut self.host_events,
        )?;
        if taken.longitudinal {
            stop_domain(&mut self.actions, world, id, Domain::Longitudinal);
        }
        if taken.lateral {
            stop_domain(&mut self.actions, world, id, Domain::Lateral);
        }
        Ok(())
    }

    /// Gives entity `name`'s active `external` controller its input for the next steps (engine
    /// module `controller`, `external`): a pose, an acceleration with an optional wheel angle,
    /// or driver inputs. The input holds until the next call. Errors when the entity does not
    /// exist or no active `external` controller holds one of its motion domains.
    pub fn set_external_input(
        &mut self,
        name: &str,
        input: crate::controller::ExternalInput,
    ) -> Result<(), RuntimeError> {
        let world = self.world.get_mut();
        let not_external =
            |found: String| RuntimeError::new(RuntimeErrorKind::NotExternal { found });
        let id = world
            .id(name)
            .ok_or_else(|| not_external(format!("no entity named '{name}'")))?;
        let ctrl = world.controllers.of_mut(id.index());
        let external = ctrl
            .assigned
            .iter()
            .any(|a| a.model_name() == "external" && a.holds() != Default::default());
        if !external {
            return Err(not_external(format!(
                "'{name}' without one (assign a Controller with <Property name=\"model\" value=\"external\"/> and activate it)"
            )));
        }
        ctrl.external = Some(input);
        Ok(())
    }

    /// Runs one step at time t = steps · dt, in five fixed stages:
    ///
    /// 1. `triggers`: [`Storyboard::step`] at t: in the first step the Init actions start (and
    ///    the instantaneous ones, such as TeleportAction and step-shaped SpeedAction, take effect
    ///    and end) before any story trigger is evaluated; then stop triggers, start triggers and
    ///    completions with the conditions measured at t. Actions started here take effect now;
    ///    every trigger of the step sees the world as it was when trigger evaluation began
    ///    (runtime/trigger_view.rs).
    /// 2. `actions`: every running action advances to t + dt (sets the speed and lateral target
    ///    the controllers use over the step) and may end or be replaced in its domain.
    /// 3. `controllers`: the default controller moves each entity over [t, t + dt], longitudinal
    ///    then lateral.
    /// 4. `measurements`: time becomes t + dt; road position, speed, velocity, acceleration,
    ///    yaw rate and odometer are those after the move.
    /// 5. `output`: the frame at t + dt and the step's event records go to the sinks (the first
    ///    step also writes the frame at t = 0, after the Init actions).
    ///
    /// So a transition logged at t acts on the motion from t on, as in esmini's reference runs.
    /// Returns the stop reason once the run is over; a step after that does nothing.
    pub fn step(
        &mut self,
        frames: &mut dyn FrameSink,
        events: &mut dyn EventSink,
    ) -> Result<Option<StopReason>, RuntimeError> {
        if self.stopped.is_some() {
            return Ok(self.stopped);
        }
        let dt = self.config.dt;
        let time = self.time();
        let log = RefCell::new(std::mem::take(&mut self.host_events));
        let mut errors = Vec::new();
        let view = RefCell::new(TriggerView::default());

        // Stage 1: triggers and transitions.
        let clock = Instant::now();
        self.world.get_mut().time = time;
        // Values from outside due by now (within a millionth of a step of round-off).
        while let Some(v) = self
            .scheduled_values
            .front()
            .filter(|v| v.time <= time + dt * crate::tolerance::STEP_FRACTION)
        {
            let v = v.clone();
            self.scheduled_values.pop_front();
            self.world.get_mut().user_values.set(v.name, v.value);
        }
        if self.step == 0 {
            // Signal controllers enter their phases at t = 0 and monitors show their declared
            // values, before the Init actions (which may set a signal's state).
            let world = self.world.get_mut();
            world.signals.advance(time, &mut log.borrow_mut());
            let monitors = world
                .monitors
                .iter()
                .map(|(name, &value)| EventRecord::Monitor {
                    time,
                    element: name.clone(),
                    value,
                });
            log.borrow_mut().extend(monitors);
        }
        {
            let mut conditions = Conditions {
                world: &self.world,
                conditions: &self.conditions,
                states: &mut self.condition_states,
                reported: &mut self.reported,
                log: &log,
                view: &view,
            };
            let mut host = HostCell {
                table: &mut self.actions,
                world: &self.world,
                log: &log,
                errors: &mut errors,
                view: &view,
                story: self.step > 0,
                time,
                dt,
            };
            self.storyboard
                .step(time, dt, &mut conditions, &mut host, &mut Transitions(&log))?;
        }
        self.counters.triggers += clock.elapsed();
        if let Some(e) = errors.into_iter().next() {
            self.emit(&log.into_inner(), events)?;
            return Err(e);
        }
        if self.storyboard.is_complete() {
            self.stopped = Some(StopReason::StopTrigger);
        } else if !self.has_stop_trigger && self.storyboard.stories_complete() {
            self.stopped = Some(StopReason::StoriesComplete);
        }
        let world = self.world.get_mut();
        if self.step == 0 {
            // The Init actions set speeds without a move: the velocity follows the speed along
            // the heading from the first frame (the trailer stage sets its trailers' own).
            for e in world.entities.iter_mut().filter(|e| e.placed) {
                e.velocity.translational = e.travel_velocity();
            }
            // Trailers connected at definition stand behind their tows from the first frame.
            super::trailer::follow(world, 0.0);
            // The frame at t = 0: the initial state after the Init actions.
            super::finite::check(&world.entities, time).map_err(|(_, e)| e)?;
            let clock = Instant::now();
            frames
                .frame(&frame_of(world, &self.source, time, self.step))
                .map_err(output_error("frames"))?;
            self.counters.output += clock.elapsed();
        }
        if self.stopped.is_some() {
            self.emit(&log.into_inner(), events)?;
            return Ok(self.stopped);
        }

        // Stage 2: actions.
        let clock = Instant::now();
        for e in world.entities.iter_mut() {
            e.start_speed = e.speed;
        }
        self.actions.step_all(world, time, dt);
        self.counters.actions += clock.elapsed();

        // Stage 3: controllers.
        let clock = Instant::now();
        // User controllers give their commands, then every entity moves (controller/stage.rs).
        crate::controller::stage::step(world, time, dt);
        // Towed vehicles follow their tows' hitches (runtime/trailer.rs).
        super::trailer::follow(world, dt);
        // Traffic sources, sinks and swarms (traffic).
        crate::traffic::step(world, dt);
        self.counters.controllers += clock.elapsed();

        // Stage 4: time advance and measurements (taken by the controllers' move).
        let clock = Instant::now();
        self.step += 1;
        let time = self.step as f64 * dt;
        world.time = time;
        world.signals.advance(time, &mut log.borrow_mut());
        self.counters.measurements += clock.elapsed();

        // Stage 5: output. Vehicles spawned and removed by traffic actions in this step
        // (traffic); a state that is not finite is refused with the step's records
        // (runtime/finite.rs).
        let clock = Instant::now();
        log.borrow_mut().append(&mut world.traffic.events);
        if let Err((entity, e)) = super::finite::check(&world.entities, time) {
            log.borrow_mut().push(EventRecord::error(time, &entity, &e));
            self.emit(&log.into_inner(), events)?;
            return Err(e);
        }
        frames
            .frame(&frame_of(world, &self.source, time, self.step))
            .map_err(output_error("frames"))?;
        self.emit(&log.into_inner(), events)?;
        self.counters.output += clock.elapsed();

        let end = self.config.end_time();
        // Within a millionth of a step of the end: round-off of steps · dt, at any dt.
        if time >= end - dt * crate::tolerance::STEP_FRACTION {
            self.stopped = Some(match self.config.duration {
                Some(d) if d <= self.config.max_time => StopReason::Duration,
                _ => StopReason::TimeCap,
            });
        }
        Ok(self.stopped)
    }

    fn emit(
        &self,
        records: &[EventRecord],
        events: &mut dyn EventSink,
    ) -> Result<(), RuntimeError> {
        records
            .iter()
            .try_for_each(|r| events.event(r))
            .map_err(output_error("events"))
    }

    /// Steps until the run ends; returns why. Sinks are finished at the end.
    pub fn run(
        &mut self,
        frames: &mut dyn FrameSink,
        events: &mut dyn EventSink,
    ) -> Result<StopReason, RuntimeError> {
        let reason = loop {
            if let Some(reason) = self.step(frames, events)? {
                break reason;
            }
        };
        frames.finish().map_err(output_error("frames"))?;
        events.finish().map_err(output_error("events"))?;
        Ok(reason)
    }
}

/// The frame the output stage hands to the sinks: the world's state at `time` (both the t = 0
/// frame and every step's frame are made here).
fn frame_of<'a>(world: &'a World, source: &'a ScenarioSource, time: f64, step: u64) -> Frame<'a> {
    Frame {
        time,
        step,
        entities: &world.entities,
        signals: &world.signals,
        environment: &world.environment,
        source,
    }
}

fn output_error(what: &'static str) -> impl Fn(SinkError) -> RuntimeError {
    move |error| RuntimeError::new(RuntimeErrorKind::Output { what, error })
}

/// The action host of stage 1, borrowing the world through its cell (conditions read it in
/// the same storyboard step).
struct HostCell<'a> {
    table: &'a mut ActionTable,
    world: &'a RefCell<World>,
    log: &'a RefCell<Vec<EventRecord>>,
    errors: &'a mut Vec<RuntimeError>,
    view: &'a RefCell<TriggerView>,
    /// The Init actions have started: actions started now belong to the Stories.
    story: bool,
    time: f64,
    dt: f64,
}

impl HostCell<'_> {
    fn with<R>(&mut self, f: impl FnOnce(&mut Host<'_>) -> R) -> R {
        let mut world = self.world.borrow_mut();
        // Conditions still to be evaluated in this step see the world as it was before.
        self.view.borrow_mut().before_change(&world);
        let mut events = self.log.borrow_mut();
        let mut host = Host {
            table: self.table,
            world: &mut world,
            events: &mut events,
            errors: self.errors,
            story: self.story,
            time: self.time,
        };
        f(&mut host)
    }
}

impl crate::storyboard::ActionHost for HostCell<'_> {
    fn start(&mut self, id: crate::storyboard::ActionId) {
        self.with(|h| h.start(id));
    }

    fn stop(&mut self, id: crate::storyboard::ActionId) {
        self.with(|h| h.stop(id));
    }

    fn status(&self, id: crate::storyboard::ActionId) -> crate::storyboard::ActionStatus {
        crate::actions::status(self.table, id, self.time + self.dt)
    }

    fn init_complete(&mut self) {
        self.story = true;
    }
}
