//! Writes the two test scenes as traces for checking with the official OSI tools:
//! the synthetic scene of tests/it/common as `DIR/sample.osi` and `DIR/sample.mcap`, and
//! the corpus-road scene of tests/it/common/road_scene.rs (lanes from
//! straight_500m.xodr) as `DIR/road_scene.osi` and `DIR/road_scene.mcap`:
//! `cargo run -p oscsim-osi --example sample_traces -- DIR` then
//! `scripts/osi_check.sh DIR/*.osi DIR/*.mcap`.

#[path = "../tests/it/common/mod.rs"]
mod common;

use osi::trace::{McapTraceInfo, McapTraceWriter, OsiFileWriter, TraceWriter};
use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let Some(dir) = std::env::args_os().nth(1).map(PathBuf::from) else {
        eprintln!("usage: sample_traces DIR");
        return ExitCode::from(2);
    };
    let sample = common::frames(100, 5);
    let (net, mut builder) = common::road_scene::builder(osi::ground_truth::StaticData::First);
    let road: Vec<_> = (0..50)
        .map(|k| common::road_scene::frame(&net, &mut builder, k))
        .collect();
    let run = |name: &str, frames: &[osi::osi3::GroundTruth]| -> Result<(), osi::Error> {
        let mut osi_file = OsiFileWriter::create(&dir.join(format!("{name}.osi")))?;
        let info = McapTraceInfo {
            description: Some(format!("oscsim-osi test scene {name}")),
            ..Default::default()
        };
        let mut mcap_file = McapTraceWriter::create(&dir.join(format!("{name}.mcap")), &info)?;
        for gt in frames {
            osi_file.write(gt)?;
            mcap_file.write(gt)?;
        }
        osi_file.finish()?;
        mcap_file.finish()
    };
    match run("sample", &sample).and_then(|()| run("road_scene", &road)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
