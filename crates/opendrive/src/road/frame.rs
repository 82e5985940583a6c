//! The road's local frame at s (OpenDRIVE 1.8 §8.3 reference-line coordinate system): the
//! reference point lifted by the elevation, heading from the plan view, pitch from the
//! elevation slope and roll from the superelevation. A point (t, height) of the cross-section
//! sits at reference point + Rz(h)·Ry(p)·Rx(r)·(0, t, height): t is measured in the tilted
//! cross-section (§10.5 superelevation rotates the t-axis about the s-axis).

use crate::math::{eval_piecewise, Pose, Real};
use crate::model::Road;

/// The reference-line frame at some s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RoadFrame {
    pub(crate) x: Real,
    pub(crate) y: Real,
    pub(crate) z: Real,
    pub(crate) hdg: Real,
    pub(crate) curvature: Real,
    pub(crate) pitch: Real,
    pub(crate) roll: Real,
    /// d(roll)/ds (rad/m).
    pub(crate) roll_rate: Real,
    pub(super) sin_h: Real,
    pub(super) cos_h: Real,
    sin_p: Real,
    cos_p: Real,
    sin_r: Real,
    cos_r: Real,
}

/// The cross-section point (t, height) of a frame at reference point `xy` with heading,
/// pitch and roll given by their sines and cosines: Rx(roll)·(0, t, height) = (0, a, b),
/// Ry(pitch) moves it b·sin p forward, Rz(h) turns it. Returns its horizontal place and b
/// (the height after roll, for z = b·cos p). [`RoadFrame::place`] and
/// `PlanFrame::place` (plan_frame.rs) both place points with it.
#[inline]
pub(crate) fn cross_section(
    t: Real,
    height: Real,
    [x, y]: [Real; 2],
    [sin_h, cos_h]: [Real; 2],
    sin_p: Real,
    [sin_r, cos_r]: [Real; 2],
) -> ([Real; 2], Real) {
    let a = t * cos_r - height * sin_r;
    let b = t * sin_r + height * cos_r;
    let fwd = b * sin_p;
    (
        [x + fwd * cos_h - a * sin_h, y + fwd * sin_h + a * cos_h],
        b,
    )
}

/// The frame of `road` at `s` (s already within [0, length]). Always inlined: its callers
/// read a few of its numbers, which then stay in registers (returned through memory, they
/// were stored one by one and read back two at a time, loads that wait for the stores, issue
/// 31).
#[inline(always)]
pub(crate) fn road_frame(road: &Road, s: Real) -> RoadFrame {
    let (rp, sin_h, cos_h) = road.plan_view.eval_trig(s);
    let (z, dz) = eval_piecewise(&road.elevation, s);
    let (roll, roll_rate) = eval_piecewise(&road.superelevation, s);
    // Positive pitch is nose down (rotation about the left-pointing y axis). Flat and unbanked
    // roads skip the trigonometry.
    let (pitch, sin_p, cos_p) = if dz == 0.0 {
        (0.0, 0.0, 1.0)
    } else {
        let p = -dz.atan();
        let (sp, cp) = p.sin_cos();
        (p, sp, cp)
    };
    let (sin_r, cos_r) = if roll == 0.0 {
        (0.0, 1.0)
    } else {
        roll.sin_cos()
    };
    RoadFrame {
        x: rp.x,
        y: rp.y,
        z,
        hdg: rp.hdg,
        curvature: rp.curvature,
        pitch,
        roll,
        roll_rate,
        sin_h,
        cos_h,
        sin_p,
        cos_p,
        sin_r,
        cos_r,
    }
}

impl RoadFrame {
    /// World position of the cross-section point (t, height above the road surface).
    #[inline]
    pub(crate) fn place(&self, t: Real, height: Real) -> [Real; 3] {
        self.place_from([self.x, self.y], t, height)
    }

    /// [`place`](Self::place) with the reference point `xy` in place of the frame's own.
    #[inline(always)]
    fn place_from(&self, xy: [Real; 2], t: Real, height: Real) -> [Real; 3] {
        let ([x, y], b) = cross_section(
            t,
            height,
            xy,
            [self.sin_h, self.cos_h],
            self.sin_p,
            [self.sin_r, self.cos_r],
        );
        [x, y, self.z + b * self.cos_p]
    }

    /// The pose of the surface point at `t` ([`place`](Self::place) at height 0): heading,
    /// pitch and roll the reference line's ([`Road::pose`]).
    #[inline(always)]
    pub(crate) fn pose(&self, t: Real) -> Pose {
        self.pose_from([self.x, self.y], t)
    }

    /// [`pose`](Self::pose) with the reference point `xy` in place of the frame's own.
    #[inline(always)]
    pub(crate) fn pose_from(&self, xy: [Real; 2], t: Real) -> Pose {
        let [x, y, z] = self.place_from(xy, t, 0.0);
        Pose {
            x,
            y,
            z,
            h: self.hdg,
            p: self.pitch,
            r: self.roll,
        }
    }

