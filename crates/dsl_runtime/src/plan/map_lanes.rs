//! The map's modifiers against the loaded road network (ASAM OpenSCENARIO DSL 2.1 §8.12.2.2;
//! OpenDRIVE 1.8 §11 lanes, §11.5 lane linkage): bindings of lane fields, after the checks of
//! the roads the plan drives on (`map_checks`), done once before anything is planned.
//!
//! | modifier | class | oscsim |
//! | --- | --- | --- |
//! | `number_of_lanes(route, n, lane_type, lane_use, directionality)` on a `route`, `road`, `compound_route` | check | every lane section of the plan's roads (every free route field is those roads) has n lanes of that type, use and directionality, both sides counted |
//! | the same on a `lane_section` | binding | a lane section of the plan's roads has n such lanes |
//! | `start_lane(l)` | binding | l is a driving lane with a lane section before it in its driving direction and no predecessor there |
//! | `end_lane(l)` | binding | l is a driving lane with a lane section after it in its driving direction and no successor there |
//! | `lane_side(l1, side, l2, count)`, `compound_lane_side(…)` | binding | l1 and l2 are driving lanes of one lane section, l1 `count` lanes to the side of l2 across the road (t grows to the left of the s-axis, §8.12.5), every lane of the section counted; with `lane_section` (`route`), on the plan's roads |
//! | `routes_are_in_sequence(preceding, succeeding, road)` on lane fields | binding | `succeeding` is a successor of `preceding` in its driving direction (the network's lane links, through lane sections and road links); with `road`, both on the plan's roads |
//! | `routes_are_in_sequence(preceding, succeeding)` on route fields other than two lanes | binding | a road (`road`, `route`, `route_element`, `compound_route`) or lane-section end over a lane of the modifier's own on it, driven in +s on the plan's roads; a lane end over itself. With a road end, the second's road is another the first leads onto, directly or through a connecting lane, in a lane of one id; else the lanes follow each other (lane links). The road and section fields are bound whole (`map_roads`); without named routes the plan drives the roads (`junction_roads`) |
//! | `routes_are_in_sequence(preceding, succeeding)` on two routes the map makes | check | `succeeding` starts where `preceding` ends or on the road after it, in its lane (`map_checks`); the plan drives both |
//! | `routes_are_in_sequence(preceding, succeeding)` on a route the map makes and a field | binding | the made route a road end whose lane is fixed where it ends (starts) (`made_lane`); the field bound as beside a road field; the plan drives the made route's roads and the field's (`crate` picks that chain) |
//! | `routes_are_opposite(route1, route2, containing_road, lateral_overlap)` on lane fields | binding | both in one lane section, driven in opposite directions; with `containing_road`, on the plan's roads; `lateral_overlap` `never` (two lanes never share their width) or none |
//! | `routes_are_opposite` on route fields | binding | `route2` is the plan's roads driven against s, or the one road `route1` is bound to driven so (`against::bind_routes`) |
//! | `roads_follow_in_junction(in_lane, out_lane, direction)` on lane fields | binding | `out_lane` reached from `in_lane` through one connecting lane of a junction, turning the way `direction` names (`map_junctions::Turn`); without named routes the plan drives that way (`junction_roads`) |
//! | `roads_follow_in_junction(junction, in_road, out_road, direction, clockwise_count, number_of_roads, junction_route, resulting_route)` | binding | as on lane fields, over two lanes of the modifier's own when `in_lane`/`out_lane` are not given; `junction` is the connecting lane's junction, `in_road`/`out_road` the lanes' roads, `junction_route` the connecting road, whole (one field one road across the modifiers), `clockwise_count` and `number_of_roads` counted by `map_junctions`; the way through on the plan's roads (without named routes the plan drives it) |
//! | `crossing_connects(crossing, start_lane, end_lane, start_s_coord, start_angle)` | binding | the lanes a crosswalk of the map joins by the straight line from the start lane's centre (`map_crossings`), on the plan's roads; the crossing field is that crosswalk (`map_crossings::MapCrossing`); a map without a crosswalk is an error at the modifier |
//! | `routes_overlap(r1, r2, kind)` | check | both are the plan's roads, so they overlap as `equal`: `equal` and `any` hold, another kind is an error |
//!
//! Lane fields range over the driving lanes (OpenDRIVE types a vehicle drives on) of every
//! road outside junctions. Every assignment of the constrained fields that satisfies all the
//! modifiers is found (in the network's order; at most [`MAX_SOLUTIONS`] kept, and an error
//! past [`MAX_TRIED`] partial assignments tried); those that put every field on the plan's roads
//! are preferred (the scenario happens there), and one is drawn from the run's seed when
//! several remain. A modifier after which nothing satisfies the modifiers so far is an error
//! at it, naming what the map has.

