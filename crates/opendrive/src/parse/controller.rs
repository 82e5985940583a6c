//! Reads `<controller>` (OpenDRIVE 1.8 §14, "Controllers"; XSD `t_controller` with its
//! `<control signalId type>` children).

use roxmltree::Node;

use super::reader::{children, Reader};
use crate::error::Error;
use crate::model::Controller;

/// XSD `t_controller`.
pub(crate) fn read_controller(r: &Reader, node: Node) -> Result<Controller, Error> {
    let mut signal_ids = Vec::new();
    for c in children(node, "control") {
        signal_ids.push(r.req_str(c, "signalId")?.to_string());
    }
    Ok(Controller {
        id: r.req_str(node, "id")?.to_string(),
        name: node.attribute("name").unwrap_or_default().to_string(),
        signal_ids,
    })
}
