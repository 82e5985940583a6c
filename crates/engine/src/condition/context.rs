//! What a condition may ask the runtime beyond the entities (OpenSCENARIO 1.3 §7.6.2
//! "ByValueCondition": simulation time, parameters, variables, storyboard element states,
//! time of day, user-defined values, traffic signals; and the collision record that
//! CollisionCondition reads).

use scenario::expr::Value;
use scenario::SourcePos;

use crate::position::EntityQuery;
use crate::storyboard::StateView;

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

    /// The member entities of EntitySelection `name` (OpenSCENARIO 1.3 §7.2.2; expanded, in
    /// declaration order), for TriggeringEntities that name a selection; `None` when `name` is
    /// no selection. The default knows no selections.
    fn entity_selection(&self, name: &str) -> Option<Vec<String>> {
        let _ = name;
        None
    }

    /// The mark `name` a state check noted (oscsim, no XML form: `scenario::StateCheck::mark`),
    /// `None` before it ran. The default knows no marks.
    fn mark(&self, name: &str) -> Option<super::Mark> {
        let _ = name;
        None
    }

    /// Told after each evaluation of the condition written at `pos`: its raw value (false when
    /// it could not be evaluated) and, for a ByEntityCondition, the triggering entities for
    /// which its EntityCondition held, in order. The runtime keeps them for
    /// `Actors/@selectTriggeringEntities` (OpenSCENARIO 1.3 §7.3.1); the default forgets them.
    fn note_triggering(&self, pos: &SourcePos, value: bool, held: &[String]) {
        let _ = (pos, value, held);
    }

    /// True when the bounding boxes of entities `a` and `b` touch or overlap now
    /// (CollisionCondition). The default implementation tests the two boxes'
    /// ground-plane footprints (OpenSCENARIO 2.0 §8.7.5.1.1 time_to_collision() being 0);
    /// a runtime with its own collision record may override it.
    fn collided(&self, a: &str, b: &str) -> bool {
        match (self.entity(a), self.entity(b)) {
            (Some(ea), Some(eb)) if a != b => ea
                .traffic_participant()
                .time_to_collision(&eb.physical_object())
                .is_some_and(|t| t <= 0.0),
            _ => false,
        }
    }
}
