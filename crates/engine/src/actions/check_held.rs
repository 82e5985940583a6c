//! oscsim's state check held over its phase (`scenario::StateCheck::throughout`, no XML form):
//! the OpenSCENARIO DSL runtime's constraints `at: all` of a phase whose place or end its plan
//! does not know (ASAM OpenSCENARIO DSL 2.1 §8.9 `at: all`: "the constraint holds throughout
//! the phase"), such as a `yaw` measured in the world (`check_heading`). The check runs when
//! the action starts, as any state check (`check::start`), and again in every step of stage 2
//! after it, in a pass before every other part (`ActionTable::step_all`), so on the actor and
//! every entity it names as the stage finds them, all at the step's start (the poses and
//! speeds the last step gave them; before, a reference whose SpeedAction came earlier in slot
//! order was read at the step's end), until the action is stopped: its phase's Act ending
//! stops it. A failure ends the action and is the
//! step's failure: an error record in the event log and a failed run.
//!
//! With `track: projected` (`StateCheck::projected`, §8.9.1.1.3: the reference "projected"
//! from its state at the phase start) the entity of its gap or lane count is recorded when the
//! check starts (`condition::Projection`: its road, lane, s and speed then) and read at every
//! later step as projected from there: along that lane's centre line at that speed, in the
//! check's measure (`position::RoadChain`: the plan's s, u along the direction of travel of an
//! actor driving against s, the projection along the entity's own direction of travel), the
//! gap at that speed, the lane counted from that lane in its direction of travel then, a t
//! beside it (`StateCheck::beside`) from its t then (the DSL plan's reading at a known start).

use opendrive::Direction;
use scenario::{SourcePos, StateCheck};

use super::check::{self, CheckRefs};
use crate::condition::Projection;
use crate::error::Error;
use crate::position::RoadChain;
use crate::store::World;
use crate::storyboard::ActionStatus;
use crate::world::lanes::lane_shift;
use crate::EntityId;

/// A state check held from its start until its action is stopped.
#[derive(Debug, Clone)]
pub(crate) struct HeldCheck {
    /// What it requires (with a projection: all but the gap and lane count read from it).
    check: Box<StateCheck>,
    /// The entities it names, by id (resolved when the storyboard was built).
    refs: CheckRefs,
    /// With `track: projected`: the entity of the gap, lane count or t beside, projected from
    /// the start.
    projection: Option<Projected>,
    /// Where it is written.
    pos: SourcePos,
    /// Why it failed, once it has.
    pub failure: Option<Error>,
}

/// What a projected check reads from its entity's projection.
#[derive(Debug, Clone)]
struct Projected {
    /// The entity's name.
    name: String,
    /// The entity as it was at the start.
    from: Projection,
    /// The gap (`StateCheck::gap`) measured from it.
    gap: Option<(scenario::SpeedGap, f64)>,
    /// The lane count (`StateCheck::lane_of`) from its lane then.
    lane_of: Option<i32>,
    /// The actor's t minus the entity's then (`StateCheck::beside`, m, positive left), the
    /// tolerance (m), and the entity's t then (m).
    beside: Option<(f64, f64, f64)>,
}

impl HeldCheck {
    /// `check` (written at `pos`; `refs`: the entities it names), which held at its start
    /// `time`; with `track: projected` the entity it relates to is recorded now. `Err` where
    /// that entity is off every lane.
    pub(super) fn new(
        world: &World,
        (check, refs): (&StateCheck, &CheckRefs),
        (time, pos): (f64, &SourcePos),
    ) -> Result<Self, Error> {
        let mut held = check.clone();
        let projection = match check.projected {
            false => None,
            true => {
                let gap = held.gap.take();
                let lane_of = held.lane_of.take();
                let beside = held.beside.take();
                let of = gap
                    .as_ref()
                    .map(|(g, _)| (g.entity_ref.clone(), refs.gap()))
                    .or(lane_of.as_ref().map(|(x, _)| (x.clone(), refs.lane_of())))
                    .or(beside.as_ref().map(|(x, _, _)| (x.clone(), refs.beside())));
                match of {
                    None => None,
                    Some((x, id)) => {
                        let from = id.and_then(|o| check::projection(world, o, time));
                        let Some(mut from) = from else {
                            let fail = check::failure(check, time);
                            let want = format!("'{x}' on a lane to project it from");
                            return Err(fail(want, "it off every lane".into()));
                        };
                        // Its lane then: the one its reference point is in (its track's
                        // may already be the target of a lane change starting now).
                        let there = id.map(|o| world.entity(o));
                        let at = there.and_then(|o| o.road_position.as_ref());
                        if let Some(p) = at {
                            from.lane = p.lane_id;
                        }
                        let lane_of = lane_of.map(|(_, n)| n);
                        // x's t then (the start check found x on a road beside the actor).
                        let t_x = at.map_or(0.0, |p| p.t);
                        let beside = beside.map(|(_, dt, tol)| (dt, tol, t_x));
                        Some(Projected {
                            name: x,
                            from,
                            gap,
                            lane_of,
                            beside,
                        })
                    }
                }
            }
        };
        Ok(Self {
            check: Box::new(held),
            refs: *refs,
            projection,
            pos: pos.clone(),
            failure: None,
        })
    }
}

