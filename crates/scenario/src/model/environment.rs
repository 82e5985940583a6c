//! Environment (OpenSCENARIO 1.3 "Environment", XSD `Environment`, `TimeOfDay`,
//! `Weather`, `Sun`, `Fog`, `Precipitation`, `Wind`, `DomeImage`, `RoadCondition`).

use crate::model::{
    BoundingBox, CatalogOrigin, CloudState, FractionalCloudCover, PrecipitationType, Properties,
    Wetness,
};

/// An environment (XSD `Environment`).
#[derive(Debug, Clone, PartialEq)]
pub struct Environment {
    /// `name`.
    pub name: String,
    /// TimeOfDay.
    pub time_of_day: Option<TimeOfDay>,
    /// Weather.
    pub weather: Option<Weather>,
    /// RoadCondition.
    pub road_condition: Option<RoadCondition>,
    /// Set when it came from a catalog.
    pub catalog: Option<CatalogOrigin>,
}

/// Time of day (XSD `TimeOfDay`).
#[derive(Debug, Clone, PartialEq)]
pub struct TimeOfDay {
    /// Time runs during the simulation.
    pub animation: bool,
    /// dateTime as written.
    pub date_time: String,
}

/// Weather (XSD `Weather`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Weather {
    /// cloudState (deprecated since 1.2).
    pub cloud_state: Option<CloudState>,
    /// fractionalCloudCover (1.2+).
    pub fractional_cloud_cover: Option<FractionalCloudCover>,
    /// Atmospheric pressure, Pa (1.1+).
    pub atmospheric_pressure: Option<f64>,
    /// Temperature, K (1.1+).
    pub temperature: Option<f64>,
    /// Sun.
    pub sun: Option<Sun>,
    /// Fog.
    pub fog: Option<Fog>,
    /// Precipitation.
    pub precipitation: Option<Precipitation>,
    /// Wind (1.1+).
    pub wind: Option<Wind>,
    /// DomeImage (1.2+): file path and azimuth offset, rad.
    pub dome_image: Option<(String, Option<f64>)>,
}

/// Sun (XSD `Sun`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sun {
    /// Azimuth, rad.
    pub azimuth: f64,
    /// Elevation, rad.
    pub elevation: f64,
    /// Illuminance, lx (`illuminance`, or the deprecated `intensity`).
    pub illuminance: Option<f64>,
}

/// Fog (XSD `Fog`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fog {
    /// Visual range, m.
    pub visual_range: f64,
    /// Extent of the fog.
    pub bounding_box: Option<BoundingBox>,
}

/// Precipitation (XSD `Precipitation`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Precipitation {
    /// Type.
    pub precipitation_type: PrecipitationType,
    /// Intensity, mm/h (`precipitationIntensity`; the deprecated 0..1 `intensity` is kept
    /// separately).
    pub precipitation_intensity: Option<f64>,
    /// The deprecated 1.0 `intensity`, 0..1.
    pub intensity: Option<f64>,
}

/// Wind (XSD `Wind`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wind {
    /// Direction the wind comes from, rad.
    pub direction: f64,
    /// Speed, m/s.
    pub speed: f64,
}

/// Road condition (XSD `RoadCondition`).
#[derive(Debug, Clone, PartialEq)]
pub struct RoadCondition {
    /// Friction scale factor.
    pub friction_scale_factor: f64,
    /// Wetness (1.2+).
    pub wetness: Option<Wetness>,
    /// Properties.
    pub properties: Properties,
}
