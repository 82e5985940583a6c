//! The road network reference (OpenSCENARIO 1.3, XSD `RoadNetwork`, `TrafficSignals`,
//! `TrafficSignalController`, `Phase`, `UsedArea`). The LogicFile path resolves against the
//! scenario's directory and must exist (in the load's file provider); parsing it is the opendrive crate's job.

use std::path::Path;

use crate::error::{Error, ErrorKind, Result};
use crate::model::{Phase, RoadNetwork, TrafficSignalController};
use crate::reader::context::{Ctx, Node};
use crate::reader::files::resolve_path;
use crate::reader::positions::read_position;

/// Reads XSD `RoadNetwork`; the LogicFile must exist (resolved against the scenario).
pub(crate) fn read_road_network<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
    path: &Path,
) -> Result<RoadNetwork> {
    ctx.expect_children(
        n,
        &["LogicFile", "SceneGraphFile", "TrafficSignals", "UsedArea"],
    )?;
    let mut road = RoadNetwork::default();
    if let Some(l) = ctx.opt_child(n, "LogicFile") {
        let written: String = ctx.req(l, "filepath")?;
        let resolved = resolve_path(path, &written);
        if !ctx.files.is_file(&resolved) {
            let pos = ctx
                .raw_attr(l, "filepath")
                .map_or_else(|| ctx.pos(l), |a| ctx.attr_pos(&a));
            return Err(Error::new(
                ErrorKind::FileNotFound {
                    what: "road network",
                    written,
                    resolved,
                },
                pos,
            ));
        }
        road.logic_file = Some(resolved);
    }
    if let Some(s) = ctx.opt_child(n, "SceneGraphFile") {
        road.scene_graph_file = Some(ctx.req(s, "filepath")?);
    }
    if let Some(t) = ctx.opt_child(n, "TrafficSignals") {
        for c in ctx.children(t, "TrafficSignalController") {
            let mut phases = Vec::new();
            for p in ctx.children(c, "Phase") {
                let mut signal_states = Vec::new();
                for s in ctx.children(p, "TrafficSignalState") {
                    signal_states.push((ctx.req(s, "trafficSignalId")?, ctx.req(s, "state")?));
                }
                // The 1.2 XSD spells it `TrafficeSignalGroupState`; 1.3 corrected the name.
                let misspelt = ctx.opt_child(p, "TrafficeSignalGroupState");
                if let Some(g) = misspelt {
                    ctx.warn(g, "TrafficeSignalGroupState (the 1.2 spelling) read as TrafficSignalGroupState".into());
                }
                let group_state = match ctx.opt_child(p, "TrafficSignalGroupState").or(misspelt) {
                    Some(g) => Some(ctx.req(g, "state")?),
                    None => None,
                };
                phases.push(Phase {
                    name: ctx.req(p, "name")?,
                    duration: ctx.req(p, "duration")?,
                    signal_states,
                    group_state,
                    pos: ctx.pos(p),
                });
            }
            road.traffic_signal_controllers
                .push(TrafficSignalController {
                    name: ctx.req(c, "name")?,
                    delay: ctx.opt(c, "delay")?,
                    reference: ctx.opt(c, "reference")?,
                    phases,
                    pos: ctx.pos(c),
                });
        }
    }
    if let Some(u) = ctx.opt_child(n, "UsedArea") {
        ctx.since(u, 1);
        for p in ctx.children(u, "Position") {
            road.used_area.push(read_position(ctx, p)?);
        }
    }
    Ok(road)
}
