//! Checks that every reference in the file names something that exists: road links
//! (OpenDRIVE 1.8 §10), `road/@junction`, junction connections and their lane links (§12).
//! Runs over the XML a second time so that errors point at the referring attribute.

use roxmltree::Node;
use rustc_hash::FxHashMap;

use super::reader::{child, children, Reader};
use crate::error::Error;
use crate::model::Road;

/// Lookup tables of the ids read in the first pass.
pub(crate) struct Ids<'a> {
    /// Road id → road.
    pub(crate) roads: &'a FxHashMap<String, usize>,
    /// All roads.
    pub(crate) road_list: &'a [Road],
    /// Junction id → index.
    pub(crate) junctions: &'a FxHashMap<String, usize>,
}

/// Whether any lane section of `road` holds lane `id`.
fn has_lane(road: &Road, id: i32) -> bool {
    road.lane_sections.iter().any(|ls| ls.lane(id).is_some())
}

/// Fails at the first reference to a road or junction that does not exist. Lane links naming
/// a lane that does not exist are returned as warnings (generated files in the corpus hold
/// such links; the lane graph ignores them).
pub(crate) fn check_references(r: &Reader, root: Node, ids: &Ids) -> Result<Vec<Error>, Error> {
    let mut warnings = Vec::new();
    for road in children(root, "road") {
        if let Some(j) = road.attribute("junction").map(str::trim) {
            if j != "-1" && !j.is_empty() && !ids.junctions.contains_key(j) {
                return Err(r.unknown(road, "junction", "junction", j));
            }
        }
        let Some(link) = child(road, "link") else {
            continue;
        };
        for end in ["predecessor", "successor"] {
            let Some(l) = children(link, end).next() else {
                continue;
            };
            let id = r.req_str(l, "elementId")?;
            let (known, target) = match l.attribute("elementType") {
                Some("junction") => (ids.junctions.contains_key(id), "junction"),
                _ => (ids.roads.contains_key(id), "road"),
            };
            if !known {
                return Err(r.unknown(l, "elementId", target, id));
            }
        }
    }
    for junction in children(root, "junction") {
        for c in children(junction, "connection") {
            let incoming = r.req_str(c, "incomingRoad")?;
            let Some(&inc) = ids.roads.get(incoming) else {
                return Err(r.unknown(c, "incomingRoad", "road", incoming));
            };
            let attr = if c.attribute("connectingRoad").is_some() {
                "connectingRoad"
            } else {
                "linkedRoad"
            };
            let connecting = r.req_str(c, attr)?;
            let Some(&con) = ids.roads.get(connecting) else {
                return Err(r.unknown(c, attr, "road", connecting));
            };
            for ll in children(c, "laneLink") {
                let from = r.req_i32(ll, "from")?;
                if !has_lane(&ids.road_list[inc], from) {
                    warnings.push(r.unknown(
                        ll,
                        "from",
                        &format!("lane of road {incoming}"),
                        &from.to_string(),
                    ));
                }
                let to = r.req_i32(ll, "to")?;
                if !has_lane(&ids.road_list[con], to) {
                    warnings.push(r.unknown(
                        ll,
                        "to",
                        &format!("lane of road {connecting}"),
                        &to.to_string(),
                    ));
                }
            }
        }
    }
    Ok(warnings)
}
