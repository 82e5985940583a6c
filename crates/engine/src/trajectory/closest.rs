//! The point of a trajectory closest to a world position (for FollowTrajectoryAction's
//! `initialDistanceOffset` and TrajectoryFollowingMode `follow`, OpenSCENARIO 1.3 §6.9 and
//! XSD `TrajectoryFollowingMode`), measured horizontally.
//!
//! Method: the horizontal distance is sampled every [`SCAN_STEP`] (64 to 100 000 samples);
//! around each local minimum of the samples (the 16 lowest) ± one step is searched by golden
//! sections and the foot point polished by Newton's method on the tangential offset to
//! `opendrive::SOLVER_TOLERANCE`; the joints between pieces (polyline vertices, segment
//! starts) are candidates too; the nearest candidate wins. This misses the global minimum
//! only where the distance has two minima within one step of each other.

use opendrive::{Real, SOLVER_TOLERANCE};

use super::{Trajectory, TrajectoryPoint};

/// Largest arc-length step of the coarse scan (m).
pub const SCAN_STEP: Real = 0.5;
/// Most samples of the coarse scan (a trajectory longer than 50 km is scanned more coarsely).
const MAX_SAMPLES: usize = 100_000;
/// Most local minima of the scan that are refined.
const MAX_CANDIDATES: usize = 16;

/// The point of a trajectory closest to a position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Closest {
    /// The trajectory point (its `s` is the arc length there).
    pub point: TrajectoryPoint,
    /// Horizontal distance from the position to the point (m).
    pub distance: Real,
    /// Signed lateral offset of the position from the point (m), positive left of the
    /// trajectory's heading.
    pub t: Real,
}

impl Trajectory {
    /// The point closest (horizontally) to (x, y); see the module doc for the method.
    pub fn closest(&self, x: Real, y: Real) -> Closest {
        let length = self.length();
        let samples = ((length / SCAN_STEP).ceil() as usize).clamp(64, MAX_SAMPLES);
        let step = length / samples as Real;
        let d2 = |s: Real| {
            let p = self.eval(s);
            (p.x - x).powi(2) + (p.y - y).powi(2)
        };
        let scan: Vec<(Real, Real)> = (0..=samples)
            .map(|i| {
                let s = (i as Real * step).min(length);
                (s, d2(s))
            })
            .collect();
        // Every local minimum of the scan is refined (the nearest MAX_CANDIDATES of them), and
        // the joints between pieces are candidates of their own: at a corner the distance has
        // a kink that a sample may straddle.
        let mut minima: Vec<(Real, Real)> = (0..scan.len())
            .filter(|&i| {
                let left = i.checked_sub(1).map_or(Real::INFINITY, |j| scan[j].1);
                let right = scan.get(i + 1).map_or(Real::INFINITY, |r| r.1);
                scan[i].1 <= left && scan[i].1 <= right
            })
            .map(|i| scan[i])
            .collect();
        minima.sort_by(|a, b| a.1.total_cmp(&b.1));
        minima.truncate(MAX_CANDIDATES);
        let refined = minima.iter().map(|&(best, _)| {
            let (lo, hi) = ((best - step).max(0.0), (best + step).min(length));
            self.newton_foot(x, y, golden_section(lo, hi, d2), lo, hi)
        });
        let s = refined
            .chain(self.joints().iter().copied())
            .map(|s| (s, d2(s)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map_or(0.0, |(s, _)| s);
        self.closest_at(x, y, s)
    }
}

impl Trajectory {
    /// The point closest (horizontally) to (x, y) among arc lengths within `window` of
    /// `s_guess` (for an entity that moved a known distance since it was at `s_guess`): golden
    /// sections on that stretch, polished by Newton's method; the stretch's joints are
    /// candidates too.
    pub fn closest_near(&self, x: Real, y: Real, s_guess: Real, window: Real) -> Closest {
        let length = self.length();
        let (lo, hi) = (
            (s_guess - window).clamp(0.0, length),
            (s_guess + window).clamp(0.0, length),
        );
        let d2 = |s: Real| {
            let p = self.eval(s);
            (p.x - x).powi(2) + (p.y - y).powi(2)
        };
        let refined = self.newton_foot(x, y, golden_section(lo, hi, d2), lo, hi);
        let s = std::iter::once(refined)
            .chain(
                self.joints()
                    .iter()
                    .copied()
                    .filter(|&j| j >= lo && j <= hi),
            )
            .map(|s| (s, d2(s)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map_or(refined, |(s, _)| s);
        self.closest_at(x, y, s)
    }

    /// (x, y) seen from the trajectory point at arc length `s`.
    fn closest_at(&self, x: Real, y: Real, s: Real) -> Closest {
        let point = self.eval(s);
        let (dx, dy) = (x - point.x, y - point.y);
        let (sin_h, cos_h) = point.heading.sin_cos();
        Closest {
            point,
            distance: dx.hypot(dy),
            t: -dx * sin_h + dy * cos_h,
        }
    }

    /// Polishes `s` by Newton's method on f(s) = (P(s) − Q)·T(s), the tangential component
    /// of the offset, with f'(s) = 1 + κ·(P − Q)·N (N the left normal), staying in [lo, hi].
    /// The squared distance is flat at its minimum, so golden-section search alone resolves
    /// s only to about √ε·distance; the foot-point equation is well conditioned.
    fn newton_foot(&self, x: Real, y: Real, mut s: Real, lo: Real, hi: Real) -> Real {
        let mut p = self.eval(s);
        let mut d2 = (p.x - x).powi(2) + (p.y - y).powi(2);
        for _ in 0..8 {
            let (sn, cs) = p.heading.sin_cos();
            let (dx, dy) = (p.x - x, p.y - y);
            let f = dx * cs + dy * sn;
            let df = 1.0 + p.curvature * (-dx * sn + dy * cs);
            if df <= 0.0 || f.abs() <= SOLVER_TOLERANCE {
                break;
            }
            // Only steps that bring the point closer count: at a corner (a polyline vertex,
            // a heading offset) the foot-point equation has no root and Newton would wander.
            let next = (s - f / df).clamp(lo, hi);
            let q = self.eval(next);
            let e2 = (q.x - x).powi(2) + (q.y - y).powi(2);
            if e2 > d2 {
                break;
            }
            (s, p, d2) = (next, q, e2);
        }
        s
    }
}

/// The minimiser of `f` on [a, b] (unimodal there) by golden-section search.
fn golden_section(mut a: Real, mut b: Real, f: impl Fn(Real) -> Real) -> Real {
    const INV_PHI: Real = 0.618_033_988_749_894_9;
    let mut c = b - INV_PHI * (b - a);
    let mut d = a + INV_PHI * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..200 {
        if b - a <= SOLVER_TOLERANCE {
            break;
        }
        if fc <= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - INV_PHI * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + INV_PHI * (b - a);
            fd = f(d);
        }
    }
    0.5 * (a + b)
}