/// Checks `held` on `actor` at `now`: running while it holds, ended with its failure noted
/// once it does not.
pub(super) fn step(world: &World, actor: EntityId, held: &mut HeldCheck, now: f64) -> ActionStatus {
    let checked = check::require(world, actor, (&held.check, &held.refs), (now, &held.pos))
        .and_then(|()| match &held.projection {
            Some(p) => require_projected(world, actor, &held.check, p, now),
            None => Ok(()),
        });
    match checked {
        Ok(()) => ActionStatus::Running,
        Err(e) => {
            held.failure = Some(e);
            ActionStatus::Ended
        }
    }
}

/// The gap and lane of `p` on `actor` at `now`, its entity read as projected from the start
/// (module doc); `check` gives the roads and what is checked.
fn require_projected(
    world: &World,
    actor: EntityId,
    check: &StateCheck,
    p: &Projected,
    now: f64,
) -> Result<(), Error> {
    let e = world.entity(actor);
    let fail = check::failure(check, now);
    let x = &p.from;
    let chain = RoadChain::new(&world.network, &check.roads);
    let Some(at) = e.road_position.as_ref() else {
        return Err(fail(
            format!("'{}' on a road", e.name),
            "it off every road".into(),
        ));
    };
    // On one road the actor on x's road then; on a plan over several roads on any of them.
    let on = chain.is_chain() || at.road_id == x.road;
    if let Some(shift) = p.lane_of {
        let direction = match x.forward {
            true => Direction::Forward,
            false => Direction::Backward,
        };
        let lane = lane_shift(x.lane, shift, direction);
        if !on || chain.s_of(&at.road_id, at.s).is_none() || at.lane_id != lane {
            return Err(fail(
                format!(
                    "'{}' in lane {lane} of {}, counted from lane {} of the entity projected from {:.3} s",
                    e.name,
                    chain.roads_or(&x.road),
                    x.lane,
                    x.time
                ),
                format!("it in lane {} of road {}", at.lane_id, at.road_id),
            ));
        }
    }
    // Beside x projected: x's t at the start (along its lane, as the plan reads it).
    if let Some((dt, tol, t_x)) = p.beside {
        let got = chain.left(at.t - t_x);
        if !on || (got - dt).abs() > tol {
            return Err(fail(
                format!(
                    "'{}' {dt:.3} m to the left of where '{}' was across the road at {:.3} s (within {tol} m)",
                    e.name, p.name, x.time
                ),
                format!("{got:.3} m on road {}", at.road_id),
            ));
        }
    }
    if let Some((g, tol)) = &p.gap {
        let there = x.s_at(chain, now);
        let here = chain.s_of(&at.road_id, at.s).filter(|_| on);
        let (Some(there), Some(here)) = (there, here) else {
            return Err(fail(
                format!(
                    "'{}' and '{}' projected from {:.3} s on {}",
                    e.name,
                    g.entity_ref,
                    x.time,
                    chain.roads_or(&x.road)
                ),
                format!(
                    "'{}' on road {}, or the projection past its lane",
                    e.name, at.road_id
                ),
            ));
        };
        // x − actor along the road, at x's speed at the start.
        let gap = -g.offset(x.speed);
        let got = there - here;
        if (got - gap).abs() > *tol {
            return Err(fail(
                format!(
                    "'{}' projected from {:.3} s at {:.3} m/s {gap:.3} m from '{}' {} (within {tol} m)",
                    g.entity_ref,
                    x.time,
                    x.speed,
                    e.name,
                    chain.along()
                ),
                format!("{got:.3} m"),
            ));
        }
    }
    Ok(())
}
