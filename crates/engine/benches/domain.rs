//! Criterion benchmarks of the OpenSCENARIO 2.0 §8.7 measurement methods:
//! time_to_collision (§8.7.5.1.1) over 1,000 pairs, and space_gap (§8.7.5.1.3) between pairs
//! of cars on the radius-100 m arc of esmini's curve_r100.xodr.
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use engine::domain::{
    BoundingBox, DistanceDirection, MovableObject, PhysicalObject, Position3d, TrafficParticipant,
    Vector3,
};
use opendrive::{Pose, RoadNetwork};

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

fn space_gap_on_curve(c: &mut Criterion) {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus/esmini/xodr/curve_r100.xodr"
    );
    let net = RoadNetwork::from_file(std::path::Path::new(path)).expect("corpus road loads");
    // 100 pairs in lane −1 on the arc (s ∈ [500, 657]), 5 to 30 m apart.
    let pairs: Vec<(TrafficParticipant, TrafficParticipant)> = (0..100)
        .map(|i| {
            let s = 505.0 + 1.2 * i as f64;
            let ahead = 5.0 + 0.25 * i as f64;
            let pose = |s: f64| {
                net.lane_pose("0", -1, s.min(655.0), 0.0)
                    .expect("s on the road")
            };
            let (a, b) = (pose(s), pose(s + ahead));
            (car(a.x, a.y, a.h, 10.0), car(b.x, b.y, b.h, 10.0))
        })
        .collect();
    let mut group = c.benchmark_group("space_gap");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(3));
    group.throughput(Throughput::Elements(pairs.len() as u64));
    group.bench_function("curve_r100_100_pairs", |bench| {
        bench.iter(|| {
            let mut sum = 0.0;
            for (a, b) in &pairs {
                sum += black_box(a)
                    .space_gap(&net, black_box(b), DistanceDirection::Longitudinal)
                    .expect("both on the road");
            }
            sum
        })
    });
    group.finish();
}

criterion_group!(benches, time_to_collision, space_gap_on_curve);
criterion_main!(benches);
