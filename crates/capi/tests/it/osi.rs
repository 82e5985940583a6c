//! OSI bytes through the C API (called from Rust through the rlib, the same functions C
//! calls): a simulation made with `osi = 1` hands out each frame's GroundTruth; they decode
//! as osi3.GroundTruth with both entities of the cut-in under the same ids in every frame,
//! time stamps k·dt, and lanes in the first frame only.
// These tests call the C API through its raw pointers, as a C program does: the workspace
// lint unsafe_code is allowed here as in the capi crate itself.
#![allow(unsafe_code)]

use std::ffi::CString;

use oscsim::*;
use osi::osi3::GroundTruth;
use prost::Message;

#[test]
fn osi_frames_decode_with_stable_ids() {
    let path = CString::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/scenarios/cut_in_highway.xosc"
    ))
    .expect("no NUL in the path");
    let mut config = oscsim_config_default();
    config.osi = 1;
    let mut sim = std::ptr::null_mut();
    // SAFETY: valid string, readable config, writable out pointer.
    let status =
        unsafe { oscsim_simulation_new(path.as_ptr(), std::ptr::null(), 0, &config, &mut sim) };
    assert_eq!(status, OscsimStatus::Ok);
    let mut frames: Vec<GroundTruth> = Vec::new();
    let mut reason = OscsimStopReason::Running;
    while reason == OscsimStopReason::Running {
        // SAFETY: a live handle and writable outputs throughout.
        unsafe {
            assert_eq!(oscsim_simulation_step(sim, &mut reason), OscsimStatus::Ok);
            let mut count = 0;
            assert_eq!(
                oscsim_simulation_osi_frame_count(sim, &mut count),
                OscsimStatus::Ok
            );
            for i in 0..count {
                let (mut data, mut len) = (std::ptr::null(), 0);
                let status = oscsim_simulation_osi_ground_truth(sim, i, &mut data, &mut len);
                assert_eq!(status, OscsimStatus::Ok);
                let bytes = std::slice::from_raw_parts(data, len);
                frames.push(GroundTruth::decode(bytes).expect("osi3.GroundTruth bytes"));
            }
        }
    }
    // SAFETY: freed once.
    unsafe { oscsim_simulation_free(sim) };
    // 10 s of 0.05 s steps: 200 steps, 201 frames (t = 0 too).
    assert_eq!(frames.len(), 201);
    let ids = |gt: &GroundTruth| -> Vec<u64> {
        gt.moving_object
            .iter()
            .map(|o| o.id.as_ref().and_then(|i| i.value).expect("an id"))
            .collect()
    };
    let first = ids(&frames[0]);
    assert_eq!(first.len(), 2);
    for (k, gt) in frames.iter().enumerate() {
        assert_eq!(ids(gt), first, "frame {k}");
        let ts = gt.timestamp.as_ref().expect("a time stamp");
        let nanos = ts.seconds.unwrap_or(0) as u64 * 1_000_000_000 + ts.nanos.unwrap_or(0) as u64;
        assert_eq!(nanos, k as u64 * 50_000_000, "frame {k}");
        assert_eq!(gt.lane.is_empty(), k > 0, "lanes in frame {k}");
    }
}

#[test]
fn osi_needs_the_flag() {
    let path = CString::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/scenarios/cut_in_highway.xosc"
    ))
    .expect("no NUL in the path");
    let mut sim = std::ptr::null_mut();
    // SAFETY: as above; null config means the defaults (osi = 0).
    unsafe {
        let status = oscsim_simulation_new(
            path.as_ptr(),
            std::ptr::null(),
            0,
            std::ptr::null(),
            &mut sim,
        );
        assert_eq!(status, OscsimStatus::Ok);
        let mut count = 0;
        let status = oscsim_simulation_osi_frame_count(sim, &mut count);
        assert_eq!(status, OscsimStatus::Argument);
        oscsim_simulation_free(sim);
    }
}
