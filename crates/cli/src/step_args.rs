//! The stepping flags `oscsim run` and `oscsim batch` share: step length, duration, time cap and
//! seed, turned into the engine's configuration.

use engine::EngineConfig;

/// `--dt`, `--duration`, `--max-time`, `--seed`.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct StepArgs {
    /// Step length in seconds.
    #[arg(long, default_value_t = engine::runtime::DEFAULT_DT)]
    pub dt: f64,
    /// Simulated seconds to run (default: until the storyboard ends).
    #[arg(long)]
    pub duration: Option<f64>,
    /// Hard cap on simulated seconds.
    #[arg(long, default_value_t = engine::runtime::DEFAULT_MAX_TIME)]
    pub max_time: f64,
    /// Seed of the random streams (spawned traffic, routeStrategy random); the same seed gives
    /// the same run (for a batch: each variant's seed is derived from it and its number).
    #[arg(long, default_value_t = engine::runtime::DEFAULT_SEED)]
    pub seed: u64,
}

impl StepArgs {
    /// The engine configuration of these flags.
    pub fn config(&self) -> EngineConfig {
        EngineConfig {
            dt: self.dt,
            duration: self.duration,
            max_time: self.max_time,
            seed: self.seed,
        }
    }
}
