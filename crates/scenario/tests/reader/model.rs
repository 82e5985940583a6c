//! The resolved model: deprecated 1.0 forms on the 1.3 model, version warnings, parameter
//! scopes (OpenSCENARIO 1.3 §9.1), entity selections (§7.2.2), ParameterValueDistribution
//! files. Expected values are worked out by hand from the fixtures in `tests/files/`.

use std::path::{Path, PathBuf};

use scenario::{
    ActionKind, ByValueCondition, ConditionKind, ControllerAction, EntityCondition, EntityObject,
    LongitudinalAction, PositionKind, Priority, PrivateAction, RelativeDistanceType, RoutingAction,
    Scenario, Shape,
};

/// Values that pass through decimal text and at most two operations.
const TOL: f64 = 1e-12;

fn fixture(name: &str) -> PathBuf {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/files")).join(name)
}

#[test]
fn deprecated_1_0_forms_read_as_1_3() {
    let s = Scenario::load(&fixture("deprecated_1_0.xosc")).unwrap();
    // Count is an 'integer' (1.0 spelling of int) 3; Half = 3 * 0.5 = 1.5.
    assert!((s.parameter_declarations[1].value.as_f64().unwrap() - 1.5).abs() < TOL);
    let init = &s.storyboard.init.privates[0].actions;
    let ActionKind::Private(PrivateAction::Teleport(p)) = &init[0].kind else {
        panic!()
    };
    // latitude 1.0471975511965976 rad = π/3 = 60°, longitude −π/6 = −30°, height 12 m.
    let PositionKind::Geo {
        latitude_deg,
        longitude_deg,
        altitude,
        ..
    } = p.kind
    else {
        panic!()
    };
    assert!((latitude_deg - 60.0).abs() < 1e-9 && (longitude_deg + 30.0).abs() < 1e-9);
    assert!((altitude.unwrap() - 12.0).abs() < TOL);
    let ActionKind::Private(PrivateAction::Controller(c)) = &init[1].kind else {
        panic!()
    };
    let ControllerAction::Activate { domains, .. } = c.as_ref() else {
        panic!()
    };
    assert_eq!(
        (domains.longitudinal, domains.lateral),
        (Some(true), Some(false))
    );
    let EntityObject::Pedestrian(ped) = &s.entities.object("Ped").unwrap().entity_object else {
        panic!()
    };
    assert_eq!(ped.model3d.as_deref(), Some("walker.osgb"));

    let event = &s.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[0].events[0];
    assert_eq!(event.priority, Priority::Override);
    let ActionKind::Private(PrivateAction::Routing(r)) = &event.actions[0].kind else {
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
    let Shape::Clothoid(cl) = &trajectory.shape else {
        panic!()
    };
    assert!((cl.curvature_prime - 0.001).abs() < TOL && (cl.length - 1.5).abs() < TOL);
    let timing = time_reference.unwrap();
    assert!((timing.scale - 2.0).abs() < TOL && (timing.offset - 0.5).abs() < TOL);
    let condition = &event.start_trigger.as_ref().unwrap().condition_groups[0].conditions[0];
    assert!((condition.delay - 0.5).abs() < TOL);
    let ConditionKind::ByEntity {
        entity_condition, ..
    } = &condition.kind
    else {
        panic!()
    };
    let EntityCondition::RelativeDistance { measure, .. } = entity_condition else {
        panic!()
    };
    assert_eq!(
        measure.relative_distance_type,
        Some(RelativeDistanceType::EuclidianDistance)
    );
}

#[test]
fn deprecated_forms_and_too_new_features_warn_with_their_position() {
    let s = Scenario::load(&fixture("deprecated_1_0.xosc")).unwrap();
    let shown: Vec<String> = s
        .warnings
        .iter()
        .map(|w| format!("{}:{} {}", w.pos.line, w.pos.col, w.message))
        .collect();
    let expect = [
        // Line 5: `<ParameterDeclaration name="Count" parameterType="integer"`, element at col 5.
        "5:5 ParameterDeclaration@parameterType: 'integer' is deprecated, read as 'int'",
        "22:7 Pedestrian@model is deprecated, read as model3d",
        "32:39 GeoPosition@latitude/longitude/height are deprecated (rad), read as latitudeDeg/longitudeDeg/altitude",
        "35:13 PrivateAction/ActivateControllerAction is deprecated, read as ControllerAction/ActivateControllerAction",
        // Line 45: the value of priority starts at col 39.
        "45:39 Event@priority: 'overwrite' is a deprecated literal, read as 'override'",
        "50:23 FollowTrajectoryAction/Trajectory is deprecated, read as TrajectoryRef",
        "52:27 Clothoid@curvatureDot is deprecated, read as curvaturePrime",
        "66:21 SpeedProfileAction needs OpenSCENARIO 1.2, but the file declares 1.0",
    ];
    for e in expect {
        assert!(
            shown.iter().any(|w| w == e),
            "missing warning {e}\nfound:\n{}",
            shown.join("\n")
        );
    }
    assert!(
        shown.iter().any(|w| w.starts_with("78:")
            && w.contains(
                "'cartesianDistance' is a deprecated literal, read as 'euclidianDistance'"
            )),
        "{shown:?}"
    );
}

#[test]
fn inner_declarations_shadow_outer_ones_and_see_them() {
    let s = Scenario::load(&fixture("scopes_and_selections.xosc")).unwrap();
    let maneuver = &s.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[0];
    let event = &maneuver.events[0];
    let ActionKind::Private(PrivateAction::Longitudinal(
        LongitudinalAction::LongitudinalDistance {
            entity_ref,
            distance,
            ..
        },
    )) = &event.actions[0].kind
    else {
        panic!()
    };
    // Story: Speed = 10 * 2 = 20; Maneuver: Gap = 20 + 1 = 21.
    assert!((distance.unwrap() - 21.0).abs() < TOL);
    assert_eq!(entity_ref, "Car2");
    let ConditionKind::ByValue(ByValueCondition::SimulationTime { value, .. }) =
        &event.start_trigger.as_ref().unwrap().condition_groups[0].conditions[0].kind
    else {
        panic!()
    };
    assert!((value - 20.0).abs() < TOL);
    // Outside the story, Speed is the global 10 again.
    let stop = &s.storyboard.stop_trigger.as_ref().unwrap().condition_groups[0].conditions[0];
    let ConditionKind::ByValue(ByValueCondition::SimulationTime { value, .. }) = &stop.kind else {
        panic!()
    };
    assert!((value - 10.0).abs() < TOL);
    assert_eq!(s.variable_declarations[0].name, "Laps");
}

#[test]
fn selections_expand_by_type_and_through_nested_selections() {
    let s = Scenario::load(&fixture("scopes_and_selections.xosc")).unwrap();
    // People = every pedestrian = [Walker]; Everyone = vehicles [Car1, Car2] + People, in
    // declaration order of the objects.
    assert_eq!(s.entities.resolve("People"), ["Walker"]);
    assert_eq!(s.entities.resolve("Everyone"), ["Car1", "Walker", "Car2"]);
    assert_eq!(s.entities.resolve("Car1"), ["Car1"]);
    assert!(s.entities.resolve("Nobody").is_empty());
}

#[test]
fn actions_and_conditions_keep_their_source_position() {
    let s = Scenario::load(&fixture("scopes_and_selections.xosc")).unwrap();
    let event = &s.storyboard.stories[0].acts[0].maneuver_groups[0].maneuvers[0].events[0];
    // `<Action name="InStory">` on line 54 at col 15; `<Condition name="T"` on line 63, col 19.
    assert_eq!(
        (event.actions[0].pos.line, event.actions[0].pos.col),
        (54, 15)
    );
    let c = &event.start_trigger.as_ref().unwrap().condition_groups[0].conditions[0];
    assert_eq!((c.pos.line, c.pos.col), (63, 19));
    assert!(c.pos.file.ends_with("scopes_and_selections.xosc"));
}

#[test]
fn a_parameter_value_distribution_loads_its_scenario_file() {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus/esmini/xosc/cut-in_parameter_set.xosc"
    ));
    let s = Scenario::load(path).unwrap();
    assert_eq!(s.parameter_value_distribution.as_deref(), Some(path));
    assert!(s.path.ends_with("esmini/xosc/cut-in.xosc"));
}

