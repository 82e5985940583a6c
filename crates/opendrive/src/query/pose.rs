//! (road, s, t) → world pose and (road, lane, s, offset) → world pose (OpenDRIVE 1.8 §8.3–8.4
//! reference-line and local coordinate systems, §11 lanes for the lane centre and lane height).
//!
//! Heading of a lane pose: the true tangent of the curve t(s) = lane centre + offset in the
//! horizontal plane, h = road heading + atan2(dt/ds, 1 − κ·t), κ the reference line's
//! curvature; on banked roads t is first projected (t·cos r, and the change of roll along s
//! counts), see `RoadFrame::tangent_heading`. esmini uses
//! h = road heading + atan(dt/ds) instead; the reference tests reproduce that convention in the
//! comparison only. Pitch and roll of a lane pose are the road's.

use crate::error::{Error, ErrorKind};
use crate::math::{normalize_angle, Pose, Real, S_TOLERANCE};
use crate::model::{Lane, LaneSection, Road};
use crate::network::RoadNetwork;
use crate::road::frame::road_frame;
use crate::road::lane_span::{for_each_span, lane_span, LaneSpan};

impl Road {
    /// `s` clamped onto [0, length], or an error if it lies further out or is not finite.
    #[inline]
    pub(crate) fn check_s(&self, s: Real) -> Result<Real, Error> {
        if s.is_finite() && s >= -S_TOLERANCE && s <= self.length + S_TOLERANCE {
            Ok(s.clamp(0.0, self.length))
        } else {
            Err(self.s_out_of_range(s))
        }
    }

    /// The error of [`check_s`](Self::check_s), out of line: the functions that check s are
    /// inlined into the step's code, which never takes this path.
    #[cold]
    #[inline(never)]
    fn s_out_of_range(&self, s: Real) -> Error {
        Error::new(ErrorKind::SOutOfRange {
            road: self.id.clone(),
            s,
            length: self.length,
        })
    }

    /// World pose of the road point (s, t): t from the reference line, positive left, on the
    /// road surface; heading, pitch and roll of the reference line at s.
    ///
    /// Always inlined: returned through memory, the pose was stored a number at a time and
    /// read back by the caller two at a time, loads that wait for the stores to reach the
    /// cache (a third of the samples of the move's `place_on_track` at 4,000 vehicles, issue
    /// 31); inlined, its numbers stay in registers.
    #[inline(always)]
    pub fn pose(&self, s: Real, t: Real) -> Result<Pose, Error> {
        let s = self.check_s(s)?;
        Ok(road_frame(self, s).pose(t))
    }

    /// Heading of the reference line at `s`: the `h` of [`pose`](Self::pose) at any t, bit for
    /// bit, without evaluating the elevation and lateral profiles. Always inlined: the moves
    /// of the step ask it once per entity for the curvature (engine world/lanes.rs), where
    /// an out-of-line call returning its `Result` through memory was 60 instructions for a
    /// line's heading (issue 31).
    #[inline(always)]
    pub fn heading(&self, s: Real) -> Result<Real, Error> {
        let s = self.check_s(s)?;
        Ok(self.plan_view.eval_trig(s).0.hdg)
    }

    /// Lateral extent of lane `lane_id` at `s` (lane section looked up from s; a lane ending
    /// at s is found at its end, see [`Road::lane_section_holding`]).
    pub fn lane_span(&self, lane_id: i32, s: Real) -> Result<LaneSpan, Error> {
        let s = self.check_s(s)?;
        let section = self.lane_section_holding(lane_id, s);
        lane_span(self, section, lane_id, s).ok_or_else(|| self.no_lane(lane_id, s))
    }

    /// The lane section that holds lane `lane_id` at `s`: the one valid at `s`
    /// ([`Road::lane_section_at`]), or, where `s` is the end of the previous section and the
    /// lane is in that one only, the previous one. A lane's centre line and borders are
    /// defined on its section's closed interval [s_start, s_end] (OpenDRIVE 1.8 §11.3: the
    /// lane section's polynomials hold up to the next section's start), so a lane that ends
    /// at a section boundary has a position at its end, as the one that begins there does.
    pub fn lane_section_holding(&self, lane_id: i32, s: Real) -> &LaneSection {
        &self.lane_sections[self.lane_section_index_holding(lane_id, s)]
    }

