//! AppearanceAction (OpenSCENARIO 1.3 §7.7.2 private actions, XSD `AppearanceAction`,
//! `LightStateAction`, `AnimationAction`): lights and animations of an entity. They change
//! nothing in the motion; oscsim keeps the state each one set, per entity (the lights on the
//! entity, so that they reach the frames and OSI), and writes every change to the event log
//! (kind `entity`).
//!
//! When each ends: a LightStateAction ends `transitionTime` after its start (XSD
//! `LightStateAction`: "Time to transition from current lightState to given new lightState
//! (default: transitionTime = 0)"; its `LightState` is the state "after execution of the
//! LightStateAction", so the action executes for the transition time). The end is recorded in
//! the step whose advance reaches start + transitionTime, as for every transition over a fixed
//! time (actions::status): transitionTime 1 s from 35.150 s ends at 36.100 s. The state records
//! the new light state from the start; the fading in between is not modelled.
//!
//! esmini 3.6.0 also runs the action for its transitionTime (its `light_state` log:
//! actionHighBeamOn, transitionTime 1, 35.150 → 36.150 s, one step later than oscsim because
//! it counts the time after its check), but never ends an action whose new mode is `flashing`
//! (it keeps the action running to blink the light, until the storyboard stops). The standard
//! makes `flashing` a LightMode like `on`, a state the transition reaches (XSD `LightMode`), so
//! oscsim ends those too.
//!
//! An AnimationAction ends as the standard's action table says (Annex A, "Action ends"): with
//! `loop` true it performs the animation continuously and has "no regular ending", like a
//! PedestrianAnimation (a motion or gestures, performed continuously) unless `loop` is false;
//! otherwise it ends "after animationDuration", and at once without one. An action with no
//! regular ending runs until the storyboard stops it (its Event's stop trigger or an
//! override). The animation itself is not played out: the state records the action.

use std::collections::BTreeMap;

use scenario::{AnimationAction, AnimationType, AppearanceAction, LightKind};

use crate::output::EventRecord;
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::world::entity::EntityId;

/// A LightStateAction running through its `transitionTime`, or an AnimationAction through its
/// `animationDuration` or without a regular ending.
#[derive(Debug, Clone)]
pub(crate) struct Transition {
    /// Simulation time at which the action reaches its goal, s; `None`: no regular ending.
    ends_at: Option<f64>,
}

impl Transition {
    /// Whether the action reaches its goal by `step_end`, the end of the step the runtime is
    /// in: then it ends in this step, like every transition over a fixed time
    /// (actions::status). The 1e-9 s absorbs the rounding of summed steps, as for the
    /// SpeedAction and LaneChangeAction durations.
    pub(crate) fn completes_by(&self, step_end: f64) -> bool {
        self.ends_at
            .is_some_and(|end| step_end >= end - crate::tolerance::TIME)
    }

    /// The status after the step from `now` to `now + dt`.
    pub(crate) fn step(&self, now: f64, dt: f64) -> ActionStatus {
        if self.completes_by(now + dt) {
            ActionStatus::Ended
        } else {
            ActionStatus::Running
        }
    }
}

/// The animations set so far, per entity.
#[derive(Debug, Clone, Default)]
pub(crate) struct Appearances {
    animations: BTreeMap<(EntityId, String), AnimationAction>,
}

impl Appearances {
    /// The AnimationAction last applied to animation `name` of entity `id` (the component,
    /// pedestrian motion, file path or user-defined type, as in the event log).
    pub(crate) fn animation(&self, id: EntityId, name: &str) -> Option<&AnimationAction> {
        self.animations.get(&(id, name.to_owned()))
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

/// When an AnimationAction started at `time` ends (module doc): `None` at once, else the
/// transition to run.
fn animation_end(a: &AnimationAction, time: f64) -> Option<Transition> {
    let pedestrian = matches!(a.animation_type, AnimationType::Pedestrian { .. });
    if a.looping == Some(true) || (pedestrian && a.looping != Some(false)) {
        return Some(Transition { ends_at: None });
    }
    a.animation_duration
        .filter(|&d| d > 0.0)
        .map(|d| Transition {
            ends_at: Some(time + d),
        })
}

/// Applies `action` to `actor` at `time` on behalf of the action called `element`; returns the
/// transition still to run, if any (a LightStateAction's `transitionTime` > 0, an
/// AnimationAction's duration or continuous animation).
pub(crate) fn start(
    world: &mut World,
    appearances: &mut Appearances,
    actor: EntityId,
    action: &AppearanceAction,
    element: &str,
    time: f64,
    events: &mut Vec<EventRecord>,
) -> Option<Transition> {
    let (change, transition) = match action {
        AppearanceAction::LightState(l) => {
            let transition = l.transition_time.filter(|&d| d > 0.0).map(|d| Transition {
                ends_at: Some(time + d),
            });
            let name = light_name(&l.light_type);
            let change = format!("light {name} {}", l.light_state.mode.as_str());
            world
                .entity_mut(actor)
                .lights
                .insert(name, l.light_state.clone());
            (change, transition)
        }
        AppearanceAction::Animation(a) => {
            let name = animation_name(&a.animation_type);
            let change = match a.state {
                Some(s) => format!("animation {name} state {s}"),
                None => format!("animation {name}"),
            };
            appearances.animations.insert((actor, name), a.clone());
            (change, animation_end(a, time))
        }
        _ => return None,
    };
    events.push(EventRecord::Entity {
        time,
        element: element.to_owned(),
        entity: world.entity(actor).name.clone(),
        change,
    });
    transition
}
