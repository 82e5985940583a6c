//! Cost of position resolution and condition evaluation (OpenSCENARIO 1.3 §7.4, §7.6) on
//! esmini's curve_r100.xodr through the test harness's fake runtime: the per-call price the
//! runtime pays for each condition of each evaluated trigger every step.
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

#[path = "../tests/support/condition.rs"]
mod condition_support;
#[path = "../tests/support/corpus.rs"]
mod corpus;

use std::hint::black_box;
use std::time::Duration;

use condition_support::{at, by_entity, corpus_road, measure, FakeWorld};
use criterion::{criterion_group, criterion_main, Criterion};
use engine::condition::{evaluate, ConditionState};
use engine::position::resolve;
use scenario::{
    CoordinateSystem, EntityCondition, PositionKind, RelativeDistanceType, Rule,
    TimeToCollisionTarget,
};

fn world() -> FakeWorld {
    let mut w = FakeWorld::new(corpus_road("esmini/xodr/curve_r100.xodr"));
    w.place_on_lane("Ego", "0", -1, 480.0, true);
    w.place_on_lane("Lead", "0", -1, 530.0, true);
    w.set_speed("Ego", 20.0);
    w.set_speed("Lead", 10.0);
    w
}

fn positions(c: &mut Criterion) {
    let w = world();
    let lane = at(PositionKind::Lane {
        road_id: "0".into(),
        lane_id: "-1".into(),
        s: 550.0,
        offset: Some(0.3),
        orientation: None,
    });
    let ds_lane = at(PositionKind::RelativeLane {
        entity_ref: "Ego".into(),
        d_lane: 1,
        ds: None,
        ds_lane: Some(50.0),
        offset: None,
        orientation: None,
    });
    let mut g = c.benchmark_group("position");
    g.sample_size(10).measurement_time(Duration::from_secs(2));
    g.bench_function("LanePosition on the arc", |b| {
        b.iter(|| resolve(black_box(&lane), &w))
    });
    g.bench_function("RelativeLanePosition dsLane 50 m", |b| {
        b.iter(|| resolve(black_box(&ds_lane), &w))
    });
    g.finish();
}

fn conditions(c: &mut Criterion) {
    let w = world();
    let rel = |m| {
        by_entity(
            &["Ego"],
            false,
            EntityCondition::RelativeDistance {
                entity_ref: "Lead".into(),
                value: 30.0,
                rule: Rule::LessThan,
                measure: m,
            },
        )
    };
    let entity_free = rel(measure(true, None, None));
    let road_free = rel(measure(
        true,
        Some(CoordinateSystem::Road),
        Some(RelativeDistanceType::Longitudinal),
    ));
    let ttc = by_entity(
        &["Ego"],
        false,
        EntityCondition::TimeToCollision {
            target: TimeToCollisionTarget::EntityRef("Lead".into()),
            value: 3.0,
            rule: Rule::LessThan,
            measure: measure(
                false,
                Some(CoordinateSystem::Road),
                Some(RelativeDistanceType::Longitudinal),
            ),
        },
    );
    let mut g = c.benchmark_group("condition");
    g.sample_size(10).measurement_time(Duration::from_secs(2));
    for (name, cond) in [
        ("RelativeDistance freespace euclidean", &entity_free),
        ("RelativeDistance freespace road longitudinal", &road_free),
        ("TimeToCollision road longitudinal", &ttc),
    ] {
        g.bench_function(name, |b| {
            let mut state = ConditionState::new();
            b.iter(|| evaluate(black_box(cond), &w, &mut state))
        });
    }
    g.finish();
}

criterion_group!(benches, positions, conditions);
criterion_main!(benches);
