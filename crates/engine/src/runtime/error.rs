//! The runtime's name for the engine's error ([`crate::error`]): `RuntimeError` is
//! [`crate::Error`], `RuntimeErrorKind` is [`crate::ErrorKind`].

pub use crate::error::{Error as RuntimeError, ErrorKind as RuntimeErrorKind};
