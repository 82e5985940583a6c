//! Stochastic parameter value distributions (OpenSCENARIO 1.3 §9.5): sample means within a
//! 5-sigma tolerance of the closed-form means (20 000 draws, fixed seed), ranges respected,
//! and exact reproducibility of the documented seeding and draw order.
//!
//! Tolerances: the standard error of a mean of N draws is σ/√N; with N = 20 000 each bound
//! below is 5 of those (a false failure has probability below 10⁻⁶ for a fresh seed, and the
//! seed is fixed, so the test is deterministic).

use std::path::{Path, PathBuf};

use rand::{Rng, SeedableRng};
use scenario::distribution::{seed_for, DistributionPlan};

const N: f64 = 20_000.0;

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/files/distribution")
        .join(name)
}

fn plan() -> DistributionPlan {
    DistributionPlan::load(&fixture("stochastic_all.xosc")).unwrap_or_else(|e| panic!("{e}"))
}

fn values(plan: &DistributionPlan, parameter: &str) -> Vec<f64> {
    plan.runs
        .iter()
        .map(|r| {
            r[parameter]
                .parse::<f64>()
                .unwrap_or_else(|e| panic!("{parameter}: {e}"))
        })
        .collect()
}

fn mean(xs: &[f64]) -> f64 {
    xs.iter().sum::<f64>() / xs.len() as f64
}

fn variance(xs: &[f64]) -> f64 {
    let m = mean(xs);
    xs.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (xs.len() as f64 - 1.0)
}

/// |sample mean − expected| ≤ 5 σ/√N.
fn assert_mean(xs: &[f64], expected: f64, sigma: f64, what: &str) {
    let tolerance = 5.0 * sigma / N.sqrt();
    let m = mean(xs);
    assert!(
        (m - expected).abs() <= tolerance,
        "{what}: mean {m}, expected {expected} ± {tolerance}"
    );
}

#[test]
fn twenty_thousand_runs_with_every_parameter() {
    let plan = plan();
    assert_eq!(plan.runs.len(), 20_000);
    assert!(plan.runs.iter().all(|r| r.len() == 7));
}

#[test]
fn uniform() {
    // U[10, 20): mean 15, σ² = 10²/12 = 8.333…
    let xs = values(&plan(), "uniform");
    assert!(xs.iter().all(|x| (10.0..20.0).contains(x)));
    assert_mean(&xs, 15.0, (100.0_f64 / 12.0).sqrt(), "uniform");
}

#[test]
fn normal() {
    // N(30, σ² = 4): mean 30, σ = 2. The sample variance has standard error σ²·√(2/(N−1)),
    // 4·0.0100 = 0.040, so |s² − 4| ≤ 0.2.
    let xs = values(&plan(), "normal");
    assert_mean(&xs, 30.0, 2.0, "normal");
    let s2 = variance(&xs);
    assert!((s2 - 4.0).abs() <= 0.2, "normal variance {s2}");
}

#[test]
fn truncated_normal_stays_in_range() {
    // N(30, 4) truncated to [28, 32] = μ ± 1σ: symmetric, so the mean stays 30; its variance is
    // σ²(1 − 2φ(1)/(2Φ(1) − 1)) = 4(1 − 2·0.241971/0.682689) = 1.16450, σ = 1.07912.
    let xs = values(&plan(), "normal_truncated");
    assert!(xs.iter().all(|x| (28.0..=32.0).contains(x)));
    assert_mean(&xs, 30.0, 1.079_12, "truncated normal");
    let s2 = variance(&xs);
    // Standard error of s²: √((μ₄ − σ⁴)/N). For Z truncated to ±1: E[Z⁴] = 3·E[Z²] −
    // 2φ(1)/(2Φ(1) − 1) = 3·0.291120 − 0.708880 = 0.164480, so μ₄ = 2⁴·0.164480 = 2.63168,
    // σ⁴ = 1.16450² = 1.35606, se = √(1.27562/20000) = 0.00799; 5 se = 0.040.
    assert!(
        (s2 - 1.164_50).abs() <= 0.040,
        "truncated normal variance {s2}"
    );
}

