//! The stepping flags `oscsim run` and `oscsim batch` share: step length, duration, time cap and
//! seed, the driver models of spawned traffic and of the scenario's vehicles, turned into the engine's configuration.

use engine::runtime::TrafficModel;
use engine::EngineConfig;

/// `--traffic-model` values.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum TrafficModelArg {
    /// Intelligent Driver Model.
    Idm,
    /// IDM and MOBIL lane changes.
    Mobil,
}

impl TrafficModelArg {
    fn model(self) -> TrafficModel {
        match self {
            TrafficModelArg::Idm => TrafficModel::Idm,
            TrafficModelArg::Mobil => TrafficModel::Mobil,
        }
    }
}

/// `--dt`, `--duration`, `--max-time`, `--seed`, `--traffic-model`, `--vehicle-model`.
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
    /// Give every vehicle spawned by a traffic action (TrafficSwarm/Source/AreaAction) that the
    /// scenario gives no controller this driver model, with its default parameters: `idm`
    /// (car following) or `mobil` (car following and lane changes).
    #[arg(long, value_enum, value_name = "MODEL")]
    pub traffic_model: Option<TrafficModelArg>,
    /// Give every vehicle of the scenario that has no ObjectController this driver model
    /// (the scale scenarios' vehicles, say), activated before the Init, whose SpeedAction
    /// becomes the desired speed: `idm` or `mobil`, default parameters.
    #[arg(long, value_enum, value_name = "MODEL")]
    pub vehicle_model: Option<TrafficModelArg>,
    /// Vehicles the default controller or the `idm`/`mobil` driver models move stop before
    /// vehicle traffic lights (OpenDRIVE type 1000001) showing red and drive on when they turn
    /// (docs/signals.md). Off by default: signals do not change the motion.
    #[arg(long)]
    pub stop_at_red_lights: bool,
}

impl StepArgs {
    /// The engine configuration of these flags.
    pub fn config(&self) -> EngineConfig {
        EngineConfig {
            dt: self.dt,
            duration: self.duration,
            max_time: self.max_time,
            seed: self.seed,
            traffic_model: self.traffic_model.map(TrafficModelArg::model),
            vehicle_model: self.vehicle_model.map(TrafficModelArg::model),
            stop_at_red_lights: self.stop_at_red_lights,
            ..EngineConfig::default()
        }
    }
}
