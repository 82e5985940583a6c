//! The example examples/aeb_cut_in.rs as a test (issue 13): on the bundled cut-in, Ego under
//! the default controller runs into OverTaker (it keeps 25 m/s while OverTaker, cut in ahead,
//! brakes to 15 m/s: the boxes meet at 14.55 s), and the example's AEB, driving Ego as an
//! `external` controller, brakes in time and keeps a positive gap.

use crate::aeb;

#[test]
fn default_controller_collides_and_the_aeb_avoids_it() {
    let path = aeb::scenario_path();
    let default = aeb::run(&path, false).expect("default run");
    assert!(default.collided, "{default:?}");
    assert!(default.braked_at.is_none());
    let with_aeb = aeb::run(&path, true).expect("AEB run");
    assert!(!with_aeb.collided, "{with_aeb:?}");
    assert!(with_aeb.min_gap > 0.0, "{with_aeb:?}");
    // It braked, after the cut-in (OverTaker starts braking at about 8.4 s), and ends no
    // faster than OverTaker's 15 m/s.
    let t = with_aeb.braked_at.expect("the AEB braked");
    assert!(t > 8.0, "braked at {t}");
    assert!(with_aeb.final_speed <= 15.0 + 1e-9, "{with_aeb:?}");
}
