//! Issue 34 — equivalents of ASAM's OpenSCENARIO 1.2/1.3 examples that overtake by lane changes
//! (DoubleLaneChanger, Overtaker, FastOvertakeWithReInitialization), written for this project
//! on the RQ 31 stand-in road along +x (`rq31_straight.xodr`: lane −2's centre at t = −4.55,
//! lane −3's at −8.45; x = s, y = t). The ASAM files are not copied (no licence statement for
//! redistribution); each fixture's comment says what it keeps of its example.
//!
//! Readings these examples rest on (OpenSCENARIO 1.3):
//! - An Act without StartTrigger (XSD 1.2/1.3 Act: StartTrigger minOccurs="0") starts with its
//!   Story, at the storyboard's start.
//! - RelativeDistanceCondition and DistanceCondition compare the distance's magnitude (§6.4:
//!   distances are ≥ 0), so "more than 5 m ahead" is also "more than 5 m behind": the
//!   examples rely on the rising edge, which the first evaluation never gives (it only
//!   records the value; the 1.0 User Guide: edged conditions are false when first checked).
//! - A LaneChangeAction with `dynamicsDimension="time"` keeps the speed along the path, so the
//!   sideways motion costs distance along the road: for the sinusoid Δ·(1 − cos(πτ/T))/2 at
//!   speed v, ∫(v − √(v² − ẏ²))dτ ≈ Δ²π²/(16·T·v) (first order in (ẏ/v)²).
//! - A TeleportAction started in a Story takes its target from the entities as the step
//!   began and shows it in that step's frame (the next row); a step SpeedAction in the same
//!   Event moves the entity from the next step on.

use engine::storyboard::Transition;

use crate::support::{run, transitions};

/// Closed forms along a straight road, up to round-off (and the engine's 6-digit inputs).
const POS_TOL: f64 = 1e-6;
/// The first-order estimate of the distance a sideways sinusoid costs (see the module doc)
/// is good to (ẏ/v)⁴ terms: under 1 mm at these speeds.
const LOSS_TOL: f64 = 1e-3;
/// Step times are sums of dt = 0.05 s.
const TIME_TOL: f64 = 1e-9;

/// Road distance a time-based sinusoidal lane change of `delta` m in `t` s at speed `v` costs.
fn lane_change_loss(delta: f64, t: f64, v: f64) -> f64 {
    delta * delta * std::f64::consts::PI.powi(2) / (16.0 * t * v)
}

#[test]
fn double_lane_changer_equivalent_cuts_in_front_of_ego_and_back_out() {
    let (_, rows, events) = run("asam_double_lane_changer.xosc", &[]);
    let at = |name: &str, t: Transition| transitions(&events, name, t);
    // The Act has no StartTrigger: it, its group and maneuver start at 0 with the storyboard.
    assert!((at("MyAct", Transition::Start)[0]).abs() < TIME_TOL);
    // Δ = x_A1 − x_Ego = −13.5 + (47.222 − 36.111)·t = −13.5 + 11.111·t. At 0 |Δ| = 13.5 > 5
    // (recorded, no edge); |Δ| ≤ 5 from 0.77 s; Δ > 5 once t > 18.5 / 11.111 = 1.665 s: the
    // rising edge at 1.70 s (Δ(1.65) = 4.83, Δ(1.70) = 5.39).
    let right = at("RightAction", Transition::Start);
    assert_eq!(right.len(), 1, "{right:?}");
    assert!((right[0] - 1.70).abs() < TIME_TOL, "{right:?}");
    let x0 = 986.5 + 47.222 * 1.70;
    assert!((rows.at("A1", 1.70).x - x0).abs() < POS_TOL);
    // 2 s to lane −3 (RelativeTargetLane −1 from A1 itself: its right), sinusoidal: halfway
    // at 2.70 s, y = −4.55 − 3.9/2 = −6.5. The end time 3.70 s is reached in the step that
    // starts at 3.65 s; the left change starts when the next step's triggers see
    // completeState, 3.70 s, and ends the same way at 5.65 s.
    assert!((rows.at("A1", 2.70).y + 6.5).abs() < POS_TOL);
    assert!((at("RightAction", Transition::End)[0] - 3.65).abs() < TIME_TOL);
    assert!((rows.at("A1", 3.70).y + 8.45).abs() < POS_TOL);
    assert!((at("LeftAction", Transition::Start)[0] - 3.70).abs() < TIME_TOL);
    assert!((at("LeftAction", Transition::End)[0] - 5.65).abs() < TIME_TOL);
    // Back in lane −2 at 6 s, behind the straight line by the two changes' cost:
    // 2 · 3.9²·π²/(16 · 2 · 47.222) = 2 · 0.0993 = 0.199 m.
    let r = rows.at("A1", 6.0);
    let loss = 2.0 * lane_change_loss(3.9, 2.0, 47.222);
    assert!((r.y + 4.55).abs() < POS_TOL);
    assert!(
        (r.x - (986.5 + 47.222 * 6.0 - loss)).abs() < LOSS_TOL,
        "{} vs {}",
        r.x,
        986.5 + 47.222 * 6.0 - loss
    );
    // Stop: A1 to A2 (A2 70 m ahead of Ego at 36.111): Δ₂ = −83.5 + 11.111·t − 0.199 > 50
    // once t > 133.699 / 11.111 = 12.033 s: the rising edge at 12.05 s.
    let stop = at("storyBoard", Transition::Stop);
    assert_eq!(stop.len(), 1, "{stop:?}");
    assert!((stop[0] - 12.05).abs() < TIME_TOL, "{stop:?}");
}

