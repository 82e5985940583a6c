//! oscsim's state check (`scenario::PrivateAction::Check`, no XML form): the OpenSCENARIO DSL
//! runtime's `at: start` constraints of a phase that starts on a run-time condition (ASAM
//! OpenSCENARIO DSL 2.1 §8.9), which its plan cannot decide before the run. When the action
//! starts, the actor's road position (the one measured at the step's start, as every trigger
//! of the step sees it) must be in the lane, at the offset (from the lane's centre, or from a
//! border of the lane as wide as it is there), with a place beside another entity in a
//! driving lane or across a straight line beside another entity's box (`across_line`: the
//! DSL's `lateral(…)` beside x of a walk along a crossing), and at the distance to another
//! entity it gives (or in the lane given relative to another entity's), at the speed it gives
//! (absolute or another entity's plus a value) and that far from a mark noted before (its
//! odometer), a linear speed change starting with it must fit the vehicle's Performance,
//! which SpeedAction would otherwise meet by stretching the change in time
//! (`speed::least_time`), and an acceleration held over a time must keep the speed within 0
//! and the maximum (where the AccelerationAction would end, the vehicle standing or at its top
//! speed); otherwise it fails: an error record in the event log, and the run
//! stops with [`ErrorKind::CheckFailed`](crate::ErrorKind::CheckFailed). A check that holds
//! then notes its mark, if it has one (the actor's odometer and, with a gap, its side of the
//! place the gap asks for: `condition::mark`). The DSL runtime also runs checks at a phase's
//! end, for a constraint that holds there only if the run happens to meet it, and checks held
//! over a phase (`check_held`). The actor's heading, measured in the world or from another
//! entity, is `check_heading`'s. Places are
//! measured as the check's `roads` say (`position::RoadChain`): on the actor's road in its s,
//! on a plan over several roads in the plan's s, and for an actor driving the roads against s
//! along its direction of travel (u = L − s, t and offsets to its left), the plan's numbers.

use opendrive::{Direction, RoadPosition};
use scenario::{AcrossLine, HeadingFrom, RateWithin, SourcePos, SpeedTarget, StateCheck};

use super::lane_change::side_lane;
use super::speed;

use crate::condition::{place_error, Mark, MarkId, MarkIds, Projection};
use crate::error::{Error, ErrorKind};
use crate::position::RoadChain;
use crate::store::World;
use crate::world::lanes::lane_shift;
use crate::world::shapes::peak_slope;
use crate::EntityId;

/// The entities a state check names, resolved to their ids once, when the storyboard is built
/// (`runtime::build`, through [`super::ActionTable::push`]): a check, and a held one at every
/// step, reads each entity by its id, never looking its name up again. `None` where the check
/// names no entity.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct CheckRefs {
    /// `StateCheck::lane_of`'s entity.
    lane_of: Option<EntityId>,
    /// `StateCheck::gap`'s entity.
    gap: Option<EntityId>,
    /// `StateCheck::beside`'s entity.
    beside: Option<EntityId>,
    /// `StateCheck::beside_in_lane`'s entity.
    beside_in_lane: Option<EntityId>,
    /// `StateCheck::across_line`'s entity.
    across_line: Option<EntityId>,
    /// The entity whose speed `StateCheck::speed` adds to.
    speed: Option<EntityId>,
    /// The entity `StateCheck::heading` is measured from.
    heading: Option<EntityId>,
    /// The entity of the gap of `StateCheck::mark`.
    mark_gap: Option<EntityId>,
    /// The slot of the mark the check notes (`StateCheck::mark`).
    mark: Option<MarkId>,
    /// The slot of the mark `StateCheck::travelled` measures from.
    travelled: Option<MarkId>,
    /// The slot of the mark `StateCheck::lane_at_mark` counts from.
    lane_at_mark: Option<MarkId>,
}

