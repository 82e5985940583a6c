//! The one way the commands load a scenario: the front door (`load` crate) with the flags of
//! either language — `--road` and `--seed` for OpenSCENARIO DSL, `--param` for XML — and an
//! OpenSCENARIO DSL file's check errors shown as source snippets (miette) on stderr.

use std::path::Path;

use anyhow::Context;

/// The front door's options from the command's flags.
pub fn options(
    road: Option<&Path>,
    scenario: Option<&str>,
    params: &[(String, String)],
    step: &crate::step_args::StepArgs,
) -> load::Options {
    load::Options {
        road: road.map(Path::to_path_buf),
        seed: step.seed,
        params: params.to_vec(),
        dt: step.dt,
        open_end: step.duration.is_some(),
        scenario: scenario.map(str::to_owned),
        // The command line binds no external methods: `load` below refuses a scenario that
        // calls or reads one, at its place.
        bindings: None,
    }
}

/// Prints the snippets of a DSL file's check errors on stderr (the error itself is returned).
pub fn show(e: &load::Error) {
    if let load::ErrorKind::Check(d) = e.kind() {
        let mut text = Vec::new();
        if crate::dsl::write_diagnostics(d.diagnostics(), &mut text).is_ok() {
            eprint!("{}", String::from_utf8_lossy(&text));
        }
    }
}

/// Loads `path` (either language) for `oscsim run`, `view` and `plot`. The command line binds
/// no external methods: a DSL scenario with a `call` of one cannot run (the error names the
/// first call's place).
pub fn load(path: &Path, options: &load::Options) -> anyhow::Result<load::Loaded> {
    load::load(path, options)
        .inspect_err(show)
        .map_err(anyhow::Error::from)
        .and_then(|loaded| match loaded.calls.first() {
            Some(c) => Err(anyhow::anyhow!(
                "expected a host binding for external method `{}` (the Python package's Simulation.bind), found none at {}",
                c.method,
                c.pos
            )),
            None => Ok(loaded),
        })
        .with_context(|| format!("cannot run {}", path.display()))
}
