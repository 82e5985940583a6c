//! Catalogs of every kind (OpenSCENARIO 1.3 §9.4): Vehicle, Controller, Pedestrian,
//! MiscObject, Environment, Maneuver, Trajectory, Route, each referenced from
//! `tests/files/catalog_kinds.xosc`, most with ParameterAssignments. Expected values are
//! worked out by hand from the catalog files in `tests/files/catalogs/`.

use std::path::{Path, PathBuf};

use scenario::{
    ActionKind, EntityObject, FractionalCloudCover, GlobalAction, LongitudinalAction, PositionKind,
    Priority, PrivateAction, RouteStrategy, RoutingAction, Scenario, Shape, SpeedTarget,
};

/// Tolerance for values that pass through decimal text and one or two operations.
const TOL: f64 = 1e-12;

fn file() -> PathBuf {
    Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/files/catalog_kinds.xosc"
    ))
    .to_path_buf()
}

fn load() -> Scenario {
    Scenario::load(&file()).unwrap()
}

fn vehicle(s: &Scenario, name: &str) -> scenario::Vehicle {
    match &s.entities.object(name).unwrap().entity_object {
        EntityObject::Vehicle(v) => (**v).clone(),
        other => panic!("{other:?}"),
    }
}

#[test]
fn vehicle_entry_takes_the_assigned_parameter_and_recomputes_dependent_defaults() {
    let s = load();
    let truck = vehicle(&s, "Truck");
    // MaxSpeed := $TruckTop = 30 (assignment resolved in the scenario's scope).
    assert!((truck.performance.max_speed - 30.0).abs() < TOL);
    // Length = ${$MaxSpeed / 2.5} is declared after MaxSpeed: 30 / 2.5 = 12, not 25 / 2.5.
    assert!((truck.bounding_box.length - 12.0).abs() < TOL);
    // mass = ${$Mass * 1000} with the default Mass 12: 12 000 kg.
    assert!((truck.mass.unwrap() - 12_000.0).abs() < TOL);
    let origin = truck.catalog.unwrap();
    assert_eq!(
        (origin.catalog_name.as_str(), origin.entry_name.as_str()),
        ("TestVehicles", "truck")
    );
    assert_eq!(
        origin.parameter_assignments,
        [("MaxSpeed".to_owned(), "30".to_owned())]
    );
    assert!(origin.file.ends_with("catalogs/Vehicles/TestVehicles.xosc"));
    // The reference is on line 20 of catalog_kinds.xosc, indented by 6.
    assert_eq!((origin.pos.line, origin.pos.col), (20, 7));
}

#[test]
fn controller_entry_through_object_controller() {
    let s = load();
    let truck = s.entities.object("Truck").unwrap();
    let c = &truck.object_controllers[0].controller;
    assert_eq!(c.name, "cautious");
    assert_eq!(
        c.properties.properties,
        [("timeHeadway".to_owned(), "3.5".to_owned())]
    );
}

#[test]
fn pedestrian_entry_keeps_its_defaults_without_assignments() {
    let s = load();
    let EntityObject::Pedestrian(p) = &s.entities.object("Walker").unwrap().entity_object else {
        panic!()
    };
    assert!((p.mass - 80.0).abs() < TOL);
    assert!((p.bounding_box.height - 1.8).abs() < TOL);
}

#[test]
fn misc_object_entry_takes_an_expression_assignment() {
    let s = load();
    let EntityObject::MiscObject(m) = &s.entities.object("Cone").unwrap().entity_object else {
        panic!()
    };
    // Mass := ${1.5 * 2} = 3.
    assert!((m.mass - 3.0).abs() < TOL);
}

#[test]
fn environment_entry_in_an_environment_action() {
    let s = load();
    let ActionKind::Global(GlobalAction::Environment(env)) = &s.storyboard.init.actions[0].kind
    else {
        panic!()
    };
    let weather = env.weather.as_ref().unwrap();
    assert!((weather.fog.unwrap().visual_range - 120.0).abs() < TOL);
    assert_eq!(
        weather.fractional_cloud_cover,
        Some(FractionalCloudCover::EightOktas)
    );
    assert!((env.road_condition.as_ref().unwrap().friction_scale_factor - 0.8).abs() < TOL);
}

#[test]
fn route_entry_in_an_assign_route_action() {
    let s = load();
    let private = &s.storyboard.init.privates[0];
    let ActionKind::Private(PrivateAction::Routing(r)) = &private.actions[0].kind else {
        panic!()
    };
    let RoutingAction::AssignRoute(route) = r.as_ref() else {
        panic!()
    };
    assert!(route.closed);
    assert_eq!(route.waypoints[1].route_strategy, RouteStrategy::Fastest);
    let PositionKind::Lane { s: end_s, .. } = route.waypoints[1].position.kind else {
        panic!()
    };
    assert!((end_s - 250.0).abs() < TOL);
}

#[test]
fn maneuver_entry_in_a_maneuver_group_maps_the_deprecated_priority() {
    let s = load();
    let group = &s.storyboard.stories[0].acts[0].maneuver_groups[0];
    // The catalog maneuver comes first, in document order.
    let m = &group.maneuvers[0];
    assert_eq!(m.name, "brake");
    let event = &m.events[0];
    assert_eq!(event.priority, Priority::Override);
    assert_eq!(event.maximum_execution_count, 2);
    let ActionKind::Private(PrivateAction::Longitudinal(LongitudinalAction::Speed {
        target, ..
    })) = &event.actions[0].kind
    else {
        panic!()
    };
    // TargetSpeed := ${$TruckTop / 10} = 3.
    let SpeedTarget::Absolute(speed) = target else {
        panic!("{target:?}")
    };
    assert!((speed - 3.0).abs() < TOL);
    assert!(s
        .warnings
        .iter()
        .any(|w| w.message.contains("'overwrite' is a deprecated literal")));
}

#[test]
fn trajectory_entry_in_a_follow_trajectory_action() {
    let s = load();
    let m = &s.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[1];
    let ActionKind::Private(PrivateAction::Routing(r)) = &m.events[0].actions[0].kind else {
        panic!()
    };
    let RoutingAction::FollowTrajectory {
        trajectory,
        time_reference,
        ..
    } = r.as_ref()
    else {
        panic!()
    };
    assert!(time_reference.is_none());
    let Shape::Polyline(vertices) = &trajectory.shape else {
        panic!()
    };
    // Dy := -2 (assigned as "$Dy", the esmini spelling of the name).
    let PositionKind::World { x, y, .. } = vertices[1].position.kind else {
        panic!()
    };
    assert!((x - 20.0).abs() < TOL && (y + 2.0).abs() < TOL);
}

#[test]
fn global_overrides_reach_catalog_entries_through_assignments() {
    let s = Scenario::load_with_parameters(&file(), &[("TruckTop".into(), "40".into())]).unwrap();
    let truck = vehicle(&s, "Truck");
    // MaxSpeed := 40, Length = 40 / 2.5 = 16.
    assert!((truck.performance.max_speed - 40.0).abs() < TOL);
    assert!((truck.bounding_box.length - 16.0).abs() < TOL);
}

#[test]
fn an_override_of_an_undeclared_parameter_is_an_error() {
    let err = Scenario::load_with_parameters(&file(), &[("Nope".into(), "1".into())]).unwrap_err();
    assert_eq!(
        err.kind().to_string(),
        "expected a globally declared parameter to override, found unknown 'Nope'"
    );
    // Reported at the root element, line 2.
    assert_eq!((err.pos().line, err.pos().col), (2, 1));
}
