//! The trajectory CSV in the long layout of the reference files (corpus
//! `reference/esmini/*.csv`): header `time,id,name,x,y,z,h,p,r,roadId,laneId,offset,t,s,speed`,
//! one row per placed entity per frame. Time with 3 decimals, the rest with 6, so files are
//! byte-identical for identical runs; road columns are empty off the road.
//!
//! Written by hand: one fixed numeric layout, where a CSV crate would add only quoting, which
//! names need only when they hold a comma or quote (handled here).

use std::io::Write;

use super::fixed::push_fixed;
use super::frame::{Frame, FrameSink};
use super::SinkError;

/// The header line.
pub const HEADER: &str = "time,id,name,x,y,z,h,p,r,roadId,laneId,offset,t,s,speed";

/// Writes frames as CSV rows to `W`.
#[derive(Debug)]
pub struct CsvWriter<W: Write> {
    out: W,
    header_written: bool,
    /// The frame's rows being put together.
    row: Vec<u8>,
    /// The frame's time as its rows start it: formatted once per frame.
    time: Vec<u8>,
}

impl<W: Write> CsvWriter<W> {
    /// A writer that writes the header before the first row.
    pub fn new(out: W) -> Self {
        CsvWriter {
            out,
            header_written: false,
            row: Vec::with_capacity(256),
            time: Vec::with_capacity(24),
        }
    }

    /// The underlying writer.
    pub fn into_inner(self) -> W {
        self.out
    }
}

/// `name` quoted per RFC 4180 when it holds a comma, quote or line break (borrowed, so no
/// allocation, when it holds none).
pub(super) fn field(name: &str) -> std::borrow::Cow<'_, str> {
    if name
        .bytes()
        .any(|b| matches!(b, b',' | b'"' | b'\n' | b'\r'))
    {
        format!("\"{}\"", name.replace('"', "\"\"")).into()
    } else {
        name.into()
    }
}

impl<W: Write> FrameSink for CsvWriter<W> {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), SinkError> {
        if !self.header_written {
            writeln!(self.out, "{HEADER}")?;
            self.header_written = true;
        }
        // The frame's rows are put together in a buffer kept from frame to frame and written
        // in one call: no allocation per row once the buffer holds a frame, the numbers
        // formatted by `fixed` (the bytes of `{:.3}` / `{:.6}`).
        let row = &mut self.row;
        row.clear();
        self.time.clear();
        push_fixed(&mut self.time, frame.time, 3);
        self.time.push(b',');
        let mut ids = itoa::Buffer::new();
        for e in frame.objects() {
            let p = e.pose;
            row.extend_from_slice(&self.time);
            row.extend_from_slice(ids.format(e.id).as_bytes());
            row.push(b',');
            row.extend_from_slice(field(e.name).as_bytes());
            for v in [p.x, p.y, p.z, p.h, p.p, p.r] {
                row.push(b',');
                push_fixed(row, v, 6);
            }
            row.push(b',');
            match e.road_position {
                Some(rp) => {
                    row.extend_from_slice(field(&rp.road_id).as_bytes());
                    row.push(b',');
                    row.extend_from_slice(ids.format(rp.lane_id).as_bytes());
                    for v in [rp.offset, rp.t, rp.s] {
                        row.push(b',');
                        push_fixed(row, v, 6);
                    }
                    row.push(b',');
                }
                None => row.extend_from_slice(b",,,,,"),
            }
            push_fixed(row, e.speed, 6);
            row.push(b'\n');
        }
        Ok(self.out.write_all(row)?)
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        Ok(self.out.flush()?)
    }
}
