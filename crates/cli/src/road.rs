//! `oscsim road …`: inspect an OpenDRIVE network.
//!
//! - `info FILE` — roads, lengths, lane sections, junctions, bounding box.
//! - `sample FILE [--step M]` — CSV `road_id,s,lane_id,x,y,z,h,p,r`: for every road, every s on
//!   the step grid plus the road's end, the centre of every lane of the lane section at s
//!   (left outermost to right outermost; lane 0 is the centre lane, i.e. the reference line
//!   moved by laneOffset). Metres and radians (angles in (−π, π]), 6 decimals.
//! - `locate FILE` — reads CSV `x,y,h` on stdin (header line optional) and writes CSV
//!   `x,y,h,road_id,lane_id,s,t,offset` (t from the reference line, offset from the lane
//!   centre, both positive to the left); a point no road can take gets empty fields.

use std::io::{BufRead, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Context;
use clap::Subcommand;
use opendrive::{JunctionKind, RoadNetwork};

/// Arguments of `oscsim road`.
#[derive(clap::Args, Debug)]
#[command(after_help = "Exit status: 0 success, 1 invalid input, 2 usage error.")]
pub struct RoadArgs {
    #[command(subcommand)]
    command: RoadCommand,
}

#[derive(Subcommand, Debug)]
enum RoadCommand {
    /// Roads, lengths, lane sections, junctions and bounding box of an .xodr file.
    Info {
        /// The OpenDRIVE file.
        file: PathBuf,
    },
    /// Lane-centre samples as CSV: road_id,s,lane_id,x,y,z,h,p,r.
    Sample {
        /// The OpenDRIVE file.
        file: PathBuf,
        /// Distance between samples along s (m, > 0).
        #[arg(long, default_value_t = 1.0, value_parser = parse_step)]
        step: f64,
    },
    /// Map CSV x,y,h from stdin to road positions: x,y,h,road_id,lane_id,s,t,offset.
    Locate {
        /// The OpenDRIVE file.
        file: PathBuf,
    },
}

/// `--step`: a finite number > 0.
fn parse_step(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        _ => Err(format!("expected a step > 0 in metres, found \"{text}\"")),
    }
}

/// Runs `oscsim road`.
pub fn run(args: RoadArgs) -> anyhow::Result<ExitCode> {
    let stdout = std::io::stdout();
    let mut out = BufWriter::new(stdout.lock());
    match args.command {
        RoadCommand::Info { file } => info(&load(&file)?, &file, &mut out)?,
        RoadCommand::Sample { file, step } => sample(&load(&file)?, step, &mut out)?,
        RoadCommand::Locate { file } => {
            let net = load(&file)?;
            locate(&net, std::io::stdin().lock(), &mut out)?;
        }
    }
    out.flush()?;
    Ok(ExitCode::SUCCESS)
}

fn load(file: &Path) -> anyhow::Result<RoadNetwork> {
    let net = RoadNetwork::from_file(file)?;
    for w in net.warnings() {
        eprintln!("warning: {w}");
    }
    Ok(net)
}

/// `road info`: a summary table.
fn info(net: &RoadNetwork, file: &Path, out: &mut impl Write) -> anyhow::Result<()> {
    let h = net.header();
    let total: f64 = net.roads().iter().map(|r| r.length).sum();
    writeln!(out, "file: {}", file.display())?;
    writeln!(
        out,
        "OpenDRIVE {}.{}, name \"{}\"",
        h.rev_major, h.rev_minor, h.name
    )?;
    writeln!(
        out,
        "roads: {}, total length {total:.3} m",
        net.roads().len()
    )?;
    let direct = net
        .junctions()
        .iter()
        .filter(|j| j.kind == JunctionKind::Direct)
        .count();
    writeln!(
        out,
        "junctions: {} ({} direct)",
        net.junctions().len(),
        direct
    )?;
    if let Some([x0, y0, x1, y1]) = net.bounding_box() {
        writeln!(
            out,
            "bounding box: x [{x0:.3}, {x1:.3}], y [{y0:.3}, {y1:.3}] m"
        )?;
    }
    writeln!(out)?;
    writeln!(
        out,
        "{:<10} {:>12} {:>9} {:>9} {:>6} {:>6}  geometry",
        "road", "length (m)", "junction", "sections", "left", "right"
    )?;
    for r in net.roads() {
        let left = r
            .lane_sections
            .iter()
            .map(|ls| ls.left.len())
            .max()
            .unwrap_or(0);
        let right = r
            .lane_sections
            .iter()
            .map(|ls| ls.right.len())
            .max()
            .unwrap_or(0);
        let mut kinds: Vec<&str> = r
            .plan_view
            .geometries()
            .iter()
            .map(|g| g.kind.name())
            .collect();
        kinds.dedup();
        writeln!(
            out,
            "{:<10} {:>12.3} {:>9} {:>9} {:>6} {:>6}  {}",
            r.id,
            r.length,
            r.junction.as_deref().unwrap_or("-"),
            r.lane_sections.len(),
            left,
            right,
            kinds.join(",")
        )?;
    }
    if !net.junctions().is_empty() {
        writeln!(out)?;
        writeln!(
            out,
            "{:<10} {:<8} {:>12}",
            "junction", "type", "connections"
        )?;
        for j in net.junctions() {
            let kind = match j.kind {
                JunctionKind::Default => "default",
                JunctionKind::Direct => "direct",
                _ => "other",
            };
            writeln!(out, "{:<10} {:<8} {:>12}", j.id, kind, j.connections.len())?;
        }
    }
    Ok(())
}

