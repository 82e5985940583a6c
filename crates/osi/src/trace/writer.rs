//! The seam between whoever produces ground truth (the engine) and the trace formats:
//! a [`TraceWriter`] takes one `osi3.GroundTruth` per frame.

use std::path::Path;

use crate::error::{Error, ErrorKind};
use crate::osi3::GroundTruth;

/// A sink for a sequence of GroundTruth frames, in strictly increasing time.
pub trait TraceWriter {
    /// Appends one frame.
    fn write(&mut self, ground_truth: &GroundTruth) -> Result<(), Error>;

    /// Writes what the format needs at the end and flushes. Further writes fail with
    /// [`crate::ErrorKind::Finished`]; a second `finish` does nothing.
    fn finish(&mut self) -> Result<(), Error>;

    /// Number of frames written so far.
    fn frames(&self) -> u64;
}

/// Nanoseconds of an `osi3.Timestamp` (negative times and unset fields count as 0), the
/// MCAP `publish_time` of the frame (OSI 3.8 §2.2.6.1.2).
pub fn timestamp_nanos(ground_truth: &GroundTruth) -> u64 {
    ground_truth.timestamp.as_ref().map_or(0, |t| {
        let secs = u64::try_from(t.seconds.unwrap_or(0)).unwrap_or(0);
        secs.saturating_mul(1_000_000_000)
            .saturating_add(u64::from(t.nanos.unwrap_or(0)))
    })
}

/// Keeps a trace's frames in strictly increasing time and hands out each frame's time.
#[derive(Debug, Default)]
pub(crate) struct TimeOrder {
    last: Option<u64>,
}

impl TimeOrder {
    /// The frame's time (ns), if it has a timestamp later than the previous frame's.
    pub(crate) fn next(&mut self, ground_truth: &GroundTruth, path: &Path) -> Result<u64, Error> {
        if ground_truth.timestamp.is_none() {
            return Err(Error::in_file(ErrorKind::MissingTimestamp, path));
        }
        let now = timestamp_nanos(ground_truth);
        if let Some(previous) = self.last.filter(|&p| p >= now) {
            let kind = ErrorKind::TimestampNotIncreasing {
                previous,
                found: now,
            };
            return Err(Error::in_file(kind, path));
        }
        self.last = Some(now);
        Ok(now)
    }
}
