//! Criterion benchmarks of trajectories (OpenSCENARIO 1.3 §7.6) and route planning (§7.5):
//! building a 40-point cubic NURBS (its arc-length table), evaluating polyline, clothoid and
//! NURBS trajectories by s, the closest point on the NURBS, and planning routes on esmini's
//! multi_intersections.xodr (63 roads, 5 junctions) with each strategy.
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use engine::routing::{plan_route, RoutingOptions};
use engine::trajectory::{build, Trajectory};
use scenario::{
    Clothoid, ControlPoint, Nurbs, Position, PositionKind, Route, RouteStrategy, Shape, Vertex,
    Waypoint,
};

#[path = "../tests/support/corpus.rs"]
mod corpus;
#[path = "../tests/support/trajectory.rs"]
mod support;

use support::{corpus as roads, here as pos, world, Roads};

/// 40 points on a sine wave of amplitude 20 m and wavelength 200 m, 10 m apart in x.
fn wave() -> Vec<(f64, f64)> {
    (0..40)
        .map(|i| {
            let x = 10.0 * i as f64;
            (x, 20.0 * (x * std::f64::consts::TAU / 200.0).sin())
        })
        .collect()
}

fn nurbs_shape() -> Shape {
    let pts = wave();
    let n = pts.len();
    // Clamped uniform cubic knot vector: 4 zeros, 1 … n − 4, 4 × (n − 3).
    let mut knots = vec![0.0; 4];
    knots.extend((1..n - 3).map(|k| k as f64));
    knots.extend([(n - 3) as f64; 4]);
    Shape::Nurbs(Nurbs {
        order: 4,
        control_points: pts
            .iter()
            .map(|&(x, y)| ControlPoint {
                time: None,
                weight: None,
                position: world(x, y),
            })
            .collect(),
        knots,
    })
}

fn trajectory(shape: Shape, ctx: &Roads) -> Trajectory {
    let t = scenario::Trajectory {
        name: "bench".into(),
        closed: false,
        shape,
        catalog: None,
    };
    // Constant, valid shapes.
    build(&t, ctx, &pos()).expect("valid trajectory")
}

fn shapes(c: &mut Criterion) {
    let ctx = roads("esmini/xodr/straight_500m.xodr");
    let mut g = c.benchmark_group("trajectory");
    g.sample_size(10).measurement_time(Duration::from_secs(2));
    g.bench_function("build_nurbs_40_cubic", |b| {
        b.iter(|| trajectory(black_box(nurbs_shape()), &ctx))
    });
    let polyline = trajectory(
        Shape::Polyline(
            wave()
                .into_iter()
                .map(|(x, y)| Vertex {
                    time: None,
                    position: world(x, y),
                })
                .collect(),
        ),
        &ctx,
    );
    let clothoid = trajectory(
        Shape::Clothoid(Clothoid {
            curvature: 0.0,
            curvature_prime: 1e-4,
            length: 300.0,
            start_time: None,
            stop_time: None,
            position: world(0.0, 0.0),
        }),
        &ctx,
    );
    let nurbs = trajectory(nurbs_shape(), &ctx);
    for (name, t) in [
        ("eval_1000_polyline", &polyline),
        ("eval_1000_clothoid", &clothoid),
        ("eval_1000_nurbs", &nurbs),
    ] {
        let step = t.length() / 1000.0;
        g.bench_function(name, |b| {
            b.iter(|| {
                (0..1000)
                    .map(|i| t.eval(black_box(i as f64 * step)).x)
                    .sum::<f64>()
            })
        });
    }
    g.bench_function("closest_nurbs", |b| {
        b.iter(|| nurbs.closest(black_box(155.0), black_box(3.0)))
    });
    g.finish();
}

fn lane(road: &str, s: f64) -> Waypoint {
    Waypoint {
        route_strategy: RouteStrategy::Shortest,
        position: Position {
            kind: PositionKind::Lane {
                road_id: road.into(),
                lane_id: "-1".into(),
                s,
                offset: None,
                orientation: None,
            },
            pos: pos(),
        },
    }
}

fn routes(c: &mut Criterion) {
    let ctx = roads("esmini/xodr/multi_intersections.xodr");
    let mut g = c.benchmark_group("routing");
    g.sample_size(10).measurement_time(Duration::from_secs(2));
    for strategy in [
        RouteStrategy::Shortest,
        RouteStrategy::Fastest,
        RouteStrategy::LeastIntersections,
        RouteStrategy::Random,
    ] {
        let mut route = Route {
            name: "bench".into(),
            closed: false,
            waypoints: vec![lane("196", 50.0), lane("281", 100.0)],
            catalog: None,
        };
        route.waypoints[1].route_strategy = strategy;
        g.bench_function(format!("plan_two_junctions_{strategy:?}"), |b| {
            b.iter(|| plan_route(black_box(&route), &ctx, &RoutingOptions::default(), &pos()))
        });
    }
    g.finish();
}

criterion_group!(benches, shapes, routes);
criterion_main!(benches);
