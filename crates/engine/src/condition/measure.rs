//! Distances between a triggering entity and a target (an entity or a position), as the
//! distance-based conditions measure them (OpenSCENARIO 1.3 §6.4 "Distances"; attributes
//! `freespace`, `coordinateSystem`, `relativeDistanceType`, `routingAlgorithm`), through the
//! OpenSCENARIO 2.0 §8.7 methods of `domain`.
//!
//! Who measures and with which sign (pitfalls 12–13): the triggering entity measures, in its
//! own frame. Longitudinal and lateral values are signed, positive when the target lies ahead
//! of / left of the triggering entity; Euclidean values are ≥ 0. The conditions compare the
//! magnitude (§6.4: "distances [are] greater than or equal to zero"); TimeHeadway and
//! TimeToCollision use the sign to tell ahead from behind and closing from opening.
//!
//! | coordinateSystem | longitudinal / lateral | euclidianDistance |
//! | --- | --- | --- |
//! | entity (default) | §8.7.2.1.1 object_distance() on the entity's x / y axis; freespace: gap between the boxes' intervals on that axis, 0 when they overlap | 3D distance of the reference points; freespace: 2D distance between the boxes' ground footprints, 0 when they overlap |
//! | road, lane | §8.7.5.1.3 space_gap() along the road s / t (boxes when freespace, points otherwise), turned to the triggering entity's direction of travel; across roads along the shortest road path; lane: along the lane centre (below) | √(ds² + dt²) of those |
//! | world | Δx / Δy of the world axes (box intervals when freespace) | as entity |
//! | trajectory | difference of the closest-point s / t on the trajectory the triggering entity follows (box corners' intervals when freespace); none without one | √(ds² + dt²) of those |
//!
//! Lane coordinates: as road coordinates, the longitudinal value stretched to the triggering
//! entity's lane centre line (`road_distance`).
//!
//! `routingAlgorithm="assignedRoute"` measures longitudinal road and lane distances along the
//! triggering entity's assigned route (§8.7.4.1.1 distance_along_route() of both, reference
//! points; with `freespace` the boxes' extents ahead of / behind the reference points are
//! taken off, 0 when they overlap). Without an assigned route, and for every other
//! algorithm, the shortest path along roads is used (the only one the road model offers).
//!
//! A measurement that needs a road position or a trajectory fails softly (`None`: the
//! condition is false) while an entity is off the roads, the roads are not joined, or the
//! entity follows no trajectory.

use opendrive::{Real, RoadNetwork};
use scenario::{CoordinateSystem, DistanceMeasure, RelativeDistanceType, RoutingAlgorithm};

use super::road_distance::road_distance;
use super::target::{advanced, participant, point_box, Target};
use super::ConditionErrorKind;
use crate::domain::{
    DistanceDirection, DistanceMode, Physical, PhysicalObject, RouteDistanceEnum,
    TrafficParticipant,
};
use crate::position::{local_to_world, EntityView};

/// Half-width of the central difference that turns a distance into its rate (s).
const RATE_STEP: Real = 1e-3;

/// The world velocity of an entity (m/s).
pub(crate) fn world_velocity(e: &EntityView<'_>) -> [Real; 3] {
    let v = e.velocity.translational;
    local_to_world(&e.pose, v.x, v.y, v.z)
}

