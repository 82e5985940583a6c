//! `<planView>` and `<geometry>` (OpenDRIVE 1.8 §9.1–9.2): the road reference line as a
//! sequence of geometries, each placed at (x, y, hdg) in the inertial frame; the geometry
//! valid at s is found by binary search.

use super::{line, Arc, LocalPoint, ParamPoly3, Poly3, Spiral};
use crate::math::{normalize_angle, Real};

/// The curve type of a `<geometry>`.
#[derive(Debug, Clone, PartialEq)]
pub enum GeometryKind {
    /// `<line>`.
    Line,
    /// `<arc>`.
    Arc(Arc),
    /// `<spiral>`.
    Spiral(Spiral),
    /// `<poly3>`.
    Poly3(Poly3),
    /// `<paramPoly3>`.
    ParamPoly3(ParamPoly3),
}

impl GeometryKind {
    /// The element name ("line", "arc", "spiral", "poly3", "paramPoly3").
    pub fn name(&self) -> &'static str {
        match self {
            Self::Line => "line",
            Self::Arc(_) => "arc",
            Self::Spiral(_) => "spiral",
            Self::Poly3(_) => "poly3",
            Self::ParamPoly3(_) => "paramPoly3",
        }
    }
}

/// `<geometry s x y hdg length>` with its curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Geometry {
    /// `s` (m) where the geometry starts.
    pub s: Real,
    /// `x` (m) of the start.
    pub x: Real,
    /// `y` (m) of the start.
    pub y: Real,
    /// `hdg` (rad) at the start.
    pub hdg: Real,
    /// `length` (m).
    pub length: Real,
    /// The curve.
    pub kind: GeometryKind,
    cos_h: Real,
    sin_h: Real,
}

/// A point of the reference line: position, heading and curvature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RefPoint {
    /// x (m).
    pub x: Real,
    /// y (m).
    pub y: Real,
    /// Heading (rad), in (−π, π].
    pub hdg: Real,
    /// Signed curvature (1/m).
    pub curvature: Real,
}

impl Geometry {
    /// A geometry from its attributes and curve.
    pub fn new(s: Real, x: Real, y: Real, hdg: Real, length: Real, kind: GeometryKind) -> Self {
        let (sin_h, cos_h) = hdg.sin_cos();
        Self {
            s,
            x,
            y,
            hdg,
            length,
            kind,
            cos_h,
            sin_h,
        }
    }

    /// The curve in its local frame at `ds` from the geometry's start.
    #[inline]
    pub fn local(&self, ds: Real) -> LocalPoint {
        match &self.kind {
            GeometryKind::Line => line::eval(ds),
            GeometryKind::Arc(a) => a.eval(ds),
            GeometryKind::Spiral(sp) => sp.eval(ds),
            GeometryKind::Poly3(p) => p.eval(ds),
            GeometryKind::ParamPoly3(p) => p.eval(ds),
        }
    }

    /// The reference line at `s` with the sine and cosine of its heading (a line reuses its
    /// start heading's, computed once).
    ///
    /// Always inlined, the curves' case called out: returned through memory, its six numbers
    /// were stored one by one and read back two at a time by the caller, a load the stores
    /// cannot forward to, which waits until they reach the cache (`road_frame` spent two
    /// thirds of its samples there on the scale highway's lines, issue 31).
    #[inline(always)]
    pub(crate) fn eval_trig(&self, s: Real) -> (RefPoint, Real, Real) {
        match self.kind {
            GeometryKind::Line => {
                let [x, y] = line::along([self.x, self.y], s - self.s, [self.sin_h, self.cos_h]);
                let rp = RefPoint {
                    x,
                    y,
                    hdg: normalize_angle(self.hdg),
                    curvature: 0.0,
                };
                (rp, self.sin_h, self.cos_h)
            }
            _ => self.eval_trig_curve(s),
        }
    }

    /// [`eval_trig`](Self::eval_trig) of a curve: the sine and cosine of its heading at `s`.
    #[inline(never)]
    fn eval_trig_curve(&self, s: Real) -> (RefPoint, Real, Real) {
        let rp = self.eval(s);
        let (sin_h, cos_h) = rp.hdg.sin_cos();
        (rp, sin_h, cos_h)
    }

    /// The reference line at road coordinate `s` (within or slightly outside this geometry).
    #[inline]
    pub fn eval(&self, s: Real) -> RefPoint {
        let l = self.local(s - self.s);
        RefPoint {
            x: self.x + l.u * self.cos_h - l.v * self.sin_h,
            y: self.y + l.u * self.sin_h + l.v * self.cos_h,
            hdg: normalize_angle(self.hdg + l.hdg),
            curvature: l.curvature,
        }
    }
}

/// `<planView>`: geometries sorted by `s`, never empty (the parser checks).
#[derive(Debug, Clone, PartialEq)]
pub struct PlanView {
    geometries: Vec<Geometry>,
    /// [`straight_heading`](Self::straight_heading), decided once.
    straight: Option<Real>,
}

