//! Reads `<junction>` (OpenDRIVE 1.8 §12, junctions; XSD `t_junction`): connections with
//! `connectingRoad` (common junctions) or `linkedRoad` (direct junctions) and lane links.

use roxmltree::Node;

use super::reader::{children, Reader};
use super::road::read_contact_point;
use crate::error::{Error, ErrorKind};
use crate::model::{Connection, ContactPoint, Junction, JunctionKind, LaneLink};

/// XSD `t_junction`.
pub(crate) fn read_junction(r: &Reader, node: Node) -> Result<Junction, Error> {
    let kind = match node.attribute("type").unwrap_or("default") {
        "default" => JunctionKind::Default,
        "direct" => JunctionKind::Direct,
        _ => JunctionKind::Other,
    };
    let mut connections = Vec::new();
    for c in children(node, "connection") {
        let connecting = c
            .attribute("connectingRoad")
            .or_else(|| c.attribute("linkedRoad"))
            .ok_or_else(|| {
                r.error_at(
                    c,
                    ErrorKind::MissingAttribute {
                        element: "connection".into(),
                        attribute: "connectingRoad (or linkedRoad)".into(),
                    },
                )
            })?;
        let contact_point =
            read_contact_point(r, c, "contactPoint")?.unwrap_or(ContactPoint::Start);
        let mut lane_links = Vec::new();
        for l in children(c, "laneLink") {
            lane_links.push(LaneLink {
                from: r.req_i32(l, "from")?,
                to: r.req_i32(l, "to")?,
            });
        }
        connections.push(Connection {
            id: r.req_str(c, "id")?.to_string(),
            incoming_road: r.req_str(c, "incomingRoad")?.to_string(),
            connecting_road: connecting.to_string(),
            contact_point,
            lane_links,
        });
    }
    Ok(Junction {
        id: r.req_str(node, "id")?.to_string(),
        name: node.attribute("name").unwrap_or_default().to_string(),
        kind,
        connections,
    })
}
