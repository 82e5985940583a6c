//! `<roadMark>` (OpenDRIVE 1.8 §11.8 "Road markings", XSD `t_road_lanes_laneSection_lcr_lane_roadMark`):
//! the marking along a lane's outer border (the centre lane's: along the lane-offset line),
//! valid from its `sOffset` to the next record's. Kept as data: the engine does not use it;
//! viewers and OSI lane boundaries do.

use crate::math::Real;

/// `roadMark/@type` (XSD `e_roadMarkType`). Double types name their lines from the inside of
/// the road outwards (§11.8).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum RoadMarkType {
    /// `none`.
    None,
    /// `solid`.
    Solid,
    /// `broken`.
    Broken,
    /// `solid solid`.
    SolidSolid,
    /// `solid broken`.
    SolidBroken,
    /// `broken solid`.
    BrokenSolid,
    /// `broken broken`.
    BrokenBroken,
    /// `botts dots`.
    BottsDots,
    /// `grass`.
    Grass,
    /// `curb`.
    Curb,
    /// `custom`: the lines of the `<type>` child describe it.
    Custom,
    /// `edge`.
    Edge,
    /// Any other value, as written.
    Other(String),
}

impl RoadMarkType {
    /// Reads an `e_roadMarkType` value.
    pub fn parse(text: &str) -> Self {
        match text {
            "none" => Self::None,
            "solid" => Self::Solid,
            "broken" => Self::Broken,
            "solid solid" => Self::SolidSolid,
            "solid broken" => Self::SolidBroken,
            "broken solid" => Self::BrokenSolid,
            "broken broken" => Self::BrokenBroken,
            "botts dots" => Self::BottsDots,
            "grass" => Self::Grass,
            "curb" => Self::Curb,
            "custom" => Self::Custom,
            "edge" => Self::Edge,
            other => Self::Other(other.to_string()),
        }
    }
}

impl RoadMarkType {
    /// The `e_roadMarkType` value.
    pub fn name(&self) -> &str {
        match self {
            Self::None => "none",
            Self::Solid => "solid",
            Self::Broken => "broken",
            Self::SolidSolid => "solid solid",
            Self::SolidBroken => "solid broken",
            Self::BrokenSolid => "broken solid",
            Self::BrokenBroken => "broken broken",
            Self::BottsDots => "botts dots",
            Self::Grass => "grass",
            Self::Curb => "curb",
            Self::Custom => "custom",
            Self::Edge => "edge",
            Self::Other(text) => text,
        }
    }
}

/// `roadMark/@color` (XSD `e_roadMarkColor`).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum RoadMarkColor {
    /// `standard` (white in most countries).
    Standard,
    /// `blue`.
    Blue,
    /// `green`.
    Green,
    /// `red`.
    Red,
    /// `white`.
    White,
    /// `yellow`.
    Yellow,
    /// `orange`.
    Orange,
    /// `violet`.
    Violet,
    /// `black`.
    Black,
    /// Any other value, as written.
    Other(String),
}

impl RoadMarkColor {
    /// Reads an `e_roadMarkColor` value.
    pub fn parse(text: &str) -> Self {
        match text {
            "standard" => Self::Standard,
            "blue" => Self::Blue,
            "green" => Self::Green,
            "red" => Self::Red,
            "white" => Self::White,
            "yellow" => Self::Yellow,
            "orange" => Self::Orange,
            "violet" => Self::Violet,
            "black" => Self::Black,
            other => Self::Other(other.to_string()),
        }
    }
}

/// One `<line>` of a road mark's `<type>` (XSD `t_road_lanes_laneSection_lcr_lane_roadMark_type_line`):
/// a repeated dash pattern.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadMarkLine {
    /// `length` of a dash (m); 0 for a solid line in some files.
    pub length: Real,
    /// `space` between dashes (m); 0 for a solid line.
    pub space: Real,
    /// `tOffset` from the border (m, positive left).
    pub t_offset: Real,
    /// `sOffset` of the first dash from the road mark's start (m).
    pub s_offset: Real,
    /// `width` (m), if given.
    pub width: Option<Real>,
}

/// `<roadMark>` of a lane.
#[derive(Debug, Clone, PartialEq)]
pub struct RoadMark {
    /// `sOffset` from the lane section start (m).
    pub s_offset: Real,
    /// `type`.
    pub mark_type: RoadMarkType,
    /// `weight` is `bold` (else `standard`).
    pub bold: bool,
    /// `color`.
    pub color: RoadMarkColor,
    /// `width` (m), if given.
    pub width: Option<Real>,
    /// The `<line>`s of the `<type>` child, if any (the dash pattern).
    pub lines: Vec<RoadMarkLine>,
}
