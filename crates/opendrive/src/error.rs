//! The crate's error type: an opaque [`Error`] whose [`ErrorKind`] says what went wrong and
//! whose position says where (a [`SourcePos`]: file, 1-based `line:col`), in the style of
//! roxmltree's errors.

use std::fmt;
use std::path::Path;
use std::sync::Arc;

use source::SourcePos;

/// What went wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The file could not be read.
    #[error("cannot read file: {0}")]
    Io(String),
    /// The text is not well-formed XML.
    #[error("malformed XML: {0}")]
    Xml(String),
    /// The root element is not `<OpenDRIVE>`.
    #[error("expected root element <OpenDRIVE>, found <{0}>")]
    NotOpenDrive(String),
    /// A required attribute is absent.
    #[error("expected attribute `{attribute}` on <{element}>, found none")]
    MissingAttribute {
        /// Element name.
        element: String,
        /// Attribute name.
        attribute: String,
    },
    /// A required child element is absent.
    #[error("expected element <{child}> inside <{element}>, found none")]
    MissingElement {
        /// Parent element name.
        element: String,
        /// Missing child element name.
        child: String,
    },
    /// An attribute's value does not have the expected form or range.
    #[error("expected {expected} for `{attribute}` of <{element}>, found \"{found}\"")]
    InvalidValue {
        /// Element name.
        element: String,
        /// Attribute name.
        attribute: String,
        /// What was expected, e.g. "a finite number" or "a length > 0".
        expected: String,
        /// The text found in the file.
        found: String,
    },
    /// A reference names a road, junction or lane that does not exist.
    #[error("expected an existing {target} for `{attribute}` of <{element}>, found \"{id}\"")]
    UnknownReference {
        /// Element holding the reference.
        element: String,
        /// Attribute holding the reference.
        attribute: String,
        /// What kind of thing is referenced ("road", "junction", "lane").
        target: String,
        /// The referenced id.
        id: String,
    },
    /// The geometry or lane data is inconsistent (e.g. an empty planView, a lane section
    /// beyond the road's end).
    #[error("expected {expected} in <{element}>, found {found}")]
    Inconsistent {
        /// Element concerned.
        element: String,
        /// What was expected.
        expected: String,
        /// What was found.
        found: String,
    },
    /// A query names a road that the network does not hold.
    #[error("expected an existing road, found road id \"{0}\"")]
    NoSuchRoad(String),
    /// A query names a lane that the road's lane section at s does not hold.
    #[error("expected an existing lane, found lane {lane} on road \"{road}\" at s = {s}")]
    NoSuchLane {
        /// Road id.
        road: String,
        /// Lane id.
        lane: i32,
        /// s of the query (m).
        s: f64,
    },
    /// A query's s lies outside [0, length] of the road, or is not finite.
    #[error("expected s in [0, {length}] on road \"{road}\", found {s}")]
    SOutOfRange {
        /// Road id.
        road: String,
        /// s of the query (m).
        s: f64,
        /// The road's length (m).
        length: f64,
    },
}

/// An error of the OpenDRIVE crate: a kind, and for errors found in a file its path and
/// position. Display: `"<kind> at <file>:<line>:<col>"`.
#[derive(Debug, Clone, PartialEq)]
pub struct Error(Box<Inner>);

/// The boxed contents of an [`Error`] (boxed so that `Result<_, Error>` stays one word).
#[derive(Debug, Clone, PartialEq)]
struct Inner {
    kind: ErrorKind,
    place: Place,
}

/// Where an error was found.
#[derive(Debug, Clone, PartialEq)]
enum Place {
    /// Nowhere in a file (queries on a loaded network).
    None,
    /// A file as a whole.
    File(Arc<Path>),
    /// A place in a file.
    Pos(SourcePos),
}

impl Error {
    /// An error without a place (queries on a loaded network).
    pub(crate) fn new(kind: ErrorKind) -> Self {
        Self(Box::new(Inner {
            kind,
            place: Place::None,
        }))
    }

    /// An error about a whole file (e.g. it cannot be read).
    pub(crate) fn in_file(kind: ErrorKind, file: &Path) -> Self {
        Self(Box::new(Inner {
            kind,
            place: Place::File(Arc::from(file)),
        }))
    }

    /// An error at a place in a file.
    pub(crate) fn at(kind: ErrorKind, pos: SourcePos) -> Self {
        Self(Box::new(Inner {
            kind,
            place: Place::Pos(pos),
        }))
    }

    /// What went wrong.
    pub fn kind(&self) -> &ErrorKind {
        &self.0.kind
    }

    /// The file the error was found in, if any.
    pub fn file(&self) -> Option<&Path> {
        match &self.0.place {
            Place::None => None,
            Place::File(file) => Some(file),
            Place::Pos(pos) => Some(&pos.file),
        }
    }

    /// The file and 1-based line:col the error was found at, if any.
    pub fn pos(&self) -> Option<&SourcePos> {
        match &self.0.place {
            Place::Pos(pos) => Some(pos),
            _ => None,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.0.kind)?;
        match &self.0.place {
            Place::Pos(pos) => write!(f, " at {pos}"),
            Place::File(file) => write!(f, " in {}", file.display()),
            Place::None => Ok(()),
        }
    }
}

impl std::error::Error for Error {}
