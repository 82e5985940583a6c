//! The world as the triggers of one step see it: every condition evaluated in stage 1 of a step
//! measures the entities as they stood when that step's trigger evaluation began (OpenSCENARIO 1.3
//! §8.3.1, §8.4; semantics-pitfalls #6).
//!
//! # The rule
//!
//! Within one step the storyboard walks its triggers in document order, and an Event that
//! fires starts its actions at once; an instantaneous action (TeleportAction, a `step`
//! SpeedAction, AddEntityAction …) then changes the entities inside the walk. The standard treats
//! the Stories, Acts and ManeuverGroups of a storyboard as concurrent (§8.3.1: only start
//! triggers, action execution and stop triggers take simulation time) and gives their document
//! order no meaning, so whether a later trigger of the same step sees that change must not
//! depend on where it is written. oscsim therefore fixes: **every condition of a step measures
//! the entities as they stood when the step's trigger evaluation began** (in the first step,
//! after the Init actions, §8.5.1) — the state the previous step's `measurements` stage took,
//! like a sensor sampling once per step. Actions started in the step act on the entities at
//! once (the step's frame shows it, and the motion goes on from there); conditions see it from
//! the next step.
//!
//! The scenario's values — parameters, variables and traffic signal states — are not
//! measurements: a value set in the step is what the scenario holds from then on, and
//! conditions evaluated after the setting action read it. esmini's `traffic_lights` reference
//! depends on this (a TrafficSignalStateAction at 3.55 s and the condition "signal 1 is yellow,
//! delay 3 s" of a later Event firing at 6.55 s), while its `lane_change_simple` reference shows
//! the entity rule (two Events triggered by the same EndOfRoadCondition start in one step,
//! although the first one teleports the entity away from the road's end). For values, the
//! order of the storyboard walk (document order, storyboard::executor) decides within a step.
//! StoryboardElementStateConditions read the element states as the walk leaves them.
//!
//! # How
//!
//! Nothing is copied in the common step in which no action starts after the first condition was
//! asked. When the first action starts (or stops) after that, the entity store is copied first;
//! from then on each condition evaluation swaps the copy in and out (a pointer swap), so the
//! conditions read the step-start entities while the actions keep changing the live ones.

use crate::store::World;
use crate::world::entity::Entity;

/// The state conditions read during one step's trigger evaluation; make a new one per step.
#[derive(Debug, Default)]
pub(crate) struct TriggerView {
    /// A condition has been evaluated in this step.
    begun: bool,
    /// The entity store as it was before the first change after `begun`.
    frozen: Option<Vec<Entity>>,
}

impl TriggerView {
    /// Call before an action changes `world` during stage 1: keeps the state conditions must
    /// still see, if a condition has been evaluated in this step and nothing was kept yet.
    pub(crate) fn before_change(&mut self, world: &World) {
        if self.begun && self.frozen.is_none() {
            self.frozen = Some(world.entities().to_vec());
        }
    }

    /// Runs a condition evaluation `f` on the world as the step's triggers see it.
    pub(crate) fn evaluate<R>(&mut self, world: &mut World, f: impl FnOnce(&World) -> R) -> R {
        self.begun = true;
        let Some(frozen) = self.frozen.as_mut() else {
            return f(world);
        };
        // Entities added to the store during the walk (spawned objects) keep their ids, which
        // index the store: the copy gets them as they are now, so every id stays valid.
        if frozen.len() < world.entities().len() {
            frozen.extend_from_slice(&world.entities()[frozen.len()..]);
        }
        world.with_entities(frozen, f)
    }
}
