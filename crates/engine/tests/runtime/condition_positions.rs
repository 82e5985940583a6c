//! A condition's position resolved when the engine is built (engine condition/refs.rs;
//! OpenSCENARIO 1.3 §7.4 Position, §7.6.3 DistanceCondition): an entity-free one once, to its
//! pose; a relative one to its entity's id, read where that entity stands at each evaluation.
//! An undeclared `entityRef` of a relative one, and an entity-free one the road network does
//! not have, are load errors at the Position element.
//!
//! The file: runtime/trigger_view.xosc. Car1 drives 10 m/s on lane −1 of the straight road
//! (x = s) from s = 100; the Event "near before" starts when t > 1 and the DistanceCondition
//! "near before distance" (road coordinates, longitudinal, `lessThan 1`; its position, the
//! LanePosition element at 38:43, the place the reader gives a Position) holds.

use crate::runtime_support;

use engine::output::EventRecord;
use engine::storyboard::Transition;
use engine::{Engine, EngineConfig};
use runtime_support::{file, Recorder};
use scenario::{EntityCondition, PositionKind};

/// trigger_view.xosc with the position of "near before distance" replaced by `kind`.
fn with_position(kind: PositionKind) -> scenario::Scenario {
    let mut s = scenario::Scenario::load(&file("trigger_view.xosc")).expect("loads");
    // The Story's first ManeuverGroup, "near before group"; its one Event's second condition.
    let event = &mut s.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[0].events[0];
    assert_eq!(event.name, "near before");
    let trigger = event.start_trigger.as_mut().expect("its start trigger");
    let condition = &mut trigger.condition_groups[0].conditions[1];
    assert_eq!(condition.name, "near before distance");
    let scenario::ConditionKind::ByEntity {
        entity_condition: EntityCondition::Distance { position, .. },
        ..
    } = &mut condition.kind
    else {
        panic!("not a DistanceCondition: {condition:?}");
    };
    assert_eq!((position.pos.line, position.pos.col), (38, 43));
    position.kind = kind;
    s
}

fn build(s: &scenario::Scenario) -> Result<Engine, engine::Error> {
    let network = engine::load::road_network(s).expect("road network");
    Engine::new(s, network, EngineConfig::default())
}

/// Start time of Event "near before" in a run of `s`, if it starts (its startTransition; a
/// standby Event is stopped with the storyboard at the end, 2.05 s).
fn near_before_start(s: &scenario::Scenario) -> Option<f64> {
    let mut engine = build(s).unwrap_or_else(|e| panic!("does not build: {e}"));
    let (mut frames, mut events) = (Recorder::default(), Vec::new());
    engine.run(&mut frames, &mut events).expect("runs");
    events.iter().find_map(|e| match e {
        EventRecord::Transition(t)
            if t.name == "near before" && t.transition == Transition::Start =>
        {
            Some(t.time)
        }
        _ => None,
    })
}

fn relative_road(entity_ref: &str, ds: f64) -> PositionKind {
    PositionKind::RelativeRoad {
        entity_ref: entity_ref.into(),
        ds,
        dt: 0.0,
        orientation: None,
    }
}

/// A RelativeRoadPosition `ds` ahead of Car1 itself: the road-longitudinal distance from Car1
/// to it is ds wherever Car1 is, read at each evaluation from Car1's pose by id. ds = 0.5 < 1:
/// the condition holds from the first step, so the Event starts with the time condition, at
/// the first step with t > 1, 1.05 s (steps of 0.05 s). ds = 1.5 > 1: it never holds and the
/// Event never starts (the run ends at t > 2).
#[test]
fn a_position_relative_to_an_entity_is_measured_from_where_it_stands_now() {
    let start =
        near_before_start(&with_position(relative_road("Car1", 0.5))).expect("near before starts");
    assert!((start - 1.05).abs() < 1e-9, "started at {start}");
    assert_eq!(
        near_before_start(&with_position(relative_road("Car1", 1.5))),
        None
    );
}