/// semantics-pitfalls.md #10 (scenario_runner #655): `$name` resolves in catalog references'
/// entry names too. esmini's cut-in.xosc references `entryName="$HostVehicle"` with
/// HostVehicle = "car_white", and `--param` overrides reach it.
#[test]
fn pitfall_10_parameters_resolve_in_catalog_entry_names() {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus/esmini/xosc/cut-in.xosc"
    ));
    let s = Scenario::load(path).unwrap();
    let EntityObject::Vehicle(ego) = &s.entities.object("Ego").unwrap().entity_object else {
        panic!()
    };
    assert_eq!(ego.catalog.as_ref().unwrap().entry_name, "car_white");
    assert_eq!(ego.name, "car_white");
    let s =
        Scenario::load_with_parameters(path, &[("HostVehicle".into(), "car_blue".into())]).unwrap();
    let EntityObject::Vehicle(ego) = &s.entities.object("Ego").unwrap().entity_object else {
        panic!()
    };
    assert_eq!(ego.name, "car_blue");
}

#[test]
fn a_catalog_file_is_not_a_scenario() {
    let path = fixture("catalogs/Vehicles/TestVehicles.xosc");
    let err = Scenario::load(&path).unwrap_err();
    assert_eq!(
        err.kind().to_string(),
        "expected a scenario definition or parameter value distribution, found a Catalog"
    );
    // `  <Catalog name="TestVehicles">` on line 4.
    assert_eq!((err.pos().line, err.pos().col), (4, 3));
}

