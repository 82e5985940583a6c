//! The trajectory CSV in the long layout of the reference files (corpus
//! `reference/esmini/*.csv`): header `time,id,name,x,y,z,h,p,r,roadId,laneId,offset,t,s,speed`,
//! one row per placed entity per frame. Time with 3 decimals, the rest with 6, so files are
//! byte-identical for identical runs; road columns are empty off the road.
//!
//! Written by hand: one fixed numeric layout, where a CSV crate would add only quoting, which
//! names need only when they hold a comma or quote (handled here).

use std::io::Write;

use super::frame::{Frame, FrameSink};

/// The header line.
pub const HEADER: &str = "time,id,name,x,y,z,h,p,r,roadId,laneId,offset,t,s,speed";

/// Writes frames as CSV rows to `W`.
#[derive(Debug)]
pub struct CsvWriter<W: Write> {
    out: W,
    header_written: bool,
}

impl<W: Write> CsvWriter<W> {
    /// A writer that writes the header before the first row.
    pub fn new(out: W) -> Self {
        CsvWriter {
            out,
            header_written: false,
        }
    }

    /// The underlying writer.
    pub fn into_inner(self) -> W {
        self.out
    }
}

/// `name` quoted per RFC 4180 when it holds a comma, quote or line break.
pub(super) fn field(name: &str) -> std::borrow::Cow<'_, str> {
    if name.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", name.replace('"', "\"\"")).into()
    } else {
        name.into()
    }
}

impl<W: Write> FrameSink for CsvWriter<W> {
    fn frame(&mut self, frame: &Frame<'_>) -> std::io::Result<()> {
        if !self.header_written {
            writeln!(self.out, "{HEADER}")?;
            self.header_written = true;
        }
        for e in frame.objects() {
            let p = e.pose;
            write!(
                self.out,
                "{:.3},{},{},{:.6},{:.6},{:.6},{:.6},{:.6},{:.6},",
                frame.time,
                e.id,
                field(e.name),
                p.x,
                p.y,
                p.z,
                p.h,
                p.p,
                p.r
            )?;
            match e.road_position {
                Some(rp) => write!(
                    self.out,
                    "{},{},{:.6},{:.6},{:.6},",
                    field(&rp.road_id),
                    rp.lane_id,
                    rp.offset,
                    rp.t,
                    rp.s
                )?,
                None => write!(self.out, ",,,,,")?,
            }
            writeln!(self.out, "{:.6}", e.speed)?;
        }
        Ok(())
    }

    fn finish(&mut self) -> std::io::Result<()> {
        self.out.flush()
    }
}
