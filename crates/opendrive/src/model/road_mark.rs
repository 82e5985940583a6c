//! `<roadMark>` (OpenDRIVE 1.8 §11.8 "Road markings", XSD `t_road_lanes_laneSection_lcr_lane_roadMark`):
//! the marking along a lane's outer border (the centre lane's: along the lane-offset line),
//! valid from its `sOffset` to the next record's. Viewers and OSI lane boundaries draw it; the
//! engine's lane-changing driver model asks [`RoadMark::permits_lane_change`] whether it may
//! cross it.

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
    /// `laneChange`, if given.
    pub lane_change: Option<RoadMarkLaneChange>,
}

/// `roadMark/@laneChange` (XSD `e_road_lanes_laneSection_lcr_lane_roadMark_laneChange`): the
/// directions in which a lane change across the mark is allowed, "taking into account that
/// lanes are numbered in ascending order from right to left" (§11.8).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RoadMarkLaneChange {
    /// `increase`: towards the lane with the larger id only.
    Increase,
    /// `decrease`: towards the lane with the smaller id only.
    Decrease,
    /// `both`.
    Both,
    /// `none`.
    None,
}

impl RoadMarkLaneChange {
    /// Reads a `laneChange` value; `None` for a value the schema does not have.
    pub fn parse(text: &str) -> Option<Self> {
        Some(match text {
            "increase" => Self::Increase,
            "decrease" => Self::Decrease,
            "both" => Self::Both,
            "none" => Self::None,
            _ => return None,
        })
    }
}

impl RoadMark {
    /// Whether a vehicle may cross this mark, the record of lane `border_of` (0: the centre
    /// lane), moving towards larger lane ids (`increasing`) or smaller ones.
    ///
    /// `laneChange`, when given, decides (§11.8). Without it the standard's default is
    /// `both`; oscsim reads the paint instead, as a driver does, so that a solid line keeps
    /// traffic in lane on roads that do not write `laneChange` (most do not): `solid`,
    /// `solid solid`, `curb`, `grass` and `edge` may not be crossed; `solid broken` and
    /// `broken solid` may be crossed from the side of their broken line (double types name
    /// their lines from the inside of the road outwards, so the first line faces the lane
    /// `border_of`; on the centre line, where there is no inside, neither way); every other
    /// type, `none` and `custom` included, may be crossed.
    pub fn permits_lane_change(&self, border_of: i32, increasing: bool) -> bool {
        match self.lane_change {
            Some(RoadMarkLaneChange::Both) => return true,
            Some(RoadMarkLaneChange::None) => return false,
            Some(RoadMarkLaneChange::Increase) => return increasing,
            Some(RoadMarkLaneChange::Decrease) => return !increasing,
            None => {}
        }
        // Leaving lane `border_of` outwards: away from the centre.
        let outwards = (border_of > 0) == increasing;
        match self.mark_type {
            RoadMarkType::Solid
            | RoadMarkType::SolidSolid
            | RoadMarkType::Curb
            | RoadMarkType::Grass
            | RoadMarkType::Edge => false,
            // Inner line solid: only from the outside inwards.
            RoadMarkType::SolidBroken => border_of != 0 && !outwards,
            // Inner line broken: only from the inside outwards.
            RoadMarkType::BrokenSolid => border_of != 0 && outwards,
            _ => true,
        }
    }
}
