//! Runtime cost: (1) wall time of the whole esmini cut-in scenario (build from the loaded
//! model, 22 s simulated at dt = 0.05 s, CSV and event log to memory); (2) entity-steps per
//! second for 1 000 vehicles on a 200 km straight road with 4 lanes under the default
//! controller (the scenario is written to a temporary folder at start-up); (3) the whole
//! esmini synchronize scenario (SynchronizeAction).

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use engine::output::{CsvWriter, JsonlWriter};
use engine::{Engine, EngineConfig};
use std::fmt::Write as _;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Duration;

/// Vehicles in the traffic benchmark.
const VEHICLES: usize = 1_000;
/// Steps per measured iteration of the traffic benchmark.
const STEPS: u64 = 20;

/// Wall time of a whole run of the esmini corpus scenario `file`: build from the loaded model,
/// run to the storyboard's end, CSV and event log to memory.
fn whole_run(c: &mut Criterion, group: &str, file: &str, measurement: Duration) {
    let path = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/corpus/esmini/xosc"
    ))
    .join(file);
    let Ok(scenario) = scenario::Scenario::load(&path) else {
        eprintln!("{file} not found; skipping");
        return;
    };
    let mut group = c.benchmark_group(group);
    group.sample_size(10).measurement_time(measurement);
    group.bench_function(format!("{file} whole run"), |b| {
        b.iter(|| {
            // The road network is read in every iteration, as a one-off run reads it.
            let network = engine::load::road_network(&scenario).expect("road network loads");
            let mut engine =
                Engine::new(&scenario, network, EngineConfig::default()).expect("builds");
            let mut csv = CsvWriter::new(Vec::new());
            let mut events = JsonlWriter::new(Vec::new());
            engine.run(&mut csv, &mut events).expect("runs");
            black_box(csv.into_inner().len())
        })
    });
    group.finish();
}

fn cut_in(c: &mut Criterion) {
    whole_run(c, "runtime", "cut-in.xosc", Duration::from_secs(5));
}

/// SynchronizeAction cost: synchronize.xosc, 32.2 s simulated = 644 steps, seven vehicles of
/// which four synchronise with the master for 10 s.
fn synchronize(c: &mut Criterion) {
    whole_run(c, "synchronize", "synchronize.xosc", Duration::from_secs(3));
}

/// Writes the straight road and a scenario with `VEHICLES` vehicles to a temporary folder.
fn traffic_scenario() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("oscsim-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp folder");
    let mut lanes = String::new();
    for id in 1..=4 {
        let _ = write!(
            lanes,
            r#"<lane id="-{id}" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>"#
        );
    }
    let road = format!(
        r#"<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" junction="-1" length="200000"><link/><planView><geometry s="0" x="0" y="0" hdg="0" length="200000"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none" level="false"/></center><right>{lanes}</right></laneSection></lanes></road></OpenDRIVE>"#
    );
    std::fs::write(dir.join("straight.xodr"), road).expect("road written");
    let (mut objects, mut init) = (String::new(), String::new());
    for i in 0..VEHICLES {
        let lane = -((i % 4) as i32) - 1;
        let s = 10.0 + 40.0 * (i / 4) as f64;
        let speed = 20.0 + (i % 7) as f64;
        let _ = write!(
            objects,
            r#"<ScenarioObject name="V{i}"><Vehicle name="car" vehicleCategory="car"><BoundingBox><Center x="1.4" y="0" z="0.75"/><Dimensions width="2" length="5" height="1.5"/></BoundingBox><Performance maxSpeed="70" maxAcceleration="10" maxDeceleration="10"/><Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.8" trackWidth="1.68" positionX="2.98" positionZ="0.4"/><RearAxle maxSteering="0" wheelDiameter="0.8" trackWidth="1.68" positionX="0" positionZ="0.4"/></Axles><Properties/></Vehicle></ScenarioObject>"#
        );
        let _ = write!(
            init,
            r#"<Private entityRef="V{i}"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="{lane}" offset="0" s="{s}"/></Position></TeleportAction></PrivateAction><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/><SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Private>"#
        );
    }
    let xosc = format!(
        r#"<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="3" date="2026-11-21T00:00:00" description="traffic" author="oscsim"/>
<ParameterDeclarations/><CatalogLocations/><RoadNetwork><LogicFile filepath="straight.xodr"/></RoadNetwork>
<Entities>{objects}</Entities><Storyboard><Init><Actions>{init}</Actions></Init><StopTrigger><ConditionGroup><Condition name="never" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="1e9" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"#
    );
    let path = dir.join("traffic.xosc");
    std::fs::write(&path, xosc).expect("scenario written");
    path
}

fn traffic(c: &mut Criterion) {
    let path = traffic_scenario();
    // No cap within the benchmark's reach: the storyboard's stop trigger never fires.
    let config = EngineConfig {
        max_time: 1e9,
        ..EngineConfig::default()
    };
    let mut engine = Engine::load(&path, &[], config).expect("traffic loads");
    let mut group = c.benchmark_group("runtime");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(5));
    group.throughput(Throughput::Elements(VEHICLES as u64 * STEPS));
    group.bench_function("1000 vehicles, default controller", |b| {
        b.iter(|| {
            for _ in 0..STEPS {
                black_box(engine.step(&mut (), &mut ()).expect("steps"));
            }
        })
    });
    group.finish();
    let _ = std::fs::remove_dir_all(path.parent().unwrap_or(&path));
}

criterion_group!(benches, cut_in, traffic, synchronize);
criterion_main!(benches);
