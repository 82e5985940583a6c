//! `lateral(d, side_of/left_of/right_of: x)` beside a walk along a crossing (ASAM OpenSCENARIO
//! DSL 2.1 §8.9 `lateral`: "the lateral position of the actor" relative to x; §8.12.2.2.9
//! `crossing_connects`): the walk's route is the crossing, so the lateral position is taken
//! across the crossing's line (as `crossing_walk::crossing_shift` takes it without a
//! reference), and "beside x" is beside x's place across that line. oscsim's reading, where
//! the standard gives a lateral position only along a route and a crossing's line is not its
//! lane's direction:
//!
//! - x's place across the line is its bounding box projected on the line's normal (+ to the
//!   walker's left): from x's reference point where the plan has it, the box turned to x's
//!   heading — along the crossing's line while x walks one itself (its record, a
//!   `types::CrossingLine`), else along its lane's driving direction;
//! - the walker's centre is then where `lateral::beside` puts it from that extent, as beside
//!   x in a lane (`measure_by`, `side`, d), the walker's width across its own line;
//! - `at: start`: x read at the walk's start, the walk's line moved so; `at: all` (the
//!   default, §8.9.1.1.1: the constraint "holds throughout the phase") the same, held over the
//!   walk: the plan's check that x's place across is the same at the walk's end (1e-6 m), an
//!   error before the run, and the engine's check at every step of the walk (oscsim's
//!   `StateCheck::across_line`, held: `StateCheck::throughout`), measured as the plan measures
//!   it: x's box, turned to x's heading where the engine has it, projected on the normal of
//!   the crossing's line in the world (the line in road coordinates where the reference line is
//!   straight under the crosswalk, as `crossing_walk` lays the walk), the walker's reference
//!   point `lateral::beside` from it (1 cm); a failure is an error record and a failed run (x
//!   moving across the line within the walk and back, which the two ends do not show);
//!   `at: end`: x read at the walk's end, the walk from the crossing's line to there (its
//!   end depends on the line's length: settled by repeating, 1e-9 s).
//!
//! A first phase is placed on the crossing's line by the placement (x's place is not known
//! then) and moved beside x here, before anything else reads it.

use super::crossing_walk::{walked_part, Part, Walk};
use super::lateral;
use super::map_crossings::MapCrossing;
use super::planner::Planner;
use super::types::{CrossingPoint, Planned, LATERAL_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Arg, At, Modifier};
use crate::road::PlanRoad;
use scenario::{AcrossLine, StateCheck};

/// How far x's place across the line may differ at the walk's end under `at: all` (m).
pub(super) const ACROSS_TOLERANCE: f64 = 1e-6;

impl Planner<'_> {
    /// x's box across crossing `c`'s line at `tau`: the centre of its extent and the extent
    /// (m, + to the walker's left), read as the module doc says; an error at `e` where x walks
    /// a crossing at a speed that changes and `tau` is inside that walk.
    fn across_line(
        &self,
        c: &MapCrossing,
        (x, e): (&str, &Arg),
        tau: f64,
    ) -> Result<(f64, f64), Error> {
        let (_, s0, w0) = c.crossing.start;
        let (_, s1, w1) = c.crossing.end;
        let length = (s1 - s0).hypot(w1 - w0);
        let (us, ut) = ((s1 - s0) / length, (w1 - w0) / length);
        let (ns, nt) = (-ut, us);
        let (ls, lt) = (c.road_start + s0, w0);
        let walk = self
            .crossing_lines
            .iter()
            .find(|l| l.actor == x && l.t0 <= tau && tau <= l.t1);
        let (p, h) = match walk {
            Some(l) => {
                let inside = tau > l.t0 + 1e-9 && tau < l.t1 - 1e-9;
                if inside && !l.uniform {
                    return Err(e.site.err(
                        K::Unsatisfiable,
                        format!("expected `{x}`'s place across crossing `{}` known to the plan at {tau:.2} s, found `{x}` inside a walk along a crossing at a changing speed from {:.2} s to {:.2} s (the plan knows it at the walk's ends)", c.field, l.t0, l.t1),
                    ));
                }
                let f = if l.t1 > l.t0 {
                    (tau - l.t0) / (l.t1 - l.t0)
                } else {
                    0.0
                };
                let (ds, dt) = (l.to.0 - l.from.0, l.to.1 - l.from.1);
                let n = ds.hypot(dt);
                let h = if n > 0.0 { (ds / n, dt / n) } else { (us, ut) };
                ((l.from.0 + f * ds, l.from.1 + f * dt), h)
            }
            None => {
                let sign = if self.entities[self.index[x]].against {
                    -1.0
                } else {
                    1.0
                };
                ((self.s_at(x, tau), self.t_at(x, tau)), (sign, 0.0))
            }
        };
        let bb = self.entities[self.index[x]].data.bounding_box;
        let left = (-h.1, h.0);
        let across = |along: f64, side: f64| {
            let (s, t) = (
                p.0 + along * h.0 + side * left.0,
                p.1 + along * h.1 + side * left.1,
            );
            (s - ls) * ns + (t - lt) * nt
        };
        let corners = [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)].map(|(a, b)| {
            across(
                bb.center[0] + a * bb.length / 2.0,
                bb.center[1] + b * bb.width / 2.0,
            )
        });
        let lo = corners.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = corners.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Ok(((lo + hi) / 2.0, hi - lo))
    }

    /// The walker `target`'s place across crossing `c`'s line (m, + to its left) that
    /// `lateral(…)` `m` beside x (`e`, on side `sigma`) asks for at `tau`.
    pub(super) fn beside_across(
        &self,
        c: &MapCrossing,
        m: &Modifier,
        (e, sigma): (&Arg, f64),
        target: &str,
        tau: f64,
    ) -> Result<f64, Error> {
        let x = self.entity_of(e)?;
        let (centre, extent) = self.across_line(c, (&x, e), tau)?;
        lateral::beside(m, sigma, (centre, extent), self.width(target))
    }
}

