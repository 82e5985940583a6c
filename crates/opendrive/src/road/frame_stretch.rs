//! Where a road's frame comes from the same pieces (OpenDRIVE 1.8 §9.2 plan-view geometries,
//! §9.3 `<line>`, §8.4 elevation, §10.5 superelevation): the s-range around a point inside one
//! plan-view geometry, one elevation record and one superelevation record, and, where that
//! geometry is a line and both records are constants, the frame's numbers that stay the same
//! along it. There [`Road::pose_in`] gives [`Road::pose`]'s bits with the reference point
//! moved along the line and nothing looked up or branched on: the engine's default controller
//! asks the pose of every moving entity at every step (issue 31).
//!
//! Why bit for bit: [`road_frame`] at s evaluates the geometry `PlanView::index_at` finds (the
//! last one starting at or before s) and the records `eval_piecewise` finds; inside the range
//! they are the same ones (it ends before the next geometry's start and a
//! [`CONSTANT_MARGIN`] inside each record's ends, `narrow_to_record`), and s lies on the road,
//! where `check_s` leaves it as it is. A `<line>`'s reference point is `line::along` of its
//! start, ds = s − s₀ and the sine and cosine of its heading, its heading, curvature, sine and
//! cosine the same at every s (`Geometry::eval_trig`); a constant record (b = c = d = 0, of
//! either sign) evaluates with ds > 0 to the same bits at every s and its derivative to a zero
//! (the argument of `constant_lanes`), so the elevation, pitch, roll and their sines and
//! cosines are the same too. Every number of the frame but x and y is therefore the one at
//! any other s of the range; x and y are computed here by the line's own formula, and the
//! pose from them by the same `RoadFrame::pose_from`, or, where the stretch is flat and
//! unbanked (the pitch's and roll's sines +0, cosines 1) and t finite, by
//! `RoadFrame::flat_pose_from` from constants kept with the stretch (the same operations on
//! the same values: `RoadFrame::flat_constants`).

use super::constant_lanes::{is_constant, narrow_to_record, CONSTANT_MARGIN};
use super::frame::{road_frame, RoadFrame};
use crate::error::Error;
use crate::geometry::{line, GeometryKind};
use crate::math::{Pose, Real};
use crate::model::Road;

/// An s-range of one road over which its frame comes from the same plan-view geometry and
/// profile records ([`Road::frame_stretch`]), with the frame's unchanging numbers where it
/// runs along a straight line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameStretch {
    /// Start of the range (m), on the road.
    pub lo: Real,
    /// End of the range (m), on the road.
    pub hi: Real,
    /// The frame at a point of the range and the line's start, where the geometry is a
    /// `<line>` and the profiles are constant.
    line: Option<LineFrame>,
}

/// A straight stretch's frame: the line's start (s₀, x₀, y₀) and the frame at one s of the
/// stretch, whose numbers other than x and y hold all along it (module doc), and where it is
/// flat and unbanked the constants of its cross section ([`RoadFrame::flat_constants`]).
#[derive(Debug, Clone, Copy, PartialEq)]
struct LineFrame {
    start: [Real; 3],
    frame: RoadFrame,
    flat: Option<[Real; 3]>,
}

impl FrameStretch {
    /// Whether `s` lies in the range (never at a NaN).
    #[inline]
    pub fn holds(&self, s: Real) -> bool {
        self.lo <= s && s <= self.hi
    }

    /// Whether the frame runs along a straight line with constant profiles here, so that
    /// [`Road::pose_in`] computes it without a look-up.
    #[inline]
    pub fn is_straight(&self) -> bool {
        self.line.is_some()
    }
}

impl LineFrame {
    /// [`Road::pose`] at (s, t) for an s of the stretch (module doc): on a flat, unbanked
    /// stretch at a finite t by [`RoadFrame::flat_pose_from`], else by the full cross
    /// section.
    #[inline(always)]
    fn pose(&self, s: Real, t: Real) -> Pose {
        let [s0, x0, y0] = self.start;
        let f = &self.frame;
        let xy = line::along([x0, y0], s - s0, [f.sin_h, f.cos_h]);
        match self.flat {
            Some(flat) if t.is_finite() => f.flat_pose_from(xy, t, flat),
            _ => f.pose_from(xy, t),
        }
    }
}

