//! TrafficSwarmAction (OpenSCENARIO 1.3 XSD `TrafficSwarmAction`): keep `numberOfVehicles`
//! spawned vehicles in the area around a central object, between a circle of `innerRadius`
//! and an ellipse (semi-axes `semiMajorAxis` along the central object's heading,
//! `semiMinorAxis` across it, centre `offset` m ahead of the object).
//!
//! Each step, the swarm's vehicles outside the ellipse leave the scenario; then, while fewer
//! than `numberOfVehicles` remain, one vehicle appears at a random free lane point of the
//! ring (at most [`ATTEMPTS`] points drawn per step, one vehicle per step, so the swarm fills
//! over some seconds as esmini's does). Start speed: uniform in `InitialSpeedRange` (1.2),
//! else `velocity`, else [`DEFAULT_SPEED`]; vehicles take their lane's driving direction. With a
//! `DirectionOfTravelDistribution` (1.2) each new vehicle first draws whether it travels the
//! central object's way (heading within 90° of it) or the opposite way, with probabilities in
//! proportion to `same` and `opposite`, and only lane points of that kind are taken. Nothing
//! appears while the central object is not placed.

use std::f64::consts::FRAC_PI_2;

use opendrive::Real;
use rand::Rng;
use scenario::{SourcePos, TrafficAction, TrafficMix};

use super::spawn::{add, lane_point, remove};
use super::spawning::{Running, Tables};
use crate::error::Error;
use crate::store::World;
use crate::world::EntityId;

/// Random points tried per step for a new vehicle.
pub(crate) const ATTEMPTS: usize = 20;
/// Start speed without `velocity` or `InitialSpeedRange` (m/s, 50 km/h).
pub(crate) const DEFAULT_SPEED: Real = 50.0 / 3.6;

/// A swarm's settings.
#[derive(Debug, Clone)]
pub(crate) struct Swarm {
    /// The central object, resolved when the action starts (each step reads it by id).
    central: EntityId,
    inner: Real,
    major: Real,
    minor: Real,
    offset: Real,
    count: usize,
    speed: (Real, Real),
    /// (same, opposite) weights of the direction of travel.
    direction: Option<(Real, Real)>,
    mix: TrafficMix,
}

impl Swarm {
    /// Reads a `TrafficAction::Swarm`; the central object must be declared in `world`, the
    /// radii ≥ 0 and the ellipse non-degenerate.
    pub(crate) fn new(
        world: &World,
        action: &TrafficAction,
        pos: &SourcePos,
    ) -> Result<Self, Error> {
        let TrafficAction::Swarm {
            central_object,
            inner_radius,
            semi_major_axis,
            semi_minor_axis,
            offset,
            number_of_vehicles,
            velocity,
            initial_speed_range,
            direction_of_travel,
            traffic,
        } = action
        else {
            return Err(Error::at("a TrafficSwarmAction", "another action", pos));
        };
        let positive = |v: f64| v.is_finite() && v > 0.0;
        let valid = inner_radius.is_finite()
            && *inner_radius >= 0.0
            && positive(*semi_major_axis)
            && positive(*semi_minor_axis)
            && offset.is_finite();
        if !valid {
            return Err(Error::at(
                "innerRadius >= 0 and finite semi-axes > 0",
                format!("innerRadius {inner_radius}, semiMajorAxis {semi_major_axis}, semiMinorAxis {semi_minor_axis}"),
                pos,
            ));
        }
        let speed = match (initial_speed_range, velocity) {
            (Some(r), _) => (r.lower_limit, r.upper_limit),
            (None, Some(v)) => (*v, *v),
            _ => (DEFAULT_SPEED, DEFAULT_SPEED),
        };
        let central = world.id(central_object).ok_or_else(|| {
            Error::at(
                "a declared entity",
                format!("centralObject '{central_object}'"),
                pos,
            )
        })?;
        Ok(Swarm {
            central,
            inner: *inner_radius,
            major: *semi_major_axis,
            minor: *semi_minor_axis,
            offset: *offset,
            count: *number_of_vehicles as usize,
            speed,
            direction: direction_of_travel.filter(|(s, o)| s + o > 0.0),
            mix: traffic.clone(),
        })
    }

    /// Whether (x, y) lies inside the ellipse placed on the central object at `c`.
    fn in_ellipse(&self, c: (Real, Real, Real), x: Real, y: Real) -> bool {
        let (u, v) = self.local(c, x, y);
        (u / self.major).powi(2) + (v / self.minor).powi(2) <= 1.0
    }

    /// (x, y) in the ellipse's frame: u along the central heading from the ellipse centre.
    fn local(&self, (cx, cy, h): (Real, Real, Real), x: Real, y: Real) -> (Real, Real) {
        let (dx, dy) = (
            x - cx - self.offset * h.cos(),
            y - cy - self.offset * h.sin(),
        );
        (dx * h.cos() + dy * h.sin(), -dx * h.sin() + dy * h.cos())
    }

    /// One step: remove the swarm's vehicles outside the ellipse, then add one if short.
    pub(crate) fn step(
        &mut self,
        world: &mut World,
        tables: &mut Tables<'_>,
        run: &mut Running,
    ) -> Result<(), Error> {
        let central = world.entity(self.central);
        if !central.placed {
            return Ok(());
        }
        let c = (central.pose.x, central.pose.y, central.pose.h);
        let outside = run
            .members
            .iter()
            .copied()
            .filter(|&id| {
                let p = world.entity(id).pose;
                !self.in_ellipse(c, p.x, p.y)
            })
            .collect::<Vec<_>>();
        for id in outside {
            remove(world, tables.spawning, &run.name, id);
        }
        run.members.retain(|&id| world.entity(id).placed);
        if run.members.len() >= self.count {
            return Ok(());
        }
        let same_way = self
            .direction
            .map(|(same, opposite)| run.rng.gen::<f64>() * (same + opposite) < same);
        for _ in 0..ATTEMPTS {
            let u = (run.rng.gen::<f64>() * 2.0 - 1.0) * self.major;
            let v = (run.rng.gen::<f64>() * 2.0 - 1.0) * self.minor;
            let (h, ox) = (c.2, self.offset);
            let x = c.0 + (ox + u) * h.cos() - v * h.sin();
            let y = c.1 + (ox + u) * h.sin() + v * h.cos();
            let Some(pose) = lane_point(world, x, y) else {
                continue;
            };
            let r = (pose.x - c.0).hypot(pose.y - c.1);
            if r < self.inner || !self.in_ellipse(c, pose.x, pose.y) {
                continue;
            }
            let along = opendrive::normalize_angle(pose.h - c.2).abs() <= FRAC_PI_2;
            if same_way.is_some_and(|same| same != along) {
                continue;
            }
            let (lo, hi) = self.speed;
            let speed = lo + (hi - lo) * run.rng.gen::<f64>();
            add(world, tables, run, &self.mix, pose, speed)?;
            break;
        }
        Ok(())
    }
}