use opendrive::{Direction, LaneHandle, RoadHandle, RoadNetwork};

use crate::error::{Error, ErrorKind as K};
use crate::resolve::{EndKind, JunctionRoads, MapKind, MapModifier, SeqEnd};
use crate::road::PlanRoad;

use super::map_crossings::{crossing, has_crosswalk, MapCrossing};
use super::map_junctions::{self, connecting, heading_change, Turn};
use super::map_roads::{section_span, MapLane};

/// The most assignments of lane fields kept.
const MAX_SOLUTIONS: usize = 100_000;
/// The most partial assignments tried: past it the search stops with an error, so a large
/// network with loosely constrained fields cannot hang the plan.
const MAX_TRIED: usize = 2_000_000;

/// Checks the network against `mods` and binds the lane fields they constrain (`choose(n)`
/// draws among n).
pub(crate) fn bind(
    road: &PlanRoad<'_>,
    mods: &[MapModifier],
    choose: &mut dyn FnMut(usize) -> usize,
) -> Result<(Vec<MapLane>, Vec<MapCrossing>), Error> {
    for m in mods {
        super::map_checks::check(road, m)?;
    }
    let lane_mods: Vec<&MapModifier> = mods.iter().filter(|m| fields(m).is_some()).collect();
    if lane_mods.is_empty() {
        return Ok((Vec::new(), Vec::new()));
    }
    let net = road.network();
    for m in &lane_mods {
        if let (MapKind::Crossing { crossing: c, .. }, false) = (&m.kind, has_crosswalk(net)) {
            return Err(m.site.err(
                K::Road,
                format!(
                    "expected a crosswalk on the map for `{c}` (an OpenDRIVE object of type crosswalk with an outline, or a length and width), found none on roads {}",
                    net.roads().iter().map(|r| r.id.as_str()).collect::<Vec<_>>().join(", ")
                ),
            ));
        }
    }
    let domain = driving_lanes(net);
    let plan_ids = road.ids();
    let on_plan = |h: &LaneHandle| plan_ids.contains(&net.roads()[h.road as usize].id);
    let mut last = (Vec::new(), Vec::new());
    for k in 1..=lane_mods.len() {
        let (names, solutions, tried) = solve(net, &domain, &lane_mods[..k], &on_plan);
        if tried >= MAX_TRIED {
            return Err(lane_mods[k - 1].site.err(
                K::Road,
                format!("expected lane fields the map's modifiers constrain enough to search, found more than {MAX_TRIED} assignments to try after {}(…); constrain them further (start_lane, end_lane, lane_side to a bound lane)", lane_mods[k - 1].name),
            ));
        }
        if solutions.is_empty() {
            let m = lane_mods[k - 1];
            let roads: Vec<&str> = net
                .roads()
                .iter()
                .filter(|r| r.junction.is_none())
                .map(|r| r.id.as_str())
                .collect();
            return Err(m.site.err(
                K::Road,
                format!(
                    "expected lanes of the map for {} that satisfy {}(…){}, found none on roads {}",
                    names
                        .iter()
                        .map(|n| format!("`{n}`"))
                        .collect::<Vec<_>>()
                        .join(", "),
                    m.name,
                    if k > 1 {
                        " and the map modifiers before it"
                    } else {
                        ""
                    },
                    roads.join(", ")
                ),
            ));
        }
        last = (names, solutions);
    }
    let (names, solutions) = last;
    // A route the map makes is where it is: only the lanes chosen count.
    let made: Vec<&str> = lane_mods
        .iter()
        .filter_map(|m| match &m.kind {
            MapKind::RoutesInSequence {
                preceding,
                succeeding,
            } => Some([preceding, succeeding]),
            _ => None,
        })
        .flatten()
        .filter(|e| e.kind == EndKind::Made)
        .map(|e| e.lane.as_str())
        .collect();
    let preferred: Vec<&Vec<LaneHandle>> = solutions
        .iter()
        .filter(|s| {
            s.iter()
                .zip(&names)
                .all(|(h, n)| on_plan(h) || made.contains(&n.as_str()))
        })
        .collect();
    let pool: Vec<&Vec<LaneHandle>> = if preferred.is_empty() {
        solutions.iter().collect()
    } else {
        preferred
    };
    let pick = if pool.len() > 1 {
        choose(pool.len())
    } else {
        0
    };
    let chosen = pool[pick.min(pool.len() - 1)];
    let starts = road.starts();
    let own: Vec<&str> = lane_mods
        .iter()
        .filter_map(|m| own_lanes(m))
        .flatten()
        .collect();
    let road_fields = super::map_roads::whole_fields(road, &lane_mods, &names, chosen)?;
    let at = |f: &str| names.iter().position(|n| n == f).map(|i| chosen[i]);
    let crossings = lane_mods
        .iter()
        .filter_map(|m| match &m.kind {
            MapKind::Crossing {
                crossing: field,
                start_lane,
                end_lane,
                start_s,
                start_angle,
                ..
            } => {
                // The search kept only lanes a crossing joins (Rel::Crossing), on the plan's
                // roads.
                let c = crossing(net, at(start_lane)?, at(end_lane)?, *start_s, *start_angle)?;
                let id = &net.roads()[c.road].id;
                Some(MapCrossing {
                    field: field.clone(),
                    road_start: starts.iter().find(|(r, _)| r == id)?.1,
                    why: format!(
                        "crosswalk {} of road {id} bound by map.{}(…) at {}",
                        c.object,
                        m.name,
                        m.site.at()
                    ),
                    crossing: c,
                })
            }
            _ => None,
        })
        .collect();
    let lanes = names
        .iter()
        .zip(chosen)
        .filter(|(field, _)| !own.contains(&field.as_str()))
        .map(|(field, h)| {
            let r = &net.roads()[h.road as usize];
            let (s0, s1) = section_span(net, *h);
            let by = lane_mods
                .iter()
                .find(|m| fields(m).is_some_and(|f| f.contains(&field.as_str())))
                .map(|m| format!("bound by map.{}(…) at {}", m.name, m.site.at()))
                .unwrap_or_default();
            MapLane {
                field: field.clone(),
                road: r.id.clone(),
                lane: h.lane,
                span: road.plan_span(&r.id, s0, s1),
                why: by,
                whole_road: false,
            }
        })
        .chain(road_fields)
        .collect();
    Ok((lanes, crossings))
}

