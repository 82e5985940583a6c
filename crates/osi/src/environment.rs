//! The scenario's environment (OpenSCENARIO 1.3 §7.7.1 EnvironmentAction, XSD `Environment`,
//! `TimeOfDay`, `Weather`, `Sun`, `Fog`, `Precipitation`, `Wind`) → ASAM OSI 3.8
//! `GroundTruth.environmental_conditions` (osi_environment.proto, `osi3.EnvironmentalConditions`).
//!
//! Nothing is written until an EnvironmentAction (Init or story) has set a part; from then on
//! every frame carries the environment in force:
//! - TimeOfDay → `unix_timestamp` (the `dateTime` in UTC, whole seconds, floor) and
//!   `time_of_day.seconds_since_midnight` (the wall clock of the `dateTime`'s own zone; no
//!   zone = UTC), both running on with the simulation when `animation` is true.
//! - `atmosphericPressure` (Pa) → `atmospheric_pressure`, `temperature` (K) → `temperature`:
//!   same units, copied.
//! - Sun: OpenSCENARIO counts the azimuth clockwise from north (π/2 east), OSI counterclockwise
//!   from north (π/2 west): OSI azimuth = (2π − azimuth) mod 2π. `elevation` is the same angle
//!   in both. `illuminance` (lx) → `sun.intensity` (lx) and, as the ambient light of a scene
//!   lit by the sun, `ambient_illumination` by the band table below.
//! - Wind: OpenSCENARIO gives the direction the wind blows *to* as a heading in the world
//!   frame (0 = +x, counterclockwise); OSI the direction it comes *from*, counterclockwise from
//!   north, north being the projected frame's +y (OSI: the y axis when `proj_string` defines
//!   none). The origin heading is direction + π, and in the projected frame heading + yaw of
//!   the OpenDRIVE header `<offset>` (`proj_frame_offset`); from north: − π/2. So
//!   origin_direction = (direction + yaw + π/2) mod 2π. `speed` (m/s) is copied.
//! - `fractionalCloudCover` zeroOktas…eightOktas → `clouds.fractional_cloud_cover` ZERO…EIGHT
//!   oktas, nineOktas → SKY_OBSCURED. The deprecated `cloudState` (only when no
//!   fractionalCloudCover is given): free → ZERO_OKTAS, overcast → EIGHT_OKTAS, cloudy, rainy,
//!   skyOff → OTHER (known, but no okta count).
//! - Fog `visualRange` V (m) and Precipitation `precipitationIntensity` I (mm/h) by the bands
//!   below. `precipitationType` dry → NONE whatever the intensity; rain or snow without
//!   `precipitationIntensity` → the deprecated 0..1 `intensity`: 0 → NONE, otherwise OTHER
//!   (it has no unit to band); neither → OTHER.
//!
//! Band tables, from the comments of osi_environment.proto (ASAM OSI 3.8.0), intervals
//! [lower, upper[:
//!
//! | Precipitation I (mm/h) | | Fog V (m) | | AmbientIllumination E (lx) | |
//! |---|---|---|---|---|---|
//! | [0, 0.1[ | NONE | [40000, ∞[ | EXCELLENT_VISIBILITY | < 0.01 | LEVEL1 |
//! | [0.1, 0.5[ | VERY_LIGHT | [10000, 40000[ | GOOD_VISIBILITY | [0.01, 1[ | LEVEL2 |
//! | [0.5, 1.9[ | LIGHT | [4000, 10000[ | MODERATE_VISIBILITY | [1, 3[ | LEVEL3 |
//! | [1.9, 8.1[ | MODERATE | [2000, 4000[ | POOR_VISIBILITY | [3, 10[ | LEVEL4 |
//! | [8.1, 34[ | HEAVY | [1000, 2000[ | MIST | [10, 20[ | LEVEL5 |
//! | [34, 149[ | VERY_HEAVY | [200, 1000[ | LIGHT | [20, 400[ | LEVEL6 |
//! | [149, ∞[ | EXTREME | [50, 200[ | THICK | [400, 1000[ | LEVEL7 |
//! | | | [0, 50[ | DENSE | [1000, 10000[ | LEVEL8 |
//! | | | | | ≥ 10000 | LEVEL9 |
//!
//! Not written: `relative_humidity` (OpenSCENARIO has none), `source_reference` (OSI: "for
//! OpenDRIVE and OpenSCENARIO there is no direct counterpart"). RoadCondition
//! (`frictionScaleFactor`, `wetness`) has no field in `EnvironmentalConditions`; it stays in
//! the engine's state (docs/osi.md "Environment").

