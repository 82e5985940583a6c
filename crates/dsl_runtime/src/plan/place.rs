//! Initial placement (ASAM OpenSCENARIO DSL 2.1 §8.9, constraints `at: start` / `at: all` of
//! an actor's first phase): lane, s along the plan's road and speed of every vehicle at time 0.
//!
//! - `lane(n [, from: left])`: the n-th driving lane from the right (left); `lane(same_as: x)`,
//!   `lane(side_of: x, side: s)` (n lanes beside x, `side` left by default), `left_of` /
//!   `right_of`. No lane constraint: lane 1 (the rightmost driving lane).
//! - `position(d, ahead_of: x)` / `behind: x`: d between the reference points (the rear axle
//!   centres, as the engine's positions); `time: t` for d = t · x's speed; `position(d)` alone:
//!   s = d. A vehicle group's members: member 0 where the group is placed (beside its lane
//!   reference when it has no position); a single-lane group's next members each behind the
//!   previous with [`GROUP_GAP`] between bumpers; a common-route group over several lanes
//!   fills the lanes from member 0's leftwards a row at a time, each row [`GROUP_GAP`] behind
//!   the one ahead; for a group driving against s the same in its direction of travel, on
//!   the view (behind: u smaller, leftwards: towards the drivers' left). Nothing places an actor: it floats, and floating actors are
//!   shifted together so that the rearmost bumper is at [`FLOAT_REAR`].
//! - `lateral(d, measure_by: …)`: the offset from the lane's centre (`lateral` module).
//! - `keep_position()` without a speed: standing (0 m/s).
//! - `speed(v)`, `speed(v, faster_than: x)` (x's speed + v), `slower_than`, `same_as`; nothing:
//!   [`DEFAULT_SPEED`].

use std::collections::HashMap;

use super::lateral;
use super::types::MAX_SPEED;
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{Arg, At, ModKind, Modifier, Val};
use crate::road::PlanRoad;

/// Bumper-to-bumper gap between members of a group (m).
pub(crate) const GROUP_GAP: f64 = 10.0;
/// s of the rearmost bumper of actors nothing places (m).
pub(crate) const FLOAT_REAR: f64 = 10.0;
/// Speed of an actor nothing gives a speed (m/s): 50 km/h.
pub(crate) const DEFAULT_SPEED: f64 = 50.0 / 3.6;
/// Time gap of `position(ahead_of|behind: x)` without a distance or time (s): the two-second
/// rule of driving schools.
pub(crate) const DEFAULT_TIME_GAP: f64 = 2.0;

/// Distance between reference points of `position(ahead_of|behind: x)` without a distance or
/// time: [`DEFAULT_TIME_GAP`] at x's speed `vx`, and at least [`GROUP_GAP`] between the
/// bumpers that face each other (`overhangs`: the actor's and x's overhangs towards each
/// other, m).
pub(crate) fn default_distance(vx: f64, overhangs: f64) -> f64 {
    (DEFAULT_TIME_GAP * vx).max(GROUP_GAP + overhangs)
}

/// One actor to place: its placing modifiers, and for a group member its group's place.
pub(crate) struct ToPlace<'m> {
    /// Entity name.
    pub name: String,
    /// The modifiers of its first phase that hold at the start.
    pub mods: Vec<&'m Modifier>,
    /// For a group member: the previous member (None for the first one).
    pub member_after: Option<Option<String>>,
    /// For a member after the first of a common-route group over several lanes: the
    /// members, in list order, and its index (see [`across`]).
    pub across: Option<(Vec<String>, usize)>,
    /// Front and rear overhang of the bounding box from the reference point (m).
    pub front: f64,
    /// Rear overhang (m).
    pub rear: f64,
    /// Width of its bounding box (m), for `lateral(…)`.
    pub width: f64,
    /// Its first phase (for errors when no modifier places it).
    pub site: Site,
    /// Lane and s of the start of a named route it follows in its first phase (`along`):
    /// where it starts when no `lane`/`position` places it.
    pub route: Option<(i32, f64)>,
    /// A person: `lane(n)` counts the road's sidewalks where it has any (`crate::road`).
    pub walker: bool,
    /// Where a stationary object stands (its `location(pose)` on the road): nothing else
    /// places it.
    pub fixed: Option<Start>,
    /// It drives against s (its route's lane is driven in −s): placed on the plan's roads
    /// driven that way (`crate::road`), its s the distance u along its direction of travel.
    pub against: bool,
}

