//! Reading back the traces this crate writes, for tests and tools: `.osi`
//! (ASAM OSI 3.8 §2.2.6.1.1) and the OSI `.mcap` layout (§2.2.6.1.2). Every problem is
//! reported with the file and the byte offset; nothing here panics on bad input.

use std::collections::BTreeMap;
use std::path::Path;

use prost::Message;

use crate::error::{Error, ErrorKind};
use crate::osi3::GroundTruth;
use crate::schema::GROUND_TRUTH_SCHEMA_NAME;
use crate::trace::mcap_file::OSI_TRACE_METADATA_NAME;

/// Every GroundTruth of a `.osi` file.
pub fn read_osi(path: &Path) -> Result<Vec<GroundTruth>, Error> {
    let bytes = std::fs::read(path).map_err(|e| Error::in_file(ErrorKind::Io(e), path))?;
    read_osi_bytes(&bytes, path)
}

/// Every GroundTruth of `.osi` bytes; `path` names them in errors.
pub fn read_osi_bytes(bytes: &[u8], path: &Path) -> Result<Vec<GroundTruth>, Error> {
    let mut frames = Vec::new();
    let mut pos = 0usize;
    while pos < bytes.len() {
        let left = bytes.len() - pos;
        let Some(prefix) = bytes.get(pos..pos + 4) else {
            let kind = ErrorKind::Truncated {
                offset: pos as u64,
                wanted: 4,
                found: left as u64,
            };
            return Err(Error::in_file(kind, path));
        };
        // `prefix` has exactly 4 bytes: the slice above is pos..pos + 4.
        let len = u32::from_le_bytes(prefix.try_into().expect("4-byte slice")) as usize;
        let start = pos + 4;
        let Some(body) = bytes.get(start..start.saturating_add(len)) else {
            let kind = ErrorKind::Truncated {
                offset: start as u64,
                wanted: len as u64,
                found: (bytes.len() - start) as u64,
            };
            return Err(Error::in_file(kind, path));
        };
        let gt = GroundTruth::decode(body).map_err(|source| {
            let kind = ErrorKind::Decode {
                offset: start as u64,
                source,
            };
            Error::in_file(kind, path)
        })?;
        frames.push(gt);
        pos = start + len;
    }
    Ok(frames)
}

/// What an OSI `.mcap` trace holds, as read back.
#[derive(Debug, Clone, Default)]
pub struct McapTrace {
    /// MCAP header profile.
    pub profile: String,
    /// Entries of the `net.asam.osi.trace` metadata record.
    pub trace_metadata: BTreeMap<String, String>,
    /// Topic of the ground-truth channel.
    pub topic: String,
    /// Metadata of the ground-truth channel.
    pub channel_metadata: BTreeMap<String, String>,
    /// Schema encoding of the channel (`protobuf`).
    pub schema_encoding: String,
    /// Schema data of the channel (a binary `FileDescriptorSet`).
    pub schema_data: Vec<u8>,
    /// Message encoding of the channel (`protobuf`).
    pub message_encoding: String,
    /// Each frame with its MCAP `sequence`, `log_time` and `publish_time` (ns).
    pub frames: Vec<McapFrame>,
}

/// One message of an OSI `.mcap` trace.
#[derive(Debug, Clone, PartialEq)]
pub struct McapFrame {
    /// MCAP sequence number.
    pub sequence: u32,
    /// MCAP log time (ns).
    pub log_time: u64,
    /// MCAP publish time (ns).
    pub publish_time: u64,
    /// The decoded message.
    pub ground_truth: GroundTruth,
}

/// Reads an OSI `.mcap` trace whose messages are all `osi3.GroundTruth` on one channel.
pub fn read_mcap(path: &Path) -> Result<McapTrace, Error> {
    let bytes = std::fs::read(path).map_err(|e| Error::in_file(ErrorKind::Io(e), path))?;
    read_mcap_bytes(&bytes, path)
}

/// Like [`read_mcap`], from bytes; `path` names them in errors.
pub fn read_mcap_bytes(bytes: &[u8], path: &Path) -> Result<McapTrace, Error> {
    let mcap_err = |e| Error::in_file(ErrorKind::Mcap(e), path);
    let not_osi = |expected: &str, found: String| {
        let kind = ErrorKind::NotOsiTrace {
            expected: expected.to_string(),
            found,
        };
        Error::in_file(kind, path)
    };
    let mut trace = McapTrace::default();
    for record in mcap::read::LinearReader::new(bytes).map_err(mcap_err)? {
        match record.map_err(mcap_err)? {
            mcap::records::Record::Header(h) => trace.profile = h.profile,
            mcap::records::Record::Metadata(m) if m.name == OSI_TRACE_METADATA_NAME => {
                trace.trace_metadata = m.metadata;
            }
            _ => {}
        }
    }
    if trace.trace_metadata.is_empty() {
        return Err(not_osi(
            "a metadata record named net.asam.osi.trace",
            "none".into(),
        ));
    }
    let summary = mcap::read::Summary::read(bytes)
        .map_err(mcap_err)?
        .ok_or_else(|| not_osi("an indexed MCAP file with a summary section", "none".into()))?;
    let mut channels: Vec<_> = summary.channels.values().collect();
    channels.sort_by_key(|c| c.id);
    let channel = match channels.as_slice() {
        [one] => one,
        other => {
            return Err(not_osi(
                "exactly one channel",
                format!("{} channels", other.len()),
            ))
        }
    };
    let schema = channel
        .schema
        .as_ref()
        .ok_or_else(|| not_osi("a channel with a schema", "a schemaless channel".into()))?;
    if schema.name != GROUND_TRUTH_SCHEMA_NAME {
        return Err(not_osi("schema osi3.GroundTruth", schema.name.clone()));
    }
    trace.topic = channel.topic.clone();
    trace.channel_metadata = channel.metadata.clone();
    trace.message_encoding = channel.message_encoding.clone();
    trace.schema_encoding = schema.encoding.clone();
    trace.schema_data = schema.data.to_vec();

    for message in mcap::MessageStream::new(bytes).map_err(mcap_err)? {
        let message = message.map_err(mcap_err)?;
        let ground_truth = GroundTruth::decode(message.data.as_ref()).map_err(|source| {
            // The stream does not expose file offsets; the frame index locates the message.
            let kind = ErrorKind::DecodeFrame {
                frame: trace.frames.len() as u64,
                source,
            };
            Error::in_file(kind, path)
        })?;
        trace.frames.push(McapFrame {
            sequence: message.sequence,
            log_time: message.log_time,
            publish_time: message.publish_time,
            ground_truth,
        });
    }
    Ok(trace)
}
