//! The crate's error type: what went wrong, in which file, and where.
//!
//! Trace files are binary, so a place in one is a byte offset, shown as
//! `file:byte N`. Values handed in by a caller (a category string, a colour) carry no
//! file; their message says which value was expected and which was found.

use std::fmt;
use std::path::{Path, PathBuf};

/// An error of the `osi` crate: a [`ErrorKind`] plus, where there is one, the file.
#[derive(Debug)]
pub struct Error {
    kind: ErrorKind,
    path: Option<PathBuf>,
}

/// What went wrong.
#[derive(Debug)]
#[non_exhaustive]
pub enum ErrorKind {
    /// Reading or writing the file failed.
    Io(std::io::Error),
    /// The MCAP library refused to write or read the file.
    Mcap(mcap::McapError),
    /// A length prefix announced more bytes than the file holds.
    Truncated {
        /// Byte offset of the message (after its length prefix).
        offset: u64,
        /// Bytes the length prefix announced.
        wanted: u64,
        /// Bytes left in the file.
        found: u64,
    },
    /// Bytes that do not decode as an `osi3.GroundTruth`.
    Decode {
        /// Byte offset of the message.
        offset: u64,
        /// What the protobuf decoder reported.
        source: prost::DecodeError,
    },
    /// A message of an `.mcap` trace that does not decode as an `osi3.GroundTruth`.
    DecodeFrame {
        /// 0-based index of the message in the channel.
        frame: u64,
        /// What the protobuf decoder reported.
        source: prost::DecodeError,
    },
    /// A message longer than the 4-byte length prefix of `.osi` can announce.
    MessageTooLarge {
        /// Encoded length of the message.
        len: usize,
    },
    /// A frame whose timestamp is not later than the previous frame's (OSI trace readers
    /// expect strictly increasing time).
    TimestampNotIncreasing {
        /// Previous frame's time (ns).
        previous: u64,
        /// This frame's time (ns).
        found: u64,
    },
    /// A frame without timestamp.
    MissingTimestamp,
    /// A frame written after [`crate::trace::TraceWriter::finish`].
    Finished,
    /// A file that is not the OSI trace layout this crate writes or reads.
    NotOsiTrace {
        /// What was expected.
        expected: String,
        /// What was found instead.
        found: String,
    },
    /// The road model could not be evaluated (the opendrive crate's error, with its place).
    OpenDrive(opendrive::Error),
    /// A value handed in by the caller that is outside its domain.
    InvalidValue {
        /// Which value (for example "vehicleCategory").
        what: &'static str,
        /// What was expected.
        expected: &'static str,
        /// What was found.
        found: String,
    },
}

impl Error {
    pub(crate) fn new(kind: ErrorKind) -> Self {
        Error { kind, path: None }
    }

    pub(crate) fn in_file(kind: ErrorKind, path: &Path) -> Self {
        Error {
            kind,
            path: Some(path.to_path_buf()),
        }
    }

    pub(crate) fn invalid(what: &'static str, expected: &'static str, found: &str) -> Self {
        Error::new(ErrorKind::InvalidValue {
            what,
            expected,
            found: found.to_string(),
        })
    }

    /// What went wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }

    /// The file concerned, if any.
    pub fn path(&self) -> Option<&Path> {
        self.path.as_deref()
    }

    /// The line:col of a text file the error is about, where it has one: a road network
    /// that does not load ([`ErrorKind::OpenDrive`], its `.xodr` position). A place in a trace
    /// file is a byte offset, not a line and column: see the kind's `offset` and [`path`](Self::path).
    pub fn pos(&self) -> Option<&opendrive::SourcePos> {
        match &self.kind {
            ErrorKind::OpenDrive(e) => e.pos(),
            _ => None,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let file = self
            .path
            .as_deref()
            .map_or_else(|| "<memory>".to_string(), |p| p.display().to_string());
        match &self.kind {
            ErrorKind::Io(e) => write!(f, "cannot access {file}: {e}"),
            ErrorKind::Mcap(e) => write!(f, "mcap error in {file}: {e}"),
            ErrorKind::Truncated {
                offset,
                wanted,
                found,
            } => write!(
                f,
                "expected a message of {wanted} bytes, found only {found} bytes at {file}:byte {offset}"
            ),
            ErrorKind::Decode { offset, source } => write!(
                f,
                "expected an osi3.GroundTruth, found undecodable bytes ({source}) at {file}:byte {offset}"
            ),
            ErrorKind::DecodeFrame { frame, source } => write!(
                f,
                "expected an osi3.GroundTruth, found undecodable bytes ({source}) in message {frame} of {file}"
            ),
            ErrorKind::MessageTooLarge { len } => write!(
                f,
                "expected a message of at most 4294967295 bytes, found {len} bytes for {file}"
            ),
            ErrorKind::TimestampNotIncreasing { previous, found } => write!(
                f,
                "expected a timestamp after {previous} ns, found {found} ns in {file}"
            ),
            ErrorKind::MissingTimestamp => {
                write!(f, "expected a GroundTruth with a timestamp, found none for {file}")
            }
            ErrorKind::Finished => write!(f, "expected an open trace, found {file} already finished"),
            ErrorKind::NotOsiTrace { expected, found } => {
                write!(f, "expected {expected}, found {found} in {file}")
            }
            ErrorKind::OpenDrive(e) => write!(f, "road model: {e}"),
            ErrorKind::InvalidValue {
                what,
                expected,
                found,
            } => write!(f, "expected {what} to be {expected}, found {found:?}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match &self.kind {
            ErrorKind::Io(e) => Some(e),
            ErrorKind::Mcap(e) => Some(e),
            ErrorKind::OpenDrive(e) => Some(e),
            ErrorKind::Decode { source, .. } | ErrorKind::DecodeFrame { source, .. } => {
                Some(source)
            }
            _ => None,
        }
    }
}
