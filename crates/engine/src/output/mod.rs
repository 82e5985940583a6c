//! Output of a run: the per-step [`Frame`] pushed to a [`FrameSink`] (the trajectory CSV, or
//! the OSI writer the cli feeds), and the [`EventRecord`]s pushed to an [`EventSink`] (the
//! JSON-lines event log).
//!
//! | module | job |
//! | --- | --- |
//! | `frame` | the per-step snapshot of every entity and the `FrameSink` seam |
//! | `event` | event records (storyboard transitions, custom commands, errors) and `EventSink` |
//! | `error` | the typed error sinks return |
//! | `csv` | the long-layout trajectory CSV |
//! | `fixed` | fixed-point float formatting without allocation (the bytes of `{:.N}`) |
//! | `jsonl` | the JSON-lines event log |
//! | `signals_csv` | the traffic signal states per frame, companion of the trajectory CSV |

mod csv;
mod error;
mod event;
mod fixed;
mod frame;
mod jsonl;
mod signals_csv;

pub use csv::CsvWriter;
pub use error::{SinkError, SinkErrorKind};
pub use event::{EventRecord, EventSink, SignalKind};
pub use fixed::push_fixed;
pub use frame::{EntityFrame, Frame, FrameSink};
pub use jsonl::JsonlWriter;
pub use signals_csv::{SignalsCsvWriter, SIGNALS_HEADER};
