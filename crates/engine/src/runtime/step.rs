//! The fixed step and its five named stages (OpenSCENARIO 1.3 §8 "Scenario at runtime";
//! semantics-pitfalls #6 for the order of work).
//!
//! [`Engine::step`] calls the stages in order; each stage is one private method that times
//! itself into [`StageCounters`](super::StageCounters):
//!
//! | stage | method | job |
//! | --- | --- | --- |
//! | 1 | `triggers` | values from outside, then the storyboard at t (Init actions first, then stop triggers, start triggers, completions) |
//! | – | `initial_frame` | first step only: the state after the Init actions, written as the frame at t = 0 |
//! | 2 | `actions` | every running action advances to t + dt |
//! | 3 | `controllers` | every entity moves over [t, t + dt]; trailers follow; traffic spawns and removes |
//! | 4 | `measurements` | time becomes t + dt; signal phases advance |
//! | 5 | `output` | the frame at t + dt and the step's records go to the sinks |

use std::cell::RefCell;
use std::time::Instant;

use super::conditions::Conditions;
use super::engine::{Engine, StopReason};
use super::trigger_view::TriggerView;
use crate::actions::{ActionTable, Host};
use crate::controller::ControllerTable;
use crate::error::{Error, ErrorKind};
use crate::output::{EventRecord, EventSink, Frame, FrameSink, SinkError};
use crate::snapshot::ScenarioSource;
use crate::store::World;
use crate::storyboard::{TransitionRecord, TransitionSink};
use crate::traffic::Traffic;

/// The step's event records: transitions, action records and traffic notes, in order.
type Log = RefCell<Vec<EventRecord>>;

