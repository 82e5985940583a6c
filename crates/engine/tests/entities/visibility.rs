//! VisibilityAction in the engine's frames (OpenSCENARIO 1.3 XSD `VisibilityAction`: the actor
//! is visible in image generators `graphics`, in sensors `sensors`, for other traffic
//! participants `traffic`; all three true until an action changes them). The OSI side is
//! `crates/cli/tests/osi/visibility.rs`, on the same scenario.

use std::path::PathBuf;

use engine::output::{Frame, FrameSink};
use engine::runtime::Visibility;
use engine::{Engine, EngineConfig};

/// `(time, entity name, visibility)` of every entity in every frame.
#[derive(Default)]
struct Flags(Vec<(f64, String, Visibility)>);

impl FrameSink for Flags {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), engine::SinkError> {
        for e in frame.objects() {
            self.0.push((frame.time, e.name.to_owned(), e.visibility));
        }
        Ok(())
    }
}

/// osi_visibility.xosc: "hideEgo" (graphics on, sensors off, traffic on) runs in the step at
/// 0.5 s, "hideTarget" (the same flags) at 1 s, "showTarget" (graphics off, sensors on,
/// traffic off) at 2 s. An action of the step at T shows from the frame at T + 0.05 s.
#[test]
fn frames_carry_the_flags_each_visibility_action_set() {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../cli/tests/files"))
        .join("osi_visibility.xosc");
    let mut engine = Engine::load(&path, &[], EngineConfig::default()).expect("loads");
    let mut flags = Flags::default();
    engine.run(&mut flags, &mut Vec::new()).expect("runs");
    let all = Visibility::default();
    assert!(all.graphics && all.sensors && all.traffic);
    let hidden = Visibility {
        sensors: false,
        ..all
    };
    let shown = Visibility {
        graphics: false,
        sensors: true,
        traffic: false,
    };
    let mut checked = 0;
    for (t, name, v) in &flags.0 {
        let expected = match name.as_str() {
            "Ego" if *t > 0.5 + 1e-6 => hidden,
            "Target" if *t > 2.0 + 1e-6 => shown,
            "Target" if *t > 1.0 + 1e-6 => hidden,
            _ => all,
        };
        assert_eq!(*v, expected, "{name} at {t}");
        checked += 1;
    }
    // Two entities in each of the 61 frames, 0 to 3 s.
    assert_eq!(checked, 2 * 61);
}
