//! When each traffic signal controller is in which phase (OpenSCENARIO 1.3,
//! `TrafficSignalController`, `Phase`).
//!
//! A controller runs its phases in order, each for its `duration`, and starts over after the
//! last: the cycle time is the sum of the durations. A controller without `reference` starts
//! its first phase at t = 0. A controller with `reference` and `delay` is connected to the
//! referenced one: "its first phase virtually starts `delay` seconds after the start of the
//! reference's first phase" (1.3, TrafficSignalController.delay). *Virtually*: the controller
//! does not wait; at t = 0 it is already where a cycle begun at t = `delay` would be, i.e. the
//! phase at t is the one at the cycle position `(t − origin) mod cycle` with
//! `origin = origin(reference) + delay`.
//!
//! A TrafficSignalControllerAction at time t puts its controller at the start of the named phase
//! (its origin becomes t minus that phase's offset in the cycle), and the controller cycles on
//! from there. Controllers connected to it keep their delay to it: their origins move with it
//! (the connection is a standing relation between the two, not a one-off start offset; the
//! standard does not say otherwise).
//!
//! A phase covers `[start, start + duration)` of the cycle; a phase of duration 0 is entered and
//! left at the same instant and is never reported. Cycle positions within [`BOUNDARY`] of a
//! phase's start count as that phase (steps of `k · dt` round off around phase boundaries). A
//! controller whose phases are all of duration 0 (cycle time 0), or that has none, does not
//! cycle: it stays in the phase it was put in (the first one at the start).

use std::collections::BTreeMap;

use scenario::{SourcePos, TrafficSignalController};

use crate::error::Error;

/// A cycle position within this many seconds before a phase's start counts as that phase.
pub(crate) const BOUNDARY: f64 = crate::tolerance::TIME;

/// The timing of one controller.
#[derive(Debug, Clone)]
pub(crate) struct Clock {
    /// Offset of each phase's start within the cycle (s); `starts[0] = 0`.
    starts: Vec<f64>,
    /// Duration of each phase (s).
    durations: Vec<f64>,
    /// The cycle time (s).
    cycle: f64,
    /// The referenced controller (index) and the delay to it (s).
    reference: Option<(usize, f64)>,
    /// When the cycle's first phase (virtually) starts (s).
    origin: f64,
    /// For a controller that does not cycle: the phase it was put in.
    held: usize,
}

impl Clock {
    /// The phase at time `t`; `None` for a controller without phases.
    pub(crate) fn phase_at(&self, t: f64) -> Option<usize> {
        if self.starts.is_empty() {
            return None;
        }
        if self.cycle <= 0.0 {
            return Some(self.held);
        }
        let p = (t - self.origin).rem_euclid(self.cycle);
        // The last phase of positive duration whose start is at or (within BOUNDARY) after p;
        // past the last start, around the wrap, the cycle begins again.
        let phase = (0..self.starts.len())
            .rev()
            .find(|&k| self.durations[k] > 0.0 && self.starts[k] <= p + BOUNDARY)
            .unwrap_or(0);
        if p + BOUNDARY >= self.cycle {
            return Some(self.first_timed());
        }
        Some(phase)
    }

    /// The first phase of positive duration (phase 0 when none has).
    fn first_timed(&self) -> usize {
        self.durations.iter().position(|&d| d > 0.0).unwrap_or(0)
    }
}

/// The timing of every controller of a scenario, in declaration order.
#[derive(Debug, Clone, Default)]
pub(crate) struct Schedule {
    clocks: Vec<Clock>,
}