impl CheckRefs {
    /// The entities `check`, the action written at `pos`, names, by their ids in `world`: an
    /// entity the scenario does not declare is an error at the check (a load error, as an
    /// undeclared `entityRef` of any action is). The entities of its speed targets
    /// (`speed_change`, `speed_at_rate`) are read when it runs, as a SpeedAction's are
    /// (`speed::target_speed`), and must be declared too. The marks it notes and reads get
    /// their slots in `marks` (`condition::MarkIds`), so that no step looks a mark up by name.
    pub(crate) fn resolve(
        (world, marks): (&World, &mut MarkIds),
        check: &StateCheck,
        pos: &SourcePos,
    ) -> Result<Self, Error> {
        let id = |name: Option<&str>| {
            name.map(|n| {
                world.id(n).ok_or_else(|| {
                    Error::at(
                        format!("a declared entity for {}", check.what),
                        format!("'{n}'"),
                        pos,
                    )
                })
            })
            .transpose()
        };
        let targets = [
            check.speed_change.as_ref().map(|c| &c.0),
            check.speed_at_rate.as_ref().map(|c| &c.0),
        ];
        for target in targets.into_iter().flatten() {
            if let SpeedTarget::Relative { entity_ref, .. }
            | SpeedTarget::RelativeAtStart { entity_ref, .. } = target
            {
                id(Some(entity_ref))?;
            }
        }
        Ok(Self {
            lane_of: id(check.lane_of.as_ref().map(|x| x.0.as_str()))?,
            gap: id(check.gap.as_ref().map(|g| g.0.entity_ref.as_str()))?,
            beside: id(check.beside.as_ref().map(|x| x.0.as_str()))?,
            beside_in_lane: id(check.beside_in_lane.as_ref().map(|x| x.0.as_str()))?,
            across_line: id(check.across_line.as_ref().map(|a| a.entity_ref.as_str()))?,
            speed: id(check.speed.as_ref().and_then(|x| x.0.as_deref()))?,
            heading: id(match check.heading.as_ref().map(|h| &h.from) {
                Some(HeadingFrom::Entity(x)) => Some(x.as_str()),
                _ => None,
            })?,
            mark_gap: id(check
                .mark
                .as_ref()
                .and_then(|m| m.gap.as_ref())
                .map(|g| g.entity_ref.as_str()))?,
            mark: check.mark.as_ref().map(|m| marks.id(&m.name)),
            travelled: check.travelled.as_ref().map(|t| marks.id(&t.0)),
            lane_at_mark: check.lane_at_mark.as_ref().map(|l| marks.id(&l.0)),
        })
    }

    /// The entity of the gap (`StateCheck::gap`).
    pub(super) fn gap(&self) -> Option<EntityId> {
        self.gap
    }

    /// The entity of the lane count (`StateCheck::lane_of`).
    pub(super) fn lane_of(&self) -> Option<EntityId> {
        self.lane_of
    }

    /// The entity of the place across the road (`StateCheck::beside`).
    pub(super) fn beside(&self) -> Option<EntityId> {
        self.beside
    }
}

/// Checks `check` on `actor` at `time` (`pos`: where the check is written; `refs`: the
/// entities it names), then notes its mark if it has one.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    (check, refs): (&StateCheck, &CheckRefs),
    (time, pos): (f64, &SourcePos),
) -> Result<(), Error> {
    require(world, actor, (check, refs), (time, pos))?;
    if let Some(mark) = &check.mark {
        let e = world.entity(actor);
        let chain = RoadChain::new(&world.network, &check.roads);
        let gap_error = match &mark.gap {
            Some(gap) => {
                let other = refs.mark_gap.map(|o| world.entity(o));
                let place = match (e.road_position.as_ref(), other) {
                    (Some(a), Some(o)) => o
                        .road_position
                        .as_ref()
                        .and_then(|x| place_error(chain, a, x, o.speed, gap)),
                    _ => None,
                };
                // Without a place on x's road the gap can never be reached: an error now, not
                // a phase that never ends.
                let Some(place) = place else {
                    let on = match chain.is_chain() {
                        true => format!("with '{}' on {}", gap.entity_ref, chain.describe()),
                        false => format!("on the road of '{}'", gap.entity_ref),
                    };
                    return Err(Error::new(ErrorKind::CheckFailed {
                        what: check.what.clone(),
                        expected: format!("'{}' {on}", e.name),
                        found: "it elsewhere".into(),
                        time,
                    }));
                };
                Some(place)
            }
            None => None,
        };
        // Projected: the gap's entity along its lane at its speed now.
        let projection = match (&mark.gap, mark.projected) {
            (Some(_), true) => refs.mark_gap.and_then(|o| projection(world, o, time)),
            _ => None,
        };
        if let (Some(gap), true, None) = (&mark.gap, mark.projected, &projection) {
            return Err(Error::new(ErrorKind::CheckFailed {
                what: check.what.clone(),
                expected: format!("'{}' on a lane", gap.entity_ref),
                found: "it off every lane".into(),
                time,
            }));
        }
        let odometer = e.odometer;
        let lane = e
            .road_position
            .as_ref()
            .map(|p| (p.road_id.clone(), p.lane_id));
        if let Some(id) = refs.mark {
            world.marks.note(
                id,
                Mark {
                    odometer,
                    lane,
                    gap_error,
                    projection,
                    roads: check.roads.clone(),
                },
            );
        }
    }
    Ok(())
}

