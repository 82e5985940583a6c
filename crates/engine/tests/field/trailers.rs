//! Class 6 — a trailer connected during the run (OpenSCENARIO 1.3 §7.2.2.6 "Trailer modeling",
//! ConnectTrailerAction) and vehicles with more than two axles or a steering rear axle
//! (AdditionalAxle; `trajectory::max_curvature`).
//!
//! Fixture `trailer_connect.xosc`: Truck (hitch 1 m behind its rear axle) at 10 m/s along
//! +x on lane -1 (y = -1.535) from x = 50; at t = 1 s it connects Trailer (coupler 5 m ahead
//! of its axle). From then on the coupler sits on the hitch (`runtime::trailer`): on a straight
//! line the trailer's axle is at x_truck − 1 − 5, heading 0, moving at the truck's speed.

use crate::support::run;

/// Straight line: closed forms up to round-off.
const POS_TOL: f64 = 1e-6;

#[test]
fn a_trailer_connected_to_a_moving_tow_follows_its_hitch() {
    // Trailer at s = 54: its coupler (59) is at the hitch when Truck (60) connects it.
    let (_, rows, _) = run("trailer_connect.xosc", &[]);
    // Before: it stands.
    let before = rows.at("Trailer", 0.5);
    assert!(
        (before.x - 54.0).abs() < POS_TOL && before.speed.abs() < POS_TOL,
        "{before:?}"
    );
    // t = 3 s: Truck at 50 + 30 = 80, hitch at 79, trailer axle at 74.
    let truck = rows.at("Truck", 3.0);
    let trailer = rows.at("Trailer", 3.0);
    assert!((truck.x - 80.0).abs() < POS_TOL, "{truck:?}");
    assert!((trailer.x - 74.0).abs() < POS_TOL, "{trailer:?}");
    assert!(
        (trailer.y + 1.535).abs() < POS_TOL && trailer.h.abs() < POS_TOL,
        "{trailer:?}"
    );
    assert!((trailer.speed - 10.0).abs() < POS_TOL, "{trailer:?}");
    // Standing 10 m further back (s = 44) it is pulled up to the hitch at once: the same.
    let (_, rows, _) = run("trailer_connect.xosc", &[("TrailerS", "44")]);
    let trailer = rows.at("Trailer", 3.0);
    assert!((trailer.x - 74.0).abs() < POS_TOL, "{trailer:?}");
}

fn axle(x: f64, steering: f64) -> scenario::Axle {
    scenario::Axle {
        max_steering: steering,
        wheel_diameter: 0.8,
        track_width: 2.0,
        position_x: x,
        position_z: 0.4,
    }
}

/// Within floating-point evaluation of tan and √.
const CURVATURE_TOL: f64 = 1e-12;

#[test]
fn a_tandem_axle_moves_the_turning_centre_and_bounds_the_curvature() {
    use engine::trajectory::max_curvature;
    // Two axles: front at 4.0 m steering 0.5 rad, rear at 0: tan 0.5 / 4 = 0.136575.
    let mut axles = scenario::Axles {
        front_axle: Some(axle(4.0, 0.5)),
        rear_axle: axle(0.0, 0.0),
        additional_axles: Vec::new(),
    };
    let two = max_curvature(&axles).expect("steers");
    assert!((two - 0.5f64.tan() / 4.0).abs() < CURVATURE_TOL, "{two}");
    // A non-steering AdditionalAxle 1.3 m behind the rear one (a tandem): the turning
    // centre's line moves to their mean, x_c = −0.65; on it κ_c = tan 0.5 / 4.65 = 0.117484;
    // the reference point (x = 0) runs at √(R² + 0.65²): κ = κ_c / √(1 + (0.65 κ_c)²) =
    // 0.117143 1/m, a wider circle than the two-axle truck's.
    axles.additional_axles.push(axle(-1.3, 0.0));
    let kc = 0.5f64.tan() / 4.65;
    let expected = kc / (1.0 + (0.65 * kc).powi(2)).sqrt();
    let three = max_curvature(&axles).expect("steers");
    assert!(
        (three - expected).abs() < CURVATURE_TOL,
        "{three} {expected}"
    );
    assert!((three - 0.117143).abs() < 1e-6, "{three}");
    // A second steering axle at 2.8 m limited to 0.3 rad: tan 0.3 / 3.45 = 0.089589 <
    // 0.117484 on the centre's line: it is the tighter bound.
    axles.additional_axles.push(axle(2.8, 0.3));
    let kc = 0.3f64.tan() / 3.45;
    let expected = kc / (1.0 + (0.65 * kc).powi(2)).sqrt();
    let four = max_curvature(&axles).expect("steers");
    assert!((four - expected).abs() < CURVATURE_TOL, "{four} {expected}");
}
