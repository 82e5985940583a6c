//! The enums of OpenSCENARIO 2.0 §8.7.12–8.7.17 (vehicle_category, intended_infrastructure,
//! distance_direction, distance_mode, on_route_type, route_distance_enum). `color` (§8.7.11)
//! has its own module because of its RGB table.
//!
//! Each enum's `Default` is the value the seed marks "(default)" where it marks one.

/// §8.7.12 vehicle_category: vehicle category based on UN ECE/TRANS/WP.29/78/Rev.6, extended
/// by non-self-propelled vehicles.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum VehicleCategory {
    /// Power-driven, at most 3.5 t, at least four wheels, at most eight passenger seats
    /// (UN L7, M1, N1).
    Car,
    /// Power-driven, at least four wheels, more than eight passenger seats (UN M2, M3).
    Bus,
    /// Power-driven, more than 3.5 t, at least four wheels, for goods (UN N2, N3).
    Truck,
    /// Designed to be towed by another vehicle, separable without a workshop.
    Trailer,
    /// No crash-resistant passenger cell: with its occupant a vulnerable road user
    /// (UN L1–L6, bicycles, pedelecs, wheelchairs, …).
    VruVehicle,
    /// Unspecified but known type of vehicle (stroller, shopping cart, …).
    Other,
}

/// §8.7.13 intended_infrastructure: infrastructure a traffic participant typically uses; the
/// values are taken from ASAM OpenDRIVE lane types.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum IntendedInfrastructure {
    /// OpenDRIVE lane type `driving`.
    Driving,
    /// A lane meant for people to walk on (OpenDRIVE `sidewalk`).
    Sidewalk,
    /// OpenDRIVE `biking`.
    Biking,
    /// OpenDRIVE `rail`.
    Rail,
    /// OpenDRIVE `tram`.
    Tram,
    /// OpenDRIVE `bus`.
    Bus,
    /// OpenDRIVE `taxi`.
    Taxi,
    /// OpenDRIVE `HOV` (high-occupancy vehicles).
    Hov,
}

/// §8.7.14 distance_direction: the axis a distance is measured along.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DistanceDirection {
    /// x-coordinate (object frame) or s-coordinate (road frame); positive when the reference
    /// is in front of the calling object (§8.7.14).
    Longitudinal,
    /// y-coordinate (object frame) or t-coordinate (road frame); positive when the reference
    /// is to the left of the calling object (§8.7.14).
    Lateral,
}

/// §8.7.15 distance_mode: between which points of two objects a distance is measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum DistanceMode {
    /// Between the reference points (§8.7.2.1.1: the default).
    #[default]
    ReferencePoints,
    /// Between the bounding boxes.
    BoundingBoxes,
}

/// §8.7.16 on_route_type: which s/t coordinate system a coordinate is taken in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum OnRouteType {
    /// The road's s/t (§8.7.2.1.2: the default).
    #[default]
    OnRoad,
    /// The lane section's s/t.
    OnLaneSection,
    /// The lane's s/t.
    OnLane,
    /// The crossing's s/t; oscsim's crossing is a junction's connecting road.
    OnCrossing,
}

/// §8.7.17 route_distance_enum: the end of a route a distance is measured from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum RouteDistanceEnum {
    /// From the route's start point (§8.7.4.1.1: the default); positive when the object is
    /// ahead of the start.
    #[default]
    FromStart,
    /// To the route's end point; positive when the object is behind the end.
    FromEnd,
}
