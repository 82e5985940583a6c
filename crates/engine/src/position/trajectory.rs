//! Positions on a trajectory (OpenSCENARIO 1.3 §7.6 "Trajectories", XSD `TrajectoryPosition`,
//! 1.1+): the point at arc length `s` along the trajectory's shape, moved `t` to its left.
//!
//! Supported shape: `Polyline` (vertices joined by straight segments; a closed trajectory
//! also joins the last vertex to the first). s is the horizontal length along the segments;
//! z is interpolated linearly between the vertices; t is measured horizontally to the left of
//! the segment's direction. Relative headings count from that direction. `Clothoid`,
//! `ClothoidSpline` and `Nurbs` shapes are reported as unsupported.

use opendrive::{normalize_angle, Pose, Real};
use scenario::{Orientation, Shape, SourcePos, Trajectory};

use super::orientation::{absolute_or, Angles};
use super::world::finite;
use super::{resolve, EntityQuery, PositionError, PositionErrorKind, ResolvedPosition};

/// `TrajectoryPosition`.
pub(crate) fn trajectory_position<Q: EntityQuery + ?Sized>(
    ctx: &Q,
    trajectory: &Trajectory,
    s: Real,
    t: Real,
    orientation: Option<&Orientation>,
    pos: &SourcePos,
) -> Result<ResolvedPosition, PositionError> {
    finite(&[("s", s), ("t", t)], pos)?;
    let unsupported = |found| {
        PositionError::new(
            PositionErrorKind::Unsupported {
                expected: "a Polyline trajectory shape",
                found,
            },
            pos,
        )
    };
    let vertices = match &trajectory.shape {
        Shape::Polyline(v) => v,
        Shape::Clothoid(_) => return Err(unsupported("a Clothoid")),
        Shape::ClothoidSpline(_) => return Err(unsupported("a ClothoidSpline")),
        Shape::Nurbs(_) => return Err(unsupported("a Nurbs")),
        _ => return Err(unsupported("an unknown shape")),
    };
    if vertices.len() < 2 {
        return Err(PositionError::new(
            PositionErrorKind::TooFewVertices {
                trajectory: trajectory.name.clone(),
                found: vertices.len(),
            },
            pos,
        ));
    }
    let mut points = Vec::with_capacity(vertices.len() + 1);
    for v in vertices {
        points.push(resolve(&v.position, ctx)?.pose);
    }
    if trajectory.closed {
        points.push(points[0]);
    }
    let length: Real = points
        .windows(2)
        .map(|w| (w[1].x - w[0].x).hypot(w[1].y - w[0].y))
        .sum();
    if !(0.0..=length + opendrive::S_TOLERANCE).contains(&s) {
        return Err(PositionError::new(
            PositionErrorKind::OutsideTrajectory {
                trajectory: trajectory.name.clone(),
                s,
                length,
            },
            pos,
        ));
    }
    // The segment holding s: the first non-degenerate one whose end reaches s, else the last.
    let mut start = 0.0;
    let mut seg = points.len() - 2;
    for (i, w) in points.windows(2).enumerate() {
        let len = (w[1].x - w[0].x).hypot(w[1].y - w[0].y);
        if s <= start + len && len > 0.0 {
            seg = i;
            break;
        }
        start += len;
    }
    if seg == points.len() - 2 {
        start =
            length - (points[seg + 1].x - points[seg].x).hypot(points[seg + 1].y - points[seg].y);
    }
    let (a, b) = (&points[seg], &points[seg + 1]);
    let len = (b.x - a.x).hypot(b.y - a.y);
    let u = if len > 0.0 {
        ((s - start) / len).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let h = (b.y - a.y).atan2(b.x - a.x);
    let (sin_h, cos_h) = h.sin_cos();
    let base = Angles {
        h: normalize_angle(h),
        p: 0.0,
        r: 0.0,
    };
    let o = absolute_or(orientation, base);
    let pose = Pose {
        x: a.x + u * (b.x - a.x) - t * sin_h,
        y: a.y + u * (b.y - a.y) + t * cos_h,
        z: a.z + u * (b.z - a.z),
        h: o.h,
        p: o.p,
        r: o.r,
    };
    Ok(ResolvedPosition::located(ctx.road_network(), pose))
}
