//! A movement along a crossing the map bound (ASAM OpenSCENARIO DSL 2.1 §8.8.4.1 `walk`,
//! §8.8 `move`/`drive`, §8.9 `along`, §8.12.2.2.9 `crossing_connects`): the actor crosses the
//! road from the crossing's start lane to its end lane. Who crosses: a person's `walk()` or
//! `move()`, an animal's `move()` (§8.7.8; the library declares `walk` on `person` only), and a
//! vehicle's `drive()` or `move()`: the standard's `crossing_use` names `pedestrian`, `animal`,
//! `bicycle`, `rail_road` and `other`, so a crossing is not a pedestrian's alone (a cyclist or a
//! tram crosses the road on one); oscsim does not check the crossing's `use` against the
//! actor (the map's crosswalks carry none).
//!
//! | form | lowered to | ends |
//! | --- | --- | --- |
//! | `x.walk() with: along(c)` (or `move()`, `drive()`) | FollowTrajectoryAction in following mode `position` along the straight line from the start lane's centre to the end lane's (`map_crossings`), timed from the phase start at the actor's speed: `speed(v)` of the phase, else the speed it has | when it reaches the end lane's centre, the line's length over the speed |
//! | `along(c, start_offset: a, end_offset: b)` | the same along the part of the line from a m after its start to b m before its end (the crossing's own s, §8.12.2.2.9: "The s-coordinate of the crossing increases from the start_lane to end_lane") | when it reaches that part's end, its length over the speed |
//! | `lateral(d, side: left\|right)` beside the walk (at: start or all) | the same along the line moved d across itself to the walker's left or right (`crossing_shift`) | as above |
//! | `lateral(d, side: …, at: end)` | the line from the walked part's start on the crossing's line to its end moved d across (the walker ends d beside the line, as `lateral(…, at: end)` ends an actor d from its lane's centre) | as above |
//! | `lateral(d, measure_by: left_to_left \| … \| closest)` | measured from the crossing's borders, as in a lane from the lane's (`lateral::lane_offset`): the crossing's width is the crosswalk's extent across the line (the standard's `crossing.width`; its outline's box in road coordinates, as `map_crossings` takes it) | as above |
//!
//! The walker must be at the start of the part it walks when the walk starts (a first phase
//! places it there, `walked_part`; a later one checks it, 0.5 m), moving, and the phase's
//! start known to the plan; a + b must be below the crossing's length. The phase's `speed(v)`
//! times the walk; no SpeedAction runs beside it (it would replace the walk's action). An
//! action on the speed or acceleration along a crossing follows the line at the action's
//! speed (`crossing_speed`); another action along one, whose path is its own (a lane change,
//! a trajectory), is an error at `along`; `lateral(…)` beside another actor is measured
//! across the crossing's line from x's place (`crossing_beside`). The plan has the walker at the part's end from the end on (its lane, s and
//! offset there); in between it keeps the walker's track along its lane (as for
//! `follow_trajectory`), since the engine moves it.

use scenario::FollowingMode;

