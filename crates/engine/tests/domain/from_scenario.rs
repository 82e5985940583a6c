//! Mapping OpenSCENARIO 1.x entities onto the 2.0 §8.7 actors (`from_scenario` module table),
//! checked on esmini corpus scenarios against the values written in their XML.

use engine::domain::{Actor, DomainErrorKind, IntendedInfrastructure, Physical, VehicleCategory};
use opendrive::Pose;
use scenario::Scenario;

fn load(name: &str) -> Scenario {
    let path = crate::corpus::corpus(&format!("esmini/xosc/{name}"));
    Scenario::load(&path).expect("corpus scenario loads")
}

fn actor(s: &Scenario, name: &str, pose: Pose) -> Actor {
    let object = s.entities.object(name).expect("entity declared");
    Actor::from_scenario(object, pose).expect("mappable entity")
}

#[test]
fn vehicle_from_catalog() {
    // pedestrian.xosc: Ego is VehicleCatalog entry car_white: vehicleCategory car,
    // model3d ../models/car_white.osgb, BoundingBox centre (1.4, 0, 0.75), length 5.04,
    // width 2.0, height 1.5; FrontAxle positionX 2.98, RearAxle 0, both maxSteering
    // 0.523598775598, wheelDiameter 0.8, trackWidth 1.68, positionZ 0.4.
    let s = load("pedestrian.xosc");
    let pose = Pose {
        x: 1.0,
        y: 2.0,
        h: 0.5,
        ..Pose::default()
    };
    let Actor::Vehicle(v) = actor(&s, "Ego", pose) else {
        panic!("Ego is a vehicle")
    };
    assert_eq!(v.vehicle_category, VehicleCategory::Car);
    assert_eq!(v.intended_infrastructure, [IntendedInfrastructure::Driving]);
    assert_eq!(
        v.geometry_reference.as_deref(),
        Some("../models/car_white.osgb")
    );
    let bb = v.bounding_box;
    assert_eq!((bb.length(), bb.width(), bb.height()), (5.04, 2.0, 1.5));
    assert_eq!(bb.center().x, 1.4);
    assert_eq!(v.center_of_gravity, bb.center());
    assert_eq!(v.pose, pose);
    let xs: Vec<f64> = v.axles.iter().map(|a| a.position_x).collect();
    assert_eq!(xs, [2.98, 0.0]);
    assert!(v
        .axles
        .iter()
        .all(|a| a.number_of_wheels == 2 && a.track_width == 1.68));
    // Rear overhang: rear axle at 0, box rear at 1.4 − 5.04/2 = −1.12 → 1.12 m.
    assert!(
        (v.rear_overhang - 1.12).abs() < 1e-12,
        "{}",
        v.rear_overhang
    );
    assert!(v.color.is_none());
}

#[test]
fn pedestrian_and_misc_object() {
    // pedestrian.xosc: pedestrian_adult, pedestrianCategory pedestrian, centre (0.06, 0,
    // 0.923), length 0.6, width 0.5, height 1.8.
    let s = load("pedestrian.xosc");
    let Actor::Person(p) = actor(&s, "pedestrian_adult", Pose::default()) else {
        panic!("a pedestrian is a person")
    };
    assert_eq!(
        p.intended_infrastructure,
        [IntendedInfrastructure::Sidewalk]
    );
    let bb = p.bounding_box;
    assert_eq!(
        (bb.length(), bb.width(), bb.height(), bb.center().z),
        (0.6, 0.5, 1.8, 0.923)
    );
    // alks_cut-out.xosc: entity Box (MiscObject box), miscObjectCategory obstacle → movable, length 2, width 1,
    // height 1.2, at rest.
    let s = load("alks_cut-out.xosc");
    let a = actor(
        &s,
        "Box",
        Pose {
            x: 3.0,
            ..Pose::default()
        },
    );
    let Actor::MovableObject(m) = &a else {
        panic!("an obstacle is movable")
    };
    assert_eq!(
        (m.bounding_box.length(), m.bounding_box.width()),
        (2.0, 1.0)
    );
    assert_eq!(m.speed(), 0.0);
    assert_eq!(a.physical_object().pose.x, 3.0);
    assert!(a.traffic_participant().is_none());
}

#[test]
fn invalid_bounding_box_is_an_error() {
    let s = load("pedestrian.xosc");
    let mut object = s
        .entities
        .object("pedestrian_adult")
        .expect("declared")
        .clone();
    if let scenario::EntityObject::Pedestrian(p) = &mut object.entity_object {
        p.bounding_box.width = -0.5;
    }
    let err = Actor::from_scenario(&object, Pose::default()).expect_err("negative width");
    assert!(matches!(
        err.kind(),
        DomainErrorKind::InvalidParameter {
            name: "bounding_box.width",
            ..
        }
    ));
}