#[test]
fn overtaker_equivalent_passes_ego_on_the_left_and_returns() {
    let (_, rows, events) = run("asam_overtaker.xosc", &[]);
    let at = |name: &str, t: Transition| transitions(&events, name, t);
    // Δ = x_A1 − x_Ego = −79 + (41.667 − 36.111)·t = −79 + 5.556·t; |Δ| < 30 once
    // t > 49 / 5.556 = 8.820 s: 8.85 s (Δ(8.80) = −30.11, Δ(8.85) = −29.83).
    assert!((at("LeftAction", Transition::Start)[0] - 8.85).abs() < TIME_TOL);
    // 5 s: 13.85 s reached in the step that starts at 13.80 s.
    assert!((at("LeftAction", Transition::End)[0] - 13.80).abs() < TIME_TOL);
    assert!((rows.at("A1", 14.0).y + 4.55).abs() < POS_TOL);
    // "More than 5 m" held from the first evaluation (79 m: no edge), fell at Δ ≥ −5
    // (13.3 s) and rises once Δ > 5: −79 + 5.556·t − L > 5 with L the change's cost,
    // 3.9²·π²/(16 · 5 · 41.667) = 0.045 m: t > 84.045 / 5.556 = 15.127 s: 15.15 s.
    let loss = lane_change_loss(3.9, 5.0, 41.667);
    assert!((loss - 0.045).abs() < 5e-4, "{loss}");
    assert!((at("RightAction", Transition::Start)[0] - 15.15).abs() < TIME_TOL);
    let x = rows.at("A1", 15.15).x;
    assert!(
        (x - (1000.0 + 41.667 * 15.15 - loss)).abs() < LOSS_TOL,
        "{x}"
    );
    assert!((at("RightAction", Transition::End)[0] - 20.10).abs() < TIME_TOL);
    // The stop trigger: the lateral distance from A1 to Ego in A1's frame,
    // −sin h·Δx + cos h·Δy, with h the heading of the path (sin h = ẏ/v), falls to 0.5 m
    // during the change back. Worked from the closed forms (offset
    // 3.9·(1 + cos(πτ/5))/2, τ = t − 15.15, Δx = x_Ego − x_A1): at 19.50 s offset 0.1604,
    // h = −0.0117, Δx = −24.9: 0.502 m (still > 0.5); at 19.55 s offset 0.1369: 0.457 m.
    // Falling edge at 19.55 s, delay 10 s: the storyboard stops at 29.55 s.
    let offset = |t: f64| {
        let tau = t - 15.15;
        3.9 * (1.0 + (std::f64::consts::PI * tau / 5.0).cos()) / 2.0
    };
    for t in [19.50, 19.55] {
        let r = rows.at("A1", t);
        assert!((r.y - (-8.45 + offset(t))).abs() < POS_TOL, "{t}: {}", r.y);
    }
    let stop = at("storyBoard", Transition::Stop);
    assert_eq!(stop.len(), 1, "{stop:?}");
    assert!((stop[0] - 29.55).abs() < TIME_TOL, "{stop:?}");
}

