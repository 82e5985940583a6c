//! Criterion benchmarks of the OpenSCENARIO 2.0 §8.7 measurement methods:
//! time_to_collision (§8.7.5.1.1) over 1,000 pairs.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use engine::domain::{
    BoundingBox, MovableObject, PhysicalObject, Position3d, TrafficParticipant, Vector3,
};
use opendrive::Pose;

/// A car (4.5 × 1.8 m box, centre 1.4 m ahead of the rear axle) at (x, y) heading h, driving
/// forward at v.
fn car(x: f64, y: f64, h: f64, v: f64) -> TrafficParticipant {
    let bb = BoundingBox::new(Position3d::new(1.4, 0.0, 0.75), 4.5, 1.8, 1.5)
        .expect("constant, valid dimensions");
    let mut m = MovableObject::new(PhysicalObject::new(
        bb,
        Pose {
            x,
            y,
            h,
            ..Pose::default()
        },
    ));
    m.velocity.translational = Vector3::new(v, 0.0, 0.0);
    TrafficParticipant::new(m, Vec::new())
}

/// 1,000 deterministic pairs spread over approaching, crossing, receding and parallel
/// motion (a golden-ratio sequence, so that no random generator is needed).
fn pairs() -> Vec<(TrafficParticipant, TrafficParticipant)> {
    let phi = 0.618_033_988_749_895_f64;
    (0..1000)
        .map(|i| {
            let u = |k: f64| (i as f64 * phi * k).fract();
            let a = car(0.0, 0.0, 0.0, 30.0 * u(1.0));
            let b = car(
                100.0 * u(2.0) - 20.0,
                20.0 * u(3.0) - 10.0,
                std::f64::consts::TAU * u(5.0),
                30.0 * u(7.0),
            );
            (a, b)
        })
        .collect()
}

fn time_to_collision(c: &mut Criterion) {
    let pairs = pairs();
    let mut group = c.benchmark_group("time_to_collision");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(3));
    group.throughput(Throughput::Elements(pairs.len() as u64));
    group.bench_function("1000_pairs", |bench| {
        bench.iter(|| {
            let mut hits = 0usize;
            for (a, b) in &pairs {
                if black_box(a).time_to_collision(black_box(b)).is_some() {
                    hits += 1;
                }
            }
            hits
        })
    });
    group.finish();
}

criterion_group!(benches, time_to_collision);
criterion_main!(benches);
