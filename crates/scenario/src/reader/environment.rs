//! Readers for the environment (OpenSCENARIO 1.3, "Environment", XSD `Environment`, `TimeOfDay`,
//! `Weather`, `Sun`, `Fog`, `Precipitation`, `Wind`, `DomeImage`, `RoadCondition`).
//! Deprecated attributes (Sun@intensity, Weather@cloudState) are kept or mapped with a warning.

use crate::error::Result;
use crate::model::{Environment, Fog, Precipitation, RoadCondition, Sun, TimeOfDay, Weather, Wind};
use crate::reader::catalog::read_catalog_reference;
use crate::reader::context::{Ctx, Node};
use crate::reader::entities::{read_bounding_box, read_properties};
use crate::reader::routing::expect_entry;

/// Reads XSD `Environment`.
pub(crate) fn read_environment<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Environment> {
    ctx.scoped(n, |ctx| {
        let time_of_day = match ctx.opt_child(n, "TimeOfDay") {
            Some(t) => Some(TimeOfDay {
                animation: ctx.req(t, "animation")?,
                date_time: ctx.req(t, "dateTime")?,
            }),
            None => None,
        };
        let weather = match ctx.opt_child(n, "Weather") {
            Some(w) => Some(read_weather(ctx, w)?),
            None => None,
        };
        let road_condition = match ctx.opt_child(n, "RoadCondition") {
            Some(r) => Some(RoadCondition {
                friction_scale_factor: ctx.req(r, "frictionScaleFactor")?,
                wetness: ctx.opt(r, "wetness")?,
                properties: read_properties(ctx, r)?,
            }),
            None => None,
        };
        Ok(Environment {
            name: ctx.req(n, "name")?,
            time_of_day,
            weather,
            road_condition,
            catalog: None,
        })
    })
}

/// Reads `c`, an `Environment` or a `CatalogReference` to one, child of `parent`.
pub(crate) fn read_environment_or_reference<'a>(
    ctx: &mut Ctx<'a>,
    parent: Node<'a>,
    c: Node<'a>,
) -> Result<Environment> {
    match c.tag_name().name() {
        "Environment" => read_environment(ctx, c),
        "CatalogReference" => {
            let (mut env, origin) = read_catalog_reference(ctx, c, |ctx, e| {
                expect_entry(ctx, e, "Environment", read_environment)
            })?;
            env.catalog = Some(origin);
            Ok(env)
        }
        _ => Err(ctx.unexpected(parent, c, "Environment, CatalogReference")),
    }
}

/// Reads XSD `Weather`.
fn read_weather<'a>(ctx: &mut Ctx<'a>, w: Node<'a>) -> Result<Weather> {
    let mut weather = Weather {
        cloud_state: ctx.opt(w, "cloudState")?,
        fractional_cloud_cover: ctx.opt(w, "fractionalCloudCover")?,
        atmospheric_pressure: ctx.opt(w, "atmosphericPressure")?,
        temperature: ctx.opt(w, "temperature")?,
        ..Weather::default()
    };
    if weather.cloud_state.is_some() && ctx.rev_minor() >= 2 {
        ctx.warn(
            w,
            "Weather@cloudState is deprecated since 1.2; use fractionalCloudCover".into(),
        );
    }
    if let Some(s) = ctx.opt_child(w, "Sun") {
        let old: Option<f64> = ctx.opt(s, "intensity")?;
        if old.is_some() {
            ctx.warn(s, "Sun@intensity is deprecated, read as illuminance".into());
        }
        weather.sun = Some(Sun {
            azimuth: ctx.req(s, "azimuth")?,
            elevation: ctx.req(s, "elevation")?,
            illuminance: ctx.opt(s, "illuminance")?.or(old),
        });
    }
    if let Some(f) = ctx.opt_child(w, "Fog") {
        let bounding_box = match ctx.opt_child(f, "BoundingBox") {
            Some(_) => Some(read_bounding_box(ctx, f)?),
            None => None,
        };
        weather.fog = Some(Fog {
            visual_range: ctx.req(f, "visualRange")?,
            bounding_box,
        });
    }
    if let Some(p) = ctx.opt_child(w, "Precipitation") {
        weather.precipitation = Some(Precipitation {
            precipitation_type: ctx.req(p, "precipitationType")?,
            precipitation_intensity: ctx.opt(p, "precipitationIntensity")?,
            intensity: ctx.opt(p, "intensity")?,
        });
    }
    if let Some(x) = ctx.opt_child(w, "Wind") {
        weather.wind = Some(Wind {
            direction: ctx.req(x, "direction")?,
            speed: ctx.req(x, "speed")?,
        });
    }
    if let Some(d) = ctx.opt_child(w, "DomeImage") {
        let file = ctx.child(d, "DomeFile")?;
        weather.dome_image = Some((ctx.req(file, "filepath")?, ctx.opt(d, "azimuthOffset")?));
    }
    Ok(weather)
}
