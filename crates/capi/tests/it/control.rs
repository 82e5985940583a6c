//! External-controller inputs through the C API (called from Rust through the rlib, the same
//! functions C calls): Ego of the bundled cut-in, handed to the program after the first step,
//! braked at 5 m/s² for 1 s from 25 m/s ends at 20 m/s; inputs before the hand-over, out of
//! range or for unknown entities are refused with their status.
// These tests call the C API through its raw pointers, as a C program does: the workspace
// lint unsafe_code is allowed here as in the capi crate itself.
#![allow(unsafe_code)]

use std::ffi::CString;

use oscsim::*;

fn speed(sim: *mut OscsimSimulation, name: &CString) -> f64 {
    let (mut index, mut state) = (0, std::mem::MaybeUninit::<OscsimEntityState>::uninit());
    // SAFETY: a live handle, a valid name, writable outputs.
    unsafe {
        assert_eq!(
            oscsim_simulation_find_entity(sim, name.as_ptr(), &mut index),
            OscsimStatus::Ok
        );
        let status = oscsim_simulation_entity_state(sim, index, state.as_mut_ptr());
        assert_eq!(status, OscsimStatus::Ok);
        state.assume_init().speed
    }
}

#[test]
fn acceleration_pedals_and_refusals() {
    let path = CString::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/scenarios/cut_in_highway.xosc"
    ))
    .expect("no NUL");
    let (ego, nobody) = (
        CString::new("Ego").expect("no NUL"),
        CString::new("Nobody").expect("no NUL"),
    );
    let mut sim = std::ptr::null_mut();
    // SAFETY: valid strings, live handle, writable outputs throughout; freed once at the end.
    unsafe {
        assert_eq!(
            oscsim_simulation_new(
                path.as_ptr(),
                std::ptr::null(),
                0,
                std::ptr::null(),
                &mut sim
            ),
            OscsimStatus::Ok
        );
        assert_eq!(
            oscsim_simulation_step(sim, std::ptr::null_mut()),
            OscsimStatus::Ok
        );
        let refused = oscsim_simulation_set_acceleration(sim, ego.as_ptr(), -5.0, f64::NAN);
        assert_eq!(refused, OscsimStatus::NotExternal);
        let unknown = oscsim_simulation_attach_external(sim, nobody.as_ptr());
        assert_eq!(unknown, OscsimStatus::NotExternal);
        assert_eq!(
            oscsim_simulation_attach_external(sim, ego.as_ptr()),
            OscsimStatus::Ok
        );
        let set = oscsim_simulation_set_acceleration(sim, ego.as_ptr(), -5.0, f64::NAN);
        assert_eq!(set, OscsimStatus::Ok);
        for _ in 0..20 {
            assert_eq!(
                oscsim_simulation_step(sim, std::ptr::null_mut()),
                OscsimStatus::Ok
            );
        }
        // 25 m/s − 5 m/s² · 20 · 0.05 s = 20 m/s.
        assert!(
            (speed(sim, &ego) - 20.0).abs() < 1e-9,
            "{}",
            speed(sim, &ego)
        );
        let bad = oscsim_simulation_set_pedals(sim, ego.as_ptr(), 1.5, 0.0, 0.0);
        assert_eq!(bad, OscsimStatus::Argument);
        let bad =
            oscsim_simulation_set_pose(sim, ego.as_ptr(), f64::INFINITY, 0.0, 0.0, 0.0, 0.0, 0.0);
        assert_eq!(bad, OscsimStatus::Argument);
        let brake = oscsim_simulation_set_pedals(sim, ego.as_ptr(), 0.0, 1.0, 0.0);
        assert_eq!(brake, OscsimStatus::Ok);
        assert_eq!(
            oscsim_simulation_step(sim, std::ptr::null_mut()),
            OscsimStatus::Ok
        );
        assert!(speed(sim, &ego) < 20.0);
        oscsim_simulation_free(sim);
    }
}
