//! Reference-line geometry (OpenDRIVE 1.8 §9): one file per geometry type, each evaluating
//! its curve exactly in the geometry's local frame (start at the origin, heading 0), and
//! [`PlanView`] placing them in the inertial frame.

mod arc;
pub(crate) mod line;
mod param_poly3;
mod plan_view;
mod poly3;
mod quadrature;
mod spiral;

pub use arc::Arc;
pub use param_poly3::{ParamPoly3, ParamRange};
pub use plan_view::{Geometry, GeometryKind, PlanView, RefPoint};
pub use poly3::Poly3;
pub use spiral::Spiral;

/// A point of a curve in its local frame: position (u, v), tangent direction and curvature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocalPoint {
    /// Along the start heading (m).
    pub u: f64,
    /// To the left of the start heading (m).
    pub v: f64,
    /// Tangent direction relative to the start heading (rad).
    pub hdg: f64,
    /// Signed curvature (1/m), positive turning left.
    pub curvature: f64,
}