/// The lane fields a binding modifier names (`None`: a check).
fn fields(m: &MapModifier) -> Option<Vec<&str>> {
    match &m.kind {
        MapKind::StartLane(l) | MapKind::EndLane(l) => Some(vec![l.as_str()]),
        MapKind::LaneSide { lane1, lane2, .. } => Some(vec![lane1.as_str(), lane2.as_str()]),
        MapKind::InSequence {
            preceding,
            succeeding,
            ..
        } => Some(vec![preceding.as_str(), succeeding.as_str()]),
        MapKind::Opposite { route1, route2, .. } => Some(vec![route1.as_str(), route2.as_str()]),
        MapKind::Junction {
            in_lane, out_lane, ..
        } => Some(vec![in_lane.as_str(), out_lane.as_str()]),
        MapKind::RoutesInSequence {
            preceding,
            succeeding,
        } => Some(vec![preceding.lane.as_str(), succeeding.lane.as_str()]),
        MapKind::Crossing {
            start_lane,
            end_lane,
            ..
        } => Some(vec![start_lane.as_str(), end_lane.as_str()]),
        _ => None,
    }
}

/// The modifier's own lanes (no field) of `m`, if it has any.
fn own_lanes(m: &MapModifier) -> Option<Vec<&str>> {
    match &m.kind {
        MapKind::Junction {
            in_lane,
            out_lane,
            roads: JunctionRoads {
                own_lanes: true, ..
            },
            ..
        }
        | MapKind::Crossing {
            start_lane: in_lane,
            end_lane: out_lane,
            own_lanes: true,
            ..
        } => Some(vec![in_lane.as_str(), out_lane.as_str()]),
        MapKind::RoutesInSequence {
            preceding,
            succeeding,
        } => Some(
            [preceding, succeeding]
                .into_iter()
                .filter(|e| e.kind != EndKind::Lane)
                .map(|e| e.lane.as_str())
                .collect(),
        ),
        _ => None,
    }
}

