//! Reads `<header>` (OpenDRIVE 1.8, XSD `t_header`) with `<geoReference>` and
//! `<offset>` (§8, georeferencing).

use roxmltree::Node;

use super::reader::{child, Reader};
use crate::error::Error;
use crate::model::{GeoReference, Header, Offset};

/// XSD `t_header`.
pub(crate) fn read_header(r: &Reader, node: Node) -> Result<Header, Error> {
    let text = |name: &str| node.attribute(name).unwrap_or_default().to_string();
    let geo_reference = child(node, "geoReference")
        .map(|g| GeoReference(g.text().unwrap_or_default().trim().to_string()));
    let offset = match child(node, "offset") {
        Some(o) => Some(Offset {
            x: r.opt_f64(o, "x", 0.0)?,
            y: r.opt_f64(o, "y", 0.0)?,
            z: r.opt_f64(o, "z", 0.0)?,
            hdg: r.opt_f64(o, "hdg", 0.0)?,
        }),
        None => None,
    };
    Ok(Header {
        rev_major: r.opt_u32(node, "revMajor", 1)?,
        rev_minor: r.opt_u32(node, "revMinor", 4)?,
        name: text("name"),
        version: text("version"),
        date: text("date"),
        vendor: text("vendor"),
        north: r.opt_f64(node, "north", 0.0)?,
        south: r.opt_f64(node, "south", 0.0)?,
        east: r.opt_f64(node, "east", 0.0)?,
        west: r.opt_f64(node, "west", 0.0)?,
        geo_reference,
        offset,
    })
}
