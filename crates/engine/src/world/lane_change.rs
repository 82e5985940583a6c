//! The lane change a route needs (OpenSCENARIO 1.3 §7.5 "Routes": the default controller
//! follows the assigned route; how it changes lanes is not given by the standard).
//!
//! Dynamics: the `cubic` transition shape of OpenSCENARIO 1.3 (XSD `DynamicsShape`; zero
//! lateral speed at both ends) along the lane, over the distance that keeps the peak lateral
//! acceleration at [`MAX_LATERAL_ACCELERATION`]. For a cubic y = Δ·(3u² − 2u³), u = x/D, at
//! speed v the lateral acceleration is v²·y″(x) = Δ·v²·(6 − 12u)/D², largest at the ends:
//! 6·Δ·v²/D². So D = v·√(6·Δ/a), a duration of √(6·Δ/a) whatever the speed: 4.58 s for a
//! 3.5 m lane. The change starts as soon as the route needs it and ends, at the latest, where
//! the road does (shorter, and so sharper, when less road is left). A driver model's change
//! (controller/stage.rs) takes its whole length where the lane it goes to links onto the next
//! road, going on across the link ([`room_for`]). A driver model does not start one into a
//! lane that ends within it ([`ends_within_change`]: less of the lane left ahead than the
//! change's length plus the vehicle's, and less than of its own lane; the `mobil` module doc
//! "A lane that ends").
//!
//! The lateral position is the blend of the two lanes' centres that LaneChangeAction uses
//! ([`Blend`]), so lane width changes along the way are followed.

use opendrive::{Direction, LaneHandle, Real, RoadNetwork};
use scenario::DynamicsShape;

use crate::position::lane_at;
use crate::world::lane_track::{Blend, LaneTrack};
use crate::world::lanes::lane_left;
use crate::world::shapes::shape_value;

/// Largest lateral acceleration of a route's lane change (m/s²): the limit UN Regulation
/// No. 79 sets for the lane change manoeuvre of an automatically commanded steering function
/// of category C (paragraph 5.6.4 and its lane change test in Annex 8: lateral acceleration
/// not above 1 m/s², the manoeuvre done within 5 s for an M1 car; 4.58 s here for 3.5 m).
pub const MAX_LATERAL_ACCELERATION: Real = 1.0;

/// A lane change in progress: from the odometer reading where it started, over `length` m of
/// travel, moving `delta` m sideways.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RouteLaneChange {
    start_odometer: Real,
    length: Real,
    delta: Real,
}

/// The distance (m) of a lane change moving `delta` m sideways at `speed` m/s (module doc).
pub fn change_length(delta: Real, speed: Real) -> Real {
    speed.abs() * (6.0 * delta.abs() / MAX_LATERAL_ACCELERATION).sqrt()
}

/// The road a driver model's lane change into lane `lane` may take (m): unbounded where
/// `lane`, at the end of `track`'s road in its direction of travel, links onto a lane of the
/// next road (OpenDRIVE 1.8 §11.5 lane linkage), since a transition in progress goes on across
/// the link (world/lanes.rs `advance`); else the rest of the road, as a route's change has.
/// A change begun 5 m before the road's end at 20 m/s took those 5 m before: 3.5 m sideways
/// in a quarter of a second (engine tests controller/user_controllers.rs
/// `a_driver_models_change_runs_its_length_across_a_road_link`).
pub(crate) fn room_for(net: &RoadNetwork, track: &LaneTrack, lane: i32) -> Real {
    let end = match track.direction {
        opendrive::Direction::Forward => net.road_at(track.road).length,
        opendrive::Direction::Backward => 0.0,
    };
    let links_on = net
        .lane_handle_on(track.road, lane, end)
        .is_some_and(|h| !net.successors(h).is_empty());
    if links_on {
        Real::INFINITY
    } else {
        road_left(net, track)
    }
}

/// The road left ahead of `track` on its road, in its direction of travel (m): the room a
/// route's lane change has ([`begin`]'s `room`).
pub(crate) fn road_left(net: &RoadNetwork, track: &LaneTrack) -> Real {
    match track.direction {
        opendrive::Direction::Forward => net.road_at(track.road).length - track.s,
        opendrive::Direction::Backward => track.s,
    }
}

