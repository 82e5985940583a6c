//! The part of a path or trajectory an action follows (ASAM OpenSCENARIO DSL 2.1 §8.8.2.16-17
//! `follow_path`, `follow_trajectory`: from `start_offset` after its start to `end_offset`
//! before its end), and points along such a part, each with the time the actor following the
//! trajectory is there, for the group forms (`group_path`): the part a group follows, and the
//! points a member's path is moved from.
//!
//! The points are the path's own (polyline or the smooth curve of `path_shape`) at most a
//! given step apart along it, so the polyline through them leaves the curve by at most its
//! sagitta h²κ/8 (h the step, κ the curve's curvature): 1.25 mm for 1 m steps on a radius of
//! 100 m. A polyline sampled with an infinite step keeps its own vertices: its part between two
//! lengths is exact. A sample's time is its segment's stamps interpolated linearly in the
//! segment's parameter (the chord's fraction, or the Bézier parameter), which is how the engine
//! times a trajectory (`path_shape`: the control points carry t₀, t₀ + Δ/3, t₀ + 2Δ/3, t₁).

use super::path_shape::{locate, segment_lengths, Pose2};
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{arg, Invoke};

/// A segment's part shorter than this adds no point (m): its point would repeat the last.
const NO_LENGTH: f64 = 1e-9;

/// A part of a path: its points and, for a trajectory, their time stamps.
pub(super) type Samples = (Vec<Pose2>, Option<Vec<f64>>);

/// The points of the path through `points` (a trajectory with `times`) from `from` to `to` m
/// along it, at most `step` m apart along it (each segment's part split evenly), with each
/// segment's vertices kept; the heading of each point is the chord's to the next (the last's
/// the chord's from the one before). `from` < `to`, both within the path's length.
pub(super) fn samples(
    points: &[Pose2],
    times: Option<&[f64]>,
    smooth: bool,
    (from, to): (f64, f64),
    step: f64,
) -> Samples {
    let lengths = segment_lengths(points, smooth);
    let mut out: Vec<(f64, f64)> = Vec::new();
    let mut stamps = Vec::new();
    let mut start = 0.0;
    for (k, &l) in lengths.iter().enumerate() {
        let (lo, hi) = (from.max(start), to.min(start + l));
        let first = out.is_empty();
        start += l;
        // A part of no length adds no point (the last segment's when nothing came before).
        if hi - lo <= NO_LENGTH && !(first && k + 1 == lengths.len()) {
            continue;
        }
        let n = ((hi - lo) / step).ceil().max(1.0) as usize;
        let segment = &points[k..=k + 1];
        for j in usize::from(!first)..=n {
            let d = lo + (hi - lo) * j as f64 / n as f64 - (start - l);
            let (_, u, at, _) = locate(segment, smooth, d);
            out.push(at);
            if let Some(t) = times {
                stamps.push(t[k] + u * (t[k + 1] - t[k]));
            }
        }
    }
    let heading = |i: usize| {
        let (a, b) = if i + 1 < out.len() {
            (out[i], out[i + 1])
        } else {
            (out[i.saturating_sub(1)], out[i])
        };
        (b.1 - a.1).atan2(b.0 - a.0)
    };
    let poses = (0..out.len())
        .map(|i| (out[i].0, out[i].1, heading(i)))
        .collect();
    (poses, times.map(|_| stamps))
}

/// The part of a path or trajectory an action follows: from `start_offset` m after its start
/// to `end_offset` m before its end (§8.8.2.16-17; both 0 unless given).
pub(super) struct Cut {
    pub start_offset: f64,
    pub end_offset: f64,
    /// The length between them (m).
    pub length: f64,
    /// Segment and parameter of the start, and of the end.
    pub start: (usize, f64),
    pub end: (usize, f64),
    pub end_point: (f64, f64),
    /// Length per unit of the end segment's parameter at the end (m).
    pub end_rate: f64,
}

