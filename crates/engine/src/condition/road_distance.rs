//! Road and lane coordinate distances of the distance-based conditions (OpenSCENARIO 1.3 §6.4
//! "Distances", `coordinateSystem="road"` / `"lane"`), through the OpenSCENARIO 2.0 §8.7.5.1.3
//! method space_gap(); the table of `measure` says what each combination measures.
//!
//! Both objects are located on the roads once per measurement (`domain::RoadPair`) and every
//! gap the measurement needs — the boxes', the reference points', each axis — is taken from
//! that location.
//!
//! `freespace`: §8.7.5.1.3 space_gap() reports overlapping boxes as a gap of the sign opposite
//! to who is ahead (the overlap, seen from the other side); §6.4 puts overlapping boxes at
//! distance 0. Who is ahead is the reference points' order. Along s that order needs no
//! projection of the reference points when the boxes' s-intervals are apart by more than
//! `APART` and each reference point lies within its own box's footprint: the lines of equal s
//! are the reference line's normals, so a point of a convex footprint has an s between its
//! corners' (to the projection's round-off, far below `APART`), and the points are then in
//! the boxes' order. Along t the lines of equal t are curves and the shortcut is not taken.
//!
//! Lane coordinates: as road coordinates, with the longitudinal value stretched by the ratio
//! of the triggering entity's lane centre line length to the reference-line length between
//! the two reference points (`position::lane_length`; exact between reference points on one
//! road, the same ratio applied to box gaps; across roads the reference-line value is kept).

use opendrive::{Real, RoadNetwork};

use super::target::{participant, Target};
use crate::domain::{
    signed_gap, DistanceDirection, Interval, Physical, PhysicalObject, RoadPair, TrafficParticipant,
};
use crate::position::{lane_arc_length, EntityView};

/// Separation of two boxes' s-intervals (m) beyond which their reference points' order is
/// taken from the intervals (module doc): ten thousand times the projections' tolerance.
const APART: Real = 1e-6;

/// The signed road (or, `lane`, lane) distance from `from` (as the §8.7 object `a`) to
/// `target` (as `b`) along `along` (`None`: √(ds² + dt²)), positive when the target lies
/// ahead of / left of `from`'s direction of travel; `free` measures between boxes. `None`
/// when either is off the roads or their roads are not joined.
pub(super) fn road_distance(
    network: &RoadNetwork,
    from: &EntityView<'_>,
    target: &Target<'_>,
    (a, b): (&TrafficParticipant, &TrafficParticipant),
    free: bool,
    lane: bool,
    along: Option<DistanceDirection>,
) -> Option<Real> {
    // space_gap is positive when the caller is ahead along +s (left along +t); turned here to
    // "target ahead / left of the triggering entity's travel".
    let travel = match from.road_position {
        Some(rp) if rp.relative_heading.cos() < 0.0 => -1.0,
        _ => 1.0,
    };
    let (ao, bo) = (a.physical_object(), b.physical_object());
    let pair = RoadPair::locate(network, ao, bo).ok()?;
    let gap = |dir| {
        let (own, theirs) = pair.intervals(network, ao, bo, dir).ok()?;
        let g = signed_gap(own, theirs);
        if !free || order_evident(dir, own, theirs, ao, bo) {
            return Some(-travel * g);
        }
        let points = pair
            .space_gap(
                network,
                participant(from, false).physical_object(),
                target.participant(false).physical_object(),
                dir,
            )
            .ok()?;
        let overlap = g == 0.0 || (points != 0.0 && g.signum() != points.signum());
        Some(if overlap { 0.0 } else { -travel * g })
    };
    let longitudinal = || {
        let d = gap(DistanceDirection::Longitudinal)?;
        Some(if lane {
            d * lane_stretch(network, from, target).unwrap_or(1.0)
        } else {
            d
        })
    };
    match along {
        Some(DistanceDirection::Longitudinal) => longitudinal(),
        Some(dir) => gap(dir),
        None => longitudinal()
            .zip(gap(DistanceDirection::Lateral))
            .map(|(s, t)| s.hypot(t)),
    }
}

/// Whether the reference points of `a` and `b` are certainly in the order of their boxes'
/// intervals `own` and `theirs` along `dir` (module doc): along s only, intervals more than
/// `APART` apart, each reference point within its footprint.
fn order_evident(
    dir: DistanceDirection,
    own: Interval,
    theirs: Interval,
    a: &PhysicalObject,
    b: &PhysicalObject,
) -> bool {
    dir == DistanceDirection::Longitudinal
        && (own.0 > theirs.1 + APART || theirs.0 > own.1 + APART)
        && reference_in_footprint(a)
        && reference_in_footprint(b)
}

/// Whether the object's reference point lies within (or on) its box's footprint.
fn reference_in_footprint(o: &PhysicalObject) -> bool {
    let f = o.bounding_box.footprint(&o.pose);
    let d = [o.pose.x - f.center[0], o.pose.y - f.center[1]];
    let (along, across) = (f.axis_x, f.axis_y());
    (d[0] * along[0] + d[1] * along[1]).abs() <= f.half_length
        && (d[0] * across[0] + d[1] * across[1]).abs() <= f.half_width
}

