//! World (x, y[, heading]) → road position (OpenDRIVE 1.8 §8.3: inverse of the reference-line
//! coordinate system). Candidate road pieces come from the R*-tree, nearest box first; on each,
//! Newton's method solves place(s, t) = (x, y) exactly (the 3-D placement of `frame`, so banked
//! roads invert too), then the lane is the one whose borders enclose t.
//!
//! Choice among candidates: the smallest distance from the road surface (0 inside a lane);
//! then, when a heading is given, the lane whose driving direction is closest to it; then the
//! smallest |t|.

use super::graph::{driving_direction, Direction};
use crate::handles::RoadHandle;
use crate::math::{angle_difference, normalize_angle, Real, LENGTH_EPSILON, SOLVER_TOLERANCE};
use crate::model::Road;
use crate::network::RoadNetwork;
use crate::road::lane_span::{road_extent, side_spans};
use crate::road::pieces_by_distance::PiecesByDistance;
use crate::road::plan_frame::plan_frame;
use crate::road::spatial::Piece;

/// Newton iterations allowed per projection.
const MAX_ITER: usize = 60;
/// A projection whose residual exceeds this (m) did not land on its piece (or the point is
/// beyond the road's end).
const RESIDUAL_TOLERANCE: Real = 1e-7;

/// A position on a road, as returned by [`RoadNetwork::locate`].
#[derive(Debug, Clone, PartialEq)]
pub struct RoadPosition {
    /// Road id.
    pub road_id: String,
    /// The same road by handle, valid for the network that made the position (road ids are
    /// unique in a network, so the two name one road): a caller comparing roads compares
    /// these instead of the id strings.
    pub road: RoadHandle,
    /// Lane whose borders enclose t (the outermost lane if t lies beyond the road surface).
    pub lane_id: i32,
    /// s along the reference line (m).
    pub s: Real,
    /// t from the reference line, positive left (m).
    pub t: Real,
    /// Offset from the lane centre, positive left (m).
    pub offset: Real,
    /// The junction the road belongs to, if any.
    pub junction_id: Option<String>,
    /// Query heading minus the road's heading at s, in (−π, π] (0 when no heading was given).
    pub relative_heading: Real,
    /// Horizontal distance from the road surface (m); 0 when the point is on a lane.
    pub distance: Real,
}

/// A position on a road as handles, as returned by [`RoadNetwork::locate_point`] (no
/// allocation); [`RoadNetwork::road_position`] turns it into a [`RoadPosition`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadPoint {
    /// The road.
    pub road: RoadHandle,
    /// Lane whose borders enclose t (the outermost lane if t lies beyond the road surface).
    pub lane_id: i32,
    /// s along the reference line (m).
    pub s: Real,
    /// t from the reference line, positive left (m).
    pub t: Real,
    /// Offset from the lane centre, positive left (m).
    pub offset: Real,
    /// Query heading minus the road's heading at s, in (−π, π] (0 when no heading was given).
    pub relative_heading: Real,
    /// Horizontal distance from the road surface (m); 0 when the point is on a lane.
    pub distance: Real,
}

/// One candidate projection.
#[derive(Debug, Clone, Copy)]
struct Candidate {
    road: usize,
    s: Real,
    t: Real,
    distance: Real,
    heading_gap: Real,
    road_hdg: Real,
    /// `lane_at(s, t)` where it was computed (a heading was given).
    lane: Option<(i32, Real)>,
}

