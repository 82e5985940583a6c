//! `oscsim road …`: inspect an OpenDRIVE network (info, sample, locate).

use std::process::ExitCode;

/// Arguments of `oscsim road`.
#[derive(clap::Args, Debug)]
pub struct RoadArgs {}

/// Runs `oscsim road`.
pub fn run(_args: RoadArgs) -> anyhow::Result<ExitCode> {
    anyhow::bail!("`oscsim road` is not built yet")
}
