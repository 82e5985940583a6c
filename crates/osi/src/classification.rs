//! From OpenSCENARIO 1.3 categories (XSD enumerations `VehicleCategory`,
//! `PedestrianCategory`, `MiscObjectCategory`) to ASAM OSI 3.8 classifications
//! (`MovingObject.Type`, `MovingObject.VehicleClassification.Type`,
//! `StationaryObject.Classification.Type`), and the OpenSCENARIO 1.2+ `Role` of a vehicle to
//! `MovingObject.VehicleClassification.Role`.
//!
//! Choices where the standards do not line up one to one:
//! - `van` → `TYPE_DELIVERY_VAN` (OSI's `TYPE_VAN` is an alias of it), `truck` →
//!   `TYPE_HEAVY_TRUCK`, `car` → `TYPE_MEDIUM_CAR` (alias `TYPE_CAR`).
//! - pedestrian category `wheelchair` is a vehicle in OSI 3.8 (`TYPE_WHEELCHAIR`), so it
//!   becomes a `TYPE_VEHICLE` with that classification; `animal` → `TYPE_ANIMAL`.
//! - misc-object categories without an OSI counterpart (`crosswalk`, `obstacle`,
//!   `parkingSpace`, `patch`, `roadMark`, `trafficIsland`, `none`, `wind`) →
//!   `TYPE_OTHER`; `streetLamp` → `TYPE_POLE`, `railing` → `TYPE_BARRIER`,
//!   `soundBarrier` → `TYPE_WALL`, `gantry` → `TYPE_OVERHEAD_STRUCTURE`.
//! - role `none` ("no specific role": ordinary traffic) → `ROLE_CIVIL`, as `civil`: OSI 3.8
//!   says `ROLE_UNKNOWN` must not be used in ground truth and `ROLE_OTHER` is a known role
//!   outside the list; every other role has its namesake (`publicTransport` →
//!   `ROLE_PUBLIC_TRANSPORT`, `roadAssistance` → `ROLE_ROAD_ASSISTANCE`, `military` →
//!   `ROLE_MILITARY`).

use crate::error::Error;
use crate::osi3::moving_object::vehicle_classification::Role as VehicleRole;
use crate::osi3::moving_object::vehicle_classification::Type as VehicleType;
use crate::osi3::moving_object::Type as MovingType;
use crate::osi3::stationary_object::classification::Type as StationaryType;

const VEHICLE_CATEGORIES: &str = "one of bicycle, bus, car, motorbike, semitrailer, trailer, \
     train, tram, truck, van";
const ROLES: &str = "one of ambulance, civil, fire, military, none, police, publicTransport, \
     roadAssistance";
const PEDESTRIAN_CATEGORIES: &str = "one of animal, pedestrian, wheelchair";
const MISC_CATEGORIES: &str = "one of barrier, building, crosswalk, gantry, none, obstacle, \
     parkingSpace, patch, pole, railing, roadMark, soundBarrier, streetLamp, trafficIsland, \
     tree, vegetation, wind";

/// OSI vehicle type of an OpenSCENARIO `vehicleCategory`.
pub fn vehicle_type(vehicle_category: &str) -> Result<VehicleType, Error> {
    Ok(match vehicle_category {
        "bicycle" => VehicleType::Bicycle,
        "bus" => VehicleType::Bus,
        "car" => VehicleType::Car,
        "motorbike" => VehicleType::Motorbike,
        "semitrailer" => VehicleType::Semitrailer,
        "trailer" => VehicleType::Trailer,
        "train" => VehicleType::Train,
        "tram" => VehicleType::Tram,
        "truck" => VehicleType::HeavyTruck,
        "van" => VehicleType::DeliveryVan,
        other => return Err(Error::invalid("vehicleCategory", VEHICLE_CATEGORIES, other)),
    })
}