/// Entity `id` projected from `time` on (ASAM OpenSCENARIO DSL 2.1 §8.9.1.1.3 `track:
/// projected`): its lane, s and speed now (`None`: off every lane).
pub(super) fn projection(world: &World, id: EntityId, time: f64) -> Option<Projection> {
    let o = world.entity(id);
    let t = o.track.as_ref()?;
    Some(Projection {
        road: t.road_id.clone(),
        lane: t.lane_id,
        s: t.s,
        speed: o.speed,
        forward: t.direction == Direction::Forward,
        time,
    })
}

/// The failure of `check` at `time`: what was expected, what was found.
pub(super) fn failure(check: &StateCheck, time: f64) -> impl Fn(String, String) -> Error + '_ {
    move |expected, found| {
        Error::new(ErrorKind::CheckFailed {
            what: check.what.clone(),
            expected,
            found,
            time,
        })
    }
}

/// Entity `id` as `refs` resolved it for `name` (`CheckRefs::resolve`: always there for a
/// check the storyboard was built with), else the check's failure `fail` naming it.
fn resolved(
    id: Option<EntityId>,
    name: &str,
    fail: &dyn Fn(String, String) -> Error,
) -> Result<EntityId, Error> {
    id.ok_or_else(|| fail(format!("'{name}' in the scenario"), "no such entity".into()))
}

