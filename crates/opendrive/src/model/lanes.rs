//! `<laneSection>` and `<lane>` (OpenDRIVE 1.8 §11, lanes): lane types, width and border
//! polynomials, height, and lane links.

use super::RoadMark;
use crate::math::{Cubic, Real};

/// `lane/@type` (OpenDRIVE 1.8 §11, XSD `e_laneType`).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum LaneType {
    /// `driving`.
    Driving,
    /// `shoulder`.
    Shoulder,
    /// `border`.
    Border,
    /// `stop`.
    Stop,
    /// `none`.
    None,
    /// `restricted`.
    Restricted,
    /// `parking`.
    Parking,
    /// `median`.
    Median,
    /// `biking`.
    Biking,
    /// `sidewalk`.
    Sidewalk,
    /// `curb`.
    Curb,
    /// `entry` (and `mwyEntry`).
    Entry,
    /// `exit` (and `mwyExit`).
    Exit,
    /// `onRamp`.
    OnRamp,
    /// `offRamp`.
    OffRamp,
    /// `connectingRamp`.
    ConnectingRamp,
    /// `bidirectional`.
    Bidirectional,
    /// `slipLane`.
    SlipLane,
    /// `bus`.
    Bus,
    /// `taxi`.
    Taxi,
    /// `HOV`.
    Hov,
    /// `tram`.
    Tram,
    /// `rail`.
    Rail,
    /// `walking`.
    Walking,
    /// `roadWorks`.
    RoadWorks,
    /// Any other value (`special1` …), as written.
    Other(String),
}

impl LaneType {
    /// Reads an `e_laneType` value.
    pub fn parse(text: &str) -> Self {
        match text {
            "driving" => Self::Driving,
            "shoulder" => Self::Shoulder,
            "border" => Self::Border,
            "stop" => Self::Stop,
            "none" => Self::None,
            "restricted" => Self::Restricted,
            "parking" => Self::Parking,
            "median" => Self::Median,
            "biking" => Self::Biking,
            "sidewalk" => Self::Sidewalk,
            "curb" => Self::Curb,
            "entry" | "mwyEntry" => Self::Entry,
            "exit" | "mwyExit" => Self::Exit,
            "onRamp" => Self::OnRamp,
            "offRamp" => Self::OffRamp,
            "connectingRamp" => Self::ConnectingRamp,
            "bidirectional" => Self::Bidirectional,
            "slipLane" => Self::SlipLane,
            "bus" => Self::Bus,
            "taxi" => Self::Taxi,
            "HOV" => Self::Hov,
            "tram" => Self::Tram,
            "rail" => Self::Rail,
            "walking" => Self::Walking,
            "roadWorks" => Self::RoadWorks,
            other => Self::Other(other.to_string()),
        }
    }

    /// The `e_laneType` value (`mwyEntry` and `mwyExit` read as `entry` and `exit`).
    pub fn name(&self) -> &str {
        match self {
            Self::Driving => "driving",
            Self::Shoulder => "shoulder",
            Self::Border => "border",
            Self::Stop => "stop",
            Self::None => "none",
            Self::Restricted => "restricted",
            Self::Parking => "parking",
            Self::Median => "median",
            Self::Biking => "biking",
            Self::Sidewalk => "sidewalk",
            Self::Curb => "curb",
            Self::Entry => "entry",
            Self::Exit => "exit",
            Self::OnRamp => "onRamp",
            Self::OffRamp => "offRamp",
            Self::ConnectingRamp => "connectingRamp",
            Self::Bidirectional => "bidirectional",
            Self::SlipLane => "slipLane",
            Self::Bus => "bus",
            Self::Taxi => "taxi",
            Self::Hov => "HOV",
            Self::Tram => "tram",
            Self::Rail => "rail",
            Self::Walking => "walking",
            Self::RoadWorks => "roadWorks",
            Self::Other(text) => text,
        }
    }

    /// Whether motor vehicles may drive on lanes of this type: driving, entry, exit, onRamp,
    /// offRamp, connectingRamp, bidirectional, slipLane, bus, taxi and HOV (the lane types
    /// the OpenDRIVE 1.8 §11 lane-type table describes as lanes for vehicle traffic). Parking, stop,
    /// shoulder, border and the others are not drivable for routing.
    pub fn is_drivable(&self) -> bool {
        matches!(
            self,
            Self::Driving
                | Self::Entry
                | Self::Exit
                | Self::OnRamp
                | Self::OffRamp
                | Self::ConnectingRamp
                | Self::Bidirectional
                | Self::SlipLane
                | Self::Bus
                | Self::Taxi
                | Self::Hov
        )
    }
}

/// Free function form of [`LaneType::is_drivable`].
pub fn is_drivable(lane_type: &LaneType) -> bool {
    lane_type.is_drivable()
}

/// `<height sOffset inner outer>`: the lane's surface raised above the road (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaneHeight {
    /// `sOffset` from the lane section start (m).
    pub s_offset: Real,
    /// Height at the inner border (m).
    pub inner: Real,
    /// Height at the outer border (m).
    pub outer: Real,
}

