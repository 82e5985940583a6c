//! From a scenario entity to an ASAM OSI 3.8 `MovingObject` or `StationaryObject`, with
//! the OSI rules the object must satisfy (osi_object.proto, OSI 3.8.0):
//! - `id` from the run's [`IdAllocator`], so it is globally unique and stable;
//! - `base` from [`RigidBodyState`]: bounding-box centre, world frame;
//! - `TYPE_VEHICLE` carries `vehicle_attributes` (with `bbcenter_to_rear`) and
//!   `vehicle_classification`; `TYPE_PEDESTRIAN` carries `pedestrian_attributes`;
//! - lanes go to `moving_object_classification.assigned_lane_id` (the top-level
//!   `assigned_lane_id` is deprecated);
//! - `source_reference` = {reference: scenario file, type: `net.asam.openscenario`,
//!   identifier: [`Vehicle` | `Pedestrian` | `MiscObject`, entity name]}.

use crate::classification::{pedestrian_type, stationary_type, vehicle_role, vehicle_type};
use crate::error::Error;
use crate::ids::IdAllocator;
use crate::osi3::moving_object::vehicle_classification::LightState;
use crate::osi3::moving_object::{
    MovingObjectClassification, PedestrianAttributes, Type as MovingType, VehicleAttributes,
    VehicleClassification,
};
use crate::osi3::stationary_object::classification::Type as StationaryType;
use crate::osi3::stationary_object::Classification as StationaryClassification;
use crate::osi3::{
    BaseStationary, ColorDescription, Dimension3d, Identifier, MovingObject, Orientation3d,
    StationaryObject, Vector3d,
};
use crate::reuse;
use crate::rigid_body::RigidBodyState;

/// `ExternalReference.type` of OpenSCENARIO sources.
pub const OPENSCENARIO_REFERENCE_TYPE: &str = "net.asam.openscenario";

/// What kind of scenario entity, with its OpenSCENARIO category.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EntityKind<'a> {
    /// A `Vehicle` with its `vehicleCategory`.
    Vehicle {
        /// `vehicleCategory` (e.g. `car`).
        category: &'a str,
    },
    /// A `Pedestrian` with its `pedestrianCategory`.
    Pedestrian {
        /// `pedestrianCategory` (e.g. `pedestrian`).
        category: &'a str,
    },
}

/// The static description of a scenario entity.
#[derive(Debug, Clone, PartialEq)]
pub struct EntityInfo<'a> {
    /// Entity name (`ScenarioObject/@name`).
    pub name: &'a str,
    /// Kind and category.
    pub kind: EntityKind<'a>,
    /// URI or path of the scenario file, for `source_reference.reference`.
    pub scenario_file: Option<&'a str>,
    /// `model3d` attribute, for `model_reference`.
    pub model3d: Option<&'a str>,
    /// Colour (see [`crate::color`]).
    pub color: Option<ColorDescription>,
    /// Entity name of the trailer hitched to this vehicle, if any.
    pub trailer: Option<&'a str>,
    /// The vehicle's light states (see [`crate::lights`]), if any light was set.
    pub lights: Option<LightState>,
    /// The vehicle's OpenSCENARIO `role` (e.g. `police`), if it has one: written to
    /// `vehicle_classification.role` (see [`crate::classification`]).
    pub role: Option<&'a str>,
}

/// OSI needs a positive, finite bounding box at a finite place (osi_check: "dimension
/// not positive"); refuse anything else rather than write an invalid object.
fn check_box(position: [f64; 3], dimension: [f64; 3]) -> Result<(), Error> {
    if !dimension.iter().all(|d| d.is_finite() && *d > 0.0) {
        return Err(Error::invalid(
            "the bounding box dimension",
            "three positive finite numbers (length, width, height)",
            &format!("{dimension:?}"),
        ));
    }
    if !position.iter().all(|p| p.is_finite()) {
        return Err(Error::invalid(
            "the position",
            "three finite numbers",
            &format!("{position:?}"),
        ));
    }
    Ok(())
}

/// The `MovingObject` of `info` in state `state`, on lanes `lanes` (OSI lane ids).
pub fn moving_object(
    ids: &mut IdAllocator,
    info: &EntityInfo<'_>,
    state: &RigidBodyState,
    lanes: &[Identifier],
) -> Result<MovingObject, Error> {
    let mut object = MovingObject::default();
    fill_moving_object(&mut object, ids, info, state, lanes)?;
    Ok(object)
}

