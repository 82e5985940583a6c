//! The running traffic actions (OpenSCENARIO 1.3 XSD `TrafficAction`) and the traffic stage of
//! the step.
//!
//! A traffic action starts, registers here and ends at once in the storyboard (it has no
//! completion of its own); its source, sink or swarm then works at every step, after the
//! controllers and trailers moved, until the run ends or a TrafficStopAction names it.
//! Vehicles spawned in a step appear in that step's frame (t + dt) and in conditions and ByType
//! selections from the next step's triggers on. TrafficStopAction stops spawning and removing;
//! the vehicles already spawned drive on. Positions (source, sink) are resolved once, at the
//! start.

use opendrive::Real;
use scenario::{SourcePos, TrafficAction, TrafficArea};

use super::area::{Area, Shape};
use super::random::stream;
use super::source_sink::{Sink, Source};
use super::spawning::{Running, Spawning, Tables};
use super::swarm::Swarm;
use crate::controller::{ControllerTable, TrafficModel};
use crate::error::{Error, ErrorKind};
use crate::output::EventRecord;
use crate::position::resolve;
use crate::store::World;

/// The traffic actions at work: the traffic stage's table, which the `Engine` keeps.
#[derive(Debug, Clone, Default)]
pub(crate) struct Traffic {
    /// The run option and this step's notes, shared by the running actions.
    spawning: Spawning,
    running: Vec<Action>,
}

impl Traffic {
    /// Some traffic action is at work (the traffic stage will spawn, remove or place
    /// vehicles).
    pub(crate) fn is_running(&self) -> bool {
        !self.running.is_empty()
    }

    /// No traffic action at work yet; spawned vehicles without a controller of their own get
    /// `model` ([`EngineConfig::traffic_model`](crate::EngineConfig::traffic_model)).
    pub(crate) fn new(model: Option<TrafficModel>) -> Self {
        Traffic {
            spawning: Spawning {
                model,
                ..Spawning::default()
            },
            running: Vec::new(),
        }
    }

    /// Vehicles spawned and removed in this step, for the event log (step.rs drains them).
    pub(crate) fn events(&mut self) -> &mut Vec<EventRecord> {
        &mut self.spawning.events
    }
}

/// One traffic action at work: its vehicles and its kind's state.
#[derive(Debug, Clone)]
struct Action {
    run: Running,
    /// Nothing left to do (a one-off TrafficAreaAction that spawned all its vehicles).
    done: bool,
    kind: Kind,
}

#[derive(Debug, Clone)]
enum Kind {
    Swarm(Box<Swarm>),
    Source(Box<Source>),
    Sink(Sink),
    Area(Box<Area>),
}

/// Whether oscsim runs this traffic action (every kind of 1.3).
pub(crate) fn supports(action: &TrafficAction) -> bool {
    matches!(
        action,
        TrafficAction::Source { .. }
            | TrafficAction::Sink { .. }
            | TrafficAction::Swarm { .. }
            | TrafficAction::Area { .. }
            | TrafficAction::Stop
    )
}

/// Starts a traffic action called `action_name` (its `trafficName` if given).
pub(crate) fn start(
    world: &World,
    traffic: &mut Traffic,
    action_name: &str,
    traffic_name: Option<&str>,
    action: &TrafficAction,
    pos: &SourcePos,
) -> Result<(), Error> {
    let name = traffic_name.unwrap_or(action_name).to_owned();
    let point = |world: &World, position| {
        resolve(position, world)
            .map(|r| (r.pose.x, r.pose.y))
            .map_err(|e| Error::new(ErrorKind::Position(e)))
    };
    let positive = |what: &str, v: f64| {
        if v.is_finite() && v >= 0.0 {
            Ok(v)
        } else {
            Err(Error::at(format!("{what} >= 0"), v.to_string(), pos))
        }
    };
    let kind = match action {
        TrafficAction::Stop => {
            let Some(target) = traffic_name else {
                return Err(Error::at(
                    "a trafficName on the TrafficAction of a TrafficStopAction",
                    "none",
                    pos,
                ));
            };
            traffic.running.retain(|a| a.run.name != target);
            return Ok(());
        }
        TrafficAction::Swarm { .. } => Kind::Swarm(Box::new(Swarm::new(world, action, pos)?)),
        TrafficAction::Source {
            position,
            radius,
            rate,
            speed,
            traffic,
        } => Kind::Source(Box::new(Source::new(
            point(world, position)?,
            positive("radius", *radius)?,
            positive("rate", *rate)?,
            *speed,
            traffic.clone(),
        ))),
        TrafficAction::Sink {
            position,
            radius,
            rate,
            ..
        } => Kind::Sink(Sink::new(
            point(world, position)?,
            positive("radius", *radius)?,
            rate.map(|r| positive("rate", r)).transpose()?,
        )),
        TrafficAction::Area {
            continuous,
            number_of_entities,
            area,
            distribution,
        } => {
            let shape = match area {
                TrafficArea::Polygon(corners) => Shape::Polygon(
                    corners
                        .iter()
                        .map(|c| point(world, c))
                        .collect::<Result<_, _>>()?,
                ),
                TrafficArea::RoadRanges(ranges) => Shape::Ranges(
                    ranges
                        .iter()
                        .flat_map(|r| {
                            r.cursors.iter().map(move |(road, s, lanes)| {
                                let from = s.unwrap_or(0.0);
                                let to = r.length.map_or(Real::INFINITY, |l| from + l);
                                (road.clone(), from, to, lanes.clone())
                            })
                        })
                        .collect(),
                ),
                _ => return Err(Error::unsupported("this TrafficArea", pos)),
            };
            Kind::Area(Box::new(Area::new(
                shape,
                *number_of_entities,
                *continuous,
                distribution,
            )))
        }
        _ => return Err(Error::unsupported("this TrafficAction", pos)),
    };
    let rng = stream(world.seed, &name);
    traffic.running.push(Action {
        run: Running::new(name, rng),
        done: false,
        kind,
    });
    Ok(())
}

/// The traffic stage: every running action spawns or removes over one step of `dt` s, giving
/// the vehicles it spawns their controllers in `controllers`. An action's spawn failures (a
/// vehicle template that does not build) end that action.
pub(crate) fn step(
    world: &mut World,
    traffic: &mut Traffic,
    controllers: &mut ControllerTable,
    dt: f64,
) {
    traffic.spawning.frame_time = world.time + dt;
    let mut tables = Tables {
        spawning: &mut traffic.spawning,
        controllers,
    };
    traffic.running.retain_mut(|a| {
        let r = &mut a.run;
        r.members.retain(|&id| world.entity(id).placed);
        let result = match &mut a.kind {
            Kind::Swarm(s) => s.step(world, &mut tables, r),
            Kind::Source(s) => s.step(world, &mut tables, r, dt),
            Kind::Sink(s) => {
                s.step(world, tables.spawning, &r.name, dt);
                Ok(())
            }
            Kind::Area(k) => k.step(world, &mut tables, r).map(|more| {
                if !more {
                    a.done = true;
                }
            }),
        };
        result.is_ok() && !a.done
    });
}
