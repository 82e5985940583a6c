//! Positions on a trajectory (OpenSCENARIO 1.3 §7.6 "Trajectories", XSD `TrajectoryPosition`,
//! 1.1+): the point at arc length `s` along the trajectory's shape, moved `t` to its left.
//!
//! The shape is evaluated by `crate::trajectory` (Polyline, Clothoid, ClothoidSpline, Nurbs;
//! s is the horizontal arc length, t horizontal and to the left of the heading at s, z from
//! the shape). Relative headings count from the trajectory's heading at s; pitch and roll are
//! 0 unless written. A ClothoidSpline whose first segment has no PositionStart has no place
//! of its own outside a FollowTrajectoryAction, and is reported as such.

use opendrive::{normalize_angle, Pose, Real};
use scenario::{Orientation, SourcePos, Trajectory};

use super::orientation::{absolute_or, Angles};
use super::world::finite;
use super::{EntityQuery, PositionError, PositionErrorKind, ResolvedPosition};

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
    // A point's own position error as it is; an error of the shape at this position.
    let shape = crate::trajectory::build(trajectory, ctx, pos).map_err(|e| match e.kind() {
        PositionErrorKind::Trajectory(shape) => {
            PositionError::new(PositionErrorKind::Trajectory(shape.clone()), pos)
        }
        _ => e,
    })?;
    let length = shape.length();
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
    let p = shape.eval(s);
    let (sin_h, cos_h) = p.heading.sin_cos();
    let base = Angles {
        h: normalize_angle(p.heading),
        p: 0.0,
        r: 0.0,
    };
    let o = absolute_or(orientation, base);
    let pose = Pose {
        x: p.x - t * sin_h,
        y: p.y + t * cos_h,
        z: p.z,
        h: o.h,
        p: o.p,
        r: o.r,
    };
    Ok(ResolvedPosition::located(ctx.road_network(), pose))
}
