//! Orientation rules of OpenSCENARIO 1.3 (XSD `Orientation`, §6.3 coordinate systems) as the
//! position forms use them, and the rotation of an entity's local axes into the world.
//!
//! * Road-based forms (RoadPosition, RelativeRoadPosition, LanePosition, RelativeLanePosition,
//!   RoutePosition): "the Pitch and Roll angles are determined by the underlying road surface";
//!   the absolute context gives the heading from the world x-axis, the relative one from the
//!   reference direction. A missing Orientation "is interpreted as the relative reference
//!   context with Heading=Pitch=Roll=0" (1.3 text of RoadPosition). The reference direction is
//!   the road's s-tangent for road coordinates and the lane's direction for lane coordinates,
//!   which oscsim takes as the lane's driving direction (OpenDRIVE 1.8 §11.2: negative ids
//!   run along +s with right-hand traffic, positive ids along −s; left-hand traffic swaps
//!   them), as the domain model's `on_lane` coordinates do (pitfall 15).
//! * Entity-relative forms (RelativeWorldPosition, RelativeObjectPosition): the relative
//!   context adds heading, pitch and roll to the reference entity's; a missing Orientation
//!   takes the entity's orientation unchanged.
//! * World-based forms (WorldPosition, GeoPosition, TrajectoryPosition's vertices): absolute.
//!
//! Pitch and roll on a tilted surface: a heading `dh` away from the road's s-tangent sees the
//! road's pitch P and roll R (OpenDRIVE signs: pitch positive nose down, roll positive right
//! side down) as `tan p = tan P·cos dh − tan R·sin dh`, `tan r = tan P·sin dh + tan R·cos dh`
//! (the surface's slope along the new forward and right axes); `dh = π` gives (−P, −R).

use opendrive::{normalize_angle, Pose, Real};
use scenario::{Orientation, ReferenceContext};

/// Heading, pitch and roll (rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Angles {
    pub h: Real,
    pub p: Real,
    pub r: Real,
}

/// True for an Orientation whose `type` is absolute (absent `type` means relative).
fn is_absolute(o: &Orientation) -> bool {
    o.reference == Some(ReferenceContext::Absolute)
}

/// Orientation of an entity standing on the road surface at `surface` (the road's pose at that
/// point: heading of the s-tangent, pitch and roll of the surface), relative headings counted
/// from `reference_h`.
pub(crate) fn on_surface(
    orientation: Option<&Orientation>,
    surface: &Pose,
    reference_h: Real,
) -> Angles {
    let h = match orientation {
        Some(o) if is_absolute(o) => o.h,
        Some(o) => reference_h + o.h,
        None => reference_h,
    };
    let h = normalize_angle(h);
    let dh = h - surface.h;
    let (tp, tr) = (surface.p.tan(), surface.r.tan());
    let p = (tp * dh.cos() - tr * dh.sin()).atan();
    let r = (tp * dh.sin() + tr * dh.cos()).atan();
    Angles { h, p, r }
}

/// Orientation relative to a reference entity's pose (entity-relative forms).
pub(crate) fn relative_to(orientation: Option<&Orientation>, reference: &Pose) -> Angles {
    match orientation {
        Some(o) if is_absolute(o) => Angles {
            h: normalize_angle(o.h),
            p: normalize_angle(o.p),
            r: normalize_angle(o.r),
        },
        Some(o) => Angles {
            h: normalize_angle(reference.h + o.h),
            p: normalize_angle(reference.p + o.p),
            r: normalize_angle(reference.r + o.r),
        },
        None => Angles {
            h: reference.h,
            p: reference.p,
            r: reference.r,
        },
    }
}

/// Orientation of a form whose frame is the world (absolute even if written relative, there
/// being nothing else to be relative to), `base` giving the heading when none is written.
pub(crate) fn absolute_or(orientation: Option<&Orientation>, base: Angles) -> Angles {
    match orientation {
        Some(o) if is_absolute(o) => Angles {
            h: normalize_angle(o.h),
            p: o.p,
            r: o.r,
        },
        Some(o) => Angles {
            h: normalize_angle(base.h + o.h),
            p: base.p + o.p,
            r: base.r + o.r,
        },
        None => base,
    }
}

/// The world offset of the vector (`dx`, `dy`, `dz`) given in the axes of an object at `pose`
/// (x forward, y left, z up): `Rz(h)·Ry(p)·Rx(r)·d`, the rotation order of OpenDRIVE 1.8 §8
/// (heading, then pitch about the new y, then roll about the new x).
pub(crate) fn local_to_world(pose: &Pose, dx: Real, dy: Real, dz: Real) -> [Real; 3] {
    let (sr, cr) = pose.r.sin_cos();
    let (sp, cp) = pose.p.sin_cos();
    let (sh, ch) = pose.h.sin_cos();
    // Roll about x.
    let (x1, y1, z1) = (dx, cr * dy - sr * dz, sr * dy + cr * dz);
    // Pitch about y (positive nose down: +x turns towards −z).
    let (x2, y2, z2) = (cp * x1 + sp * z1, y1, -sp * x1 + cp * z1);
    // Heading about z.
    [ch * x2 - sh * y2, sh * x2 + ch * y2, z2]
}