/// An undeclared `entityRef` in each of the four relative forms: a load error at the position
/// element (38:43), naming the form's XSD element and the condition.
#[test]
fn a_relative_position_naming_an_undeclared_entity_is_refused_when_the_engine_is_built() {
    let forms = [
        (
            PositionKind::RelativeWorld {
                entity_ref: "ghost".into(),
                dx: 1.0,
                dy: 0.0,
                dz: None,
                orientation: None,
            },
            "RelativeWorldPosition@entityRef",
        ),
        (
            PositionKind::RelativeObject {
                entity_ref: "ghost".into(),
                dx: 1.0,
                dy: 0.0,
                dz: None,
                orientation: None,
            },
            "RelativeObjectPosition@entityRef",
        ),
        (
            relative_road("ghost", 1.0),
            "RelativeRoadPosition@entityRef",
        ),
        (
            PositionKind::RelativeLane {
                entity_ref: "ghost".into(),
                d_lane: 0,
                ds: Some(1.0),
                ds_lane: None,
                offset: None,
                orientation: None,
            },
            "RelativeLanePosition@entityRef",
        ),
    ];
    for (kind, element) in forms {
        let Err(e) = build(&with_position(kind)) else {
            panic!("built with {element} 'ghost'");
        };
        let pos = e.pos().expect("the position's place");
        assert_eq!((pos.line, pos.col), (38, 43), "{e}");
        assert!(pos.file.ends_with("trigger_view.xosc"), "{e}");
        let text = e.to_string();
        let want = format!(
            "expected a declared entity for {element} of condition 'near before distance', found 'ghost' at "
        );
        assert!(text.starts_with(&want), "{text}");
    }
}

/// An entity-free position the road network does not have (road "7"; the file's network has
/// road "1" only): resolved once when the engine is built, so refused then, at the Position
/// element, as an action's is (engine position/check.rs), not when the condition is first
/// evaluated.
#[test]
fn an_entity_free_position_off_the_road_network_is_refused_when_the_engine_is_built() {
    let s = with_position(PositionKind::Lane {
        road_id: "7".into(),
        lane_id: "-1".into(),
        s: 110.0,
        offset: Some(0.0),
        orientation: None,
    });
    let Err(e) = build(&s) else {
        panic!("built with a LanePosition on road 7");
    };
    let pos = e.pos().expect("the position's place");
    assert_eq!((pos.line, pos.col), (38, 43), "{e}");
    let text = e.to_string();
    assert!(
        text.starts_with("expected an existing road, found road id \"7\" at "),
        "{text}"
    );
}

/// A position of the condition written by the test (not in the file): line 99, column 1.
fn written(kind: PositionKind) -> scenario::Position {
    scenario::Position {
        kind,
        pos: scenario::SourcePos::new(file("trigger_view.xosc").into(), 99, 1),
    }
}

fn lane_waypoint(road: &str, s: f64) -> scenario::Waypoint {
    scenario::Waypoint {
        route_strategy: scenario::RouteStrategy::Shortest,
        position: written(PositionKind::Lane {
            road_id: road.into(),
            lane_id: "-1".into(),
            s,
            offset: Some(0.0),
            orientation: None,
        }),
    }
}

/// A RoutePosition on the route along lane −1 of road `road` from s = 50 to s = 400 (350 m,
/// driven towards +s; road "1" is the file's straight road, x = s).
fn on_route(road: &str, in_route: scenario::InRoutePosition) -> PositionKind {
    PositionKind::Route {
        route: Box::new(scenario::Route {
            name: "R".into(),
            closed: false,
            waypoints: vec![lane_waypoint(road, 50.0), lane_waypoint("1", 400.0)],
            catalog: None,
        }),
        orientation: None,
        in_route,
    }
}

fn from_lane(path_s: f64) -> scenario::InRoutePosition {
    scenario::InRoutePosition::FromLaneCoordinates {
        path_s,
        lane_id: "-1".into(),
        lane_offset: None,
    }
}

/// A RoutePosition on a route whose waypoints name no entity is planned once, when the engine
/// is built, and measured to as before. pathS counts from the first waypoint, s = 50: pathS
/// 60.25 is s = 110.25, 0.25 m ahead of Car1 at the step of 1.05 s (s = 100 + 10 × 1.05 =
/// 110.5, longitudinal road distance |110.5 − 110.25| = 0.25 < 1): the Event starts at
/// 1.05 s. pathS 62 is s = 112, 1.5 m ahead then: never. FromCurrentEntity Car1 is where Car1
/// stands on that route (distance 0): 1.05 s.
#[test]
fn a_route_position_on_entity_free_waypoints_is_measured_to_from_its_plan() {
    let start = near_before_start(&with_position(on_route("1", from_lane(60.25))))
        .expect("near before starts");
    assert!((start - 1.05).abs() < 1e-9, "started at {start}");
    assert_eq!(
        near_before_start(&with_position(on_route("1", from_lane(62.0)))),
        None
    );
    let current = scenario::InRoutePosition::FromCurrentEntity {
        entity_ref: "Car1".into(),
    };
    let start =
        near_before_start(&with_position(on_route("1", current))).expect("near before starts");
    assert!((start - 1.05).abs() < 1e-9, "started at {start}");
}

