//! TrafficSourceAction and TrafficSinkAction (OpenSCENARIO 1.3 XSD `TrafficSourceAction`,
//! `TrafficSinkAction`).
//!
//! A source adds vehicles at `rate` per second (the fraction carried from step to step) at
//! random free lane points within `radius` of its position, at its `speed` (else
//! [`DEFAULT_SPEED`](super::swarm::DEFAULT_SPEED)); a vehicle that finds no free point in
//! [`ATTEMPTS`](super::swarm::ATTEMPTS) tries waits for the next step. A sink removes the
//! vehicles (declared or spawned) whose reference point is within `radius` of its position:
//! all of them at once, or with a `rate`, that many per second in id order.

use opendrive::Real;
use scenario::TrafficMix;

use super::spawn::{add, in_disc, lane_point, remove};
use super::spawning::{Running, Spawning, Tables};
use super::swarm::{ATTEMPTS, DEFAULT_SPEED};
use crate::error::Error;
use crate::store::World;
use crate::world::entity::EntityKind;

/// Slack on the vehicles owed by a source (a count).
const DUE_TOLERANCE: Real = crate::tolerance::VALUE;

/// A source's settings and the vehicles it owes.
#[derive(Debug, Clone)]
pub(crate) struct Source {
    at: (Real, Real),
    radius: Real,
    rate: Real,
    speed: Real,
    mix: TrafficMix,
    due: Real,
}

impl Source {
    /// A source at `at` (world x, y).
    pub(crate) fn new(
        at: (Real, Real),
        radius: Real,
        rate: Real,
        speed: Option<Real>,
        mix: TrafficMix,
    ) -> Self {
        Source {
            at,
            radius,
            rate,
            speed: speed.unwrap_or(DEFAULT_SPEED),
            mix,
            due: 0.0,
        }
    }

    /// One step of `dt` s.
    pub(crate) fn step(
        &mut self,
        world: &mut World,
        tables: &mut Tables<'_>,
        run: &mut Running,
        dt: Real,
    ) -> Result<(), Error> {
        self.due += self.rate * dt;
        // Rounding of the running sum (20 × 0.05 is not exactly 1) must not cost a step.
        while self.due >= 1.0 - DUE_TOLERANCE {
            let found = (0..ATTEMPTS).find_map(|_| {
                let (x, y) = in_disc(&mut run.rng, self.at.0, self.at.1, self.radius);
                lane_point(world, x, y)
                    .filter(|p| (p.x - self.at.0).hypot(p.y - self.at.1) <= self.radius)
            });
            let Some(pose) = found else {
                // No room now: try again next step, owing at most one vehicle.
                self.due = self.due.min(1.0);
                break;
            };
            self.due -= 1.0;
            add(world, tables, run, &self.mix, pose, self.speed)?;
        }
        Ok(())
    }
}

/// A sink's settings and its removal budget.
#[derive(Debug, Clone)]
pub(crate) struct Sink {
    at: (Real, Real),
    radius: Real,
    rate: Option<Real>,
    due: Real,
}

impl Sink {
    /// A sink at `at` (world x, y).
    pub(crate) fn new(at: (Real, Real), radius: Real, rate: Option<Real>) -> Self {
        Sink {
            at,
            radius,
            rate,
            due: 0.0,
        }
    }

    /// One step of `dt` s.
    pub(crate) fn step(
        &mut self,
        world: &mut World,
        spawning: &mut Spawning,
        name: &str,
        dt: Real,
    ) {
        let inside = world
            .entities()
            .iter()
            .filter(|e| e.placed && e.kind == EntityKind::Vehicle)
            .filter(|e| (e.pose.x - self.at.0).hypot(e.pose.y - self.at.1) <= self.radius)
            .map(|e| e.id)
            .collect::<Vec<_>>();
        let take = match self.rate {
            None => inside.len(),
            Some(rate) => {
                self.due = (self.due + rate * dt).min(inside.len() as Real);
                let n = self.due.floor();
                self.due -= n;
                n as usize
            }
        };
        for id in inside.into_iter().take(take) {
            remove(world, spawning, name, id);
        }
    }
}