/// Solves place(s, t) = (px, py) on `road` with s kept in the piece's [s0, s1]; returns (s, t, residual)
/// and the road's heading at that s (which the caller needs again: computed once). The frame
/// is evaluated again only where s has changed (the same s gives the same frame).
fn project(road: &Road, piece: &Piece, px: Real, py: Real) -> Option<(Real, Real, Real, Real)> {
    let (lo, hi) = (piece.s0, piece.s1);
    let frame = |s| plan_frame(road, s, piece.hints);
    let mut s = 0.5 * (lo + hi);
    let mut t = 0.0;
    let span = (hi - lo).max(1.0);
    let mut f = frame(s);
    let mut f_at = s;
    for _ in 0..MAX_ITER {
        if f_at.to_bits() != s.to_bits() {
            (f, f_at) = (frame(s), s);
        }
        let [x, y] = f.place(t);
        let (ex, ey) = (px - x, py - y);
        let j = f.jacobian(t);
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if !det.is_finite() || det.abs() < 1e-12 {
            return None;
        }
        let ds = ((j[1][1] * ex - j[0][1] * ey) / det).clamp(-span, span);
        let dt = (-j[1][0] * ex + j[0][0] * ey) / det;
        let s_new = (s + ds).clamp(lo, hi);
        let moved = (s_new - s).abs();
        s = s_new;
        t += dt;
        // Converged when the step is below the tolerance, or below the resolution of f64 at
        // the size of the coordinates (georeferenced files put roads at 10⁶ m and more).
        let resolution = 4.0 * f64::EPSILON * (px.abs() + py.abs());
        if (moved < SOLVER_TOLERANCE && dt.abs() < SOLVER_TOLERANCE) || ex.hypot(ey) < resolution {
            break;
        }
    }
    if f_at.to_bits() != s.to_bits() {
        f = frame(s);
    }
    let [x, y] = f.place(t);
    let resid = (px - x).hypot(py - y);
    resid.is_finite().then_some((s, t, resid, f.hdg))
}

impl RoadNetwork {
    /// The road position of world point (x, y); `heading` (rad) helps choose between
    /// overlapping roads (junctions). `None` for an empty network, non-finite input, or (in
    /// theory) a point where no road's projection is defined (a centre of curvature).
    pub fn locate(&self, x: Real, y: Real, heading: Option<Real>) -> Option<RoadPosition> {
        self.locate_point(x, y, heading)
            .map(|p| self.road_position(&p))
    }

    /// [`locate`](Self::locate) with the road as a handle: no allocation.
    pub fn locate_point(&self, x: Real, y: Real, heading: Option<Real>) -> Option<RoadPoint> {
        if !(x.is_finite() && y.is_finite()) {
            return None;
        }
        // Pieces whose box holds the point first: on a road surface that settles it, since
        // every other piece's surface is farther than its box.
        let mut inside = None;
        self.spatial.for_each_containing(x, y, |pi| {
            self.consider(&mut inside, pi, x, y, heading);
        });
        let best = match inside {
            Some(c) if c.distance <= LENGTH_EPSILON => Some(c),
            _ => self.best_candidate(self.spatial.nearest(x, y), x, y, heading),
        };
        best.map(|c| self.position(c, heading))
    }

    /// The position of (x, y) projected onto one given road (the nearest point of its
    /// surface if (x, y) lies off it); `None` for an unknown road or non-finite input.
    pub fn locate_on_road(&self, road_id: &str, x: Real, y: Real) -> Option<RoadPosition> {
        let p = self.locate_point_on_road(self.road_handle(road_id)?, x, y)?;
        Some(self.road_position(&p))
    }

    /// [`locate_on_road`](Self::locate_on_road) by handle: no string look-up.
    pub fn locate_point_on_road(&self, road: RoadHandle, x: Real, y: Real) -> Option<RoadPoint> {
        let ri = road.index();
        if ri >= self.roads.len() {
            return None;
        }
        if !(x.is_finite() && y.is_finite()) {
            return None;
        }
        // The road's pieces nearest box first (ties by piece order), found a few at a time.
        let pieces = PiecesByDistance::new(&self.spatial, ri, x, y);
        let best = self.best_candidate(pieces, x, y, None);
        best.map(|c| self.position(c, None))
    }

    /// The best candidate over pieces given nearest box first, as (piece, squared box
    /// distance); stops once a box lies farther than the best candidate's surface distance.
    fn best_candidate(
        &self,
        pieces: impl Iterator<Item = (usize, Real)>,
        x: Real,
        y: Real,
        heading: Option<Real>,
    ) -> Option<Candidate> {
        let mut best: Option<Candidate> = None;
        for (pi, d2) in pieces {
            if let Some(b) = &best {
                if d2.sqrt() > b.distance + LENGTH_EPSILON {
                    break;
                }
            }
            self.consider(&mut best, pi, x, y, heading);
        }
        best
    }

    /// Projects onto piece `pi` and keeps the candidate if it is better than `best`.
    #[inline]
    fn consider(
        &self,
        best: &mut Option<Candidate>,
        pi: usize,
        x: Real,
        y: Real,
        heading: Option<Real>,
    ) {
        if let Some(c) = self.candidate(&self.spatial.pieces[pi], x, y, heading) {
            if best.as_ref().is_none_or(|b| better(&c, b)) {
                *best = Some(c);
            }
        }
    }