/// Signed distance from `from` to `target` under `measure` (see the module table); `None`
/// when a road-based measure has no answer now.
pub(crate) fn distance(
    network: &RoadNetwork,
    from: &EntityView<'_>,
    target: &Target<'_>,
    measure: &DistanceMeasure,
) -> Result<Option<Real>, ConditionErrorKind> {
    let cs = measure
        .coordinate_system
        .unwrap_or(CoordinateSystem::Entity);
    let ty = measure
        .relative_distance_type
        .unwrap_or(RelativeDistanceType::EuclidianDistance);
    let free = measure.freespace;
    let a = participant(from, free);
    let b = target.participant(free);
    let mode = if free {
        DistanceMode::BoundingBoxes
    } else {
        DistanceMode::ReferencePoints
    };
    let along = |d| match d {
        RelativeDistanceType::Longitudinal => Some(DistanceDirection::Longitudinal),
        RelativeDistanceType::Lateral => Some(DistanceDirection::Lateral),
        _ => None,
    };
    match cs {
        CoordinateSystem::Entity | CoordinateSystem::World => match along(ty) {
            Some(dir) if cs == CoordinateSystem::Entity => {
                Ok(Some(a.object_distance(&b, dir, mode)))
            }
            Some(dir) => {
                // World axes: the same measure in a frame at the entity's point, heading 0.
                let mut world_frame = a.physical_object().clone();
                world_frame.pose.h = 0.0;
                world_frame.pose.p = 0.0;
                world_frame.pose.r = 0.0;
                if !free {
                    world_frame.bounding_box = point_box();
                }
                Ok(Some(world_frame.object_distance(&b, dir, mode)))
            }
            None if free => Ok(Some(footprint_distance(
                a.physical_object(),
                b.physical_object(),
            ))),
            None => {
                let (p, q) = (&from.pose, &b.physical_object().pose);
                Ok(Some(
                    ((q.x - p.x).powi(2) + (q.y - p.y).powi(2) + (q.z - p.z).powi(2)).sqrt(),
                ))
            }
        },
        CoordinateSystem::Road | CoordinateSystem::Lane
            if ty == RelativeDistanceType::Longitudinal
                && measure.routing_algorithm == Some(RoutingAlgorithm::AssignedRoute)
                && from.route.is_some() =>
        {
            Ok(along_assigned_route(network, from, &a, &b, free))
        }
        CoordinateSystem::Road | CoordinateSystem::Lane => Ok(road_distance(
            network,
            from,
            target,
            (&a, &b),
            free,
            cs == CoordinateSystem::Lane,
            along(ty),
        )),
        CoordinateSystem::Trajectory => Ok(from
            .trajectory
            .and_then(|path| along_trajectory(path, &a, &b, ty))),
        _ => Err(ConditionErrorKind::Unsupported {
            expected: "coordinateSystem entity, road, lane or world",
            found: "another coordinate system",
        }),
    }
}

/// Signed distance from `a` to `b` in the s/t frame of trajectory `path` (closest points);
/// with boxes (non-zero extents) the gap between the corners' intervals, 0 when they overlap.
fn along_trajectory(
    path: &crate::trajectory::Trajectory,
    a: &TrafficParticipant,
    b: &TrafficParticipant,
    ty: RelativeDistanceType,
) -> Option<Real> {
    let interval = |p: &TrafficParticipant| {
        let o = p.physical_object();
        let mut lo = [Real::INFINITY; 2];
        let mut hi = [Real::NEG_INFINITY; 2];
        for [x, y] in o.bounding_box.footprint(&o.pose).corners() {
            let c = path.closest(x, y);
            for (k, v) in [c.point.s, c.t].into_iter().enumerate() {
                lo[k] = lo[k].min(v);
                hi[k] = hi[k].max(v);
            }
        }
        (lo, hi)
    };
    let ((alo, ahi), (blo, bhi)) = (interval(a), interval(b));
    let gap = |k: usize| {
        if blo[k] > ahi[k] {
            blo[k] - ahi[k]
        } else if bhi[k] < alo[k] {
            bhi[k] - alo[k]
        } else {
            0.0
        }
    };
    Some(match ty {
        RelativeDistanceType::Longitudinal => gap(0),
        RelativeDistanceType::Lateral => gap(1),
        _ => gap(0).hypot(gap(1)),
    })
}

