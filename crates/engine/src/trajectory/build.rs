//! Building a [`Trajectory`] from the scenario model (OpenSCENARIO 1.3 §6.9, XSD `Shape`):
//! each vertex, control point and start position is resolved to a world pose by the caller's
//! [`PointSource`] (the engine's position resolver for every
//! [`EntityQuery`](crate::position::EntityQuery)), the shape is checked, and its pieces and
//! times are laid out. A point's error comes back as the source's error, so does the shape's.
//!
//! Rules taken here, each from the XSD element it concerns:
//! * `Polyline`: at least two vertices; a `closed` trajectory also runs from the last vertex
//!   back to the first (that closing piece has no time). Coincident vertices add no length;
//!   with times they are a stop. When every vertex's Position states a heading the
//!   trajectory is six-dimensional (§6.9) and carries those headings (`orientation`).
//! * `Clothoid`: starts at its Position's point and heading; times only when both
//!   `startTime` and `stopTime` are given.
//! * `ClothoidSpline` (1.3): the first segment starts at its `PositionStart`, or without one
//!   where the actor stands (esmini's reading, which the corpus scenario
//!   lane-change_clothoid_spline_based_trajectory.xosc relies on); a later segment starts
//!   at its own `PositionStart` if it has one, else where the previous one ended; its heading
//!   is that start's heading plus `hOffset` (default 0). Times when a segment has
//!   `timeStart` (then the spline needs `timeEnd`); untimed segments in between are timed
//!   at constant speed between the timed points around them (see `lead_in`).
//! * `Nurbs`: order k in 2..=n for n control points, n + k knots in non-decreasing order
//!   spanning a range, weights > 0 (default 1). Control points' orientations are not used.
//! * Times: all points of a shape have a time or none has; times never decrease. A NURBS
//!   carries `ControlPoint/@time` as one more coordinate of the rational curve (the control
//!   point's time dimension), so t(u) uses the same basis functions and weights as x and y.
//!   esmini reads it differently (each time pinned where its control point's basis function
//!   peaks, linear in u between); the paths agree, the moments along them do not
//!   (test trajectory_esmini_nurbs).
//! * oscsim's `SmoothFromActor` (no XML form): from the actor's pose when the action starts
//!   (its x, y and heading) to its end position, the cubic Hermite curve of
//!   [`scenario::hermite_controls`] as a NURBS of order 4, untimed.
//! * oscsim's `LineFromActor` (no XML form): from the actor's point when the action starts to
//!   its end position, a six-dimensional Polyline facing along the line, then the end's
//!   heading at the end point (a vertex that adds no length), untimed.
//! * `closed` has no effect on Clothoid, ClothoidSpline and Nurbs (their geometry is
//!   complete as written).

use opendrive::{Pose, Real, LENGTH_EPSILON};
use scenario::{Position, Shape, SourcePos};

use super::bspline::HPoint;
use super::clothoid::Clothoid;
use super::error::{check_finite, TrajectoryError, TrajectoryErrorKind};
use super::line::Line;
use super::nurbs::Nurbs;
use super::orientation::Orientations;
use super::path::{Piece, ShapeKind};
use super::source::PointSource;
use super::time_table::TimeTable;
use super::Trajectory;

type Result<T> = std::result::Result<T, TrajectoryError>;

/// A resolved point of a shape: where, facing where (and whether the position states that
/// heading), at which time, written where.
struct Point {
    xyz: [Real; 3],
    heading: Real,
    oriented: bool,
    time: Option<Real>,
    pos: SourcePos,
}

fn point<S: PointSource + ?Sized>(
    position: &Position,
    time: Option<Real>,
    ctx: &S,
) -> std::result::Result<Point, S::Error> {
    let r = ctx.place(position)?;
    Ok(Point {
        xyz: [r.pose.x, r.pose.y, r.pose.z],
        heading: r.pose.h,
        oriented: r.oriented,
        time,
        pos: position.pos.clone(),
    })
}