    fn candidate(
        &self,
        piece: &Piece,
        x: Real,
        y: Real,
        heading: Option<Real>,
    ) -> Option<Candidate> {
        let road = &self.roads[piece.road];
        let (s, t, resid, road_hdg) = project(road, piece, x, y)?;
        // A foot point on a neighbouring piece leaves a residual along the road; the candidate
        // then counts that residual as distance, and the neighbouring piece (whose box is no
        // farther) gives the exact one.
        let (right, left) = piece
            .extent_at(s)
            .unwrap_or_else(|| road_extent(road, road.lane_section_at(s), s));
        let outside = (t - left).max(right - t).max(0.0);
        let along = if resid > RESIDUAL_TOLERANCE {
            resid
        } else {
            0.0
        };
        // The lane is needed here only to compare headings; kept for the result.
        let lane = heading.map(|_| lane_at(road, s, t));
        let heading_gap = match (heading, lane) {
            (Some(h), Some((lane, _))) => {
                let drive = match driving_direction(road, lane) {
                    Direction::Forward => road_hdg,
                    Direction::Backward => road_hdg + std::f64::consts::PI,
                };
                angle_difference(h, drive).abs()
            }
            _ => 0.0,
        };
        Some(Candidate {
            road: piece.road,
            s,
            t,
            distance: outside.hypot(along),
            heading_gap,
            road_hdg,
            lane,
        })
    }

    fn position(&self, c: Candidate, heading: Option<Real>) -> RoadPoint {
        let road = &self.roads[c.road];
        let (lane_id, offset) = c.lane.unwrap_or_else(|| lane_at(road, c.s, c.t));
        RoadPoint {
            road: RoadHandle(c.road as u32),
            lane_id,
            s: c.s,
            t: c.t,
            offset,
            relative_heading: heading.map_or(0.0, |h| normalize_angle(h - c.road_hdg)),
            distance: c.distance,
        }
    }

    /// The [`RoadPosition`] of a point: the road's and its junction's ids added.
    pub fn road_position(&self, p: &RoadPoint) -> RoadPosition {
        let road = self.road_at(p.road);
        RoadPosition {
            road_id: road.id.clone(),
            road: p.road,
            lane_id: p.lane_id,
            s: p.s,
            t: p.t,
            offset: p.offset,
            junction_id: road.junction.clone(),
            relative_heading: p.relative_heading,
            distance: p.distance,
        }
    }
}

/// Whether candidate `a` is preferred over `b`.
fn better(a: &Candidate, b: &Candidate) -> bool {
    if (a.distance - b.distance).abs() > 1e-9 {
        return a.distance < b.distance;
    }
    if (a.heading_gap - b.heading_gap).abs() > 1e-6 {
        return a.heading_gap < b.heading_gap;
    }
    a.t.abs() < b.t.abs()
}

/// The lane at (s, t) of `road` and the offset from its centre: the first lane, from the
/// centre outwards on t's side, whose outer border lies beyond t; the outermost lane when t is
/// off the road; the nearest lane of the other side when t's side has none.
pub(crate) fn lane_at(road: &Road, s: Real, t: Real) -> (i32, Real) {
    let section = road.lane_section_at(s);
    let (off, _) = crate::road::lane_span::lane_offset(road, s);
    let (left_n, right_n) = (section.left.len() as i32, section.right.len() as i32);
    let (sign, n) = match (t >= off, left_n > 0, right_n > 0) {
        (true, true, _) | (false, true, false) => (1, left_n),
        (_, _, true) => (-1, right_n),
        _ => return (0, t - off),
    };
    // The first lane outwards whose outer border lies beyond t; else the outermost.
    let mut last = None;
    for (lane, sp) in side_spans(road, section, s, sign > 0) {
        let beyond = if sign > 0 {
            sp.outer >= t
        } else {
            sp.outer <= t
        };
        last = Some((lane.id, sp.center()));
        if beyond && sp.width() > LENGTH_EPSILON {
            break;
        }
    }
    let (chosen, center) = last.unwrap_or((sign * n, off));
    (chosen, t - center)
}
