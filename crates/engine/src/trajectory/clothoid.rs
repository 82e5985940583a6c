//! One clothoid piece (OpenSCENARIO 1.3 §6.9, XSD `Clothoid` and `ClothoidSplineSegment`):
//! curvature linear in arc length, κ(s) = κ₀ + κ'·s, from a start pose.
//!
//! The curve is the OpenDRIVE `<spiral>` (OpenDRIVE 1.8 §9.5): this module places an
//! `opendrive::Geometry` of kind `Spiral` at the start pose and evaluates it, so the clothoid's
//! Fresnel integrals are computed once in the code base (composite Gauss–Legendre quadrature,
//! error at f64 round-off; see the opendrive crate's `geometry::spiral`). z stays at the start
//! position's z: neither element has a slope.

use opendrive::{Geometry, GeometryKind, Real, Spiral};

use super::TrajectoryPoint;

/// A clothoid from a start pose: start curvature, curvature rate, length.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Clothoid {
    geometry: Geometry,
    z: Real,
}

impl Clothoid {
    /// A clothoid starting at (x, y, z) with heading `heading`, curvature `curvature` (1/m)
    /// changing by `curvature_prime` (1/m²) per metre over `length` (m, > 0, checked by the
    /// caller).
    pub(crate) fn new(
        [x, y, z]: [Real; 3],
        heading: Real,
        curvature: Real,
        curvature_prime: Real,
        length: Real,
    ) -> Self {
        let spiral = Spiral::new(curvature, curvature + curvature_prime * length, length);
        Self {
            geometry: Geometry::new(0.0, x, y, heading, length, GeometryKind::Spiral(spiral)),
            z,
        }
    }

    /// Length (m).
    pub(crate) fn length(&self) -> Real {
        self.geometry.length
    }

    /// The point `ds` metres from the start.
    pub(crate) fn eval(&self, ds: Real) -> TrajectoryPoint {
        let p = self.geometry.eval(ds);
        TrajectoryPoint {
            s: ds,
            x: p.x,
            y: p.y,
            z: self.z,
            heading: p.hdg,
            curvature: p.curvature,
        }
    }
}
