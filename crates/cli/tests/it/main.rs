//! The oscsim binary's command-line tests, one binary (issue 33); each module is one former
//! test file. `tests/osi/` stays a binary of its own with its helpers `tests/osi_common/`.

mod cli_batch;
mod cli_batch_resume;
mod cli_coverage;
mod cli_errors;
mod cli_signals;
mod dsl;
mod dsl_replay;
mod replay_browser;
mod replay_plot;
