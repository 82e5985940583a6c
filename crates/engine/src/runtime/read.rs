//! What a running [`Engine`] answers between steps, as plain values (module `snapshot`):
//! the entities in the scene, parameter and variable values, animations, the environment and
//! the road network. Owned copies: reading never exposes the engine's internal state.

use std::sync::Arc;

use opendrive::RoadNetwork;
use scenario::expr::Value;
use scenario::AnimationAction;

use super::Engine;
use crate::output::EntityFrame;
use crate::snapshot::{EntityState, EnvironmentState};
use crate::world::EntityId;

impl Engine {
    /// Every entity in the scene (placed by its Init or an AddEntityAction, not deleted), in
    /// id order.
    pub fn entities(&self) -> Vec<EntityState> {
        let world = self.world();
        world
            .entities()
            .iter()
            .filter(|e| e.placed)
            .map(|e| EntityFrame::of(e).to_state())
            .collect()
    }

    /// The id of the entity called `name`: declared in the scenario (placed yet or not) or
    /// spawned so far.
    pub fn entity_id(&self, name: &str) -> Option<EntityId> {
        self.world().id(name)
    }

    /// The entity called `name`, if it is in the scene.
    pub fn entity(&self, name: &str) -> Option<EntityState> {
        let world = self.world();
        let e = world.entity(world.id(name)?);
        e.placed.then(|| EntityFrame::of(e).to_state())
    }

    /// The current value of global parameter `name` (ParameterSetAction and
    /// ParameterModifyAction change it during the run).
    pub fn parameter(&self, name: &str) -> Option<Value> {
        self.world().parameter_value(name).cloned()
    }

    /// The current value of variable `name` (OpenSCENARIO 1.2+ VariableDeclaration).
    pub fn variable(&self, name: &str) -> Option<Value> {
        self.world().variable_value(name).cloned()
    }

    /// The AnimationAction last applied to animation `name` of entity `entity` (the
    /// component, pedestrian motion, file path or user-defined type, as in the event log).
    pub fn animation(&self, entity: &str, name: &str) -> Option<AnimationAction> {
        let id = self.world().id(entity)?;
        self.actions.appearance.animation(id, name).cloned()
    }

    /// The environment in force (EnvironmentAction: time of day, weather, road condition).
    pub fn environment(&self) -> EnvironmentState {
        self.world().environment.clone()
    }

    /// The road network the engine runs on (shared with every engine built on it).
    pub fn road_network(&self) -> Arc<RoadNetwork> {
        self.world().network.clone()
    }
}
