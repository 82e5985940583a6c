//! Issue 17 "the OSI writer … reuses the message": a steady-state OSI frame of the scale
//! highway's 200 vehicles allocates nothing. The engine steps with an `OsiSink` writing a
//! `.osi` trace (`oscsim run --osi FILE`) under a counting global allocator (the engine's
//! tests/support/counting.rs; the highway is its tests/support/scale.rs). Before the message
//! was reused: about ten allocations per moving object and frame (docs/performance.md).
//!
//! Its own test target because the counting allocator is the whole binary's.

#[path = "../../engine/tests/support/scale.rs"]
mod scale;

#[path = "../../engine/tests/support/counting.rs"]
mod counting;

use counting::{allocations, serial};
use engine::{Engine, EngineConfig, FrameSink};
use osi::sink::{OsiSink, OsiSinkOptions};

/// Vehicles of the highway (as the engine's allocation test).
const VEHICLES: usize = 200;
/// Steps before counting: the first writes the frames at t = 0 (with the lanes) and t = dt;
/// the message's lists and strings and the encoding buffer reach their size.
const WARM_UP: usize = 5;
/// Steps counted.
const COUNTED: usize = 100;

/// 100 steps of 200 vehicles with the OSI trace: not one allocation; the trace then holds
/// the frames of t = 0 and the 105 steps, each with every vehicle at its hand-computed place.
#[test]
fn a_steady_osi_frame_allocates_nothing() {
    let _serial = serial();
    let dir = scale::scratch("alloc-osi");
    let path = scale::write_scale(dir.path(), VEHICLES, 300.0);
    let mut engine = Engine::load(&path, &[], EngineConfig::default()).expect("the highway loads");
    let trace = dir.path().join("trace.osi");
    let options = OsiSinkOptions {
        pinned_time: Some(0),
        ..OsiSinkOptions::new(trace.clone())
    };
    let mut sink = OsiSink::create(&engine, &options).expect("trace created");
    for _ in 0..WARM_UP {
        engine.step(&mut sink, &mut ()).expect("steps");
    }
    let n = allocations(|| {
        for _ in 0..COUNTED {
            engine.step(&mut sink, &mut ()).expect("steps");
        }
    });
    assert_eq!(
        n, 0,
        "allocations in {COUNTED} OSI frames of {VEHICLES} vehicles"
    );
    sink.finish().expect("trace finished");

    let bytes = std::fs::read(&trace).expect("trace written");
    let frames = osi::trace::read_osi_bytes(&bytes, &trace).expect("trace decodes");
    // The frame at t = 0 and one per step: 1 + 5 + 100.
    assert_eq!(frames.len(), 106);
    // Ids: the road's 8 lanes and 9 boundaries (4 outer borders each side and the centre
    // line) take 1..=17, so vehicle v{i} is 18 + i in every frame.
    for (k, gt) in frames.iter().enumerate() {
        assert_eq!(gt.moving_object.len(), VEHICLES, "frame {k}");
        assert_eq!(gt.lane.len(), if k == 0 { 8 } else { 0 }, "frame {k}");
        for (i, o) in gt.moving_object.iter().enumerate() {
            assert_eq!(o.id.and_then(|id| id.value), Some(18 + i as u64));
        }
    }
    // v0: lane −1 (centre y = −1.75), s = 100 m at 20 m/s; the box centre 1.4 m ahead and
    // 0.75 m up: at t = 105 · 0.05 = 5.25 s, (100 + 20 · 5.25 + 1.4, −1.75, 0.75) =
    // (206.4, −1.75, 0.75). v5: lane −2 (y = −5.25), s = 115 m at 25 m/s: x = 115 + 25 · 5.25
    // + 1.4 = 247.65.
    const TOLERANCE: f64 = 1e-9;
    let last = &frames[105];
    let at = |i: usize| {
        let p = last.moving_object[i]
            .base
            .as_ref()
            .and_then(|b| b.position)
            .expect("set");
        [
            p.x.unwrap_or(f64::NAN),
            p.y.unwrap_or(f64::NAN),
            p.z.unwrap_or(f64::NAN),
        ]
    };
    for (got, want) in at(0).iter().zip([206.4, -1.75, 0.75]) {
        assert!((got - want).abs() < TOLERANCE, "v0 at {:?}", at(0));
    }
    for (got, want) in at(5).iter().zip([247.65, -5.25, 0.75]) {
        assert!((got - want).abs() < TOLERANCE, "v5 at {:?}", at(5));
    }
}

