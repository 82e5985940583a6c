//! Issue 34 — equivalents of ASAM's OpenSCENARIO 1.2/1.3 examples, written for this project:
//! the ASAM example files carry no licence statement for redistribution (only ASAM's licence
//! terms for the standard), so they are not copied into the repository. Each equivalent keeps
//! the constructs its example depends on, on a stand-in road with the example road's lane
//! layout (`rq31_straight.xodr`), with the motion worked out by hand. The examples that did
//! not run have their own equivalents elsewhere: SlowPrecedingVehicle (`init_together`),
//! SimpleOvertake (`empty_elements`), SlowPrecedingVehicleDeterministicParameterSet (a
//! distribution varying the road file: batch test `road_choice`).
//!
//! `asam_cut_in.xosc` (after CutIn): Ego on lane −3 (centre t = −8.45) at s = 1000, offset
//! 0.5, 27.778 m/s; A1 placed by RelativeLanePosition (dLane 0, ds 84) and A2 (dLane 1,
//! ds −100: lane −2, centre t = −4.55) from Ego's placement, A2 at 30.556 m/s. A2's cut-in
//! starts on the rising edge of DistanceCondition > 20 m (road coordinates, default
//! relativeDistanceType euclidianDistance: d = √(Δs² + Δt²), Δt = 3.4 m) to Ego, and changes
//! to Ego's lane (RelativeTargetLane value 0) at offset −0.05 over 55 m.

use engine::storyboard::Transition;

use crate::support::{run, transitions};

/// A straight road along +x: closed forms up to round-off.
const POS_TOL: f64 = 1e-6;
/// Step times are sums of dt = 0.05 s.
const TIME_TOL: f64 = 1e-9;

#[test]
fn cut_in_equivalent_places_relative_to_ego_and_cuts_in_on_the_rising_edge() {
    let (_, rows, events) = run("asam_cut_in.xosc", &[]);
    // Init: x = s, y = t on this road.
    let at0 = |name: &str| {
        let r = rows.at(name, 0.0);
        (r.x, r.y)
    };
    for (name, (x, y)) in [
        ("Ego", (1000.0, -8.45 + 0.5)),
        ("A1", (1084.0, -8.45)),
        ("A2", (900.0, -4.55)),
    ] {
        let (rx, ry) = at0(name);
        assert!(
            (rx - x).abs() < POS_TOL && (ry - y).abs() < POS_TOL,
            "{name}: {rx} {ry}"
        );
    }
    // Δs(t) = −100 + (30.556 − 27.778)·t = −100 + 2.778·t. The Act starts at 0.05 s and the
    // Event's first evaluation only records its value (d = 100.06 m > 20: true, no edge); d
    // falls below 20 m when |Δs| < √(20² − 3.4²) = 19.709 m and rises above it again when
    // Δs > 19.709, t > 119.709 / 2.778 = 43.092 s: the first step is 43.10 s
    // (Δs(43.05) = 19.593, Δs(43.10) = 19.732).
    let start = transitions(&events, "CutIn", Transition::Start);
    assert_eq!(start.len(), 1, "{start:?}");
    assert!((start[0] - 43.10).abs() < TIME_TOL, "{start:?}");
    // Until then A2 keeps its lane and speed: x = 900 + 30.556·43.10 = 2216.9636.
    let before = rows.at("A2", 43.10);
    assert!((before.x - 2216.9636).abs() < POS_TOL && (before.y + 4.55).abs() < POS_TOL);
    // 55 m along the road at 30.556 m/s along the path take 1.80 s and a little more (the
    // path is longer than the road by the sideways motion): the change ends in the step that
    // reaches 55 m, no earlier than 43.10 + 1.80 = 44.90 s.
    let end = transitions(&events, "CutIn", Transition::End);
    assert_eq!(end.len(), 1, "{end:?}");
    assert!(
        end[0] >= 44.90 - TIME_TOL && end[0] <= 45.0 + TIME_TOL,
        "{end:?}"
    );
    // Then A2 is in Ego's lane at offset −0.05: y = −8.45 − 0.05 = −8.5.
    for t in [45.0, 48.0] {
        assert!((rows.at("A2", t).y + 8.5).abs() < POS_TOL);
    }
}
