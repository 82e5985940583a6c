//! `<road>`: attributes, links, type and speed, and the containers for plan view, profiles,
//! lanes, objects and signals (OpenDRIVE 1.8 §10 roads).

use crate::geometry::PlanView;
use crate::math::{Cubic, Real};

use super::{ContactPoint, LaneSection, Object, Signal};

/// `road/@rule`: which side traffic keeps to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TrafficRule {
    /// Right-hand traffic (`RHT`, the default): lanes with negative ids run towards +s.
    #[default]
    RightHand,
    /// Left-hand traffic (`LHT`): lanes with positive ids run towards +s.
    LeftHand,
}

/// What a road link points to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ElementType {
    /// `road`.
    Road,
    /// `junction`.
    Junction,
}

/// `<predecessor>` or `<successor>` of a road.
#[derive(Debug, Clone, PartialEq)]
pub struct RoadLink {
    /// `elementType`.
    pub element_type: ElementType,
    /// `elementId`.
    pub element_id: String,
    /// `contactPoint` (for roads).
    pub contact_point: Option<ContactPoint>,
}

/// `<link>` of a road.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RoadLinks {
    /// `<predecessor>`: what the road's start (s = 0) connects to.
    pub predecessor: Option<RoadLink>,
    /// `<successor>`: what the road's end (s = length) connects to.
    pub successor: Option<RoadLink>,
}

/// `<speed max unit>` of a road type, converted to m/s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Speed {
    /// Maximum speed (m/s); `f64::INFINITY` for "no limit".
    pub max: Real,
}

/// `<type s type>` of a road.
#[derive(Debug, Clone, PartialEq)]
pub struct RoadType {
    /// `s` (m) where the type starts.
    pub s: Real,
    /// `type` (e.g. "motorway", "town").
    pub road_type: String,
    /// `<speed>`, if any.
    pub speed: Option<Speed>,
}

/// `<road>`.
#[derive(Debug, Clone, PartialEq)]
pub struct Road {
    /// `id`.
    pub id: String,
    /// `name`.
    pub name: String,
    /// `length` (m).
    pub length: Real,
    /// `junction`: the junction the road belongs to, `None` for "-1".
    pub junction: Option<String>,
    /// `rule`.
    pub rule: TrafficRule,
    /// `<link>`.
    pub links: RoadLinks,
    /// `<type>` records, sorted by `s`.
    pub types: Vec<RoadType>,
    /// `<planView>`: the reference line.
    pub plan_view: PlanView,
    /// `<elevationProfile>` records (`start` = s).
    pub elevation: Vec<Cubic>,
    /// `<lateralProfile>` superelevation records (`start` = s), roll angle in rad.
    pub superelevation: Vec<Cubic>,
    /// `<lanes><laneOffset>` records (`start` = s).
    pub lane_offsets: Vec<Cubic>,
    /// `<laneSection>`s, sorted by `s`.
    pub lane_sections: Vec<LaneSection>,
    /// `<objects>`.
    pub objects: Vec<Object>,
    /// `<signals>`.
    pub signals: Vec<Signal>,
}

impl Road {
    /// Index of the lane section valid at `s`: the last one starting at or before `s`
    /// (at a section boundary the new section applies).
    #[inline]
    pub fn lane_section_index(&self, s: Real) -> usize {
        let i = self
            .lane_sections
            .partition_point(|ls| ls.s <= s + crate::math::LENGTH_EPSILON);
        i.saturating_sub(1)
    }

    /// The index of the lane section valid at `s` ([`lane_section_index`](Self::lane_section_index))
    /// and the stretch of s over which it is the same ([`SectionStretch::holds`]): from the
    /// section's start (the first section: from −∞) to the next section's (the last: +∞),
    /// each compared as `lane_section_index` compares it, at s + [`LENGTH_EPSILON`]. A caller
    /// asking each step as a vehicle moves along the road keeps the index while the stretch
    /// holds (issue 31).
    ///
    /// [`LENGTH_EPSILON`]: crate::LENGTH_EPSILON
    pub fn lane_section_stretch(&self, s: Real) -> SectionStretch {
        let index = self.lane_section_index(s);
        SectionStretch {
            index,
            from: match index {
                0 => Real::NEG_INFINITY,
                i => self.lane_sections[i].s,
            },
            to: self
                .lane_sections
                .get(index + 1)
                .map_or(Real::INFINITY, |ls| ls.s),
        }
    }

    /// The lane section valid at `s`.
    pub fn lane_section_at(&self, s: Real) -> &LaneSection {
        // Invariant: the parser rejects roads without a lane section.
        &self.lane_sections[self.lane_section_index(s)]
    }

    /// End s of lane section `i` (the next section's start, or the road's length).
    pub fn lane_section_end(&self, i: usize) -> Real {
        self.lane_sections.get(i + 1).map_or(self.length, |ls| ls.s)
    }

    /// The road type valid at `s`, if any.
    pub fn type_at(&self, s: Real) -> Option<&RoadType> {
        let i = self
            .types
            .partition_point(|t| t.s <= s + crate::math::LENGTH_EPSILON);
        i.checked_sub(1).map(|i| &self.types[i])
    }
}

/// A lane section's index and the stretch of s where it is the section valid
/// ([`Road::lane_section_stretch`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SectionStretch {
    /// The section's index in [`Road::lane_sections`].
    pub index: usize,
    /// The section's start s (−∞ for the first section).
    pub from: Real,
    /// The next section's start s (+∞ for the last).
    pub to: Real,
}

impl SectionStretch {
    /// Whether [`Road::lane_section_index`]`(s)` is [`index`](Self::index): the sections at or
    /// before s + `LENGTH_EPSILON` are those up to this one (the sections are sorted by s, as
    /// the parser makes them); never at a NaN.
    #[inline]
    pub fn holds(&self, s: Real) -> bool {
        let u = s + crate::math::LENGTH_EPSILON;
        self.from <= u && u < self.to
    }
}
