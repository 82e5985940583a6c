//! The map's modifiers over route fields as checks of the roads the plan drives on (ASAM
//! OpenSCENARIO DSL 2.1 §8.12.2.2; every free route field is those roads): `number_of_lanes`
//! (on a `lane_section` field: some lane section has that many), `routes_overlap`,
//! `routes_are_in_sequence` on two routes the map makes (their points: the second starts where
//! the first ends or on the road after it), and the
//! DSL's lane enums read against the OpenDRIVE 1.8 lane types (§11 lanes). See `map_lanes` for the
//! table of every map modifier.

use opendrive::LaneType;

use crate::error::{Error, ErrorKind as K};
use crate::resolve::{MapKind, MapModifier, Route};
use crate::road::PlanRoad;

/// Checks a modifier over route fields against the plan's roads.
pub(super) fn check(road: &PlanRoad<'_>, m: &MapModifier) -> Result<(), Error> {
    match &m.kind {
        MapKind::NumberOfLanes {
            route,
            section,
            n,
            lane_type,
            lane_use,
            directionality,
        } => {
            let keep = |t: &LaneType| -> Result<bool, Error> {
                Ok(matches_type(m, lane_type.as_deref(), t, type_of)?
                    && matches_type(m, lane_use.as_deref(), t, use_of)?
                    && matches_type(m, directionality.as_deref(), t, directionality_of)?)
            };
            let what = [
                lane_type.clone(),
                lane_use.as_ref().map(|u| format!("{u}-use")),
                directionality.clone(),
            ]
            .into_iter()
            .flatten()
            .collect::<Vec<_>>()
            .join(" ");
            let what = if what.is_empty() {
                "lanes".to_string()
            } else {
                format!("{what} lanes")
            };
            let net = road.network();
            let mut counts = Vec::new();
            for id in road.ids() {
                let Some(r) = net.roads().iter().find(|r| r.id == id) else {
                    continue;
                };
                for ls in &r.lane_sections {
                    let mut ids = Vec::new();
                    for l in ls.right.iter().rev().chain(ls.left.iter()) {
                        if keep(&l.lane_type)? {
                            ids.push(l.id);
                        }
                    }
                    counts.push((id.clone(), ls.s, ids));
                }
            }
            let shown = |(id, s, ids): &(String, f64, Vec<i32>)| {
                format!(
                    "{} on road {id} (the lane section from s = {s:.2} m{})",
                    ids.len(),
                    if ids.is_empty() {
                        String::new()
                    } else {
                        format!(": lanes {ids:?}")
                    }
                )
            };
            if *section {
                if !counts.iter().any(|(_, _, ids)| ids.len() == *n as usize) {
                    return Err(m.site.err(
                        K::Road,
                        format!(
                            "expected a lane section of the roads the plan drives on with {n} {what} for `{route}`, found {}",
                            counts.iter().map(shown).collect::<Vec<_>>().join(", ")
                        ),
                    ));
                }
            } else if let Some(c) = counts.iter().find(|(_, _, ids)| ids.len() != *n as usize) {
                return Err(m.site.err(
                    K::Road,
                    format!(
                        "expected {n} {what} on `{route}` (the roads the plan drives on), found {}",
                        shown(c)
                    ),
                ));
            }
            Ok(())
        }
        MapKind::NamedInSequence {
            preceding,
            succeeding,
        } => in_sequence(road, m, preceding, succeeding),
        MapKind::RoutesOverlap {
            route1,
            route2,
            kind,
        } => {
            if kind == "equal" || kind == "any" {
                Ok(())
            } else {
                Err(m.site.err(
                    K::Road,
                    format!(
                        "expected `{route1}` and `{route2}` to overlap as {kind}, found both the roads the plan drives on ({}), which overlap as equal",
                        road.ids().join(", ")
                    ),
                ))
            }
        }
        _ => Ok(()),
    }
}

/// Whether lane type `t` is what `want` (a member of the DSL's enum, read by `read`) names;
/// no filter: yes. A member no OpenDRIVE lane type says is an error at the modifier.
fn matches_type(
    m: &MapModifier,
    want: Option<&str>,
    t: &LaneType,
    read: fn(&str, &LaneType) -> Option<bool>,
) -> Result<bool, Error> {
    let Some(w) = want else {
        return Ok(true);
    };
    read(w, t).ok_or_else(|| {
        m.site.err(
            K::Argument,
            format!("expected a {w} the OpenDRIVE lane types say (see docs/dsl.md, map modifiers), found {w}, which none of them does"),
        )
    })
}

