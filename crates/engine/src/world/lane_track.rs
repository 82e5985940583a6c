//! The lane an entity tracks (OpenSCENARIO 1.3 §7.2.2.1: the default controller keeps the
//! entity in its lane at its offset; §6.3.3 road and lane coordinates): the lane and offset
//! followed, the direction of travel, a lateral transition in progress ([`Blend`]) and the
//! memos the step keeps on it. Plain state below `entity` (which holds it) and the modules
//! that move it (`lanes`, `lane_change`, `route_follow`).

use opendrive::{Direction, FrameStretch, LaneSpan, Real, RoadHandle};

/// Where the default controller keeps an entity: the lane it follows and its offset from that
/// lane's centre, and the direction of travel along s.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LaneTrack {
    /// Road id.
    pub road_id: String,
    /// The same road as `road_id`, by handle: the step finds the road without hashing its id.
    /// The track's two writers (`world::place_on_lane`, which makes it, and
    /// `lanes::advance`, which carries it onto the next road) set both.
    pub road: RoadHandle,
    /// Lane id followed.
    pub lane_id: i32,
    /// s along the road's reference line (m).
    pub s: Real,
    /// Lateral position t from the reference line (m, positive left).
    pub t: Real,
    /// Offset from the followed lane's centre (m, positive left).
    pub offset: Real,
    /// Travel towards increasing or decreasing s.
    pub direction: Direction,
    /// Entity heading minus the lane's direction of travel (rad); 0 when aligned.
    pub relative_heading: Real,
    /// A lateral transition in progress (lane change or lane offset), if any.
    pub blend: Option<Blend>,
    /// The reference line's curvature at the track's s, as the last move computed it there
    /// (world/lanes.rs `curvature`; `None` until then).
    pub(crate) curvature: Option<CurvatureAt>,
    /// The followed lane's span and the lane look-up over an s-range where the road's lanes do
    /// not change (world/lanes.rs; `None` where they do). Where it is kept, its range lies
    /// inside `frame`'s stretch of the same road (made inside it, dropped where `frame` is
    /// made anew around another range: world/lanes.rs `refresh_frame`), so that `frame`
    /// holds every s the memo holds.
    pub(crate) lanes: Option<LanesMemo>,
    /// The road's frame stretch around the track's s as the last pose found it
    /// (world/lanes.rs `track_pose`; `None` until then).
    pub(crate) frame: Option<FrameAt>,
}

/// A [`FrameStretch`] of one road ([`Road::frame_stretch`](opendrive::Road::frame_stretch)):
/// where it holds the track's s, the pose is computed from it
/// ([`Road::pose_in`](opendrive::Road::pose_in)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct FrameAt {
    /// The road.
    pub(crate) road: RoadHandle,
    /// Its stretch.
    pub(crate) stretch: FrameStretch,
}

/// Lane answers that stay the same over an s-range of one road
/// ([`Road::constant_lanes`](opendrive::Road::constant_lanes): every lane border is the same
/// number at every s there), kept while the track moves inside it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LanesMemo {
    /// The road.
    pub(crate) road: RoadHandle,
    /// The s-range.
    pub(crate) lo: Real,
    /// The s-range's end.
    pub(crate) hi: Real,
    /// The lane whose span is kept.
    pub(crate) lane: i32,
    /// Its span.
    pub(crate) span: LaneSpan,
    /// `position::lane_at` at the lateral position with these bits, once asked.
    pub(crate) at: Option<(u64, Option<(i32, Real)>)>,
}

/// The reference line's curvature of one road at one s (`lanes::curvature`, a pure function
/// of both): a move ends by computing it where the entity now stands, and the next move starts
/// there, so it is computed once per step instead of twice. Keyed by road and the bits of s,
/// so that a track moved by anything else (an action, a teleport) never reads a stale value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct CurvatureAt {
    /// The road.
    pub(crate) road: RoadHandle,
    /// `s.to_bits()`.
    pub(crate) s_bits: u64,
    /// The curvature (1/m).
    pub(crate) value: Real,
}

impl LaneTrack {
    /// The curvature memo, if it holds the track's road and s.
    #[inline]
    pub(crate) fn curvature_here(&self) -> Option<Real> {
        self.curvature
            .filter(|c| c.road == self.road && c.s_bits == self.s.to_bits())
            .map(|c| c.value)
    }
}

/// A lateral transition from one (lane, offset) to the track's own: the lateral position is
/// t = (1 − w)·(centre(from_lane) + from_offset) + w·(centre(lane_id) + offset).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Blend {
    /// The lane left.
    pub from_lane: i32,
    /// Offset from its centre at the start (m).
    pub from_offset: Real,
    /// Weight w of the target, 0 → 1.
    pub weight: Real,
    /// dw per metre travelled along the lane (for the heading).
    pub weight_per_m: Real,
}
