//! OverrideControllerValueAction (OpenSCENARIO 1.3 §7.7.2.5 "ControllerAction", XSD
//! `OverrideControllerValueAction` with `OverrideThrottleAction`, `OverrideBrakeAction`,
//! `OverrideClutchAction`, `OverrideParkingBrakeAction`, `OverrideSteeringWheelAction`,
//! `OverrideGearAction`): the driver inputs a controller's output is overridden with.
//!
//! Each input the action names replaces the entity's previous override of that input (with
//! `active="false"` it releases it); the inputs it does not name keep theirs. The state lives
//! in [`Entity::overrides`](crate::runtime::Entity::overrides), where the OSI writer can read it,
//! and each change is written to the event log as an entity change (`"override brake on
//! 0.5"`, `"override gear off"`).
//!
//! Effect on motion: none. The standard defines the inputs and their ranges (pedal positions
//! 0..1, brake force in N, steering wheel angle in rad, the gear) but no mapping from them to
//! the vehicle's motion: that needs a vehicle model (engine, brakes, steering ratio) which
//! OpenSCENARIO leaves to the controller and which the default controller (§7.5.1: it keeps
//! speed and lane) does not have. So the values are kept and reported, not applied, as esmini
//! also does with its default controller.

use scenario::{BrakeInput, Gear, OverrideControllerValueAction};

use crate::output::EventRecord;
use crate::store::World;
use crate::world::entity::EntityId;

/// "on 0.5" / "off": the change of one input for the event log.
fn change(active: bool, value: String) -> String {
    if active {
        format!("on {value}")
    } else {
        "off".to_owned()
    }
}

fn brake_text(input: BrakeInput) -> String {
    match input {
        BrakeInput::Percent(p) => format!("{p}"),
        BrakeInput::Force(f) => format!("{f} N"),
        _ => "(unknown input)".to_owned(),
    }
}

fn gear_text(gear: Gear) -> String {
    match gear {
        Gear::Manual(n) => format!("manual {n}"),
        Gear::Automatic(a) => format!("automatic {a:?}"),
        _ => "(unknown gear)".to_owned(),
    }
}

/// Applies the action to `actor`: stores the named overrides and logs each change.
pub(crate) fn start(
    world: &mut World,
    actor: EntityId,
    action: &OverrideControllerValueAction,
    name: &str,
    time: f64,
    events: &mut Vec<EventRecord>,
) {
    let e = world.entity_mut(actor);
    let mut changes = Vec::new();
    if let Some(o) = action.throttle {
        changes.push(("throttle", change(o.active, format!("{}", o.value))));
        e.overrides.throttle = Some(o);
    }
    if let Some(o) = action.brake {
        changes.push(("brake", change(o.active, brake_text(o.input))));
        e.overrides.brake = Some(o);
    }
    if let Some(o) = action.clutch {
        changes.push(("clutch", change(o.active, format!("{}", o.value))));
        e.overrides.clutch = Some(o);
    }
    if let Some(o) = action.parking_brake {
        changes.push(("parkingBrake", change(o.active, brake_text(o.input))));
        e.overrides.parking_brake = Some(o);
    }
    if let Some(o) = action.steering_wheel {
        changes.push((
            "steeringWheel",
            change(o.active, format!("{} rad", o.value)),
        ));
        e.overrides.steering_wheel = Some(o);
    }
    if let Some(o) = action.gear {
        changes.push(("gear", change(o.active, gear_text(o.gear))));
        e.overrides.gear = Some(o);
    }
    let entity = e.name.clone();
    for (input, what) in changes {
        events.push(EventRecord::Entity {
            time,
            element: name.to_owned(),
            entity: entity.clone(),
            change: format!("override {input} {what}"),
        });
    }
}