/// Where an actor starts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Start {
    /// Lane id.
    pub lane: i32,
    /// s (m).
    pub s: f64,
    /// Speed (m/s).
    pub v: f64,
    /// Offset from the lane's centre (m, + left): `lateral(…)`.
    pub offset: f64,
}

/// The modifier of `kind` of `p`'s first phase that holds at the start.
fn find<'m>(p: &ToPlace<'m>, kind: ModKind) -> Option<&'m Modifier> {
    p.mods
        .iter()
        .find(|m| m.kind == kind && m.at != At::End)
        .copied()
}

/// Places every actor of `all`: on `forward`, or on `against` (the same roads driven against
/// s, `crate::road`) for an actor that drives so; relations between actors of opposite
/// directions are refused before (`against::check_references`).
pub(crate) fn place(
    forward: &PlanRoad<'_>,
    against: Option<&PlanRoad<'_>>,
    all: &[ToPlace<'_>],
    entity: &dyn Fn(&str) -> Option<String>,
) -> Result<HashMap<String, Start>, Error> {
    let view = |p: &ToPlace<'_>| match (p.against, against) {
        (true, Some(a)) => a,
        _ => forward,
    };
    let mut lane: HashMap<String, i32> = HashMap::new();
    let mut s: HashMap<String, (f64, bool)> = HashMap::new();
    let mut v: HashMap<String, f64> = HashMap::new();
    let reference = |m: &Modifier, names: &[&str]| -> Result<Option<(String, String)>, Error> {
        for n in names {
            if let Some(e) = m.arg(n) {
                let ent = e.path.as_deref().and_then(entity).ok_or_else(|| {
                    e.site.err(
                        K::UnknownActor,
                        format!("expected a vehicle for `{n}:`, found another value"),
                    )
                })?;
                return Ok(Some((n.to_string(), ent)));
            }
        }
        Ok(None)
    };
    let number = |m: &Modifier, n: &str| m.arg(n).map(Arg::number).transpose();
    // The s of `x` in `p`'s frame: a stationary object's (placed in +s) turned into u = L − s
    // for an actor driving against s (it has no direction of its own); any other actor's as
    // placed (relations across directions are refused before).
    let seen = |p: &ToPlace<'_>, x: &str, s: &HashMap<String, (f64, bool)>| {
        let (sx, fl) = *s.get(x)?;
        // Fixed and placed in +s (a stationary object; an actor fixed driving against s, such
        // as an oncoming member of random traffic, is placed in u already).
        let stands = all
            .iter()
            .any(|q| q.name == x && q.fixed.is_some() && !q.against);
        Some(match (stands && p.against, against) {
            (true, Some(a)) => (a.length() - sx, fl),
            _ => (sx, fl),
        })
    };
    for p in all {
        if let Some(f) = p.fixed {
            lane.insert(p.name.clone(), f.lane);
            s.insert(p.name.clone(), (f.s, false));
            v.insert(p.name.clone(), f.v);
        }
    }
    for _round in 0..=all.len() {
        let mut progress = false;
        for p in all {
            let road = view(p);
            // Speed.
            if !v.contains_key(&p.name) {
                let value = match find(p, ModKind::Speed) {
                    // keep_position(): a vehicle standing from the start.
                    None if find(p, ModKind::KeepPosition).is_some() => Some(0.0),
                    None => Some(DEFAULT_SPEED),
                    Some(m) => {
                        let own = number(m, "speed")?;
                        match reference(m, &["faster_than", "slower_than", "same_as"])? {
                            None => Some(own.unwrap_or(DEFAULT_SPEED)),
                            Some((how, x)) => v.get(&x).map(|vx| match how.as_str() {
                                "faster_than" => vx + own.unwrap_or(0.0),
                                "slower_than" => vx - own.unwrap_or(0.0),
                                _ => *vx,
                            }),
                        }
                    }
                };
                if let Some(x) = value {
                    v.insert(p.name.clone(), x);
                    progress = true;
                }
            }
            // Lane.
            if !lane.contains_key(&p.name) {
                let at_s = s.get(&p.name).map_or(0.0, |x| x.0);
                let value = match (&p.across, find(p, ModKind::Lane)) {
                    (Some((members, i)), _) => lane.get(&members[0]).map(|l0| {
                        let lanes = leftwards(road, *l0, at_s);
                        Some(lanes[i % lanes.len()])
                    }),
                    (None, m) => match m {
                        None if p.route.is_some() => p.route.map(|r| Some(r.0)),
                        None => Some(road.numbered(1, false, at_s, p.walker)),
                        Some(m) => {
                            let n = number(m, "lane")?.map_or(1, |x| x.round() as i64);
                            let from_left = matches!(m.arg("from").map(Arg::eval).transpose()?, Some(Val::Enum(f)) if f == "left");
                            match reference(m, &["same_as", "side_of", "left_of", "right_of"])? {
                            None => Some(road.numbered(n, from_left, at_s, p.walker)),
                            Some((how, x)) => lane.get(&x).map(|lx| match how.as_str() {
                                "same_as" => Some(*lx),
                                "left_of" => road.beside(*lx, true, n, at_s),
                                "right_of" => road.beside(*lx, false, n, at_s),
                                _ => {
                                    let left = !matches!(m.arg("side").map(Arg::eval).transpose(), Ok(Some(Val::Enum(sd))) if sd == "right");
                                    road.beside(*lx, left, n, at_s)
                                }
                            }),
                        }
                        }
                    },
                };
                if let Some(l) = value {
                    let Some(l) = l else {
                        let site = find(p, ModKind::Lane).map_or(&p.site, |m| &m.site);
                        return Err(site.err(
                            K::Unsatisfiable,
                            format!(
                                "expected a driving lane for `{}` on road {}, found none there",
                                p.name,
                                road.id()
                            ),
                        ));
                    };
                    lane.insert(p.name.clone(), l);
                    progress = true;
                }
            }
            // Position.
            if !s.contains_key(&p.name) {
                // A group member after the first is placed by the formation; the group's
                // position modifiers place its first member.
                let follower = p.across.is_some() || matches!(p.member_after, Some(Some(_)));
                let value = match find(p, ModKind::Position).filter(|_| !follower) {
                    Some(m) => {
                        let r = reference(m, &["ahead_of", "behind"])?;
                        let d = match (number(m, "distance")?, number(m, "time")?, &r) {
                            (Some(d), _, _) => Some(d),
                            (None, Some(t), Some((_, x))) => v.get(x).map(|vx| t * vx),
                            (None, None, Some((how, x))) => v.get(x).map(|vx| {
                                let q = all.iter().find(|q| &q.name == x);
                                let overhangs = if how == "ahead_of" {
                                    p.rear + q.map_or(0.0, |q| q.front)
                                } else {
                                    p.front + q.map_or(0.0, |q| q.rear)
                                };
                                default_distance(*vx, overhangs)
                            }),
                            _ => {
                                return Err(m.site.err(
                                    K::Unsatisfiable,
                                    "expected a distance (or a time and a reference) in position(…), found neither",
                                ))
                            }
                        };
                        match (d, r) {
                            (None, _) => None,
                            (Some(d), None) => Some((d, false)),
                            (Some(d), Some((how, x))) => seen(p, &x, &s).map(|(sx, fl)| {
                                (if how == "ahead_of" { sx + d } else { sx - d }, fl)
                            }),
                        }
                    }
                    None if p.across.is_some() => p.across.as_ref().and_then(|(members, i)| {
                        let l0 = lane.get(&members[0])?;
                        let n = leftwards(road, *l0, s.get(&members[0])?.0).len();
                        if *i < n {
                            // The first row: beside the first member.
                            s.get(&members[0]).copied()
                        } else {
                            // A later row: behind the member n places ahead, in its lane.
                            let ahead = &members[i - n];
                            s.get(ahead).map(|(sa, fl)| {
                                (behind_in_formation(all, ahead, *sa, p.front), *fl)
                            })
                        }
                    }),
                    None => match &p.member_after {
                        _ if p.route.is_some() && !matches!(p.member_after, Some(Some(_))) => {
                            p.route.map(|r| (r.1.max(p.rear), false))
                        }
                        Some(Some(prev)) => s
                            .get(prev)
                            .map(|(sp, fl)| (behind_in_formation(all, prev, *sp, p.front), *fl)),
                        _ => match find(p, ModKind::Lane)
                            .map(|m| reference(m, &["same_as", "side_of", "left_of", "right_of"]))
                            .transpose()?
                            .flatten()
                        {
                            // Beside (or in the lane of) a reference: alongside it.
                            Some((how, x)) if how != "same_as" => seen(p, &x, &s),
                            _ => Some((0.0, true)),
                        },
                    },
                };
                if let Some(x) = value {
                    s.insert(p.name.clone(), x);
                    progress = true;
                }
            }
        }
        if !progress {
            break;
        }
    }
    // Shift floating actors behind the start of the road (in each direction of travel).
    let shift = |against: bool| {
        let rearmost = all
            .iter()
            .filter(|p| p.against == against)
            .filter_map(|p| s.get(&p.name).filter(|x| x.1).map(|x| x.0 - p.rear))
            .fold(f64::INFINITY, f64::min);
        if rearmost.is_finite() {
            FLOAT_REAR - rearmost
        } else {
            0.0
        }
    };
    let mut out = HashMap::new();
    for p in all {
        let road = view(p);
        if let Some(f) = p.fixed {
            out.insert(p.name.clone(), f);
            continue;
        }
        let (Some(l), Some((sv, fl)), Some(vv)) =
            (lane.get(&p.name), s.get(&p.name), v.get(&p.name))
        else {
            let site = p.mods.first().map_or(&p.site, |m| &m.site);
            return Err(site.err(
                K::Unsatisfiable,
                format!("expected a placement of `{}` that does not depend on itself, found a cycle of references", p.name),
            ));
        };
        if !(0.0..=MAX_SPEED).contains(vv) {
            let site = find(p, ModKind::Speed).map_or(&p.site, |m| &m.site);
            return Err(site.err(
                K::Unsatisfiable,
                format!(
                    "expected a start speed of `{}` within 0 to {} m/s, found {vv:.2} m/s",
                    p.name, MAX_SPEED
                ),
            ));
        }
        let sv = if *fl { sv + shift(p.against) } else { *sv };
        if sv - p.rear < 0.0 || sv + p.front > road.length() {
            let site = p.mods.first().map_or(&p.site, |m| &m.site);
            return Err(site.err(
                K::Road,
                format!(
                    "expected `{}` on road {} (0 m to {:.1} m), found it placed at s = {sv:.2} m",
                    p.name,
                    road.id(),
                    road.length()
                ),
            ));
        }
        let offset = match find(p, ModKind::Lateral) {
            // Beside another actor: placed below, once that one is.
            Some(m) if lateral::reference(m)?.is_some() => 0.0,
            Some(m) => lateral::lane_offset(m, road.lane_width(*l, sv), p.width)?,
            None => 0.0,
        };
        out.insert(
            p.name.clone(),
            Start {
                lane: *l,
                s: sv,
                v: *vv,
                offset,
            },
        );
    }
    beside_others(&view, all, entity, &mut out)?;
    Ok(out)
}

