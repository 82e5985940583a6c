//! Traffic signals at runtime (OpenSCENARIO 1.3: RoadNetwork/TrafficSignals with
//! `TrafficSignalController`, `Phase`, `TrafficSignalState`, `TrafficSignalGroupState`;
//! `TrafficSignalControllerAction`, `TrafficSignalStateAction`; read by
//! `TrafficSignalCondition` and `TrafficSignalControllerCondition`).
//!
//! | module | job |
//! | --- | --- |
//! | `schedule` | which phase each controller is in at a time: cycling, reference and delay, a phase set by an action |
//! | `group` | the signals of a controller, which a phase's TrafficSignalGroupState sets |
//! | `red_light` | run option `stop_at_red_lights`: vehicles stop at red vehicle lights (default and car-following controllers) |
//!
//! [`Signals`] keeps the live state: each controller's phase and each signal's state (the
//! strings of the scenario, e.g. `"off;off;on"`). When a controller enters a phase, the phase's
//! TrafficSignalStates set their signals; a TrafficSignalStateAction sets one signal until the
//! next phase of a controller that lists it sets it again. The state at time t is what the
//! step that begins at t reads in its conditions and what the frame at t shows. Every change is
//! an event record (`kind` `trafficSignalController` with the phases, `trafficSignal` with the
//! states), so a run's log shows when each light switched.

mod group;
mod red_light;
mod schedule;

use scenario::{SourcePos, TrafficSignalController};

use crate::error::Error;
use crate::output::EventRecord;
pub use crate::output::SignalKind;
pub use crate::world::SignalStates;
use red_light::{shows_red, RedLights};
use schedule::Schedule;

/// One controller's names and states, in the scenario's order.
#[derive(Debug, Clone)]
pub(crate) struct Controller {
    pub(crate) name: String,
    /// Phase names and their (signal id, state) lists (a TrafficSignalGroupState already
    /// expanded to every signal of the controller, group.rs).
    pub(crate) phases: Vec<(String, Vec<(String, String)>)>,
}

/// The traffic signal controllers of a run and the current state of every signal.
#[derive(Debug, Clone, Default)]
pub struct Signals {
    controllers: Vec<Controller>,
    schedule: Schedule,
    /// The phase each controller is in (index), once entered.
    current: Vec<Option<usize>>,
    /// Signal id → state.
    states: SignalStates,
    /// Run option `stop_at_red_lights` and the vehicles it holds.
    red_lights: RedLights,
}

impl Signals {
    /// The controllers of a scenario (errors name the controller's or phase's file:line:col)
    /// on a road network with `road_controllers` (its `<controller>`s, OpenDRIVE 1.8 §14).
    /// No phase is entered yet: [`Signals::advance`] at t = 0 enters the first ones.
    pub(crate) fn new(
        controllers: &[TrafficSignalController],
        road_controllers: &[opendrive::Controller],
    ) -> Result<Self, Error> {
        let schedule = Schedule::new(controllers)?;
        Ok(Signals {
            controllers: controllers
                .iter()
                .map(|c| group::phase_states(c, road_controllers))
                .collect::<Result<_, _>>()?,
            schedule,
            current: vec![None; controllers.len()],
            states: SignalStates::default(),
            red_lights: RedLights::default(),
        })
    }

    /// Whether run option `stop_at_red_lights` is on: the driver models' views ask it inline
    /// before [`red_light_ahead`](Self::red_light_ahead), so that a run without the option
    /// costs them no call (issue 31).
    #[inline]
    pub(crate) fn stops_at_red_lights(&self) -> bool {
        self.red_lights.enabled
    }

    /// Turns run option `stop_at_red_lights` on or off (red_light.rs).
    pub(crate) fn set_stop_at_red_lights(&mut self, on: bool) {
        self.red_lights.enabled = on;
    }

    /// With `stop_at_red_lights` on: sets the speed of default-controlled vehicle `e` (entity
    /// index `i`) for its coming move of `dt` s before red vehicle lights (red_light.rs).
    pub(crate) fn govern_speed(
        &mut self,
        net: &opendrive::RoadNetwork,
        i: usize,
        e: &mut crate::world::Entity,
        dt: f64,
    ) {
        if !self.red_lights.enabled {
            return;
        }
        let states = &self.states;
        let red = |id: &str| states.state(id).is_some_and(shows_red);
        self.red_lights.govern(net, red, i, e, dt);
    }

