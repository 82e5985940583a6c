//! `avoid_collisions(true)`: the engine's IDM car following drives the actor in its phase
//! (`avoid_collisions.osc`, IDM's equations and the hand-worked values in its comment).

use crate::support::{run, DT};

/// How close the follower is to the IDM equilibrium after 50 s (m, m/s): the approach from
/// 96 m at 10 m/s closing speed settles from above without overshoot, the residue decaying
/// (2.3 cm and 4 mm/s left at 50 s in this run); small beside the 68 m the gap closes by.
const SETTLED_GAP: f64 = 0.05;
const SETTLED_SPEED: f64 = 0.01;

#[test]
fn avoid_collisions_follows_a_slower_lead_at_the_idm_equilibrium_gap() {
    let r = run("avoid_collisions", 0, None);
    // Boxes: front 3.5 m, rear 0.5 m ahead of / behind the reference points.
    let gap = |t: f64| (r.at(t, "lead").s - 0.5) - (r.at(t, "ego").s + 3.5);
    assert!((gap(0.0) - 96.0).abs() < 1e-9, "gap(0) = {}", gap(0.0));
    // The first step: IDM's −1.908 m/s² at t = 0 (worked in the file) over dt.
    let a0 = 0.73 * (-(155.2117 / 96.0_f64).powi(2));
    let v1 = r.at(DT, "ego").speed;
    assert!(
        (v1 - (25.0 + a0 * DT)).abs() < 1e-3,
        "ego v({DT}) = {v1}, a0 {a0}"
    );
    // Never closer than the equilibrium gap by more than the tolerance: no collision.
    for (t, _) in &r.frames {
        assert!(gap(*t) > 27.869 - SETTLED_GAP, "gap {} at {t}", gap(*t));
    }
    let (lead, ego) = (r.at(50.0, "lead"), r.at(50.0, "ego"));
    // Lead has no modifier: its plan, 15 m/s from 200 m.
    assert!((lead.s - 950.0).abs() < 1e-9, "lead s(50) = {}", lead.s);
    assert!(
        (gap(50.0) - 27.869).abs() < SETTLED_GAP,
        "gap(50) = {}",
        gap(50.0)
    );
    assert!(
        (ego.speed - 15.0).abs() < SETTLED_SPEED,
        "ego v(50) = {}",
        ego.speed
    );
}

#[test]
fn avoid_collisions_ends_with_its_phase() {
    let r = run("avoid_collisions_ends", 0, None);
    let (a, b) = (r.at(30.0, "ego"), r.at(50.0, "ego"));
    // Settling under the IDM until 30 s: still above lead's speed.
    assert!(a.speed > 15.0 + SETTLED_SPEED, "ego v(30) = {}", a.speed);
    assert!(
        (b.speed - a.speed).abs() < 1e-9,
        "v(30) {} v(50) {}",
        a.speed,
        b.speed
    );
    assert!(
        (b.s - (a.s + 20.0 * a.speed)).abs() < 1e-6,
        "s(30) {} s(50) {}",
        a.s,
        b.s
    );
}

/// How close a walker stopping behind one standing is to s0 after 60 s (m): the gap decays
/// towards s0 from above; 2 cm is small beside the 19 m it closes by.
const STOPPED_GAP: f64 = 0.02;
/// The first step's speed against the IDM at t = 0 held over dt (m/s): round-off only.
const FIRST_STEP: f64 = 1e-6;

#[test]
fn a_person_avoiding_collisions_stops_behind_one_standing_in_her_lane() {
    // walker_avoid_collisions.osc: the IDM with a walker's parameters, worked in the file.
    let r = run("walker_avoid_collisions", 0, None);
    let gap = |t: f64| (r.at(t, "bob").s - 0.25) - (r.at(t, "alice").s + 0.25);
    assert!((gap(0.0) - 19.5).abs() < 1e-9, "gap(0) = {}", gap(0.0));
    let v1 = r.at(DT, "alice").speed;
    assert!(
        (v1 - 1.399_041_3).abs() < FIRST_STEP,
        "alice v({DT}) = {v1}"
    );
    // Never closer than s0: no collision.
    for (t, _) in &r.frames {
        assert!(gap(*t) > 0.5 - 1e-9, "gap {} at {t}", gap(*t));
    }
    assert!(
        (gap(60.0) - 0.5).abs() < STOPPED_GAP,
        "gap(60) = {}",
        gap(60.0)
    );
    assert!(
        r.at(60.0, "alice").speed < 0.01,
        "{:?}",
        r.at(60.0, "alice")
    );
    assert!((r.at(60.0, "bob").s - 30.0).abs() < 1e-9);
    assert_eq!(r.at(60.0, "alice").lane, r.at(60.0, "bob").lane);
}