/// Builds the runtime trajectory of `trajectory`, resolving its positions through `ctx`.
/// `pos` names the element that uses it (FollowTrajectoryAction, TrajectoryPosition) for
/// errors about the shape as a whole; errors about one point name that point's Position.
/// A ClothoidSpline whose first segment has no PositionStart is an error here; see
/// [`build_for_actor`].
pub fn build<S: PointSource + ?Sized>(
    trajectory: &scenario::Trajectory,
    ctx: &S,
    pos: &SourcePos,
) -> std::result::Result<Trajectory, S::Error> {
    build_for_actor(trajectory, ctx, None, pos)
}

/// As [`build`], for the trajectory of a FollowTrajectoryAction whose actor stands at
/// `actor`: a ClothoidSpline's first segment without PositionStart starts there.
pub fn build_for_actor<S: PointSource + ?Sized>(
    trajectory: &scenario::Trajectory,
    ctx: &S,
    actor: Option<&Pose>,
    pos: &SourcePos,
) -> std::result::Result<Trajectory, S::Error> {
    let name = &trajectory.name;
    let mut orientations = None;
    let (kind, pieces, times) = match &trajectory.shape {
        Shape::Polyline(vertices) => {
            if vertices.len() < 2 {
                return Err(TrajectoryError::new(
                    TrajectoryErrorKind::TooFewVertices {
                        trajectory: name.clone(),
                        found: vertices.len(),
                    },
                    pos,
                )
                .into());
            }
            let points = vertices
                .iter()
                .map(|v| point(&v.position, v.time, ctx))
                .collect::<std::result::Result<Vec<_>, _>>()?;
            let (pieces, times, headings) = polyline(&points, trajectory.closed)?;
            orientations = headings;
            (ShapeKind::Polyline, pieces, times)
        }
        Shape::Clothoid(c) => {
            let (piece, times) = clothoid(c, ctx, pos)?;
            (ShapeKind::Clothoid, vec![piece], times)
        }
        Shape::ClothoidSpline(spline) => {
            let (pieces, times) = clothoid_spline(spline, ctx, actor, pos)?;
            (ShapeKind::ClothoidSpline, pieces, times)
        }
        Shape::Nurbs(n) => {
            let (piece, times) = nurbs(name, n, ctx, pos)?;
            (ShapeKind::Nurbs, vec![piece], times)
        }
        Shape::SmoothFromActor(c) => {
            let Some(a) = actor else {
                return Err(TrajectoryError::new(TrajectoryErrorKind::NoActor, pos).into());
            };
            let (piece, times) = nurbs(name, &smooth_from(a, c, ctx)?, ctx, pos)?;
            (ShapeKind::Nurbs, vec![piece], times)
        }
        Shape::LineFromActor(c) => {
            let Some(a) = actor else {
                return Err(TrajectoryError::new(TrajectoryErrorKind::NoActor, pos).into());
            };
            let points = line_from(a, c, ctx)?;
            let (pieces, times, headings) = polyline(&points, false)?;
            orientations = headings;
            (ShapeKind::Polyline, pieces, times)
        }
        _ => {
            return Err(TrajectoryError::new(
                TrajectoryErrorKind::UnknownShape("another shape"),
                pos,
            )
            .into())
        }
    };
    let mut t = Trajectory::new(name, kind, trajectory.closed, pieces, times);
    if let Some(o) = orientations {
        t = t.with_orientations(o);
    }
    if t.length() <= LENGTH_EPSILON {
        return Err(TrajectoryError::new(TrajectoryErrorKind::ZeroLength(t.length()), pos).into());
    }
    Ok(t)
}

/// oscsim's smooth curve from the actor standing at `actor` (its x, y and heading) to
/// `c.end` (its point and heading), as the NURBS of order 4 of the Hermite curve's Bézier
/// ([`scenario::hermite_controls`]), untimed; the control points are written where the end
/// is.
fn smooth_from<S: PointSource + ?Sized>(
    actor: &Pose,
    c: &scenario::SmoothFromActor,
    ctx: &S,
) -> std::result::Result<scenario::Nurbs, S::Error> {
    let end = point(&c.end, None, ctx)?;
    let controls = scenario::hermite_controls(
        (actor.x, actor.y, actor.h),
        (end.xyz[0], end.xyz[1], end.heading),
    );
    let control_points = controls
        .iter()
        .map(|&[x, y]| scenario::ControlPoint {
            time: None,
            weight: None,
            position: Position {
                kind: scenario::PositionKind::World {
                    x,
                    y,
                    z: None,
                    h: None,
                    p: None,
                    r: None,
                },
                pos: end.pos.clone(),
            },
        })
        .collect();
    Ok(scenario::Nurbs {
        order: 4,
        control_points,
        knots: vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
    })
}