/// OSI vehicle role of an OpenSCENARIO `role` (module doc for `none`).
pub fn vehicle_role(role: &str) -> Result<VehicleRole, Error> {
    Ok(match role {
        "none" | "civil" => VehicleRole::Civil,
        "ambulance" => VehicleRole::Ambulance,
        "fire" => VehicleRole::Fire,
        "military" => VehicleRole::Military,
        "police" => VehicleRole::Police,
        "publicTransport" => VehicleRole::PublicTransport,
        "roadAssistance" => VehicleRole::RoadAssistance,
        other => return Err(Error::invalid("role", ROLES, other)),
    })
}

/// OSI moving-object type of an OpenSCENARIO `pedestrianCategory`, and the vehicle type
/// where OSI counts it as a vehicle (`wheelchair`).
pub fn pedestrian_type(
    pedestrian_category: &str,
) -> Result<(MovingType, Option<VehicleType>), Error> {
    Ok(match pedestrian_category {
        "pedestrian" => (MovingType::Pedestrian, None),
        "wheelchair" => (MovingType::Vehicle, Some(VehicleType::Wheelchair)),
        "animal" => (MovingType::Animal, None),
        other => {
            return Err(Error::invalid(
                "pedestrianCategory",
                PEDESTRIAN_CATEGORIES,
                other,
            ))
        }
    })
}

/// OSI stationary-object type of an OpenSCENARIO `miscObjectCategory`.
pub fn stationary_type(misc_object_category: &str) -> Result<StationaryType, Error> {
    Ok(match misc_object_category {
        "barrier" => StationaryType::Barrier,
        "building" => StationaryType::Building,
        "gantry" => StationaryType::OverheadStructure,
        "pole" | "streetLamp" => StationaryType::Pole,
        "railing" => StationaryType::Barrier,
        "soundBarrier" => StationaryType::Wall,
        "tree" => StationaryType::Tree,
        "vegetation" => StationaryType::Vegetation,
        "crosswalk" | "none" | "obstacle" | "parkingSpace" | "patch" | "roadMark"
        | "trafficIsland" | "wind" => StationaryType::Other,
        other => return Err(Error::invalid("miscObjectCategory", MISC_CATEGORIES, other)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vehicle_categories_map_to_the_osi_numbers() {
        // Numbers from OSI 3.8 MovingObject.VehicleClassification.Type.
        let table = [
            ("car", 4),
            ("van", 6),
            ("truck", 7),
            ("semitrailer", 8),
            ("trailer", 9),
            ("motorbike", 10),
            ("bicycle", 11),
            ("bus", 12),
            ("tram", 13),
            ("train", 14),
        ];
        for (category, number) in table {
            assert_eq!(vehicle_type(category).unwrap() as i32, number, "{category}");
        }
    }

    #[test]
    fn vehicle_roles_map_to_the_osi_numbers() {
        // Numbers from OSI 3.8 MovingObject.VehicleClassification.Role.
        let table = [
            ("none", 2),
            ("civil", 2),
            ("ambulance", 3),
            ("fire", 4),
            ("police", 5),
            ("publicTransport", 6),
            ("roadAssistance", 7),
            ("military", 10),
        ];
        for (role, number) in table {
            assert_eq!(vehicle_role(role).unwrap() as i32, number, "{role}");
        }
        assert!(vehicle_role("Police").is_err());
    }

    #[test]
    fn unknown_category_names_what_was_expected() {
        let err = vehicle_type("Car").unwrap_err();
        assert_eq!(
            err.to_string(),
            format!("expected vehicleCategory to be {VEHICLE_CATEGORIES}, found \"Car\"")
        );
        assert!(pedestrian_type("robot").is_err());
        assert!(stationary_type("lamp").is_err());
    }

    #[test]
    fn pedestrian_and_misc_categories() {
        assert_eq!(
            pedestrian_type("pedestrian").unwrap(),
            (MovingType::Pedestrian, None)
        );
        assert_eq!(
            pedestrian_type("wheelchair").unwrap(),
            (MovingType::Vehicle, Some(VehicleType::Wheelchair))
        );
        assert_eq!(stationary_type("streetLamp").unwrap() as i32, 4); // TYPE_POLE
        assert_eq!(stationary_type("tree").unwrap() as i32, 7); // TYPE_TREE
    }
}
