//! TrafficSignalGroupState (OpenSCENARIO 1.3, XSD `Phase`, `TrafficSignalGroupState`): "Each
//! phase can have one TrafficSignalGroupState to provide the observable state for all traffic
//! signals that are controlled by the controller if they share the same state" (issue 34
//! class 6). The controller is the group.
//!
//! Which signals a controller controls: TrafficSignalController@name is the "ID of the traffic
//! signal controller in the road network", so the signals of the road network's `<controller>`
//! with that id (OpenDRIVE 1.8 §14, its `<control signalId>`s; a `<controller>` whose `name` is
//! the controller's name when no id matches), followed by every signal a TrafficSignalState of
//! any of its phases names, each once, in that order. A phase with a group state sets each of
//! them to the group state when the controller enters it. The standard calls the two forms
//! mutually exclusive; a phase with both is read with its TrafficSignalStates applied after the
//! group state, so a signal named in both shows its own. A group state on a controller with no
//! signal (no `<controller>` of that id in the road network, no TrafficSignalState) would set
//! nothing: an error at the phase.

use scenario::TrafficSignalController;

use super::Controller;
use crate::error::Error;

/// The signal ids controller `c` controls (see the module doc), each once.
fn members(c: &TrafficSignalController, road_controllers: &[opendrive::Controller]) -> Vec<String> {
    let road = road_controllers
        .iter()
        .find(|r| r.id == c.name)
        .or_else(|| road_controllers.iter().find(|r| r.name == c.name));
    let mut ids: Vec<String> = Vec::new();
    let named = c
        .phases
        .iter()
        .flat_map(|p| p.signal_states.iter().map(|(id, _)| id));
    for id in road
        .into_iter()
        .flat_map(|r| r.signal_ids.iter())
        .chain(named)
    {
        if !ids.contains(id) {
            ids.push(id.clone());
        }
    }
    ids
}

/// Controller `c` with each phase's (signal id, state) list, group states expanded.
pub(super) fn phase_states(
    c: &TrafficSignalController,
    road_controllers: &[opendrive::Controller],
) -> Result<Controller, Error> {
    let needs_members = c.phases.iter().any(|p| p.group_state.is_some());
    let members = if needs_members {
        members(c, road_controllers)
    } else {
        Vec::new()
    };
    let mut phases = Vec::with_capacity(c.phases.len());
    for p in &c.phases {
        let mut states = Vec::new();
        if let Some(group) = &p.group_state {
            if members.is_empty() {
                return Err(Error::at(
                    format!(
                        "a traffic signal controlled by '{}' for the TrafficSignalGroupState of phase '{}' \
                         (a <controller id=\"{}\"> of the road network, or a TrafficSignalState of its phases)",
                        c.name, p.name, c.name
                    ),
                    "none",
                    &p.pos,
                ));
            }
            states.extend(members.iter().map(|id| (id.clone(), group.clone())));
        }
        states.extend(p.signal_states.iter().cloned());
        phases.push((p.name.clone(), states));
    }
    Ok(Controller {
        name: c.name.clone(),
        phases,
    })
}