/// Every driving lane of the roads outside junctions, in the network's order.
fn driving_lanes(net: &RoadNetwork) -> Vec<LaneHandle> {
    let mut out = Vec::new();
    for (ri, r) in net.roads().iter().enumerate() {
        if r.junction.is_some() {
            continue;
        }
        for (k, ls) in r.lane_sections.iter().enumerate() {
            for l in ls.right.iter().chain(ls.left.iter()) {
                if l.lane_type.is_drivable() {
                    out.push(LaneHandle {
                        road: ri as u32,
                        section: k as u32,
                        lane: l.id,
                    });
                }
            }
        }
    }
    out
}

/// The fields `mods` name (in first-use order) and every assignment of lanes of `domain` to
/// them that satisfies all of `mods` (at most [`MAX_SOLUTIONS`]), and how many partial
/// assignments were tried (at most [`MAX_TRIED`]).
fn solve(
    net: &RoadNetwork,
    domain: &[LaneHandle],
    mods: &[&MapModifier],
    on_plan: &dyn Fn(&LaneHandle) -> bool,
) -> (Vec<String>, Vec<Vec<LaneHandle>>, usize) {
    let mut names: Vec<String> = Vec::new();
    for m in mods {
        for f in fields(m).unwrap_or_default() {
            if !names.iter().any(|n| n == f) {
                names.push(f.to_string());
            }
        }
    }
    let index = |f: &str| names.iter().position(|n| n == f).unwrap_or(0);
    // Each field's own domain: the lanes its one-field modifiers allow.
    let own: Vec<Vec<LaneHandle>> = names
        .iter()
        .map(|n| {
            domain
                .iter()
                .copied()
                .filter(|h| {
                    mods.iter().all(|m| match &m.kind {
                        MapKind::StartLane(l) if l == n => starts(net, *h),
                        MapKind::EndLane(l) if l == n => ends(net, *h),
                        // With `road:`, `containing_road:`, `lane_section:` (the plan's roads).
                        MapKind::LaneSide {
                            lane1: a,
                            lane2: b,
                            on_plan_roads: true,
                            ..
                        }
                        | MapKind::InSequence {
                            preceding: a,
                            succeeding: b,
                            on_plan_roads: true,
                        }
                        | MapKind::Opposite {
                            route1: a,
                            route2: b,
                            on_plan_roads: true,
                        } if a == n || b == n => on_plan(h),
                        MapKind::Junction {
                            in_lane: a,
                            out_lane: b,
                            roads:
                                JunctionRoads {
                                    on_plan_roads: true,
                                    ..
                                },
                            ..
                        } if a == n || b == n => on_plan(h),
                        // A crossing's lanes: on the plan's roads, where the scenario happens.
                        MapKind::Crossing {
                            start_lane: a,
                            end_lane: b,
                            ..
                        } if a == n || b == n => on_plan(h),
                        // A route the map makes: its lane where it ends (starts).
                        MapKind::RoutesInSequence {
                            preceding,
                            succeeding,
                        } if [preceding, succeeding]
                            .iter()
                            .any(|e| e.kind == EndKind::Made && e.lane == *n) =>
                        {
                            made_lane(net, preceding, succeeding) == Some(*h)
                        }
                        // The own lanes of roads and lane sections in sequence: driven in +s,
                        // as the plan drives.
                        MapKind::RoutesInSequence {
                            preceding,
                            succeeding,
                        } if [preceding, succeeding]
                            .iter()
                            .any(|e| e.kind != EndKind::Lane && e.lane == *n) =>
                        {
                            on_plan(h) && net.driving_direction(*h) == Direction::Forward
                        }
                        _ => true,
                    })
                })
                .collect()
        })
        .collect();
    let rels: Vec<Rel> = mods
        .iter()
        .filter_map(|m| match &m.kind {
            MapKind::LaneSide {
                lane1,
                left,
                lane2,
                count,
                ..
            } => Some(Rel::Side(index(lane1), *left, index(lane2), *count)),
            MapKind::InSequence {
                preceding,
                succeeding,
                ..
            } => Some(Rel::Follows(index(succeeding), index(preceding))),
            MapKind::Opposite { route1, route2, .. } => {
                Some(Rel::Opposite(index(route1), index(route2)))
            }
            MapKind::Junction {
                in_lane,
                out_lane,
                direction,
                roads,
            } => Some(Rel::Through(
                index(out_lane),
                index(in_lane),
                direction.as_deref().and_then(Turn::named),
                roads.clockwise_count,
                roads.number_of_roads,
            )),
            // A road (or route) end: the other on the road after it; else lanes (of lane
            // sections) one after the other.
            MapKind::RoutesInSequence {
                preceding,
                succeeding,
            } => Some(
                if [preceding, succeeding]
                    .iter()
                    .any(|e| matches!(e.kind, EndKind::Road | EndKind::Made))
                {
                    Rel::NextRoad(index(&succeeding.lane), index(&preceding.lane))
                } else {
                    Rel::Follows(index(&succeeding.lane), index(&preceding.lane))
                },
            ),
            MapKind::Crossing {
                start_lane,
                end_lane,
                start_s,
                start_angle,
                ..
            } => Some(Rel::Crossing(
                index(start_lane),
                index(end_lane),
                *start_s,
                *start_angle,
            )),
            _ => None,
        })
        .collect();
    let mut out = Vec::new();
    let mut partial = Vec::new();
    let mut tried = 0;
    search(net, &own, &rels, &mut partial, &mut out, &mut tried);
    out.retain(|sol| one_road_per_field(net, mods, &index, sol));
    (names, out, tried)
}

