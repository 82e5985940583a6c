//! The single-channel binary trace format `.osi` (ASAM OSI 3.8 §2.2.6.1.1): each
//! serialized message after its length as a four-byte little-endian unsigned integer
//! that does not count itself.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use prost::Message;

use crate::error::{Error, ErrorKind};
use crate::osi3::GroundTruth;
use crate::trace::writer::{TimeOrder, TraceWriter};

/// Writes GroundTruth frames as a `.osi` trace.
#[derive(Debug)]
pub struct OsiFileWriter<W: Write> {
    out: Option<W>,
    path: PathBuf,
    buf: Vec<u8>,
    frames: u64,
    time: TimeOrder,
}

impl OsiFileWriter<BufWriter<File>> {
    /// Creates (or truncates) the file at `path`.
    pub fn create(path: &Path) -> Result<Self, Error> {
        let file = File::create(path).map_err(|e| Error::in_file(ErrorKind::Io(e), path))?;
        Ok(Self::new(BufWriter::new(file), path))
    }
}

impl<W: Write> OsiFileWriter<W> {
    /// Writes into `out`; `path` names it in errors.
    pub fn new(out: W, path: &Path) -> Self {
        OsiFileWriter {
            out: Some(out),
            path: path.to_path_buf(),
            buf: Vec::new(),
            frames: 0,
            time: TimeOrder::default(),
        }
    }

    /// Finishes and hands back the inner writer, if not finished before.
    pub fn into_inner(mut self) -> Result<Option<W>, Error> {
        if let Some(out) = self.out.as_mut() {
            out.flush()
                .map_err(|e| Error::in_file(ErrorKind::Io(e), &self.path))?;
        }
        Ok(self.out.take())
    }
}

impl<W: Write> TraceWriter for OsiFileWriter<W> {
    fn write(&mut self, ground_truth: &GroundTruth) -> Result<(), Error> {
        let Some(out) = self.out.as_mut() else {
            return Err(Error::in_file(ErrorKind::Finished, &self.path));
        };
        self.time.next(ground_truth, &self.path)?;
        // Room for the prefix first, then the message; the prefix is filled in after, so
        // the message's length is computed only once (by `encode`).
        self.buf.clear();
        self.buf.extend_from_slice(&[0; 4]);
        // Encoding into a Vec cannot run out of space: Vec grows as needed.
        ground_truth
            .encode(&mut self.buf)
            .expect("encoding into a Vec<u8> never fails");
        let len = self.buf.len() - 4;
        let prefix = u32::try_from(len)
            .map_err(|_| Error::in_file(ErrorKind::MessageTooLarge { len }, &self.path))?;
        self.buf[..4].copy_from_slice(&prefix.to_le_bytes());
        out.write_all(&self.buf)
            .map_err(|e| Error::in_file(ErrorKind::Io(e), &self.path))?;
        self.frames += 1;
        Ok(())
    }

    fn finish(&mut self) -> Result<(), Error> {
        if let Some(mut out) = self.out.take() {
            out.flush()
                .map_err(|e| Error::in_file(ErrorKind::Io(e), &self.path))?;
        }
        Ok(())
    }

    fn frames(&self) -> u64 {
        self.frames
    }
}
