//! The run's settings in one place: step length, duration and the hard cap on simulated time.

pub use crate::controller::TrafficModel;
use crate::error::{Error, ErrorKind};

/// Default step length (s), the reference runs' fixed time step.
pub const DEFAULT_DT: f64 = 0.05;
/// Default hard cap on simulated time (s): a run without a stop trigger ends here.
pub const DEFAULT_MAX_TIME: f64 = 3600.0;
/// Default seed of the run's random streams.
pub const DEFAULT_SEED: u64 = 1;

/// Settings of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EngineConfig {
    /// Fixed step length (s), > 0.
    pub dt: f64,
    /// Stop after this much simulated time (s), if set.
    pub duration: Option<f64>,
    /// Hard cap on simulated time (s), so that no run is endless.
    pub max_time: f64,
    /// Seed of the run's random streams: spawned traffic (each traffic action draws from its own
    /// stream keyed by its name) and routes with routeStrategy `random` (keyed by the route's
    /// name). Default [`DEFAULT_SEED`].
    pub seed: u64,
    /// The controller every vehicle spawned by a traffic action gets when the scenario gives
    /// it none (no ControllerDistribution, no template ObjectController): `idm` or `mobil`,
    /// assigned and activated at the spawn (runtime/traffic/controllers.rs). Default `None`:
    /// the default controller.
    pub traffic_model: Option<TrafficModel>,
    /// The controller every vehicle ScenarioObject without an ObjectController gets (the
    /// scale scenarios' vehicles, say): `idm` or `mobil`, assigned and activated when the
    /// engine is built, before the Init, whose SpeedAction then gives the desired speed
    /// (runtime/traffic/controllers.rs). Default `None`: the default controller.
    pub vehicle_model: Option<TrafficModel>,
    /// Vehicles the default controller or the `idm`/`mobil` driver models move stop before
    /// vehicle traffic lights showing red and drive on when they no longer do
    /// (signals/red_light.rs, docs/signals.md). Default
    /// `false`: signals do not affect motion, so existing runs keep their results.
    pub stop_at_red_lights: bool,
    /// Threads the controllers stage works the driver models' (`idm`, `mobil`) commands out
    /// on when many vehicles have one (256 or more; controller/parallel.rs). Default 1: on
    /// the calling thread. Any count gives the same outputs, bit for bit; more threads take
    /// less wall time and somewhat more CPU time.
    pub controller_threads: usize,
}

impl Default for EngineConfig {
    fn default() -> Self {
        EngineConfig {
            dt: DEFAULT_DT,
            duration: None,
            max_time: DEFAULT_MAX_TIME,
            seed: DEFAULT_SEED,
            traffic_model: None,
            vehicle_model: None,
            stop_at_red_lights: false,
            controller_threads: 1,
        }
    }
}

impl EngineConfig {
    /// Checks the values: dt finite and positive, duration and cap finite and ≥ 0.
    pub fn validate(&self) -> Result<(), Error> {
        let bad = |name, expected, found| {
            Err(Error::new(ErrorKind::Config {
                name,
                expected,
                found,
            }))
        };
        if !(self.dt.is_finite() && self.dt > 0.0) {
            return bad("dt", "a finite step length > 0 s", self.dt);
        }
        if let Some(d) = self.duration {
            if !(d.is_finite() && d >= 0.0) {
                return bad("duration", "a finite duration >= 0 s", d);
            }
        }
        if !(self.max_time.is_finite() && self.max_time >= 0.0) {
            return bad("max_time", "a finite time >= 0 s", self.max_time);
        }
        if self.controller_threads == 0 {
            return bad("controller_threads", "a thread count >= 1", 0.0);
        }
        Ok(())
    }

    /// The simulated time at which the run ends at the latest.
    pub fn end_time(&self) -> f64 {
        self.duration
            .map_or(self.max_time, |d| d.min(self.max_time))
    }
}
