//! `oscsim validate FILE...`: load scenarios and report errors.

use std::process::ExitCode;

/// Arguments of `oscsim validate`.
#[derive(clap::Args, Debug)]
pub struct ValidateArgs {}

/// Runs `oscsim validate`.
pub fn run(_args: ValidateArgs) -> anyhow::Result<ExitCode> {
    anyhow::bail!("`oscsim validate` is not built yet")
}
