//! Yaws measured in the world or from another object, checked against the plan's headings
//! (ASAM OpenSCENARIO DSL 2.1 §8.9 `yaw` with `measure_by: relative_to_north` or
//! `length_to_length`, `length_to_width`, `width_to_length`, `width_to_width` and
//! `relative_to: x`; `orientation` with `measured_by: absolute` or `relative_to_reference`).
//!
//! The frame (oscsim's choice, the standard names the measures but no axes): headings are
//! those of the road network's inertial frame, OpenDRIVE's x, y (x east, y north where the
//! network is georeferenced), counted counter-clockwise about z from +x as OpenSCENARIO 1.x
//! and ISO 8855 count a heading. `absolute` is that heading; `relative_to_north` counts from
//! +y (north), so the heading is π/2 + ψ. Between two objects the angle is counted from x's
//! axis to the actor's: `length_to_length` (and `width_to_width`, the same turn) heading(x) + ψ;
//! `length_to_width` from x's width axis (its left, heading(x) + π/2) to the actor's length
//! axis; `width_to_length` from x's length axis to the actor's width axis (its left), so
//! heading(x) + ψ − π/2. `orientation(…, relative_to: x, measured_by: relative_to_reference)`
//! is `length_to_length`.
//!
//! The plan's actors face along their lane (the road's heading there, turned by a yaw relative
//! to the road asked in the first phase), so the check needs their places: it is made once
//! every phase is planned ([`check_headings`]), at the phase start (`at: start`), its end
//! (`at: end`) or every step from one to the other (`at: all`). In the actor's first phase a
//! heading other than its lane's becomes its yaw relative to the road from the run's start
//! (the Init's relative Orientation), under the physical rules of a yaw relative to the road
//! (`checks::crabwise`).
//!
//! Where the plan does not know the actor's place — a phase that starts at run time, `at: end`
//! of a phase whose end it does not know, `at: all` over such a phase for an actor (or an x)
//! that moves — the engine checks the heading then (`engine_check`: oscsim's StateCheck with a
//! `HeadingCheck`, at the phase start, held over the phase, or in its `after` actions at its
//! end; a failure is an error record and a failed run). A first phase that starts at run time
//! sets no yaw from the run's start: the plan knows no place to take it from, so the actor
//! faces along its lane and the engine's check fails where the heading asked differs (§8.9.25
//! `must_be_physical`: the plan turns no actor at a moment it does not know); `at: end` of a
//! first phase with an end the plan does not know sets it only for an actor that stands.
//!
//! An actor driving against s (`crate::road`'s view, `against`) faces −s: its yaw relative to
//! the road's s-axis is π unless its first phase asks another, and its place is on its view
//! (u = L − s, t to its left), whose headings are the road's turned by π. An angle between two
//! objects' axes is one of the world frame, so a reference x of either direction is measured
//! the same way.

use std::f64::consts::{FRAC_PI_2, PI};

use crate::error::{Error, ErrorKind as K};
use crate::resolve::{ActorKind, At};

use scenario::{HeadingCheck, HeadingFrom, PrivateAction, StateCheck};

use super::planner::Planner;
use super::types::{Frame, HeadingAsk, Planned, HEADING_TOLERANCE};

/// Angles within this of each other are the same (rad): a thousandth of a degree.
pub(crate) const SAME_ANGLE: f64 = 1e-3 * std::f64::consts::PI / 180.0;

impl Planner<'_> {
    /// The heading (rad) of the road's s-axis where `name` is at `t`, on the plan's roads;
    /// `None` off them. An actor driving against s is placed on its view (`against_road`, in u
    /// along its direction of travel), whose headings are the road's turned by π.
    fn road_heading(&self, name: &str, t: f64) -> Option<f64> {
        let (road, along) = match self.entities[self.index[name]].against {
            true => (self.against_road.as_ref()?, PI),
            false => (&self.road, 0.0),
        };
        road.world_pose(self.s_on(road, name, t), self.t_on(road, name, t))
            .map(|p| opendrive::normalize_angle(p.2 - along))
    }

    /// The yaw relative to the road's s-axis of `name` driving along its lane (§8.9.9): 0 in
    /// +s, π against s (it faces −s).
    fn yaw_along(&self, name: &str) -> f64 {
        if self.entities[self.index[name]].against {
            PI
        } else {
            0.0
        }
    }

    /// The heading (rad) of `name`'s lane at `t` in its direction of travel.
    fn lane_heading(&self, name: &str, t: f64) -> Option<f64> {
        Some(opendrive::normalize_angle(
            self.road_heading(name, t)? + self.yaw_along(name),
        ))
    }

    /// The world heading of `name` at `t` as planned: the road's s-axis turned by its yaw
    /// relative to the road (its first phase's, else along its lane: 0, or π against s); a
    /// stationary object's, its location's yaw.
    fn heading_of(&self, name: &str, t: f64) -> Option<f64> {
        let e = &self.entities[self.index[name]];
        // A stationary object stands at its location's yaw (§8.7.3.1.1), off any lane.
        if let ActorKind::Stationary(l) = &e.data.kind {
            return Some(l.orientation[0]);
        }
        let yaw = e.yaw.as_ref().map_or(self.yaw_along(name), |(y, _)| *y);
        Some(opendrive::normalize_angle(
            self.road_heading(name, t)? + yaw,
        ))
    }
}

