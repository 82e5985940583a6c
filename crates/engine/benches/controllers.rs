//! Controllers stage cost (issue 13): entity-steps per second for 1,000 vehicles, each driven by
//! an `idm` controller, on the scale highway of `shared/tools/make_scale.py`: one straight 20 km
//! road with 4 lanes each way, 3.5 m wide; vehicle i in lane −(1 + i mod 4) at
//! s = 100 + 15·⌊i/4⌋ m, 20 + (i mod 7) m/s, a 4.5 m × 2 m car (the script's layout), here with
//! an ObjectController `idm` (the model's defaults, desired speed = the start speed) activated
//! on the longitudinal domain in the Init. Each step builds the per-lane index and answers one
//! leader query per vehicle. For comparison the same road and vehicles under the default
//! controller. The scenario is written to a temporary folder at start-up.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use engine::{Engine, EngineConfig};
use std::fmt::Write as _;
use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// Vehicles.
const VEHICLES: usize = 1_000;
/// Steps per measured iteration.
const STEPS: u64 = 20;

fn road(dir: &Path) {
    let lane = |id: i32| {
        format!(
            r#"<lane id="{id}" type="driving" level="false"><link/><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>"#
        )
    };
    let left: String = (1..=4).rev().map(lane).collect();
    let right: String = (1..=4).map(|i| lane(-i)).collect();
    let xodr = format!(
        r#"<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="6" name="highway_20km"/>
<road id="1" junction="-1" length="20000"><link/><planView><geometry s="0" x="0" y="0" hdg="0" length="20000"><line/></geometry></planView>
<lanes><laneSection s="0"><left>{left}</left><center><lane id="0" type="none" level="false"/></center><right>{right}</right></laneSection></lanes></road></OpenDRIVE>"#
    );
    std::fs::write(dir.join("highway_20km.xodr"), xodr).expect("road written");
}

/// Writes the scenario with `VEHICLES` vehicles, with an `idm` controller each or not.
fn scenario(dir: &Path, idm: bool) -> PathBuf {
    let (mut objects, mut init) = (String::new(), String::new());
    let controller = if idm {
        r#"<ObjectController name="driver"><Controller name="driver"><Properties><Property name="model" value="idm"/></Properties></Controller></ObjectController>"#
    } else {
        ""
    };
    let activate = if idm {
        r#"<PrivateAction><ControllerAction><ActivateControllerAction longitudinal="true"/></ControllerAction></PrivateAction>"#
    } else {
        ""
    };
    for i in 0..VEHICLES {
        let lane = -((i % 4) as i32) - 1;
        let s = 100.0 + 15.0 * (i / 4) as f64;
        let speed = 20.0 + (i % 7) as f64;
        let _ = write!(
            objects,
            r#"<ScenarioObject name="v{i}"><Vehicle name="v{i}" vehicleCategory="car"><BoundingBox><Center x="1.4" y="0" z="0.75"/><Dimensions width="2" length="4.5" height="1.5"/></BoundingBox><Performance maxSpeed="70" maxAcceleration="10" maxDeceleration="10"/><Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.8" trackWidth="1.68" positionX="2.98" positionZ="0.4"/><RearAxle maxSteering="0" wheelDiameter="0.8" trackWidth="1.68" positionX="0" positionZ="0.4"/></Axles><Properties/></Vehicle>{controller}</ScenarioObject>"#
        );
        let _ = write!(
            init,
            r#"<Private entityRef="v{i}"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="{lane}" offset="0" s="{s}"/></Position></TeleportAction></PrivateAction><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/><SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>{activate}</Private>"#
        );
    }
    let xosc = format!(
        r#"<?xml version="1.0"?><OpenSCENARIO><FileHeader revMajor="1" revMinor="3" date="2026-11-26T00:00:00" description="scale" author="oscsim"/>
<ParameterDeclarations/><CatalogLocations/><RoadNetwork><LogicFile filepath="highway_20km.xodr"/></RoadNetwork>
<Entities>{objects}</Entities><Storyboard><Init><Actions>{init}</Actions></Init><StopTrigger><ConditionGroup><Condition name="never" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="1e9" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"#
    );
    let path = dir.join(if idm { "scale_idm.xosc" } else { "scale.xosc" });
    std::fs::write(&path, xosc).expect("scenario written");
    path
}

fn highway(c: &mut Criterion) {
    let dir = std::env::temp_dir().join(format!("oscsim-bench-controllers-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp folder");
    road(&dir);
    let config = EngineConfig {
        max_time: 1e9,
        ..EngineConfig::default()
    };
    let mut group = c.benchmark_group("controllers");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(5));
    group.throughput(Throughput::Elements(VEHICLES as u64 * STEPS));
    for (label, idm) in [
        ("1000 vehicles, idm", true),
        ("1000 vehicles, default controller", false),
    ] {
        let path = scenario(&dir, idm);
        let mut engine = Engine::load(&path, &[], config).expect("scale scenario loads");
        group.bench_function(label, |b| {
            b.iter(|| {
                for _ in 0..STEPS {
                    black_box(engine.step(&mut (), &mut ()).expect("steps"));
                }
            })
        });
    }
    group.finish();
    let _ = std::fs::remove_dir_all(&dir);
}

criterion_group!(benches, highway);
criterion_main!(benches);
