//! The shapes a DSL path or trajectory is lowered to (ASAM OpenSCENARIO DSL 2.1 §8.12
//! `path_interpolation`: `straight_line`, `smooth`), as the Shape of a 1.x
//! FollowTrajectoryAction (OpenSCENARIO 1.3 §6.9, XSD `Polyline`, `Nurbs`):
//!
//! | interpolation | Shape |
//! | --- | --- |
//! | `straight_line` | Polyline through the points; the headings are the segments' (`change_position`'s line ends facing along the target's lane: `line_ending_along`) |
//! | `smooth` | the cubic Hermite curve through the points with their headings, as a Nurbs of order 4 |
//!
//! The standard says only that `smooth` is "a smooth curve" through the points. oscsim takes
//! the cubic Hermite curve, the usual smooth interpolation of poses: between points P₀ (heading
//! h₀) and P₁ (heading h₁), L = |P₁ − P₀| apart, the cubic Bézier with control points P₀,
//! P₀ + L/3·(cos h₀, sin h₀), P₁ − L/3·(cos h₁, sin h₁), P₁ (tangents of length L, the
//! "chord" scaling: a curve between two points of the same heading on one line is the line).
//! The segments are joined as one B-spline of order 4 whose inner knots have multiplicity 3,
//! so it passes through every point with that point's heading (tangent-continuous). Times
//! are a coordinate of the control points (t₀, t₀ + Δ/3, t₀ + 2Δ/3, t₁ for a segment of Δ):
//! the engine's NURBS time t(u) is then linear in u on each segment, so the actor is at each
//! point at its time stamp, and half-way through a segment's time at the Bézier's u = ½,
//! (P₀ + 3C₁ + 3C₂ + P₁)/8.
//!
//! Written here rather than taken from a crate: the Bézier control points are four lines, and
//! the engine has the NURBS evaluation; [`length`] (Gauss–Legendre quadrature of |B′|) is the
//! plan's estimate of when an untimed smooth path ends.

use scenario::{
    ControlPoint, FollowingMode, LineFromActor, Nurbs, Position, PositionKind, PrivateAction,
    ReferenceContext, RoutingAction, Shape, SmoothFromActor, Timing, Trajectory, TrajectoryAtSpeed,
    Vertex,
};

use crate::error::Site;

/// A point of a path: world x, y (m) and heading (rad).
pub(crate) type Pose2 = (f64, f64, f64);