/// The s grid of a road: 0, step, 2·step, … below the length, then the length itself.
fn s_grid(length: f64, step: f64) -> impl Iterator<Item = f64> {
    let n = (length / step).ceil() as usize;
    (0..n)
        .map(move |k| k as f64 * step)
        .filter(move |&s| s < length - opendrive::LENGTH_EPSILON)
        .chain(std::iter::once(length))
}

/// `road sample`: lane centres on the s grid.
fn sample(net: &RoadNetwork, step: f64, out: &mut impl Write) -> anyhow::Result<()> {
    writeln!(out, "road_id,s,lane_id,x,y,z,h,p,r")?;
    for road in net.roads() {
        for s in s_grid(road.length, step) {
            for lane in road.lane_section_at(s).lanes() {
                let p = road.lane_pose(lane.id, s, 0.0)?;
                writeln!(
                    out,
                    "{},{s:.6},{},{:.6},{:.6},{:.6},{:.6},{:.6},{:.6}",
                    road.id, lane.id, p.x, p.y, p.z, p.h, p.p, p.r
                )?;
            }
        }
    }
    Ok(())
}

/// `road locate`: CSV x,y,h in, road positions out. Each input line is read into one reused
/// buffer and its fields parsed in place; numbers are written by `engine::output::push_fixed`
/// (the bytes of `{:.6}` without `core::fmt`'s slow exact-decimal path) into one reused line
/// buffer; the road's id is copied from the network (no `String` per look-up).
fn locate(net: &RoadNetwork, mut input: impl BufRead, out: &mut impl Write) -> anyhow::Result<()> {
    writeln!(out, "x,y,h,road_id,lane_id,s,t,offset")?;
    let mut line: Vec<u8> = Vec::with_capacity(128);
    let mut row: Vec<u8> = Vec::with_capacity(128);
    let mut digits = itoa::Buffer::new();
    for i in 0.. {
        line.clear();
        if input
            .read_until(b'\n', &mut line)
            .context("cannot read stdin")?
            == 0
        {
            break;
        }
        let text = std::str::from_utf8(&line)
            .map_err(|_| {
                std::io::Error::new(
                    std::io::ErrorKind::InvalidData,
                    "stream did not contain valid UTF-8",
                )
            })
            .context("cannot read stdin")?
            .trim();
        if text.is_empty() {
            continue;
        }
        let Some((x, y, h)) = parse_point(text) else {
            if i == 0 && text.split(',').all(|f| f.trim().parse::<f64>().is_err()) {
                continue; // header line
            }
            anyhow::bail!(
                "expected three numbers x,y,h, found \"{text}\" at stdin line {}",
                i + 1
            );
        };
        row.clear();
        for v in [x, y, h] {
            engine::output::push_fixed(&mut row, v, 6);
            row.push(b',');
        }
        match net.locate_point(x, y, Some(h)) {
            Some(p) => {
                row.extend_from_slice(net.road_at(p.road).id.as_bytes());
                row.push(b',');
                row.extend_from_slice(digits.format(p.lane_id).as_bytes());
                for v in [p.s, p.t, p.offset] {
                    row.push(b',');
                    engine::output::push_fixed(&mut row, v, 6);
                }
            }
            None => row.extend_from_slice(b",,,,"),
        }
        row.push(b'\n');
        out.write_all(&row)?;
    }
    Ok(())
}