/// Writes the `MovingObject` of `info` in state `state`, on lanes `lanes`, over `object`
/// (e.g. last frame's message of the same entity): the same message [`moving_object`] gives,
/// reusing `object`'s strings and lists (module `reuse`). On error `object` is unchanged.
pub fn fill_moving_object(
    object: &mut MovingObject,
    ids: &mut IdAllocator,
    info: &EntityInfo<'_>,
    state: &RigidBodyState,
    lanes: &[Identifier],
) -> Result<(), Error> {
    check_box(state.bbox_centre_position(), state.dimension)?;
    let (object_type, vehicle, entity_type) = match info.kind {
        EntityKind::Vehicle { category } => (
            MovingType::Vehicle,
            Some(vehicle_type(category)?),
            "Vehicle",
        ),
        EntityKind::Pedestrian { category } => {
            let (t, v) = pedestrian_type(category)?;
            (t, v, "Pedestrian")
        }
    };
    let role = info.role.map(vehicle_role).transpose()?.map(|r| r as i32);
    let old = std::mem::take(object);
    let lane_ids = old
        .moving_object_classification
        .map(|c| c.assigned_lane_id)
        .unwrap_or_default();
    *object = MovingObject {
        id: Some(ids.moving_object(info.name)),
        base: Some(state.base_moving()),
        r#type: Some(object_type as i32),
        model_reference: reuse::string(old.model_reference, info.model3d),
        moving_object_classification: Some(MovingObjectClassification {
            assigned_lane_id: reuse::ids(lane_ids, lanes),
            ..Default::default()
        }),
        source_reference: reuse::source_reference(
            old.source_reference,
            info.scenario_file,
            OPENSCENARIO_REFERENCE_TYPE,
            &[entity_type, info.name],
        ),
        color_description: info.color,
        ..Default::default()
    };
    if let Some(vehicle) = vehicle {
        let trailer_id = info.trailer.map(|t| ids.moving_object(t));
        object.vehicle_classification = Some(VehicleClassification {
            r#type: Some(vehicle as i32),
            has_trailer: Some(trailer_id.is_some()),
            trailer_id,
            light_state: info.lights,
            role,
        });
        object.vehicle_attributes = Some(VehicleAttributes {
            bbcenter_to_rear: Some(state.bbcenter_to_rear()),
            ..Default::default()
        });
    }
    if object_type == MovingType::Pedestrian {
        // The skeleton root is not modelled: place it at the bounding-box centre.
        object.pedestrian_attributes = Some(PedestrianAttributes {
            bbcenter_to_root: Some(Vector3d {
                x: Some(0.0),
                y: Some(0.0),
                z: Some(0.0),
            }),
            skeleton_bone: Vec::new(),
        });
    }
    Ok(())
}

/// A `MiscObject` or an `ExternalObjectReference` as a `StationaryObject`; `position` is
/// the bounding-box centre in the world frame, `orientation` yaw, pitch, roll,
/// `dimension` length, width, height.
pub struct MiscObjectInfo<'a> {
    /// Entity name.
    pub name: &'a str,
    /// `miscObjectCategory` of a MiscObject; `None` for an ExternalObjectReference
    /// (classified `TYPE_OTHER`, source_reference entity type `ExternalObjectReference`).
    pub category: Option<&'a str>,
    /// URI or path of the scenario file.
    pub scenario_file: Option<&'a str>,
    /// `model3d` attribute.
    pub model3d: Option<&'a str>,
    /// Colour.
    pub color: Option<ColorDescription>,
    /// Bounding-box centre, world frame (m).
    pub position: [f64; 3],
    /// Yaw, pitch, roll (rad).
    pub orientation: [f64; 3],
    /// Length, width, height (m).
    pub dimension: [f64; 3],
}

/// The `StationaryObject` of a MiscObject.
pub fn stationary_object(
    ids: &mut IdAllocator,
    info: &MiscObjectInfo<'_>,
    lanes: &[Identifier],
) -> Result<StationaryObject, Error> {
    let mut object = StationaryObject::default();
    fill_stationary_object(&mut object, ids, info, lanes)?;
    Ok(object)
}

/// Writes the `StationaryObject` of a MiscObject over `object`, as [`fill_moving_object`]
/// does for moving objects: the message [`stationary_object`] gives, in `object`'s buffers.
/// On error `object` is unchanged.
pub fn fill_stationary_object(
    object: &mut StationaryObject,
    ids: &mut IdAllocator,
    info: &MiscObjectInfo<'_>,
    lanes: &[Identifier],
) -> Result<(), Error> {
    check_box(info.position, info.dimension)?;
    let (classification, entity_type) = match info.category {
        Some(category) => (stationary_type(category)?, "MiscObject"),
        None => (StationaryType::Other, "ExternalObjectReference"),
    };
    let old = std::mem::take(object);
    let lane_ids = old
        .classification
        .map(|c| c.assigned_lane_id)
        .unwrap_or_default();
    *object = StationaryObject {
        id: Some(ids.stationary_object(info.name)),
        base: Some(base_stationary(
            info.position,
            info.orientation,
            info.dimension,
        )),
        classification: Some(StationaryClassification {
            r#type: Some(classification as i32),
            assigned_lane_id: reuse::ids(lane_ids, lanes),
            ..Default::default()
        }),
        model_reference: reuse::string(old.model_reference, info.model3d),
        source_reference: reuse::source_reference(
            old.source_reference,
            info.scenario_file,
            OPENSCENARIO_REFERENCE_TYPE,
            &[entity_type, info.name],
        ),
        color_description: info.color,
    };
    Ok(())
}