/// The requirements of `check` on `actor` at `time` (`refs`: the entities it names).
pub(super) fn require(
    world: &World,
    actor: EntityId,
    (check, refs): (&StateCheck, &CheckRefs),
    (time, pos): (f64, &SourcePos),
) -> Result<(), Error> {
    let e = world.entity(actor);
    let fail = failure(check, time);
    super::check_heading::require(world, e, (check, refs.heading), &fail)?;
    // The change must run as written: the SpeedAction would stretch a faster one in time.
    if let (Some((target, shape, within)), Some(perf)) = (&check.speed_change, e.performance) {
        let v1 = speed::target_speed(world, target, pos)?;
        let least = speed::least_time(&perf, *shape, e.speed, v1);
        if least > within + crate::tolerance::TIME {
            let limit = if v1 >= e.speed {
                perf.max_acceleration
            } else {
                perf.max_deceleration
            };
            return Err(fail(
                format!(
                    "'{}''s speed from {:.3} to {v1:.3} m/s within {within:.3} s at the vehicle's {:.3} m/s² or less",
                    e.name,
                    e.speed,
                    limit.abs(),
                ),
                format!("it needs {:.3} m/s²", peak_slope(*shape) * (v1 - e.speed).abs() / within),
            ));
        }
    }
    // At a rate the change takes |v1 − v| / a and covers |v1² − v²| / (2a), which must end
    // within the phase: its length, or the distance that ends it.
    if let Some((target, rate, within)) = &check.speed_at_rate {
        let v1 = speed::target_speed(world, target, pos)?;
        let (needed, limit, unit, tol) = match *within {
            RateWithin::Time(t) => ((v1 - e.speed).abs() / rate, t, "s", crate::tolerance::TIME),
            RateWithin::Distance(d) => (
                (v1 * v1 - e.speed * e.speed).abs() / (2.0 * rate),
                d,
                "m",
                crate::tolerance::LENGTH,
            ),
        };
        if needed > limit + tol {
            return Err(fail(
                format!(
                    "'{}''s speed from {:.3} to {v1:.3} m/s at {rate:.3} m/s² within {limit:.3} {unit}",
                    e.name, e.speed,
                ),
                format!("it needs {needed:.3} {unit}"),
            ));
        }
    }
    // Held over the phase the acceleration must keep the speed within 0 and the maximum: the
    // AccelerationAction would end there, the acceleration 0 for the rest of the phase.
    if let Some((a, within)) = check.held_acceleration {
        let max = e.performance.map_or(f64::INFINITY, |p| p.max_speed.abs());
        let (v0, v1) = (e.speed, e.speed + a * within);
        let bound = if v1 < 0.0 { 0.0 } else { max };
        if (v1 < -crate::tolerance::SPEED || v1 > max + crate::tolerance::SPEED) && a != 0.0 {
            return Err(fail(
                format!(
                    "'{}''s speed from {v0:.3} m/s at {a:.3} m/s² for {within:.3} s within 0 and {max:.3} m/s",
                    e.name,
                ),
                format!(
                    "it reaches {bound:.3} m/s after {:.3} s ({v1:.3} m/s at the end)",
                    (bound - v0) / a
                ),
            ));
        }
    }
    if let Some((other, value, tol)) = &check.speed {
        let base = match other {
            Some(o) => world.entity(resolved(refs.speed, o, &fail)?).speed,
            None => 0.0,
        };
        let want = base + value;
        if (e.speed - want).abs() > *tol {
            let of = other.as_ref().map_or(String::new(), |o| {
                format!(" ('{o}''s {base:.3} m/s {value:+.3} m/s)")
            });
            return Err(fail(
                format!("'{}' at {want:.3} m/s{of} (within {tol} m/s)", e.name),
                format!("it at {:.3} m/s", e.speed),
            ));
        }
    }
    if let Some((mark, d, tol)) = &check.travelled {
        let Some(m) = refs.travelled.and_then(|id| world.marks.get(id)) else {
            return Err(fail(format!("the mark '{mark}' noted"), "none".into()));
        };
        let got = e.odometer - m.odometer;
        if (got - d).abs() > *tol {
            return Err(fail(
                format!(
                    "'{}' {d:.3} m travelled since the phase start (within {tol} m)",
                    e.name
                ),
                format!("{got:.3} m"),
            ));
        }
    }
    if let Some(a) = &check.across_line {
        require_across(world, e, (a, refs.across_line), &fail)?;
    }
    let places = check.lane.is_some()
        || check.lane_of.is_some()
        || check.lane_at_mark.is_some()
        || check.s.is_some()
        || check.offset.is_some()
        || check.offset_in_width.is_some()
        || check.beside_in_lane.is_some()
        || check.gap.is_some()
        || check.beside.is_some();
    if !places {
        return Ok(());
    }
    let Some(at) = e.road_position.as_ref() else {
        return Err(fail(
            format!("'{}' on a road", e.name),
            "it off every road".into(),
        ));
    };
    // Where along the plan's roads (a road's s plus its start), or the road's own s; against
    // s along the direction of travel (u = L − s, t and offsets to the actor's left).
    let chain = RoadChain::new(&world.network, &check.roads);
    let along = |p: &RoadPosition| chain.s_of(&p.road_id, p.s);
    if let Some((road, lane)) = &check.lane {
        let on_road = match chain.is_chain() {
            false => at.road_id == *road,
            true => along(at).is_some(),
        };
        if !on_road || at.lane_id != *lane {
            let of = chain.roads_or(road);
            return Err(fail(
                format!("'{}' in lane {lane} of {of}", e.name),
                format!("it in lane {} of road {}", at.lane_id, at.road_id),
            ));
        }
    }
    if let Some((other, shift)) = &check.lane_of {
        let there = refs.lane_of.map(|o| world.entity(o));
        let Some((rp, track)) = there.and_then(|o| o.road_position.as_ref().zip(o.track.as_ref()))
        else {
            return Err(fail(
                format!("'{other}' on a lane"),
                format!("'{other}' off the road"),
            ));
        };
        let lane = lane_shift(rp.lane_id, *shift, track.direction);
        // On one road both on it; on a plan over several roads on any of them (the lane ids
        // are the same on each).
        if chain.pair(at, rp).is_none() || at.lane_id != lane {
            let of = chain.roads_or(&rp.road_id);
            return Err(fail(
                format!(
                    "'{}' in lane {lane} of {of}, {}'{other}''s lane {}",
                    e.name,
                    match shift {
                        0 => String::new(),
                        n => format!(
                            "{} lane{} to the {} of ",
                            n.abs(),
                            if n.abs() == 1 { "" } else { "s" },
                            if *n > 0 { "left" } else { "right" }
                        ),
                    },
                    rp.lane_id
                ),
                format!("it in lane {} of road {}", at.lane_id, at.road_id),
            ));
        }
    }
    if let Some((mark, shift)) = &check.lane_at_mark {
        let noted = refs.lane_at_mark.and_then(|id| world.marks.get(id));
        let Some((road, from)) = noted.and_then(|m| m.lane.as_ref().map(|(r, l)| (r, *l))) else {
            return Err(fail(
                format!("the mark '{mark}' noted on a lane"),
                "none".into(),
            ));
        };
        let direction = e.track.as_ref().map_or(Direction::Forward, |t| t.direction);
        let lane = lane_shift(from, *shift, direction);
        if at.road_id != *road || at.lane_id != lane {
            let of = match shift {
                0 => "its lane at the phase start".to_string(),
                n => format!(
                    "{} lane{} to the {} of its lane {from} at the phase start",
                    n.abs(),
                    if n.abs() == 1 { "" } else { "s" },
                    if *n > 0 { "left" } else { "right" }
                ),
            };
            return Err(fail(
                format!("'{}' in lane {lane} of road {road}, {of}", e.name),
                format!("it in lane {} of road {}", at.lane_id, at.road_id),
            ));
        }
    }
    if let Some((s, tol)) = check.s {
        let Some(got) = along(at) else {
            return Err(fail(
                format!("'{}' on {}", e.name, chain.describe()),
                format!("it on road {}", at.road_id),
            ));
        };
        if (got - s).abs() > tol {
            return Err(fail(
                format!("'{}' at {} (within {tol} m)", e.name, chain.place(s)),
                format!("it at {}", chain.place(got)),
            ));
        }
    }
    // Offsets to the left of the direction of travel (against s: −the road's).
    let offset_left = chain.left(at.offset);
    if let Some((offset, tol)) = check.offset {
        if (offset_left - offset).abs() > tol {
            return Err(fail(
                format!(
                    "'{}' {offset:.3} m from its lane's centre (within {tol} m)",
                    e.name
                ),
                format!("it {offset_left:.3} m from it"),
            ));
        }
    }
    // From a border: the lane's width where the actor is.
    if let Some((k, c, tol)) = check.offset_in_width {
        let width = world
            .network
            .lane_width(&at.road_id, at.lane_id, at.s)
            .unwrap_or(0.0);
        let offset = k * width + c;
        if (offset_left - offset).abs() > tol {
            return Err(fail(
                format!(
                    "'{}' {offset:.3} m from the centre of its lane {width:.3} m wide (within {tol} m)",
                    e.name
                ),
                format!("it {offset_left:.3} m from it"),
            ));
        }
    }
    // Another entity on the actor's road (on a plan over several roads on any of them): its
    // road position and speed.
    let beside = |other: &str, id: Option<EntityId>| {
        id.map(|o| world.entity(o))
            .and_then(|o| Some((o.road_position.as_ref()?, o.speed)))
            .filter(|(p, _)| chain.pair(at, p).is_some())
            .ok_or_else(|| {
                let of = chain.roads_or(&at.road_id);
                fail(
                    format!("'{other}' on {of} beside '{}'", e.name),
                    format!("'{other}' elsewhere"),
                )
            })
    };
    // x's t beside the actor's: each on its own road, one measure where the reference lines
    // of the roads between them join continuously.
    let beside_t = |other: &str, id: Option<EntityId>| {
        let (there, _) = beside(other, id)?;
        chain
            .lateral_compares(&at.road_id, &there.road_id)
            .map_err(|want| fail(want, format!("'{other}' on road {}", there.road_id)))?;
        Ok::<_, Error>(there)
    };
    if let Some((other, dt, tol)) = &check.beside {
        let there = beside_t(other, refs.beside)?;
        let got = chain.left(at.t - there.t);
        if (got - dt).abs() > *tol {
            return Err(fail(
                format!(
                    "'{}' {dt:.3} m to the left of '{other}' across the road (within {tol} m)",
                    e.name
                ),
                format!("{got:.3} m"),
            ));
        }
    }
    if let Some((other, dt)) = &check.beside_in_lane {
        let there = beside_t(other, refs.beside_in_lane)?;
        let t = there.t + chain.left(*dt);
        let road = world.network.road(&at.road_id);
        let lane = road
            .zip(e.track.as_ref())
            .and_then(|(r, k)| side_lane(r, k, t));
        if lane.is_none() {
            return Err(fail(
                format!(
                    "'{}''s place {:.3} m to the {} of '{other}' in a driving lane of its side of road {}",
                    e.name,
                    dt.abs(),
                    if *dt > 0.0 { "left" } else { "right" },
                    at.road_id
                ),
                format!("t = {t:.3} m at s = {:.3} m, off them", at.s),
            ));
        }
    }
    if let Some((g, tol)) = &check.gap {
        let other = &g.entity_ref;
        // On a plan over several roads x may be on another of them: the plan's s of both.
        let (there_s, speed) = match chain.is_chain() {
            false => beside(other, refs.gap).map(|(there, v)| (along(there), v))?,
            true => refs
                .gap
                .map(|o| world.entity(o))
                .and_then(|o| Some((along(o.road_position.as_ref()?), o.speed)))
                .filter(|(s, _)| s.is_some())
                .ok_or_else(|| {
                    fail(
                        format!("'{other}' on {}", chain.describe()),
                        format!("'{other}' elsewhere"),
                    )
                })?,
        };
        let (Some(there_s), Some(at_s)) = (there_s, along(at)) else {
            return Err(fail(
                format!("'{}' on {}", e.name, chain.describe()),
                format!("it on road {}", at.road_id),
            ));
        };
        // x − actor along the road, at x's speed now.
        let gap = -g.offset(speed);
        let got = there_s - at_s;
        if (got - gap).abs() > *tol {
            return Err(fail(
                format!(
                    "'{other}' {gap:.3} m from '{}' {} (within {tol} m)",
                    e.name,
                    chain.along()
                ),
                format!("{got:.3} m"),
            ));
        }
    }
    Ok(())
}

/// `e`'s place across a straight line beside another entity (`StateCheck::across_line`): its
/// reference point across the line, from the middle of the entity's box across it (the box's
/// footprint, turned to its heading now, projected on the line's normal), against
/// `per_extent`·extent + `offset` (`id`: the entity, resolved when the storyboard was built).
fn require_across(
    world: &World,
    e: &crate::world::entity::Entity,
    (a, id): (&AcrossLine, Option<EntityId>),
    fail: &dyn Fn(String, String) -> Error,
) -> Result<(), Error> {
    let x = world.entity(resolved(id, &a.entity_ref, fail)?);
    let n = [a.normal.0, a.normal.1];
    let (lo, hi) = x.bounding_box.footprint(&x.pose).project(n);
    let want = a.per_extent * (hi - lo) + a.offset;
    let got = e.pose.x * n[0] + e.pose.y * n[1] - (lo + hi) / 2.0;
    if (got - want).abs() > a.tolerance {
        return Err(fail(
            format!(
                "'{}' {want:.3} m across the line from the middle of '{}''s box across it, {:.3} m wide (within {} m)",
                e.name,
                a.entity_ref,
                hi - lo,
                a.tolerance
            ),
            format!("{got:.3} m"),
        ));
    }
    Ok(())
}
