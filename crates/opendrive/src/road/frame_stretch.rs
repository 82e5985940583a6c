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
//! pose from them by the same `RoadFrame::pose_from`.

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
/// stretch, whose numbers other than x and y hold all along it (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
struct LineFrame {
    start: [Real; 3],
    frame: RoadFrame,
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
    /// [`Road::pose`] at (s, t) for an s of the stretch (module doc).
    #[inline(always)]
    fn pose(&self, s: Real, t: Real) -> Pose {
        let [s0, x0, y0] = self.start;
        let f = &self.frame;
        f.pose_from(line::along([x0, y0], s - s0, [f.sin_h, f.cos_h]), t)
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
        let flat = |r: Option<&_>| r.map_or(true, is_constant);
        let straight =
            matches!(g.kind, GeometryKind::Line) && flat(elevation) && flat(superelevation);
        Some(FrameStretch {
            lo,
            hi,
            line: straight.then(|| LineFrame {
                start: [g.s, g.x, g.y],
                frame: road_frame(self, s),
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
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{Arc, Geometry, PlanView};
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
