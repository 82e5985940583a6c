//! `Nurbs` (OpenSCENARIO 1.3 §6.9, XSD `Nurbs`, `ControlPoint`, `Knot`): a non-uniform
//! rational B-spline of order k (degree k − 1) with weighted control points and a knot vector
//! of (control points + order) non-decreasing values; the curve runs over
//! [u_(k−1), u_n] (0-based knots, n control points).
//!
//! Rational form (Piegl & Tiller, "The NURBS Book", 2nd ed., §4.2–4.3): with A(u) the
//! B-spline of the homogeneous points (w·P, w) and C = A/w, the derivatives are
//! C' = (A' − w'C)/w and C'' = (A'' − 2w'C' − w''C)/w (differentiate A = w·C twice). Control-point times are a further
//! homogeneous coordinate, so t(u) is the same rational curve's time component.
//!
//! Arc length: s(u) = ∫|C'_xy| du, tabulated at build time by adaptive 5-point
//! Gauss–Legendre quadrature: an interval is accepted when its one-panel and two-panel sums
//! differ by less than [`ARC_LENGTH_TOLERANCE`], else halved (at most 12 times). The table's
//! error is therefore of the order of that tolerance per interval. s → u inverts the table by
//! Newton's method on the interval holding s, safeguarded by bisection, to
//! `opendrive::SOLVER_TOLERANCE`.
//!
//! Time: the follower reads s(t) by linear interpolation between (s, t) samples of the curve
//! ([`Nurbs::time_samples`]). The arc-length rows alone are too sparse where t(u) is not
//! linear (an end span of a clamped knot vector: ASAM's FollowTrajectory_Nurbs put the car
//! 1 ms, 1.3 cm, behind its curve at 1 s), so each row interval is halved while the curve's
//! time at its middle differs from the chord's by more than [`TIME_SAMPLE_TOLERANCE`].

use opendrive::{normalize_angle, Real, SOLVER_TOLERANCE};

use super::bspline::{BSpline, HPoint, DIM};
use super::TrajectoryPoint;

/// Accepted difference (m) between the one- and two-panel quadrature of one table interval.
pub const ARC_LENGTH_TOLERANCE: Real = 1e-10;
/// Deepest halving of a start interval when building the arc-length table (at most 2¹²
/// leaves each): bounds the work on curves whose speed has a kink (a cusp where control
/// points coincide), where the quadrature converges slowly.
const MAX_DEPTH: u32 = 12;
/// Accepted difference (s) between the curve's time at the middle of two time samples and the
/// linear interpolation between them (1e-7 s: 5 µm at 50 m/s).
pub(crate) const TIME_SAMPLE_TOLERANCE: Real = 1e-7;
/// Deepest halving of an arc-length row interval when sampling the time (2²⁰ samples at most
/// each; the chord error falls by 4 a halving, so 1e-3 s needs 7).
const MAX_TIME_DEPTH: u32 = 20;
/// Intervals each knot span starts with before adaptive halving.
const START_PANELS: usize = 4;

/// Gauss–Legendre 5-point nodes on [−1, 1] and weights (Abramowitz & Stegun, table 25.4).
const GL5: [(Real, Real); 5] = [
    (0.0, 0.568_888_888_888_888_9),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

/// One row of the arc-length table: parameter u and the arc length up to it.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Row {
    u: Real,
    s: Real,
}

/// A checked NURBS curve with its arc-length table.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Nurbs {
    curve: BSpline,
    d1: Option<BSpline>,
    d2: Option<BSpline>,
    table: Vec<Row>,
}

/// Value, first and second derivative of the rational curve (x, y, z, t) at one u.
struct Jet {
    c: [Real; 4],
    d1: [Real; 4],
    d2: [Real; 4],
}

impl Nurbs {
    /// The curve of `degree` with homogeneous `control` points on `knots` (checked by the
    /// caller: see `build`). Builds the arc-length table.
    pub(crate) fn new(degree: usize, knots: Vec<Real>, control: Vec<HPoint>) -> Self {
        let curve = BSpline::new(degree, knots, control);
        let d1 = curve.derivative();
        let d2 = d1.as_ref().and_then(BSpline::derivative);
        let mut n = Self {
            curve,
            d1,
            d2,
            table: Vec::new(),
        };
        n.table = n.arc_length_table();
        n
    }

    /// Horizontal length (m).
    pub(crate) fn length(&self) -> Real {
        self.table.last().map_or(0.0, |r| r.s)
    }

    fn jet(&self, u: Real) -> Jet {
        let zero = [0.0; DIM];
        let a = self.curve.eval(u);
        let a1 = self.d1.as_ref().map_or(zero, |d| d.eval(u));
        let a2 = self.d2.as_ref().map_or(zero, |d| d.eval(u));
        let (w, w1, w2) = (a[3], a1[3], a2[3]);
        let mut jet = Jet {
            c: [0.0; 4],
            d1: [0.0; 4],
            d2: [0.0; 4],
        };
        // Coordinates x, y, z, t sit at homogeneous indices 0, 1, 2, 4.
        for (i, h) in [0, 1, 2, 4].into_iter().enumerate() {
            let c = a[h] / w;
            let c1 = (a1[h] - w1 * c) / w;
            let c2 = (a2[h] - 2.0 * w1 * c1 - w2 * c) / w;
            jet.c[i] = c;
            jet.d1[i] = c1;
            jet.d2[i] = c2;
        }
        jet
    }

