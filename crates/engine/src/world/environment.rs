//! The environment in force (OpenSCENARIO 1.3 §7.7.1 EnvironmentAction, XSD `Environment`):
//! time of day, weather and road condition, and the scenario's clock. The time of day runs on
//! with the simulation when its `animation` is true: it is the set dateTime plus the simulation
//! time elapsed since the action ([`EnvironmentState::clock_at`]). `actions/environment.rs`
//! changes it.

use scenario::{RoadCondition, TimeOfDay, Weather};

use super::date_time::parse_zoned_date_time;

/// The environment in force and when its time of day was set.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct EnvironmentState {
    pub(crate) time_of_day: Option<(TimeOfDay, f64)>,
    pub(crate) weather: Option<Weather>,
    pub(crate) road_condition: Option<RoadCondition>,
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

    /// Whether no EnvironmentAction has set anything yet.
    pub fn is_empty(&self) -> bool {
        self.time_of_day.is_none() && self.weather.is_none() && self.road_condition.is_none()
    }

    /// The date and time at simulation time `time`: the TimeOfDay's `dateTime`, plus the
    /// simulation time since it was set when its `animation` is true. `None` without a
    /// TimeOfDay or when its `dateTime` is not an xsd:dateTime.
    pub fn clock_at(&self, time: f64) -> Option<Clock> {
        let (time_of_day, set_at) = self.time_of_day_setting()?;
        let (start, utc_offset) = parse_zoned_date_time(&time_of_day.date_time)?;
        let elapsed = if time_of_day.animation {
            time - set_at
        } else {
            0.0
        };
        Some(Clock {
            unix_time: start + elapsed,
            utc_offset,
        })
    }
}

/// A date and time of the scenario's clock (TimeOfDay `dateTime`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Clock {
    /// Seconds since 1970-01-01T00:00:00Z, leap seconds not counted.
    pub unix_time: f64,
    /// Offset of the `dateTime`'s zone from UTC (s); 0 for `Z` or no zone (taken as UTC).
    pub utc_offset: i64,
}

impl Clock {
    /// Seconds since midnight of the `dateTime`'s zone (the local wall clock), in [0, 86400).
    pub fn seconds_since_midnight(&self) -> f64 {
        (self.unix_time + self.utc_offset as f64).rem_euclid(86_400.0)
    }
}
