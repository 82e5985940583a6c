//! EnvironmentAction (OpenSCENARIO 1.3 §7.7.1 global actions, XSD `EnvironmentAction`,
//! `Environment`): time of day, weather and road condition, kept in the world's state.
//! Instantaneous. Each part the action gives (TimeOfDay, Weather, RoadCondition) replaces
//! the one in force; parts it leaves out stay as they were (all three are optional since 1.2).
//! The time of day runs on with the simulation when its `animation` is true: it is the set
//! dateTime plus the simulation time elapsed since the action
//! ([`EnvironmentState::clock_at`](crate::EnvironmentState::clock_at)); the state is
//! `world/environment.rs`.

use scenario::Environment;

use crate::store::World;

/// Applies `environment` at simulation time `time`.
pub(crate) fn start(world: &mut World, environment: &Environment, time: f64) {
    let state = &mut world.environment;
    if let Some(t) = &environment.time_of_day {
        state.time_of_day = Some((t.clone(), time));
    }
    if let Some(w) = &environment.weather {
        state.weather = Some(w.clone());
    }
    if let Some(r) = &environment.road_condition {
        state.road_condition = Some(r.clone());
    }
}
