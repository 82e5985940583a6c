//! Writes the benchmarks' generated town grid (`benches/grid`) to a file, for timing the
//! command line on it: `cargo run --release -p oscsim-opendrive --example grid_xodr -- OUT.xodr [MB]`
//! (default 60 MB). Then loads it five times and prints each load's wall time and the
//! process's CPU time for it (user + system, from /proc/self/stat on Linux; on a shared
//! machine the CPU time is the steadier figure).

#[path = "../benches/grid/mod.rs"]
mod grid;

use std::path::PathBuf;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let out = PathBuf::from(args.next().ok_or("usage: grid_xodr OUT.xodr [MB]")?);
    let mb: usize = args.next().map_or(Ok(60), |a| a.parse())?;
    let text = grid::grid_for_bytes(mb * 1_000_000);
    std::fs::write(&out, &text)?;
    drop(text);
    for _ in 0..5 {
        let (t0, c0) = (Instant::now(), cpu_seconds());
        let net = opendrive::RoadNetwork::from_file(&out)?;
        let (wall, cpu) = (t0.elapsed().as_secs_f64(), cpu_seconds() - c0);
        println!(
            "{}: {} roads, {} junctions, {} warnings; loaded in {wall:.3} s wall, {cpu:.2} s CPU",
            out.display(),
            net.roads().len(),
            net.junctions().len(),
            net.warnings().len(),
        );
    }
    Ok(())
}

/// User + system CPU time of this process so far (s), from /proc/self/stat (clock ticks of
/// 1/100 s); NaN where that file is missing.
fn cpu_seconds() -> f64 {
    let Ok(stat) = std::fs::read_to_string("/proc/self/stat") else {
        return f64::NAN;
    };
    // Fields after the command name (which ends with ')'): utime is the 12th, stime the 13th.
    let fields: Vec<&str> = stat
        .rsplit_once(')')
        .map_or(vec![], |(_, rest)| rest.split_whitespace().collect());
    let tick = |i: usize| fields.get(i).and_then(|v| v.parse::<f64>().ok());
    match (tick(11), tick(12)) {
        (Some(u), Some(s)) => (u + s) / 100.0,
        _ => f64::NAN,
    }
}
