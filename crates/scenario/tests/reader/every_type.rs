//! Every action and condition type of OpenSCENARIO 1.3 reads into typed data with its values
//! (`tests/files/every_action_and_condition.xosc`: one Event with 32 actions, one condition
//! group per condition type). Values are compared with the fixture's attribute text.

use std::path::Path;

use scenario::*;

/// Decimal attribute text read as f64 and compared without arithmetic.
const TOL: f64 = 1e-12;

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < TOL
}

fn load() -> Scenario {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/files/every_action_and_condition.xosc"
    ));
    Scenario::load(path).unwrap()
}

fn event(s: &Scenario) -> &Event {
    &s.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[0].events[0]
}

fn private(e: &Event, i: usize) -> &PrivateAction {
    match &e.actions[i].kind {
        ActionKind::Private(p) => p,
        other => panic!("action {i}: {other:?}"),
    }
}

fn global(e: &Event, i: usize) -> &GlobalAction {
    match &e.actions[i].kind {
        ActionKind::Global(g) => g,
        other => panic!("action {i}: {other:?}"),
    }
}

#[test]
fn longitudinal_and_lateral_actions() {
    let s = load();
    let e = event(&s);
    assert_eq!(e.actions.len(), 32);
    let PrivateAction::Longitudinal(LongitudinalAction::Speed { dynamics, target }) = private(e, 0)
    else {
        panic!()
    };
    assert_eq!(dynamics.dynamics_shape, DynamicsShape::Cubic);
    assert!(close(dynamics.value, 4.0));
    let SpeedTarget::Relative {
        speed_target_value_type,
        continuous,
        ..
    } = target
    else {
        panic!()
    };
    assert_eq!(
        (*speed_target_value_type, *continuous),
        (SpeedTargetValueType::Delta, true)
    );
    let PrivateAction::Longitudinal(LongitudinalAction::LongitudinalDistance {
        time_gap,
        displacement,
        dynamic_constraints,
        ..
    }) = private(e, 1)
    else {
        panic!()
    };
    assert!(close(time_gap.unwrap(), 1.5));
    assert_eq!(
        *displacement,
        Some(LongitudinalDisplacement::TrailingReferencedEntity)
    );
    assert!(close(dynamic_constraints.unwrap().max_speed.unwrap(), 30.0));
    let PrivateAction::Longitudinal(LongitudinalAction::SpeedProfile { entries, .. }) =
        private(e, 2)
    else {
        panic!()
    };
    assert_eq!(entries.len(), 2);
    assert!(entries[1].time.is_none());
    let PrivateAction::Lateral(LateralAction::LaneChange {
        target,
        target_lane_offset,
        ..
    }) = private(e, 3)
    else {
        panic!()
    };
    assert_eq!(*target, LaneChangeTarget::Absolute("-2".into()));
    assert!(close(target_lane_offset.unwrap(), 0.5));
    let PrivateAction::Lateral(LateralAction::LaneOffset {
        max_lateral_acc,
        target,
        ..
    }) = private(e, 4)
    else {
        panic!()
    };
    assert!(close(max_lateral_acc.unwrap(), 0.8));
    assert!(matches!(target, LaneOffsetTarget::Relative { value, .. } if close(*value, -0.4)));
    let PrivateAction::Lateral(LateralAction::LateralDistance { displacement, .. }) = private(e, 5)
    else {
        panic!()
    };
    assert_eq!(
        *displacement,
        Some(LateralDisplacement::LeftToReferencedEntity)
    );
}