/// A relation between two lane fields (by their index).
#[derive(Debug, Clone, Copy)]
enum Rel {
    /// The first is n lanes to the left (`true`) or right of the second.
    Side(usize, bool, usize, u32),
    /// The first is a successor of the second in its driving direction.
    Follows(usize, usize),
    /// The two lie in one lane section and are driven in opposite directions.
    Opposite(usize, usize),
    /// The first is reached from the second through one connecting lane of a junction,
    /// turning that way, its road that many roads clockwise round the junction from the
    /// second's, the junction's roads that many (`None`: any).
    Through(usize, usize, Option<Turn>, Option<u32>, Option<u32>),
    /// The first lies on another road the second leads onto, directly or through one
    /// connecting lane of a junction, in a lane of the same id.
    NextRoad(usize, usize),
    /// A crosswalk joins the first to the second, from s (else its middle) at that angle to
    /// the lane (else perpendicular) (`map_crossings`).
    Crossing(usize, usize, Option<f64>, Option<f64>),
}

impl Rel {
    /// Whether it holds for the assignment `a` (`None` while a field is unassigned).
    fn holds(self, net: &RoadNetwork, a: &[LaneHandle]) -> Option<bool> {
        let (i, j) = match self {
            Rel::Side(i, _, j, _)
            | Rel::Follows(i, j)
            | Rel::Opposite(i, j)
            | Rel::Through(i, j, ..)
            | Rel::NextRoad(i, j)
            | Rel::Crossing(i, j, ..) => (i, j),
        };
        let (x, y) = (*a.get(i)?, *a.get(j)?);
        Some(match self {
            Rel::Side(_, left, _, n) => beside(net, y, left, n) == Some(x),
            Rel::Follows(..) => net.successors(y).contains(&x),
            Rel::Crossing(_, _, s, angle) => crossing(net, x, y, s, angle).is_some(),
            Rel::Opposite(..) => {
                (x.road, x.section) == (y.road, y.section)
                    && net.driving_direction(x) != net.driving_direction(y)
            }
            // One lane id, as the plan keeps over its roads.
            Rel::NextRoad(..) => {
                x.road != y.road
                    && x.lane == y.lane
                    && (net.successors(y).contains(&x) || connecting(net, y, x).is_some())
            }
            Rel::Through(_, _, turn, cw, n) => connecting(net, y, x).is_some_and(|c| {
                let junction = net.roads()[c.road as usize].junction.as_deref();
                let at = junction.unwrap_or_default();
                turn.is_none_or(|t| heading_change(net, y, x).map(Turn::of) == Some(t))
                    && n.is_none_or(|n| map_junctions::number_of_roads(net, at) == n as usize)
                    && cw.is_none_or(|k| {
                        let (from, to) = (y.road as usize, x.road as usize);
                        map_junctions::clockwise_count(net, at, from, to) == Some(k)
                    })
            }),
        })
    }
}