/// Longitudinal distance from `a` to `b` along `from`'s assigned route (positive when `b` is
/// further along it); `None` when either is off the route.
fn along_assigned_route(
    network: &RoadNetwork,
    from: &EntityView<'_>,
    a: &TrafficParticipant,
    b: &TrafficParticipant,
    freespace: bool,
) -> Option<Real> {
    let route = from.route?;
    let start = RouteDistanceEnum::FromStart;
    let sa = a.distance_along_route(network, route, start).ok()?;
    let sb = b.distance_along_route(network, route, start).ok()?;
    let d = sb - sa;
    if !freespace {
        return Some(d);
    }
    // Extents of the boxes ahead of (front) and behind (rear) their reference points.
    let front = |p: &TrafficParticipant| {
        let bb = &p.physical_object().bounding_box;
        bb.center().x + 0.5 * bb.length()
    };
    let rear = |p: &TrafficParticipant| {
        let bb = &p.physical_object().bounding_box;
        0.5 * bb.length() - bb.center().x
    };
    Some(if d >= 0.0 {
        (d - front(a) - rear(b)).max(0.0)
    } else {
        (d + rear(a) + front(b)).min(0.0)
    })
}

/// The rate of change of |distance| (m/s) under the same measure, by a central difference of
/// ±`RATE_STEP` s with both objects moving along their current velocities; `None` when either
/// sample has no answer.
pub(crate) fn distance_rate(
    network: &RoadNetwork,
    from: &EntityView<'_>,
    target: &Target<'_>,
    measure: &DistanceMeasure,
) -> Result<Option<Real>, ConditionErrorKind> {
    let later = distance(
        network,
        &advanced(from, RATE_STEP),
        &target.advanced(RATE_STEP),
        measure,
    )?;
    let earlier = distance(
        network,
        &advanced(from, -RATE_STEP),
        &target.advanced(-RATE_STEP),
        measure,
    )?;
    Ok(later
        .zip(earlier)
        .map(|(l, e)| (l.abs() - e.abs()) / (2.0 * RATE_STEP)))
}

/// The time until `from`'s box touches the target's, both keeping their velocities
/// (§8.7.5.1.1 time_to_collision()); `None` when they never do.
pub(crate) fn box_time_to_collision(from: &EntityView<'_>, target: &Target<'_>) -> Option<Real> {
    let b = target.participant(true);
    from.traffic_participant().time_to_collision(&b)
}

/// The 2D distance between the ground footprints of two objects' boxes, 0 when they touch or
/// overlap: the smallest distance from a corner of one rectangle to an edge of the other
/// (two disjoint convex polygons are closest at a vertex of one of them).
pub(crate) fn footprint_distance(a: &PhysicalObject, b: &PhysicalObject) -> Real {
    let ca = a.bounding_box.footprint(&a.pose).corners();
    let cb = b.bounding_box.footprint(&b.pose).corners();
    if overlap(&ca, &cb) {
        return 0.0;
    }
    let mut best = Real::INFINITY;
    for (p, poly) in ca
        .iter()
        .map(|p| (p, &cb))
        .chain(cb.iter().map(|p| (p, &ca)))
    {
        for i in 0..4 {
            best = best.min(point_segment(*p, poly[i], poly[(i + 1) % 4]));
        }
    }
    best
}

/// Separating-axis test of two convex quadrilaterals (corners in order around each).
fn overlap(a: &[[Real; 2]; 4], b: &[[Real; 2]; 4]) -> bool {
    for poly in [a, b] {
        for i in 0..4 {
            let (p, q) = (poly[i], poly[(i + 1) % 4]);
            let n = [q[1] - p[1], p[0] - q[0]];
            if n[0] == 0.0 && n[1] == 0.0 {
                continue;
            }
            let proj = |c: &[Real; 2]| c[0] * n[0] + c[1] * n[1];
            let (amin, amax) = a
                .iter()
                .map(proj)
                .fold((Real::INFINITY, Real::NEG_INFINITY), |(l, h), v| {
                    (l.min(v), h.max(v))
                });
            let (bmin, bmax) = b
                .iter()
                .map(proj)
                .fold((Real::INFINITY, Real::NEG_INFINITY), |(l, h), v| {
                    (l.min(v), h.max(v))
                });
            if amax < bmin || bmax < amin {
                return false;
            }
        }
    }
    true
}

/// Distance from point `p` to the segment `a`–`b`.
fn point_segment(p: [Real; 2], a: [Real; 2], b: [Real; 2]) -> Real {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let u = if len2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p[0] - a[0] - u * dx).hypot(p[1] - a[1] - u * dy)
}
