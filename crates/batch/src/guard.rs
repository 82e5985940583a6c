//! A variant cannot stall or sink a sweep: its wall-clock limit (`--variant-timeout`) and the
//! containment of a panic in its run. Either way the variant is a failed row with the reason
//! and the other variants go on.
//!
//! **The limit is cooperative.** A thread cannot be stopped from outside in Rust, and a process
//! per variant would cost more than the variant itself (a variant of the bundled cut-in runs in
//! under 2 ms). So the variant's run carries a [`Deadline`], a frame sink the engine feeds
//! after each step's output stage (engine runtime/step.rs, stage 5); once the wall clock has
//! passed the limit it refuses the frame, which ends the run with an error between two steps.
//! Building the variant's engine happens before the first frame and is not interrupted (it
//! reads no file: batch plan.rs), nor is a single step that never ends: the engine's own loops
//! are bounded (docs/robustness.md, the fuzzers' hang findings).
//!
//! **What a timeout records is deterministic except for which variant times out.** The row
//! holds only the message [`timeout_message`] (the limit, not the simulated time reached,
//! which depends on the machine's speed), and the variant's saved outputs, an arbitrary prefix
//! of its run, are not kept (save.rs). Whether a variant near the limit passes it depends on
//! the machine and its load; every variant that does not pass it gives the row it gives
//! without a limit.
//!
//! **Panics** in a variant's run (a bug in the engine) are caught with
//! [`std::panic::catch_unwind`] and recorded as "the engine panicked: MESSAGE"; the panic hook
//! still prints the place to standard error. Its saved outputs are not kept either. The plan is
//! shared read-only between variants, so a panic leaves nothing half-changed behind.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::{Duration, Instant};

use engine::output::Frame;
use engine::{FrameSink, SinkError};

/// The error a [`Deadline`] stops a run with.
#[derive(Debug, thiserror::Error)]
#[error("the variant's wall-clock limit passed")]
struct Expired;

/// A frame sink that ends the run once the wall clock passes its instant (module doc).
#[derive(Debug)]
pub(crate) struct Deadline {
    at: Instant,
    /// Whether this deadline stopped the run.
    pub(crate) expired: bool,
}

impl Deadline {
    /// The deadline `limit` after `start`.
    pub(crate) fn new(start: Instant, limit: Duration) -> Self {
        Deadline {
            at: start + limit,
            expired: false,
        }
    }
}

impl FrameSink for Deadline {
    fn frame(&mut self, _: &Frame<'_>) -> Result<(), SinkError> {
        if Instant::now() >= self.at {
            self.expired = true;
            return Err(SinkError::sink(Expired));
        }
        Ok(())
    }
}

/// The error of a variant stopped by `limit`.
pub(crate) fn timeout_message(limit: Duration) -> String {
    format!(
        "timed out: ran longer than the variant timeout of {} s (wall clock)",
        limit.as_secs_f64()
    )
}

/// `run()`, or the message of its panic as its error.
pub(crate) fn contain<T>(run: impl FnOnce() -> Result<T, String>) -> Result<T, String> {
    // AssertUnwindSafe: what the closure borrows (the plan, the options) is only read.
    catch_unwind(AssertUnwindSafe(run)).unwrap_or_else(|payload| {
        let message = payload
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic without a message".to_owned());
        Err(format!("the engine panicked: {message}"))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_panic_becomes_the_variants_error() {
        assert_eq!(contain(|| Ok::<_, String>(3)), Ok(3));
        assert_eq!(
            contain(|| Err::<u8, _>("expected a lane".to_owned())),
            Err("expected a lane".to_owned())
        );
        // (The panic hook prints both panics to the test's standard error.)
        let text = contain::<u8>(|| panic!("index {} out of range", 7));
        let literal = contain::<u8>(|| panic!("plain"));
        assert_eq!(
            text,
            Err("the engine panicked: index 7 out of range".to_owned())
        );
        assert_eq!(literal, Err("the engine panicked: plain".to_owned()));
    }

    #[test]
    fn the_message_names_the_limit_only() {
        assert_eq!(
            timeout_message(Duration::from_millis(2500)),
            "timed out: ran longer than the variant timeout of 2.5 s (wall clock)"
        );
    }
}