/// Gauss–Legendre 5-point nodes on [−1, 1] and weights (Abramowitz & Stegun, table 25.4).
const GL5: [(f64, f64); 5] = [
    (0.0, 0.568_888_888_888_888_9),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

/// Panels of [`integrate01`]: 16 five-point panels integrate the speed of these smooth cubics
/// (and of a sinusoidal lane change) to far below a millimetre.
const PANELS: usize = 16;

/// The control points of the smooth curve through `points`: 3n − 2 for n points (each
/// segment's P₀, C₁, C₂, with the last point once).
pub(crate) fn hermite_controls(points: &[Pose2]) -> Vec<[f64; 2]> {
    let mut out = Vec::with_capacity(3 * points.len());
    for w in points.windows(2) {
        out.extend_from_slice(&scenario::hermite_controls(w[0], w[1])[..3]);
    }
    if let Some(&(x, y, _)) = points.last() {
        out.push([x, y]);
    }
    out
}

/// Arc length (m) of the smooth curve through `points`.
pub(crate) fn length(points: &[Pose2]) -> f64 {
    let c = hermite_controls(points);
    c.windows(4)
        .step_by(3)
        .map(|b| integrate01(|u| bezier_speed(b, u)))
        .sum()
}

/// |B′(u)| of the cubic Bézier with control points `c` (four).
fn bezier_speed(c: &[[f64; 2]], u: f64) -> f64 {
    let v = 1.0 - u;
    let d = |i: usize| {
        3.0 * (v * v * (c[1][i] - c[0][i])
            + 2.0 * u * v * (c[2][i] - c[1][i])
            + u * u * (c[3][i] - c[2][i]))
    };
    d(0).hypot(d(1))
}

/// ∫₀¹ f(u) du by [`PANELS`] five-point Gauss–Legendre panels (exact for polynomials up to
/// degree 9 on each panel; far below a millimetre for the smooth integrands here).
pub(crate) fn integrate01(f: impl Fn(f64) -> f64) -> f64 {
    let h = 1.0 / PANELS as f64;
    (0..PANELS)
        .map(|k| {
            let mid = (k as f64 + 0.5) * h;
            GL5.iter()
                .map(|(x, w)| w * f(mid + x * h / 2.0))
                .sum::<f64>()
                * h
                / 2.0
        })
        .sum()
}

/// The length (m) of each segment of the path through `points`: its chord, or its smooth
/// curve's.
pub(crate) fn segment_lengths(points: &[Pose2], smooth_curve: bool) -> Vec<f64> {
    points
        .windows(2)
        .map(|w| {
            if smooth_curve {
                length(w)
            } else {
                (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1)
            }
        })
        .collect()
}

/// Where the path through `points` is `d` m from its start: the segment k, the fraction u of
/// it (the chord's fraction, or the Bézier parameter, found by bisection on its arc length; a
/// segment's time runs linearly in u either way), the point (x, y), and the rate of length in
/// u there (m per unit u: the chord, or |B′(u)|).
pub(crate) fn locate(
    points: &[Pose2],
    smooth_curve: bool,
    d: f64,
) -> (usize, f64, (f64, f64), f64) {
    let lengths = segment_lengths(points, smooth_curve);
    let mut left = d.max(0.0);
    let last = lengths.len().saturating_sub(1);
    let found = lengths.iter().position(|l| {
        let here = left <= *l;
        if !here {
            left -= l;
        }
        here
    });
    // Beyond the last segment (d at or past the path's length, or above the sum of the
    // lengths by its rounding): the path's end, not what the subtractions left over.
    let (k, left) = match found {
        Some(k) => (k, left),
        None => (last, lengths.get(last).copied().unwrap_or(0.0)),
    };
    let (a, b) = (points[k], points[k + 1]);
    if !smooth_curve {
        let u = if lengths[k] > 0.0 {
            (left / lengths[k]).clamp(0.0, 1.0)
        } else {
            0.0
        };
        return (
            k,
            u,
            (a.0 + u * (b.0 - a.0), a.1 + u * (b.1 - a.1)),
            lengths[k],
        );
    }
    let c = hermite_controls(&[a, b]);
    let speed = |u: f64| bezier_speed(&c, u);
    // ∫₀ᵘ |B′| = u·∫₀¹ |B′(u·w)| dw, rising in u: bisection to 1e-12 of the parameter.
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..42 {
        let mid = 0.5 * (lo + hi);
        if mid * integrate01(|w| speed(mid * w)) < left {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let u = 0.5 * (lo + hi);
    let v = 1.0 - u;
    let at = |i: usize| {
        v * v * v * c[0][i]
            + 3.0 * v * v * u * c[1][i]
            + 3.0 * v * u * u * c[2][i]
            + u * u * u * c[3][i]
    };
    (k, u, (at(0), at(1)), speed(u))
}

/// `action` (a FollowTrajectoryAction) starting `d` m along its trajectory (1.x
/// initialDistanceOffset: the time to reach that point is deducted from the trajectory's).
pub(crate) fn starting_at(action: PrivateAction, d: f64) -> PrivateAction {
    match action {
        PrivateAction::Routing(mut r) => {
            if let RoutingAction::FollowTrajectory {
                initial_distance_offset,
                ..
            } = r.as_mut()
            {
                *initial_distance_offset = (d > 0.0).then_some(d);
            }
            PrivateAction::Routing(r)
        }
        other => other,
    }
}

/// A world position (x, y; the road surface's z) written at `site`.
fn world(x: f64, y: f64, site: &Site) -> Position {
    Position {
        kind: world_point(x, y),
        pos: site.pos.clone(),
    }
}

/// A WorldPosition at (x, y), the rest of the pose left to the trajectory.
pub(crate) fn world_point(x: f64, y: f64) -> PositionKind {
    PositionKind::World {
        x,
        y,
        z: None,
        h: None,
        p: None,
        r: None,
    }
}

/// A FollowTrajectoryAction along the polyline through `points` (world x, y; headings those
/// of its segments), at the speed the actor has or, with `times`, reaching each point at its
/// time stamp counted from the action's start (the first stamp at the start).
pub(crate) fn polyline(
    name: &str,
    points: &[(f64, f64)],
    times: Option<&[f64]>,
    mode: FollowingMode,
    site: &Site,
) -> PrivateAction {
    let kinds = points.iter().map(|&(x, y)| world_point(x, y)).collect();
    polyline_through(name, kinds, times, mode, site)
}

/// [`polyline`] through positions of any kind, which the engine resolves when the action
/// starts.
pub(crate) fn polyline_through(
    name: &str,
    kinds: Vec<PositionKind>,
    times: Option<&[f64]>,
    mode: FollowingMode,
    site: &Site,
) -> PrivateAction {
    let first = times.and_then(|t| t.first().copied()).unwrap_or(0.0);
    let vertices = kinds
        .into_iter()
        .enumerate()
        .map(|(i, kind)| Vertex {
            time: times.map(|t| t[i] - first),
            position: Position {
                kind,
                pos: site.pos.clone(),
            },
        })
        .collect();
    follow(name, Shape::Polyline(vertices), times.is_some(), mode)
}

/// A FollowTrajectoryAction along the straight line from `from` to `to`'s point at the speed
/// the actor has, facing along the line, that leaves the actor facing `to`'s heading where it
/// ends: a six-dimensional Polyline (§6.9, every vertex's Position states a heading) of the
/// line's two ends at the line's heading and a last vertex at the end point again at `to`'s
/// heading, which adds no length (coincident vertices), so the heading turns only at the
/// line's end (`change_position`'s straight line ends along the target's lane: the default
/// controller "maintains lane offset", §7.5.1, and keeps the heading it is handed).
pub(crate) fn line_ending_along(
    name: &str,
    (x0, y0): (f64, f64),
    (x1, y1, h1): Pose2,
    site: &Site,
) -> PrivateAction {
    let along = (y1 - y0).atan2(x1 - x0);
    let oriented = |x, y, h| PositionKind::World {
        x,
        y,
        z: None,
        h: Some(h),
        p: None,
        r: None,
    };
    let kinds = vec![
        oriented(x0, y0, along),
        oriented(x1, y1, along),
        oriented(x1, y1, h1),
    ];
    polyline_through(name, kinds, None, FollowingMode::Position, site)
}

/// A FollowTrajectoryAction along the smooth curve through `points` (two or more, consecutive
/// ones apart), timed as [`polyline`].
pub(crate) fn smooth(
    name: &str,
    points: &[Pose2],
    times: Option<&[f64]>,
    mode: FollowingMode,
    site: &Site,
) -> PrivateAction {
    let first = times.and_then(|t| t.first().copied()).unwrap_or(0.0);
    // Control point i belongs to segment i / 3, a third of its time further per point.
    let time = |i: usize| {
        times.map(|t| {
            let (seg, third) = (i / 3, (i % 3) as f64 / 3.0);
            match t.get(seg + 1) {
                Some(next) => t[seg] + third * (next - t[seg]) - first,
                None => t[seg] - first,
            }
        })
    };
    let control_points: Vec<ControlPoint> = hermite_controls(points)
        .into_iter()
        .enumerate()
        .map(|(i, [x, y])| ControlPoint {
            time: time(i),
            weight: None,
            position: world(x, y, site),
        })
        .collect();
    // Order 4 (cubic): a clamped knot vector with every segment's end knot three times.
    let segments = points.len().saturating_sub(1);
    let mut knots = vec![0.0; 4];
    for k in 1..segments {
        knots.extend([k as f64; 3]);
    }
    knots.extend([segments as f64; 4]);
    follow(
        name,
        Shape::Nurbs(Nurbs {
            order: 4,
            control_points,
            knots,
        }),
        times.is_some(),
        mode,
    )
}

/// A FollowTrajectoryAction from where the engine finds the actor when the action starts to
/// `end` (its heading), untimed (shapes with no XML form): with `smooth` oscsim's smooth curve
/// from the actor (scenario `Shape::SmoothFromActor`: the curve [`smooth`] builds, from the
/// actor's heading then), else oscsim's straight line from the actor (`Shape::LineFromActor`:
/// the line [`line_ending_along`] builds, facing along it, then `end`'s heading where it
/// ends).
pub(crate) fn from_actor(
    name: &str,
    end: Pose2,
    smooth: bool,
    mode: FollowingMode,
    site: &Site,
) -> PrivateAction {
    let (x, y, h) = end;
    let end = Position {
        kind: PositionKind::World {
            x,
            y,
            z: None,
            h: Some(h),
            p: None,
            r: None,
        },
        pos: site.pos.clone(),
    };
    let shape = if smooth {
        Shape::SmoothFromActor(SmoothFromActor { end })
    } else {
        Shape::LineFromActor(LineFromActor { end })
    };
    follow(name, shape, false, mode)
}

/// oscsim's FollowTrajectoryAction timed at `lead`'s speed (scenario
/// `RoutingAction::FollowTrajectoryAtSpeed`, no XML form) along the points of a trajectory
/// ([`along`]): point k is reached at `times[k]` + `distances[k]` / v₀ after the first stamp,
/// v₀ `lead`'s speed when the action starts (a smooth curve's control points at the same
/// thirds of both, so each segment's time stays linear in its parameter). `what` names it
/// for the engine's error when `lead` stands.
pub(crate) fn along_at_speed(
    name: &str,
    (points, times, distances): (&[Pose2], &[f64], &[f64]),
    smooth_curve: bool,
    (lead, what): (&str, String),
    site: &Site,
) -> PrivateAction {
    let mode = FollowingMode::Position;
    let timed = along(name, points, Some(times), smooth_curve, mode, site);
    // The same shape with the distances as its stamps: each point's distance, in order.
    let by = along(name, points, Some(distances), smooth_curve, mode, site);
    let (Some((trajectory, Some(time_reference))), Some((by, _))) =
        (trajectory_of(timed), trajectory_of(by))
    else {
        unreachable!("along() builds a FollowTrajectoryAction, timed when given times")
    };
    let distances = point_times(&by.shape);
    PrivateAction::Routing(Box::new(RoutingAction::FollowTrajectoryAtSpeed(Box::new(
        TrajectoryAtSpeed {
            trajectory,
            time_reference,
            following_mode: mode,
            entity_ref: lead.to_string(),
            distances,
            what,
        },
    ))))
}

/// The trajectory and time reference of a FollowTrajectoryAction.
fn trajectory_of(action: PrivateAction) -> Option<(Trajectory, Option<Timing>)> {
    match action {
        PrivateAction::Routing(r) => match *r {
            RoutingAction::FollowTrajectory {
                trajectory,
                time_reference,
                ..
            } => Some((*trajectory, time_reference)),
            _ => None,
        },
        _ => None,
    }
}

/// The times of a shape's points in order (a Polyline's vertices, a Nurbs's control points;
/// 0 where a point has none).
fn point_times(shape: &Shape) -> Vec<f64> {
    match shape {
        Shape::Polyline(v) => v.iter().map(|p| p.time.unwrap_or(0.0)).collect(),
        Shape::Nurbs(n) => n
            .control_points
            .iter()
            .map(|p| p.time.unwrap_or(0.0))
            .collect(),
        _ => Vec::new(),
    }
}

/// A FollowTrajectoryAction along the points of a path or trajectory: the [`smooth`] curve
/// through them when `smooth`, else the [`polyline`].
pub(crate) fn along(
    name: &str,
    points: &[Pose2],
    times: Option<&[f64]>,
    smooth_curve: bool,
    mode: FollowingMode,
    site: &Site,
) -> PrivateAction {
    if smooth_curve {
        smooth(name, points, times, mode, site)
    } else {
        let xy: Vec<(f64, f64)> = points.iter().map(|&(x, y, _)| (x, y)).collect();
        polyline(name, &xy, times, mode, site)
    }
}

/// A FollowTrajectoryAction along `shape` in following `mode` (`position`: exactly on it;
/// `follow`: steered along it within the vehicle's limits), with a relative time reference
/// when it is `timed`.
fn follow(name: &str, shape: Shape, timed: bool, mode: FollowingMode) -> PrivateAction {
    PrivateAction::Routing(Box::new(RoutingAction::FollowTrajectory {
        trajectory: Box::new(Trajectory {
            name: name.to_string(),
            closed: false,
            shape,
            catalog: None,
        }),
        time_reference: timed.then_some(Timing {
            domain_absolute_relative: ReferenceContext::Relative,
            offset: 0.0,
            scale: 1.0,
        }),
        following_mode: mode,
        initial_distance_offset: None,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Closed forms of these tests are exact up to round-off (m).
    const TOL: f64 = 1e-9;

    #[test]
    fn points_on_one_line_with_its_heading_give_the_line() {
        // Three points along x with heading 0: the control points are at thirds, and the
        // length is the line's, 30 m.
        let pts = [(0.0, 0.0, 0.0), (12.0, 0.0, 0.0), (30.0, 0.0, 0.0)];
        let c = hermite_controls(&pts);
        let xs: Vec<f64> = c.iter().map(|p| p[0]).collect();
        let want = [0.0, 4.0, 8.0, 12.0, 18.0, 24.0, 30.0];
        assert_eq!(xs.len(), want.len());
        for (x, w) in xs.iter().zip(want) {
            assert!((x - w).abs() < TOL, "{xs:?}");
        }
        assert!((length(&pts) - 30.0).abs() < TOL);
    }

    #[test]
    fn a_quarter_turn_is_longer_than_its_chord_and_shorter_than_its_control_polygon() {
        // (0, 0) heading 0 to (10, 10) heading π/2: chord 14.142 m; control polygon
        // 4.714 + |(10 − 4.714, 10 − 4.714)| + 4.714 = 4.714·2 + 7.475 = 16.903 m. A cubic
        // lies within the hull of its control polygon, so its length lies in between. It is
        // flatter than the quarter circle of radius 10 (15.708 m; the circle's Bézier has
        // tangents of 5.523 m, these 4.714 m): 15.372 m, summed over 20,000 chords.
        let pts = [(0.0, 0.0, 0.0), (10.0, 10.0, std::f64::consts::FRAC_PI_2)];
        let l = length(&pts);
        assert!(l > 14.142 && l < 16.903, "{l}");
        // Chords undercut the arc by O(1/n²): 1e-6 m covers them.
        assert!((l - 15.372_358).abs() < 1e-6, "{l}");
    }

    #[test]
    fn the_end_of_a_path_is_its_last_point_whatever_the_sum_rounds_to() {
        // opposite_paths.osc's trajectory: two chords of 20.024984 m whose sum rounds above
        // what subtracting the first leaves of it against the second (the last segment's u
        // came out 1.8e-16, its start, and the trajectory's end time that of its middle point).
        let pts = [
            (196.147505, 25.249188, 0.0),
            (176.745255, 20.29412, 0.0),
            (157.934046, 13.428379, 0.0),
        ];
        let total: f64 = segment_lengths(&pts, false).iter().sum();
        let (k, u, (x, y), _) = locate(&pts, false, total);
        assert_eq!(k, 1);
        assert!((u - 1.0).abs() < TOL, "{u}");
        assert!((x - 157.934046).abs() < TOL && (y - 13.428379).abs() < TOL);
        // Past the end: the end.
        let (k, u, _, _) = locate(&pts, false, total + 5.0);
        assert!(k == 1 && (u - 1.0).abs() < TOL, "{k} {u}");
    }
}
