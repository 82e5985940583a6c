//! Modifiers that constrain the motion without adding to it, checked against the plan (ASAM
//! OpenSCENARIO DSL 2.1 §8.9 `keep_lane`, `keep_speed`, `keep_position`, `physical_movement`,
//! `yaw`, `orientation`).

use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{At, Kind, ModKind, Modifier, Phase, Val};
use crate::track::Track;

use super::heading::{object_axis, SAME_ANGLE};
use super::types::{Frame, HeadingAsk};
use std::f64::consts::FRAC_PI_2;

/// Checks `keep_lane()`, `keep_speed()` and `physical_movement(must_be_physical)` against the
/// other modifiers of their invocation: a lane change beside `keep_lane`, a speed change beside
/// `keep_speed`, or a step of speed (`speed(v)` in a later phase, `step`: the speeds before and
/// after) beside either `keep_speed` or `must_be_physical` is an error at that modifier.
pub(crate) fn check_keeps(
    mods: &[Modifier],
    step: Option<(&Modifier, f64, f64)>,
) -> Result<(), Error> {
    let step = step.filter(|(_, v0, v1)| (v1 - v0).abs() > 1e-9);
    for k in mods {
        match k.kind {
            ModKind::KeepLane => {
                if let Some(c) = mods.iter().find(|m| {
                    m.kind == ModKind::ChangeLane || (m.kind == ModKind::Lane && m.at == At::End)
                }) {
                    return Err(c.site.err(
                        K::Unsatisfiable,
                        format!(
                            "expected no lane change beside {}() at {}, found `{}(…)`",
                            k.name,
                            k.site.at(),
                            c.name
                        ),
                    ));
                }
            }
            ModKind::KeepPosition => {
                let moves = |m: &&Modifier| match m.kind {
                    ModKind::ChangeSpeed
                    | ModKind::Acceleration
                    | ModKind::Distance
                    | ModKind::ChangeLane => true,
                    ModKind::Lane | ModKind::Position | ModKind::Lateral => m.at == At::End,
                    // speed(0) (or 0 at the end) agrees; anything else moves.
                    ModKind::Speed => !matches!(
                        (m.arg("speed").map(|e| e.number()), m.arg("faster_than").or(m.arg("slower_than")).or(m.arg("same_as"))),
                        (Some(Ok(v)), None) if v == 0.0
                    ),
                    _ => false,
                };
                if let Some(c) = mods.iter().find(moves) {
                    return Err(c.site.err(
                        K::Unsatisfiable,
                        format!(
                            "expected no movement beside {}() at {}, found `{}(…)`",
                            k.name,
                            k.site.at(),
                            c.name
                        ),
                    ));
                }
            }
            ModKind::KeepSpeed => {
                if let Some(c) = mods.iter().find(|m| {
                    matches!(m.kind, ModKind::ChangeSpeed | ModKind::Acceleration)
                        || (matches!(m.kind, ModKind::Speed | ModKind::Position) && m.at == At::End)
                }) {
                    return Err(c.site.err(
                        K::Unsatisfiable,
                        format!(
                            "expected no speed change beside {}() at {}, found `{}(…)`",
                            k.name,
                            k.site.at(),
                            c.name
                        ),
                    ));
                }
                if let Some((c, v0, v1)) = step {
                    return Err(c.site.err(
                        K::Unsatisfiable,
                        format!("expected the speed kept beside {}() at {}, found a step from {v0:.2} m/s to {v1:.2} m/s", k.name, k.site.at()),
                    ));
                }
            }
            ModKind::PhysicalMovement => {
                let must = matches!(k.arg("option").map(|e| e.eval()).transpose()?, Some(Val::Enum(o)) if o == "must_be_physical");
                if let (true, Some((c, v0, v1))) = (must, step) {
                    return Err(c.site.err(
                        K::Unsatisfiable,
                        format!("expected a physical movement (physical_movement(must_be_physical) at {}), found a step of speed from {v0:.2} m/s to {v1:.2} m/s at the phase start; use change_speed(…) or speed(…, at: end)", k.site.at()),
                    ));
                }
            }
            _ => {}
        }
    }
    Ok(())
}

/// What [`check_orientation`] finds: the yaw relative to the road a first phase asks for (and
/// its place), and the yaws measured in the world or from another object.
pub(crate) type Orientations = (Option<(f64, Site)>, Vec<HeadingAsk>);

