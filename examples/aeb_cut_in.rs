//! A system under test in the loop: a simple automatic emergency brake (AEB) drives Ego through
//! the bundled cut-in (examples/scenarios/cut_in_highway.xosc) as an `external` controller.
//!
//! ```sh
//! cargo run -p oscsim-engine --example aeb_cut_in
//! ```
//!
//! The scenario: Ego keeps 25 m/s in lane −2; OverTaker passes at 32 m/s, cuts in 10 m ahead
//! of Ego and brakes at 4 m/s² to 15 m/s. Under the default controller Ego keeps its speed and
//! runs into OverTaker at 14.55 s (the run goes on to [`END_TIME`]). Here the program takes Ego over with [`Engine::attach_external`], and
//! before every step its AEB reads the world (the road positions of Ego and of everything in
//! its path), works out the time to collision and sets Ego's acceleration with
//! [`Engine::set_external_input`]; the lateral domain keeps the lane, as the default controller
//! would. The run prints the closest gap and whether the boxes met, for both runs.
//!
//! The AEB (written for this example, in the spirit of the two-stage systems of the Euro NCAP
//! AEB Car-to-Car protocols: partial braking first, full braking when the collision is close):
//! TTC = gap / closing speed, for the nearest object whose box overlaps Ego's path; below
//! [`PARTIAL_TTC`] it brakes at [`PARTIAL_BRAKE`], below [`FULL_TTC`] at [`FULL_BRAKE`]; once
//! braking it holds at least the partial level, and it lets go when Ego no longer closes in
//! (Ego then keeps its speed).

use std::error::Error;
use std::path::{Path, PathBuf};

use engine::controller::ExternalInput;
use engine::{Engine, EngineConfig, EntityState};

/// TTC below which the AEB brakes partly (s).
pub const PARTIAL_TTC: f64 = 1.6;
/// TTC below which it brakes fully (s).
pub const FULL_TTC: f64 = 0.9;
/// Partial braking (m/s²).
pub const PARTIAL_BRAKE: f64 = -4.0;
/// Full braking (m/s²).
pub const FULL_BRAKE: f64 = -9.0;
/// The end of the run (s), the scenario's parameter `EndTime` (its default, 10 s, ends before
/// the collision).
pub const END_TIME: f64 = 16.0;

/// What a run showed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome {
    /// The smallest bumper-to-bumper gap to an object in Ego's path (m); ≤ 0 is a collision.
    pub min_gap: f64,
    /// The boxes met.
    pub collided: bool,
    /// When the AEB first braked (s), if it did.
    pub braked_at: Option<f64>,
    /// Ego's speed at the end (m/s).
    pub final_speed: f64,
}

/// The bundled scenario.
pub fn scenario_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenarios/cut_in_highway.xosc")
}

/// The scenario's parameters for this run: past the default end (10 s) to 16 s, beyond the
/// collision at 14.55 s.
pub fn params() -> Vec<(String, String)> {
    vec![("EndTime".to_owned(), END_TIME.to_string())]
}

/// The gap from `ego`'s front bumper to the rear of `other` along Ego's heading, when `other`'s
/// box overlaps Ego's width and lies ahead: what a forward sensor measures (boxes taken as
/// aligned with Ego).
fn gap_ahead(ego: &EntityState, other: &EntityState) -> Option<f64> {
    let (dx, dy) = (other.pose.x - ego.pose.x, other.pose.y - ego.pose.y);
    let (sin, cos) = ego.pose.h.sin_cos();
    let (along, across) = (dx * cos + dy * sin, -dx * sin + dy * cos);
    let (eb, ob) = (&ego.bounding_box, &other.bounding_box);
    let lateral = across + ob.center().y - eb.center().y;
    if lateral.abs() >= 0.5 * (eb.width() + ob.width()) {
        return None;
    }
    let front = eb.center().x + 0.5 * eb.length();
    let rear = along + ob.center().x - 0.5 * ob.length();
    let far = along + ob.center().x + 0.5 * ob.length();
    (far > front).then_some(rear - front)
}

/// The nearest object in Ego's path: (gap, its speed).
fn in_path(scene: &[EntityState], ego: &EntityState) -> Option<(f64, f64)> {
    scene
        .iter()
        .filter(|o| o.id != ego.id)
        .filter_map(|o| gap_ahead(ego, o).map(|g| (g, o.speed)))
        .min_by(|a, b| a.0.total_cmp(&b.0))
}

/// The AEB's acceleration for Ego now (module doc), from the entities in the scene (`scene`,
/// [`Engine::entities`]); `braking`: it braked in the last step (once braking it holds at
/// least the partial level until Ego no longer closes in).
pub fn aeb(scene: &[EntityState], ego: &EntityState, braking: bool) -> f64 {
    let Some((gap, speed)) = in_path(scene, ego) else {
        return 0.0;
    };
    let closing = ego.speed - speed;
    if closing <= 0.0 {
        return 0.0;
    }
    let ttc = gap.max(0.0) / closing;
    if ttc < FULL_TTC {
        FULL_BRAKE
    } else if ttc < PARTIAL_TTC || braking {
        PARTIAL_BRAKE
    } else {
        0.0
    }
}

/// Runs the scenario at `path`, with the AEB driving Ego or (`with_aeb` false) under the
/// default controller.
pub fn run(path: &Path, with_aeb: bool) -> Result<Outcome, Box<dyn Error>> {
    let mut engine = Engine::load(path, &params(), EngineConfig::default())?;
    if with_aeb {
        engine.attach_external("Ego")?;
    }
    let mut braking = false;
    let mut outcome = Outcome {
        min_gap: f64::INFINITY,
        collided: false,
        braked_at: None,
        final_speed: 0.0,
    };
    loop {
        if with_aeb && engine.steps() > 0 {
            let scene = engine.entities();
            let ego = scene.iter().find(|e| e.name == "Ego").ok_or("no Ego")?;
            let acceleration = aeb(&scene, ego, braking);
            braking = acceleration < 0.0;
            if acceleration < 0.0 && outcome.braked_at.is_none() {
                outcome.braked_at = Some(engine.time());
            }
            engine.set_external_input(
                "Ego",
                ExternalInput::Acceleration {
                    acceleration,
                    steering: None,
                },
            )?;
        }
        let stop = engine.step(&mut (), &mut ())?;
        let scene = engine.entities();
        let ego = scene.iter().find(|e| e.name == "Ego").ok_or("no Ego")?;
        if let Some((gap, _)) = in_path(&scene, ego) {
            outcome.min_gap = outcome.min_gap.min(gap);
            outcome.collided |= gap <= 0.0;
        }
        outcome.final_speed = ego.speed;
        if stop.is_some() {
            break;
        }
    }
    Ok(outcome)
}

#[allow(dead_code)] // A test includes this file as a module and calls `run` itself.
fn main() -> Result<(), Box<dyn Error>> {
    let path = scenario_path();
    for (label, with_aeb) in [("default controller", false), ("AEB (external)", true)] {
        let o = run(&path, with_aeb)?;
        println!(
            "{label:>20}: closest gap {:7.2} m, collision {}, braking from {}, final speed {:.2} m/s",
            o.min_gap,
            if o.collided { "yes" } else { "no" },
            o.braked_at.map_or("-".to_owned(), |t| format!("{t:.2} s")),
            o.final_speed
        );
    }
    Ok(())
}