/// The lane of the route the map makes among the ends of `routes_are_in_sequence`: at the
/// end of its last road (the last lane section, lane id of its points) where it precedes, at
/// the start of its first road (the first section) where it succeeds; the routes it makes
/// drive their lanes in +s (`crate::road::route_roads`).
fn made_lane(net: &RoadNetwork, preceding: &SeqEnd, succeeding: &SeqEnd) -> Option<LaneHandle> {
    let (route, first) = match (&preceding.made, &succeeding.made) {
        (Some(r), _) => (r, true),
        (None, Some(r)) => (r, false),
        (None, None) => return None,
    };
    let points = super::route::points(route)?;
    let (id, lane, _) = if first {
        points.last()?
    } else {
        points.first()?
    };
    let road = net.roads().iter().position(|r| &r.id == id)?;
    let sections = net.roads()[road].lane_sections.len();
    Some(LaneHandle {
        road: road as u32,
        section: if first {
            sections.checked_sub(1)? as u32
        } else {
            0
        },
        lane: *lane,
    })
}

/// Whether the road and junction fields of `roads_follow_in_junction` get one road (one
/// junction) each in the assignment `sol` of the lane fields, across all of `mods`.
fn one_road_per_field(
    net: &RoadNetwork,
    mods: &[&MapModifier],
    index: &dyn Fn(&str) -> usize,
    sol: &[LaneHandle],
) -> bool {
    let mut seen: Vec<(&str, String)> = Vec::new();
    let id = |h: LaneHandle| net.roads()[h.road as usize].id.clone();
    for m in mods {
        // (field, the value the assignment gives it).
        let values: Vec<(&str, String)> = match &m.kind {
            MapKind::Junction {
                in_lane,
                out_lane,
                roads,
                ..
            } => {
                let (a, b) = (sol[index(in_lane)], sol[index(out_lane)]);
                let c = connecting(net, a, b);
                let through = c
                    .and_then(|c| net.roads()[c.road as usize].junction.clone())
                    .unwrap_or_default();
                [
                    (roads.in_road.as_deref(), id(a)),
                    (roads.out_road.as_deref(), id(b)),
                    (roads.junction.as_deref(), through),
                    (
                        roads.junction_route.as_deref(),
                        c.map(id).unwrap_or_default(),
                    ),
                ]
                .into_iter()
                .filter_map(|(f, v)| f.map(|f| (f, v)))
                .collect()
            }
            MapKind::RoutesInSequence {
                preceding,
                succeeding,
            } => [preceding, succeeding]
                .into_iter()
                .filter_map(|e: &SeqEnd| {
                    let h = sol[index(&e.lane)];
                    match e.kind {
                        EndKind::Lane | EndKind::Made => None,
                        EndKind::Road => Some((e.field.as_str(), id(h))),
                        EndKind::Section => {
                            Some((e.field.as_str(), format!("{}/{}", id(h), h.section)))
                        }
                    }
                })
                .collect(),
            _ => continue,
        };
        for (f, value) in values {
            // A junction field and a road field of one name cannot both be; the path says.
            match seen.iter().find(|(g, _)| *g == f) {
                Some((_, v)) if *v != value => return false,
                Some(_) => {}
                None => seen.push((f, value)),
            }
        }
    }
    true
}

