//! The plain data every kind of traffic action (OpenSCENARIO 1.3 §7.2.2.3, XSD
//! `TrafficAction`) works on as it spawns and removes vehicles: one action's vehicles
//! ([`Running`]), the notes and run option the traffic stage shares across its actions
//! ([`Spawning`]), and the tables a kind's step changes beside the world ([`Tables`]).
//!
//! This module imports no other module of `traffic`: the kinds (`area`, `source_sink`,
//! `swarm`) and their helpers (`spawn`, `controllers`) read and write it, and `state`, the
//! running table above them, holds it with each action's kind.

use rand_chacha::ChaCha8Rng;

use crate::controller::{ControllerTable, TrafficModel};
use crate::output::EventRecord;
use crate::store::World;
use crate::world::entity::EntityId;

/// What the traffic stage shares across its running actions: the run option for spawned
/// vehicles' controllers and this step's notes for the event log.
#[derive(Debug, Clone, Default)]
pub(crate) struct Spawning {
    /// The controller model spawned vehicles get without one from the scenario
    /// ([`crate::EngineConfig::traffic_model`]).
    pub model: Option<TrafficModel>,
    /// Vehicles spawned and removed in this step, for the event log (step.rs drains them).
    pub events: Vec<EventRecord>,
    /// Time of the frame that first shows this step's changes (s).
    pub frame_time: f64,
}

impl Spawning {
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

/// The tables a traffic action's step changes beside the world: the stage's shared notes, and
/// the user controllers it gives the vehicles it spawns.
pub(crate) struct Tables<'a> {
    /// The run option and the notes for the event log.
    pub spawning: &'a mut Spawning,
    /// The user controllers of every entity (engine module `controller`).
    pub controllers: &'a mut ControllerTable,
}

/// One traffic action's vehicles: its name, random stream and members.
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
}

impl Running {
    /// No vehicle spawned yet.
    pub(crate) fn new(name: String, rng: ChaCha8Rng) -> Self {
        Running {
            name,
            rng,
            spawned: 0,
            members: Vec::new(),
        }
    }

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
