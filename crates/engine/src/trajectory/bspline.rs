//! B-spline curves (the non-rational core of OpenSCENARIO 1.3 §6.9 `Nurbs`), evaluated by
//! de Boor's algorithm (C. de Boor, "On calculating with B-splines", J. Approx. Theory 6,
//! 1972), the numerically stable form of the Cox–de Boor recursion, and differentiated by
//! the derivative-control-point formula (Piegl & Tiller, "The NURBS Book", 2nd ed., §3.3):
//! Qᵢ = p·(Pᵢ₊₁ − Pᵢ)/(uᵢ₊ₚ₊₁ − uᵢ₊₁), a B-spline of degree p − 1 on the knots without their
//! first and last entries.
//!
//! Written by hand: a general NURBS crate (e.g. `curvo`, built on nalgebra) brings a geometry
//! kernel for what is some eighty lines here, and the scenario format needs its own knot
//! checks with positioned errors anyway.
//!
//! Points are homogeneous `[w·x, w·y, w·z, w, w·t]`: the rational curve divides by `w`, and
//! the control points' times ride along as a fifth coordinate.

use opendrive::Real;

/// Dimension of a homogeneous control point: w·x, w·y, w·z, w, w·t.
pub(crate) const DIM: usize = 5;

/// A homogeneous point.
pub(crate) type HPoint = [Real; DIM];

/// Degrees below this evaluate without allocating.
const STACK_POINTS: usize = 8;

/// A B-spline curve of degree `degree` (checked by the caller: control points ≥ degree + 1,
/// knots = control points + degree + 1, non-decreasing, a non-empty parameter range).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct BSpline {
    degree: usize,
    knots: Vec<Real>,
    control: Vec<HPoint>,
}

impl BSpline {
    /// A B-spline of `degree` on `knots` with `control` points (see the type's invariant).
    pub(crate) fn new(degree: usize, knots: Vec<Real>, control: Vec<HPoint>) -> Self {
        debug_assert_eq!(knots.len(), control.len() + degree + 1);
        Self {
            degree,
            knots,
            control,
        }
    }

    /// The parameter range [u_p, u_n] (n = number of control points).
    pub(crate) fn domain(&self) -> (Real, Real) {
        (self.knots[self.degree], self.knots[self.control.len()])
    }

    /// The knot spans of positive width inside the domain, as (u_start, u_end).
    pub(crate) fn spans(&self) -> Vec<(Real, Real)> {
        (self.degree..self.control.len())
            .map(|i| (self.knots[i], self.knots[i + 1]))
            .filter(|(a, b)| b > a)
            .collect()
    }

    /// Index k of the knot span holding `u`: knots[k] ≤ u < knots[k+1] with k in
    /// [degree, n − 1], the last non-empty span for u at the domain's end.
    fn span(&self, u: Real) -> usize {
        let n = self.control.len();
        let mut k = self
            .knots
            .partition_point(|&x| x <= u)
            .saturating_sub(1)
            .clamp(self.degree, n - 1);
        while k > self.degree && self.knots[k] >= self.knots[k + 1] {
            k -= 1;
        }
        k
    }

    /// The curve's point at parameter `u` (clamped to the domain).
    pub(crate) fn eval(&self, u: Real) -> HPoint {
        let (lo, hi) = self.domain();
        let u = u.clamp(lo, hi);
        let p = self.degree;
        let k = self.span(u);
        // The p + 1 points of de Boor's triangle, on the stack for the usual degrees.
        let mut stack = [[0.0; DIM]; STACK_POINTS];
        let mut heap = Vec::new();
        let d: &mut [HPoint] = if p < STACK_POINTS {
            &mut stack[..=p]
        } else {
            heap.resize(p + 1, [0.0; DIM]);
            &mut heap
        };
        d.copy_from_slice(&self.control[k - p..=k]);
        for r in 1..=p {
            for j in (r..=p).rev() {
                let left = self.knots[j + k - p];
                let den = self.knots[j + 1 + k - r] - left;
                let alpha = if den > 0.0 { (u - left) / den } else { 0.0 };
                let prev = d[j - 1];
                for (v, q) in d[j].iter_mut().zip(prev) {
                    *v = (1.0 - alpha) * q + alpha * *v;
                }
            }
        }
        d[p]
    }

    /// The derivative curve dC/du, or `None` for degree 0 (piecewise constant: derivative 0).
    pub(crate) fn derivative(&self) -> Option<BSpline> {
        let p = self.degree;
        if p == 0 {
            return None;
        }
        let n = self.control.len();
        let control = (0..n - 1)
            .map(|i| {
                let den = self.knots[i + p + 1] - self.knots[i + 1];
                let f = if den > 0.0 { p as Real / den } else { 0.0 };
                let mut q = [0.0; DIM];
                for (c, v) in q.iter_mut().enumerate() {
                    *v = f * (self.control[i + 1][c] - self.control[i][c]);
                }
                q
            })
            .collect();
        let knots = self.knots[1..self.knots.len() - 1].to_vec();
        Some(BSpline::new(p - 1, knots, control))
    }
}