impl Road {
    /// The s-range holding `s` over which the road's frame comes from one plan-view geometry,
    /// one elevation record and one superelevation record (module doc), from the geometry's
    /// start (at least 0) to before the next one's (a [`CONSTANT_MARGIN`] before it, or the
    /// road's end), a margin inside the records' ends; `None` where `s` is off the road or not
    /// finite, before the first profile record, or outside that range (within the margin of
    /// an end). Where the geometry is a `<line>` and both records constant (or absent), the
    /// stretch is straight ([`FrameStretch::is_straight`]).
    pub fn frame_stretch(&self, s: Real) -> Option<FrameStretch> {
        if !(s.is_finite() && (0.0..=self.length).contains(&s)) {
            return None;
        }
        let geometries = self.plan_view.geometries();
        let i = self.plan_view.index_at(s);
        let g = &geometries[i];
        let end = geometries
            .get(i + 1)
            .map_or(self.length, |next| next.s - CONSTANT_MARGIN);
        let mut range = (g.s.max(0.0), end.min(self.length));
        let elevation = narrow_to_record(&self.elevation, 0.0, s, &mut range)?;
        let superelevation = narrow_to_record(&self.superelevation, 0.0, s, &mut range)?;
        let (lo, hi) = range;
        if !(lo <= s && s <= hi) {
            return None;
        }
        let flat = |r: Option<&_>| r.is_none_or(is_constant);
        let straight =
            matches!(g.kind, GeometryKind::Line) && flat(elevation) && flat(superelevation);
        Some(FrameStretch {
            lo,
            hi,
            line: straight.then(|| {
                let frame = road_frame(self, s);
                LineFrame {
                    start: [g.s, g.x, g.y],
                    frame,
                    flat: frame.flat_constants(),
                }
            }),
        })
    }

    /// [`pose`](Self::pose) at (s, t), given a stretch of this road
    /// ([`frame_stretch`](Self::frame_stretch)): where the stretch is straight and holds `s`,
    /// along its line without a look-up, else the full computation; the same bits either way
    /// (module doc). A stretch of another road gives that road's pose where it holds `s`.
    #[inline(always)]
    pub fn pose_in(&self, stretch: &FrameStretch, s: Real, t: Real) -> Result<Pose, Error> {
        match &stretch.line {
            Some(line) if stretch.holds(s) => Ok(line.pose(s, t)),
            _ => self.pose(s, t),
        }
    }

