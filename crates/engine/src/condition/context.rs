//! What a condition may ask the runtime beyond the entities (OpenSCENARIO 1.3 §7.6.2
//! "ByValueCondition": simulation time, parameters, variables, storyboard element states,
//! time of day, user-defined values, traffic signals; and the collision record that
//! CollisionCondition reads).

use scenario::expr::Value;
use scenario::SourcePos;

use super::{MarkId, SelectionId};
use crate::position::{EntityQuery, EntityView};
use crate::storyboard::StateView;
use crate::world::EntityId;

/// Everything condition evaluation reads at one moment of a step. Implemented by the runtime;
/// read-only. Entities and the road network come from the [`EntityQuery`] supertrait.
pub trait ConditionContext: EntityQuery {
    /// Simulation time since the start of the scenario, s (SimulationTimeCondition; also the
    /// clock of the duration conditions EndOfRoad, Offroad and StandStill).
    fn simulation_time(&self) -> f64;

    /// The current value of parameter `name` (ParameterCondition), `None` if undeclared.
    /// Parameters can change at runtime through ParameterSetAction (deprecated since 1.2).
    fn parameter(&self, name: &str) -> Option<Value>;

    /// The current value of variable `name` (VariableCondition, 1.2+), `None` if undeclared.
    fn variable(&self, name: &str) -> Option<Value>;

    /// The storyboard's element states at this moment of the step
    /// (StoryboardElementStateCondition).
    fn storyboard(&self) -> StateView<'_>;

    /// The current value of user-defined value `name` (UserDefinedValueCondition), as the
    /// runtime's registry of external values holds it (e.g. a
    /// [`UserValueRegistry`](super::UserValueRegistry)); `None` when nothing has been
    /// registered under that name.
    fn user_defined_value(&self, name: &str) -> Option<Value>;

    /// The current state of traffic signal `name` (TrafficSignalCondition), e.g. `"off;off;on"`
    /// as set by TrafficSignalStateAction or a controller phase; `None` for an unknown signal.
    fn traffic_signal_state(&self, name: &str) -> Option<&str>;

    /// The current phase name of traffic signal controller `name`
    /// (TrafficSignalControllerCondition); `None` for an unknown controller.
    fn traffic_signal_controller_phase(&self, name: &str) -> Option<&str>;

    /// The scenario's current time of day as seconds since 1970-01-01T00:00:00Z (UTC, f64),
    /// i.e. the TimeOfDay set by an EnvironmentAction plus the simulation time elapsed if its
    /// `animation` is true; `None` when no TimeOfDay was ever set.
    fn time_of_day(&self) -> Option<f64>;

    /// The id of the declared entity `name` (placed or not), `None` if the scenario declares
    /// none by that name: how a condition's names are resolved (condition/refs.rs). The
    /// default numbers the entities of [`EntityQuery::entities`] in order; a runtime that
    /// overrides it overrides [`ConditionContext::entity_at`] with it.
    fn entity_id(&self, name: &str) -> Option<EntityId> {
        self.entities()
            .position(|e| e.name == name)
            .map(|i| EntityId(i as u32))
    }

    /// Entity `id` as it stands now, `None` if it is not placed (not added yet, or deleted).
    /// The default reads the `id.index()`-th of [`EntityQuery::entities`].
    fn entity_at(&self, id: EntityId) -> Option<EntityView<'_>> {
        self.entities().nth(id.index())
    }

    /// The handle of EntitySelection `name` (OpenSCENARIO 1.3 §7.2.2), for TriggeringEntities
    /// that name a selection; `None` when `name` is no selection. The default knows no
    /// selections.
    fn selection_id(&self, name: &str) -> Option<SelectionId> {
        let _ = name;
        None
    }

    /// The placed members of selection `id` now (expanded, in id order: §7.2.2.2 takes a
    /// selection's members as they are when it is used).
    fn selection_members(&self, id: SelectionId) -> Vec<EntityId> {
        let _ = id;
        Vec::new()
    }

    /// The slot of mark `name` (oscsim, no XML form: `scenario::StateCheck::mark`), `None`
    /// when no mark by that name can be noted. The default knows no marks.
    fn mark_id(&self, name: &str) -> Option<MarkId> {
        let _ = name;
        None
    }

    /// The mark in slot `id`, `None` before the check that notes it ran. The default knows no
    /// marks.
    fn mark(&self, id: MarkId) -> Option<&super::Mark> {
        let _ = id;
        None
    }

    /// Told after each evaluation of the condition written at `pos`: its raw value (false when
    /// it could not be evaluated) and, for a ByEntityCondition, the triggering entities for
    /// which its EntityCondition held, in order. The runtime keeps them for
    /// `Actors/@selectTriggeringEntities` (OpenSCENARIO 1.3 §7.3.1); the default forgets them.
    fn note_triggering(&self, pos: &SourcePos, value: bool, held: &[EntityId]) {
        let _ = (pos, value, held);
    }

    /// True when the bounding boxes of entities `a` and `b` (two entities: the caller tells
    /// them apart) touch or overlap now (CollisionCondition). The default implementation tests
    /// the two boxes' ground-plane footprints (OpenSCENARIO 2.0 §8.7.5.1.1
    /// time_to_collision() being 0); a runtime with its own collision record may override it.
    fn collided(&self, a: &EntityView<'_>, b: &EntityView<'_>) -> bool {
        a.traffic_participant()
            .time_to_collision(&b.physical_object())
            .is_some_and(|t| t <= 0.0)
    }
}