impl Planner<'_> {
    /// The engine's check of `m`, a `lateral(…)` at: all beside x (`e`, on side `sigma`) of
    /// the walker `target` along crossing `c`, held over the walk as the action `name` (module
    /// doc): its place across the line's world normal from the middle of x's box across it,
    /// `lateral::beside` of x's extent (linear in it: k·extent + c). `None` off the plan's
    /// roads (the walk is not planned there either).
    pub(super) fn across_check(
        &self,
        c: &MapCrossing,
        m: &Modifier,
        (e, sigma): (&Arg, f64),
        target: &str,
        name: String,
    ) -> Result<Option<Planned>, Error> {
        let x = self.entity_of(e)?;
        let (_, s0, w0) = c.crossing.start;
        let (_, s1, w1) = c.crossing.end;
        let ends = self
            .road
            .world_pose(c.road_start + s0, w0)
            .zip(self.road.world_pose(c.road_start + s1, w1));
        let Some(((x0, y0, _), (x1, y1, _))) = ends else {
            return Ok(None);
        };
        let length = (x1 - x0).hypot(y1 - y0);
        // The walker's left of the line: its direction turned by +90°.
        let normal = (-(y1 - y0) / length, (x1 - x0) / length);
        let width = self.width(target);
        let offset = lateral::beside(m, sigma, (0.0, 0.0), width)?;
        let per_extent = lateral::beside(m, sigma, (0.0, 1.0), width)? - offset;
        let check = StateCheck {
            what: format!("{}(…) at {}", m.name, m.site.at()),
            across_line: Some(AcrossLine {
                entity_ref: x,
                normal,
                per_extent,
                offset,
                tolerance: LATERAL_TOLERANCE,
            }),
            throughout: true,
            ..StateCheck::default()
        };
        Ok(Some(self.checked(check, m, target, name)))
    }
}

/// The length of a walked part in the world (m), `None` off the plan's roads.
pub(super) fn part_length(road: &PlanRoad<'_>, (a, b): Part) -> Option<f64> {
    let (p, q) = road.world_pose(a.1, a.2).zip(road.world_pose(b.1, b.2))?;
    Some((q.0 - p.0).hypot(q.1 - p.1))
}

/// Rounds of settling a walk's end against x's place there before it is an error.
const SETTLE_ROUNDS: usize = 100;
/// How close two rounds' ends must come (m in s and t).
const SETTLE_TOLERANCE: f64 = 1e-9;

impl Planner<'_> {
    /// The walked part of `w` for a walk of `target` ending at `te`: beside x at: end, from the
    /// line's start to x's place across at `te`; else the part as at the start.
    fn part_at(&self, w: &Walk<'_>, target: &str, te: f64) -> Result<Part, Error> {
        match w.beside {
            Some((m, r)) if m.at == At::End => {
                let b = self.beside_across(w.c, m, r, target, te)?;
                walked_part(&self.road, w.c, w.along, (0.0, b))
            }
            _ => Ok(w.fixed),
        }
    }

    /// The walk's span and walked part, settled: `span_of` gives the span for a part's length
    /// (`None`: the walk never ends), and beside x at: end the part depends on the end
    /// (module doc). Beside x at: all, x's place across at the end must be the start's.
    pub(super) fn settle_walk(
        &self,
        w: &Walk<'_>,
        target: &str,
        span_of: &dyn Fn(&Self, f64) -> Option<f64>,
    ) -> Result<Option<(f64, Part)>, Error> {
        let mut part = w.fixed;
        for _ in 0..SETTLE_ROUNDS {
            let Some(length) = part_length(&self.road, part) else {
                return Ok(None);
            };
            let Some(span) = span_of(self, length) else {
                return Ok(None);
            };
            let next = self.part_at(w, target, w.t + span)?;
            let moved = (next.1 .1 - part.1 .1)
                .abs()
                .max((next.1 .2 - part.1 .2).abs());
            part = next;
            if moved > SETTLE_TOLERANCE {
                continue;
            }
            if let (Some((m, r)), Some(a)) = (w.beside, w.start_across) {
                if m.at == At::All {
                    let b = self.beside_across(w.c, m, r, target, w.t + span)?;
                    if (b - a).abs() > ACROSS_TOLERANCE {
                        return Err(m.site.err(
                            K::Unsatisfiable,
                            format!("expected `{target}`'s place across crossing `{}` beside `{}` the same at its walk's end, {:.2} s, as at its start (at: all), found {a:.2} m then and {b:.2} m at the end (x moves across the crossing's line)", w.c.field, r.0.path.as_deref().unwrap_or("x"), w.t + span),
                        ));
                    }
                }
            }
            return Ok(Some((span, part)));
        }
        let m = w.beside.map_or(&w.along.site, |(m, _)| &m.site);
        Err(m.err(
            K::Unsatisfiable,
            format!("expected the end of the walk along crossing `{}` to settle beside the other actor's place there, found it moving on after {SETTLE_ROUNDS} rounds", w.c.field),
        ))
    }

    /// Puts the walker `target`, in its first phase, at `at` on the crossing from the run's
    /// start (the placement put it on the crossing's line, x's place unknown then).
    pub(super) fn place_on_crossing(&mut self, target: &str, (lane, s, w): CrossingPoint) {
        let v = self.track(target).at(0.0).1;
        let offset = w - self.road.lane_center(lane, s);
        let i = self.index[target];
        let track = &mut self.entities[i].track;
        *track = crate::track::Track::new(s, v, lane);
        track.set_offset(0.0, offset);
    }
}
