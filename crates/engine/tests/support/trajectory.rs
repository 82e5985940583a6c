//! Shared harness of the trajectory and routing tests: a road network with no entities
//! behind `EntityQuery`, and builders for positions and shapes written at `test.xosc:3:5`.

#![allow(dead_code)] // each test file uses a different part

use std::path::Path;
use std::sync::Arc;

use engine::position::{EntityQuery, EntityView};
use opendrive::RoadNetwork;
use scenario::{
    ControlPoint, Nurbs, Position, PositionKind, ReferenceContext, Route, RouteStrategy, Shape,
    SourcePos, Timing, Trajectory, Vertex, Waypoint,
};

/// A road network and no entities.
pub struct Roads(pub RoadNetwork);

impl EntityQuery for Roads {
    fn entity(&self, _: &str) -> Option<EntityView<'_>> {
        None
    }
    fn entities(&self) -> Box<dyn Iterator<Item = EntityView<'_>> + '_> {
        Box::new(std::iter::empty())
    }
    fn road_network(&self) -> &RoadNetwork {
        &self.0
    }
}

/// A corpus road network, by path relative to `shared/corpus/`.
pub fn corpus(rel: &str) -> Roads {
    // The corpus is part of the test fixture; a missing file is a broken checkout.
    Roads(RoadNetwork::from_file(&crate::corpus::corpus(rel)).expect("corpus road network loads"))
}

/// A road network of this crate's `tests/files/`.
pub fn fixture(name: &str) -> Roads {
    // The fixture is part of the test; a missing file is a broken checkout.
    Roads(
        RoadNetwork::from_file(&crate::corpus::fixture(name)).expect("fixture road network loads"),
    )
}

/// The straight 500 m road of esmini (road "1" along +x from the origin).
pub fn straight() -> Roads {
    corpus("esmini/xodr/straight_500m.xodr")
}

/// Where every test element claims to be written.
pub fn here() -> SourcePos {
    SourcePos {
        file: Arc::from(Path::new("test.xosc")),
        line: 3,
        col: 5,
    }
}

/// A source position on line `line` of test.xosc (to tell points apart in errors).
pub fn line(line: u32) -> SourcePos {
    SourcePos { line, ..here() }
}

/// A WorldPosition (x, y, z, heading) written on line `at`.
pub fn world_at(x: f64, y: f64, z: f64, h: f64, at: u32) -> Position {
    Position {
        kind: PositionKind::World {
            x,
            y,
            z: Some(z),
            h: Some(h),
            p: None,
            r: None,
        },
        pos: line(at),
    }
}

/// A WorldPosition at (x, y), z = 0, heading 0, written at `here()`.
pub fn world(x: f64, y: f64) -> Position {
    Position {
        pos: here(),
        ..world_at(x, y, 0.0, 0.0, 3)
    }
}

/// A LanePosition on `road`, lane `lane` at s.
pub fn lane(road: &str, lane: i32, s: f64) -> Position {
    Position {
        kind: PositionKind::Lane {
            road_id: road.into(),
            lane_id: lane.to_string(),
            s,
            offset: None,
            orientation: None,
        },
        pos: here(),
    }
}

/// A trajectory named "T" of `shape`.
pub fn trajectory(shape: Shape, closed: bool) -> Trajectory {
    Trajectory {
        name: "T".into(),
        closed,
        shape,
        catalog: None,
    }
}

/// A polyline through (x, y, time) points, each vertex written on its own line (10, 11, …).
pub fn polyline(points: &[(f64, f64, Option<f64>)]) -> Shape {
    Shape::Polyline(
        points
            .iter()
            .enumerate()
            .map(|(i, &(x, y, time))| Vertex {
                time,
                position: world_at(x, y, 0.0, 0.0, 10 + i as u32),
            })
            .collect(),
    )
}

/// A NURBS of `order` through (x, y, weight, time) control points (on lines 20, 21, …).
pub fn nurbs(order: u32, points: &[(f64, f64, Option<f64>, Option<f64>)], knots: &[f64]) -> Shape {
    Shape::Nurbs(Nurbs {
        order,
        control_points: points
            .iter()
            .enumerate()
            .map(|(i, &(x, y, weight, time))| ControlPoint {
                time,
                weight,
                position: world_at(x, y, 0.0, 0.0, 20 + i as u32),
            })
            .collect(),
        knots: knots.to_vec(),
    })
}

/// A Clothoid from `start` with constant curvature `curvature` over `length` m (an arc).
pub fn arc(curvature: f64, length: f64, start: Position) -> Shape {
    Shape::Clothoid(scenario::Clothoid {
        curvature,
        curvature_prime: 0.0,
        length,
        start_time: None,
        stop_time: None,
        position: start,
    })
}

