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
use rand_chacha::ChaCha8Rng;
use scenario::{SourcePos, TrafficAction, TrafficArea};

use super::area::{Area, Shape};
use super::random::stream;
use super::source_sink::{Sink, Source};
use super::swarm::Swarm;
use crate::controller::{ControllerTable, TrafficModel};
use crate::error::{Error, ErrorKind};
use crate::output::EventRecord;
use crate::position::resolve;
use crate::store::World;
use crate::world::entity::EntityId;

/// The traffic actions at work: the traffic stage's table, which the `Engine` keeps.
#[derive(Debug, Clone, Default)]
pub(crate) struct Traffic {
    /// The controller model spawned vehicles get without one from the scenario
    /// ([`crate::EngineConfig::traffic_model`]).
    pub model: Option<TrafficModel>,
    running: Vec<Running>,
    /// Vehicles spawned and removed in this step, for the event log (step.rs drains them).
    pub events: Vec<EventRecord>,
    /// Time of the frame that first shows this step's changes (s).
    frame_time: f64,
}

/// The tables the traffic stage changes beside the world, handed to it by the `Engine` that
/// keeps them: its own, and the user controllers it gives the vehicles it spawns.
pub(crate) struct Tables<'a> {
    /// The traffic actions at work, their notes for the event log and the run option.
    pub traffic: &'a mut Traffic,
    /// The user controllers of every entity (engine module `controller`).
    pub controllers: &'a mut ControllerTable,
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
            model,
            ..Traffic::default()
        }
    }

    /// Records that `entity` underwent `change` (spawned, removed) by traffic action `element`.
    pub(crate) fn note(&mut self, element: &str, entity: &str, change: &str) {
        self.events.push(EventRecord::Entity {
            time: self.frame_time,
            element: element.to_owned(),
            entity: entity.to_owned(),
            change: change.to_owned(),
        });
    }
}

/// One traffic action at work.
#[derive(Debug, Clone)]
pub(crate) struct Running {
    /// `trafficName`, else the action's name: the prefix of its vehicles' names.
    pub name: String,
    /// Its random stream.
    pub rng: ChaCha8Rng,
    /// Vehicles spawned so far (the n of `<name>.entity_<n>`).
    pub spawned: u32,
    /// Its spawned vehicles still in the scenario.
    pub members: Vec<EntityId>,
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

impl Running {
    /// The name of the next vehicle: `<name>.entity_<n>`, n counting on past any name the
    /// world already has (a declared entity may carry such a name).
    pub fn next_name(&mut self, world: &World) -> String {
        loop {
            self.spawned += 1;
            let name = format!("{}.entity_{}", self.name, self.spawned);
            if world.id(&name).is_none() {
                return name;
            }
        }
    }
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
            traffic.running.retain(|r| r.name != target);
            return Ok(());
        }
        TrafficAction::Swarm { .. } => Kind::Swarm(Box::new(Swarm::new(action, pos)?)),
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
    traffic.running.push(Running {
        name,
        rng,
        spawned: 0,
        members: Vec::new(),
        done: false,
        kind,
    });
    Ok(())
}

/// The traffic stage: every running action spawns or removes over one step of `dt` s. An
/// action's spawn failures (a vehicle template that does not build) end that action.
pub(crate) fn step(world: &mut World, tables: &mut Tables<'_>, dt: f64) {
    tables.traffic.frame_time = world.time + dt;
    let mut running = std::mem::take(&mut tables.traffic.running);
    running.retain_mut(|r| {
        r.members.retain(|&id| world.entity(id).placed);
        let mut kind = r.kind.clone();
        let result = match &mut kind {
            Kind::Swarm(s) => s.step(world, tables, r),
            Kind::Source(s) => s.step(world, tables, r, dt),
            Kind::Sink(s) => {
                s.step(world, tables.traffic, &r.name, dt);
                Ok(())
            }
            Kind::Area(a) => a.step(world, tables, r).map(|more| {
                if !more {
                    r.done = true;
                }
            }),
        };
        r.kind = kind;
        result.is_ok() && !r.done
    });
    tables.traffic.running = running;
}