    /// [`pose_in`](Self::pose_in) for an `s` the caller knows the stretch holds
    /// ([`FrameStretch::holds`]; e.g. an s inside a range made inside the stretch), without
    /// testing it: the same bits there. Given an s outside a straight stretch, the pose would
    /// be extrapolated along its line instead of the road's.
    #[inline(always)]
    pub fn pose_in_held(&self, stretch: &FrameStretch, s: Real, t: Real) -> Result<Pose, Error> {
        match &stretch.line {
            Some(line) => Ok(line.pose(s, t)),
            None => self.pose(s, t),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Arc, Geometry, PlanView};
    use crate::math::Cubic;
    use crate::road::constant_lanes::tests::cubic;
    use crate::road::frame::tests::straight_road;

    /// A 100 m road of three lines (0–30 m at 0.5 rad, 30–60 m at 0.5 rad from where the
    /// first ends, 60–80 m at 0.7 rad) and an arc (80–100 m, 0.01 /m).
    fn pieces() -> Road {
        let mut road = straight_road(100.0, Vec::new(), Vec::new());
        let (c, s) = (0.5_f64.cos(), 0.5_f64.sin());
        let line = |s0: Real, x: Real, y: Real, h: Real, len: Real| {
            Geometry::new(s0, x, y, h, len, GeometryKind::Line)
        };
        road.plan_view = PlanView::new(vec![
            line(0.0, 1000.0, -2000.0, 0.5, 30.0),
            line(30.0, 1000.0 + 30.0 * c, -2000.0 + 30.0 * s, 0.5, 30.0),
            line(60.0, 1000.0 + 60.0 * c, -2000.0 + 60.0 * s, 0.7, 20.0),
            Geometry::new(
                80.0,
                1000.0 + 60.0 * c + 20.0 * 0.7_f64.cos(),
                -2000.0 + 60.0 * s + 20.0 * 0.7_f64.sin(),
                0.7,
                20.0,
                GeometryKind::Arc(Arc { curvature: 0.01 }),
            ),
        ]);
        road
    }

    /// The roads of the test: the plain one; a constant elevation of −0 and 12 m (two
    /// records, the second from 45 m); a climb of 2 % from 50 m; a constant bank of 0.05 rad;
    /// a bank growing from 20 m; a −0 superelevation record; no record before 10 m (s before
    /// the first record is extrapolated).
    fn roads() -> Vec<(&'static str, Road)> {
        let plain = pieces();
        let mut elevated = pieces();
        elevated.elevation = vec![cubic(0.0, -0.0, 0.0), cubic(45.0, 12.0, -0.0)];
        let mut climbing = pieces();
        climbing.elevation = vec![cubic(0.0, 3.0, 0.0), cubic(50.0, 3.0, 0.02)];
        let mut banked = pieces();
        banked.superelevation = vec![cubic(0.0, 0.05, 0.0)];
        let mut tilting = pieces();
        tilting.superelevation = vec![cubic(0.0, 0.0, 0.0), cubic(20.0, 0.0, 0.001)];
        let mut negative_zero = pieces();
        negative_zero.superelevation = vec![cubic(0.0, -0.0, -0.0)];
        let mut late = pieces();
        late.elevation = vec![cubic(10.0, 1.0, 0.0)];
        vec![
            ("plain", plain),
            ("elevated", elevated),
            ("climbing", climbing),
            ("banked", banked),
            ("tilting", tilting),
            ("negative zero", negative_zero),
            ("late", late),
        ]
    }

    fn bits(p: Pose) -> [u64; 6] {
        [p.x, p.y, p.z, p.h, p.p, p.r].map(Real::to_bits)
    }

    /// `pose_in` against `pose`, bit for bit, at every s of a grid over every stretch of the
    /// roads (each stretch asked where it was made and used at every s of the road, so also
    /// outside it, where it must fall back), the stretches' own ends and one ulp beyond, the
    /// pieces' and records' ends, and t over the lane widths, ±0 and far out.
    #[test]
    fn the_straight_stretch_gives_the_full_pose_bit_for_bit() {
        let mut grid: Vec<Real> = (0..=1000).map(|i| Real::from(i) * 0.1).collect();
        for end in [10.0, 20.0, 30.0, 45.0, 50.0, 60.0, 80.0, 100.0] {
            grid.extend([
                end - CONSTANT_MARGIN,
                end - 1e-6,
                end - 1e-9,
                end + 1e-9,
                end + 1e-6,
                end + CONSTANT_MARGIN,
            ]);
        }
        let ts = [0.0, -0.0, 1.75, -1.75, -5.25, 3.5e-3, 1e3, -1e-300];
        let (mut fast, mut straight_at) = (0, Vec::new());
        for (name, road) in roads() {
            // Each range's stretch as made at the first and at the last s of the grid in it.
            let mut stretches: Vec<(FrameStretch, FrameStretch)> = Vec::new();
            for &s in &grid {
                if let Some(st) = road.frame_stretch(s) {
                    assert!(st.holds(s), "{name} at {s}: the stretch holds its s");
                    assert!(0.0 <= st.lo && st.hi <= road.length);
                    match stretches
                        .iter_mut()
                        .find(|(a, _)| (a.lo, a.hi) == (st.lo, st.hi))
                    {
                        Some((_, last)) => *last = st,
                        None => stretches.push((st, st)),
                    }
                }
            }
            let stretches: Vec<FrameStretch> =
                stretches.into_iter().flat_map(|(a, b)| [a, b]).collect();
            for st in &stretches {
                let ends = [st.lo, st.hi].map(|e| [e, e.next_up(), e.next_down()]);
                for &s in grid.iter().chain(ends.as_flattened()) {
                    for &t in &ts {
                        let full = road.pose(s, t);
                        let given = road.pose_in(st, s, t);
                        if st.holds(s) {
                            let held = road.pose_in_held(st, s, t).expect("held: on the road");
                            assert_eq!(bits(held), bits(road.pose(s, t).expect("on the road")));
                        }
                        match (full, given) {
                            (Ok(a), Ok(b)) => assert_eq!(
                                bits(a),
                                bits(b),
                                "{name}, stretch {st:?}, s = {s}, t = {t}: {a:?} against {b:?}"
                            ),
                            (Err(_), Err(_)) => {}
                            (a, b) => panic!("{name} at {s}: {a:?} against {b:?}"),
                        }
                        fast += usize::from(st.is_straight() && st.holds(s));
                    }
                }
                if st.is_straight() && !straight_at.contains(&(name, st.lo, st.hi)) {
                    straight_at.push((name, st.lo, st.hi));
                }
            }
        }
        // The straight stretches: each line of the plain road (the first two touching at
        // 30 m, one margin apart), cut where a record changes (45 m) or varies (50 m, 20 m);
        // none on the arc, on the varying records, or before the late record's 10 m.
        let m = CONSTANT_MARGIN;
        let lines = [(0.0, 30.0 - m), (30.0, 60.0 - m), (60.0, 80.0 - m)];
        let expect = |name: &'static str, ranges: &[(Real, Real)]| {
            let got: Vec<_> = straight_at.iter().filter(|(n, ..)| *n == name).collect();
            let want: Vec<_> = ranges.iter().map(|&(lo, hi)| (name, lo, hi)).collect();
            assert_eq!(got, want.iter().collect::<Vec<_>>(), "{name}");
        };
        expect("plain", &lines);
        // A record from 0 m starts its range a margin after it.
        let from_margin = [(m, 30.0 - m), (30.0, 60.0 - m), (60.0, 80.0 - m)];
        expect("banked", &from_margin);
        expect("negative zero", &from_margin);
        expect(
            "elevated",
            &[
                (m, 30.0 - m),
                (30.0, 45.0 - m),
                (45.0 + m, 60.0 - m),
                (60.0, 80.0 - m),
            ],
        );
        expect("climbing", &[(m, 30.0 - m), (30.0, 50.0 - m)]);
        expect("tilting", &[(m, 20.0 - m)]);
        expect(
            "late",
            &[(10.0 + m, 30.0 - m), (30.0, 60.0 - m), (60.0, 80.0 - m)],
        );
        // The straight path was taken: the plain road's lines alone hold about 800 s of the
        // grid, each asked of two stretches at eight t (12,800).
        assert!(fast > 50_000, "the straight path was taken {fast} times");
    }