#[test]
fn other_private_actions() {
    let s = load();
    let e = event(&s);
    let PrivateAction::Visibility(v) = private(e, 6) else {
        panic!()
    };
    assert_eq!((v.graphics, v.sensors, v.traffic), (true, false, true));
    assert_eq!(v.sensor_references, ["front_radar"]);
    let PrivateAction::Synchronize(sync) = private(e, 7) else {
        panic!()
    };
    assert!(
        matches!(sync.target_position.kind, PositionKind::RelativeRoad { dt, .. } if close(dt, -3.5))
    );
    assert!(matches!(
        sync.final_speed,
        Some(FinalSpeed::Absolute { value, steady_state: Some(SteadyState::Time(t)) }) if close(value, 8.0) && close(t, 3.0)
    ));
    let PrivateAction::Controller(c) = private(e, 8) else {
        panic!()
    };
    assert!(
        matches!(c.as_ref(), ControllerAction::Assign { activate, .. } if activate.lateral == Some(true))
    );
    let PrivateAction::Controller(c) = private(e, 9) else {
        panic!()
    };
    let ControllerAction::OverrideValues(o) = c.as_ref() else {
        panic!()
    };
    assert_eq!(o.brake.unwrap().input, BrakeInput::Force(800.0));
    assert_eq!(o.gear.unwrap().gear, Gear::Automatic(AutomaticGearType::D));
    assert!(close(o.steering_wheel.unwrap().max_torque.unwrap(), 5.0));
    let PrivateAction::Controller(c) = private(e, 10) else {
        panic!()
    };
    assert!(
        matches!(c.as_ref(), ControllerAction::Activate { object_controller_ref: Some(r), .. } if r == "Driver")
    );
    let PrivateAction::Teleport(p) = private(e, 11) else {
        panic!()
    };
    assert!(
        matches!(p.kind, PositionKind::RelativeLane { d_lane: 1, ds_lane: Some(d), .. } if close(d, 12.0))
    );
    let PrivateAction::Routing(r) = private(e, 12) else {
        panic!()
    };
    let RoutingAction::AssignRoute(route) = r.as_ref() else {
        panic!()
    };
    assert!(
        matches!(route.waypoints[1].position.kind, PositionKind::Geo { latitude_deg, .. } if close(latitude_deg, 57.7))
    );
    let PrivateAction::Routing(r) = private(e, 13) else {
        panic!()
    };
    let RoutingAction::FollowTrajectory {
        trajectory,
        initial_distance_offset,
        ..
    } = r.as_ref()
    else {
        panic!()
    };
    let Shape::Nurbs(n) = &trajectory.shape else {
        panic!()
    };
    assert_eq!((n.order, n.control_points.len(), n.knots.len()), (3, 3, 6));
    assert!(close(initial_distance_offset.unwrap(), 2.0));
    let PrivateAction::Routing(r) = private(e, 14) else {
        panic!()
    };
    let RoutingAction::AcquirePosition(p) = r.as_ref() else {
        panic!()
    };
    assert!(
        matches!(&p.kind, PositionKind::Route { in_route: InRoutePosition::FromLaneCoordinates { path_s, .. }, .. } if close(*path_s, 30.0))
    );
    assert!(
        matches!(private(e, 15), PrivateAction::Routing(r) if matches!(r.as_ref(), RoutingAction::RandomRoute))
    );
    let PrivateAction::Appearance(AppearanceAction::LightState(l)) = private(e, 16) else {
        panic!()
    };
    assert_eq!(
        l.light_type,
        LightKind::Vehicle(VehicleLightType::IndicatorLeft)
    );
    assert_eq!(l.light_state.mode, LightMode::Flashing);
    let PrivateAction::Appearance(AppearanceAction::Animation(a)) = private(e, 17) else {
        panic!()
    };
    assert_eq!(
        a.animation_type,
        AnimationType::VehicleComponent(VehicleComponentType::DoorFrontLeft)
    );
    assert_eq!(
        *private(e, 18),
        PrivateAction::Trailer(TrailerAction::Connect {
            trailer_ref: "Trailer".into()
        })
    );
    assert_eq!(
        *private(e, 19),
        PrivateAction::Trailer(TrailerAction::Disconnect)
    );
}