/// oscsim's straight line from the actor standing at `actor` to `c.end`: the vertices of the
/// six-dimensional Polyline (§6.9) from the actor's point to the end's at the line's heading,
/// and the end's point again at the end's heading (coincident vertices add no length, so the
/// heading turns only where the line ends), untimed.
fn line_from<S: PointSource + ?Sized>(
    actor: &Pose,
    c: &scenario::LineFromActor,
    ctx: &S,
) -> std::result::Result<Vec<Point>, S::Error> {
    let end = point(&c.end, None, ctx)?;
    let along = (end.xyz[1] - actor.y).atan2(end.xyz[0] - actor.x);
    let at = |xyz: [Real; 3], heading: Real| Point {
        xyz,
        heading,
        oriented: true,
        time: None,
        pos: end.pos.clone(),
    };
    Ok(vec![
        at([actor.x, actor.y, actor.z], along),
        at(end.xyz, along),
        at(end.xyz, end.heading),
    ])
}

/// The times of `points` if every one has a time (non-decreasing), `None` if none has.
fn point_times(points: &[Point], element: &'static str) -> Result<Option<Vec<Real>>> {
    if points.iter().all(|p| p.time.is_none()) {
        return Ok(None);
    }
    let mut times = Vec::with_capacity(points.len());
    for (i, p) in points.iter().enumerate() {
        let t = p.time.ok_or_else(|| {
            TrajectoryError::new(
                TrajectoryErrorKind::PartialTimes {
                    element,
                    index: i + 1,
                },
                &p.pos,
            )
        })?;
        check_finite(&[("time", t)], &p.pos)?;
        ordered_time(times.last().copied(), t, element, i, &p.pos)?;
        times.push(t);
    }
    Ok(Some(times))
}

/// `Err` when `t` comes before `previous`.
fn ordered_time(
    previous: Option<Real>,
    t: Real,
    element: &'static str,
    i: usize,
    pos: &SourcePos,
) -> Result<()> {
    match previous {
        Some(previous) if t < previous => Err(TrajectoryError::new(
            TrajectoryErrorKind::TimesOutOfOrder {
                element,
                index: i + 1,
                previous,
                found: t,
            },
            pos,
        )),
        _ => Ok(()),
    }
}

/// The pieces of a Polyline, its times, and its vertex headings when every vertex states one
/// (a six-dimensional trajectory, §6.9).
fn polyline(
    points: &[Point],
    closed: bool,
) -> Result<(Vec<Piece>, Option<TimeTable>, Option<Orientations>)> {
    let times = point_times(points, "Vertex")?;
    let mut pieces = Vec::with_capacity(points.len());
    let mut s_at_vertex = vec![0.0];
    let mut s = 0.0;
    let mut ends: Vec<(&Point, &Point)> = points.windows(2).map(|w| (&w[0], &w[1])).collect();
    if closed {
        ends.push((&points[points.len() - 1], &points[0]));
    }
    for (i, (a, b)) in ends.into_iter().enumerate() {
        if let Some(line) = Line::new(a.xyz, b.xyz) {
            s += line.length();
            pieces.push(Piece::Line(line));
        }
        if i + 1 < points.len() {
            s_at_vertex.push(s);
        }
    }
    let mut headings: Vec<Real> = points.iter().map(|p| p.heading).collect();
    let mut s_headings = s_at_vertex.clone();
    if closed {
        // The closing piece turns back to the first vertex's heading.
        s_headings.push(s);
        headings.push(points[0].heading);
    }
    let orientations = points
        .iter()
        .all(|p| p.oriented)
        .then(|| Orientations::new(s_headings, headings));
    let table = times.map(|t| TimeTable::new(s_at_vertex.into_iter().zip(t).collect()));
    Ok((pieces, table, orientations))
}