/// Depth-first assignment of the fields after `partial`, keeping every full one that holds.
fn search(
    net: &RoadNetwork,
    own: &[Vec<LaneHandle>],
    rels: &[Rel],
    partial: &mut Vec<LaneHandle>,
    out: &mut Vec<Vec<LaneHandle>>,
    tried: &mut usize,
) {
    if out.len() >= MAX_SOLUTIONS || *tried >= MAX_TRIED {
        return;
    }
    if partial.len() == own.len() {
        out.push(partial.clone());
        return;
    }
    for h in &own[partial.len()] {
        *tried += 1;
        partial.push(*h);
        if rels.iter().all(|r| r.holds(net, partial) != Some(false)) {
            search(net, own, rels, partial, out, tried);
        }
        partial.pop();
    }
}

/// The roads of a way through a junction the map's modifiers ask for
/// (`roads_follow_in_junction`), for the plan to drive when no named route
/// says otherwise: the first assignment that satisfies the modifiers, when its lane into the
/// junction and its lane out have one id and are driven in +s (the plan keeps its lane ids).
/// Indices into `net.roads()`: the road in, the connecting road, the road out.
pub(crate) fn junction_roads(net: &RoadNetwork, mods: &[MapModifier]) -> Option<Vec<usize>> {
    let lane_mods: Vec<&MapModifier> = mods.iter().filter(|m| fields(m).is_some()).collect();
    let (in_lane, out_lane) = lane_mods.iter().find_map(|m| match &m.kind {
        MapKind::Junction {
            in_lane, out_lane, ..
        } => Some((in_lane.clone(), out_lane.clone())),
        MapKind::RoutesInSequence {
            preceding,
            succeeding,
        } => Some((preceding.lane.clone(), succeeding.lane.clone())),
        _ => None,
    })?;
    let (names, solutions, _) = solve(net, &driving_lanes(net), &lane_mods, &|_| true);
    let at = |f: &str| names.iter().position(|n| n == f);
    let (i, o) = (at(&in_lane)?, at(&out_lane)?);
    solutions.iter().find_map(|sol| {
        let (a, b) = (sol[i], sol[o]);
        let forward = |h: LaneHandle| net.driving_direction(h) == Direction::Forward;
        if net.successors(a).contains(&b) && a.road != b.road {
            // Roads linked directly (routes_are_in_sequence on road or route fields).
            return (a.lane == b.lane && forward(a) && forward(b))
                .then(|| vec![a.road as usize, b.road as usize]);
        }
        let c = connecting(net, a, b)?;
        (a.lane == b.lane && c.lane == a.lane && forward(a) && forward(b) && forward(c))
            .then(|| vec![a.road as usize, c.road as usize, b.road as usize])
    })
}

