//! Random traffic created where the plan does not know every other vehicle's place (ASAM
//! OpenSCENARIO DSL 2.1 §8.7.18.1; plan/random_traffic_late.rs): after a run-time condition,
//! or beside a vehicle the engine moves. The engine deals the members when the creating phase
//! starts (oscsim's CreateRandomTraffic) by the plan's rule among the places the others have
//! then. Expectations in the scenario files.

use crate::support::{run, run_to_error_on, Obj, Run, DT};

/// Positions of an actor driving its plan on a straight road: float round-off only (m).
const S_TOL: f64 = 1e-6;
/// The IDM's minimum gap s0 (m) and time headway T (s), the engine's defaults.
const S0: f64 = 2.0;
const T: f64 = 1.6;

/// A vehicle's box along its lane's direction of travel in s (4 m boxes, reference point
/// 0.5 m from the rear; lanes 1 and 2 are driven in −s, their front at lower s).
fn span(o: &Obj) -> (f64, f64) {
    if o.lane > 0 {
        (o.s - 3.5, o.s + 0.5)
    } else {
        (o.s - 0.5, o.s + 3.5)
    }
}

/// Checks that at `at` the members `names` of random traffic are at their drawn speeds in
/// driving lanes, apart from each other and from `others` by s0 + v_max·T less `moved` (how
/// far the others moved in the step the members were held), and drive on along their lanes.
pub(crate) fn dealt_apart(
    r: &Run,
    seed: u64,
    at: f64,
    names: &[String],
    others: &[&str],
    moved: f64,
) {
    let mut v_max = others.iter().fold(0.0_f64, |a, m| a.max(r.at(at, m).speed));
    let mut boxes: Vec<(i32, f64, f64, &str)> = Vec::new();
    for m in names
        .iter()
        .map(String::as_str)
        .chain(others.iter().copied())
    {
        let o = r.at(at, m);
        if m.starts_with("g.") {
            assert!((22.5..=27.5).contains(&o.speed), "seed {seed}: {o:?}");
            assert!([-3, -2, -1, 1, 2].contains(&o.lane), "seed {seed}: {o:?}");
            v_max = v_max.max(o.speed);
        }
        let (a, b) = span(o);
        boxes.push((o.lane, a, b, m));
    }
    boxes.sort_by(|p, q| p.0.cmp(&q.0).then(p.1.total_cmp(&q.1)));
    // Pairs with a member (the others' own gaps are their plans' and models').
    for w in boxes
        .windows(2)
        .filter(|w| w[0].0 == w[1].0 && (w[0].3.starts_with("g.") || w[1].3.starts_with("g.")))
    {
        let gap = w[1].1 - w[0].2;
        assert!(
            gap >= S0 + v_max * T - moved - S_TOL,
            "seed {seed}: {} to {}: {gap} m at {at} s",
            w[0].3,
            w[1].3
        );
    }
    // Then their model drives them along their lanes' directions (22.5 m/s or more less
    // what the IDM takes off in 1 s).
    for m in names {
        let (p, q) = (r.at(at, m), r.at(at + 1.0, m));
        let ds = if p.lane > 0 { p.s - q.s } else { q.s - p.s };
        if q.s > 4.0 && q.s < 996.0 {
            assert!(ds > 20.0, "seed {seed}: {m} moved {ds} m in 1 s");
        }
    }
}

/// Counts the members in the world in each frame: none before `created`, all after its step.
pub(crate) fn created_at(r: &Run, seed: u64, created: f64, n: usize) {
    for (t, objs) in &r.frames {
        let present = objs.iter().filter(|o| o.name.starts_with("g.")).count();
        if *t < created - 1e-9 {
            assert_eq!(present, 0, "seed {seed}: members in the world at {t}");
        } else if *t > created + DT + 1e-9 {
            assert_eq!(present, n, "seed {seed}: members at {t}");
        }
    }
}