#[test]
fn global_and_user_defined_actions() {
    let s = load();
    let e = event(&s);
    let GlobalAction::Environment(env) = global(e, 20) else {
        panic!()
    };
    let weather = env.weather.as_ref().unwrap();
    assert!(close(weather.temperature.unwrap(), 293.15));
    assert!(close(weather.wind.unwrap().speed, 4.0));
    assert_eq!(
        env.road_condition.as_ref().unwrap().wetness,
        Some(Wetness::WetWithPuddles)
    );
    assert!(matches!(
        global(e, 21),
        GlobalAction::Entity {
            add_at: Some(_),
            ..
        }
    ));
    assert!(matches!(
        global(e, 22),
        GlobalAction::Entity { add_at: None, .. }
    ));
    assert!(matches!(
        global(e, 23),
        GlobalAction::TrafficSignal(TrafficSignalAction::State { .. })
    ));
    assert!(matches!(
        global(e, 24),
        GlobalAction::TrafficSignal(TrafficSignalAction::Controller { .. })
    ));
    assert_eq!(
        *global(e, 25),
        GlobalAction::SetMonitor {
            monitor_ref: "Safe".into(),
            value: false
        }
    );
    assert_eq!(
        *global(e, 26),
        GlobalAction::Variable {
            variable_ref: "Laps".into(),
            rule: ModifyRule::AddValue(1.0)
        }
    );
    let GlobalAction::Traffic {
        traffic_name,
        action,
    } = global(e, 27)
    else {
        panic!()
    };
    assert_eq!(traffic_name.as_deref(), Some("swarm"));
    let TrafficAction::Swarm {
        number_of_vehicles,
        traffic,
        initial_speed_range,
        ..
    } = action.as_ref()
    else {
        panic!()
    };
    assert_eq!(*number_of_vehicles, 12);
    assert_eq!(
        traffic
            .definition
            .as_ref()
            .unwrap()
            .vehicle_categories
            .len(),
        2
    );
    assert!(close(initial_speed_range.unwrap().upper_limit, 30.0));
    assert!(
        matches!(global(e, 28), GlobalAction::Traffic { action, .. } if matches!(action.as_ref(), TrafficAction::Source { rate, .. } if close(*rate, 0.5)))
    );
    assert!(
        matches!(global(e, 29), GlobalAction::Traffic { action, .. } if matches!(action.as_ref(), TrafficAction::Sink { rate: None, .. }))
    );
    assert!(
        matches!(global(e, 30), GlobalAction::Traffic { action, .. } if matches!(action.as_ref(), TrafficAction::Stop))
    );
    let ActionKind::UserDefined(u) = &e.actions[31].kind else {
        panic!()
    };
    assert_eq!(
        (u.command_type.as_str(), u.content.as_str()),
        ("log", "hello")
    );
}

