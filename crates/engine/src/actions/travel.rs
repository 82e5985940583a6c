//! oscsim's TravelAction (`scenario::LongitudinalAction::Travel`, an action with no XML form):
//! the OpenSCENARIO DSL runtime's `position(…, at: end)` and `distance(…)` over a phase of
//! known duration that starts on a run-time condition (ASAM OpenSCENARIO DSL 2.1 §8.9), whose
//! speed profile depends on the actor's state at that start. No 1.x action computes a profile
//! from the state at its start: a SpeedProfileAction's targets are fixed before the run.
//!
//! When it starts, the action measures Δs, the distance to cover along the actor's lane centre
//! (`position::RoadChain::lane_length`: from the actor's s to the goal's; on a DSL plan over
//! several roads, `Travel::roads`, in the plan's s and across the roads' joints, the other
//! entity likewise on any of them; for an actor driving against s, `PlanRoads::against`, in
//! u = L − s along its direction of travel, the goal and the gap as the plan writes them),
//! and takes the profile of two
//! linear halves the DSL plan uses at a known start: v₀ → v_m over T/2 and v_m → v_e over T/2
//! with v_m = (4·Δs/T − v₀ − v_e)/2, so that ∫v dt = Δs. It runs as a SpeedProfileAction in
//! `position` mode (strictly linear between the targets) with the targets (v_m, T/2) and
//! (v_e, T/2), and ends with it. A goal relative to another entity is where that entity is
//! at the end if it keeps the speed it has at the start, along its lane; an end speed relative
//! to another entity is that entity's speed at the start (plus the value), likewise.
//!
//! A profile the limits forbid (v_m below 0 or above the maximum speed, a half's acceleration
//! above the maximum, v_m outside [v₀, v_e] when monotonous) is never run another way: the
//! action fails with [`ErrorKind::CheckFailed`](crate::ErrorKind::CheckFailed), an error
//! record in the event log, and the run stops.

use opendrive::Direction;
use scenario::{
    FollowingMode, LongitudinalAction, SourcePos, SpeedProfileEntry, Travel, TravelGoal,
};

use super::{speed_profile, Part};
use crate::error::{Error, ErrorKind};
use crate::position::RoadChain;
use crate::store::World;
use crate::world::entity::EntityId;

/// Starts `travel` on `actor` at `now`.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    travel: &Travel,
    now: f64,
    pos: &SourcePos,
) -> Result<Part, Error> {
    let fail = |expected: String, found: String| {
        Error::new(ErrorKind::CheckFailed {
            what: travel.what.clone(),
            expected,
            found,
            time: now,
        })
    };
    let e = world.entity(actor);
    let name = e.name.clone();
    let v0 = e.speed;
    let t = travel.duration;
    if !(t > 0.0 && t.is_finite()) {
        return Err(Error::at("a duration above 0 s", format!("{t} s"), pos));
    }
    let ds = match &travel.goal {
        TravelGoal::Distance(d) => *d,
        goal => {
            let Some(track) = e.track.as_ref() else {
                return Err(fail(
                    format!("'{name}' on a lane"),
                    "it off every road".into(),
                ));
            };
            // On a plan over several roads: the plan's s, along the lane across the joints.
            let chain = RoadChain::new(&world.network, &travel.roads);
            let (road, lane, forward) = (
                track.road_id.as_str(),
                track.lane_id,
                track.direction == Direction::Forward,
            );
            let off_chain = |who: &str| {
                fail(
                    format!("'{who}' on {}", chain.describe()),
                    format!("'{who}' on road {road}"),
                )
            };
            let s0 = chain.s_of(road, track.s).ok_or_else(|| off_chain(&name))?;
            let s1 = match goal {
                TravelGoal::RoadS(s) => *s,
                TravelGoal::FromEntity(gap) => {
                    let entity_ref = &gap.entity_ref;
                    let x = world
                        .id(entity_ref)
                        .map(|x| world.entity(x))
                        .ok_or_else(|| {
                            Error::at("an entity of the scenario", format!("'{entity_ref}'"), pos)
                        })?;
                    let Some(xt) = x.track.as_ref().filter(|xt| match chain.is_chain() {
                        true => chain.s_of(&xt.road_id, xt.s).is_some(),
                        false => xt.road_id == road,
                    }) else {
                        let at = match chain.is_chain() {
                            true => chain.describe(),
                            false => format!("road {road} beside '{name}'"),
                        };
                        return Err(fail(
                            format!("'{entity_ref}' on {at}"),
                            format!("'{entity_ref}' elsewhere"),
                        ));
                    };
                    let x_forward = xt.direction == Direction::Forward;
                    let s_x = chain
                        .s_at_lane_distance(
                            (&xt.road_id, xt.lane_id, xt.s),
                            (x.speed * t).abs(),
                            x_forward == (x.speed >= 0.0),
                        )
                        .map_err(|err| {
                            fail(
                                format!("'{entity_ref}' on its lane {t} s later at its speed"),
                                format!("the lane ends first ({err})"),
                            )
                        })?;
                    s_x + gap.offset(x.speed)
                }
                _ => return Err(Error::unsupported("this TravelAction goal", pos)),
            };
            let length = chain.lane_length(road, lane, (s0, s1)).ok_or_else(|| {
                let of = chain.roads_or(road);
                fail(
                    format!("lane {lane} of {of} up to {}", chain.place(s1)),
                    "none".into(),
                )
            })?;
            // Along the direction of travel: a goal behind the actor is a negative distance.
            if (s1 >= s0) == chain.increasing(forward) {
                length
            } else {
                -length
            }
        }
    };
    let ve = match &travel.end_speed_of {
        // Another entity's speed at the start (plus a value), as the goal takes its motion.
        Some((other, delta)) => {
            let x = world
                .id(other)
                .map(|x| world.entity(x))
                .ok_or_else(|| Error::at("an entity of the scenario", format!("'{other}'"), pos))?;
            x.speed + delta
        }
        None => travel.end_speed.unwrap_or(v0),
    };
    let vm = (4.0 * ds / t - v0 - ve) / 2.0;
    let (max_speed, max_acc) = travel.limits;
    let profile = format!("{ds:.3} m in {t} s from {v0:.3} m/s: {v0:.3} → {vm:.3} → {ve:.3} m/s");
    let worst = ((vm - v0).abs()).max((ve - vm).abs()) / (t / 2.0);
    if !(0.0..=max_speed).contains(&vm) {
        return Err(fail(
            format!("'{name}' between 0 and {max_speed} m/s"),
            profile,
        ));
    }
    if worst > max_acc + crate::tolerance::SPEED {
        return Err(fail(
            format!("'{name}' accelerating at {max_acc} m/s² or less"),
            format!("{profile}, {worst:.3} m/s²"),
        ));
    }
    if travel.monotonous && (vm - v0) * (ve - vm) < -crate::tolerance::SPEED {
        return Err(fail(
            format!("a monotonous speed profile of '{name}'"),
            profile,
        ));
    }
    let halves = LongitudinalAction::SpeedProfile {
        entity_ref: None,
        following_mode: FollowingMode::Position,
        dynamic_constraints: None,
        entries: vec![
            SpeedProfileEntry {
                speed: vm,
                time: Some(t / 2.0),
            },
            SpeedProfileEntry {
                speed: ve,
                time: Some(t / 2.0),
            },
        ],
    };
    speed_profile::start(world, actor, &halves, now, pos)
}
