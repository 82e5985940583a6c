//! Writes the synthetic sample scene (tests/common) as `DIR/sample.osi` and
//! `DIR/sample.mcap`, for checking with the official OSI tools:
//! `cargo run -p oscsim-osi --example sample_traces -- DIR` then
//! `scripts/osi_check.sh DIR/sample.osi DIR/sample.mcap`.

#[path = "../tests/common/mod.rs"]
mod common;

use osi::trace::{McapTraceInfo, McapTraceWriter, OsiFileWriter, TraceWriter};
use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let Some(dir) = std::env::args_os().nth(1).map(PathBuf::from) else {
        eprintln!("usage: sample_traces DIR");
        return ExitCode::from(2);
    };
    let frames = common::frames(100, 5);
    let run = || -> Result<(), osi::Error> {
        let mut osi_file = OsiFileWriter::create(&dir.join("sample.osi"))?;
        let info = McapTraceInfo {
            description: Some("oscsim-osi synthetic sample".into()),
            ..Default::default()
        };
        let mut mcap_file = McapTraceWriter::create(&dir.join("sample.mcap"), &info)?;
        for gt in &frames {
            osi_file.write(gt)?;
            mcap_file.write(gt)?;
        }
        osi_file.finish()?;
        mcap_file.finish()
    };
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
