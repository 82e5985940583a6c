//! The error a [`FrameSink`](super::FrameSink) or [`EventSink`](super::EventSink) returns: an
//! I/O error, or the sink's own error kept as its type (an OSI mapping error stays an
//! `osi::Error` that the caller can downcast to), never flattened into a string.

use std::error::Error as StdError;
use std::sync::Arc;

/// Why a sink could not take a frame or an event record, or could not finish.
#[derive(Debug, Clone, thiserror::Error)]
#[error("{kind}")]
pub struct SinkError {
    kind: SinkErrorKind,
}

/// The kinds of [`SinkError`].
#[derive(Debug, Clone, thiserror::Error)]
#[non_exhaustive]
pub enum SinkErrorKind {
    /// Reading or writing a file or stream failed.
    #[error(transparent)]
    Io(Arc<std::io::Error>),
    /// The sink's own error (e.g. `osi::Error`), typed: see [`SinkError::downcast_ref`].
    #[error(transparent)]
    Sink(Arc<dyn StdError + Send + Sync + 'static>),
}

impl SinkError {
    /// A sink's own error, kept as its type.
    pub fn sink(error: impl StdError + Send + Sync + 'static) -> Self {
        SinkError {
            kind: SinkErrorKind::Sink(Arc::new(error)),
        }
    }

    /// What went wrong.
    pub fn kind(&self) -> &SinkErrorKind {
        &self.kind
    }

    /// The sink's own error as type `E`, if it is one.
    pub fn downcast_ref<E: StdError + 'static>(&self) -> Option<&E> {
        match &self.kind {
            SinkErrorKind::Io(e) => (&**e as &(dyn StdError + 'static)).downcast_ref(),
            SinkErrorKind::Sink(e) => e.downcast_ref(),
        }
    }
}

impl From<std::io::Error> for SinkError {
    fn from(e: std::io::Error) -> Self {
        SinkError {
            kind: SinkErrorKind::Io(Arc::new(e)),
        }
    }
}

/// Two sink errors are equal when they are the same error value (shared by clones) or say the
/// same thing: the wrapped errors need not be comparable.
impl PartialEq for SinkError {
    fn eq(&self, other: &Self) -> bool {
        self.to_string() == other.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, thiserror::Error, PartialEq)]
    #[error("lane 3 has no boundary")]
    struct Mapping;

    #[test]
    fn keeps_the_sink_error_type() {
        let e = SinkError::sink(Mapping);
        assert_eq!(e.downcast_ref::<Mapping>(), Some(&Mapping));
        assert_eq!(e.to_string(), "lane 3 has no boundary");
        assert!(e.downcast_ref::<std::io::Error>().is_none());
        let io: SinkError = std::io::Error::other("disk full").into();
        assert!(matches!(io.kind(), SinkErrorKind::Io(_)));
        assert_eq!(io.to_string(), "disk full");
        assert_eq!(io.clone(), io);
    }
}