/// Timing with domain `absolute` or relative, `scale` and `offset`.
pub fn timing(absolute: bool, scale: f64, offset: f64) -> Timing {
    Timing {
        domain_absolute_relative: if absolute {
            ReferenceContext::Absolute
        } else {
            ReferenceContext::Relative
        },
        offset,
        scale,
    }
}

/// A route named "R" through `positions`, every waypoint with `strategy`.
pub fn route(positions: Vec<Position>, strategy: RouteStrategy, closed: bool) -> Route {
    Route {
        name: "R".into(),
        closed,
        waypoints: positions
            .into_iter()
            .map(|position| Waypoint {
                route_strategy: strategy,
                position,
            })
            .collect(),
        catalog: None,
    }
}

/// A road network with one vehicle `name` at `pose`, standing where `locate` finds it.
pub struct Placed {
    pub roads: RoadNetwork,
    pub name: &'static str,
    pub pose: opendrive::Pose,
    pub road_position: Option<opendrive::RoadPosition>,
}

impl Placed {
    /// `name` at `pose` on `roads`, its road position looked up with its heading.
    pub fn new(roads: RoadNetwork, name: &'static str, pose: opendrive::Pose) -> Self {
        let road_position = roads.locate(pose.x, pose.y, Some(pose.h));
        Self {
            roads,
            name,
            pose,
            road_position,
        }
    }
}

impl EntityQuery for Placed {
    fn entity(&self, name: &str) -> Option<EntityView<'_>> {
        // A 4.5 × 1.8 × 1.5 m box 1.4 m ahead of the rear axle: constant, valid dimensions.
        let bb = engine::domain::BoundingBox::new(
            engine::domain::Position3d::new(1.4, 0.0, 0.75),
            4.5,
            1.8,
            1.5,
        )
        .expect("valid box");
        (name == self.name).then(|| EntityView {
            road_position: self.road_position.as_ref(),
            ..EntityView::new(self.name, scenario::ObjectType::Vehicle, self.pose, bb)
        })
    }
    fn entities(&self) -> Box<dyn Iterator<Item = EntityView<'_>> + '_> {
        Box::new(self.entity(self.name).into_iter())
    }
    fn road_network(&self) -> &RoadNetwork {
        &self.roads
    }
}

/// A corpus scenario, relative to `shared/corpus/`.
pub fn corpus_scenario(rel: &str) -> scenario::Scenario {
    // A corpus scenario that loads (checked by the scenario crate's own corpus tests).
    scenario::Scenario::load(&crate::corpus::corpus(rel)).expect("corpus scenario loads")
}

/// The road network a loaded scenario names.
pub fn scenario_roads(sc: &scenario::Scenario) -> RoadNetwork {
    let logic = sc
        .road_network
        .logic_file
        .as_ref()
        .expect("the scenario names its road");
    // The scenario's road network is part of the corpus.
    RoadNetwork::from_file(logic).expect("road network loads")
}

/// The RoutingActions of the scenario's Init section, each with its action's source position.
pub fn init_routing_actions(
    sc: &scenario::Scenario,
) -> impl Iterator<Item = (&scenario::RoutingAction, &SourcePos)> {
    sc.storyboard
        .init
        .privates
        .iter()
        .flat_map(|p| &p.actions)
        .filter_map(|a| match &a.kind {
            scenario::ActionKind::Private(scenario::PrivateAction::Routing(r)) => {
                Some((r.as_ref(), &a.pos))
            }
            _ => None,
        })
}

/// The FollowTrajectoryAction of the story event `event`: its trajectory, time reference and
/// the action's source position.
pub fn follow_trajectory_of<'a>(
    sc: &'a scenario::Scenario,
    event: &str,
) -> (&'a Trajectory, Option<Timing>, &'a SourcePos) {
    let ev = sc
        .storyboard
        .stories
        .iter()
        .flat_map(|s| &s.acts)
        .flat_map(|a| &a.maneuver_groups)
        .flat_map(|g| &g.maneuvers)
        .flat_map(|m| &m.events)
        .find(|e| e.name == event)
        .unwrap_or_else(|| panic!("no event {event}"));
    let action = &ev.actions[0];
    let scenario::ActionKind::Private(scenario::PrivateAction::Routing(r)) = &action.kind else {
        panic!("{event} is not a routing action");
    };
    let scenario::RoutingAction::FollowTrajectory {
        trajectory,
        time_reference,
        ..
    } = r.as_ref()
    else {
        panic!("{event} is not a FollowTrajectoryAction");
    };
    (trajectory, *time_reference, &action.pos)
}
