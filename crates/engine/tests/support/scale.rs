//! The scale highway of issue 17, written by Rust for the benchmarks and the allocation test:
//! the same road and scenario as `../shared/tools/make_scale.py OUT N DURATION` (the file
//! esmini's figures in `../shared/corpus/reference/performance.md` were measured on), so a
//! figure measured here and one measured with `oscsim run` on the tool's output describe the
//! same work: one straight road "1" of 20 km with 4 driving lanes of 3.5 m each way; vehicle
//! `v{i}` (4.5 m × 2 m, box centre 1.4 m ahead of the reference point) in lane −(1 + i mod 4)
//! at s = 100 + 15·⌊i / 4⌋ m, at 20 + (i mod 7) m/s (a step SpeedAction in Init), on the
//! default controller; the storyboard stops when SimulationTime > DURATION.
//! (The tool's files also carry road marks and a date; neither changes the motion.)
//!
//! [`write_traffic`] writes the driver-model traffic of issue 31 on it, as
//! `scripts/traffic_scale.py oscsim` makes it from the tool's file: each vehicle with an
//! ObjectController of a built-in model (`idm`, `mobil`), activated in its Init after the
//! SpeedAction (longitudinal; for `mobil` lateral too), so its desired speed is its start
//! speed.

#![allow(dead_code)] // each target uses a different part

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Writes `xodr/highway_20km.xodr` and `xosc/scale_{vehicles}.xosc` under `dir` (created if
/// missing) and returns the scenario's path.
pub fn write_scale(dir: &Path, vehicles: usize, duration: f64) -> PathBuf {
    write(dir, vehicles, duration, None)
}

/// Writes the highway with every vehicle driven by `model` (`idm`, `mobil`; module doc) as
/// `xosc/{model}_{vehicles}.xosc` and returns its path.
pub fn write_traffic(dir: &Path, vehicles: usize, duration: f64, model: &str) -> PathBuf {
    write(dir, vehicles, duration, Some(model))
}

fn write(dir: &Path, vehicles: usize, duration: f64, model: Option<&str>) -> PathBuf {
    let (xodr_dir, xosc_dir) = (dir.join("xodr"), dir.join("xosc"));
    std::fs::create_dir_all(&xodr_dir).expect("xodr folder");
    std::fs::create_dir_all(&xosc_dir).expect("xosc folder");
    std::fs::write(xodr_dir.join("highway_20km.xodr"), highway()).expect("road written");
    let name = model.unwrap_or("scale");
    let path = xosc_dir.join(format!("{name}_{vehicles}.xosc"));
    std::fs::write(&path, scenario(vehicles, duration, model)).expect("scenario written");
    path
}

/// A fresh scratch folder of its own for `what` below the system's temporary folder, removed
/// with everything in it when the returned value drops (at the end of the test or benchmark
/// that holds it, also when it fails).
pub fn scratch(what: &str) -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix(&format!("oscsim-{what}-"))
        .tempdir()
        .expect("the temporary folder is writable")
}

/// The 20 km road, 4 lanes of 3.5 m each way.
fn highway() -> String {
    let lane = |id: i32| {
        format!(
            r#"<lane id="{id}" type="driving" level="false"><link/><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane>"#
        )
    };
    let left: String = (1..=4).rev().map(lane).collect();
    let right: String = (1..=4).map(|i| lane(-i)).collect();
    format!(
        r#"<?xml version="1.0"?><OpenDRIVE><header name="highway_20km" revMajor="1" revMinor="5"/>
<road rule="RHT" id="1" junction="-1" length="20000"><link/><planView><geometry s="0" x="0" y="0" hdg="0" length="20000"><line/></geometry></planView><elevationProfile/><lateralProfile/>
<lanes><laneSection s="0"><left>{left}</left><center><lane id="0" type="none" level="false"/></center><right>{right}</right></laneSection></lanes></road></OpenDRIVE>"#
    )
}

/// The scenario: `vehicles` vehicles, each driven by `model` if given, stop after `duration` s.
fn scenario(vehicles: usize, duration: f64, model: Option<&str>) -> String {
    let (mut objects, mut init) = (String::new(), String::new());
    let (controller, activate) = match model {
        Some(m) => (
            format!(
                r#"<ObjectController name="driver"><Controller name="driver"><Properties><Property name="model" value="{m}"/></Properties></Controller></ObjectController>"#
            ),
            format!(
                r#"<PrivateAction><ControllerAction><ActivateControllerAction longitudinal="true" lateral="{}"/></ControllerAction></PrivateAction>"#,
                m == "mobil"
            ),
        ),
        None => (String::new(), String::new()),
    };
    for i in 0..vehicles {
        let lane = -(1 + (i % 4) as i32);
        let s = 100.0 + 15.0 * (i / 4) as f64;
        let speed = 20.0 + (i % 7) as f64;
        let _ = write!(
            objects,
            r#"<ScenarioObject name="v{i}"><Vehicle name="v{i}" vehicleCategory="car"><BoundingBox><Center x="1.4" y="0.0" z="0.75"/><Dimensions width="2.0" length="4.5" height="1.5"/></BoundingBox><Performance maxSpeed="70.0" maxDeceleration="10.0" maxAcceleration="10.0"/><Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.8" trackWidth="1.68" positionX="2.98" positionZ="0.4"/><RearAxle maxSteering="0.0" wheelDiameter="0.8" trackWidth="1.68" positionX="0.0" positionZ="0.4"/></Axles></Vehicle>{controller}</ScenarioObject>"#
        );
        let _ = write!(
            init,
            r#"<Private entityRef="v{i}"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="{lane}" s="{s:.1}" offset="0.0"/></Position></TeleportAction></PrivateAction><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" value="0.0" dynamicsDimension="time"/><SpeedActionTarget><AbsoluteTargetSpeed value="{speed:.1}"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>{activate}</Private>"#
        );
    }
    format!(
        r#"<?xml version="1.0"?><OpenSCENARIO><FileHeader description="scale_{vehicles}" author="oscsim" revMajor="1" revMinor="3" date="2026-11-26T00:00:00"/><CatalogLocations/><RoadNetwork><LogicFile filepath="../xodr/highway_20km.xodr"/></RoadNetwork>
<Entities>{objects}</Entities><Storyboard><Init><Actions>{init}</Actions></Init><StopTrigger><ConditionGroup><Condition name="stop" delay="0.0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="{duration:.1}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"#
    )
}
