//! The physical objects a scenario names (ASAM OpenSCENARIO DSL 2.1 §8.7 physical object
//! actors, §8.7.18 groups): what each path is, and the solver's values of its fields that the
//! run needs — bounding box of every physical object (§8.7.9), category and axles of a vehicle
//! (§8.7.6, §8.7.10), and where a `stationary_object` stands (§8.7.3.1.1 `location(pose)`).
//!
//! | DSL actor | OpenSCENARIO 1.x entity |
//! | --- | --- |
//! | `vehicle` | Vehicle, category by `vehicle_category` (below) |
//! | `person` | Pedestrian, category `pedestrian` |
//! | `animal` | Pedestrian, category `animal` |
//! | `stationary_object` | MiscObject, category `barrier` (anchored; `obstacle` is movable in 1.x) |
//!
//! `vehicle_category` (§8.7.12) to 1.x: `car`, `bus`, `truck`, `trailer` the same;
//! `vru_vehicle` a `bicycle` when the first of its `intended_infrastructure` is `biking` (the
//! seed's Code 1 tells a bicycle from a motorcycle so), else a `motorbike`; `other` a `tram` or
//! `train` when that is `tram` or `rail`, else a `car` (1.x has no other land vehicle).

use dsl::semantics::hir::{Member, ModifierApp};
use scenario::{Axle, Axles, BoundingBox, PedestrianCategory, VehicleCategory};

use super::eval::Eval;
use crate::error::{Error, ErrorKind as K, Site};

/// What an actor path names.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Object {
    /// A vehicle, person, animal or located stationary object.
    Actor(ActorData),
    /// A vehicle group: its members' paths and data, in list order, and whether its formation
    /// spreads over the lanes (a `common_route_vehicle_group` that is not single-lane).
    Group(Vec<(String, ActorData)>, bool),
    /// A `random_traffic_vehicle_group`: its members' paths and data, in list order
    /// (`plan::random_traffic` places them).
    RandomTraffic(Vec<(String, ActorData)>),
    /// A `stationary_object` without `location(…)`: nowhere to put it.
    Unlocated,
}

/// Which §8.7 actor a physical object is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum ActorKind {
    /// `vehicle` (§8.7.6).
    Vehicle,
    /// `person` (§8.7.7) or `animal` (§8.7.8): a 1.x Pedestrian of this category.
    Walker(PedestrianCategory),
    /// `stationary_object` (§8.7.3) at its `location(pose)`.
    Stationary(Location),
}

/// A `stationary_object`'s pose (§8.7.3.1.1), world coordinates (m, rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Location {
    /// x, y, z (m).
    pub position: [f64; 3],
    /// yaw, pitch, roll (rad).
    pub orientation: [f64; 3],
}

/// The fields of a physical object the run needs, from the solver's values.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ActorData {
    /// Which actor it is.
    pub kind: ActorKind,
    /// OpenSCENARIO 1.x category of a vehicle's `vehicle_category` (`car` for the others).
    pub category: VehicleCategory,
    /// Its bounding box (§8.7.9), in its own coordinates (origin: the rear axle's centre).
    pub bounding_box: BoundingBox,
    /// Its axles, rear first.
    pub axles: Axles,
}

/// Classifies `path` (`None`: not a physical object or vehicle group of the program);
/// `located` holds the scenario's `location(…)` modifiers.
pub(crate) fn classify(ctx: &Eval<'_>, path: &str, located: &[Located]) -> Option<Object> {
    let (_, v) = ctx.lookup(path)?;
    if ctx.is_a(v, "vehicle") {
        return Some(Object::Actor(vehicle(ctx, path)));
    }
    for (name, category) in [
        ("person", PedestrianCategory::Pedestrian),
        ("animal", PedestrianCategory::Animal),
    ] {
        if ctx.is_a(v, name) {
            let mut data = vehicle(ctx, path);
            data.kind = ActorKind::Walker(category);
            data.category = VehicleCategory::Car;
            return Some(Object::Actor(data));
        }
    }
    if ctx.is_a(v, "stationary_object") {
        return Some(match located.iter().find(|l| l.path == path) {
            Some(l) => {
                let mut data = vehicle(ctx, path);
                data.kind = ActorKind::Stationary(l.location);
                data.category = VehicleCategory::Car;
                Object::Actor(data)
            }
            None => Object::Unlocated,
        });
    }
    if ctx.is_a(v, "vehicle_group") {
        let lanes =
            ctx.is_a(v, "common_route_vehicle_group") && !ctx.is_a(v, "single_lane_vehicle_group");
        let n = match ctx.lookup(&format!("{path}.vehicles"))?.1 {
            dsl::Value::List(items) => items.len(),
            _ => 0,
        };
        let members = (0..n)
            .map(|i| {
                let member = format!("{path}.vehicles[{i}]");
                let data = vehicle(ctx, &member);
                (member, data)
            })
            .collect();
        if ctx.is_a(v, "random_traffic_vehicle_group") {
            return Some(Object::RandomTraffic(members));
        }
        return Some(Object::Group(members, lanes));
    }
    None
}

