//! Traffic actions (OpenSCENARIO 1.3, "Actions", XSD `TrafficAction` choices and
//! `TrafficDefinition`/`TrafficDistribution`). Radii and distances in m, rates in 1/s,
//! speeds in m/s.

use crate::model::{
    Controller, Position, Properties, Range, Role, ScenarioObject, VehicleCategory,
};

/// Traffic actions (XSD `TrafficAction`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum TrafficAction {
    /// TrafficSourceAction: spawn vehicles around a position.
    Source {
        /// Centre.
        position: Position,
        /// Radius, m.
        radius: f64,
        /// Vehicles per s.
        rate: f64,
        /// Start speed, m/s (`speed`, or the deprecated `velocity`).
        speed: Option<f64>,
        /// What to spawn.
        traffic: TrafficMix,
    },
    /// TrafficSinkAction: remove vehicles near a position.
    Sink {
        /// Centre.
        position: Position,
        /// Radius, m.
        radius: f64,
        /// Vehicles per s (absent: all).
        rate: Option<f64>,
        /// What to remove (deprecated TrafficDefinition).
        traffic: TrafficMix,
    },
    /// TrafficSwarmAction: keep traffic around a central object.
    Swarm {
        /// CentralObject entity.
        central_object: String,
        /// Inner radius, m.
        inner_radius: f64,
        /// Semi-major axis, m.
        semi_major_axis: f64,
        /// Semi-minor axis, m.
        semi_minor_axis: f64,
        /// Longitudinal offset, m.
        offset: f64,
        /// Number of vehicles.
        number_of_vehicles: u32,
        /// Start speed, m/s (deprecated `velocity`).
        velocity: Option<f64>,
        /// Start speed range, m/s (1.2+).
        initial_speed_range: Option<Range>,
        /// Share of same and opposite direction (1.2+).
        direction_of_travel: Option<(f64, f64)>,
        /// What to spawn.
        traffic: TrafficMix,
    },
    /// TrafficAreaAction (1.3).
    Area {
        /// Keep the number up.
        continuous: bool,
        /// Number of entities.
        number_of_entities: u32,
        /// Where: a polygon or road ranges.
        area: TrafficArea,
        /// What to spawn.
        distribution: Vec<TrafficDistributionEntry>,
    },
    /// TrafficStopAction (1.2+): stop the named traffic.
    Stop,
}

/// What traffic consists of: the deprecated TrafficDefinition, or a 1.3 TrafficDistribution.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TrafficMix {
    /// TrafficDefinition.
    pub definition: Option<TrafficDefinition>,
    /// TrafficDistribution entries (1.3).
    pub distribution: Vec<TrafficDistributionEntry>,
}

/// XSD `TrafficDefinition`.
#[derive(Debug, Clone, PartialEq)]
pub struct TrafficDefinition {
    /// `name`.
    pub name: String,
    /// (category, weight).
    pub vehicle_categories: Vec<(VehicleCategory, f64)>,
    /// (role, weight) (1.2+).
    pub vehicle_roles: Vec<(Role, f64)>,
    /// (controller, weight).
    pub controllers: Vec<(Controller, f64)>,
}

/// XSD `TrafficDistributionEntry` (1.3).
#[derive(Debug, Clone, PartialEq)]
pub struct TrafficDistributionEntry {
    /// Weight.
    pub weight: f64,
    /// EntityDistribution: (template, weight).
    pub entities: Vec<(ScenarioObject, f64)>,
    /// Properties.
    pub properties: Properties,
}

/// XSD `TrafficArea` (1.3).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum TrafficArea {
    /// Polygon corners.
    Polygon(Vec<Position>),
    /// RoadRange entries.
    RoadRanges(Vec<RoadRange>),
}

/// XSD `RoadRange`.
#[derive(Debug, Clone, PartialEq)]
pub struct RoadRange {
    /// Length, m.
    pub length: Option<f64>,
    /// RoadCursor entries: road id, s (m), lane ids.
    pub cursors: Vec<(String, Option<f64>, Vec<i32>)>,
}
