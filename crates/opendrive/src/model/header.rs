//! `<header>` with `<geoReference>` and `<offset>` (OpenDRIVE 1.8 header element, §8
//! georeferencing). oscsim works in the file's inertial frame; `geo.rs` maps it to WGS 84.

/// `<header>`: file metadata.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Header {
    /// `revMajor`.
    pub rev_major: u32,
    /// `revMinor`.
    pub rev_minor: u32,
    /// `name`.
    pub name: String,
    /// `version`.
    pub version: String,
    /// `date`.
    pub date: String,
    /// `vendor`.
    pub vendor: String,
    /// `north`, `south`, `east`, `west` (m), as written; 0 when absent.
    pub north: f64,
    /// See `north`.
    pub south: f64,
    /// See `north`.
    pub east: f64,
    /// See `north`.
    pub west: f64,
    /// `<geoReference>`: the projection string (PROJ or WKT), if any.
    pub geo_reference: Option<GeoReference>,
    /// `<offset>`: shift applied to the inertial frame, if any.
    pub offset: Option<Offset>,
}

/// `<geoReference>` text (a PROJ string or WKT).
#[derive(Debug, Clone, PartialEq)]
pub struct GeoReference(pub String);

/// `<offset>`: a translation and rotation of the inertial frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Offset {
    /// x (m).
    pub x: f64,
    /// y (m).
    pub y: f64,
    /// z (m).
    pub z: f64,
    /// Heading (rad).
    pub hdg: f64,
}