#[test]
fn lognormal_has_the_given_mean_and_variance() {
    // expectedValue 2 and variance 0.5 are those of the values: mean 2, σ = √0.5.
    let xs = values(&plan(), "lognormal");
    assert!(xs.iter().all(|x| *x > 0.0));
    assert_mean(&xs, 2.0, 0.5_f64.sqrt(), "lognormal");
}

#[test]
fn poisson_gives_integers_with_mean_lambda() {
    // Poisson(3.5): mean 3.5, σ² = 3.5.
    let plan = plan();
    assert!(
        plan.runs
            .iter()
            .all(|r| r["poisson"].parse::<u64>().is_ok()),
        "integers"
    );
    let xs = values(&plan, "poisson");
    assert_mean(&xs, 3.5, 3.5_f64.sqrt(), "poisson");
}

#[test]
fn histogram_mixes_its_bins_by_weight() {
    // Bins [0,1) weight 1 and [1,3) weight 3: P = 1/4, 3/4.
    // Mean = ¼·0.5 + ¾·2 = 1.625. E[X²] = ¼·(1/3) + ¾·(13/3) = 3.3333…, σ² = 3.3333 − 1.625²
    // = 0.692708, σ = 0.832291.
    let xs = values(&plan(), "histogram");
    assert!(xs.iter().all(|x| (0.0..3.0).contains(x)));
    assert_mean(&xs, 1.625, 0.832_291, "histogram");
    // Share in the first bin: 1/4 ± 5·√(¼·¾/N) = 0.25 ± 0.0153.
    let share = xs.iter().filter(|x| **x < 1.0).count() as f64 / N;
    assert!(
        (share - 0.25).abs() <= 5.0 * (0.25_f64 * 0.75 / N).sqrt(),
        "first-bin share {share}"
    );
}

#[test]
fn probability_set_frequencies_follow_the_weights() {
    // Weights 1, 2, 7 → p = 0.1, 0.2, 0.7; each frequency within 5·√(p(1−p)/N).
    let plan = plan();
    for (value, p) in [("car_white", 0.1), ("van_red", 0.2), ("truck_yellow", 0.7)] {
        let share = plan.runs.iter().filter(|r| r["vehicle"] == value).count() as f64 / N;
        let tolerance = 5.0 * (p * (1.0 - p) / N).sqrt();
        assert!(
            (share - p).abs() <= tolerance,
            "{value}: {share}, expected {p} ± {tolerance}"
        );
    }
}

#[test]
fn same_seed_same_runs_other_seed_other_runs() {
    let text =
        std::fs::read_to_string(fixture("stochastic_all.xosc")).unwrap_or_else(|e| panic!("{e}"));
    let path = fixture("stochastic_all.xosc");
    let first = DistributionPlan::from_text(&text, &path).unwrap_or_else(|e| panic!("{e}"));
    let second = DistributionPlan::from_text(&text, &path).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(first, second);
    let reseeded = text.replace("randomSeed=\"12345\"", "randomSeed=\"12346\"");
    let other = DistributionPlan::from_text(&reseeded, &path).unwrap_or_else(|e| panic!("{e}"));
    assert_ne!(first.runs[0], other.runs[0]);
}

#[test]
fn seeding_and_draw_order_are_as_documented() {
    // The module doc's recipe, by hand: ChaCha20Rng::seed_from_u64(7), then per run
    // 20 + (40 − 20)·u with u = gen::<f64>().
    let plan =
        DistributionPlan::load(&fixture("uniform_seed7.xosc")).unwrap_or_else(|e| panic!("{e}"));
    let mut rng = rand_chacha::ChaCha20Rng::seed_from_u64(7);
    let expected: Vec<String> = (0..3)
        .map(|_| (20.0 + 20.0 * rng.gen::<f64>()).to_string())
        .collect();
    let got: Vec<&str> = plan.runs.iter().map(|r| r["EgoSpeed"].as_str()).collect();
    assert_eq!(got, expected);
}

#[test]
fn seed_mapping() {
    // Integral seeds in [0, 2^64) are used as they are; others by their IEEE-754 bits.
    assert_eq!(seed_for(Some(7.0)), 7);
    assert_eq!(seed_for(None), 0);
    assert_eq!(seed_for(Some(7.5)), 7.5_f64.to_bits());
    assert_eq!(seed_for(Some(-1.0)), (-1.0_f64).to_bits());
}