/// The vehicle at `path` (for another physical object, its bounding box; the caller sets its
/// kind).
fn vehicle(ctx: &Eval<'_>, path: &str) -> ActorData {
    let num = |p: &str, default: f64| match ctx.lookup(&format!("{path}.{p}")) {
        Some((_, dsl::Value::Quantity { si, .. })) => *si,
        Some((_, dsl::Value::Float(f))) => *f,
        _ => default,
    };
    let list = format!("{path}.intended_infrastructure");
    let infrastructure: Vec<String> = match ctx.lookup(&list) {
        Some((_, dsl::Value::List(items))) => (0..items.len())
            .filter_map(|i| match ctx.lookup(&format!("{list}[{i}]")) {
                Some((_, dsl::Value::Enum { member, .. })) => Some(member.clone()),
                _ => None,
            })
            .collect(),
        _ => Vec::new(),
    };
    let category = match ctx.lookup(&format!("{path}.vehicle_category")) {
        Some((_, dsl::Value::Enum { member, .. })) => category(member, &infrastructure),
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
    ActorData {
        kind: ActorKind::Vehicle,
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

/// The OpenSCENARIO 1.x category of a DSL `vehicle_category` member (§8.7.12) of a vehicle
/// intended for `infrastructure` (§8.7.13), by its first element (the one the seed's Code 1
/// constrains; the list's other elements are the solver's draws when only the first is
/// constrained); see the module table.
fn category(member: &str, infrastructure: &[String]) -> VehicleCategory {
    let intended = |i: &str| infrastructure.first().is_some_and(|x| x == i);
    match member {
        "bus" => VehicleCategory::Bus,
        "truck" => VehicleCategory::Truck,
        "trailer" => VehicleCategory::Trailer,
        "vru_vehicle" if intended("biking") => VehicleCategory::Bicycle,
        "vru_vehicle" => VehicleCategory::Motorbike,
        "other" if intended("tram") => VehicleCategory::Tram,
        "other" if intended("rail") => VehicleCategory::Train,
        _ => VehicleCategory::Car,
    }
}

/// A `stationary_object`'s `location(pose)` (§8.7.3.1.1): the object's path and pose.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Located {
    /// The object's path.
    pub path: String,
    /// Its pose.
    pub location: Location,
    /// The modifier.
    pub site: Site,
}

/// Reads `app`, a modifier applied in the scenario's body, when it is `x.location(pose)`
/// (`None` for another modifier). The pose is a `pose_3d` instance whose fields the solver gave.
pub(crate) fn location(ctx: &Eval<'_>, app: &ModifierApp) -> Option<Result<Located, Error>> {
    if app.name.text != "location" {
        return None;
    }
    let site = ctx.site(app.span);
    let Some(path) = app.target.as_ref().and_then(|a| ctx.path_of(a)) else {
        return Some(Err(site.err(
            K::Modifier,
            "expected location(…) applied to a stationary_object (x.location(pose)), found it applied to the scenario",
        )));
    };
    let Some(pose) = super::eval::bind(&app.args, &["pose".to_string()])
        .into_iter()
        .find(|(n, _)| n == "pose")
        .map(|(_, e)| e)
    else {
        return Some(Err(site.err(
            K::Argument,
            "expected a pose in location(…) (a mandatory argument), found none",
        )));
    };
    let pose_site = ctx.site(pose.span);
    let Some(base) = ctx.path_of(pose) else {
        return Some(Err(pose_site.err(
            K::Value,
            "expected a pose_3d field of the scenario in location(…), found another expression",
        )));
    };
    let num = |f: &str| {
        match ctx.lookup(&format!("{base}.{f}")) {
        Some((_, dsl::Value::Quantity { si, .. })) => Ok(*si),
        Some((_, dsl::Value::Float(x))) => Ok(*x),
        Some((_, dsl::Value::Int(i))) => Ok(*i as f64),
        _ => Err(pose_site.err(
            K::Value,
            format!("expected a value of `{base}.{f}` (a pose_3d with its position and orientation), found none"),
        )),
    }
    };
    let read = || -> Result<Located, Error> {
        Ok(Located {
            path,
            location: Location {
                position: [num("position.x")?, num("position.y")?, num("position.z")?],
                orientation: [
                    num("orientation.yaw")?,
                    num("orientation.pitch")?,
                    num("orientation.roll")?,
                ],
            },
            site,
        })
    };
    Some(read())
}

/// The `location(…)` modifiers of the scenario's `members`.
pub(crate) fn locations(ctx: &Eval<'_>, members: &[Member]) -> Result<Vec<Located>, Error> {
    let mut out: Vec<Located> = Vec::new();
    for m in members {
        if let Member::Modifier(app) = m {
            if let Some(l) = location(ctx, app) {
                let l = l?;
                if let Some(first) = out.iter().find(|o| o.path == l.path) {
                    return Err(l.site.err(
                        K::Modifier,
                        format!(
                            "expected one location(…) of `{}` (it cannot change, §8.7.3.1.1), found a second; the first is at {}",
                            l.path,
                            first.site.at()
                        ),
                    ));
                }
                out.push(l);
            }
        }
    }
    Ok(out)
}
