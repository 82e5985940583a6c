//! World-frame positions (OpenSCENARIO 1.3 §6.3.1 world coordinate system, §6.3.2 object
//! coordinate system; XSD `WorldPosition`, `RelativeWorldPosition`, `RelativeObjectPosition`).
//!
//! * WorldPosition: x, y as written. An absent z puts the point on the road surface below it
//!   (z = 0 where there is no road); absent h, p, r are 0 (1.3: "missing value is
//!   interpreted as 0").
//! * RelativeWorldPosition: the reference entity's reference point plus (dx, dy, dz) along the
//!   world axes.
//! * RelativeObjectPosition: the reference entity's reference point plus (dx, dy, dz) along the
//!   entity's own axes (x forward, y left, z up), turned by its heading, pitch and roll.
//!
//! For both relative forms an absent dz puts the point on the road surface (or at the
//! entity's height plus the rotated offset's z off-road), and the orientation follows
//! `orientation::relative_to`.

use opendrive::{Pose, Real, RoadNetwork, LENGTH_EPSILON};
use scenario::{Orientation, SourcePos};

use super::orientation::{local_to_world, relative_to, Angles};
use super::{EntityQuery, EntityView, PositionError, PositionErrorKind, ResolvedPosition};

/// The entity `name`, or an `UnknownEntity` error at `pos`.
pub(crate) fn entity<'q, Q: EntityQuery + ?Sized>(
    ctx: &'q Q,
    name: &str,
    pos: &SourcePos,
) -> Result<EntityView<'q>, PositionError> {
    ctx.entity(name)
        .ok_or_else(|| PositionError::new(PositionErrorKind::UnknownEntity(name.into()), pos))
}

/// Height of the road surface at (x, y), `None` off every road.
pub(crate) fn surface_z(network: &RoadNetwork, x: Real, y: Real) -> Option<Real> {
    let rp = network.locate(x, y, None)?;
    if rp.distance > LENGTH_EPSILON {
        return None;
    }
    network.road_pose(&rp.road_id, rp.s, rp.t).ok().map(|p| p.z)
}

/// The angles of an Orientation element, if there is one, are finite numbers (`pos`: its
/// position's place).
pub(crate) fn finite_orientation(
    orientation: Option<&Orientation>,
    pos: &SourcePos,
) -> Result<(), PositionError> {
    match orientation {
        Some(o) => finite(
            &[
                ("Orientation h", o.h),
                ("Orientation p", o.p),
                ("Orientation r", o.r),
            ],
            pos,
        ),
        None => Ok(()),
    }
}

/// Checks that every value is finite.
pub(crate) fn finite(
    values: &[(&'static str, Real)],
    pos: &SourcePos,
) -> Result<(), PositionError> {
    for &(what, value) in values {
        if !value.is_finite() {
            return Err(PositionError::new(
                PositionErrorKind::NotFinite { what, value },
                pos,
            ));
        }
    }
    Ok(())
}

/// `WorldPosition`.
#[allow(clippy::too_many_arguments)] // the six attributes of the XSD element, plus context.
pub(crate) fn world(
    network: &RoadNetwork,
    x: Real,
    y: Real,
    z: Option<Real>,
    angles: [Option<Real>; 3],
    pos: &SourcePos,
) -> Result<ResolvedPosition, PositionError> {
    finite(&[("x", x), ("y", y), ("z", z.unwrap_or(0.0))], pos)?;
    let z = z.unwrap_or_else(|| surface_z(network, x, y).unwrap_or(0.0));
    let [h, p, r] = angles.map(|a| a.unwrap_or(0.0));
    finite(&[("h", h), ("p", p), ("r", r)], pos)?;
    let pose = Pose {
        x,
        y,
        z,
        h: opendrive::normalize_angle(h),
        p,
        r,
    };
    Ok(ResolvedPosition::located(network, pose))
}

/// `RelativeWorldPosition` (`in_object_axes` false) and `RelativeObjectPosition` (true);
/// `reference` gives the entity `entity_ref` names (`resolve::resolve_with`).
#[allow(clippy::too_many_arguments)] // the attributes of the XSD elements, plus context.
pub(crate) fn relative<'q>(
    network: &RoadNetwork,
    entity_ref: &str,
    reference: impl FnOnce(&str) -> Result<EntityView<'q>, PositionError>,
    [dx, dy]: [Real; 2],
    dz: Option<Real>,
    orientation: Option<&Orientation>,
    in_object_axes: bool,
    pos: &SourcePos,
) -> Result<ResolvedPosition, PositionError> {
    finite(&[("dx", dx), ("dy", dy), ("dz", dz.unwrap_or(0.0))], pos)?;
    let e = reference(entity_ref)?;
    let d = if in_object_axes {
        local_to_world(&e.pose, dx, dy, dz.unwrap_or(0.0))
    } else {
        [dx, dy, dz.unwrap_or(0.0)]
    };
    let (x, y) = (e.pose.x + d[0], e.pose.y + d[1]);
    let z = match dz {
        Some(_) => e.pose.z + d[2],
        None => surface_z(network, x, y).unwrap_or(e.pose.z + d[2]),
    };
    let Angles { h, p, r } = relative_to(orientation, &e.pose);
    let pose = Pose { x, y, z, h, p, r };
    Ok(ResolvedPosition::located(network, pose))
}

/// `GeoPosition`: latitude and longitude (degrees) through the network's georeference to x/y,
/// then as a WorldPosition with z on the road surface (resolve.rs says why).
pub(crate) fn geo(
    network: &RoadNetwork,
    [latitude, longitude]: [Real; 2],
    altitude: Option<Real>,
    orientation: Option<&Orientation>,
    pos: &SourcePos,
) -> Result<ResolvedPosition, PositionError> {
    finite(
        &[
            ("latitudeDeg", latitude),
            ("longitudeDeg", longitude),
            ("altitude", altitude.unwrap_or(0.0)),
        ],
        pos,
    )?;
    let transform = opendrive::GeoTransform::new(network.header())
        .map_err(|e| PositionError::new(PositionErrorKind::Geo(e), pos))?;
    let (x, y) = transform
        .to_local(latitude, longitude)
        .map_err(|e| PositionError::new(PositionErrorKind::Geo(e), pos))?;
    let angles = match orientation {
        None => [None; 3],
        Some(o) if o.reference == Some(scenario::ReferenceContext::Relative) => {
            return Err(PositionError::new(
                PositionErrorKind::Unsupported {
                    expected: "an absolute Orientation for a GeoPosition",
                    found: "type=\"relative\" (a GeoPosition has no reference)",
                },
                pos,
            ))
        }
        Some(o) => [Some(o.h), Some(o.p), Some(o.r)],
    };
    world(network, x, y, None, angles, pos)
}