impl Schedule {
    /// The schedule of `controllers`: references resolved, origins set for t = 0.
    ///
    /// Errors (with the controller's file:line:col): a reference to no controller, a reference
    /// without a delay, a negative or non-finite delay or duration, a cycle of references.
    pub(crate) fn new(controllers: &[TrafficSignalController]) -> Result<Self, Error> {
        let index: BTreeMap<&str, usize> = controllers
            .iter()
            .enumerate()
            .map(|(i, c)| (c.name.as_str(), i))
            .collect();
        let mut clocks = Vec::with_capacity(controllers.len());
        for c in controllers {
            let mut starts = Vec::with_capacity(c.phases.len());
            let mut cycle = 0.0;
            for p in &c.phases {
                if !(p.duration.is_finite() && p.duration >= 0.0) {
                    return Err(Error::at(
                        "a Phase duration ≥ 0 s",
                        p.duration.to_string(),
                        &p.pos,
                    ));
                }
                starts.push(cycle);
                cycle += p.duration;
            }
            let reference = match (&c.reference, c.delay) {
                (None, _) => None,
                (Some(name), delay) => {
                    let Some(&r) = index.get(name.as_str()) else {
                        return Err(Error::at(
                            "the name of a TrafficSignalController as reference",
                            format!("'{name}'"),
                            &c.pos,
                        ));
                    };
                    let delay = check_delay(delay, &c.pos)?;
                    Some((r, delay))
                }
            };
            clocks.push(Clock {
                durations: c.phases.iter().map(|p| p.duration).collect(),
                starts,
                cycle,
                reference,
                origin: 0.0,
                held: 0,
            });
        }
        let mut schedule = Schedule { clocks };
        for (i, c) in controllers.iter().enumerate() {
            schedule.check_acyclic(i, &c.pos)?;
        }
        for i in 0..schedule.clocks.len() {
            schedule.clocks[i].origin = schedule.chained_origin(i);
        }
        Ok(schedule)
    }

    /// Refuses a chain of references from controller `i` that comes back to a controller it
    /// passed.
    fn check_acyclic(&self, i: usize, pos: &SourcePos) -> Result<(), Error> {
        let mut at = i;
        for _ in 0..=self.clocks.len() {
            match self.clocks[at].reference {
                None => return Ok(()),
                Some((r, _)) => at = r,
            }
        }
        Err(Error::at(
            "TrafficSignalController references without a cycle",
            "a controller that references itself through its reference chain",
            pos,
        ))
    }

    /// The origin of controller `i` from its reference chain (the chain is acyclic).
    fn chained_origin(&self, i: usize) -> f64 {
        match self.clocks[i].reference {
            None => self.clocks[i].origin,
            Some((r, delay)) => self.chained_origin(r) + delay,
        }
    }

    /// The clocks, in declaration order.
    pub(crate) fn clocks(&self) -> &[Clock] {
        &self.clocks
    }

    /// Puts controller `i` at the start of `phase` at time `t` (TrafficSignalControllerAction);
    /// controllers connected to it, directly or through others, move with it.
    pub(crate) fn set_phase(&mut self, i: usize, phase: usize, t: f64) {
        let clock = &mut self.clocks[i];
        clock.held = phase;
        clock.origin = t - clock.starts.get(phase).copied().unwrap_or(0.0);
        // Clear a reference of its own: the action decides this controller's time now.
        clock.reference = None;
        for j in 0..self.clocks.len() {
            if self.depends_on(j, i) {
                self.clocks[j].origin = self.chained_origin(j);
            }
        }
    }

    /// Whether controller `j` references `i` through its chain.
    fn depends_on(&self, j: usize, i: usize) -> bool {
        let mut at = j;
        for _ in 0..self.clocks.len() {
            match self.clocks[at].reference {
                Some((r, _)) if r == i => return true,
                Some((r, _)) => at = r,
                None => return false,
            }
        }
        false
    }
}

/// The delay of a controller with a reference: required, finite (any sign: a negative delay
/// starts the controller's cycle before its reference's).
fn check_delay(delay: Option<f64>, pos: &SourcePos) -> Result<f64, Error> {
    match delay {
        Some(d) if d.is_finite() => Ok(d),
        Some(d) => Err(Error::at("a finite delay (s)", d.to_string(), pos)),
        None => Err(Error::at(
            "a delay with the reference (1.3: a controller with a reference has a delay to it)",
            "no delay",
            pos,
        )),
    }
}