    /// |dC_xy/du| at u (from A and A' only).
    fn speed(&self, u: Real) -> Real {
        let a = self.curve.eval(u);
        let Some(d1) = &self.d1 else { return 0.0 };
        let a1 = d1.eval(u);
        let (w, w1) = (a[3], a1[3]);
        let dx = (a1[0] - w1 * a[0] / w) / w;
        let dy = (a1[1] - w1 * a[1] / w) / w;
        dx.hypot(dy)
    }

    /// ∫ₐᵇ |C'_xy| du by one 5-point Gauss–Legendre panel.
    fn panel(&self, a: Real, b: Real) -> Real {
        let (m, h) = (0.5 * (a + b), 0.5 * (b - a));
        GL5.iter()
            .map(|&(x, w)| w * self.speed(m + h * x))
            .sum::<Real>()
            * h
    }

    fn arc_length_table(&self) -> Vec<Row> {
        let spans = self.curve.spans();
        let mut rows = vec![Row {
            u: spans.first().map_or(0.0, |s| s.0),
            s: 0.0,
        }];
        for (a, b) in spans {
            let step = (b - a) / START_PANELS as Real;
            for i in 0..START_PANELS {
                let lo = a + step * i as Real;
                let hi = if i + 1 == START_PANELS { b } else { lo + step };
                self.adapt(lo, hi, self.panel(lo, hi), 0, &mut rows);
            }
        }
        rows
    }

    /// Appends rows covering (a, b], halving while the two-panel sum differs from `whole`.
    fn adapt(&self, a: Real, b: Real, whole: Real, depth: u32, rows: &mut Vec<Row>) {
        let m = 0.5 * (a + b);
        let (left, right) = (self.panel(a, m), self.panel(m, b));
        if (left + right - whole).abs() <= ARC_LENGTH_TOLERANCE || depth >= MAX_DEPTH {
            let s0 = rows.last().map_or(0.0, |r| r.s);
            rows.push(Row { u: m, s: s0 + left });
            rows.push(Row {
                u: b,
                s: s0 + left + right,
            });
        } else {
            self.adapt(a, m, left, depth + 1, rows);
            self.adapt(m, b, right, depth + 1, rows);
        }
    }

    /// The parameter u at arc length `s` (clamped to [0, length]).
    fn parameter_at(&self, s: Real) -> Real {
        let s = s.clamp(0.0, self.length());
        let i = self
            .table
            .partition_point(|r| r.s < s)
            .clamp(1, self.table.len().max(2) - 1);
        let (r0, r1) = (self.table[i - 1], self.table[i]);
        if r1.s - r0.s <= 0.0 {
            return r0.u;
        }
        let (mut lo, mut hi) = (r0.u, r1.u);
        let mut u = r0.u + (s - r0.s) / (r1.s - r0.s) * (r1.u - r0.u);
        for _ in 0..50 {
            let f = r0.s + self.panel(r0.u, u) - s;
            if f.abs() <= SOLVER_TOLERANCE {
                break;
            }
            if f > 0.0 {
                hi = u;
            } else {
                lo = u;
            }
            let v = self.speed(u);
            let newton = u - f / v;
            u = if v > 0.0 && newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
        }
        u
    }

    /// The point at arc length `s`, and the curve's time there (from the control points'
    /// times; 0 when they have none).
    pub(crate) fn eval(&self, s: Real) -> (TrajectoryPoint, Real) {
        let j = self.jet(self.parameter_at(s));
        let (dx, dy) = (j.d1[0], j.d1[1]);
        let v2 = dx * dx + dy * dy;
        let curvature = if v2 > 0.0 {
            (dx * j.d2[1] - dy * j.d2[0]) / (v2 * v2.sqrt())
        } else {
            0.0
        };
        let point = TrajectoryPoint {
            s,
            x: j.c[0],
            y: j.c[1],
            z: j.c[2],
            heading: normalize_angle(dy.atan2(dx)),
            curvature,
        };
        (point, j.c[3])
    }

    /// (s, t) samples of the curve's time component for s(t) by linear interpolation: the
    /// arc-length rows, each interval halved while the time at its middle is further than
    /// [`TIME_SAMPLE_TOLERANCE`] from the chord. The running maximum keeps the samples
    /// monotone against round-off (non-decreasing control times give a non-decreasing t(u)
    /// by the variation-diminishing property of B-splines).
    pub(crate) fn time_samples(&self) -> Vec<(Real, Real)> {
        let mut out: Vec<(Real, Real)> = Vec::with_capacity(self.table.len());
        let time = |s: Real| self.eval(s).1;
        for (i, r) in self.table.iter().enumerate() {
            let t = time(r.s);
            if i > 0 {
                let (s0, t0) = out[out.len() - 1];
                self.refine_time((s0, t0), (r.s, t), 0, &mut out);
            }
            let t_max = out.last().map_or(t, |&(_, m)| m.max(t));
            out.push((r.s, t_max));
        }
        out
    }

    /// Pushes the samples strictly inside (a, b) that bring the chord within tolerance.
    fn refine_time(
        &self,
        a: (Real, Real),
        b: (Real, Real),
        depth: u32,
        out: &mut Vec<(Real, Real)>,
    ) {
        let sm = 0.5 * (a.0 + b.0);
        let tm = self.eval(sm).1;
        if (tm - 0.5 * (a.1 + b.1)).abs() <= TIME_SAMPLE_TOLERANCE
            || depth >= MAX_TIME_DEPTH
            || b.0 - a.0 <= 0.0
        {
            return;
        }
        self.refine_time(a, (sm, tm), depth + 1, out);
        let t_max = out.last().map_or(tm, |&(_, m)| m.max(tm));
        out.push((sm, t_max));
        self.refine_time((sm, tm), b, depth + 1, out);
    }
}