/// The route planned once is refused once, when the engine is built (before: at each
/// evaluation, a runtime error and false): a waypoint off the network at the waypoint's own
/// place (99:1), a pathS past the route's 350 m at the RoutePosition (38:43), an undeclared
/// FromCurrentEntity `entityRef` at the RoutePosition, naming its XSD element.
#[test]
fn an_entity_free_route_position_that_cannot_be_resolved_is_refused_when_the_engine_is_built() {
    let refused = |kind: PositionKind| {
        let Err(e) = build(&with_position(kind)) else {
            panic!("built");
        };
        let pos = e.pos().expect("the position's place").clone();
        ((pos.line, pos.col), e.to_string())
    };
    let (at, text) = refused(on_route("7", from_lane(10.0)));
    assert_eq!(at, (99, 1), "{text}");
    assert!(
        text.starts_with("expected an existing road, found road id \"7\" at "),
        "{text}"
    );
    let (at, text) = refused(on_route("1", from_lane(351.0)));
    assert_eq!(at, (38, 43), "{text}");
    assert!(
        text.starts_with("expected pathS in [0, 350] along route \"R\", found 351 at "),
        "{text}"
    );
    let ghost = scenario::InRoutePosition::FromCurrentEntity {
        entity_ref: "ghost".into(),
    };
    let (at, text) = refused(on_route("1", ghost));
    assert_eq!(at, (38, 43), "{text}");
    assert!(
        text.starts_with(
            "expected a declared entity for FromCurrentEntity@entityRef of condition 'near before distance', found 'ghost' at "
        ),
        "{text}"
    );
}

/// A TrajectoryPosition at `s` on a polyline through `vertices`.
fn on_polyline(vertices: Vec<PositionKind>, s: f64) -> PositionKind {
    PositionKind::Trajectory {
        trajectory: Box::new(scenario::Trajectory {
            name: "T".into(),
            closed: false,
            shape: scenario::Shape::Polyline(
                vertices
                    .into_iter()
                    .map(|k| scenario::Vertex {
                        time: None,
                        position: written(k),
                    })
                    .collect(),
            ),
            catalog: None,
        }),
        s,
        t: None,
        orientation: None,
    }
}

fn world_xy(x: f64, y: f64) -> PositionKind {
    PositionKind::World {
        x,
        y,
        z: None,
        h: None,
        p: None,
        r: None,
    }
}

/// A TrajectoryPosition on world points (resolved once) and one on points relative to Car1
/// (drawn at each evaluation from where Car1 stands). The polyline (50, −1.5) → (400, −1.5)
/// runs along the road (x = s): s = 60.25 is x = 110.25, 0.25 m behind Car1's 110.5 at 1.05 s:
/// the Event starts at 1.05 s. The polyline from Car1 (ds 0) to 100 m ahead of it: s = 0.5 is
/// 0.5 m ahead of Car1 wherever it is: 1.05 s; s = 1.5 never.
#[test]
fn a_trajectory_position_is_resolved_once_or_drawn_from_where_its_entity_stands() {
    let fixed = on_polyline(vec![world_xy(50.0, -1.5), world_xy(400.0, -1.5)], 60.25);
    let start = near_before_start(&with_position(fixed)).expect("near before starts");
    assert!((start - 1.05).abs() < 1e-9, "started at {start}");
    let relative = |s| {
        on_polyline(
            vec![relative_road("Car1", 0.0), relative_road("Car1", 100.0)],
            s,
        )
    };
    let start = near_before_start(&with_position(relative(0.5))).expect("near before starts");
    assert!((start - 1.05).abs() < 1e-9, "started at {start}");
    assert_eq!(near_before_start(&with_position(relative(1.5))), None);
    // Past the world polyline's 350 m: refused when the engine is built, at the position.
    let Err(e) = build(&with_position(on_polyline(
        vec![world_xy(50.0, -1.5), world_xy(400.0, -1.5)],
        351.0,
    ))) else {
        panic!("built with s past the trajectory");
    };
    assert_eq!(e.pos().map(|p| (p.line, p.col)), Some((38, 43)), "{e}");
}