impl Engine {
    /// Runs one step at time t = steps · dt, in five fixed stages:
    ///
    /// 1. `triggers`: [`Storyboard::step`](crate::storyboard::Storyboard::step) at t: in the
    ///    first step the Init actions start (and the instantaneous ones, such as TeleportAction
    ///    and step-shaped SpeedAction, take effect and end) before any story trigger is
    ///    evaluated; then stop triggers, start triggers and completions with the conditions
    ///    measured at t. Actions started here take effect now; every trigger of the step sees
    ///    the world as it was when trigger evaluation began (runtime/trigger_view.rs).
    /// 2. `actions`: every running action advances to t + dt (sets the speed and lateral target
    ///    the controllers use over the step) and may end or be replaced in its domain; one that
    ///    fails there (oscsim's RelativeAccelerationAction whose speed change misses its time)
    ///    writes an error record at t + dt and the step returns its error.
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
    ) -> Result<Option<StopReason>, Error> {
        if self.stopped.is_some() {
            return Ok(self.stopped);
        }
        let dt = self.config.dt;
        let time = self.time();
        let log = RefCell::new(std::mem::take(&mut self.host_events));

        if let Some(e) = self.triggers(time, dt, &log)? {
            emit(&log.into_inner(), events)?;
            return Err(e);
        }
        if self.storyboard.is_complete() {
            self.stopped = Some(StopReason::StopTrigger);
        } else if !self.has_stop_trigger && self.storyboard.stories_complete() {
            self.stopped = Some(StopReason::StoriesComplete);
        }
        if self.step == 0 {
            self.initial_frame(time, frames)?;
        }
        if self.stopped.is_some() {
            emit(&log.into_inner(), events)?;
            return Ok(self.stopped);
        }
        if let Some((name, e)) = self.actions(time, dt).into_iter().next() {
            log.borrow_mut()
                .push(EventRecord::error(time + dt, &name, &e));
            emit(&log.into_inner(), events)?;
            return Err(e);
        }
        let moved = self.controllers(time, dt, &log);
        let time = self.measurements(dt, &log);
        self.output(time, moved, log, frames, events)?;

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

    /// Steps until the run ends; returns why. Sinks are finished at the end.
    pub fn run(
        &mut self,
        frames: &mut dyn FrameSink,
        events: &mut dyn EventSink,
    ) -> Result<StopReason, Error> {
        let reason = loop {
            if let Some(reason) = self.step(frames, events)? {
                break reason;
            }
        };
        frames.finish().map_err(output_error("frames"))?;
        events.finish().map_err(output_error("events"))?;
        Ok(reason)
    }

    /// Stage 1: values from outside due by `time`, at t = 0 the signals' first phases and the
    /// monitors' declared values, then the storyboard's step. `Err` when the storyboard fails
    /// (returned at once); `Ok(Some(e))` for the first action that failed to start, which the
    /// step reports after writing the step's records.
    fn triggers(&mut self, time: f64, dt: f64, log: &Log) -> Result<Option<Error>, Error> {
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
        let mut errors = Vec::new();
        let view = RefCell::new(TriggerView::default());
        let mut conditions = Conditions {
            world: &self.world,
            conditions: &self.conditions,
            refs: &self.condition_refs,
            states: &mut self.condition_states,
            reported: &mut self.reported,
            log,
            view: &view,
        };
        let mut host = HostCell {
            table: &mut self.actions,
            world: &self.world,
            controllers: &mut self.controllers,
            traffic: &mut self.traffic,
            log,
            errors: &mut errors,
            view: &view,
            story: self.step > 0,
            time,
            dt,
        };
        self.storyboard
            .step(time, dt, &mut conditions, &mut host, &mut Transitions(log))?;
        self.counters.triggers += clock.elapsed();
        Ok(errors.into_iter().next())
    }

    /// First step only, after stage 1: the Init actions set speeds without a move, so the
    /// velocity follows the speed along the heading; trailers connected at definition stand
    /// behind their tows; the state is written as the frame at t = 0 (timed as output).
    fn initial_frame(&mut self, time: f64, frames: &mut dyn FrameSink) -> Result<(), Error> {
        let world = self.world.get_mut();
        for e in world.entities_mut().iter_mut().filter(|e| e.placed) {
            e.velocity.translational = e.travel_velocity();
        }
        // The trailer stage sets its trailers' own velocity.
        super::trailer_stage::follow(world, 0.0);
        super::finite::check(world.entities(), time).map_err(|(_, e)| e)?;
        let clock = Instant::now();
        frames
            .frame(&frame_of(world, &self.source, time, self.step))
            .map_err(output_error("frames"))?;
        self.counters.output += clock.elapsed();
        Ok(())
    }

    /// Stage 2: every running action advances to t + dt. Returns the actions that failed in
    /// it (their names and errors): the step reports the first and the run stops.
    fn actions(&mut self, time: f64, dt: f64) -> Vec<(String, Error)> {
        let clock = Instant::now();
        let world = self.world.get_mut();
        // Each actor's speed at the stage's start is noted there (actions/mod.rs).
        let failures = self.actions.step_all(world, time, dt);
        self.counters.actions += clock.elapsed();
        failures
    }

    /// Stage 3: user controllers give their commands, then every entity moves
    /// (controller/stage.rs), and what they note is logged (a mandatory lane lost,
    /// controller/mobil.rs); towed vehicles follow their tows' hitches (store/trailer.rs);
    /// traffic sources, sinks and swarms spawn and remove (traffic). Returns what the moves
    /// found of the entities' states for the output stage's guard: `Moved::finite`, every
    /// placed entity was finite after its move; `Moved::traffic`, a traffic action ran after
    /// the moves.
    fn controllers(&mut self, time: f64, dt: f64, log: &Log) -> Moved {
        let clock = Instant::now();
        let world = self.world.get_mut();
        let threads = self.config.controller_threads;
        let finite =
            crate::controller::stage::step(world, &mut self.controllers, time, dt, threads);
        // What the controllers decided from the world at `time` and note (a mandatory lane
        // lost, controller/mobil.rs), at that time.
        let entities = world.entities();
        self.controllers.notes(
            time,
            |i| entities.get(i).map_or("", |e| e.name.as_str()),
            &mut log.borrow_mut(),
        );
        super::trailer_stage::follow(world, dt);
        let traffic = self.traffic.is_running();
        crate::traffic::step(world, &mut self.traffic, &mut self.controllers, dt);
        self.counters.controllers += clock.elapsed();
        Moved { finite, traffic }
    }

    /// Stage 4: time advances to t + dt (the measurements were taken by the controllers'
    /// move); signal controllers advance their phases. Returns the new time.
    fn measurements(&mut self, dt: f64, log: &Log) -> f64 {
        let clock = Instant::now();
        self.step += 1;
        let time = self.step as f64 * dt;
        let world = self.world.get_mut();
        world.time = time;
        world.signals.advance(time, &mut log.borrow_mut());
        self.counters.measurements += clock.elapsed();
        time
    }

    /// Stage 5: the vehicles spawned and removed by traffic actions in this step are logged;
    /// a state that is not finite is refused with the step's records (runtime/finite.rs);
    /// otherwise the frame at `time` and the records go to the sinks.
    fn output(
        &mut self,
        time: f64,
        moved: Moved,
        log: Log,
        frames: &mut dyn FrameSink,
        events: &mut dyn EventSink,
    ) -> Result<(), Error> {
        let clock = Instant::now();
        let world = self.world.get_mut();
        let mut log = log.into_inner();
        log.append(self.traffic.events());
        // The moves tested every entity they moved; the trailers placed after them are
        // tested here, and everything when a traffic action ran (runtime/finite.rs).
        let later = (!moved.traffic).then(|| world.trailers.trailers());
        if let Err((entity, e)) =
            super::finite::check_after_moves(world.entities(), moved.finite, later, time)
        {
            log.push(EventRecord::error(time, &entity, &e));
            emit(&log, events)?;
            return Err(e);
        }
        frames
            .frame(&frame_of(world, &self.source, time, self.step))
            .map_err(output_error("frames"))?;
        emit(&log, events)?;
        self.counters.output += clock.elapsed();
        Ok(())
    }
}