use std::f64::consts::{FRAC_PI_2, TAU};

use engine::EnvironmentState;
use scenario::{CloudState, FractionalCloudCover, PrecipitationType, Weather};

use crate::osi3::environmental_conditions::cloud_layer::FractionalCloudCover as Okta;
use crate::osi3::environmental_conditions::{
    AmbientIllumination, CloudLayer, Fog, Precipitation, Sun, TimeOfDay, Wind,
};
use crate::osi3::EnvironmentalConditions;

/// The conditions of `environment` at simulation time `time` (s); `north_yaw` is the yaw of the
/// OpenDRIVE header `<offset>` (rad, 0 without one). `None` while no EnvironmentAction has set
/// anything.
pub fn environmental_conditions(
    environment: &EnvironmentState,
    time: f64,
    north_yaw: f64,
) -> Option<EnvironmentalConditions> {
    if environment.is_empty() {
        return None;
    }
    let mut c = EnvironmentalConditions::default();
    if let Some(clock) = environment.clock_at(time) {
        // Finite: the parsed dateTime is a few 10¹⁰ s at most, plus the simulation time.
        c.unix_timestamp = Some(clock.unix_time.floor() as i64);
        c.time_of_day = Some(TimeOfDay {
            // In [0, 86400): fits u32; floor keeps it below 86400.
            seconds_since_midnight: Some(clock.seconds_since_midnight().floor() as u32),
        });
    }
    if let Some(w) = environment.weather() {
        weather(&mut c, w, north_yaw);
    }
    Some(c)
}

/// Fills the weather fields of `c` from `w`.
fn weather(c: &mut EnvironmentalConditions, w: &Weather, north_yaw: f64) {
    c.atmospheric_pressure = w.atmospheric_pressure;
    c.temperature = w.temperature;
    if let Some(sun) = w.sun {
        c.sun = Some(Sun {
            azimuth: Some((TAU - sun.azimuth).rem_euclid(TAU)),
            elevation: Some(sun.elevation),
            intensity: sun.illuminance,
        });
        c.ambient_illumination = sun.illuminance.map(|e| ambient_illumination(e) as i32);
    }
    if let Some(wind) = w.wind {
        c.wind = Some(Wind {
            origin_direction: Some((wind.direction + north_yaw + FRAC_PI_2).rem_euclid(TAU)),
            speed: Some(wind.speed),
        });
    }
    let cover = match (w.fractional_cloud_cover, w.cloud_state) {
        (Some(f), _) => Some(oktas(f)),
        (None, Some(s)) => Some(cloud_state(s)),
        (None, None) => None,
    };
    c.clouds = cover.map(|o| CloudLayer {
        fractional_cloud_cover: Some(o as i32),
    });
    c.fog = w.fog.map(|f| fog(f.visual_range) as i32);
    c.precipitation = w.precipitation.map(|p| {
        let band = match (p.precipitation_type, p.precipitation_intensity, p.intensity) {
            (PrecipitationType::Dry, _, _) => Precipitation::None,
            (_, Some(mm_per_hour), _) => precipitation(mm_per_hour),
            (_, None, Some(0.0)) => Precipitation::None,
            _ => Precipitation::Other,
        };
        band as i32
    });
}

/// The OSI band of a precipitation intensity `i` (mm/h); see the module doc's table.
pub fn precipitation(i: f64) -> Precipitation {
    const BANDS: [(f64, Precipitation); 6] = [
        (0.1, Precipitation::None),
        (0.5, Precipitation::VeryLight),
        (1.9, Precipitation::Light),
        (8.1, Precipitation::Moderate),
        (34.0, Precipitation::Heavy),
        (149.0, Precipitation::VeryHeavy),
    ];
    band(i, &BANDS, Precipitation::Extreme)
}

