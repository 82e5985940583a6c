//! A 3 × 2 × 4 deterministic grid over `files/following.xosc` (Ego behind Target in one lane,
//! constant speeds, bumper-to-bumper gap `Gap`, 10 s): the documented variant order, and the
//! collision of every variant against gap / closing speed worked out by hand.

use std::path::{Path, PathBuf};

use batch::{run, Options, Plan, StopReason};

fn file(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/files")
        .join(name)
}

const EGO: [f64; 3] = [20.0, 25.0, 30.0];
const TARGET: [f64; 2] = [10.0, 20.0];
const GAP: [f64; 4] = [10.0, 20.0, 40.0, 80.0];
/// The step (s): a collision shows in the first frame at or after the instant of contact.
const DT: f64 = 0.05;

#[test]
fn the_grid_has_24_variants_in_the_documented_order() {
    let plan = Plan::load(&file("grid.xosc")).unwrap();
    assert_eq!(plan.parameters, ["EgoSpeed", "TargetSpeed", "Gap"]);
    assert_eq!(plan.variants.len(), 24);
    // The first distribution varies slowest, the last fastest: variant i is
    // (EGO[i / 8], TARGET[(i / 4) % 2], GAP[i % 4]).
    for i in 0..24 {
        let values: Vec<f64> = plan.values(i).iter().map(|v| v.parse().unwrap()).collect();
        assert_eq!(
            values,
            [EGO[i / 8], TARGET[(i / 4) % 2], GAP[i % 4]],
            "variant {i}"
        );
    }
}

/// Both cars keep their speeds, so the gap closes at v_ego − v_target and reaches 0 at
/// t* = Gap / (v_ego − v_target) when the closing speed is positive. The run's last frame is at
/// 10 s (the stop trigger fires after 9.99 s), so a collision is recorded when t* ≤ 10 s, in
/// the first frame at or after t* (t* itself up to one step later). E.g. EgoSpeed 25,
/// TargetSpeed 10, Gap 40: 40 / 15 = 2.667 s → frame 2.7 s. EgoSpeed 25, TargetSpeed 20,
/// Gap 80: 80 / 5 = 16 s > 10 s → none. Equal speeds never collide, and their time to
/// collision is never defined.
#[test]
fn collision_and_its_time_follow_gap_over_closing_speed() {
    let plan = Plan::load(&file("grid.xosc")).unwrap();
    let table = run(&plan, &Options::default(), &|_, _| {}).unwrap();
    assert_eq!(table.rows.len(), 24);
    let mut collisions = 0;
    for (i, row) in table.rows.iter().enumerate() {
        assert_eq!(row.variant, i as u64);
        let o = row
            .result
            .as_ref()
            .unwrap_or_else(|e| panic!("variant {i}: {e}"));
        let (ego, target, gap) = (EGO[i / 8], TARGET[(i / 4) % 2], GAP[i % 4]);
        assert_eq!(o.stop, Some(StopReason::StopTrigger));
        assert!(
            (o.end_time - 10.0).abs() < 1e-9,
            "variant {i}: {}",
            o.end_time
        );
        let closing = ego - target;
        let expected = (closing > 0.0)
            .then(|| gap / closing)
            .filter(|t| *t <= 10.0);
        match (expected, o.first_collision_time) {
            (Some(t), Some(got)) => {
                assert!(o.collision);
                assert!(
                    got >= t - 1e-9 && got <= t + DT + 1e-9,
                    "variant {i}: t* {t}, frame {got}"
                );
                collisions += 1;
            }
            (None, None) => assert!(!o.collision, "variant {i}"),
            other => panic!("variant {i}: expected vs got {other:?}"),
        }
        if closing == 0.0 {
            assert_eq!(o.min_ttc, None, "variant {i}");
            // Equal speeds keep the gap: min_gap is Gap itself (to 1e-6, the CSV's precision),
            // and the headway is (Gap + 5) / v: reference point to reference point.
            assert!(
                (o.min_gap.unwrap() - gap).abs() < 2e-6,
                "variant {i}: {:?}",
                o.min_gap
            );
            let headway = (gap + 5.0) / ego;
            assert!(
                (o.min_headway.unwrap() - headway).abs() < 2e-6,
                "variant {i}: {:?}",
                o.min_headway
            );
        } else {
            // The first frame, t = 0: TTC = Gap / closing exactly; it only falls from there.
            assert!(o.min_ttc.unwrap() <= gap / closing + 1e-6, "variant {i}");
        }
    }
    // Hand count: closing 10 (20/10, 30/20): all four gaps by 8 s, twice; 15 (25/10): all
    // four (80/15 = 5.33 s); 20 (30/10): all four; 5 (25/20): 10 and 20 and 40 (8 s), not 80.
    assert_eq!(collisions, 4 + 4 + 4 + 4 + 3);
}

#[test]
fn any_number_of_jobs_gives_the_same_table() {
    let plan = Plan::load(&file("grid.xosc")).unwrap();
    let one = run(&plan, &Options::default(), &|_, _| {}).unwrap();
    let two = run(
        &plan,
        &Options {
            jobs: 2,
            ..Options::default()
        },
        &|_, _| {},
    )
    .unwrap();
    assert_eq!(one.to_csv(), two.to_csv());
    assert_eq!(
        batch::to_parquet(&one).unwrap(),
        batch::to_parquet(&two).unwrap()
    );
}