#[test]
fn the_1_2_spelling_of_traffic_signal_group_state_is_read() {
    let s = Scenario::load(&fixture("traffic_signals_1_2.xosc")).unwrap();
    let controller = &s.road_network.traffic_signal_controllers[0];
    assert_eq!(controller.name, "Crossing");
    assert!((controller.delay.unwrap() - 2.5).abs() < TOL);
    let phases: Vec<(&str, f64)> = controller
        .phases
        .iter()
        .map(|p| (p.name.as_str(), p.duration))
        .collect();
    assert_eq!(phases.len(), 2);
    assert!((phases[1].1 - 25.5).abs() < TOL);
    assert_eq!(controller.phases[0].group_state.as_deref(), Some("green"));
    assert_eq!(
        controller.phases[0].signal_states,
        [("1".to_owned(), "off;off;on".to_owned())]
    );
    assert_eq!(s.warnings.len(), 1, "{:?}", s.warnings);
    assert_eq!((s.warnings[0].pos.line, s.warnings[0].pos.col), (10, 11));
}

#[test]
fn a_name_declared_twice_in_one_block_warns_and_the_last_wins() {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus/esmini/xosc/follow_reference.xosc"
    ));
    let s = Scenario::load(path).unwrap();
    // Lines 6 and 9 of follow_reference.xosc both declare lane_change_duration = 2; the
    // warning points at the second name, line 9, column 35.
    let w = s
        .warnings
        .iter()
        .find(|w| {
            w.message
                .contains("'lane_change_duration' is declared twice")
        })
        .unwrap();
    assert_eq!((w.pos.line, w.pos.col), (9, 35));
    let n = s
        .parameter_declarations
        .iter()
        .filter(|p| p.name == "lane_change_duration")
        .count();
    assert_eq!(n, 2);
}

/// 1.0's `alongRoute="true"` ("routing is taken into account") names the coordinate system
/// only: it reads as the 1.3 `coordinateSystem="road"`, and `relativeDistanceType` stays
/// unset, i.e. its 1.3 default `euclidianDistance`; esmini's cut-in_sumo.xosc line 148:
/// `<TimeHeadwayCondition alongRoute="true" entityRef="Target1" freespace="true" …/>`.
#[test]
fn along_route_true_reads_as_the_road_coordinate_system() {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus/esmini/xosc/cut-in_sumo.xosc"
    ));
    let s = Scenario::load(path).unwrap();
    let mut measures = Vec::new();
    for act in &s.storyboard.stories[0].acts {
        for m in act.maneuver_groups.iter().flat_map(|g| &g.maneuvers) {
            for e in &m.events {
                let Some(t) = &e.start_trigger else { continue };
                for c in t.condition_groups.iter().flat_map(|g| &g.conditions) {
                    if let ConditionKind::ByEntity {
                        entity_condition: EntityCondition::TimeHeadway { measure, .. },
                        ..
                    } = &c.kind
                    {
                        measures.push((c.pos.line, *measure));
                    }
                }
            }
        }
    }
    // Its Condition element ("redtrigger") starts on line 142.
    let (_, measure) = measures.iter().find(|(line, _)| *line == 142).unwrap();
    assert_eq!(
        measure.coordinate_system,
        Some(scenario::CoordinateSystem::Road)
    );
    assert_eq!(measure.relative_distance_type, None);
    assert!(measure.freespace);
    let w = s
        .warnings
        .iter()
        .find(|w| w.message.contains("alongRoute"))
        .unwrap();
    assert_eq!(
        w.message,
        "TimeHeadwayCondition@alongRoute=\"true\" is deprecated, read as coordinateSystem=\"road\" (relativeDistanceType keeps its default)"
    );
    assert_eq!(w.pos.line, 148);
}

/// The esmini habits accepted for its corpus (reader/compat.rs, reader/resolve.rs), each
/// with a warning where it departs from the standard.
#[test]
fn esmini_compatibility_forms() {
    let corpus = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus/esmini/xosc"
    ));
    // traffic_lights.xosc line 285: `value="${$RedLightDistance - 6}"` with the *string*
    // parameter RedLightDistance = "50": read as the number 50, so 50 − 6 = 44.
    let s = Scenario::load(&corpus.join("traffic_lights.xosc")).unwrap();
    let mut found = None;
    for story in &s.storyboard.stories {
        for act in &story.acts {
            for m in act.maneuver_groups.iter().flat_map(|g| &g.maneuvers) {
                for e in &m.events {
                    for a in &e.actions {
                        if a.name == "StopOnYellowAction" {
                            found = Some(a.kind.clone());
                        }
                    }
                }
            }
        }
    }
    let Some(ActionKind::Private(PrivateAction::Longitudinal(LongitudinalAction::Speed {
        dynamics,
        ..
    }))) = found
    else {
        panic!("{found:?}")
    };
    assert!((dynamics.value - 44.0).abs() < TOL);
    assert!(s.warnings.iter().any(|w| w.pos.line == 285
        && w.message == "SpeedActionDynamics@value: a string parameter holding a number is used as a number"));

    // cut-in.xosc line 162: `<Condition name="${BrakeCondition_HWT + _ + $HeadwayTime_Brake}"`
    // is no 1.3 expression; the name is kept as written.
    let s = Scenario::load(&corpus.join("cut-in.xosc")).unwrap();
    let w = s
        .warnings
        .iter()
        .find(|w| w.message.starts_with("Condition@name kept as written"))
        .unwrap();
    assert_eq!(w.pos.line, 162);
}