/// The three numbers of a line `x,y,h` (fields trimmed); `None` unless there are exactly three
/// fields and each is a number.
fn parse_point(text: &str) -> Option<(f64, f64, f64)> {
    let mut fields = text.split(',').map(|f| f.trim().parse::<f64>());
    let (x, y, h) = (fields.next()?, fields.next()?, fields.next()?);
    match (fields.next(), x, y, h) {
        (None, Ok(x), Ok(y), Ok(h)) => Some((x, y, h)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn highway() -> (RoadNetwork, PathBuf) {
        let path = PathBuf::from(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../examples/roads/highway.xodr"
        ));
        let net = RoadNetwork::from_file(&path).unwrap_or_else(|e| panic!("{e}"));
        (net, path)
    }

    #[test]
    fn s_grid_ends_exactly_at_the_road_length() {
        // 0, 2, 4, 6 below 7, then 7; a length on the grid is not repeated.
        let g: Vec<f64> = s_grid(7.0, 2.0).collect();
        assert_eq!(g.len(), 5);
        assert!((g[3] - 6.0).abs() < 1e-12 && (g[4] - 7.0).abs() < 1e-12);
        assert_eq!(s_grid(6.0, 2.0).count(), 4);
    }

    #[test]
    fn sample_writes_every_lane_of_every_grid_point() {
        let (net, _) = highway();
        let mut buf = Vec::new();
        sample(&net, 5.0, &mut buf).unwrap_or_else(|e| panic!("{e}"));
        let text = String::from_utf8(buf).unwrap_or_default();
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("road_id,s,lane_id,x,y,z,h,p,r"));
        // Expected rows: Σ over roads and grid points of the lanes of the section at s.
        let expected: usize = net
            .roads()
            .iter()
            .map(|r| {
                s_grid(r.length, 5.0)
                    .map(|s| r.lane_section_at(s).lanes().count())
                    .sum::<usize>()
            })
            .sum();
        let rows: Vec<&str> = lines.collect();
        assert_eq!(rows.len(), expected);
        // Road 0 starts at s = 0 with its first listed lane: 9 comma-separated fields.
        assert!(rows[0].starts_with("0,0.000000,"), "{}", rows[0]);
        assert!(rows.iter().all(|r| r.split(',').count() == 9));
    }

    #[test]
    fn locate_reads_optional_header_and_inverts_sample_points() {
        let (net, _) = highway();
        // Centre of lane -1 of road 0 at s = 50, 0.5 m to the left of it.
        let p = net
            .lane_pose("0", -1, 50.0, 0.5)
            .unwrap_or_else(|e| panic!("{e}"));
        let input = format!("x,y,h\n{},{},{}\n\n", p.x, p.y, p.h);
        let mut buf = Vec::new();
        locate(&net, input.as_bytes(), &mut buf).unwrap_or_else(|e| panic!("{e}"));
        let text = String::from_utf8(buf).unwrap_or_default();
        let row: Vec<&str> = text.lines().nth(1).unwrap_or_default().split(',').collect();
        assert_eq!(row.len(), 8, "{text}");
        assert_eq!((row[3], row[4]), ("0", "-1"), "{text}");
        let s: f64 = row[5].parse().unwrap_or(f64::NAN);
        let offset: f64 = row[7].parse().unwrap_or(f64::NAN);
        assert!(
            (s - 50.0).abs() < 1e-6 && (offset - 0.5).abs() < 1e-6,
            "{text}"
        );
    }

    #[test]
    fn locate_rejects_a_malformed_line_with_its_number() {
        let (net, _) = highway();
        let err = locate(&net, "1,2,3\n4,five,6\n".as_bytes(), &mut Vec::new())
            .err()
            .map(|e| e.to_string());
        assert_eq!(
            err.as_deref(),
            Some("expected three numbers x,y,h, found \"4,five,6\" at stdin line 2")
        );
    }

    #[test]
    fn locate_parses_exactly_three_numbers_and_rejects_invalid_utf8() {
        // Fields are trimmed; anything but three numbers is no point.
        assert_eq!(parse_point(" 1.5 , -2 ,3e1"), Some((1.5, -2.0, 30.0)));
        for text in ["1,2", "1,2,3,4", "1,x,3", "1,,3"] {
            assert_eq!(parse_point(text), None, "{text}");
        }
        let (net, _) = highway();
        let err = locate(&net, &b"x,y,h\n1,2,\xff\n"[..], &mut Vec::new())
            .err()
            .map(|e| format!("{e:#}"));
        assert_eq!(
            err.as_deref(),
            Some("cannot read stdin: stream did not contain valid UTF-8")
        );
    }

    #[test]
    fn info_lists_every_road_and_junction() {
        let (net, path) = highway();
        let mut buf = Vec::new();
        info(&net, &path, &mut buf).unwrap_or_else(|e| panic!("{e}"));
        let text = String::from_utf8(buf).unwrap_or_default();
        assert!(
            text.contains(&format!("roads: {},", net.roads().len())),
            "{text}"
        );
        for r in net.roads() {
            assert!(
                text.lines()
                    .any(|l| l.starts_with(&format!("{:<10} ", r.id))),
                "{text}"
            );
        }
        assert!(
            parse_step("0").is_err() && parse_step("-1").is_err() && parse_step("NaN").is_err()
        );
    }
}