/// The lane `n` lanes to the left (or right) of `h` across its lane section, every lane of
/// the section counted (the centre lane not).
fn beside(net: &RoadNetwork, h: LaneHandle, left: bool, n: u32) -> Option<LaneHandle> {
    let ls = &net.roads()[h.road as usize].lane_sections[h.section as usize];
    // Right to left: −k … −1, 1 … m.
    let ids: Vec<i32> = ls
        .right
        .iter()
        .rev()
        .chain(ls.left.iter())
        .map(|l| l.id)
        .collect();
    let i = ids.iter().position(|id| *id == h.lane)? as i64;
    let j = if left {
        i + i64::from(n)
    } else {
        i - i64::from(n)
    };
    let id = *ids.get(usize::try_from(j).ok()?)?;
    Some(LaneHandle { lane: id, ..h })
}

/// Whether a lane section lies before (`before`) or after the lane `h` in its driving
/// direction: an earlier (later) section of its road, or a road joined at that end.
fn has_section(net: &RoadNetwork, h: LaneHandle, before: bool) -> bool {
    let road = RoadHandle(h.road);
    let last = net.roads()[h.road as usize].lane_sections.len() as u32 - 1;
    let dir = net.driving_direction(h);
    let dir = if before { dir.reverse() } else { dir };
    match dir {
        Direction::Forward => h.section < last || !net.joined_roads(road, dir).is_empty(),
        Direction::Backward => h.section > 0 || !net.joined_roads(road, dir).is_empty(),
    }
}

/// §8.12.2.2.8: "the lane starts in its lane_section and has no predecessor in the previous
/// lane_section".
fn starts(net: &RoadNetwork, h: LaneHandle) -> bool {
    has_section(net, h, true) && net.predecessors(h).is_empty()
}

/// §8.12.2.2.7: "the lane ends in its lane_section and has no successor in the next
/// lane_section".
fn ends(net: &RoadNetwork, h: LaneHandle) -> bool {
    has_section(net, h, false) && net.successors(h).is_empty()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::test_roads::net;

    /// (road id, section, lane) of the driving lanes that pass `keep`.
    fn lanes(
        net: &RoadNetwork,
        keep: fn(&RoadNetwork, LaneHandle) -> bool,
    ) -> Vec<(String, u32, i32)> {
        driving_lanes(net)
            .into_iter()
            .filter(|h| keep(net, *h))
            .map(|h| (net.roads()[h.road as usize].id.clone(), h.section, h.lane))
            .collect()
    }

    #[test]
    fn start_and_end_lanes_are_read_from_the_lane_links() {
        // lane_drop.xodr: lane -3 of section 0 has no successor and section 1 follows it; lane
        // 1 (driven in -s) has none before section 0 either, but no section lies after it.
        let drop = net("lane_drop.xodr");
        assert_eq!(lanes(&drop, ends), [("1".to_string(), 0, -3)]);
        assert!(lanes(&drop, starts).is_empty());
        // road_link_unequal_number_of_lanes0.xodr: road 2's lane -3 has no predecessor while
        // road 1 lies before it; road 1's -3 goes on into road 2's -4.
        let unequal = net("road_link_unequal_number_of_lanes0.xodr");
        assert_eq!(lanes(&unequal, starts), [("2".to_string(), 0, -3)]);
        assert!(lanes(&unequal, ends).is_empty());
    }

    #[test]
    fn lanes_beside_count_every_lane_of_the_section_across_the_centre() {
        let drop = net("lane_drop.xodr");
        let h = |lane| LaneHandle {
            road: 0,
            section: 0,
            lane,
        };
        assert_eq!(beside(&drop, h(-3), true, 2), Some(h(-1)));
        assert_eq!(beside(&drop, h(-3), true, 3), Some(h(1)));
        assert_eq!(beside(&drop, h(-1), false, 2), Some(h(-3)));
        assert_eq!(beside(&drop, h(-3), false, 1), None);
        assert_eq!(beside(&drop, h(1), true, 1), None);
    }
}
