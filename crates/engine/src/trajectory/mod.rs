//! Trajectory shapes at runtime (OpenSCENARIO 1.3 §6.9 "Trajectories", XSD `Trajectory`,
//! `Shape`, `Polyline`, `Clothoid`, `ClothoidSpline`, `Nurbs`, `TimeReference`, `Timing`):
//! a [`Trajectory`] evaluated by horizontal arc length s, with s(t) and t(s) where the shape
//! carries times, and the closest point to a world position.
//!
//! Files are named for what they compute:
//!
//! | module | implements |
//! | --- | --- |
//! | `error` | `TrajectoryError`, `TrajectoryErrorKind` |
//! | `point` | `TrajectoryPoint`: x, y, z, heading, curvature at s |
//! | `line` | one straight piece of a Polyline |
//! | `clothoid` | one clothoid piece (Clothoid, ClothoidSplineSegment) on the opendrive spiral |
//! | `bspline` | B-spline evaluation by de Boor's algorithm (Cox–de Boor recursion) and its derivative |
//! | `nurbs` | Nurbs: rational curve, validation, arc-length table, time samples |
//! | `orientation` | the headings along a six-dimensional Polyline (§6.9) |
//! | `time_table` | the (s, t) pairs of vertices and segment times; s(t), t(s) |
//! | `follow` | TrajectoryFollowingMode `follow`: the timed motion within Performance limits |
//! | `steer` | TrajectoryFollowingMode `follow` of a steering-limited vehicle: pure pursuit |
//! | `timing` | TimeReference / Timing: simulation time ↔ trajectory time |
//! | `path` | `Trajectory`: the pieces in order, evaluation by s, lengths |
//! | `closest` | the point of a trajectory closest to a world position |
//! | `source` | `PointSource`: the seam through which a shape's Positions are resolved |
//! | `build` | scenario `Trajectory` → `Trajectory`, its Positions resolved by a `PointSource` |

mod bspline;
mod build;
mod closest;
mod clothoid;
mod error;
mod follow;
mod line;
mod nurbs;
mod orientation;
mod path;
mod point;
mod source;
mod steer;
mod time_table;
mod timing;

pub use build::{build, build_for_actor};
pub use closest::Closest;
pub use closest::SCAN_STEP;
pub use error::{TrajectoryError, TrajectoryErrorKind};
pub use follow::FollowLimits;
pub use nurbs::ARC_LENGTH_TOLERANCE;
pub use path::{ShapeKind, Trajectory};
pub use point::TrajectoryPoint;
pub use source::{PlacedPoint, PointSource};
pub use steer::{drive_arc, max_curvature, pursuit_curvature, Pursuit};
pub use timing::{controls_longitudinal, TrajectoryClock};
