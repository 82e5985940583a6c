//! The OSI multi-channel trace format `.mcap` (ASAM OSI 3.8 §2.2.6.1.2), written with the
//! `mcap` crate: an indexed MCAP file with every message in (uncompressed) chunks; one
//! metadata record `net.asam.osi.trace` with `version`, `min_osi_version`,
//! `max_osi_version`, `min_protobuf_version`, `max_protobuf_version` and the recommended
//! `creation_time`, `description`, `data_sources`; a schema record `osi3.GroundTruth`
//! (encoding `protobuf`, data the binary `FileDescriptorSet`); one channel with message
//! encoding `protobuf` and the channel metadata `net.asam.osi.trace.channel.osi_version`,
//! `…protobuf_version` and `…description`; and each message with
//! `publish_time = log_time =` the GroundTruth timestamp in nanoseconds and `sequence` the
//! frame counter from 1 (the standard reserves 0 for "no reliable sequence number").
//!
//! Chunks stay uncompressed so that the crate builds without C code (the zstd and lz4
//! features of `mcap` are off); the standard allows uncompressed chunks.

use std::collections::BTreeMap;
use std::fs::File;
use std::io::{BufWriter, Seek, Write};
use std::path::{Path, PathBuf};

use prost::Message;

use crate::error::{Error, ErrorKind};
use crate::osi3::GroundTruth;
use crate::schema::{GROUND_TRUTH_FILE_DESCRIPTOR_SET, GROUND_TRUTH_SCHEMA_NAME};
use crate::trace::writer::{TimeOrder, TraceWriter};
use crate::version::{OSI_VERSION, PROTOBUF_VERSION};

/// Name of the OSI trace metadata record.
pub const OSI_TRACE_METADATA_NAME: &str = "net.asam.osi.trace";
/// Channel metadata key of the OSI version.
pub const CHANNEL_OSI_VERSION_KEY: &str = "net.asam.osi.trace.channel.osi_version";
/// Channel metadata key of the protobuf version.
pub const CHANNEL_PROTOBUF_VERSION_KEY: &str = "net.asam.osi.trace.channel.protobuf_version";
/// Channel metadata key of the channel description.
pub const CHANNEL_DESCRIPTION_KEY: &str = "net.asam.osi.trace.channel.description";
/// Topic of the ground-truth channel.
pub const GROUND_TRUTH_TOPIC: &str = "GroundTruth";

/// What goes into the `net.asam.osi.trace` metadata besides the versions.
#[derive(Debug, Clone, Default)]
pub struct McapTraceInfo {
    /// `creation_time`: ISO 8601 UTC time the recording started, e.g. `2026-11-21T05:00:00Z`.
    pub creation_time: Option<String>,
    /// `description`: what the trace holds.
    pub description: Option<String>,
    /// `data_sources`: comma-separated sources, e.g. the scenario file.
    pub data_sources: Option<String>,
}

/// Writes GroundTruth frames as an OSI `.mcap` trace.
pub struct McapTraceWriter<W: Write + Seek> {
    out: Option<mcap::Writer<W>>,
    path: PathBuf,
    channel: u16,
    buf: Vec<u8>,
    frames: u64,
    time: TimeOrder,
}

impl McapTraceWriter<BufWriter<File>> {
    /// Creates (or truncates) the file at `path` and writes the header, metadata,
    /// schema and channel.
    pub fn create(path: &Path, info: &McapTraceInfo) -> Result<Self, Error> {
        let file = File::create(path).map_err(|e| Error::in_file(ErrorKind::Io(e), path))?;
        Self::new(BufWriter::new(file), path, info)
    }
}

impl<W: Write + Seek> McapTraceWriter<W> {
    /// Writes into `out`; `path` names it in errors.
    pub fn new(out: W, path: &Path, info: &McapTraceInfo) -> Result<Self, Error> {
        let err = |e| Error::in_file(ErrorKind::Mcap(e), path);
        let mut writer = mcap::WriteOptions::new()
            .compression(None)
            .profile("")
            .library(concat!("oscsim-osi ", env!("CARGO_PKG_VERSION")))
            .create(out)
            .map_err(err)?;

        let mut metadata = BTreeMap::new();
        for key in ["version", "min_osi_version", "max_osi_version"] {
            metadata.insert(key.to_string(), OSI_VERSION.to_string());
        }
        for key in ["min_protobuf_version", "max_protobuf_version"] {
            metadata.insert(key.to_string(), PROTOBUF_VERSION.to_string());
        }
        let optional = [
            ("creation_time", &info.creation_time),
            ("description", &info.description),
            ("data_sources", &info.data_sources),
        ];
        for (key, value) in optional {
            if let Some(v) = value {
                metadata.insert(key.to_string(), v.clone());
            }
        }
        writer
            .write_metadata(&mcap::records::Metadata {
                name: OSI_TRACE_METADATA_NAME.to_string(),
                metadata,
            })
            .map_err(err)?;

        let schema = writer
            .add_schema(
                GROUND_TRUTH_SCHEMA_NAME,
                "protobuf",
                GROUND_TRUTH_FILE_DESCRIPTOR_SET,
            )
            .map_err(err)?;
        let channel_metadata = BTreeMap::from([
            (CHANNEL_OSI_VERSION_KEY.to_string(), OSI_VERSION.to_string()),
            (
                CHANNEL_PROTOBUF_VERSION_KEY.to_string(),
                PROTOBUF_VERSION.to_string(),
            ),
            (
                CHANNEL_DESCRIPTION_KEY.to_string(),
                "ground truth of the simulated scenario, one message per output step".to_string(),
            ),
        ]);
        let channel = writer
            .add_channel(schema, GROUND_TRUTH_TOPIC, "protobuf", &channel_metadata)
            .map_err(err)?;
        Ok(McapTraceWriter {
            out: Some(writer),
            path: path.to_path_buf(),
            channel,
            buf: Vec::new(),
            frames: 0,
            time: TimeOrder::default(),
        })
    }
}

impl<W: Write + Seek> TraceWriter for McapTraceWriter<W> {
    fn write(&mut self, ground_truth: &GroundTruth) -> Result<(), Error> {
        let Some(out) = self.out.as_mut() else {
            return Err(Error::in_file(ErrorKind::Finished, &self.path));
        };
        self.buf.clear();
        // Encoding into a Vec cannot run out of space: Vec grows as needed.
        ground_truth
            .encode(&mut self.buf)
            .expect("encoding into a Vec<u8> never fails");
        let time = self.time.next(ground_truth, &self.path)?;
        let header = mcap::records::MessageHeader {
            channel_id: self.channel,
            // Counting from 1; the MCAP sequence field is 32 bits, a longer trace wraps.
            sequence: ((self.frames + 1) & u64::from(u32::MAX)) as u32,
            log_time: time,
            publish_time: time,
        };
        out.write_to_known_channel(&header, &self.buf)
            .map_err(|e| Error::in_file(ErrorKind::Mcap(e), &self.path))?;
        self.frames += 1;
        Ok(())
    }

    fn finish(&mut self) -> Result<(), Error> {
        if let Some(mut out) = self.out.take() {
            out.finish()
                .map_err(|e| Error::in_file(ErrorKind::Mcap(e), &self.path))?;
            out.into_inner()
                .flush()
                .map_err(|e| Error::in_file(ErrorKind::Io(e), &self.path))?;
        }
        Ok(())
    }

    fn frames(&self) -> u64 {
        self.frames
    }
}