/// Traffic lights and signs are written in place too: on the cli's osi_signals.xosc (a vehicle
/// light S1, a pedestrian light S2 that turns green at t = 3 s, a static speed-limit sign), 100
/// steps with the OSI sink allocate exactly what the same 100 steps of a second engine allocate
/// without it, so the sink adds none (whatever the engine's own share).
#[test]
fn traffic_signals_add_no_allocation() {
    use osi::osi3::traffic_light::classification::Mode;
    let _serial = serial();
    let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../cli/tests/files/osi_signals.xosc");
    let load = || Engine::load(&file, &[], EngineConfig::default()).expect("the scenario loads");
    let (mut with, mut without) = (load(), load());
    let dir = scale::scratch("alloc-osi-signals");
    let trace = dir.path().join("trace.osi");
    let options = OsiSinkOptions {
        pinned_time: Some(0),
        ..OsiSinkOptions::new(trace.clone())
    };
    let mut sink = OsiSink::create(&with, &options).expect("trace created");
    for _ in 0..WARM_UP {
        with.step(&mut sink, &mut ()).expect("steps");
        without.step(&mut (), &mut ()).expect("steps");
    }
    let with_sink = allocations(|| {
        for _ in 0..COUNTED {
            with.step(&mut sink, &mut ()).expect("steps");
        }
    });
    let engine_alone = allocations(|| {
        for _ in 0..COUNTED {
            without.step(&mut (), &mut ()).expect("steps");
        }
    });
    assert_eq!(
        with_sink, engine_alone,
        "allocations with / without the OSI sink"
    );
    sink.finish().expect("trace finished");

    let frames = osi::trace::read_osi(&trace).expect("trace decodes");
    assert_eq!(frames.len(), 106);
    // The sign goes with the static data (first frame only), the 3 + 2 bulbs in every frame.
    assert_eq!(frames[0].traffic_sign.len(), 1);
    assert!(frames[1..].iter().all(|f| f.traffic_sign.is_empty()));
    assert!(frames.iter().all(|f| f.traffic_light.len() == 5));
    // At t = 5.25 s: S1 in "go" (off;off;on), S2 in "walk" since 3 s (off;on).
    let modes: Vec<Option<i32>> = frames[105]
        .traffic_light
        .iter()
        .map(|l| l.classification.as_ref().and_then(|c| c.mode))
        .collect();
    let (off, on) = (Some(Mode::Off as i32), Some(Mode::Constant as i32));
    assert_eq!(modes, [off, off, on, off, on]);
}

/// The bindings' sink (`StepFrames`: each step's frames encoded for Python and C) reuses its
/// buffers too: 100 steps of the 200 vehicles, `begin_step` before each, allocate nothing; the
/// newest frame is that of t = 105 · 0.05 = 5.25 s with every vehicle.
#[test]
fn the_bindings_frames_allocate_nothing() {
    use osi::sink::{GroundTruthSink, SinkOptions, StepFrames};
    use prost::Message;
    let _serial = serial();
    let dir = scale::scratch("alloc-osi-bindings");
    let path = scale::write_scale(dir.path(), VEHICLES, 300.0);
    let mut engine = Engine::load(&path, &[], EngineConfig::default()).expect("the highway loads");
    let sink = GroundTruthSink::new(&engine, &SinkOptions::default()).expect("sink");
    let mut frames = StepFrames::new(sink);
    for _ in 0..WARM_UP {
        frames.begin_step();
        engine.step(&mut frames, &mut ()).expect("steps");
    }
    let n = allocations(|| {
        for _ in 0..COUNTED {
            frames.begin_step();
            engine.step(&mut frames, &mut ()).expect("steps");
        }
    });
    assert_eq!(n, 0, "allocations in {COUNTED} steps with StepFrames");
    assert_eq!(frames.frames().len(), 1);
    let gt = osi::osi3::GroundTruth::decode(frames.latest()).expect("decodes");
    let t = gt.timestamp.expect("timestamp");
    assert_eq!((t.seconds, t.nanos), (Some(5), Some(250_000_000)));
    assert_eq!(gt.moving_object.len(), VEHICLES);
}