/// Places the actors whose first phase has `lateral(…)` relative to another actor, once that
/// one is placed: the offset in its lane, or, without a lane of its own, the lane that holds
/// the asked t (see the `lateral` module), on the view the actor drives (`view`: x drives it
/// too, `against::check_references`), so left and right are the drivers'.
fn beside_others<'r>(
    view: &dyn Fn(&ToPlace<'_>) -> &'r PlanRoad<'r>,
    all: &[ToPlace<'_>],
    entity: &dyn Fn(&str) -> Option<String>,
    out: &mut HashMap<String, Start>,
) -> Result<(), Error> {
    let mut pending = Vec::new();
    // A fixed actor stays where it is (one held for a member of random traffic is placed
    // beside it once the member is drawn: random_traffic_relations).
    for p in all.iter().filter(|p| p.fixed.is_none()) {
        if let Some(m) = find(p, ModKind::Lateral) {
            if let Some((e, sigma)) = lateral::reference(m)? {
                let x = e.path.as_deref().and_then(entity).ok_or_else(|| {
                    e.site.err(
                        K::UnknownActor,
                        "expected a vehicle of the scenario beside which to place, found another value",
                    )
                })?;
                pending.push((p, m, x, sigma));
            }
        }
    }
    // Whether an actor's lane modifier refers to `name` (placed by lane before this pass).
    let refers = |name: &str| {
        all.iter().any(|q| {
            q.mods.iter().any(|m| {
                m.kind == ModKind::Lane
                    && ["same_as", "side_of", "left_of", "right_of"]
                        .iter()
                        .any(|k| {
                            m.arg(k)
                                .and_then(|e| e.path.as_deref())
                                .and_then(entity)
                                .is_some_and(|x| x == name)
                        })
            })
        })
    };
    let mut done: Vec<&str> = Vec::new();
    for _round in 0..=pending.len() {
        let mut progress = false;
        for (p, m, x, sigma) in &pending {
            let waits = |n: &str| {
                pending
                    .iter()
                    .any(|(q, ..)| q.name == n && !done.contains(&n))
            };
            // A column's member after the first keeps to its slot behind the member before it,
            // in that one's lane (the formation's), once that one is beside x; a member of a
            // group over several lanes keeps its slot in the block around member 0, once
            // member 0 is beside x.
            let prev = match (&p.member_after, &p.across) {
                (_, Some((members, _))) => Some(members[0].as_str()),
                (Some(Some(prev)), None) => Some(prev.as_str()),
                _ => None,
            };
            // A block's member waits for every member before it (its row's lanes and the
            // member ahead of it follow from theirs).
            let block_waits = p
                .across
                .as_ref()
                .is_some_and(|(members, i)| members[..*i].iter().any(|m| waits(m)));
            if done.contains(&p.name.as_str()) || waits(x) || prev.is_some_and(waits) || block_waits
            {
                continue;
            }
            let (Some(sx), Some(q)) = (out.get(x).copied(), all.iter().find(|q| &q.name == x))
            else {
                continue;
            };
            let road = view(p);
            // A stationary object's place (in +s) in the frame of an actor driving against s:
            // u = L − s, its offset to the left of that direction (as `place` reads it).
            let sx = match (q.fixed.is_some(), p.against) {
                (true, true) => Start {
                    s: road.length() - sx.s,
                    offset: -sx.offset,
                    ..sx
                },
                _ => sx,
            };
            let t_x = road.lane_center(sx.lane, sx.s) + sx.offset;
            let t_a = lateral::beside(m, *sigma, (t_x, q.width), p.width)?;
            let st = out[&p.name];
            let own_lane = p.mods.iter().any(|m| m.kind == ModKind::Lane)
                || p.across.is_some()
                || matches!(p.member_after, Some(Some(_)))
                || p.route.is_some();
            // A member of a group over several lanes: the block moved with member 0, its lane
            // the one its slot takes from member 0's new lane leftwards (`leftwards`, a row at a
            // time), at member 0's offset in its lane (issue 27: before, every member took x's
            // t_a in the lane it had before member 0 moved, and two members stood on one
            // place).
            // A later row (i ≥ n, n lanes from member 0's new one) drives behind member i − n
            // in its lane, 10 m between bumpers, as `place` lays the block out.
            if let (Some((members, i)), Some(first)) = (&p.across, prev.and_then(|q| out.get(q))) {
                let lanes = leftwards(road, first.lane, first.s);
                let n = lanes.len();
                let s = if *i < n {
                    first.s
                } else {
                    let ahead = &members[i - n];
                    let sa = out.get(ahead).map_or(st.s, |a| a.s);
                    behind_in_formation(all, ahead, sa, p.front)
                };
                out.insert(
                    p.name.clone(),
                    Start {
                        lane: lanes[i % n],
                        s,
                        offset: first.offset,
                        ..st
                    },
                );
                done.push(&p.name);
                progress = true;
                continue;
            }
            let lane = if let Some(l) = prev.and_then(|q| out.get(q)).map(|q| q.lane) {
                l
            } else if own_lane {
                st.lane
            } else {
                let l = road.lane_holding(st.s, t_a).ok_or_else(|| {
                    m.site.err(
                        K::Unsatisfiable,
                        format!("expected a driving lane at t = {t_a:.2} m (where lateral(…) puts `{}`), found none", p.name),
                    )
                })?;
                if l != st.lane && refers(&p.name) {
                    return Err(m.site.err(
                        K::Unsatisfiable,
                        format!("expected a lane(…) of `{}` beside this lateral(…): another actor's lane refers to it, and its lane follows from the lateral position only after that one is placed", p.name),
                    ));
                }
                l
            };
            let offset = t_a - road.lane_center(lane, st.s);
            let w = road.lane_width(lane, st.s);
            if offset.abs() > w / 2.0 + 1e-9 {
                return Err(m.site.err(
                    K::Unsatisfiable,
                    format!("expected `{}`'s reference point in its lane {lane} ({w:.2} m wide), found lateral(…) puts it {offset:.2} m from the lane's centre", p.name),
                ));
            }
            out.insert(p.name.clone(), Start { lane, offset, ..st });
            done.push(&p.name);
            progress = true;
        }
        if !progress {
            break;
        }
    }
    if let Some((p, m, ..)) = pending
        .iter()
        .find(|(p, ..)| !done.contains(&p.name.as_str()))
    {
        return Err(m.site.err(
            K::Unsatisfiable,
            format!("expected a lateral placement of `{}` that does not depend on itself, found a cycle of references", p.name),
        ));
    }
    Ok(())
}

/// The s of a member of a formation whose front is `front` m ahead of its reference point,
/// behind `ahead` (at `s_ahead`) with [`GROUP_GAP`] between the bumpers.
fn behind_in_formation(all: &[ToPlace<'_>], ahead: &str, s_ahead: f64, front: f64) -> f64 {
    let rear = all.iter().find(|q| q.name == ahead).map_or(0.0, |q| q.rear);
    s_ahead - rear - GROUP_GAP - front
}

/// Driving lanes from `l0` leftwards at `s` (`l0` first): the lanes a common-route group's
/// formation fills, a row at a time.
fn leftwards(road: &PlanRoad<'_>, l0: i32, s: f64) -> Vec<i32> {
    let mut out = vec![l0];
    while let Some(l) = road.beside(l0, true, out.len() as i64, s) {
        out.push(l);
    }
    out
}
