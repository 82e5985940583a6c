//! OSI trace files: the [`TraceWriter`] seam, the `.osi` and `.mcap` writers, readers,
//! the file naming convention, and [`TraceFile`] for the command line.

mod file_name;
mod mcap_file;
mod osi_file;
mod output;
mod read;
mod writer;

pub use file_name::{trace_file_name, utc_basic_timestamp, utc_extended_timestamp};
pub use mcap_file::{
    McapTraceInfo, McapTraceWriter, CHANNEL_DESCRIPTION_KEY, CHANNEL_OSI_VERSION_KEY,
    CHANNEL_PROTOBUF_VERSION_KEY, GROUND_TRUTH_TOPIC, OSI_TRACE_METADATA_NAME,
};
pub use osi_file::OsiFileWriter;
pub use output::{TraceFile, TraceFormat, TraceOptions};
pub use read::{read_mcap, read_mcap_bytes, read_osi, read_osi_bytes, McapFrame, McapTrace};
pub use writer::{timestamp_nanos, TraceWriter};