/// A `BaseStationary` of box centre `[x, y, z]`, orientation `[yaw, pitch, roll]` and
/// dimension `[length, width, height]` (world frame).
pub(crate) fn base_stationary(
    [x, y, z]: [f64; 3],
    [yaw, pitch, roll]: [f64; 3],
    [length, width, height]: [f64; 3],
) -> BaseStationary {
    BaseStationary {
        dimension: Some(Dimension3d {
            length: Some(length),
            width: Some(width),
            height: Some(height),
        }),
        position: Some(Vector3d {
            x: Some(x),
            y: Some(y),
            z: Some(z),
        }),
        orientation: Some(Orientation3d {
            roll: Some(roll),
            pitch: Some(pitch),
            yaw: Some(yaw),
        }),
        ..Default::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ids::IdKey;

    fn car() -> EntityInfo<'static> {
        EntityInfo {
            name: "Ego",
            kind: EntityKind::Vehicle { category: "car" },
            scenario_file: Some("s.xosc"),
            model3d: None,
            color: None,
            trailer: Some("Trailer"),
            lights: None,
            role: None,
        }
    }

    #[test]
    fn flat_or_nan_boxes_are_refused() {
        let mut ids = IdAllocator::new();
        let flat = RigidBodyState {
            dimension: [4.5, 1.8, 0.0],
            ..Default::default()
        };
        let err = moving_object(&mut ids, &car(), &flat, &[]).unwrap_err();
        assert_eq!(
            err.to_string(),
            "expected the bounding box dimension to be three positive finite numbers \
             (length, width, height), found \"[4.5, 1.8, 0.0]\""
        );
        let nan = RigidBodyState {
            reference_point: [f64::NAN, 0.0, 0.0],
            dimension: [4.5, 1.8, 1.5],
            ..Default::default()
        };
        assert!(moving_object(&mut ids, &car(), &nan, &[]).is_err());
    }

    #[test]
    fn trailer_gets_its_own_stable_id() {
        let mut ids = IdAllocator::new();
        let state = RigidBodyState {
            dimension: [4.5, 1.8, 1.5],
            ..Default::default()
        };
        let ego = moving_object(&mut ids, &car(), &state, &[]).unwrap();
        let class = ego.vehicle_classification.unwrap();
        assert_eq!(class.has_trailer, Some(true));
        // Ego got id 1, its trailer 2; the trailer keeps 2 when it is written itself.
        assert_eq!(ego.id.unwrap().value, Some(1));
        assert_eq!(class.trailer_id.unwrap().value, Some(2));
        assert_eq!(
            ids.get(&IdKey::MovingObject("Trailer".into()))
                .unwrap()
                .value,
            Some(2)
        );
    }

    #[test]
    fn external_object_reference_is_a_stationary_other() {
        let mut ids = IdAllocator::new();
        let info = MiscObjectInfo {
            name: "Bridge",
            category: None,
            scenario_file: None,
            model3d: None,
            color: None,
            position: [0.0, 0.0, 5.0],
            orientation: [0.0; 3],
            dimension: [10.0, 20.0, 1.0],
        };
        let o = stationary_object(&mut ids, &info, &[]).unwrap();
        assert_eq!(
            o.classification.unwrap().r#type,
            Some(StationaryType::Other as i32)
        );
        assert_eq!(
            o.source_reference[0].identifier,
            vec!["ExternalObjectReference".to_string(), "Bridge".to_string()]
        );
    }

    /// A slot last written with a pedestrian on two lanes, then written with a vehicle on
    /// none, holds exactly the vehicle's fresh message (no field of the pedestrian left).
    #[test]
    fn a_reused_object_equals_a_fresh_one() {
        let mut ids = IdAllocator::new();
        let state = RigidBodyState {
            dimension: [4.5, 1.8, 1.5],
            bbox_centre: [1.4, 0.0, 0.75],
            ..Default::default()
        };
        let walker = EntityInfo {
            name: "Walker-with-a-long-name",
            kind: EntityKind::Pedestrian {
                category: "pedestrian",
            },
            model3d: Some("walker.osgb"),
            trailer: None,
            ..car()
        };
        let lanes = [Identifier { value: Some(7) }, Identifier { value: Some(8) }];
        let mut slot = moving_object(&mut ids, &walker, &state, &lanes).unwrap();
        assert!(slot.pedestrian_attributes.is_some());
        fill_moving_object(&mut slot, &mut ids, &car(), &state, &[]).unwrap();
        let fresh = moving_object(&mut ids, &car(), &state, &[]).unwrap();
        assert_eq!(slot, fresh);
        // Walker 1, Ego 2, Trailer 3, in the order first asked.
        assert_eq!(slot.id.unwrap().value, Some(2));
        // A refused state leaves the slot as it was.
        let flat = RigidBodyState {
            dimension: [0.0; 3],
            ..state
        };
        assert!(fill_moving_object(&mut slot, &mut ids, &walker, &flat, &lanes).is_err());
        assert_eq!(slot, fresh);
    }
}
