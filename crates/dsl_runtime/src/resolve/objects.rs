//! The physical objects a scenario's `do` tree names (ASAM OpenSCENARIO DSL 2.1 §8.7 physical
//! object actors, §8.7.18 groups): what each path is, and the solver's values of its fields that
//! the run needs — bounding box, category and axles of a vehicle (§8.7.6, §8.7.9, §8.7.10).

use scenario::{Axle, Axles, BoundingBox, VehicleCategory};

use super::eval::Eval;

/// What an actor path names.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Object {
    /// A vehicle.
    Vehicle(VehicleData),
    /// A vehicle group: its members' paths and data, in list order, and whether its formation
    /// spreads over the lanes (a `common_route_vehicle_group` that is not single-lane).
    Group(Vec<(String, VehicleData)>, bool),
    /// A `random_traffic_vehicle_group`: not planned.
    RandomTraffic,
}

/// The fields of a vehicle the run needs, from the solver's values.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct VehicleData {
    /// OpenSCENARIO 1.x category of its `vehicle_category`.
    pub category: VehicleCategory,
    /// Its bounding box (§8.7.9), in its own coordinates (origin: the rear axle's centre).
    pub bounding_box: BoundingBox,
    /// Its axles, rear first.
    pub axles: Axles,
}

/// Classifies `path` (`None`: not a vehicle or vehicle group of the program).
pub(crate) fn classify(ctx: &Eval<'_>, path: &str) -> Option<Object> {
    let (_, v) = ctx.lookup(path)?;
    if ctx.is_a(v, "vehicle") {
        return Some(Object::Vehicle(vehicle(ctx, path)));
    }
    if ctx.is_a(v, "random_traffic_vehicle_group") {
        return Some(Object::RandomTraffic);
    }
    if ctx.is_a(v, "vehicle_group") {
        let lanes =
            ctx.is_a(v, "common_route_vehicle_group") && !ctx.is_a(v, "single_lane_vehicle_group");
        let n = match ctx.lookup(&format!("{path}.vehicles"))?.1 {
            dsl::Value::List(items) => items.len(),
            _ => 0,
        };
        return Some(Object::Group(
            (0..n)
                .map(|i| {
                    let member = format!("{path}.vehicles[{i}]");
                    let data = vehicle(ctx, &member);
                    (member, data)
                })
                .collect(),
            lanes,
        ));
    }
    None
}

/// The vehicle at `path`.
fn vehicle(ctx: &Eval<'_>, path: &str) -> VehicleData {
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
    VehicleData {
        category,
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
        axles: Axles {
            front_axle: front,
            rear_axle: rear,
            additional_axles: additional,
        },
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