/// How far (m) a change of `track` (on `road`) into lane `lane` moves sideways: from its t to
/// the lane's centre at its s plus the track's offset from its own lane's centre, which the
/// change keeps: [`begin`]'s arithmetic, which `begin` keeps written out (called from it, it
/// changed how the controllers stage's walk was compiled: 5 instructions more per `mobil`
/// entity-step on the scale highway, issue 31). `None` where `road` has no lane `lane` at s.
fn change_delta(road: &opendrive::Road, track: &LaneTrack, lane: i32) -> Option<Real> {
    let target = road.lane_span(lane, track.s).ok()?.center() + track.offset;
    Some(target - track.t)
}

/// Whether a driver model must not start a change of `track` from its own lane `own` into the
/// lane beside `beside` (its handle at the track's s and the direction of travel) at `speed`
/// for a vehicle `length` m long (module doc "A lane that ends"): the lane beside has less
/// than the change's length ([`change_length`] of the change's sideways move,
/// [`change_delta`]) plus `length` ahead of the track's s ([`lane_left`], `choose` picking
/// at a road's end as the gap searches do), and less than the own lane has. `false` where the
/// road has no such lane at s.
pub(crate) fn ends_within_change(
    net: &RoadNetwork,
    track: &LaneTrack,
    own: LaneHandle,
    beside: (LaneHandle, Direction),
    speed: Real,
    length: Real,
    choose: &mut dyn FnMut(&str, &[LaneHandle]) -> Option<LaneHandle>,
) -> bool {
    let road = net.road_at(track.road);
    let Some(delta) = change_delta(road, track, beside.0.lane) else {
        return false;
    };
    let needed = change_length(delta, speed) + length;
    let (h, direction) = beside;
    let left = lane_left(net, h, direction, track.s, needed, choose);
    // The own lane walked only where the lane beside is too short (a NaN refuses nothing).
    left < needed && left < lane_left(net, own, track.direction, track.s, needed, choose)
}

/// Starts moving `track` into lane `lane` (keeping its offset from the lane centre) over the
/// distance [`change_length`] gives, at most `room` m. `None` when the change is done at once
/// (no room left): the track is then already in the new lane.
pub(crate) fn begin(
    net: &RoadNetwork,
    track: &mut LaneTrack,
    lane: i32,
    speed: Real,
    odometer: Real,
    room: Real,
) -> Option<RouteLaneChange> {
    let road = net.road(&track.road_id)?;
    let target = road.lane_span(lane, track.s).ok()?.center() + track.offset;
    let (from_lane, from_offset) =
        lane_at(road, track.s, track.t).unwrap_or((track.lane_id, track.offset));
    let delta = target - track.t;
    let length = change_length(delta, speed).min(room.max(0.0));
    track.lane_id = lane;
    if length <= opendrive::LENGTH_EPSILON {
        track.blend = None;
        return None;
    }
    track.blend = Some(Blend {
        from_lane,
        from_offset,
        weight: 0.0,
        weight_per_m: 0.0,
    });
    Some(RouteLaneChange {
        start_odometer: odometer,
        length,
        delta,
    })
}

/// Sets the blend weight for the end of a step that will travel `distance` m; `false` once the
/// change is complete (the blend is then removed). Progress is by distance travelled, so the
/// lateral share of the motion is sin θ = Δ·f′(p)/D and the blend's dw per metre along the
/// lane ([`Blend::weight_per_m`]) is f′(p)/D / cos θ.
pub(crate) fn step(
    change: &RouteLaneChange,
    track: &mut LaneTrack,
    odometer: Real,
    distance: Real,
) -> bool {
    let p = (odometer + distance.abs() - change.start_odometer) / change.length;
    if p >= 1.0 {
        track.blend = None;
        return false;
    }
    let (f, df_dp) = shape_value(DynamicsShape::Cubic, p);
    match &mut track.blend {
        Some(b) => {
            let per_m = df_dp / change.length;
            let sin = (change.delta * per_m).clamp(-1.0, 1.0);
            b.weight = f;
            b.weight_per_m = per_m / (1.0 - sin * sin).sqrt().max(Real::EPSILON);
            true
        }
        None => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn length_keeps_the_peak_lateral_acceleration() {
        // 3.5 m at 10 m/s: D = 10·√(6·3.5/1) = 10·√21 = 45.8258 m; the peak lateral
        // acceleration 6·Δ·v²/D² = 6·3.5·100/2100 = 1 m/s².
        let d = change_length(3.5, 10.0);
        assert!((d - 45.825_756_949_558_4).abs() < 1e-9, "{d}");
        assert!((6.0 * 3.5 * 100.0 / (d * d) - MAX_LATERAL_ACCELERATION).abs() < 1e-12);
        // Direction and sign of the move do not matter.
        assert!((change_length(-3.5, -10.0) - d).abs() < 1e-12);
    }
}
