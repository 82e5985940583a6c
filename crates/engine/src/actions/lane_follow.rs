//! oscsim's following of other entities' lane changes (`scenario::LateralAction::FollowLanes`,
//! no XML form): the OpenSCENARIO DSL runtime's `lane(same_as/side_of/left_of/right_of: x)`
//! at: all of an actor with no sideways motion of its own in a phase that starts on a run-time
//! condition (ASAM OpenSCENARIO DSL 2.1 §8.9 `lane`, §8.9.1.1.1: the constraint "holds
//! throughout the phase"), where the plan does not know when x changes lanes. At a start the
//! plan knows, it gives the actor a sinusoidal LaneChangeAction over the span of each of x's
//! (the same shape as x's `change_lane`); here the engine does the same as x's changes begin.
//!
//! Whenever x's lane track (`world::lane_track`) shows a new lane on the road it was on with
//! a transition under way (x began a lane change: its LaneChangeAction, or a model's), the
//! actor's track takes the lane `value` lanes to the left of x's new lane in x's direction of
//! travel (as a RelativeTargetLane counts them), at its centre, from the lane and offset the
//! actor is at; from then on, every step after x's own action has stepped (the second pass of
//! the action stage, as `lateral_follow`), the actor's transition has x's weight and its rate
//! per metre, so the two move across by the same share of their changes at every step and,
//! where the lanes are as wide, cross their lanes' borders in the same step. When x's
//! transition ends, the actor's does. x on another road than it was (the lane ids of the next
//! road may differ) is read afresh there, not followed. Held until the phase's Act stops it.
//!
//! Several references (one per `lane(…: x)` of the invocation, in the modifiers' order): the
//! actor takes the lane counted from whichever reference just began a change, and mirrors
//! that reference's transition; a reference that begins one while another's is mirrored
//! takes over, from where the actor is (its transition then starts at the new reference's
//! weight). Where several begin in the same step the first of them in the list is followed
//! (oscsim's rule; the standard gives none: such relations that then disagree are
//! over-constrained, and the engine's held check of each reports the one that fails as an
//! `error` record and a failed run).
//!
//! A chain (car follows ego, who follows npc): the action stage steps the followings of lanes
//! last, each after those of the actors it follows (`ActionTable::step_all`), so car reads
//! ego's new lane and weight of the same step, whatever their order in the storyboard.

use scenario::{FollowedLane, SourcePos};

use super::Part;
use crate::error::Error;
use crate::position::lane_at;
use crate::store::targets::entity_ref;
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::world::entity::EntityId;
use crate::world::lane_track::Blend;
use crate::world::lanes::lane_shift;

/// A running following of other entities' lane changes on one actor.
#[derive(Debug, Clone)]
pub(crate) struct LaneFollowState {
    /// The entities followed, in the modifiers' order.
    references: Vec<Reference>,
    /// The index in `references` of the one whose change is being mirrored.
    mirroring: Option<usize>,
}

/// One entity followed.
#[derive(Debug, Clone)]
struct Reference {
    /// The entity.
    id: EntityId,
    /// Lanes to the left of its lane (0: its lane).
    shift: i32,
    /// Its road and lane at the last step.
    seen: Option<(String, i32)>,
}

impl LaneFollowState {
    /// The entities followed.
    pub(crate) fn references(&self) -> impl Iterator<Item = EntityId> + '_ {
        self.references.iter().map(|r| r.id)
    }
}

/// Starts following the lane changes of each of `followed` on an actor.
pub(crate) fn start(
    world: &World,
    followed: &[FollowedLane],
    pos: &SourcePos,
) -> Result<Part, Error> {
    let references = followed
        .iter()
        .map(|f| {
            let id = entity_ref(world, &f.entity_ref, pos)?;
            Ok(Reference {
                id,
                shift: f.value,
                seen: lane_of(world, id),
            })
        })
        .collect::<Result<_, Error>>()?;
    Ok(Part::LaneFollow(LaneFollowState {
        references,
        mirroring: None,
    }))
}

/// `id`'s road and lane on its lane track as the action starts, if it has one: a lane change
/// of its that begins in the same step (its transition at weight 0: started before this
/// action in the storyboard's order) counts from the lane it leaves, so that it is followed.
fn lane_of(world: &World, id: EntityId) -> Option<(String, i32)> {
    let t = world.entity(id).track.as_ref()?;
    let lane = match t.blend {
        Some(b) if b.weight == 0.0 => b.from_lane,
        _ => t.lane_id,
    };
    Some((t.road_id.clone(), lane))
}

/// One step: mirror a change of a reference's that began, or the one under way (module doc).
pub(crate) fn step(world: &mut World, actor: EntityId, s: &mut LaneFollowState) -> ActionStatus {
    // The first reference that began a change on its road in this step: its index, the lane
    // counted from its new one, its transition.
    let mut began: Option<(usize, i32, Blend)> = None;
    for (i, r) in s.references.iter_mut().enumerate() {
        let x = world.entity(r.id);
        if !x.placed {
            return ActionStatus::Stopped;
        }
        let Some(xt) = x.track.as_ref() else {
            continue;
        };
        let lane = xt.lane_id;
        // Compared in place: the road id is copied only when x's road or lane changed, not
        // at every step.
        let same_road = r.seen.as_ref().is_some_and(|(road, _)| *road == xt.road_id);
        let changed = !(same_road && r.seen.as_ref().is_some_and(|(_, l)| *l == lane));
        if changed {
            r.seen = Some((xt.road_id.clone(), lane));
        }
        if let (Some(b), true, true, None) = (xt.blend, changed, same_road, began) {
            began = Some((i, lane_shift(lane, r.shift, xt.direction), b));
        }
    }
    // The transition of the reference mirrored, as it stands after this step's.
    let mirrored = s
        .mirroring
        .and_then(|i| s.references.get(i))
        .and_then(|r| world.entity(r.id).track.as_ref())
        .map(|t| t.blend);
    let (net, e) = world.entity_on_network_mut(actor);
    let Some(track) = e.track.as_mut() else {
        return ActionStatus::Running;
    };
    match (began, mirrored) {
        (Some((i, target, b)), _) => {
            // From where the actor is: the lane holding its t and the offset there (as a
            // LaneChangeAction starts, `lane_change::begin`).
            let (from_lane, from_offset) = net
                .road(&track.road_id)
                .and_then(|r| lane_at(r, track.s, track.t))
                .unwrap_or((track.lane_id, track.offset));
            track.lane_id = target;
            track.offset = 0.0;
            track.blend = Some(Blend {
                from_lane,
                from_offset,
                weight: b.weight,
                weight_per_m: b.weight_per_m,
            });
            s.mirroring = Some(i);
        }
        (None, Some(Some(b))) => {
            if let Some(a) = &mut track.blend {
                a.weight = b.weight;
                a.weight_per_m = b.weight_per_m;
            }
        }
        (None, Some(None)) => {
            track.blend = None;
            s.mirroring = None;
        }
        (None, None) => {}
    }
    ActionStatus::Running
}