#[test]
fn fast_overtake_equivalent_reinitialises_a2_behind_a1_in_a_story() {
    let (_, rows, events) = run("asam_fast_overtake.xosc", &[]);
    let at = |name: &str, t: Transition| transitions(&events, name, t);
    // Ego closes on A1 at 36.111 − 25 = 11.111 m/s from 121 m: closer than 60 m once
    // t > 61 / 11.111 = 5.490 s: 5.50 s (distance 60.45 at 5.45, 59.89 at 5.50).
    assert!((at("MyReduceSpeedAction", Transition::Start)[0] - 5.50).abs() < TIME_TOL);
    // 25 → 16.667 m/s in 4 s: 2.0833 m/s² (0.10417 m/s a step), the end reached in the step
    // that starts at 9.45 s.
    assert!((at("MyReduceSpeedAction", Transition::End)[0] - 9.45).abs() < TIME_TOL);
    // The startTransition is seen by Act 2's Event in the same trigger stage (it comes after
    // Act 1): 5.50 + 2 s delay = 7.50 s.
    assert!((at("SetUpA2", Transition::Start)[0] - 7.50).abs() < TIME_TOL);
    // A1 at 7.50 s: 1121 + 25·5.5 + 0.05·Σ_{k=1..40}(25 − 0.10417·k) = 1258.5 + 45.729
    // = 1304.229 m (each step moves at the speed it ends with).
    let dv = (25.0 - 50.0 / 3.0) / 80.0;
    let x_a1 = 1121.0 + 25.0 * 5.5 + 0.05 * (40.0 * 25.0 - dv * 820.0);
    assert!((rows.at("A1", 7.50).x - x_a1).abs() < POS_TOL);
    // A2 re-initialised 200 m behind A1, one lane to its left (lane −2), heading 0 from the
    // absolute Orientation (it stood on lane 2 facing −x), shown in the next frame.
    let r = rows.at("A2", 7.55);
    assert!((r.x - (x_a1 - 200.0)).abs() < POS_TOL && (r.y + 4.55).abs() < POS_TOL);
    assert!(r.h.abs() < POS_TOL && (r.speed - 55.556).abs() < POS_TOL);
    assert!((rows.at("A2", 7.50).x - 100.0).abs() < POS_TOL);
    // A1 at 9.50 s: 1258.5 + 0.05·Σ_{k=1..80}(25 − 0.10417·k) = 1341.625 m, then 16.667 m/s.
    // Δ = x_A2 − x_A1 = (x_a1 − 200 + 55.556·(t − 7.55)) − (1341.625 + 16.667·(t − 9.5))
    // reaches 500 at t = 25.676 s: the rising edge at 25.70 s (Δ(25.65) = 499.0). From the
    // first evaluation to the teleport A2 stood 1021 m away on the other carriageway (≥ 500:
    // recorded, no edge).
    let x_a1_end = 1258.5 + 0.05 * (80.0 * 25.0 - dv * 3240.0);
    assert!((rows.at("A1", 9.50).x - x_a1_end).abs() < POS_TOL);
    let gap = |t: f64| (x_a1 - 200.0 + 55.556 * (t - 7.55)) - (x_a1_end + 50.0 / 3.0 * (t - 9.5));
    assert!(gap(25.65) < 500.0 && gap(25.70) >= 500.0);
    let stop = at("storyBoard", Transition::Stop);
    assert_eq!(stop.len(), 1, "{stop:?}");
    assert!((stop[0] - 25.70).abs() < TIME_TOL, "{stop:?}");
}