/// How much longer the centre line of `from`'s lane is than the reference line between the
/// two reference points' s (both on `from`'s road); `None` when they are on different roads
/// or at the same s.
fn lane_stretch(network: &RoadNetwork, from: &EntityView<'_>, target: &Target<'_>) -> Option<Real> {
    let own = from.road_position?;
    let other_s = match target {
        Target::Entity(e) => e.road_position.filter(|rp| rp.road_id == own.road_id)?.s,
        Target::Point(p) => network.locate_on_road(&own.road_id, p.x, p.y)?.s,
    };
    let ds = (other_s - own.s).abs();
    if ds <= opendrive::LENGTH_EPSILON {
        return None;
    }
    Some(lane_arc_length(network, &own.road_id, own.lane_id, own.s, other_s)? / ds)
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use opendrive::{Pose, RoadNetwork};
    use scenario::ObjectType;

    use super::*;
    use crate::domain::{BoundingBox, Position3d};

    /// The bundled highway (spirals, an arc, a junction), where the batch benchmark runs.
    fn highway() -> RoadNetwork {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/roads/highway.xodr");
        // The road is part of the repository; a missing file is a broken checkout.
        RoadNetwork::from_file(&path).expect("examples/roads/highway.xodr loads")
    }

    /// §6.4 freespace road distance by the rule in full: the boxes' space_gap, 0 when the
    /// reference points are in the other order (overlap), both gaps from separate locations.
    fn full_rule(net: &RoadNetwork, a: &EntityView<'_>, b: &EntityView<'_>) -> Option<Real> {
        let dir = DistanceDirection::Longitudinal;
        let g = participant(a, true)
            .space_gap(net, &participant(b, true), dir)
            .ok()?;
        let points = participant(a, false)
            .space_gap(net, &participant(b, false), dir)
            .ok()?;
        let overlap = g == 0.0 || (points != 0.0 && g.signum() != points.signum());
        Some(if overlap { 0.0 } else { -g })
    }

    #[test]
    fn the_shortcut_gives_the_full_rule_bit_for_bit() {
        // Ego in lane −2 of road 0 (spirals, then an arc of R = 200 m) from s = 20 to 180; the
        // other car in lane −1 or −2, 30 m behind to 30 m ahead in 0.7 m steps (boxes apart
        // and overlapping), headed along the road, yawed by 0.3 rad, or reversed; the box of
        // the batch's cut-in (centre 1.4 m ahead of the reference point), and one whose
        // reference point lies outside it (centre 4 m ahead of a 5 m box), which never takes
        // the shortcut.
        let net = highway();
        let (mut evident, mut full) = (0, 0);
        for centre_x in [1.4, 4.0] {
            let bb = BoundingBox::new(Position3d::new(centre_x, 0.0, 0.75), 5.0, 2.0, 1.5)
                .expect("valid box");
            for k in 0..9 {
                let s = 20.0 + 20.0 * k as Real;
                let ego_pose = net.lane_pose("0", -2, s, 0.0).expect("on road 0");
                for step in -43..=43 {
                    let other_s = s + 0.7 * step as Real;
                    for (lane, yaw) in [(-1, 0.0), (-2, 0.3), (-1, std::f64::consts::PI)] {
                        let Ok(p) = net.lane_pose("0", lane, other_s, 0.0) else {
                            continue;
                        };
                        let other_pose = Pose { h: p.h + yaw, ..p };
                        let a = EntityView::new("Ego", ObjectType::Vehicle, ego_pose, bb);
                        let b = EntityView::new("Other", ObjectType::Vehicle, other_pose, bb);
                        let (pa, pb) = (participant(&a, true), participant(&b, true));
                        let got = road_distance(
                            &net,
                            &a,
                            &Target::Entity(b),
                            (&pa, &pb),
                            true,
                            false,
                            Some(DistanceDirection::Longitudinal),
                        );
                        let want = full_rule(&net, &a, &b);
                        assert_eq!(
                            got.map(Real::to_bits),
                            want.map(Real::to_bits),
                            "s {s}, other s {other_s}, lane {lane}, yaw {yaw}: {got:?} vs {want:?}"
                        );
                        let pair =
                            RoadPair::locate(&net, pa.physical_object(), pb.physical_object())
                                .expect("both on road 0");
                        let (own, theirs) = pair
                            .intervals(
                                &net,
                                pa.physical_object(),
                                pb.physical_object(),
                                DistanceDirection::Longitudinal,
                            )
                            .expect("corners project");
                        if order_evident(
                            DistanceDirection::Longitudinal,
                            own,
                            theirs,
                            pa.physical_object(),
                            pb.physical_object(),
                        ) {
                            evident += 1;
                        } else {
                            full += 1;
                        }
                    }
                }
            }
        }
        // Both ways were taken: the comparison covers the shortcut and the full rule.
        assert!(
            evident > 500 && full > 500,
            "{evident} shortcut, {full} full"
        );
    }
}
