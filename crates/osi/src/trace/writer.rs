//! The seam between whoever produces ground truth (the engine) and the trace formats:
//! a [`TraceWriter`] takes one `osi3.GroundTruth` per frame.

use crate::error::Error;
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
