//! OpenSCENARIO 2.0 §8.7.5.1.1 method time_to_collision(): "the time until the bounding_box
//! of traffic_participant would collide with the bounding box of the reference
//! physical_object, assuming both keep moving with their current velocity".
//!
//! Model (oscsim's reading of "current velocity"): both boxes keep their present translational
//! velocity (velocity_6d.translational turned into world axes by the present pose) and their
//! present orientation; the yaw rate is not extrapolated. The boxes are taken as their
//! ground-plane footprints (oriented rectangles, see `footprint`), and the vertical extents
//! must overlap: a box passing over or under the other (a bridge) never collides.
//!
//! Computation: exact, by the separating axis theorem on the relative motion. Two convex
//! polygons overlap iff their projections overlap on every edge normal of both; for two
//! rectangles that is four axes. With B moving at w = v_B − v_A relative to A, the projections
//! on axis n overlap for t in a closed interval [t0, t1] (all t or none when w·n = 0), and the
//! boxes touch exactly for t in the intersection of the four intervals. The time to collision
//! is that intersection's lower end clipped at 0: `Some(0)` when the boxes already overlap or
//! touch, `None` when the intersection is empty or lies wholly in the past (receding).
//! Touching counts as collision (grazing contact gives a time), with intervals widened by
//! `LENGTH_EPSILON` so that round-off cannot turn a grazing contact into a miss. A pose or
//! velocity that is not finite (NaN, ∞) gives `None`: no time can be computed from it.
//!
//! Why by hand: the exact interval computation is some thirty lines over the rectangle
//! projections that `space_gap` also uses; parry's shape casting would bring nalgebra and an
//! iterative, tolerance-bounded GJK/EPA result for what is a closed-form question here.

use opendrive::{Real, LENGTH_EPSILON};

use super::footprint::{dot, Footprint};
use super::frame::Frame;
use super::{Physical, PhysicalObject, TrafficParticipant, Velocity6d};

impl TrafficParticipant {
    /// §8.7.5.1.1 `time_to_collision(reference)`: seconds until this participant's bounding
    /// box touches `reference`'s, both keeping their current velocities; `Some(0.0)` when they
    /// already overlap, `None` when they never touch. See the module doc for the model.
    pub fn time_to_collision(&self, reference: &impl Physical) -> Option<Real> {
        time_to_collision(self.physical_object(), &self.velocity(), reference)
    }
}

/// Time to collision between `a` moving with `va` and `reference` with its own velocity.
pub(crate) fn time_to_collision(
    a: &PhysicalObject,
    va: &Velocity6d,
    reference: &impl Physical,
) -> Option<Real> {
    let b = reference.physical_object();
    let vb = reference.velocity();
    let inputs = [&a.pose, &b.pose]
        .into_iter()
        .flat_map(|p| [p.x, p.y, p.z, p.h, p.p, p.r]);
    let speeds = [va, &vb]
        .into_iter()
        .flat_map(|v| [v.translational.x, v.translational.y]);
    if !inputs.chain(speeds).all(Real::is_finite) {
        return None;
    }
    let (frame_a, frame_b) = (Frame::new(&a.pose), Frame::new(&b.pose));
    let (fa, (a_bottom, a_top)) = a.bounding_box.placed(&frame_a, a.pose.h);
    let (fb, (b_bottom, b_top)) = b.bounding_box.placed(&frame_b, b.pose.h);
    if b_bottom > a_top + LENGTH_EPSILON || a_bottom > b_top + LENGTH_EPSILON {
        return None;
    }
    let wa = frame_a.rotate(va.translational);
    let wb = frame_b.rotate(vb.translational);
    footprint_time_to_collision(&fa, &fb, [wb.x - wa.x, wb.y - wa.y])
}

/// Earliest t ≥ 0 at which `b`, moving at `w` relative to `a`, touches `a`; see module doc.
///
/// Two intersections are kept: the exact one, whose lower end is the answer, and one of the
/// intervals widened by `LENGTH_EPSILON`, which decides whether there is contact at all. So a
/// grazing contact that round-off turns into a tiny miss still counts, and the widening does
/// not shift the time found (by `LENGTH_EPSILON / |w|`).
pub(crate) fn footprint_time_to_collision(
    a: &Footprint,
    b: &Footprint,
    w: [Real; 2],
) -> Option<Real> {
    let mut enter = 0.0;
    let (mut enter_wide, mut leave_wide) = (0.0, Real::INFINITY);
    for n in [a.axis_x, a.axis_y(), b.axis_x, b.axis_y()] {
        let (a_min, a_max) = a.project(n);
        let (b_min, b_max) = b.project(n);
        // On this axis B overlaps A while a_min − b_max ≤ (w·n)·t ≤ a_max − b_min.
        let (lo, hi) = (a_min - b_max, a_max - b_min);
        let wn = dot(w, n);
        // Exactly parallel motion is the only case without an entry time.
        if wn == 0.0 {
            if lo > LENGTH_EPSILON || hi < -LENGTH_EPSILON {
                return None;
            }
            continue;
        }
        let (lo_wide, hi_wide) = (lo - LENGTH_EPSILON, hi + LENGTH_EPSILON);
        let (t0, t0_wide, t1_wide) = if wn > 0.0 {
            (lo / wn, lo_wide / wn, hi_wide / wn)
        } else {
            (hi / wn, hi_wide / wn, lo_wide / wn)
        };
        enter = Real::max(enter, t0);
        enter_wide = Real::max(enter_wide, t0_wide);
        leave_wide = Real::min(leave_wide, t1_wide);
        if enter_wide > leave_wide {
            return None;
        }
    }
    Some(Real::min(enter, leave_wide))
}
