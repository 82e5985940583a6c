//! ASAM OSI 3.x ground-truth messages and trace writers for oscsim.
#![forbid(unsafe_code)]
#![deny(missing_docs)]