#[test]
fn every_condition_type() {
    let s = load();
    let groups = &event(&s).start_trigger.as_ref().unwrap().condition_groups;
    assert_eq!(groups.len(), 24);
    let kinds: Vec<&ConditionKind> = groups.iter().map(|g| &g.conditions[0].kind).collect();
    assert!(groups
        .iter()
        .all(|g| g.conditions[0].condition_edge == ConditionEdge::RisingOrFalling));
    let entity = |i: usize| match kinds[i] {
        ConditionKind::ByEntity {
            entity_condition,
            triggering_entities,
        } => {
            assert_eq!(triggering_entities.rule, TriggeringEntitiesRule::All);
            entity_condition
        }
        other => panic!("{i}: {other:?}"),
    };
    assert!(matches!(entity(0), EntityCondition::EndOfRoad { duration } if close(*duration, 1.0)));
    assert_eq!(
        *entity(1),
        EntityCondition::Collision(CollisionTarget::ByType(ObjectType::Pedestrian))
    );
    assert!(matches!(entity(2), EntityCondition::Offroad { .. }));
    let EntityCondition::TimeHeadway { measure, rule, .. } = entity(3) else {
        panic!()
    };
    assert_eq!(*rule, Rule::LessThan);
    assert_eq!(
        *measure,
        DistanceMeasure {
            freespace: true,
            coordinate_system: Some(CoordinateSystem::Lane),
            relative_distance_type: Some(RelativeDistanceType::Longitudinal),
            routing_algorithm: Some(RoutingAlgorithm::Shortest),
        }
    );
    assert!(
        matches!(entity(4), EntityCondition::TimeToCollision { target: TimeToCollisionTarget::EntityRef(r), .. } if r == "Box")
    );
    assert!(matches!(
        entity(5),
        EntityCondition::Acceleration {
            direction: Some(DirectionalDimension::Longitudinal),
            ..
        }
    ));
    assert!(matches!(entity(6), EntityCondition::StandStill { .. }));
    assert!(matches!(entity(7), EntityCondition::Speed { value, .. } if close(*value, 13.9)));
    assert!(matches!(entity(8), EntityCondition::RelativeSpeed { .. }));
    assert!(
        matches!(entity(9), EntityCondition::TraveledDistance { value } if close(*value, 250.0))
    );
    assert!(
        matches!(entity(10), EntityCondition::ReachPosition { tolerance, .. } if close(*tolerance, 2.0))
    );
    assert!(matches!(entity(11), EntityCondition::Distance { .. }));
    assert!(
        matches!(entity(12), EntityCondition::RelativeDistance { measure, .. } if measure.relative_distance_type == Some(RelativeDistanceType::Lateral))
    );
    assert!(
        matches!(entity(13), EntityCondition::RelativeClearance { relative_lane_ranges, .. } if relative_lane_ranges == &[(Some(-1), Some(1))])
    );
    assert!(matches!(
        entity(14),
        EntityCondition::Angle {
            angle_type: AngleType::Heading,
            ..
        }
    ));
    assert!(matches!(
        entity(15),
        EntityCondition::RelativeAngle {
            angle_type: AngleType::Pitch,
            ..
        }
    ));
    let value = |i: usize| match kinds[i] {
        ConditionKind::ByValue(v) => v,
        other => panic!("{i}: {other:?}"),
    };
    assert!(
        matches!(value(16), ByValueCondition::Parameter { parameter_ref, .. } if parameter_ref == "Limit")
    );
    assert!(matches!(value(17), ByValueCondition::TimeOfDay { .. }));
    assert!(
        matches!(value(18), ByValueCondition::SimulationTime { value, .. } if close(*value, 12.5))
    );
    assert!(matches!(
        value(19),
        ByValueCondition::StoryboardElementState {
            state: StoryboardElementState::RunningState,
            ..
        }
    ));
    assert!(matches!(
        value(20),
        ByValueCondition::UserDefinedValue {
            rule: Rule::NotEqualTo,
            ..
        }
    ));
    assert!(matches!(value(21), ByValueCondition::TrafficSignal { .. }));
    assert!(matches!(
        value(22),
        ByValueCondition::TrafficSignalController { .. }
    ));
    assert!(matches!(value(23), ByValueCondition::Variable { .. }));
}

#[test]
fn entities_of_every_kind() {
    let s = load();
    let EntityObject::Vehicle(ego) = &s.entities.object("Ego").unwrap().entity_object else {
        panic!()
    };
    assert_eq!(ego.role, Some(Role::Police));
    assert!(close(ego.mass.unwrap(), 1500.0));
    assert!(close(ego.trailer_hitch.unwrap().dx, -1.1));
    assert!(close(ego.performance.max_deceleration_rate.unwrap(), 4.0));
    let controller = &s.entities.object("Ego").unwrap().object_controllers[0];
    assert_eq!(controller.name.as_deref(), Some("Driver"));
    assert_eq!(
        controller.controller.controller_type,
        Some(ControllerType::Movement)
    );
    assert!(
        matches!(&s.entities.object("Box").unwrap().entity_object, EntityObject::MiscObject(m) if m.misc_object_category == MiscObjectCategory::Obstacle)
    );
    assert_eq!(
        s.entities.object("Sign").unwrap().entity_object,
        EntityObject::ExternalObjectReference("sign_17".into())
    );
    assert!(
        matches!(&s.entities.object("Trailer").unwrap().entity_object, EntityObject::Vehicle(t) if t.trailer_coupler.is_some())
    );
    let monitors: Vec<(&str, bool)> = s
        .monitor_declarations
        .iter()
        .map(|m| (m.name.as_str(), m.value))
        .collect();
    assert_eq!(monitors, [("Safe", true)]);
    // The only deprecated form in the file is ReachPositionCondition.
    assert_eq!(s.warnings.len(), 1, "{:?}", s.warnings);
    assert!(s.warnings[0]
        .message
        .starts_with("ReachPositionCondition is deprecated"));
}