/// Checks `yaw(…)` and `orientation(…)` (§8.9.9 yaw, §8.9.10 orientation) against the plan's
/// motion: the engine's vehicles drive along their lane's centre line (or at a constant offset
/// from it), so their yaw, pitch and roll relative to the road are 0 except while they change
/// lane or lane offset, and 0 again when such a change ends (the sinusoidal shape ends with no
/// lateral speed). A zero angle relative to the road (the default measure) therefore holds at
/// the start and end of every phase, and throughout one without a lane change or a
/// `lateral(…, at: end)`. A yaw other than 0 is the actor's from the run's start when it is
/// asked in the actor's `first` phase (the Init places it so; `plan` checks that the actor
/// stands throughout the run, the one case in which it keeps that yaw physically); `planned`
/// is the yaw the actor has (`along`, or the first phase's), which a later phase must ask for.
/// `along` is the yaw relative to the road's s-axis of an actor that drives along its lane: 0
/// in +s, π for an actor driving against s (`crate::road`: it faces −s), whose yaw of 0 would
/// face it against its travel. A yaw measured in the world (`absolute`, `relative_to_north`)
/// or from another object (`relative_to: x` with a measure between the two objects' axes) is a
/// [`HeadingAsk`] of `target` over the phase `phase` from `t0` to `end`, checked once every
/// phase is planned (`heading`: by the plan where it knows the actor's place, else by the
/// engine). So is a yaw relative to the road where `road_later` (a later phase of an actor
/// whose first phase asks for such a heading). Anything else is an error: another
/// yaw, a pitch or roll other than 0, a measure that does not fit `relative_to:` (or its
/// absence). Returns the yaw and its place when the first phase asks for one other than
/// `along` relative to the road, and the other yaws asked.
pub(crate) fn check_orientation(
    mods: &[Modifier],
    planned: f64,
    along: f64,
    first: bool,
    (target, phase, road_later): (&str, &str, bool),
    (t0, end): (Option<f64>, Option<f64>),
    entity_of: impl Fn(&crate::resolve::Arg) -> Result<String, Error>,
) -> Result<Orientations, Error> {
    let mut asked = None;
    let mut asks = Vec::new();
    /// Angles within this of 0 are 0 (rad).
    const ZERO: f64 = SAME_ANGLE;
    for m in mods.iter().filter(|m| m.kind == ModKind::Orientation) {
        let name = m.name.as_str();
        let (measure, yaw_arg) = if name == "yaw" {
            ("measure_by", "angle")
        } else {
            ("measured_by", "yaw")
        };
        let by = match m.arg(measure) {
            Some(e) => match e.eval()? {
                Val::Enum(v) => Some((v, e.site.clone())),
                _ => None,
            },
            None => None,
        };
        let by_name = by.as_ref().map_or("relative_to_road", |(v, _)| v.as_str());
        let frame = match (m.arg("relative_to"), by_name) {
            (None, "relative_to_road") => road_later.then_some(Frame::Road),
            (None, "absolute") => Some(Frame::World(0.0, "absolute")),
            (None, "relative_to_north") => Some(Frame::World(FRAC_PI_2, "relative to north (+y)")),
            (Some(x), b) => match object_axis(b) {
                Some(axis) => Some(Frame::Object(
                    axis,
                    entity_of(x)?,
                    format!("{b} from `{}`", x.path.as_deref().unwrap_or("?")),
                )),
                None => {
                    let want = if name == "yaw" {
                        "length_to_length, length_to_width, width_to_length or width_to_width"
                    } else {
                        "relative_to_reference"
                    };
                    return Err(x.site.err(
                        K::Argument,
                        format!("expected {measure}: {want} beside relative_to: (the angle between the two objects' axes), found {measure}: {b}, which measures from no object"),
                    ));
                }
            },
            (None, b) => {
                let site = by.as_ref().map_or(&m.site, |(_, s)| s);
                return Err(site.err(
                    K::Argument,
                    format!("expected relative_to: (the object whose axes the angle is measured from) beside {measure}: {b}, found none"),
                ));
            }
        };
        let in_frame = frame.is_some();
        if let Some(frame) = frame {
            if let Some(e) = m.arg(yaw_arg) {
                asks.push(HeadingAsk {
                    actor: target.to_string(),
                    frame,
                    angle: e.number()?,
                    at: m.at,
                    t0,
                    phase: phase.to_string(),
                    modifier: name.to_string(),
                    end,
                    first,
                    site: e.site.clone(),
                });
            }
        }
        let angles: &[&str] = if name == "yaw" {
            &["angle"]
        } else {
            &["yaw", "pitch", "roll"]
        };
        for a in angles {
            if let Some(e) = m.arg(a) {
                let x = e.number()?;
                let is_yaw = matches!(*a, "angle" | "yaw");
                if is_yaw && in_frame {
                    continue;
                }
                let want = if is_yaw { planned } else { 0.0 };
                // Angles compare on the circle: yaw(-180deg) is yaw(180deg).
                let off = |y: f64, from: f64| opendrive::normalize_angle(y - from).abs();
                if off(x, want) <= ZERO {
                    continue;
                }
                if is_yaw && first && off(planned, along) <= ZERO {
                    asked = Some((x, e.site.clone()));
                    continue;
                }
                return Err(e.site.err(
                    K::Unsatisfiable,
                    if is_yaw && off(planned, along) > ZERO {
                        format!("expected {a} {planned:.4} rad relative to the road (the yaw the actor stands at from its first phase), found {x:.4} rad")
                    } else if is_yaw && along != 0.0 {
                        format!("expected {a} {along:.4} rad relative to the road (§8.9.9: relative to the road's s-axis; the actor drives its lane against s, facing -s, and the engine's vehicles drive along their lane; another yaw is planned only in an actor's first phase, for an actor that stands throughout the run), found {x:.4} rad")
                    } else if is_yaw {
                        format!("expected {a} 0 relative to the road (the engine's vehicles drive along their lane; another yaw is planned only in an actor's first phase, for an actor that stands throughout the run), found {x:.4} rad")
                    } else {
                        format!("expected {a} 0 relative to the road (the engine's vehicles drive along their lane), found {x:.4} rad")
                    },
                ));
            }
        }
        if m.at == At::All {
            if let Some(c) = mods.iter().find(|q| {
                q.kind == ModKind::ChangeLane
                    || (matches!(q.kind, ModKind::Lane | ModKind::Lateral) && q.at == At::End)
            }) {
                return Err(c.site.err(
                    K::Unsatisfiable,
                    format!("expected no lateral movement while {name}(…) at {} holds throughout the phase (the actor turns while it moves sideways), found `{}(…)`", m.site.at(), c.name),
                ));
            }
        }
    }
    Ok((asked, asks))
}