/// The OSI band of a visual range `v` (m); see the module doc's table.
pub fn fog(v: f64) -> Fog {
    const BANDS: [(f64, Fog); 7] = [
        (50.0, Fog::Dense),
        (200.0, Fog::Thick),
        (1000.0, Fog::Light),
        (2000.0, Fog::Mist),
        (4000.0, Fog::PoorVisibility),
        (10000.0, Fog::ModerateVisibility),
        (40000.0, Fog::GoodVisibility),
    ];
    band(v, &BANDS, Fog::ExcellentVisibility)
}

/// The OSI band of an illuminance `e` (lx); see the module doc's table.
pub fn ambient_illumination(e: f64) -> AmbientIllumination {
    const BANDS: [(f64, AmbientIllumination); 8] = [
        (0.01, AmbientIllumination::Level1),
        (1.0, AmbientIllumination::Level2),
        (3.0, AmbientIllumination::Level3),
        (10.0, AmbientIllumination::Level4),
        (20.0, AmbientIllumination::Level5),
        (400.0, AmbientIllumination::Level6),
        (1000.0, AmbientIllumination::Level7),
        (10000.0, AmbientIllumination::Level8),
    ];
    band(e, &BANDS, AmbientIllumination::Level9)
}

/// The band of `x` in `bands` (upper limits, ascending, each band [previous, upper[), or
/// `above` from the last limit on.
fn band<T: Copy>(x: f64, bands: &[(f64, T)], above: T) -> T {
    bands
        .iter()
        .find(|(upper, _)| x < *upper)
        .map_or(above, |(_, band)| *band)
}

/// OpenSCENARIO `FractionalCloudCover` → OSI okta value.
fn oktas(f: FractionalCloudCover) -> Okta {
    match f {
        FractionalCloudCover::ZeroOktas => Okta::ZeroOktas,
        FractionalCloudCover::OneOktas => Okta::OneOktas,
        FractionalCloudCover::TwoOktas => Okta::TwoOktas,
        FractionalCloudCover::ThreeOktas => Okta::ThreeOktas,
        FractionalCloudCover::FourOktas => Okta::FourOktas,
        FractionalCloudCover::FiveOktas => Okta::FiveOktas,
        FractionalCloudCover::SixOktas => Okta::SixOktas,
        FractionalCloudCover::SevenOktas => Okta::SevenOktas,
        FractionalCloudCover::EightOktas => Okta::EightOktas,
        FractionalCloudCover::NineOktas => Okta::SkyObscured,
        // A later XSD's value: known, but not one of these.
        _ => Okta::Other,
    }
}

/// The deprecated OpenSCENARIO `CloudState` → OSI okta value (module doc).
fn cloud_state(s: CloudState) -> Okta {
    match s {
        CloudState::Free => Okta::ZeroOktas,
        CloudState::Overcast => Okta::EightOktas,
        _ => Okta::Other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn band_limits_are_the_lower_closed_bounds_of_the_osi_tables() {
        // Each band is [lower, upper[ (osi_environment.proto).
        assert_eq!(precipitation(0.0), Precipitation::None);
        assert_eq!(precipitation(0.0999), Precipitation::None);
        assert_eq!(precipitation(0.1), Precipitation::VeryLight);
        assert_eq!(precipitation(1.9), Precipitation::Moderate);
        assert_eq!(precipitation(33.99), Precipitation::Heavy);
        assert_eq!(precipitation(149.0), Precipitation::Extreme);
        assert_eq!(fog(0.0), Fog::Dense);
        assert_eq!(fog(50.0), Fog::Thick);
        assert_eq!(fog(199.9), Fog::Thick);
        assert_eq!(fog(1000.0), Fog::Mist);
        assert_eq!(fog(39999.0), Fog::GoodVisibility);
        assert_eq!(fog(40000.0), Fog::ExcellentVisibility);
        assert_eq!(ambient_illumination(0.0), AmbientIllumination::Level1);
        assert_eq!(ambient_illumination(0.01), AmbientIllumination::Level2);
        assert_eq!(ambient_illumination(399.0), AmbientIllumination::Level6);
        assert_eq!(ambient_illumination(10000.0), AmbientIllumination::Level9);
        assert_eq!(ambient_illumination(150000.0), AmbientIllumination::Level9);
    }
}
