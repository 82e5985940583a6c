//! Criterion benchmarks of the road model: load time (largest corpus file and the generated
//! 60 MB town grid of `grid/`), (road, s, t) → world evaluations per geometry type, world →
//! road look-ups on `multi_intersections.xodr` and on the grid, lane routes, and the lane
//! graph's successors and predecessors on `multi_intersections.xodr`. Short runs
//! (sample size 10) so the whole file takes about two minutes.
// criterion_group!/criterion_main! make undocumented public functions (workspace lint
// missing_docs).
#![allow(missing_docs)]

mod grid;

use std::path::{Path, PathBuf};
use std::time::Duration;

use criterion::{
    black_box, criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode, Throughput,
};
use opendrive::RoadNetwork;

fn corpus(rel: &str) -> PathBuf {
    PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus/"
    ))
    .join(rel)
}

fn load(c: &mut Criterion) {
    let mut g = c.benchmark_group("load");
    // Flat sampling: one load per sample, so the 50 MB case costs 10 loads, not 55.
    g.sample_size(10)
        .sampling_mode(SamplingMode::Flat)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(5));
    let path = corpus("esmini/xodr/multi_intersections.xodr");
    let text = std::fs::read_to_string(&path).unwrap_or_default();
    g.throughput(Throughput::Bytes(text.len() as u64));
    g.bench_function("multi_intersections.xodr", |b| {
        b.iter(|| RoadNetwork::from_str(black_box(&text), &path).map(|n| n.roads().len()))
    });
    let big = grid::grid_for_bytes(60_000_000);
    let big_path = Path::new("grid.xodr");
    // The generated file must be consistent: no warnings, or the figure would time them.
    let probe = RoadNetwork::from_str(&big, big_path).unwrap_or_else(|e| panic!("{e}"));
    assert!(probe.warnings().is_empty(), "{}", probe.warnings()[0]);
    drop(probe);
    g.throughput(Throughput::Bytes(big.len() as u64));
    g.bench_function("grid_60MB", |b| {
        b.iter(|| RoadNetwork::from_str(black_box(&big), big_path).map(|n| n.roads().len()))
    });
    g.finish();
}

/// One road of a single geometry type, 100 m long.
fn single_geometry(curve: &str) -> RoadNetwork {
    let text = format!(
        r#"<OpenDRIVE><header/><road id="1" length="100" junction="-1"><planView>
<geometry s="0" x="0" y="0" hdg="0.3" length="100">{curve}</geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right>
<lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes></road></OpenDRIVE>"#
    );
    RoadNetwork::from_str(&text, Path::new("bench.xodr")).unwrap_or_else(|e| panic!("{e}"))
}

fn road_pose(c: &mut Criterion) {
    let mut g = c.benchmark_group("road_pose");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(2));
    let cases = [
        ("line", "<line/>"),
        ("arc", r#"<arc curvature="0.01"/>"#),
        ("spiral", r#"<spiral curvStart="0.001" curvEnd="0.03"/>"#),
        ("poly3", r#"<poly3 a="0" b="0" c="0.002" d="-0.00001"/>"#),
        (
            "paramPoly3",
            r#"<paramPoly3 aU="0" bU="1" cU="0" dU="0" aV="0" bV="0" cV="0.002" dV="-0.00001" pRange="arcLength"/>"#,
        ),
    ];
    const N: usize = 1000;
    g.throughput(Throughput::Elements(N as u64));
    for (name, curve) in cases {
        let net = single_geometry(curve);
        g.bench_with_input(BenchmarkId::from_parameter(name), &net, |b, net| {
            b.iter(|| {
                let mut acc = 0.0;
                for k in 0..N {
                    let s = 100.0 * k as f64 / N as f64;
                    if let Ok(p) = net.road_pose("1", s, -1.75) {
                        acc += p.x + p.y;
                    }
                }
                acc
            })
        });
    }
    g.finish();
}

fn locate(c: &mut Criterion) {
    let mut g = c.benchmark_group("locate");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3));
    let net = RoadNetwork::from_file(&corpus("esmini/xodr/multi_intersections.xodr"))
        .unwrap_or_else(|e| panic!("{e}"));
    let points = spread_points(&net, 1000);
    g.throughput(Throughput::Elements(points.len() as u64));
    g.bench_function("multi_intersections", |b| {
        b.iter(|| {
            points
                .iter()
                .filter_map(|&(x, y, h)| net.locate(x, y, Some(h)))
                .count()
        })
    });
    // The 60 MB grid: 10 000 points spread over its roads (arterials and junctions alike).
    let grid = RoadNetwork::from_str(&grid::grid_for_bytes(60_000_000), Path::new("grid.xodr"))
        .unwrap_or_else(|e| panic!("{e}"));
    let points = spread_points(&grid, 10_000);
    g.throughput(Throughput::Elements(points.len() as u64));
    g.bench_function("grid_60MB", |b| {
        b.iter(|| {
            points
                .iter()
                .filter_map(|&(x, y, h)| grid.locate_point(x, y, Some(h)))
                .count()
        })
    });
    g.bench_function("grid_60MB_with_ids", |b| {
        b.iter(|| {
            points
                .iter()
                .filter_map(|&(x, y, h)| grid.locate(x, y, Some(h)))
                .count()
        })
    });
    g.finish();
}

