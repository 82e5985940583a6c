//! The traffic signal CSV, companion of the trajectory CSV (`oscsim run --signals FILE.csv`):
//! header `time,signal,state`, one row per signal that has a state per frame, signals in id
//! order; time with 3 decimals as in the trajectory CSV, so the two join on `time`. The state is
//! the scenario's string for the signal (e.g. `off;off;on`), set by the phases of
//! TrafficSignalControllers and by TrafficSignalStateActions (crate::signals).

use std::io::Write;

use super::csv::field;
use super::frame::{Frame, FrameSink};
use super::SinkError;

/// The header line.
pub const SIGNALS_HEADER: &str = "time,signal,state";

/// Writes the signal states of each frame as CSV rows to `W`.
#[derive(Debug)]
pub struct SignalsCsvWriter<W: Write> {
    out: W,
    header_written: bool,
}

impl<W: Write> SignalsCsvWriter<W> {
    /// A writer that writes the header before the first row.
    pub fn new(out: W) -> Self {
        SignalsCsvWriter {
            out,
            header_written: false,
        }
    }
}

impl<W: Write> FrameSink for SignalsCsvWriter<W> {
    fn frame(&mut self, frame: &Frame<'_>) -> Result<(), SinkError> {
        if !self.header_written {
            writeln!(self.out, "{SIGNALS_HEADER}")?;
            self.header_written = true;
        }
        for (id, state) in frame.signals.states() {
            writeln!(self.out, "{:.3},{},{}", frame.time, field(id), field(state))?;
        }
        Ok(())
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        Ok(self.out.flush()?)
    }
}