/// Checks every [`HeadingAsk`] against the finished plan, first turning each asked in an
/// actor's first phase into its yaw relative to the road from the run's start (where the
/// lane's heading differs from it); errors name the angle asked, the lane's heading and, for
/// a yaw relative to another object, both headings. Where the plan does not know the actor's
/// place (a run-time start, an end it does not know, `at: all` over such an end for an actor
/// or x that moves) the ask becomes the engine's check in its phase (`engine_check`).
pub(crate) fn check_headings(p: &mut Planner<'_>, asks: &[HeadingAsk]) -> Result<(), Error> {
    let dt = p.settings.dt;
    // First the yaws from the run's start: those measured in the world, then those from
    // another object (whose own may be one of the first).
    let world_first = |a: &&HeadingAsk| matches!(a.frame, Frame::World(..));
    let firsts = asks.iter().filter(|a| a.first);
    for a in firsts
        .clone()
        .filter(world_first)
        .chain(firsts.filter(|a| !world_first(a)))
    {
        // A first phase that starts at run time: the plan knows no place to take the yaw
        // relative to the road from, so the actor faces along its lane and the engine checks
        // the heading (`engine_check`).
        let Some(t0) = a.t0 else {
            continue;
        };
        let e = p.index[a.actor.as_str()];
        // Where the ask holds first: its yaw relative to the road is the actor's throughout.
        let t = match (a.at, a.end) {
            (At::End, Some(te)) => te,
            // An end the plan does not know: a standing actor's place is its start's.
            (At::End, None) if !p.entities[e].track.stands() => continue,
            _ => t0,
        };
        if p.entities[e].yaw.is_none() {
            let axis = p.road_heading(&a.actor, t).ok_or_else(|| off_road(a))?;
            let rel = opendrive::normalize_angle(wanted(p, a, t)?.0 - axis);
            if opendrive::normalize_angle(rel - p.yaw_along(&a.actor)).abs() > SAME_ANGLE {
                p.entities[e].yaw = Some((rel, a.site.clone()));
            }
        }
    }
    for (i, a) in asks.iter().enumerate() {
        let off_road = || off_road(a);
        // Where the plan does not know the actor's place (a run-time start, an end it does
        // not know, a motion over an unknown end) the engine checks the heading.
        let moves = |n: &str| p.index.contains_key(n) && !p.track(n).stands();
        let engine = match (a.t0, a.at, a.end) {
            (None, at, _) => Some(at),
            (Some(_), At::End, None) => Some(At::End),
            (Some(_), At::All, None) => {
                let x_moves = matches!(&a.frame, Frame::Object(_, x, _) if moves(x));
                (moves(&a.actor) || x_moves).then_some(At::All)
            }
            _ => None,
        };
        if let Some(at) = engine {
            engine_check(p, a, at, i);
        }
        let Some(t0) = a.t0 else {
            continue;
        };
        let times: Vec<f64> = match (a.at, a.end) {
            (At::Start, _) | (At::All, None) => vec![t0],
            (At::End, Some(te)) => vec![te],
            (At::End, None) => Vec::new(),
            (At::All, Some(te)) => {
                let n = ((te - t0) / dt).round().max(0.0) as usize;
                (0..=n).map(|i| (t0 + i as f64 * dt).min(te)).collect()
            }
        };
        for t in times {
            let (h, hx) = wanted(p, a, t)?;
            let got = p.heading_of(&a.actor, t).ok_or_else(off_road)?;
            if opendrive::normalize_angle(got - h).abs() > SAME_ANGLE {
                let lane = p.lane_heading(&a.actor, t).ok_or_else(off_road)?;
                let (measure, of_x) = match (&a.frame, hx) {
                    (Frame::World(_, m), _) => (*m, String::new()),
                    (Frame::Road, _) => ("relative to the road", String::new()),
                    (Frame::Object(_, x, m), Some(hx)) => {
                        (m.as_str(), format!(", `{x}` heading {hx:.4} rad"))
                    }
                    (Frame::Object(_, _, m), None) => (m.as_str(), String::new()),
                };
                return Err(a.site.err(
                    K::Unsatisfiable,
                    format!(
                        "expected `{}` at heading {h:.4} rad (the angle {:.4} rad, {measure}{of_x}) at {t:.2} s, found it at {got:.4} rad, its lane's heading {lane:.4} rad (the plan's actors face along their lane; another yaw only from an actor's first phase)",
                        a.actor, a.angle
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// The world heading `a` asks for at `t` (rad) and, measured from another object, that
/// object's heading then.
fn wanted(p: &Planner<'_>, a: &HeadingAsk, t: f64) -> Result<(f64, Option<f64>), Error> {
    Ok(match &a.frame {
        Frame::World(base, _) => (base + a.angle, None),
        Frame::Road => (
            p.road_heading(&a.actor, t).ok_or_else(|| off_road(a))? + a.angle,
            None,
        ),
        Frame::Object(axis, x, _) => {
            let hx = p.heading_of(x, t).ok_or_else(|| off_road(a))?;
            (hx + axis + a.angle, Some(hx))
        }
    })
}

/// The error of an actor (or its reference) off the plan's roads, where no heading is known.
fn off_road(a: &HeadingAsk) -> Error {
    a.site.err(
        K::Unsatisfiable,
        format!(
            "expected `{}` on the plan's roads at {:.2} s to measure its heading, found it off them",
            a.actor,
            a.t0.unwrap_or(0.0)
        ),
    )
}

/// The engine's check of `a` (the `i`th ask) where the plan does not know the actor's place:
/// at the phase start (`at: start`), in every step of the phase from its start (`at: all`,
/// a check held until the phase's Act ends it) or when the phase ends (`at: end`, in the
/// phase's `after` actions). Passing does nothing; failing is an error record and a failed
/// run naming the modifier, the heading asked, the actor's and its lane's (engine
/// `actions::check_heading`).
fn engine_check(p: &mut Planner<'_>, a: &HeadingAsk, at: At, i: usize) {
    let (from, angle, measure) = match &a.frame {
        Frame::World(base, m) => (HeadingFrom::World, base + a.angle, (*m).to_string()),
        Frame::Object(axis, x, m) => (HeadingFrom::Entity(x.clone()), axis + a.angle, m.clone()),
        Frame::Road => (HeadingFrom::Road, a.angle, "relative to the road".into()),
    };
    let (when, name) = match at {
        At::End => (
            "at the phase end ",
            format!("{}/{}/heading{i}.end", a.phase, a.actor),
        ),
        _ => ("", format!("{}/{}/heading{i}:check", a.phase, a.actor)),
    };
    let check = StateCheck {
        what: format!("{}(…) {when}at {}", a.modifier, a.site.at()),
        heading: Some(HeadingCheck {
            from,
            angle,
            tolerance: HEADING_TOLERANCE,
            measure: format!("{measure} {:.4} rad", a.angle),
        }),
        throughout: at == At::All,
        ..StateCheck::default()
    };
    let planned = Planned::with_phase(
        &a.actor,
        name,
        PrivateAction::Check(Box::new(check)),
        &a.site,
    );
    // Every ask comes from a phase the plan holds (`invoke` names it).
    if let Some(ph) = p.phases.iter_mut().find(|ph| ph.path == a.phase) {
        match at {
            At::End => ph.after.push(planned),
            _ => ph.actions.push(planned),
        }
    }
}

/// The heading offset of a `yaw` measure between two objects' axes (module doc), `None` for a
/// measure that is not between two objects.
pub(crate) fn object_axis(measure: &str) -> Option<f64> {
    match measure {
        "length_to_length" | "width_to_width" | "relative_to_reference" => Some(0.0),
        "length_to_width" => Some(FRAC_PI_2),
        "width_to_length" => Some(-FRAC_PI_2),
        _ => None,
    }
}