/// Whether `mods` allow a non-physical movement: `physical_movement(prefer_non_physical)`
/// ("perform the non physical way if the implementation allows that", §8.9.25) or
/// `physical_movement(prefer_physical)` ("perform the movement physical if possible"), not the
/// default `must_be_physical`.
fn non_physical(mods: &[Modifier]) -> Result<bool, Error> {
    for m in mods.iter().filter(|m| m.kind == ModKind::PhysicalMovement) {
        if let Some(e) = m.arg("option") {
            if matches!(e.eval()?, Val::Enum(o) if o == "prefer_non_physical" || o == "prefer_physical")
            {
                return Ok(true);
            }
        }
    }
    Ok(false)
}

/// Checks that `actor`, which moves with the yaw `yaw` (rad, relative to the road) asked at
/// `site`, may do so crabwise: the engine keeps the heading relative to its lane (the Init's
/// relative Orientation) while it moves along the lane, turned from the way it moves. That is
/// no physical motion (a vehicle or person moves along its heading, §8.9.17
/// `must_be_physical`, the default: "an error message is issued if this action cannot be
/// performed in conformity with the laws of physics"), so every invocation of the actor must
/// allow a non-physical one (`non_physical`); it must move along its lane only (no lane or
/// offset change: the engine would turn it with the change) and under the plan's own actions
/// (`engine_moved`: not a gap action's or a car-following controller's).
pub(crate) fn crabwise(
    root: &Phase,
    actor: &str,
    yaw: f64,
    site: &Site,
    track: &Track,
    engine_moved: bool,
) -> Result<(), Error> {
    let moving = format!("expected `{actor}` standing throughout the run with a yaw of {yaw:.4} rad relative to the road, or moving along its lane with physical_movement(prefer_non_physical) in every invocation of it, found it moving");
    for leaf in root.leaves() {
        let Kind::Invoke(inv) = &leaf.kind else {
            continue;
        };
        if inv.actor == actor && !non_physical(&inv.modifiers)? {
            return Err(site.err(
                K::Unsatisfiable,
                format!("{moving} under the default physical_movement(must_be_physical) at {}: a vehicle or person moves along its heading (§8.9.17: in conformity with the laws of physics), so one turned from its lane's s-axis would leave its lane, which its plan does not", leaf.site.at()),
            ));
        }
    }
    if let Some(t) = track.moving_in(f64::NEG_INFINITY, f64::INFINITY) {
        return Err(site.err(
            K::Unsatisfiable,
            format!("{moving} sideways from {t:.2} s (a crabwise movement keeps to the lane: no lane or offset change)"),
        ));
    }
    if engine_moved {
        return Err(site.err(
            K::Unsatisfiable,
            format!("{moving} under the engine's controller (a gap action or avoid_collisions(true)), which steers along the lane"),
        ));
    }
    Ok(())
}
