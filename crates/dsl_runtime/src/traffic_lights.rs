//! `map.set_traffic_lights_control_file(file)` (ASAM OpenSCENARIO DSL 2.1 §8.12.2.2.12:
//! "Specifies a file with traffic lights control cycles. This file references traffic lights
//! or control groups defined in the map file"), read as the traffic signal controllers of an
//! OpenSCENARIO 1.3 file (§7.2 RoadNetwork, XSD `TrafficSignals`, `TrafficSignalController`,
//! `Phase`), which the lowered scenario runs as its own.
//!
//! The standard names no format for the file. oscsim takes the one its engine runs: an
//! OpenSCENARIO 1.x file, read whole by the `scenario` crate, of which only the
//! `RoadNetwork/TrafficSignals` controllers are taken; the file must have at least one and
//! nothing else that acts (no entities, no stories: they would be silently dropped). Where the
//! standard says states "not applicable to the referenced traffic lights may result in undefined
//! behavior", oscsim is strict: every `trafficSignalId` must be a signal of the loaded map.

use std::path::Path;

use opendrive::RoadNetwork;
use scenario::TrafficSignalController;

use crate::error::{Error, ErrorKind as K, Site};

/// The controllers of the control file `file`, checked against `net`; errors at `site` (the
/// modifier).
pub(crate) fn controllers(
    file: &Path,
    net: &RoadNetwork,
    site: &Site,
) -> Result<Vec<TrafficSignalController>, Error> {
    let shown = file.display();
    let s = scenario::Scenario::load(file).map_err(|e| {
        site.err(
            K::Road,
            format!("expected an OpenSCENARIO 1.x file of traffic signal controllers for set_traffic_lights_control_file, found one that does not load: {e}"),
        )
    })?;
    if !s.entities.scenario_objects.is_empty() || !s.storyboard.stories.is_empty() {
        return Err(site.err(
            K::Road,
            format!("expected {shown} to hold traffic signal controllers only (RoadNetwork/TrafficSignals), found entities or stories (they would not run)"),
        ));
    }
    let found = s.road_network.traffic_signal_controllers;
    if found.is_empty() {
        return Err(site.err(
            K::Road,
            format!("expected a TrafficSignalController in RoadNetwork/TrafficSignals of {shown}, found none"),
        ));
    }
    let signals: Vec<&str> = net
        .roads()
        .iter()
        .flat_map(|r| r.signals.iter().map(|g| g.id.as_str()))
        .collect();
    for c in &found {
        for p in &c.phases {
            if let Some((id, _)) = p
                .signal_states
                .iter()
                .find(|(id, _)| !signals.contains(&id.as_str()))
            {
                return Err(site.err(
                    K::Road,
                    format!("expected the signals of {shown} in the map (signals {}), found `{id}` in phase `{}` of controller `{}` at {}", signals.join(", "), p.name, c.name, p.pos),
                ));
            }
        }
    }
    Ok(found)
}