    /// With `stop_at_red_lights` on: the distance (m) from `e`'s front bumper to the nearest
    /// vehicle light ahead on its road that shows red for its direction of travel, when `e`
    /// can still stop before it at its maximum deceleration (red_light.rs); `None` when the
    /// option is off, no such light is ahead, or it is too close to stop for.
    pub(crate) fn red_light_ahead(
        &self,
        net: &opendrive::RoadNetwork,
        e: &crate::world::Entity,
    ) -> Option<f64> {
        if !self.red_lights.enabled {
            return None;
        }
        let red = |id: &str| self.states.state(id).is_some_and(shows_red);
        red_light::light_ahead(net, &red, e).filter(|&d| red_light::can_stop_within(e, d))
    }

    /// The current state of signal `id`, if any was set.
    pub fn state(&self, id: &str) -> Option<&str> {
        self.states.state(id)
    }

    /// The phase controller `name` is in, if it is declared and has phases.
    pub fn phase(&self, name: &str) -> Option<&str> {
        let i = self.controllers.iter().position(|c| c.name == name)?;
        let k = self.current[i]?;
        Some(self.controllers[i].phases[k].0.as_str())
    }

    /// Every signal id with a state, and the state, in id order.
    pub fn states(&self) -> impl Iterator<Item = (&str, &str)> {
        self.states.states()
    }

    /// The state every signal shows, as frames carry it.
    pub fn signal_states(&self) -> &SignalStates {
        &self.states
    }

    /// Brings every controller to time `t`: a controller that enters a new phase sets the
    /// phase's signal states. The changes are pushed to `log`, controllers in declaration order.
    pub(crate) fn advance(&mut self, t: f64, log: &mut Vec<EventRecord>) {
        for i in 0..self.controllers.len() {
            let phase = self.schedule.clocks()[i].phase_at(t);
            if phase.is_some() && phase != self.current[i] {
                self.enter(i, phase, t, log);
            }
        }
    }

    /// Controller `i` enters `phase` at `t`.
    fn enter(&mut self, i: usize, phase: Option<usize>, t: f64, log: &mut Vec<EventRecord>) {
        let Some(k) = phase else { return };
        let c = &self.controllers[i];
        let from = self.current[i].map(|j| c.phases[j].0.clone());
        log.push(EventRecord::Signal {
            time: t,
            element: c.name.clone(),
            kind: SignalKind::Controller,
            from,
            to: c.phases[k].0.clone(),
        });
        self.current[i] = Some(k);
        let states = self.controllers[i].phases[k].1.clone();
        for (id, state) in states {
            self.set_state(&id, &state, t, log);
        }
    }

    /// TrafficSignalStateAction: signal `id` shows `state` from `t` on.
    pub(crate) fn set_state(&mut self, id: &str, state: &str, t: f64, log: &mut Vec<EventRecord>) {
        let from = self.states.0.get(id).cloned();
        if from.as_deref() == Some(state) {
            return;
        }
        log.push(EventRecord::Signal {
            time: t,
            element: id.to_owned(),
            kind: SignalKind::Signal,
            from,
            to: state.to_owned(),
        });
        self.states.0.insert(id.to_owned(), state.to_owned());
    }

    /// TrafficSignalControllerAction: controller `name` enters `phase` at `t` and cycles on
    /// from there; controllers connected to it keep their delay to it (schedule.rs).
    pub(crate) fn set_phase(
        &mut self,
        name: &str,
        phase: &str,
        t: f64,
        pos: &SourcePos,
        log: &mut Vec<EventRecord>,
    ) -> Result<(), Error> {
        let Some(i) = self.controllers.iter().position(|c| c.name == name) else {
            return Err(Error::at(
                "the name of a TrafficSignalController of the RoadNetwork",
                format!("'{name}'"),
                pos,
            ));
        };
        let Some(k) = self.controllers[i].phases.iter().position(|p| p.0 == phase) else {
            let names: Vec<&str> = self.controllers[i]
                .phases
                .iter()
                .map(|p| p.0.as_str())
                .collect();
            return Err(Error::at(
                format!("a phase of controller '{name}' ({})", names.join(", ")),
                format!("'{phase}'"),
                pos,
            ));
        };
        self.schedule.set_phase(i, k, t);
        self.enter(i, Some(k), t, log);
        // Connected controllers take their new place in the cycle at once.
        self.advance(t, log);
        Ok(())
    }
}

#[cfg(test)]
mod tests;