/// The [`Cut`] `inv`'s `start_offset` and `end_offset` make of the path through `points`: each
/// 0 m or more, together shorter than the path; with `offsets` false the whole path (a group's
/// member follows the part between them already).
pub(super) fn cut(
    inv: &Invoke,
    points: &[Pose2],
    smooth: bool,
    offsets: bool,
) -> Result<Cut, Error> {
    let total: f64 = segment_lengths(points, smooth).iter().sum();
    let offset = |param: &str| -> Result<(f64, Option<Site>), Error> {
        match arg(&inv.args, param).filter(|_| offsets) {
            None => Ok((0.0, None)),
            Some(a) => {
                let d = a.number()?;
                if d < 0.0 {
                    return Err(a.site.err(
                        K::Argument,
                        format!("expected a {param} of 0 m or more, found {d} m"),
                    ));
                }
                Ok((d, Some(a.site.clone())))
            }
        }
    };
    let ((start_offset, s_site), (end_offset, e_site)) =
        (offset("start_offset")?, offset("end_offset")?);
    // Only a given offset can leave nothing to follow (its site is there to name).
    let given = e_site.or(s_site);
    if let Some(site) = given.filter(|_| start_offset + end_offset >= total) {
        return Err(site.err(
            K::Unsatisfiable,
            format!("expected start_offset + end_offset below the {}'s length {total:.2} m, found {:.2} m", if inv.kind.along_path() { "path" } else { "trajectory" }, start_offset + end_offset),
        ));
    }
    let (k0, u0, _, _) = locate(points, smooth, start_offset);
    let (k1, u1, end_point, end_rate) = locate(points, smooth, total - end_offset);
    Ok(Cut {
        start_offset,
        end_offset,
        length: total - start_offset - end_offset,
        start: (k0, u0),
        end: (k1, u1),
        end_point,
        end_rate,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sample positions are sums of exact binary fractions of these lengths.
    const TOL: f64 = 1e-9;

    #[test]
    fn a_polylines_part_keeps_its_vertices_and_interpolates_its_stamps() {
        // (0, 0) at 0 s, (10, 0) at 2 s, (10, 10) at 4 s; the part from 5 m to 15 m: (5, 0) at
        // 1 s, the vertex (10, 0) at 2 s, (10, 5) at 3 s.
        let points = [(0.0, 0.0, 0.0), (10.0, 0.0, 0.0), (10.0, 10.0, 0.0)];
        let (p, t) = samples(
            &points,
            Some(&[0.0, 2.0, 4.0]),
            false,
            (5.0, 15.0),
            f64::INFINITY,
        );
        let t = t.unwrap_or_default();
        let want = [(5.0, 0.0, 1.0), (10.0, 0.0, 2.0), (10.0, 5.0, 3.0)];
        assert_eq!(p.len(), want.len(), "{p:?}");
        for ((x, y, _), ((wx, wy, wt), t)) in p.iter().zip(want.iter().zip(&t)) {
            assert!((x - wx).abs() < TOL && (y - wy).abs() < TOL && (t - wt).abs() < TOL);
        }
    }

    #[test]
    fn a_step_splits_each_segment_evenly() {
        // 10 m then 5 m with a 2 m step: 5 pieces of 2 m, then 3 of 5/3 m; 9 points.
        let points = [(0.0, 0.0, 0.0), (10.0, 0.0, 0.0), (10.0, 5.0, 0.0)];
        let (p, _) = samples(&points, None, false, (0.0, 15.0), 2.0);
        assert_eq!(p.len(), 9, "{p:?}");
        assert!((p[1].0 - 2.0).abs() < TOL && (p[6].1 - 5.0 / 3.0).abs() < TOL);
    }

    #[test]
    fn a_smooth_paths_part_is_sampled_along_its_curve_with_its_time() {
        // Two points on a line with its heading: the Hermite curve is the line, its Bézier
        // parameter uniform in length (handles L/3). The part from 2.5 m to 7.5 m of the 10 m
        // in 2 s, 1 m steps: 5 pieces, x = 2.5, 3.5, …, 7.5 m at 0.5, 0.7, …, 1.5 s.
        let points = [(0.0, 0.0, 0.0), (10.0, 0.0, 0.0)];
        let (p, t) = samples(&points, Some(&[0.0, 2.0]), true, (2.5, 7.5), 1.0);
        let t = t.unwrap_or_default();
        assert_eq!((p.len(), t.len()), (6, 6), "{p:?}");
        for (k, ((x, y, _), t)) in p.iter().zip(&t).enumerate() {
            let want = 2.5 + k as f64;
            // The bisection finds the parameter to 1e-12; its arc length is integrated.
            assert!(
                (x - want).abs() < 1e-9 && y.abs() < 1e-9,
                "{x} {y} vs {want}"
            );
            assert!((t - want / 5.0).abs() < 1e-9, "{t} vs {}", want / 5.0);
        }
    }
}
