//! EnvironmentAction (OpenSCENARIO 1.3 §7.7.1 global actions, XSD `EnvironmentAction`,
//! `Environment`): time of day, weather and road condition, kept in the world's state.
//! Instantaneous. Each part the action gives (TimeOfDay, Weather, RoadCondition) replaces
//! the one in force; parts it leaves out stay as they were (all three are optional since 1.2).
//! The time of day runs on with the simulation when its `animation` is true: it is the set
//! dateTime plus the simulation time elapsed since the action.

use scenario::{Environment, RoadCondition, TimeOfDay, Weather};

use crate::runtime::world::World;

/// The environment in force and when its time of day was set.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct EnvironmentState {
    time_of_day: Option<(TimeOfDay, f64)>,
    weather: Option<Weather>,
    road_condition: Option<RoadCondition>,
}

impl EnvironmentState {
    /// The TimeOfDay in force and the simulation time (s) it was set at.
    pub fn time_of_day_setting(&self) -> Option<(&TimeOfDay, f64)> {
        self.time_of_day.as_ref().map(|(t, at)| (t, *at))
    }

    /// The Weather in force.
    pub fn weather(&self) -> Option<&Weather> {
        self.weather.as_ref()
    }

    /// The RoadCondition in force.
    pub fn road_condition(&self) -> Option<&RoadCondition> {
        self.road_condition.as_ref()
    }
}

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
