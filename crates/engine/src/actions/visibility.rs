//! VisibilityAction (OpenSCENARIO 1.3 §7.7.2 private actions, XSD `VisibilityAction`): whether
//! the actor is seen by image generators (`graphics`), by sensors (`sensors`, optionally only
//! by the sensors of its `SensorReferenceSet`) and by other traffic participants (`traffic`).
//! Instantaneous (Annex A: the action does not assign a control strategy, §7.5.2).
//!
//! The flags go into the entity's state and so into every frame
//! ([`crate::output::EntityFrame::visibility`]), and each change into the event log (kind
//! `entity`, e.g. `visibility graphics on sensors off traffic on`). Where they act:
//! - `sensors`: the OSI writer leaves an entity invisible to sensors out of the GroundTruth
//!   (docs/osi.md "Visibility"); the SensorReferenceSet names only appear in the event log,
//!   since oscsim models no sensors that could be named.
//! - `graphics`, `traffic`: oscsim drives no image generator, and its default controller
//!   perceives no other entity (it keeps its lane and speed, §7.5.1), so nothing in the run
//!   changes; the flags are in the frames for the consumers that do (docs/osi.md).
//!
//! Conditions are unaffected: they are the scenario's measurements, not a traffic
//! participant's perception (§7.6).

use scenario::VisibilityAction;

use crate::output::EventRecord;
use crate::store::World;
use crate::world::entity::{EntityId, Visibility};

/// `on` / `off`.
fn on_off(flag: bool) -> &'static str {
    if flag {
        "on"
    } else {
        "off"
    }
}

/// Applies the flags to `actor` at `time` on behalf of the action called `element` and logs
/// the change.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    action: &VisibilityAction,
    element: &str,
    time: f64,
    events: &mut Vec<EventRecord>,
) {
    let e = world.entity_mut(actor);
    e.visibility = Visibility {
        graphics: action.graphics,
        sensors: action.sensors,
        traffic: action.traffic,
    };
    let mut change = format!(
        "visibility graphics {} sensors {} traffic {}",
        on_off(action.graphics),
        on_off(action.sensors),
        on_off(action.traffic)
    );
    if !action.sensor_references.is_empty() {
        change.push_str(&format!(" ({})", action.sensor_references.join(", ")));
    }
    events.push(EventRecord::Entity {
        time,
        element: element.to_owned(),
        entity: e.name.clone(),
        change,
    });
}