fn positive_length(what: &'static str, length: Real, pos: &SourcePos) -> Result<()> {
    check_finite(&[(what, length)], pos)?;
    if length <= 0.0 {
        return Err(TrajectoryError::new(
            TrajectoryErrorKind::NonPositiveLength {
                what,
                found: length,
            },
            pos,
        ));
    }
    Ok(())
}

fn clothoid<S: PointSource + ?Sized>(
    c: &scenario::Clothoid,
    ctx: &S,
    pos: &SourcePos,
) -> std::result::Result<(Piece, Option<TimeTable>), S::Error> {
    check_finite(
        &[
            ("Clothoid curvature", c.curvature),
            ("Clothoid curvaturePrime", c.curvature_prime),
        ],
        pos,
    )?;
    positive_length("Clothoid length", c.length, pos)?;
    let start = point(&c.position, None, ctx)?;
    let piece = Clothoid::new(
        start.xyz,
        start.heading,
        c.curvature,
        c.curvature_prime,
        c.length,
    );
    let times = match (c.start_time, c.stop_time) {
        (Some(t0), Some(t1)) => {
            check_finite(
                &[("Clothoid startTime", t0), ("Clothoid stopTime", t1)],
                pos,
            )?;
            ordered_time(Some(t0), t1, "Clothoid stopTime", 0, pos)?;
            Some(TimeTable::new(vec![(0.0, t0), (c.length, t1)]))
        }
        _ => None,
    };
    Ok((Piece::Clothoid(piece), times))
}

fn clothoid_spline<S: PointSource + ?Sized>(
    spline: &scenario::ClothoidSpline,
    ctx: &S,
    actor: Option<&Pose>,
    pos: &SourcePos,
) -> std::result::Result<(Vec<Piece>, Option<TimeTable>), S::Error> {
    if spline.segments.is_empty() {
        return Err(TrajectoryError::new(TrajectoryErrorKind::NoSegments, pos).into());
    }
    let mut pieces = Vec::with_capacity(spline.segments.len());
    let mut end: Option<([Real; 3], Real)> = None;
    let mut pairs = Vec::with_capacity(spline.segments.len() + 1);
    let mut s = 0.0;
    let any_timed = spline.segments.iter().any(|g| g.time_start.is_some());
    for (i, seg) in spline.segments.iter().enumerate() {
        let h_offset = seg.h_offset.unwrap_or(0.0);
        check_finite(
            &[
                ("ClothoidSplineSegment curvatureStart", seg.curvature_start),
                ("ClothoidSplineSegment curvatureEnd", seg.curvature_end),
                ("ClothoidSplineSegment hOffset", h_offset),
            ],
            pos,
        )?;
        positive_length("ClothoidSplineSegment length", seg.length, pos)?;
        let (xyz, heading) = match (&seg.position_start, end) {
            (Some(p), _) => {
                let p = point(p, None, ctx)?;
                (p.xyz, p.heading)
            }
            (None, Some(e)) => e,
            (None, None) if actor.is_some() => {
                let a = actor.copied().unwrap_or_default();
                ([a.x, a.y, a.z], a.h)
            }
            (None, None) => {
                return Err(
                    TrajectoryError::new(TrajectoryErrorKind::MissingPositionStart, pos).into(),
                )
            }
        };
        let rate = (seg.curvature_end - seg.curvature_start) / seg.length;
        let c = Clothoid::new(
            xyz,
            heading + h_offset,
            seg.curvature_start,
            rate,
            seg.length,
        );
        let last = c.eval(seg.length);
        end = Some(([last.x, last.y, last.z], last.heading));
        if let Some(t) = seg.time_start {
            check_finite(&[("ClothoidSplineSegment timeStart", t)], pos)?;
            ordered_time(
                pairs.last().map(|p: &(Real, Real)| p.1),
                t,
                "ClothoidSplineSegment",
                i,
                pos,
            )?;
            pairs.push((s, t));
        }
        s += seg.length;
        pieces.push(Piece::Clothoid(c));
    }
    let times = if any_timed {
        let t_end = spline
            .time_end
            .ok_or_else(|| TrajectoryError::new(TrajectoryErrorKind::MissingTimeEnd, pos))?;
        check_finite(&[("ClothoidSpline timeEnd", t_end)], pos)?;
        if let Some(&(_, previous)) = pairs.last().filter(|p| t_end < p.1) {
            return Err(TrajectoryError::new(
                TrajectoryErrorKind::TimeEndTooEarly {
                    previous,
                    found: t_end,
                },
                pos,
            )
            .into());
        }
        pairs.push((s, t_end));
        Some(TimeTable::new(lead_in(pairs)))
    } else {
        None
    };
    Ok((pieces, times))
}