/// `n` lane-centre points spread over all roads of `net`, shifted sideways by up to ±1.5 m,
/// with the lane's heading.
fn spread_points(net: &RoadNetwork, n: usize) -> Vec<(f64, f64, f64)> {
    let mut points = Vec::new();
    let roads = net.roads();
    for k in 0..n {
        let r = &roads[k % roads.len()];
        let s = r.length * ((k * 7919) % 1000) as f64 / 1000.0;
        let lane = r.lane_section_at(s).lanes().nth(k % 3).map_or(0, |l| l.id);
        if let Ok(p) = r.lane_pose(lane, s, ((k % 7) as f64 - 3.0) * 0.5) {
            points.push((p.x, p.y, p.h));
        }
    }
    points
}

fn route(c: &mut Criterion) {
    let mut g = c.benchmark_group("route");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(2));
    let net = load_corpus_network("esmini/xodr/multi_intersections.xodr");
    // From every drivable right lane at s = 1 of the first 20 roads to the same lane kind of the
    // last 20: a mix of reachable and unreachable targets across the grid of junctions.
    let roads = net.roads();
    let pick = |r: &opendrive::Road| {
        r.lane_section_at(1.0)
            .right
            .iter()
            .find(|l| l.lane_type.is_drivable())
            .map(|l| opendrive::LanePosition {
                road_id: r.id.clone(),
                lane_id: l.id,
                s: 1.0,
                offset: 0.0,
            })
    };
    let pairs: Vec<_> = roads
        .iter()
        .take(20)
        .zip(roads.iter().rev().take(20))
        .filter_map(|(a, b)| Some((pick(a)?, pick(b)?)))
        .collect();
    g.throughput(Throughput::Elements(pairs.len() as u64));
    g.bench_function("multi_intersections", |b| {
        b.iter(|| pairs.iter().filter_map(|(a, z)| net.route(a, z)).count())
    });
    g.finish();
}

/// The lane graph's queries on the junction network `multi_intersections.xodr`: the
/// successors and predecessors of every lane of every lane section (the route search's and the
/// engine's lane walks' step), per lane.
fn lane_graph(c: &mut Criterion) {
    let mut g = c.benchmark_group("lane_graph");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(2));
    let net = load_corpus_network("esmini/xodr/multi_intersections.xodr");
    let handles: Vec<opendrive::LaneHandle> = net
        .roads()
        .iter()
        .enumerate()
        .flat_map(|(ri, r)| {
            r.lane_sections
                .iter()
                .enumerate()
                .flat_map(move |(k, sec)| {
                    sec.left
                        .iter()
                        .chain(&sec.right)
                        .map(move |l| opendrive::LaneHandle {
                            road: ri as u32,
                            section: k as u32,
                            lane: l.id,
                        })
                })
        })
        .collect();
    g.throughput(Throughput::Elements(handles.len() as u64));
    g.bench_function("successors_multi_intersections", |b| {
        b.iter(|| {
            handles
                .iter()
                .map(|&h| black_box(net.successors(black_box(h))).len())
                .sum::<usize>()
        })
    });
    g.bench_function("predecessors_multi_intersections", |b| {
        b.iter(|| {
            handles
                .iter()
                .map(|&h| black_box(net.predecessors(black_box(h))).len())
                .sum::<usize>()
        })
    });
    g.finish();
}

fn load_corpus_network(rel: &str) -> RoadNetwork {
    RoadNetwork::from_file(&corpus(rel)).unwrap_or_else(|e| panic!("{e}"))
}

criterion_group!(benches, load, road_pose, locate, route, lane_graph);
criterion_main!(benches);
