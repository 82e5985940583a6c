//! OpenSCENARIO 2.0 §8.7 actor types and enums: the colour table (§8.7.11), speed (§8.7.4),
//! bounding-box validation (§8.7.9), rear overhang (§8.7.6) and the stationary location
//! (§8.7.3.1.1).

use engine::domain::{
    Actor, Axle, BoundingBox, Color, DomainErrorKind, MovableObject, Physical, PhysicalObject,
    Position3d, StationaryObject, TrafficParticipant, Vector3, Vehicle, VehicleCategory,
};
use opendrive::Pose;

#[test]
fn color_table_follows_w3c() {
    // W3C HTML 4.01 basic colour keywords (CSS Color 3 §4.1), the set §8.7.11 names.
    let w3c: [(&str, [u8; 3]); 16] = [
        ("white", [255, 255, 255]),
        ("silver", [192, 192, 192]),
        ("gray", [128, 128, 128]),
        ("black", [0, 0, 0]),
        ("red", [255, 0, 0]),
        ("maroon", [128, 0, 0]),
        ("yellow", [255, 255, 0]),
        ("olive", [128, 128, 0]),
        ("lime", [0, 255, 0]),
        ("green", [0, 128, 0]),
        ("aqua", [0, 255, 255]),
        ("teal", [0, 128, 128]),
        ("blue", [0, 0, 255]),
        ("navy", [0, 0, 128]),
        ("fuchsia", [255, 0, 255]),
        ("purple", [128, 0, 128]),
    ];
    for (i, (name, rgb)) in w3c.iter().enumerate() {
        let c = Color::from_name(name).expect("every W3C basic colour is a §8.7.11 value");
        assert_eq!(c, Color::ALL[i], "seed order");
        assert_eq!(c.rgb(), *rgb, "{name}");
        assert_eq!(c.name(), *name);
        assert_eq!(Color::from_rgb(*rgb), Some(c), "{name} round trip");
    }
    // The seed prints fuchsia = RGB(255,255,0) and purple = RGB(255,0,255); oscsim does not.
    assert_ne!(Color::Fuchsia.rgb(), Color::Yellow.rgb());
    assert_eq!(Color::Purple.rgb(), [128, 0, 128]);
    assert_eq!(Color::from_rgb([255, 255, 0]), Some(Color::Yellow));
    assert_eq!(Color::from_name("pink"), None);
}

fn movable(vx: f64, vy: f64) -> MovableObject {
    let bb = BoundingBox::new(Position3d::new(0.0, 0.0, 0.5), 1.0, 1.0, 1.0).expect("valid");
    let mut m = MovableObject::new(PhysicalObject::new(bb, Pose::default()));
    m.velocity.translational = Vector3::new(vx, vy, 0.0);
    m
}

#[test]
fn speed_is_signed_planar_magnitude() {
    // §8.7.4: sqrt(vx² + vy²) · sign(vx). (3, 4) → 5; (−3, 4) → −5; (0, −2) → 2 with
    // sign(0) = +1 (documented choice); vz does not count.
    let cases = [
        (3.0, 4.0, 5.0),
        (-3.0, 4.0, -5.0),
        (0.0, -2.0, 2.0),
        (0.0, 0.0, 0.0),
    ];
    for (vx, vy, expected) in cases {
        let mut m = movable(vx, vy);
        m.velocity.translational.z = 7.0;
        assert!(
            (m.speed() - expected).abs() < 1e-12,
            "({vx}, {vy}): {}",
            m.speed()
        );
    }
}

#[test]
fn bounding_box_rejects_bad_dimensions() {
    for (l, w, h, name) in [
        (-1.0, 2.0, 1.5, "bounding_box.length"),
        (4.0, f64::NAN, 1.5, "bounding_box.width"),
        (4.0, 2.0, f64::INFINITY, "bounding_box.height"),
    ] {
        let err = BoundingBox::new(Position3d::default(), l, w, h).expect_err("invalid");
        match err.kind() {
            DomainErrorKind::InvalidParameter { name: n, .. } => assert_eq!(*n, name),
            other => panic!("unexpected kind {other:?}"),
        }
    }
    let err = BoundingBox::new(Position3d::default(), -1.0, 2.0, 1.5).expect_err("invalid");
    assert_eq!(
        err.to_string(),
        "expected bounding_box.length to be a finite length >= 0 m, found -1"
    );
    let err = BoundingBox::new(Position3d::new(f64::NAN, 0.0, 0.0), 1.0, 1.0, 1.0)
        .expect_err("invalid centre");
    assert!(err
        .to_string()
        .starts_with("expected bounding_box.center.x to be a finite"));
}

fn axle(position_x: f64) -> Axle {
    Axle {
        max_steering: 0.5,
        wheel_diameter: 0.6,
        track_width: 1.6,
        position_x,
        position_z: 0.3,
        number_of_wheels: 2,
    }
}

#[test]
fn vehicle_rear_overhang_from_box_and_rear_axle() {
    // esmini's car_white: box centre x = 1.4, length 5.04 → rear end at 1.4 − 2.52 = −1.12;
    // rear axle at x = 0 → rear overhang 1.12 m.
    let bb = BoundingBox::new(Position3d::new(1.4, 0.0, 0.9), 5.04, 2.0, 1.8).expect("valid");
    let p = TrafficParticipant::new(
        MovableObject::new(PhysicalObject::new(bb, Pose::default())),
        vec![],
    );
    let v = Vehicle::new(p.clone(), VehicleCategory::Car, vec![axle(2.98), axle(0.0)])
        .expect("box reaches behind the rear axle");
    assert!(
        (v.rear_overhang - 1.12).abs() < 1e-12,
        "{}",
        v.rear_overhang
    );
    // An axle 2 m behind the box's rear end: the box ends ahead of the rear axle.
    let err = Vehicle::new(p, VehicleCategory::Trailer, vec![axle(-3.12)]).expect_err("negative");
    assert!(matches!(
        err.kind(),
        DomainErrorKind::InvalidParameter {
            name: "rear_overhang",
            ..
        }
    ));
}

#[test]
fn stationary_object_keeps_its_location_and_has_no_velocity() {
    let bb = BoundingBox::new(Position3d::default(), 1.0, 1.0, 1.0).expect("valid");
    let location = Pose {
        x: 5.0,
        y: 6.0,
        h: 1.0,
        ..Pose::default()
    };
    let s = StationaryObject::location(PhysicalObject::new(bb, Pose::default()), location);
    assert_eq!(s.pose, location);
    assert_eq!(s.velocity(), engine::domain::Velocity6d::ZERO);
    let actor = Actor::StationaryObject(s);
    assert!(actor.movable_object().is_none() && actor.traffic_participant().is_none());
    assert_eq!(actor.physical_object().pose, location);
    let mut moving = Actor::MovableObject(movable(1.0, 0.0));
    moving
        .movable_object_mut()
        .expect("movable")
        .velocity
        .translational
        .x = 2.0;
    assert!((moving.velocity().translational.x - 2.0).abs() < 1e-12);
}