/// `<lane>`.
#[derive(Debug, Clone, PartialEq)]
pub struct Lane {
    /// `id`: 0 centre, positive left, negative right.
    pub id: i32,
    /// `type`.
    pub lane_type: LaneType,
    /// `level`: keep the lane flat (excluded from superelevation). Kept as data.
    pub level: bool,
    /// `link/predecessor/@id`: the lane at the section's start side.
    pub predecessor: Option<i32>,
    /// `link/successor/@id`: the lane at the section's end side.
    pub successor: Option<i32>,
    /// `<width>` records; `start` is `sOffset` from the lane section start.
    pub widths: Vec<Cubic>,
    /// `<border>` records (used when there are no widths); `start` is `sOffset`.
    pub borders: Vec<Cubic>,
    /// `<height>` records, sorted by `s_offset`.
    pub heights: Vec<LaneHeight>,
    /// `<speed max>` of the first speed record (m/s), if any.
    pub speed_limit: Option<Real>,
    /// `<roadMark>` records along the lane's outer border, sorted by `s_offset`.
    pub road_marks: Vec<RoadMark>,
}

/// `<laneSection>`: lanes valid from `s` to the next section's `s`.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneSection {
    /// `s` (m) where the section starts.
    pub s: Real,
    /// `singleSide`.
    pub single_side: bool,
    /// Left lanes in order 1, 2, 3, … (from the centre outwards).
    pub left: Vec<Lane>,
    /// The centre lane (id 0).
    pub center: Lane,
    /// Right lanes in order −1, −2, −3, … (from the centre outwards).
    pub right: Vec<Lane>,
}

impl LaneSection {
    /// The lane with this id, if the section holds it.
    pub fn lane(&self, id: i32) -> Option<&Lane> {
        match id {
            0 => Some(&self.center),
            i if i > 0 => self
                .left
                .get(usize::try_from(i - 1).ok()?)
                .filter(|l| l.id == id),
            i => self
                .right
                .get(usize::try_from(-i - 1).ok()?)
                .filter(|l| l.id == id),
        }
    }

    /// Whether a vehicle may change from lane `from` to the adjacent lane `to` at `ds` metres
    /// from the section's start, by the road mark in effect there on the border between them
    /// ([`RoadMark::permits_lane_change`]). A lane's marks lie along its outer border and the
    /// centre lane's between the left and right lanes (§11.8), so the border of two lanes is
    /// the record of the one nearer the centre, or the centre lane's when they lie on either
    /// side of it. No mark there (or no such lane): the change is permitted.
    pub fn permits_lane_change(&self, from: i32, to: i32, ds: Real) -> bool {
        self.lane_change_stretch(from, to, ds).permitted
    }

    /// [`permits_lane_change`](Self::permits_lane_change) with the stretch of ds over which
    /// the same mark record is in effect, so the same answer holds ([`MarkStretch::holds`]).
    /// A caller asking each step as a vehicle moves along the section (the `mobil` driver
    /// model) keeps the answer while its stretch holds (issue 31).
    ///
    /// The record in effect at ds is the last of the leading records whose `sOffset` is at
    /// or before ds (the records are sorted by `sOffset`); the same records lead for every
    /// ds' from the largest `sOffset` among them (none: −∞) to before the next record's
    /// (none: +∞).
    pub fn lane_change_stretch(&self, from: i32, to: i32, ds: Real) -> MarkStretch {
        let border_of = if from.signum() * to.signum() < 0 {
            0
        } else if from.abs() < to.abs() {
            from
        } else {
            to
        };
        let marks = self
            .lane(border_of)
            .map_or(&[][..], |lane| &lane.road_marks[..]);
        let leading = marks.iter().take_while(|m| m.s_offset <= ds).count();
        let before = &marks[..leading];
        MarkStretch {
            permitted: before
                .last()
                .is_none_or(|m| m.permits_lane_change(border_of, to > from)),
            from: before
                .iter()
                .map(|m| m.s_offset)
                .fold(Real::NEG_INFINITY, Real::max),
            to: marks.get(leading).map_or(Real::INFINITY, |m| m.s_offset),
        }
    }

    /// Ids of one side's lanes (`left`: ids > 0, else < 0) whose type passes `keep`, in the
    /// order a driver heading towards +s meets them from its right (`backward`: heading
    /// towards −s): towards +s the smallest id first (−3, −2, −1; 1, 2), towards −s the
    /// largest. The one numbering rule of `lane(n)` (ASAM OpenSCENARIO DSL 2.1 §8.9, 1 the
    /// rightmost in the direction of travel) for the DSL's plan and the engine.
    pub fn side_from_right(
        &self,
        left: bool,
        backward: bool,
        keep: impl Fn(&LaneType) -> bool,
    ) -> Vec<i32> {
        let side = if left { &self.left } else { &self.right };
        let mut ids: Vec<i32> = side
            .iter()
            .filter(|l| keep(&l.lane_type))
            .map(|l| l.id)
            .collect();
        ids.sort_unstable();
        if backward {
            ids.reverse();
        }
        ids
    }

    /// All lanes, left outermost to right outermost (the centre lane included).
    pub fn lanes(&self) -> impl Iterator<Item = &Lane> {
        self.left
            .iter()
            .rev()
            .chain(std::iter::once(&self.center))
            .chain(self.right.iter())
    }
}

/// The answer of [`LaneSection::lane_change_stretch`] and the stretch [from, to) of ds (m
/// from the section's start) over which it holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MarkStretch {
    /// Whether the change is permitted ([`LaneSection::permits_lane_change`]).
    pub permitted: bool,
    /// Where the stretch starts (m from the section's start; −∞ before the first record).
    pub from: Real,
    /// Where the next record starts (+∞ after the last).
    pub to: Real,
}

impl MarkStretch {
    /// Whether the answer holds at `ds`: `from` ≤ ds < `to` (never at a NaN).
    #[inline]
    pub fn holds(&self, ds: Real) -> bool {
        self.from <= ds && ds < self.to
    }
}