use super::lateral;
use super::map_crossings::{extent, MapCrossing};
use super::path_shape::along as trajectory;
use super::planner::Planner;
use super::speed_actions::Slot;
use super::types::{CrossingLine, CrossingPoint, Planned, When, POSITION_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{
    Action, ActorKind, Along, Arg, At, Invoke, ModKind, Modifier, Phase, Route, Val,
};
use crate::road::PlanRoad;

impl Planner<'_> {
    /// Plans `inv`, a walk along the crossing `along` names, for one walker.
    pub(super) fn plan_crossing_walk(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        mods: &[Modifier],
        along: &Along,
        slot: Slot<'_>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Route::Crossing { field, .. } = &along.route else {
            return Ok(None);
        };
        let (target, t0) = (slot.target, slot.t0);
        let data = &self.entities[self.index[target]].data;
        let moves = matches!(data.kind, ActorKind::Walker(_) | ActorKind::Vehicle);
        let width = data.bounding_box.width;
        let speed_action = matches!(
            inv.kind,
            Action::ChangeSpeed
                | Action::KeepSpeed
                | Action::AssignSpeed
                | Action::RemainStationary
                | Action::ChangeAcceleration
                | Action::AssignAcceleration
                | Action::KeepAcceleration
        );
        if !(inv.kind == Action::Move || speed_action) || !moves {
            return Err(along.site.err(
                K::Unsatisfiable,
                format!("expected a movement of a person, animal or vehicle along crossing `{field}` (walk(), move(), drive(), or an action on its speed or acceleration: the crossing's line is the path), found `{target}`'s {}(), whose path is its own", inv.action),
            ));
        }
        let Some(c) = self.crossings.get(field).cloned() else {
            return Err(along.site.err(
                K::Road,
                format!("expected crossing `{field}` bound to a crosswalk of the map by map.crossing_connects(crossing: {field}, …), found no such modifier"),
            ));
        };
        let Some(t) = t0 else {
            return Err(along.site.err(
                K::Unsatisfiable,
                format!("expected a phase start the plan knows for a walk along crossing `{field}`, found one after a run-time condition"),
            ));
        };
        let mut shift = crossing_shift(&self.road, &c, &mods.iter().collect::<Vec<_>>(), width)?;
        // Beside another actor: across the crossing's line from x's place (`crossing_beside`).
        let beside = beside_of(mods)?;
        let mut start_across = None;
        if let Some((m, r)) = beside.filter(|(m, _)| m.at != At::End) {
            let a = self.beside_across(&c, m, r, target, t)?;
            (shift, start_across) = ((a, a), Some(a));
        }
        let fixed = walked_part(&self.road, &c, along, shift)?;
        let (lane0, s0, w0) = fixed.0;
        if slot.first && beside.is_some() {
            self.place_on_crossing(target, fixed.0);
        }
        let (lane, s, w) = (
            self.lane_now(target, t),
            self.s_at(target, t),
            self.t_at(target, t),
        );
        if lane != lane0
            || (s - s0).abs() > POSITION_TOLERANCE
            || (w - w0).abs() > POSITION_TOLERANCE
        {
            let part = if along.start_offset > 0.0 || shift.0 != 0.0 {
                "the start of the walked part"
            } else {
                "the start"
            };
            return Err(along.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` at {part} of crossing `{field}` ({}: lane {lane0} at s = {s0:.2} m, t = {w0:.2} m) when its walk starts, found it in lane {lane} at s = {s:.2} m, t = {w:.2} m", c.why),
            ));
        }
        let walk = Walk {
            c: &c,
            along,
            beside,
            fixed,
            t,
            start_across,
        };
        // Beside x at: all, held over the walk: the engine's check at every step (x's place
        // across the line between the walk's ends is the engine's, `crossing_beside`).
        if let Some((m, r)) = beside.filter(|(m, _)| m.at == At::All && !m.projected) {
            if let Some(check) = self.across_check(&c, m, r, target, name("across"))? {
                slot.out.push(check);
            }
        }
        if speed_action {
            return self.speed_along_crossing(p, (inv, field), &walk, slot, name);
        }
        let Slot { out, .. } = slot;
        let v = match mods
            .iter()
            .find(|m| m.kind == ModKind::Speed && m.at != At::End)
        {
            Some(m) => self.speed_value(m, t0)?.0,
            None => self.track(target).at(t).1,
        };
        if v <= 0.0 {
            return Err(along.site.err(
                K::Unsatisfiable,
                format!("expected `{target}` walking at the start of its walk along crossing `{field}` (speed(…) in the phase), found it standing"),
            ));
        }
        // Both ends lie on a road of the plan (`map_lanes` binds crossings there).
        let Some((span, part)) = self.settle_walk(&walk, target, &|_, length| Some(length / v))?
        else {
            return Ok(None);
        };
        let ((_, s0, w0), (lane1, s1, w1)) = part;
        let ends = self
            .road
            .world_pose(s0, w0)
            .zip(self.road.world_pose(s1, w1));
        let Some(((x0, y0, _), (x1, y1, _))) = ends else {
            return Ok(None);
        };
        let h = (y1 - y0).atan2(x1 - x0);
        let n = name("crossing");
        let action = trajectory(
            &n,
            &[(x0, y0, h), (x1, y1, h)],
            Some(&[0.0, span]),
            false,
            FollowingMode::Position,
            &along.site,
        );
        out.push(Planned::with_phase(target, n.clone(), action, &p.site));
        let offset = w1 - self.road.lane_center(lane1, s1);
        self.arrive(target, t, span, (lane1, s1, offset));
        let line = CrossingLine::new(target, (t, t + span), part.0, part.1);
        self.crossing_lines.push(line);
        Ok(Some(self.ends(t0, span, &n, p)))
    }
}

/// The part of crossing `c` a walk `along` it covers: from `along.start_offset` m after the
/// crossing's start to `along.end_offset` m before its end, measured along the straight line
/// (the crossing's own s, §8.12.2.2.9, "increases from the start_lane to end_lane"), its start
/// moved `shift.0` m and its end `shift.1` m across the line to the walker's left
/// (`crossing_shift`), each end with the lane that holds it. Without offsets the crossing's
/// own ends (lane centres). The line's points are taken between its ends in road coordinates,
/// which is the world line where the reference line is straight under the crosswalk (as
/// `map_crossings` lays the crossing). Offsets that leave nothing to walk are an error at
/// `along`.
pub(super) fn walked_part(
    road: &PlanRoad<'_>,
    c: &MapCrossing,
    along: &Along,
    shift: (f64, f64),
) -> Result<(CrossingPoint, CrossingPoint), Error> {
    let (lane0, s0, t0) = c.crossing.start;
    let (lane1, s1, t1) = c.crossing.end;
    let (s0, s1) = (c.road_start + s0, c.road_start + s1);
    let (a, b) = (along.start_offset, along.end_offset);
    if a == 0.0 && b == 0.0 && shift == (0.0, 0.0) {
        return Ok(((lane0, s0, t0), (lane1, s1, t1)));
    }
    let length = (s1 - s0).hypot(t1 - t0);
    let (ns, nt) = normal(c);
    if a + b >= length {
        return Err(along.site.err(
            K::Unsatisfiable,
            format!("expected start_offset + end_offset below the length of crossing `{}`, {length:.2} m ({}), found {a} m + {b} m", c.field, c.why),
        ));
    }
    let at = |f: f64, shift: f64| -> Result<CrossingPoint, Error> {
        let (s, t) = (
            s0 + f * (s1 - s0) + shift * ns,
            t0 + f * (t1 - t0) + shift * nt,
        );
        point_at(road, &c.field, (s, t), along)
    };
    Ok((at(a / length, shift.0)?, at(1.0 - b / length, shift.1)?))
}

/// The point of crossing `field` at road coordinates (s, t) with the lane that holds it; none
/// is an error at `along`.
pub(super) fn point_at(
    road: &PlanRoad<'_>,
    field: &str,
    (s, t): (f64, f64),
    along: &Along,
) -> Result<CrossingPoint, Error> {
    let lane = road
        .world_pose(s, t)
        .and_then(|(x, y, _)| road.locate(x, y))
        .map(|(lane, _, _)| lane)
        .ok_or_else(|| {
            along.site.err(
                K::Road,
                format!("expected crossing `{field}` on a lane at s = {s:.2} m, t = {t:.2} m, found none"),
            )
        })?;
    Ok((lane, s, t))
}

/// The walker's left of crossing `c`'s line in road coordinates (t is to the left of s): the
/// line's direction turned by +90°, a unit vector (ds, dt).
fn normal(c: &MapCrossing) -> (f64, f64) {
    let (_, s0, t0) = c.crossing.start;
    let (_, s1, t1) = c.crossing.end;
    let length = (s1 - s0).hypot(t1 - t0);
    (-(t1 - t0) / length, (s1 - s0) / length)
}

/// The borders of crossing `c` across its line (m, + to the walker's left): the crosswalk's
/// extent in road coordinates (`map_crossings::extent`, the box that holds the line) projected
/// on the line's normal, its right border R ≤ 0 and its left L ≥ 0 from the line.
fn borders(road: &PlanRoad<'_>, c: &MapCrossing) -> Option<(f64, f64)> {
    let r = road.network().roads().get(c.crossing.road)?;
    let o = r.objects.iter().find(|o| o.id == c.crossing.object)?;
    let (s_min, s_max, t_min, t_max) = extent(o)?;
    let (_, s0, t0) = c.crossing.start;
    let (ns, nt) = normal(c);
    let across = [
        (s_min, t_min),
        (s_min, t_max),
        (s_max, t_min),
        (s_max, t_max),
    ]
    .map(|(s, t)| (s - s0) * ns + (t - t0) * nt);
    let fold = |f: fn(f64, f64) -> f64, init| across.iter().copied().fold(init, f);
    Some((
        fold(f64::min, f64::INFINITY),
        fold(f64::max, f64::NEG_INFINITY),
    ))
}

/// How far `lateral(…)` among `mods` (the walk's modifiers) moves a walk along crossing `c`
/// across it, at the walked part's start and at its end (m, + to the walker's left as it walks
/// the crossing; 0 without one), for a walker `width` m wide: the crossing is the walk's
/// route, so the lateral position is taken across it (§8.9 `lateral`). Without `measure_by`,
/// or `center_to_center`, the walker's reference point d from the crossing's line (the line a
/// crossing is, §8.12.2.2.9); another measure from the crossing's borders, as in a lane from
/// the lane's (`lateral::lane_offset`, the crosswalk's extent across the line its width). At:
/// start or all the walk keeps that line; at: end it starts on the crossing's line and ends
/// there (the shift at the start 0). Beside another actor: (0, 0), the line itself, which
/// `crossing_beside` moves once the plan reads x.
pub(super) fn crossing_shift(
    road: &PlanRoad<'_>,
    c: &MapCrossing,
    mods: &[&Modifier],
    width: f64,
) -> Result<(f64, f64), Error> {
    let Some(m) = mods.iter().find(|m| m.kind == ModKind::Lateral) else {
        return Ok((0.0, 0.0));
    };
    let field = &c.field;
    if lateral::reference(m)?.is_some() {
        // Beside another actor: on the line until the plan reads x (`crossing_beside`).
        return Ok((0.0, 0.0));
    }
    let measure = match m.arg("measure_by").map(Arg::eval).transpose()? {
        None => None,
        Some(Val::Enum(e)) if e == "center_to_center" => None,
        Some(Val::Enum(e)) => Some(e),
        Some(_) => {
            return Err(m.site.err(
                K::Modifier,
                "expected a lat_measure_by in lateral(…, measure_by: …), found another value",
            ))
        }
    };
    let d = match measure {
        None => {
            let d = m
                .arg("distance")
                .map(Arg::number)
                .transpose()?
                .unwrap_or(0.0);
            match m.arg("side").map(Arg::eval).transpose()? {
                Some(Val::Enum(e)) if e == "right" => -d,
                Some(Val::Enum(e)) if e == "left" => d,
                _ => {
                    return Err(m.site.err(
                        K::Modifier,
                        format!("expected side: left or right in lateral(…) beside a walk along crossing `{field}` (which side of the crossing's line), found none"),
                    ))
                }
            }
        }
        Some(e) => {
            let (right, left) = borders(road, c).ok_or_else(|| {
                m.site.err(
                    K::Road,
                    format!("expected crosswalk `{}` of crossing `{field}` with an extent to measure lateral(…, measure_by: {e}) from, found none", c.crossing.object),
                )
            })?;
            // The crossing as a lane of width left − right centred between its borders.
            (left + right) / 2.0 + lateral::lane_offset(m, left - right, width)?
        }
    };
    Ok(if m.at == At::End { (0.0, d) } else { (d, d) })
}

/// A `lateral(…)` beside another actor: the modifier, its reference and side (+1 left).
pub(super) type Beside<'m> = (&'m Modifier, (&'m Arg, f64));

/// A walked part of a crossing: its start and end.
pub(super) type Part = (CrossingPoint, CrossingPoint);

/// A walk along a crossing being planned: what its walked part depends on.
pub(super) struct Walk<'w> {
    pub c: &'w MapCrossing,
    pub along: &'w Along,
    /// `lateral(…)` beside x, its reference and side.
    pub beside: Option<Beside<'w>>,
    /// The walked part as at the walk's start (`at: end` beside x: its end on the line).
    pub fixed: Part,
    /// The walk's start and the walker's place across the line then (beside x at: start or
    /// all).
    pub t: f64,
    pub start_across: Option<f64>,
}

/// The `lateral(…)` beside another actor among a walk's modifiers, with its reference and side.
pub(super) fn beside_of(mods: &[Modifier]) -> Result<Option<Beside<'_>>, Error> {
    match mods.iter().find(|m| m.kind == ModKind::Lateral) {
        Some(m) => Ok(lateral::reference(m)?.map(|r| (m, r))),
        None => Ok(None),
    }
}