    /// Index of [`Road::lane_section_holding`].
    #[inline]
    pub fn lane_section_index_holding(&self, lane_id: i32, s: Real) -> usize {
        let i = self.lane_section_index(s);
        let section = &self.lane_sections[i];
        if i == 0 || section.lane(lane_id).is_some() {
            return i;
        }
        let previous = &self.lane_sections[i - 1];
        if (s - section.s).abs() <= S_TOLERANCE && previous.lane(lane_id).is_some() {
            i - 1
        } else {
            i
        }
    }

    /// Every lane of the lane section at `s` with its span there, from the centre outwards
    /// (centre lane, left 1, 2, …, right −1, −2, …), in one pass; each span is the one
    /// [`lane_span`](Self::lane_span) gives.
    pub fn lane_spans(&self, s: Real, f: impl FnMut(&Lane, LaneSpan)) -> Result<(), Error> {
        let s = self.check_s(s)?;
        for_each_span(self, self.lane_section_at(s), s, f);
        Ok(())
    }

    fn no_lane(&self, lane: i32, s: Real) -> Error {
        Error::new(ErrorKind::NoSuchLane {
            road: self.id.clone(),
            lane,
            s,
        })
    }

    /// World pose of a point `offset` metres left of the centre of lane `lane_id` at `s`,
    /// lifted by the lane's `<height>` (a lane ending at s is found at its end, see
    /// [`Road::lane_section_holding`]).
    pub fn lane_pose(&self, lane_id: i32, s: Real, offset: Real) -> Result<Pose, Error> {
        let s = self.check_s(s)?;
        let section = self.lane_section_holding(lane_id, s);
        let span = lane_span(self, section, lane_id, s).ok_or_else(|| self.no_lane(lane_id, s))?;
        let t = span.center() + offset;
        let height = section
            .lane(lane_id)
            .map_or(0.0, |l| lane_height(l, s - section.s, &span, t));
        let f = road_frame(self, s);
        let [x, y, z] = f.place(t, height);
        let h = normalize_angle(f.tangent_heading(t, span.d_center(), height));
        Ok(Pose {
            x,
            y,
            z,
            h,
            p: f.pitch,
            r: f.roll,
        })
    }
}

/// The lane's `<height>` at `ds` from the section start and lateral position `t`: linear from
/// `inner` at the inner border to `outer` at the outer border; each record holds until the next
/// ("a specific lane geometry shall remain valid until another lane geometry of that type is
/// defined", OpenDRIVE 1.8 §11.6; esmini interpolates between records instead).
fn lane_height(lane: &Lane, ds: Real, span: &LaneSpan, t: Real) -> Real {
    if lane.heights.is_empty() {
        return 0.0;
    }
    let i = lane
        .heights
        .partition_point(|h| h.s_offset <= ds)
        .saturating_sub(1);
    let h = &lane.heights[i];
    let w = span.outer - span.inner;
    let frac = if w.abs() > 1e-12 {
        ((t - span.inner) / w).clamp(0.0, 1.0)
    } else {
        0.5
    };
    h.inner + frac * (h.outer - h.inner)
}

impl RoadNetwork {
    /// World pose of (road, s, t); see [`Road::pose`].
    pub fn road_pose(&self, road_id: &str, s: Real, t: Real) -> Result<Pose, Error> {
        self.road_or_err(road_id)?.1.pose(s, t)
    }

    /// World pose of a point `offset` metres left of the centre of a lane; see
    /// [`Road::lane_pose`].
    pub fn lane_pose(
        &self,
        road_id: &str,
        lane_id: i32,
        s: Real,
        offset: Real,
    ) -> Result<Pose, Error> {
        self.road_or_err(road_id)?.1.lane_pose(lane_id, s, offset)
    }

    /// Width of a lane at s (m).
    pub fn lane_width(&self, road_id: &str, lane_id: i32, s: Real) -> Result<Real, Error> {
        Ok(self.lane_boundaries(road_id, lane_id, s)?.width())
    }

    /// Inner and outer border (t from the reference line) of a lane at s.
    pub fn lane_boundaries(&self, road_id: &str, lane_id: i32, s: Real) -> Result<LaneSpan, Error> {
        self.road_or_err(road_id)?.1.lane_span(lane_id, s)
    }
}
