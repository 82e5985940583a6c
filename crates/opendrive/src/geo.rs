//! Georeferencing (OpenDRIVE 1.8 §8.5 "Georeferencing"): between the network's local x/y and
//! WGS 84 latitude/longitude, through the header's `<geoReference>` (a PROJ string) and
//! `<offset>`.
//!
//! §8.5: "If an offset exists, always apply the offset on the local ASAM OpenDRIVE coordinates
//! to get the world coordinates before converting the positions using PROJ":
//!
//! ```text
//! x_world = x_odr·cos(hdg) − y_odr·sin(hdg) + x_offset
//! y_world = x_odr·sin(hdg) + y_odr·cos(hdg) + y_offset
//! ```
//!
//! and the world coordinates are those of the projection the PROJ string defines. Latitude and
//! longitude are WGS 84 (`+proj=longlat +datum=WGS84`), in degrees at this interface.
//!
//! The projection is `proj4rs`, a pure-Rust transcription of PROJ's projections (PROJ itself is
//! a C library with data files; a build may not download anything). It reads PROJ strings
//! (`+proj=utm +zone=32 …`); parameters it does not use, such as `+geoidgrids` (a vertical
//! grid), do not change the horizontal result. WKT definitions are refused with a clear error.

use proj4rs::proj::Proj;

use crate::model::{Header, Offset};

/// Why a geo transform cannot be made or applied.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum GeoError {
    /// The header has no `<geoReference>`.
    #[error("expected a <geoReference> in the road network's header, found none")]
    NoGeoReference,
    /// The `<geoReference>` is not a PROJ string this implementation knows.
    #[error("expected a PROJ string (+proj=…) in <geoReference>, found \"{text}\" ({reason})")]
    Unsupported {
        /// The geoReference text.
        text: String,
        /// proj4rs's reason.
        reason: String,
    },
    /// A point could not be transformed (outside the projection's domain, not finite).
    #[error("cannot transform {what} through \"{text}\": {reason}")]
    Transform {
        /// The point, as written in the message.
        what: String,
        /// The geoReference text.
        text: String,
        /// The reason.
        reason: String,
    },
}

/// The map between a network's local x/y and WGS 84 latitude/longitude.
#[derive(Debug)]
pub struct GeoTransform {
    projected: Proj,
    wgs84: Proj,
    offset: Offset,
    text: String,
}

impl GeoTransform {
    /// The transform of a network with `header`.
    pub fn new(header: &Header) -> Result<Self, GeoError> {
        let text = header
            .geo_reference
            .as_ref()
            .ok_or(GeoError::NoGeoReference)?
            .0
            .trim()
            .to_owned();
        let projected = Proj::from_proj_string(&text).map_err(|e| GeoError::Unsupported {
            text: text.clone(),
            reason: e.to_string(),
        })?;
        let wgs84 = Proj::from_proj_string("+proj=longlat +datum=WGS84 +no_defs").map_err(|e| {
            GeoError::Unsupported {
                text: "+proj=longlat +datum=WGS84".into(),
                reason: e.to_string(),
            }
        })?;
        Ok(GeoTransform {
            projected,
            wgs84,
            offset: header.offset.unwrap_or_default(),
            text,
        })
    }

    /// The local x/y (m) of latitude/longitude (degrees, WGS 84).
    pub fn to_local(&self, latitude_deg: f64, longitude_deg: f64) -> Result<(f64, f64), GeoError> {
        let mut p = (longitude_deg.to_radians(), latitude_deg.to_radians(), 0.0);
        self.apply(&self.wgs84, &self.projected, &mut p, || {
            format!("latitude {latitude_deg}°, longitude {longitude_deg}°")
        })?;
        // Undo the offset: rotate (x_world − x_offset, y_world − y_offset) by −hdg.
        let (dx, dy) = (p.0 - self.offset.x, p.1 - self.offset.y);
        let (sin, cos) = self.offset.hdg.sin_cos();
        Ok((dx * cos + dy * sin, -dx * sin + dy * cos))
    }

    /// The latitude/longitude (degrees, WGS 84) of local x/y (m).
    pub fn to_geo(&self, x: f64, y: f64) -> Result<(f64, f64), GeoError> {
        let (sin, cos) = self.offset.hdg.sin_cos();
        let mut p = (
            x * cos - y * sin + self.offset.x,
            x * sin + y * cos + self.offset.y,
            0.0,
        );
        self.apply(&self.projected, &self.wgs84, &mut p, || {
            format!("x {x} m, y {y} m")
        })?;
        Ok((p.1.to_degrees(), p.0.to_degrees()))
    }

    fn apply(
        &self,
        from: &Proj,
        to: &Proj,
        p: &mut (f64, f64, f64),
        what: impl Fn() -> String,
    ) -> Result<(), GeoError> {
        let fail = |reason: String| GeoError::Transform {
            what: what(),
            text: self.text.clone(),
            reason,
        };
        if !(p.0.is_finite() && p.1.is_finite()) {
            return Err(fail("not a finite point".into()));
        }
        proj4rs::transform::transform(from, to, p).map_err(|e| fail(e.to_string()))?;
        if !(p.0.is_finite() && p.1.is_finite()) {
            return Err(fail("outside the projection's domain".into()));
        }
        Ok(())
    }
}
