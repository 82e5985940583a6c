//! Reading `.xodr` text into the data model, one file per part of the XSD.

mod controller;
mod header;
mod junction;
mod lanes;
mod load;
mod reader;
mod references;
mod road;

pub(crate) use controller::read_controller;
pub(crate) use header::read_header;
pub(crate) use junction::read_junction;
pub(crate) use load::{load, Loaded};
pub(crate) use reader::child;
pub(crate) use reader::Reader;
pub(crate) use references::{check_references, Ids};
pub(crate) use road::read_road;