/// §8.12.2.2.2 on two routes the map makes: `succeeding` starts where `preceding` ends, in its
/// lane (the plan keeps one lane id), further on its last road or on the road after it
/// (directly, or through one connecting road of a junction), the network's path in the driving
/// direction joining the two points.
fn in_sequence(
    road: &PlanRoad<'_>,
    m: &MapModifier,
    preceding: &Route,
    succeeding: &Route,
) -> Result<(), Error> {
    let (Some(a), Some(b)) = (
        super::route::points(preceding),
        super::route::points(succeeding),
    ) else {
        // `resolve` reads both as routes through points.
        return Ok(());
    };
    let (last, first) = (a[a.len() - 1].clone(), b[0].clone());
    let (la, lb) = (last.1, first.1);
    let at = |(id, _, s): &(String, i32, f64)| format!("road {id} at s = {s} m");
    if a.len() < 2 {
        return Err(m.site.err(
            K::Road,
            format!("expected a preceding route with an end (map.create_route([…]) through two or more points), found one from a single point ({}), which runs on over the roads after it", at(&last)),
        ));
    }
    if la != lb {
        return Err(m.site.err(
            K::Road,
            format!("expected the succeeding route to start in the lane the preceding one ends in, lane {la} (a route's lane changes are between its own points), found lane {lb}"),
        ));
    }
    let net = road.network();
    let roads = crate::road::route_roads(net, &[last.clone(), first.clone()])
        .map_err(|e| m.site.err(K::Road, format!("expected the succeeding route to start where the preceding one ends ({}) or after it: {e}", at(&last))))?;
    let through_junction = roads.len() == 3 && net.roads()[roads[1]].junction.is_some();
    if roads.len() > 2 && !through_junction {
        let ids: Vec<&str> = roads.iter().map(|&i| net.roads()[i].id.as_str()).collect();
        return Err(m.site.err(
            K::Road,
            format!("expected the succeeding route ({}) on the road the preceding one ends on ({}) or on the road after it, found the path between them over roads {}", at(&first), at(&last), ids.join(", ")),
        ));
    }
    Ok(())
}

/// §8.12 `lane_type` against an OpenDRIVE lane type.
fn type_of(w: &str, t: &LaneType) -> Option<bool> {
    let pedestrian = matches!(t, LaneType::Sidewalk | LaneType::Walking);
    let vru = matches!(t, LaneType::Biking);
    Some(match w {
        "driving" => t.is_drivable(),
        "vru_vehicles" => vru,
        "pedestrian" => pedestrian,
        "non_driving" => !t.is_drivable() && !vru && !pedestrian,
        _ => return None,
    })
}

/// §8.12 `lane_use` against an OpenDRIVE lane type (the uses that type names).
fn use_of(w: &str, t: &LaneType) -> Option<bool> {
    let named = match w {
        "normal" => LaneType::Driving,
        "exit" => LaneType::Exit,
        "entry" => LaneType::Entry,
        "on_ramp" => LaneType::OnRamp,
        "off_ramp" => LaneType::OffRamp,
        "connecting_ramp" => LaneType::ConnectingRamp,
        "hov" => LaneType::Hov,
        "bus" => LaneType::Bus,
        "parking" => LaneType::Parking,
        "stop" => LaneType::Stop,
        "restricted" => LaneType::Restricted,
        "border" => LaneType::Border,
        "shoulder" => LaneType::Shoulder,
        "curb" => LaneType::Curb,
        "median" => LaneType::Median,
        "bicycle" => LaneType::Biking,
        "sidewalk" => LaneType::Sidewalk,
        _ => return None,
    };
    Some(*t == named)
}

/// §8.12 `directionality` against an OpenDRIVE lane type: `bidirectional` lanes are driven
/// both ways, every other lane one way (its side's).
fn directionality_of(w: &str, t: &LaneType) -> Option<bool> {
    match w {
        "uni_direction" => Some(*t != LaneType::Bidirectional),
        "bi_direction" => Some(*t == LaneType::Bidirectional),
        _ => None,
    }
}