    /// The constants of [`pose_from`](Self::pose_from) on a flat, unbanked frame, `[cx, cy,
    /// z']`, where that pose is `(x + cx − t·sin h, y + cy + t·cos h, z')` for every finite t;
    /// `None` unless the pitch's and the roll's sines are +0 and their cosines 1 (the values
    /// [`road_frame`] gives where the elevation's slope and the superelevation are zero, of
    /// either sign).
    ///
    /// Why bit for bit: `cross_section` at height +0 with sin p = sin r = +0 and cos p =
    /// cos r = 1 computes a = t·1 − (+0)·(+0) = t − (+0) = t (for every t, −0 included:
    /// −0 − (+0) = −0), b = t·(+0) + (+0)·1 = (±0) + (+0) = +0 for a finite t (a sum of zeros
    /// of opposite signs is +0 when rounding to nearest), fwd = b·sin p = +0, and then x + fwd·cos h − a·sin h
    /// = (x + cx) − t·sin h with cx = (+0)·cos h, y + fwd·sin h + a·cos h = (y + cy) + t·cos h
    /// with cy = (+0)·sin h, z + b·cos p = z + (+0) = z'. The same operations on the same
    /// values in the same order, the zeros' signs included (cx and z' are kept as computed,
    /// not assumed: x + cx is not x where x = −0 and cx = +0, z + (+0) is +0 where z = −0). An
    /// infinite or NaN t gives b = NaN: the caller computes those in full.
    #[inline]
    pub(crate) fn flat_constants(&self) -> Option<[Real; 3]> {
        let zero = |v: Real| v.to_bits() == 0.0_f64.to_bits();
        (zero(self.sin_p) && self.cos_p == 1.0 && zero(self.sin_r) && self.cos_r == 1.0)
            .then_some([0.0 * self.cos_h, 0.0 * self.sin_h, self.z + 0.0])
    }

    /// [`pose_from`](Self::pose_from) on a flat, unbanked frame given its
    /// [`flat_constants`](Self::flat_constants) `[cx, cy, z']`, for a finite `t`.
    #[inline(always)]
    pub(crate) fn flat_pose_from(
        &self,
        [x, y]: [Real; 2],
        t: Real,
        [cx, cy, z]: [Real; 3],
    ) -> Pose {
        Pose {
            x: (x + cx) - t * self.sin_h,
            y: (y + cy) + t * self.cos_h,
            z,
            h: self.hdg,
            p: self.pitch,
            r: self.roll,
        }
    }

    /// Heading of the curve s ↦ place(t(s), height) in the horizontal plane, given dt/ds:
    /// the horizontal lateral offset is a = t·cos r − height·sin r, so the tangent is
    /// (1 − κa)·T + a′·N with a′ = t′·cos r − (t·sin r + height·cos r)·r′. The small forward
    /// shift b·sin p of banked, sloped cross-sections is left out of the derivative.
    #[inline]
    pub(crate) fn tangent_heading(&self, t: Real, dt_ds: Real, height: Real) -> Real {
        let a = t * self.cos_r - height * self.sin_r;
        let b = t * self.sin_r + height * self.cos_r;
        let da = dt_ds * self.cos_r - b * self.roll_rate;
        self.hdg + da.atan2(1.0 - self.curvature * a)
    }

    /// Horizontal derivatives of [`place`](Self::place) with respect to s and t (used by the
    /// world → road Newton iteration): (∂xy/∂s, ∂xy/∂t), neglecting the change of roll and
    /// pitch along s (the iteration converges on the exact residual regardless). The
    /// iteration itself uses `PlanFrame::jacobian`; this is its reference in the tests.
    #[cfg(test)]
    pub(crate) fn jacobian(&self, t: Real) -> [[Real; 2]; 2] {
        let along = 1.0 - self.curvature * t * self.cos_r;
        [
            [along * self.cos_h, -self.cos_r * self.sin_h],
            [along * self.sin_h, self.cos_r * self.cos_h],
        ]
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::geometry::{Geometry, GeometryKind, PlanView};
    use crate::math::Cubic;
    use crate::model::{LaneSection, RoadLinks, TrafficRule};

    /// A straight road along +x, for unit tests.
    pub(crate) fn straight_road(
        length: f64,
        lane_offsets: Vec<Cubic>,
        lane_sections: Vec<LaneSection>,
    ) -> Road {
        Road {
            id: "1".into(),
            name: String::new(),
            length,
            junction: None,
            rule: TrafficRule::RightHand,
            links: RoadLinks::default(),
            types: Vec::new(),
            plan_view: PlanView::new(vec![Geometry::new(
                0.0,
                0.0,
                0.0,
                0.0,
                length,
                GeometryKind::Line,
            )]),
            elevation: Vec::new(),
            superelevation: Vec::new(),
            lane_offsets,
            lane_sections,
            objects: Vec::new(),
            signals: Vec::new(),
        }
    }

    #[test]
    fn banked_and_climbing_cross_section() {
        // Straight road along +x, climbing 10 % (z = 0.1·s), banked 0.2 rad. At s = 50:
        // z = 5, pitch = −atan(0.1). The point t = 4 on the surface (height 0):
        // a = 4·cos 0.2, b = 4·sin 0.2; forward = b·sin p; z = 5 + b·cos p.
        let mut road = straight_road(100.0, vec![], vec![]);
        road.elevation = vec![Cubic {
            start: 0.0,
            a: 0.0,
            b: 0.1,
            c: 0.0,
            d: 0.0,
        }];
        road.superelevation = vec![Cubic {
            start: 0.0,
            a: 0.2,
            b: 0.0,
            c: 0.0,
            d: 0.0,
        }];
        let f = road_frame(&road, 50.0);
        let p = f.place(4.0, 0.0);
        let pitch = -(0.1_f64.atan());
        let b = 4.0 * 0.2_f64.sin();
        assert!((p[0] - (50.0 + b * pitch.sin())).abs() < 1e-12, "{p:?}");
        assert!((p[1] - 4.0 * 0.2_f64.cos()).abs() < 1e-12);
        assert!((p[2] - (5.0 + b * pitch.cos())).abs() < 1e-12);
    }
}
