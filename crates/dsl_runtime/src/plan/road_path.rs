//! Paths through points of the road network (ASAM OpenSCENARIO DSL 2.1 §8.12.2.1.11
//! `map.create_path_odr_points(points, interpolation, on_road_network)`, §8.12.2.1.12
//! `map.create_path_route_points(…)`: "Sequence of `odr_point` (`route_point`) that will be
//! converted to world x-y-z-coordinates to create a `path`"), and trajectories through them
//! (§8.12.2.1.14 `create_trajectory_odr_points(points, time_stamps, …)`, §8.12.2.1.15
//! `create_trajectory_route_points(…)`, the same points with time stamps), turned into world
//! points.
//!
//! Where the conversion happens: a point's world position needs the road network, which the
//! resolver does not have. The resolver keeps the path symbolic (`Place::RoadPath`: each point
//! as the route from it, road, lane, s and t, or a point on a route), and this module, run by
//! the plan stage that is given the network before it plans, replaces it by the `Place::Path`
//! (`Place::Trajectory`, its time stamps kept) of its world points. So the stages keep passing
//! data forward (resolve → plan → lower) and no stage calls back into another for the
//! network; from here on the path is the one `create_path` gives (the trajectory
//! `create_trajectory`'s), followed by `follow_path(absolute: …)` or by a movement with
//! `along(…)` (`follow_trajectory(absolute: …)`) (`trajectory_actions`).
//!
//! oscsim's choices where the standard is silent:
//! - a point is placed as a route from it is (`route::locate_route`: an odr point's t from its
//!   lane's centre, or from the reference line without a lane; a route point s along its route
//!   and t from its line), at the lane's centre plus t, its heading the lane's driving
//!   direction there (right-hand traffic: +s for a lane of negative id), which a `smooth`
//!   path takes as the point's heading;
//! - `on_road_network: true` ("the points of the path must be joined while keeping the whole
//!   path on the road network"): the points are joined by the path's own line (the polyline,
//!   or the smooth curve), and every point of it, sampled at most [`STEP`] apart, must be on
//!   a road's surface (within a lane's borders, with the plan's position tolerance); a line that leaves
//!   the roads is an error at the path naming where. `false` (or none given): not checked.
//! - a point the network does not have (a road, a lane at s, an s off the road) is an error at
//!   the path naming the point.

use super::path_part::samples;
use super::path_shape::{segment_lengths, Pose2};
use super::route::{locate_route, on_surface};
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{Kind, Phase, Place, Resolved, Route};
use opendrive::RoadNetwork;

/// How far apart (m along the path) its line is checked on the road network.
pub(crate) const STEP: f64 = 0.5;

/// Replaces every path through points of the road network in `resolved` by the path of their
/// world points on `net`.
pub(crate) fn locate_paths(resolved: &mut Resolved, net: &RoadNetwork) -> Result<(), Error> {
    fn walk(p: &mut Phase, net: &RoadNetwork) -> Result<(), Error> {
        if let Kind::Invoke(inv) = &mut p.kind {
            for a in &mut inv.places {
                if let Place::RoadPath {
                    points,
                    times,
                    smooth,
                    on_road_network,
                } = &a.place
                {
                    let points = world_path(points, *smooth, *on_road_network, net, &a.site)?;
                    a.place = match times {
                        None => Place::Path {
                            points,
                            smooth: *smooth,
                        },
                        Some(times) => Place::Trajectory {
                            points,
                            times: times.clone(),
                            smooth: *smooth,
                        },
                    };
                }
            }
        }
        p.children.iter_mut().try_for_each(|c| walk(c, net))
    }
    walk(&mut resolved.root, net)
}

/// The world points (x, y, heading) of the path through `points` (each a route from one point)
/// on `net`, joined `smooth`ly or not; errors at `site`.
fn world_path(
    points: &[Route],
    smooth: bool,
    on_road_network: bool,
    net: &RoadNetwork,
    site: &Site,
) -> Result<Vec<Pose2>, Error> {
    let world = points
        .iter()
        .enumerate()
        .map(|(i, r)| world_point(i, r, net, site))
        .collect::<Result<Vec<_>, _>>()?;
    if on_road_network {
        let length: f64 = segment_lengths(&world, smooth).iter().sum();
        let (line, _) = samples(&world, None, smooth, (0.0, length), STEP);
        if let Some((x, y, _)) = line
            .into_iter()
            .find(|&(x, y, _)| !net.locate(x, y, None).is_some_and(|p| on_surface(net, &p)))
        {
            return Err(site.err(
                K::Road,
                format!("expected the path's line on the road network (on_road_network: true, §8.12.2.1: \"the points of the path must be joined while keeping the whole path on the road network\"), found it off every road at x = {x:.2} m, y = {y:.2} m"),
            ));
        }
    }
    Ok(world)
}

/// World x, y and heading of the path's point `i`, the route from it `r`: the lane's centre
/// plus t, heading along the lane's driving direction.
fn world_point(
    i: usize,
    r: &Route,
    net: &RoadNetwork,
    site: &Site,
) -> Result<(f64, f64, f64), Error> {
    let mut r = r.clone();
    locate_route(&mut r, net, site)?;
    let Route::Lane {
        road, lane, s, t, ..
    } = &r
    else {
        return Err(site.err(
            K::Road,
            format!(
                "expected point {} of the path on the road network, found a route of no point",
                i + 1
            ),
        ));
    };
    let pose = net.lane_pose(road, *lane, *s, *t).map_err(|e| {
        site.err(
            K::Road,
            format!("expected point {} of the path (road {road}, lane {lane}, s = {s} m, t = {t} m) on the road network, found none there: {e}", i + 1),
        )
    })?;
    // A lane of positive id is driven in -s (right-hand traffic).
    let heading = if *lane > 0 {
        pose.h + std::f64::consts::PI
    } else {
        pose.h
    };
    Ok((pose.x, pose.y, heading))
}