    /// The flat, unbanked stretch's shortcut ([`RoadFrame::flat_pose_from`]) against
    /// [`Road::pose`], bit for bit, where the zeros' signs decide: lines from (−0, −0), (+0,
    /// +0) and (1000, −2000) in eight headings (cos h and sin h of both signs, sin 0 = +0),
    /// flat (no elevation, a constant −0, +0 or 12 m, a −0 superelevation) and not (a bank
    /// of either sign: no shortcut there; a straight stretch's elevation is constant, so its
    /// pitch is always +0), at the line's start (ds = 0, x = x₀ + 0·cos h, −0 where
    /// x₀ = −0 and cos h < 0) and over the road, at t = ±0, ±1e-300, ±1.75, 1e3, ±∞ and NaN
    /// (not finite: the full cross section).
    #[test]
    fn the_flat_stretch_gives_the_full_pose_bit_for_bit() {
        use std::f64::consts::{FRAC_PI_2, PI};
        let headings = [0.0, -0.0, 0.5, FRAC_PI_2, 2.5, PI, -2.5, -FRAC_PI_2];
        let starts = [[-0.0, -0.0], [0.0, 0.0], [1000.0, -2000.0]];
        // An elevation of −0 everywhere: a = b = c = d = −0 (−0 + ds·(−0) stays −0; a record
        // of a = −0 with a +0 among b, c, d evaluates to +0).
        let negative_zero = Cubic {
            start: 0.0,
            a: -0.0,
            b: -0.0,
            c: -0.0,
            d: -0.0,
        };
        // (name, elevation, superelevation, flat)
        let profiles: [(&str, Vec<Cubic>, Vec<Cubic>, bool); 7] = [
            ("none", vec![], vec![], true),
            ("z = -0", vec![negative_zero], vec![], true),
            ("z = +0", vec![cubic(0.0, 0.0, -0.0)], vec![], true),
            ("z = 12", vec![cubic(0.0, 12.0, 0.0)], vec![], true),
            ("roll = -0", vec![], vec![cubic(0.0, -0.0, 0.0)], true),
            ("banked", vec![], vec![cubic(0.0, 0.05, 0.0)], false),
            (
                "banked left",
                vec![cubic(0.0, 2.0, 0.0)],
                vec![cubic(0.0, -0.05, 0.0)],
                false,
            ),
        ];
        let mut grid: Vec<Real> = (0..=200).map(|i| Real::from(i) * 0.25).collect();
        grid.extend([-0.0, 1e-300, CONSTANT_MARGIN, 50.0 - CONSTANT_MARGIN, 50.0]);
        let ts = [
            0.0,
            -0.0,
            1e-300,
            -1e-300,
            1.75,
            -1.75,
            1e3,
            Real::INFINITY,
            Real::NEG_INFINITY,
            Real::NAN,
        ];
        let (mut flat_poses, mut negative_zero_x) = (0, 0);
        for h in headings {
            for [x0, y0] in starts {
                for (name, elevation, superelevation, flat) in &profiles {
                    let mut road = straight_road(50.0, Vec::new(), Vec::new());
                    road.plan_view = PlanView::new(vec![Geometry::new(
                        0.0,
                        x0,
                        y0,
                        h,
                        50.0,
                        GeometryKind::Line,
                    )]);
                    road.elevation.clone_from(elevation);
                    road.superelevation.clone_from(superelevation);
                    let st = road.frame_stretch(25.0).expect("a stretch at 25 m");
                    let line = st.line.expect("a line with constant profiles is straight");
                    assert_eq!(line.flat.is_some(), *flat, "{name}, heading {h}");
                    if *name == "z = -0" {
                        // The frame's z is −0, the pose's z' = −0 + (+0) = +0.
                        assert_eq!(line.frame.z.to_bits(), (-0.0_f64).to_bits());
                        assert_eq!(line.flat.map(|f| f[2].to_bits()), Some(0));
                    }
                    for &s in &grid {
                        for &t in &ts {
                            let full = road.pose(s, t).expect("on the road");
                            let given = road.pose_in(&st, s, t).expect("on the road");
                            assert_eq!(
                                bits(full),
                                bits(given),
                                "{name}, heading {h}, from ({x0}, {y0}), s = {s}, t = {t}: \
                                 {full:?} against {given:?}"
                            );
                            if line.flat.is_some() && st.holds(s) && t.is_finite() {
                                flat_poses += 1;
                                negative_zero_x +=
                                    usize::from(full.x.to_bits() == (-0.0_f64).to_bits());
                            }
                        }
                    }
                }
            }
        }
        // Every flat road asked at the grid's s it holds and the seven finite t; the line
        // from (−0, −0) at s = 0 gave x = −0 (a heading whose cosine is negative, t = ±0 or
        // 1e-300 against a sine of +0 or the like) more than once.
        assert!(flat_poses > 8 * 3 * 5 * 190 * 7, "{flat_poses}");
        assert!(negative_zero_x > 0, "{negative_zero_x}");
    }

