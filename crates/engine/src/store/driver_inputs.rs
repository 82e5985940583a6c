//! The driver models' per-step inputs (issue 31): for each entity, the few numbers of its
//! state the built-in controllers' commands read (OpenSCENARIO 1.3 §6.6 user-defined
//! controllers; the world view of controller/view.rs), copied from the [`Entity`] in the walk
//! that builds the step's lane index (store/lane_index.rs).
//!
//! **Why a table of its own.** An `Entity` is 1.3 kB; what an `idm` or `mobil` command reads of
//! it (its speed, its lane track's road, lane, s, direction and lateral transition, whether an
//! action holds its lateral domain) lies on several of its cache lines. At 4,000 vehicles the
//! entities (5 MB) do not stay in the core's cache from one walk over them to the next, so the
//! commands, worked out after the index is built, loaded those lines a second time per step.
//! A row here is 64 bytes; the rows of 4,000 entities (256 kB) are read in the order they were
//! written, right after. The lane handle of the entity's own lane is worked out in the same
//! walk: the index looks up the handle of the lane its road position names, which is the
//! track's lane at the same s wherever the two agree (the look-up is then not repeated).
//!
//! The rows are copies: the same numbers as the entity's at the step's start, which no
//! command changes (every command is worked out before any entity moves, controller/stage.rs),
//! so a command gives the same bits whether it reads the row or the entity.

use opendrive::{Direction, LaneHandle, Real, RoadHandle, RoadNetwork};

use crate::world::entity::{Entity, EntityId};

/// What the driver models read of an entity's lane track (the lane the default controller
/// keeps it in).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrackInput {
    /// The track's road.
    pub road: RoadHandle,
    /// The lane followed.
    pub lane_id: i32,
    /// s along the road (m).
    pub s: Real,
    /// Direction of travel along s.
    pub direction: Direction,
    /// The lane a lateral transition in progress leaves (`Some` exactly while one runs).
    pub blend_from: Option<i32>,
    /// The handle of lane `lane_id` of `road` at `s` ([`RoadNetwork::lane_handle_on`]).
    pub own: Option<LaneHandle>,
}

/// One entity's row (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DriverInput {
    /// The entity.
    pub id: EntityId,
    /// It is placed in the world.
    pub placed: bool,
    /// An action holds its lateral domain.
    pub lateral_action: bool,
    /// Its speed (m/s).
    pub speed: Real,
    /// Its lane track, if it has one.
    pub track: Option<TrackInput>,
}

impl DriverInput {
    /// The row of `e` on `net`, its own lane's handle looked up.
    pub fn of(e: &Entity, net: &RoadNetwork) -> Self {
        Self::with_own(e, |road, lane, s| net.lane_handle_on(road, lane, s))
    }

    /// Makes `row` the row of `e` on `net`, where the lane index looked up the handle of lane
    /// `looked_up` (road, lane, s, handle) for the entity's footprint: the track's own lane's
    /// handle is that one where the track names the same road, lane and s (the common case),
    /// else it is looked up. The fields are written one by one where the row is, not a row
    /// built aside and copied in: the copy loaded 8 or 16 bytes at a time what had just been
    /// stored 4 bytes at a time and waited for the stores (a third of the index walk's
    /// samples, issue 31).
    #[inline]
    pub(crate) fn write(
        row: &mut Option<DriverInput>,
        e: &Entity,
        net: &RoadNetwork,
        looked_up: Option<(RoadHandle, i32, Real, LaneHandle)>,
    ) {
        let own = |road, lane, s: Real| match looked_up {
            Some((r, l, at, h)) if (r, l) == (road, lane) && at.to_bits() == s.to_bits() => Some(h),
            _ => net.lane_handle_on(road, lane, s),
        };
        let Some(r) = row else {
            *row = Some(Self::with_own(e, own));
            return;
        };
        r.id = e.id;
        r.placed = e.placed;
        r.lateral_action = e.lateral_action.is_some();
        r.speed = e.speed;
        let (Some(rt), Some(t)) = (&mut r.track, &e.track) else {
            r.track = Self::with_own(e, own).track;
            return;
        };
        rt.road = t.road;
        rt.lane_id = t.lane_id;
        rt.s = t.s;
        rt.direction = t.direction;
        rt.blend_from = t.blend.as_ref().map(|b| b.from_lane);
        match (looked_up, &mut rt.own) {
            (Some((road, lane, at, h)), Some(o))
                if (road, lane) == (t.road, t.lane_id) && at.to_bits() == t.s.to_bits() =>
            {
                o.road = h.road;
                o.section = h.section;
                o.lane = h.lane;
            }
            (_, o) => *o = own(t.road, t.lane_id, t.s),
        }
    }

    /// The row of `e`, its own lane's handle from `own(road, lane, s)`.
    pub(crate) fn with_own(
        e: &Entity,
        own: impl FnOnce(RoadHandle, i32, Real) -> Option<LaneHandle>,
    ) -> Self {
        DriverInput {
            id: e.id,
            placed: e.placed,
            lateral_action: e.lateral_action.is_some(),
            speed: e.speed,
            track: e.track.as_ref().map(|t| TrackInput {
                road: t.road,
                lane_id: t.lane_id,
                s: t.s,
                direction: t.direction,
                blend_from: t.blend.as_ref().map(|b| b.from_lane),
                own: own(t.road, t.lane_id, t.s),
            }),
        }
    }
}
