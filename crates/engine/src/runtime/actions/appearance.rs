//! AppearanceAction (OpenSCENARIO 1.3 §7.7.2 private actions, XSD `AppearanceAction`,
//! `LightStateAction`, `AnimationAction`): lights and animations of an entity. They change
//! nothing in the motion; oscsim keeps the state each one set, per entity, and writes every
//! change to the event log (kind `entity`). Instantaneous: a `transitionTime` or
//! `animationDuration` is kept with the state, not played out.

use std::collections::BTreeMap;

use scenario::{AnimationAction, AnimationType, AppearanceAction, LightKind, LightState};

use crate::output::EventRecord;
use crate::runtime::entity::EntityId;
use crate::runtime::world::World;

/// The lights and animations set so far, per entity.
#[derive(Debug, Clone, Default)]
pub(crate) struct Appearances {
    lights: BTreeMap<(EntityId, String), LightState>,
    animations: BTreeMap<(EntityId, String), AnimationAction>,
}

impl World {
    /// The state LightStateAction last gave light `light` of entity `id` (a VehicleLight
    /// type as written in the XSD, e.g. `lowBeam`, or a user-defined light's type).
    pub fn light_state(&self, id: EntityId, light: &str) -> Option<&LightState> {
        self.appearance.lights.get(&(id, light.to_owned()))
    }

    /// The AnimationAction last applied to animation `name` of entity `id` (the component,
    /// pedestrian motion, file path or user-defined type, as in the event log).
    pub fn animation(&self, id: EntityId, name: &str) -> Option<&AnimationAction> {
        self.appearance.animations.get(&(id, name.to_owned()))
    }
}

/// The name of a light.
fn light_name(kind: &LightKind) -> String {
    match kind {
        LightKind::Vehicle(t) => t.as_str().to_owned(),
        LightKind::UserDefined(t) => t.clone(),
        _ => "light".to_owned(),
    }
}

/// The name of an animation.
fn animation_name(kind: &AnimationType) -> String {
    match kind {
        AnimationType::VehicleComponent(c) => c.as_str().to_owned(),
        AnimationType::UserDefinedComponent(c) | AnimationType::UserDefined(c) => c.clone(),
        AnimationType::Pedestrian {
            motion: Some(m), ..
        } => m.as_str().to_owned(),
        AnimationType::Pedestrian { user_defined, .. } => user_defined
            .clone()
            .unwrap_or_else(|| "pedestrian".to_owned()),
        AnimationType::File { filepath, .. } => filepath.clone(),
        _ => "animation".to_owned(),
    }
}

/// Applies `action` to `actor` at `time` on behalf of the action called `element`.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    action: &AppearanceAction,
    element: &str,
    time: f64,
    events: &mut Vec<EventRecord>,
) {
    let change = match action {
        AppearanceAction::LightState(l) => {
            let name = light_name(&l.light_type);
            let change = format!("light {name} {}", l.light_state.mode.as_str());
            world
                .appearance
                .lights
                .insert((actor, name), l.light_state.clone());
            change
        }
        AppearanceAction::Animation(a) => {
            let name = animation_name(&a.animation_type);
            let change = match a.state {
                Some(s) => format!("animation {name} state {s}"),
                None => format!("animation {name}"),
            };
            world.appearance.animations.insert((actor, name), a.clone());
            change
        }
        _ => return,
    };
    events.push(EventRecord::Entity {
        time,
        element: element.to_owned(),
        entity: world.entity(actor).name.clone(),
        change,
    });
}