    /// What the straight stretch computes, by hand: on the plain road's first line from
    /// (1000, −2000) at 0.5 rad, s = 10 and t = 2 lie at (1000 + 10·cos 0.5 − 2·sin 0.5,
    /// −2000 + 10·sin 0.5 + 2·cos 0.5) = (1007.81697, −1993.45058), z = 0, heading 0.5.
    #[test]
    fn a_straight_stretch_moves_along_its_line() {
        let road = pieces();
        let st = road.frame_stretch(5.0).expect("a stretch at 5 m");
        assert!(st.is_straight());
        assert_eq!((st.lo, st.hi), (0.0, 30.0 - CONSTANT_MARGIN));
        let p = road.pose_in(&st, 10.0, 2.0).expect("on the road");
        assert!((p.x - 1007.81697).abs() < 1e-5, "{p:?}");
        assert!((p.y - (-1993.45058)).abs() < 1e-5, "{p:?}");
        assert_eq!((p.z, p.h, p.p, p.r), (0.0, 0.5, 0.0, 0.0));
        // The arc is a stretch, not a straight one; off the road and NaN give none.
        assert!(!road.frame_stretch(90.0).expect("the arc").is_straight());
        for s in [-1.0, 100.5, Real::NAN] {
            assert!(road.frame_stretch(s).is_none(), "{s}");
        }
    }
}
