//! The vehicles of a plan: every vehicle the `do` tree drives or refers to, and the members of
//! every vehicle group it drives (`g.vehicles[i]`), with the OpenSCENARIO 1.x Vehicle the engine
//! builds from the solver's values (bounding box, category, axles). The DSL's vehicle has no
//! performance fields; oscsim gives every vehicle those of the bundled catalogs' cars: 70 m/s,
//! 10 m/s² acceleration and deceleration.

use scenario::{Axle, Axles, BoundingBox, Performance, Properties, Vehicle, VehicleCategory};

use crate::value::Ctx;

/// Maximum speed of a DSL vehicle (m/s).
pub(crate) const MAX_SPEED: f64 = 70.0;
/// Maximum acceleration and deceleration of a DSL vehicle (m/s²).
pub(crate) const MAX_ACCELERATION: f64 = 10.0;

/// What an actor path names.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum ActorKind {
    /// A vehicle: its entity.
    Vehicle,
    /// A vehicle group: its members' paths, in list order, and whether its formation spreads
    /// over the lanes (a `common_route_vehicle_group` that is not single-lane).
    Group(Vec<String>, bool),
    /// A `random_traffic_vehicle_group`: not planned.
    RandomTraffic,
}

/// Classifies `path` (`None`: not a vehicle or vehicle group of the program).
pub(crate) fn classify(ctx: &Ctx<'_>, path: &str) -> Option<ActorKind> {
    let (_, v) = ctx.lookup(path)?;
    if ctx.is_a(v, "vehicle") {
        return Some(ActorKind::Vehicle);
    }
    if ctx.is_a(v, "random_traffic_vehicle_group") {
        return Some(ActorKind::RandomTraffic);
    }
    if ctx.is_a(v, "vehicle_group") {
        let lanes =
            ctx.is_a(v, "common_route_vehicle_group") && !ctx.is_a(v, "single_lane_vehicle_group");
        let n = match ctx.lookup(&format!("{path}.vehicles"))?.1 {
            dsl::Value::List(items) => items.len(),
            _ => 0,
        };
        return Some(ActorKind::Group(
            (0..n).map(|i| format!("{path}.vehicles[{i}]")).collect(),
            lanes,
        ));
    }
    None
}

/// The vehicle at `path` as the engine's model.
pub(crate) fn vehicle(ctx: &Ctx<'_>, path: &str) -> Vehicle {
    let num = |p: &str, default: f64| match ctx.lookup(&format!("{path}.{p}")) {
        Some((_, dsl::Value::Quantity { si, .. })) => *si,
        Some((_, dsl::Value::Float(f))) => *f,
        _ => default,
    };
    let category = match ctx.lookup(&format!("{path}.vehicle_category")) {
        Some((_, dsl::Value::Enum { member, .. })) => category(member),
        _ => VehicleCategory::Car,
    };
    let axle_count = match ctx.lookup(&format!("{path}.axles")) {
        Some((_, dsl::Value::List(items))) => items.len(),
        _ => 0,
    };
    let mut axles: Vec<Axle> = (0..axle_count)
        .map(|i| {
            let a = |f: &str, d: f64| num(&format!("axles[{i}].{f}"), d);
            Axle {
                max_steering: a("max_steering", 0.5),
                wheel_diameter: a("wheel_diameter", 0.7),
                track_width: a("track_width", 1.6),
                position_x: a("position_x", 0.0),
                position_z: a("position_z", 0.35),
            }
        })
        .collect();
    axles.sort_by(|a, b| a.position_x.total_cmp(&b.position_x));
    let rear = axles.first().copied().unwrap_or(Axle {
        max_steering: 0.0,
        wheel_diameter: 0.7,
        track_width: 1.6,
        position_x: 0.0,
        position_z: 0.35,
    });
    let front = (axles.len() > 1).then(|| axles[axles.len() - 1]);
    let additional = if axles.len() > 2 {
        axles[1..axles.len() - 1].to_vec()
    } else {
        Vec::new()
    };
    Vehicle {
        name: path.to_string(),
        vehicle_category: category,
        role: None,
        mass: None,
        model3d: None,
        bounding_box: BoundingBox {
            center: [
                num("bounding_box.center.x", 1.4),
                num("bounding_box.center.y", 0.0),
                num("bounding_box.center.z", 0.75),
            ],
            width: num("bounding_box.width", 2.0),
            length: num("bounding_box.length", 5.0),
            height: num("bounding_box.height", 1.5),
        },
        performance: Performance {
            max_speed: MAX_SPEED,
            max_acceleration: MAX_ACCELERATION,
            max_deceleration: MAX_ACCELERATION,
            max_acceleration_rate: None,
            max_deceleration_rate: None,
        },
        axles: Axles {
            front_axle: front,
            rear_axle: rear,
            additional_axles: additional,
        },
        properties: Properties::default(),
        trailer_hitch: None,
        trailer_coupler: None,
        trailer: None,
        catalog: None,
    }
}

/// The OpenSCENARIO 1.x category of a DSL `vehicle_category` member (§8.7.6; the DSL's
/// passenger categories map to `car`).
fn category(member: &str) -> VehicleCategory {
    match member {
        "bus" => VehicleCategory::Bus,
        "truck" => VehicleCategory::Truck,
        "motorbike" | "motorcycle" => VehicleCategory::Motorbike,
        "bicycle" => VehicleCategory::Bicycle,
        "trailer" => VehicleCategory::Trailer,
        "semitrailer" => VehicleCategory::Semitrailer,
        "train" => VehicleCategory::Train,
        "tram" => VehicleCategory::Tram,
        "van" => VehicleCategory::Van,
        _ => VehicleCategory::Car,
    }
}
