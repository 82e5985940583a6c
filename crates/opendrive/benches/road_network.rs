//! Criterion benchmarks of the road model: load time (largest corpus file and a generated
//! network over 50 MB), (road, s, t) → world evaluations per geometry type, and world → road
//! look-ups and lane routes on `multi_intersections.xodr`. Short runs (sample size 10) so the whole file takes
//! about two minutes.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Duration;

use criterion::{
    black_box, criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode, Throughput,
};
use opendrive::{Arc, Geometry, GeometryKind, ParamPoly3, ParamRange, Poly3, RoadNetwork, Spiral};

fn corpus(rel: &str) -> PathBuf {
    PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus/"
    ))
    .join(rel)
}

/// The plan view of every generated road, relative to its start: (s, x, y, hdg, length, XML),
/// each geometry starting exactly where the previous one ends (computed with the crate's own
/// geometry, so the file is consistent and loads without gap warnings).
fn generated_plan_view() -> Vec<(f64, f64, f64, f64, f64, String)> {
    let pieces: [(f64, GeometryKind, &str); 5] = [
        (40.0, GeometryKind::Line, "<line/>"),
        (
            30.0,
            GeometryKind::Spiral(Spiral::new(0.0, 0.01, 30.0)),
            r#"<spiral curvStart="0" curvEnd="0.01"/>"#,
        ),
        (
            30.0,
            GeometryKind::Arc(Arc { curvature: 0.01 }),
            r#"<arc curvature="0.01"/>"#,
        ),
        (
            30.0,
            GeometryKind::ParamPoly3(ParamPoly3::new(
                [0.0, 1.0, 0.0, 0.0],
                [0.0, 0.0, 0.001, 0.0],
                ParamRange::ArcLength,
                30.0,
            )),
            r#"<paramPoly3 aU="0" bU="1" cU="0" dU="0" aV="0" bV="0" cV="0.001" dV="0" pRange="arcLength"/>"#,
        ),
        (
            30.0,
            GeometryKind::Poly3(Poly3::new(0.0, 0.0, -0.001, 0.0, 30.0)),
            r#"<poly3 a="0" b="0" c="-0.001" d="0"/>"#,
        ),
    ];
    let (mut s, mut x, mut y, mut hdg) = (0.0, 0.0, 0.0, 0.0);
    let mut out = Vec::new();
    for (length, kind, xml) in pieces {
        let end = Geometry::new(s, x, y, hdg, length, kind).eval(s + length);
        out.push((s, x, y, hdg, length, xml.to_string()));
        (s, x, y, hdg) = (s + length, end.x, end.y, end.hdg);
    }
    out
}

/// One road of the generated network: line, spiral, arc, paramPoly3 and poly3, three lanes
/// each side, elevation, an object and a signal. About 2.5 kB of XML.
fn generated_road(
    out: &mut String,
    id: usize,
    x0: f64,
    y0: f64,
    plan: &[(f64, f64, f64, f64, f64, String)],
) {
    let mut geometries = String::new();
    for (s, x, y, hdg, length, xml) in plan {
        let _ = writeln!(
            geometries,
            r#"      <geometry s="{s}" x="{}" y="{}" hdg="{hdg}" length="{length}">{xml}</geometry>"#,
            x0 + x,
            y0 + y
        );
    }
    let _ = write!(
        out,
        r#"  <road id="{id}" length="160" junction="-1">
    <link/>
    <planView>
{geometries}    </planView>
    <elevationProfile><elevation s="0" a="0" b="0.01" c="0" d="0"/></elevationProfile>
    <lateralProfile><superelevation s="0" a="0" b="0" c="0" d="0"/></lateralProfile>
    <lanes>
      <laneOffset s="0" a="0" b="0" c="0" d="0"/>
      <laneSection s="0">
        <left>
          <lane id="3" type="sidewalk" level="false"><width sOffset="0" a="2" b="0" c="0" d="0"/><height sOffset="0" inner="0.12" outer="0.12"/></lane>
          <lane id="2" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/><roadMark sOffset="0" type="broken" weight="standard" color="standard" width="0.12"/></lane>
          <lane id="1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/><roadMark sOffset="0" type="broken" weight="standard" color="standard" width="0.12"/></lane>
        </left>
        <center><lane id="0" type="none" level="false"><roadMark sOffset="0" type="solid" weight="standard" color="standard" width="0.12"/></lane></center>
        <right>
          <lane id="-1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/><roadMark sOffset="0" type="broken" weight="standard" color="standard" width="0.12"/></lane>
          <lane id="-2" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/><roadMark sOffset="0" type="broken" weight="standard" color="standard" width="0.12"/></lane>
          <lane id="-3" type="sidewalk" level="false"><width sOffset="0" a="2" b="0" c="0" d="0"/><height sOffset="0" inner="0.12" outer="0.12"/></lane>
        </right>
      </laneSection>
    </lanes>
    <objects><object id="{id}0" s="20" t="-12" type="pole" zOffset="0" hdg="0" orientation="none" height="3" radius="0.1"/></objects>
    <signals><signal id="{id}1" s="10" t="-11" zOffset="2" orientation="+" dynamic="no" country="DE" type="274" subtype="120" value="120" unit="km/h"/></signals>
  </road>
"#
    );
}

/// A network of disjoint generated roads on a grid, at least `bytes` long.
fn generated_network(bytes: usize) -> String {
    let mut out = String::with_capacity(bytes + 4096);
    out.push_str("<?xml version=\"1.0\"?>\n<OpenDRIVE>\n  <header revMajor=\"1\" revMinor=\"8\" name=\"generated\"/>\n");
    let plan = generated_plan_view();
    let mut id = 0;
    while out.len() < bytes {
        let (row, col) = (id / 100, id % 100);
        generated_road(&mut out, id, col as f64 * 250.0, row as f64 * 120.0, &plan);
        id += 1;
    }
    out.push_str("</OpenDRIVE>\n");
    out
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
    let big = generated_network(50 * 1024 * 1024);
    let big_path = Path::new("generated.xodr");
    // The generated file must be consistent: no warnings, or the figure would time them.
    let probe = RoadNetwork::from_str(&big, big_path).unwrap_or_else(|e| panic!("{e}"));
    assert!(probe.warnings().is_empty(), "{}", probe.warnings()[0]);
    drop(probe);
    g.throughput(Throughput::Bytes(big.len() as u64));
    g.bench_function("generated_50MB", |b| {
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
    // 1000 lane-centre points spread over all roads, shifted sideways by up to ±1.5 m.
    let mut points = Vec::new();
    let roads = net.roads();
    for k in 0..1000usize {
        let r = &roads[k % roads.len()];
        let s = r.length * ((k * 7919) % 1000) as f64 / 1000.0;
        let lane = r.lane_section_at(s).lanes().nth(k % 3).map_or(0, |l| l.id);
        if let Ok(p) = r.lane_pose(lane, s, ((k % 7) as f64 - 3.0) * 0.5) {
            points.push((p.x, p.y, p.h));
        }
    }
    g.throughput(Throughput::Elements(points.len() as u64));
    g.bench_function("multi_intersections", |b| {
        b.iter(|| {
            points
                .iter()
                .filter_map(|&(x, y, h)| net.locate(x, y, Some(h)))
                .count()
        })
    });
    g.finish();
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

fn load_corpus_network(rel: &str) -> RoadNetwork {
    RoadNetwork::from_file(&corpus(rel)).unwrap_or_else(|e| panic!("{e}"))
}

criterion_group!(benches, load, road_pose, locate, route);
criterion_main!(benches);
