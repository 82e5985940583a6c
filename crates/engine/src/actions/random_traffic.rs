//! oscsim's creation of random traffic ([`scenario::PrivateAction::CreateRandomTraffic`], no
//! XML form; ASAM OpenSCENARIO DSL 2.1 §8.7.18.1, non-normative: "the group defines the
//! initial conditions of actors in the scenario, meaning their creation and destruction"):
//! the DSL runtime writes it where its plan does not know every other vehicle's place when a
//! `random_traffic_vehicle_group` is created (after a run-time condition, or beside a vehicle
//! the engine moves). Instantaneous.
//!
//! When it starts it reads every other entity in the world where it is then, and deals the
//! members it names by the rule the plan uses ([`scenario::traffic_deal`]) over the lanes it
//! carries, with the draws of its seed; then it puts each member there (as a TeleportAction of
//! a story: held over this step, so the step's frame shows it there), at rest. The start
//! speeds and drivers are the actions after it (the plan's SpeedAction and
//! ActivateControllerAction of each member).
//!
//! Where an entity counts: on one of the action's roads, by its road position, in the lane
//! it is in, its box along the lane's direction of travel (a distance u = L − s against s),
//! its front the side it faces; elsewhere, or not in the world, it takes no room. No room for
//! every member: an error in the plan's words ("expected room on the plan's driving lanes for
//! …, found room for n"), which fails the run.

use scenario::traffic_deal::{self, Dealt, LaneSpan, Member, Occupant};
use scenario::{Position, PositionKind, RandomTrafficCreation, SourcePos};

use super::teleport;
use crate::error::Error;
use crate::store::World;

/// Deals and places the members of `c` among the entities in `world` now (module doc).
pub(crate) fn start(
    world: &mut World,
    c: &RandomTrafficCreation,
    pos: &SourcePos,
) -> Result<(), Error> {
    let mut ids = Vec::with_capacity(c.members.len());
    for (m, _) in &c.members {
        let id = world
            .id(m)
            .ok_or_else(|| Error::at("a declared entity", format!("'{m}'"), pos))?;
        ids.push(id);
    }
    let others: Vec<Occupant> = world
        .entities()
        .iter()
        .filter(|e| e.placed && !ids.contains(&e.id))
        .filter_map(|e| occupant(c, e))
        .collect();
    let spans = match &c.beside {
        Some((x, by)) => beside(world, c, x, *by, pos)?,
        None => c.lanes.clone(),
    };
    let members: Vec<Member> = ids
        .iter()
        .map(|&id| {
            let b = world.entity(id).bounding_box;
            Member {
                length: b.length(),
                rear: b.length() / 2.0 - b.center().x,
            }
        })
        .collect();
    let speeds: Vec<f64> = c.members.iter().map(|m| m.1).collect();
    let mut draws = traffic_deal::Draws::new(c.seed);
    let dealt = traffic_deal::deal(&spans, &others, &members, &speeds, &mut || draws.uniform())
        .map_err(|e| {
            let (expected, found) = e.message(c.members.len(), &c.group);
            Error::at(expected, found, pos)
        })?;
    for d in dealt {
        let position = lane_position(c, &d, pos);
        teleport::start(world, ids[d.member], &position, true)?;
        world.entity_mut(ids[d.member]).speed = 0.0;
    }
    Ok(())
}

/// Entity `e` as the dealing counts it, if it is in a lane of one of `c`'s roads.
fn occupant(c: &RandomTrafficCreation, e: &crate::world::entity::Entity) -> Option<Occupant> {
    let rp = e.road_position.as_ref()?;
    let start = c.roads.iter().find(|r| r.0 == rp.road_id)?.1;
    // Right-hand traffic (OpenDRIVE 1.8 §11.2): the left side's lanes are driven in −s.
    let against = rp.lane_id > 0;
    let s = start + rp.s;
    let u = if against { c.length - s } else { s };
    // Front and rear along the lane's direction of travel: ahead of the reference point by
    // the box's front where the entity faces that way.
    let b = e.bounding_box;
    let (front, rear) = (
        b.center().x + b.length() / 2.0,
        b.length() / 2.0 - b.center().x,
    );
    let faces_travel = (rp.relative_heading.cos() >= 0.0) != against;
    let (ahead, behind) = if faces_travel {
        (front, rear)
    } else {
        (rear, front)
    };
    Some(Occupant {
        against,
        lane: rp.lane_id,
        rear: u - behind,
        front: u + ahead,
        speed: e.speed.abs(),
    })
}

/// The spans of `c` in the lane `by` lanes to the left (right when negative) of entity `x`'s
/// lane now, in x's direction of travel (lane ids counted as a RelativeTargetLane counts them:
/// to the left in +s is towards the centre line, −2 → −1; against s, 2 → 1); none there is
/// the error.
fn beside(
    world: &World,
    c: &RandomTrafficCreation,
    x: &str,
    by: i64,
    pos: &SourcePos,
) -> Result<Vec<LaneSpan>, Error> {
    let at = world
        .id(x)
        .map(|id| world.entity(id))
        .filter(|e| e.placed)
        .and_then(|e| e.road_position.as_ref())
        .filter(|rp| c.roads.iter().any(|r| r.0 == rp.road_id));
    let Some(rp) = at else {
        return Err(Error::at(
            format!(
                "'{x}' on the plan's roads when random traffic `{}` is created beside it",
                c.group
            ),
            "it elsewhere",
            pos,
        ));
    };
    let against = rp.lane_id > 0;
    let step = if against { -1 } else { 1 };
    let lane = i64::from(rp.lane_id) + by * step;
    let spans: Vec<LaneSpan> = c
        .lanes
        .iter()
        .filter(|l| l.against == against && i64::from(l.lane) == lane)
        .copied()
        .collect();
    if spans.is_empty() || lane == 0 || (lane > 0) != against {
        return Err(Error::at(
            format!(
                "a driving lane {} lanes to the {} of '{x}''s lane {} for random traffic `{}`",
                by.abs(),
                if by > 0 { "left" } else { "right" },
                rp.lane_id,
                c.group
            ),
            "none there",
            pos,
        ));
    }
    Ok(spans)
}

/// The LanePosition of `d` on `c`'s roads: the road holding its s (the later one in its
/// direction of travel at a joint), the s on it.
fn lane_position(c: &RandomTrafficCreation, d: &Dealt, pos: &SourcePos) -> Position {
    let s = if d.against { c.length - d.s } else { d.s };
    let k = if d.against {
        c.roads
            .iter()
            .position(|r| s <= r.1 + length_of(c, r))
            .unwrap_or(c.roads.len().saturating_sub(1))
    } else {
        c.roads.iter().rposition(|r| r.1 <= s).unwrap_or(0)
    };
    let (road_id, start) = c.roads.get(k).cloned().unwrap_or_default();
    Position {
        kind: PositionKind::Lane {
            road_id,
            lane_id: d.lane.to_string(),
            s: (s - start).max(0.0),
            offset: Some(0.0),
            orientation: None,
        },
        pos: pos.clone(),
    }
}

/// The length of road `r` of `c` (m): to the next road's start, the last to `c.length`.
fn length_of(c: &RandomTrafficCreation, r: &(String, f64)) -> f64 {
    let next = c
        .roads
        .iter()
        .map(|q| q.1)
        .filter(|&q| q > r.1)
        .fold(c.length, f64::min);
    next - r.1
}