impl PlanView {
    /// A plan view from geometries sorted by `s` (at least one).
    pub(crate) fn new(geometries: Vec<Geometry>) -> Self {
        let straight = straight_heading(&geometries);
        Self {
            geometries,
            straight,
        }
    }

    /// The heading of a reference line that is one straight line: every geometry a `<line>`
    /// (§9.2.1) whose heading, wrapped into (−π, π], has the same bits as the others'. Then
    /// the heading [`Road::heading`](crate::Road::heading) gives at every s is this value,
    /// bit for bit (a line's heading does not depend on s), and the reference line's
    /// curvature is 0 everywhere. `None` for any other plan view.
    #[inline]
    pub fn straight_heading(&self) -> Option<Real> {
        self.straight
    }

    /// The geometries in order of s.
    pub fn geometries(&self) -> &[Geometry] {
        &self.geometries
    }

    /// Index of the geometry valid at `s` (the last one starting at or before `s`).
    #[inline]
    pub fn index_at(&self, s: Real) -> usize {
        self.geometries
            .partition_point(|g| g.s <= s)
            .saturating_sub(1)
    }

    /// The reference line at `s`.
    #[inline]
    pub fn eval(&self, s: Real) -> RefPoint {
        self.geometries[self.index_at(s)].eval(s)
    }

    /// The reference line at `s` with sin and cos of its heading.
    #[inline(always)]
    pub(crate) fn eval_trig(&self, s: Real) -> (RefPoint, Real, Real) {
        self.geometries[self.index_at(s)].eval_trig(s)
    }
}

/// [`PlanView::straight_heading`] of `geometries`: the wrapped heading every one of them
/// gives at any s, where all are lines with the same one.
fn straight_heading(geometries: &[Geometry]) -> Option<Real> {
    let first = normalize_angle(geometries.first()?.hdg);
    let same = geometries.iter().all(|g| {
        matches!(g.kind, GeometryKind::Line) && normalize_angle(g.hdg).to_bits() == first.to_bits()
    });
    (same && first.is_finite()).then_some(first)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_straight_heading_only_where_every_piece_is_a_line_of_one_heading() {
        let line =
            |s: Real, x: Real, hdg: Real| Geometry::new(s, x, 0.0, hdg, 10.0, GeometryKind::Line);
        // Two lines at 0.5 rad, one after the other: the heading is 0.5 at every s.
        let straight = PlanView::new(vec![line(0.0, 0.0, 0.5), line(10.0, 10.0, 0.5)]);
        assert_eq!(straight.straight_heading(), Some(0.5));
        assert_eq!(straight.eval_trig(3.0).0.hdg, 0.5);
        assert_eq!(straight.eval_trig(17.0).0.hdg, 0.5);
        // A kink (0.5 then 0.6 rad), a line then an arc: not straight.
        let kinked = PlanView::new(vec![line(0.0, 0.0, 0.5), line(10.0, 10.0, 0.6)]);
        assert_eq!(kinked.straight_heading(), None);
        let arc = Geometry::new(
            10.0,
            10.0,
            0.0,
            0.5,
            10.0,
            GeometryKind::Arc(Arc { curvature: 0.0 }),
        );
        assert_eq!(
            PlanView::new(vec![line(0.0, 0.0, 0.5), arc]).straight_heading(),
            None
        );
    }

    #[test]
    fn geometry_is_placed_by_its_start_pose() {
        // A line starting at (10, 5) with heading π/2 reaches (10, 5 + 3) after 3 m.
        let g = Geometry::new(
            100.0,
            10.0,
            5.0,
            std::f64::consts::FRAC_PI_2,
            20.0,
            GeometryKind::Line,
        );
        let p = g.eval(103.0);
        assert!(
            (p.x - 10.0).abs() < 1e-12 && (p.y - 8.0).abs() < 1e-12,
            "{p:?}"
        );
    }

    #[test]
    fn plan_view_finds_the_geometry_by_binary_search() {
        let pv = PlanView::new(vec![
            Geometry::new(0.0, 0.0, 0.0, 0.0, 10.0, GeometryKind::Line),
            Geometry::new(
                10.0,
                10.0,
                0.0,
                0.0,
                10.0,
                GeometryKind::Arc(Arc { curvature: 0.1 }),
            ),
        ]);
        assert_eq!(pv.index_at(0.0), 0);
        assert_eq!(pv.index_at(9.999), 0);
        assert_eq!(pv.index_at(10.0), 1);
        assert_eq!(pv.index_at(25.0), 1);
        // On the arc, 5 m in: (10 + sin(0.5)/0.1, 2·sin²(0.25)/0.1).
        let p = pv.eval(15.0);
        assert!((p.x - (10.0 + 0.5_f64.sin() / 0.1)).abs() < 1e-12);
        assert!((p.y - (1.0 - 0.5_f64.cos()) / 0.1).abs() < 1e-12);
    }
}