/// What the controllers stage found of the entities' states (`Engine::controllers`).
#[derive(Debug, Clone, Copy)]
struct Moved {
    /// Every placed entity's state was finite after its move.
    finite: bool,
    /// A traffic action ran after the moves (it may have spawned or placed vehicles).
    traffic: bool,
}

/// Hands the step's records to the event sink.
fn emit(records: &[EventRecord], events: &mut dyn EventSink) -> Result<(), Error> {
    records
        .iter()
        .try_for_each(|r| events.event(r))
        .map_err(output_error("events"))
}

/// Collects transitions into the step's event list.
struct Transitions<'a>(&'a Log);

impl TransitionSink for Transitions<'_> {
    fn record(&mut self, record: TransitionRecord) {
        self.0.borrow_mut().push(EventRecord::Transition(record));
    }
}

/// The frame the output stage hands to the sinks: the world's state at `time` (both the t = 0
/// frame and every step's frame are made here).
fn frame_of<'a>(world: &'a World, source: &'a ScenarioSource, time: f64, step: u64) -> Frame<'a> {
    Frame {
        time,
        step,
        entities: world.entities(),
        signals: world.signals.signal_states(),
        environment: &world.environment,
        source,
    }
}

fn output_error(what: &'static str) -> impl Fn(SinkError) -> Error {
    move |error| Error::new(ErrorKind::Output { what, error })
}

/// The action host of stage 1, borrowing the world through its cell (conditions read it in
/// the same storyboard step).
struct HostCell<'a> {
    table: &'a mut ActionTable,
    world: &'a RefCell<World>,
    controllers: &'a mut ControllerTable,
    traffic: &'a mut Traffic,
    log: &'a Log,
    errors: &'a mut Vec<Error>,
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
            controllers: self.controllers,
            traffic: self.traffic,
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