/// The (s, t) pairs of a ClothoidSpline whose timed segment starts and end are `anchors` (at
/// least two, s increasing), from the spline's start. A segment without `timeStart` is no
/// timing point: between two timed points the speed is constant, and segments before the
/// first timed one continue the speed of the first timed stretch backwards to s = 0. The 1.3
/// XSD makes every `timeStart` optional and asks only for `timeEnd` once one is given; the
/// standard does not say how untimed segments are timed, this is oscsim's reading.
fn lead_in(mut anchors: Vec<(Real, Real)>) -> Vec<(Real, Real)> {
    if let (Some(&(s0, t0)), Some(&(s1, t1))) = (anchors.first(), anchors.get(1)) {
        // s1 > s0 > 0: anchors sit at distinct segment starts or the spline's end, each
        // segment of positive length.
        if s0 > 0.0 && s1 > s0 {
            anchors.insert(0, (0.0, t0 - s0 * (t1 - t0) / (s1 - s0)));
        }
    }
    anchors
}

fn nurbs<S: PointSource + ?Sized>(
    name: &str,
    n: &scenario::Nurbs,
    ctx: &S,
    pos: &SourcePos,
) -> std::result::Result<(Piece, Option<TimeTable>), S::Error> {
    let count = n.control_points.len();
    let err = |kind| Err(TrajectoryError::new(kind, pos).into());
    if count < 2 {
        return err(TrajectoryErrorKind::TooFewControlPoints {
            trajectory: name.to_string(),
            found: count,
        });
    }
    if n.order < 2 || n.order as usize > count {
        return err(TrajectoryErrorKind::Order {
            order: n.order,
            points: count,
        });
    }
    let order = n.order as usize;
    if n.knots.len() != count + order {
        return err(TrajectoryErrorKind::KnotCount {
            expected: count + order,
            found: n.knots.len(),
        });
    }
    for (i, &k) in n.knots.iter().enumerate() {
        check_finite(&[("Knot value", k)], pos)?;
        if i > 0 && k < n.knots[i - 1] {
            return err(TrajectoryErrorKind::KnotsOutOfOrder {
                index: i + 1,
                previous: n.knots[i - 1],
                found: k,
            });
        }
    }
    let degree = order - 1;
    if n.knots[degree] >= n.knots[count] {
        return err(TrajectoryErrorKind::EmptyKnotRange {
            first: degree + 1,
            last: count + 1,
            value: n.knots[degree],
        });
    }
    let mut points = Vec::with_capacity(count);
    let mut control: Vec<HPoint> = Vec::with_capacity(count);
    for (i, cp) in n.control_points.iter().enumerate() {
        let w = cp.weight.unwrap_or(1.0);
        if !(w.is_finite() && w > 0.0) {
            return Err(TrajectoryError::new(
                TrajectoryErrorKind::Weight {
                    index: i + 1,
                    found: w,
                },
                &cp.position.pos,
            )
            .into());
        }
        let p = point(&cp.position, cp.time, ctx)?;
        let [x, y, z] = p.xyz;
        control.push([w * x, w * y, w * z, w, w * p.time.unwrap_or(0.0)]);
        points.push(p);
    }
    let timed = point_times(&points, "ControlPoint")?.is_some();
    let curve = Nurbs::new(degree, n.knots.clone(), control);
    let times = timed.then(|| TimeTable::new(curve.time_samples()));
    Ok((Piece::Nurbs(Box::new(curve)), times))
}
