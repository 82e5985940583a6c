//! The route fields the map's modifiers bind whole (ASAM OpenSCENARIO DSL 2.1 §8.12.2.2.2
//! `routes_are_in_sequence` on route fields, §8.12.2.2.3 `roads_follow_in_junction`'s
//! `junction_route`; OpenDRIVE 1.8 §12 junctions): each is one road (or lane section) of the
//! plan, read from the lanes `map_lanes` chose for the modifier; and what a binding is
//! (`MapLane`), which `map_lanes` returns.
//!
//! - an end of `routes_are_in_sequence` that is no lane field: the road (`road`, `route`,
//!   `route_element`, `compound_route`) or lane section (`lane_section`) of the modifier's own
//!   lane on it;
//! - `junction_route`: the connecting road of the way through the junction, the junction's
//!   road whose lane links the lane in to the lane out. A way the plan's roads do not take
//!   is an error at the modifier.

use crate::error::{Error, ErrorKind as K};
use crate::resolve::{EndKind, JunctionRoads, MapKind, MapModifier};
use crate::road::PlanRoad;
use opendrive::{LaneHandle, RoadNetwork};

use super::map_junctions::connecting;

/// A lane a map modifier bound a field to.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct MapLane {
    /// The field's path.
    pub field: String,
    /// The OpenDRIVE road id.
    pub road: String,
    /// The lane id.
    pub lane: i32,
    /// The plan's s of its lane section's start and end, when the road is one of the plan's.
    pub span: Option<(f64, f64)>,
    /// What bound it, for messages.
    pub why: String,
    /// Whether the field is a road or a lane section (`routes_are_in_sequence` on route
    /// fields): `span` is the whole road's (section's), `lane` the lane the modifier bound on it.
    pub whole_road: bool,
}

/// s of the start and the end of the lane section of `h` on its road (m).
pub(super) fn section_span(net: &RoadNetwork, h: LaneHandle) -> (f64, f64) {
    let r = &net.roads()[h.road as usize];
    let k = h.section as usize;
    let s1 = r.lane_sections.get(k + 1).map_or(r.length, |n| n.s);
    (r.lane_sections[k].s, s1)
}

/// The fields of `lane_mods` bound whole, from `chosen`, the lanes of the fields `names`.
pub(super) fn whole_fields(
    road: &PlanRoad<'_>,
    lane_mods: &[&MapModifier],
    names: &[String],
    chosen: &[LaneHandle],
) -> Result<Vec<MapLane>, Error> {
    let net = road.network();
    // Road and lane-section fields of routes_are_in_sequence: the road (the lane section) of
    // the modifier's own lane on it, whole.
    let ends = lane_mods.iter().filter_map(|m| match &m.kind {
        MapKind::RoutesInSequence {
            preceding,
            succeeding,
        } => Some([(m, preceding), (m, succeeding)]),
        _ => None,
    });
    let mut road_fields: Vec<MapLane> = Vec::new();
    for (m, end) in ends
        .flatten()
        .filter(|(_, e)| !matches!(e.kind, EndKind::Lane | EndKind::Made))
    {
        let Some(h) = names.iter().position(|n| *n == end.lane).map(|i| chosen[i]) else {
            continue;
        };
        let r = &net.roads()[h.road as usize];
        let (span, what) = match end.kind {
            EndKind::Section => {
                let (s0, s1) = section_span(net, h);
                (
                    road.plan_span(&r.id, s0, s1),
                    format!("the lane section of road {} from s = {s0:.2} m", r.id),
                )
            }
            _ => (
                road.plan_span(&r.id, 0.0, r.length),
                format!("road {}", r.id),
            ),
        };
        if road_fields.iter().all(|b| b.field != end.field) {
            road_fields.push(MapLane {
                field: end.field.clone(),
                road: r.id.clone(),
                lane: h.lane,
                span,
                why: format!("{what} bound by map.{}(…) at {}", m.name, m.site.at()),
                whole_road: true,
            });
        }
    }
    // junction_route of roads_follow_in_junction: the connecting road of the way through.
    for m in lane_mods {
        let MapKind::Junction {
            in_lane,
            out_lane,
            roads:
                JunctionRoads {
                    junction_route: Some(field),
                    ..
                },
            ..
        } = &m.kind
        else {
            continue;
        };
        let at = |f: &str| names.iter().position(|n| n == f).map(|i| chosen[i]);
        // The search keeps only lanes joined through a connecting lane (Rel::Through).
        let Some(c) = at(in_lane)
            .zip(at(out_lane))
            .and_then(|(a, b)| connecting(net, a, b))
        else {
            continue;
        };
        let r = &net.roads()[c.road as usize];
        let why = format!(
            "the connecting road {} of junction {} bound by map.{}(…) at {}",
            r.id,
            r.junction.as_deref().unwrap_or_default(),
            m.name,
            m.site.at()
        );
        let Some(span) = road.plan_span(&r.id, 0.0, r.length) else {
            return Err(m.site.err(
                K::Road,
                format!(
                    "expected `{field}` on the roads the plan drives on ({}), found {why}, which they do not take (a named route goes another way)",
                    road.ids().join(", ")
                ),
            ));
        };
        if road_fields.iter().all(|b| &b.field != field) {
            road_fields.push(MapLane {
                field: field.clone(),
                road: r.id.clone(),
                lane: c.lane,
                span: Some(span),
                why,
                whole_road: true,
            });
        }
    }
    Ok(road_fields)
}