#[test]
fn random_traffic_created_after_a_run_time_condition_is_dealt_among_the_places_then() {
    // random_traffic_runtime.osc: the wait ends at 5.15 s; ego at 203 m, lead at 277.25 m.
    let names: Vec<String> = (0..6).map(|i| format!("g.vehicles[{i}]")).collect();
    let mut places = Vec::new();
    for seed in [0, 1, 2, 3] {
        let r = run("random_traffic_runtime", seed, None);
        let (start, _) = r.phase("do.2.traffic");
        assert!((start - 5.15).abs() < 1e-9, "created at {start}");
        created_at(&r, seed, start, 6);
        let at = start + DT;
        // At the step's start, where the engine read them (the members are shown at its end).
        let (ego, lead) = (r.at(start, "ego"), r.at(start, "lead"));
        assert!((ego.s - 203.0).abs() < S_TOL && ego.lane == -3, "{ego:?}");
        assert!(
            (lead.s - 277.25).abs() < S_TOL && lead.lane == -3,
            "{lead:?}"
        );
        dealt_apart(&r, seed, at, &names, &["ego", "lead"], 20.0 * DT);
        places.push(
            names
                .iter()
                .map(|m| (r.at(at, m).lane, r.at(at, m).s.to_bits()))
                .collect::<Vec<_>>(),
        );
        // Seed 2 again: the same places and speeds, bit for bit.
        if seed == 2 {
            let again = run("random_traffic_runtime", seed, None);
            for m in &names {
                let (p, q) = (r.at(at + 1.0, m), again.at(at + 1.0, m));
                assert_eq!(
                    (p.x.to_bits(), p.y.to_bits(), p.speed.to_bits()),
                    (q.x.to_bits(), q.y.to_bits(), q.speed.to_bits())
                );
            }
        }
    }
    // Another seed, other places.
    assert!(places.windows(2).all(|w| w[0] != w[1]), "{places:?}");
}

#[test]
fn random_traffic_created_beside_a_vehicle_the_engine_moves_is_dealt_among_its_place_then() {
    // random_traffic_late_moved.osc: ego braked by its IDM behind npc (s = 200 m), so short of
    // the plan's 200 m at 5 s; the members are dealt around where the engine has it.
    let names: Vec<String> = (0..5).map(|i| format!("g.vehicles[{i}]")).collect();
    for seed in [0, 1, 2, 3] {
        let r = run("random_traffic_late_moved", seed, None);
        let (start, _) = r.phase("do.2.traffic");
        assert!((start - 5.0).abs() < 1e-9, "created at {start}");
        created_at(&r, seed, start, 5);
        let ego = r.at(start, "ego");
        // Behind npc's rear (199.5 m) by more than s0, its front at s + 3.5 m.
        assert!(ego.s + 3.5 < 199.5 - S0 + 1e-3 && ego.lane == -3, "{ego:?}");
        dealt_apart(&r, seed, start + DT, &names, &["ego", "npc"], 20.0 * DT);
    }
}

#[test]
fn random_traffic_created_after_a_run_time_condition_without_room_fails_the_run() {
    // random_traffic_runtime_crowded.osc: 60 members at 60 m/s do not fit at 5.15 s.
    let (error, records) = run_to_error_on("random_traffic_runtime_crowded", "straight");
    let error = error.expect("the run fails");
    assert!(
        error.starts_with("expected room on the plan's driving lanes for the 60 members of random traffic `g` (each its length plus a gap of "),
        "{error}"
    );
    assert!(error.contains(", found room for "), "{error}");
    assert!(
        error.ends_with("random_traffic_runtime_crowded.osc:30:13"),
        "{error}"
    );
    let (t, _, message) = records.first().expect("an error record");
    assert!(
        (t - 5.15).abs() < 1e-9 && message == &error,
        "{t} {message}"
    );
}

#[test]
fn random_traffic_created_beside_another_after_a_run_time_condition_is_dealt_to_its_lane_then() {
    // random_traffic_runtime_beside.osc: created at 5.15 s left of ego (lane -3): lane -2.
    let names: Vec<String> = (0..4).map(|i| format!("g.vehicles[{i}]")).collect();
    for seed in [0, 1, 2, 3] {
        let r = run("random_traffic_runtime_beside", seed, None);
        let (start, _) = r.phase("do.2.traffic");
        assert!((start - 5.15).abs() < 1e-9, "created at {start}");
        created_at(&r, seed, start, 4);
        for (t, objs) in &r.frames {
            for o in objs
                .iter()
                .filter(|o| o.name.starts_with("g.") && o.s > 4.0 && o.s < 996.0)
            {
                assert_eq!(o.lane, -2, "seed {seed} at {t}: {o:?}");
            }
        }
        dealt_apart(&r, seed, start + DT, &names, &["ego", "lead"], 20.0 * DT);
    }
}
