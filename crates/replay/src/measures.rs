//! The gaps and times the scenario's conditions measure, as a series over the run's frames,
//! computed with the engine's OpenSCENARIO 2.0 §8.7 methods on the recorded poses and boxes:
//!
//! | condition (OpenSCENARIO 1.3 §7.6) | series |
//! | --- | --- |
//! | RelativeDistance, coordinateSystem road/lane, longitudinal/lateral | \|§8.7.5.1.3 `space_gap`\| |
//! | RelativeDistance, coordinateSystem entity/world, longitudinal/lateral | \|§8.7.2.1.1 `object_distance`\| in the entity's frame |
//! | RelativeDistance, euclidianDistance | straight distance of the reference points (freespace: of the boxes' longitudinal and lateral gaps) |
//! | TimeHeadway | \|§8.7.5.1.2 `time_headway`\| (reference points along s) |
//! | TimeToCollision | §8.7.5.1.1 `time_to_collision` (boxes, current velocities) |
//!
//! Distances and headways are magnitudes, as the conditions compare them (the engine's
//! `condition/spacing.rs` compares |distance| and |Δs| / speed with the rule), so a chart's
//! line crosses a threshold where its condition's rule changes.
//!
//! The engine does not hand out the value a condition measured, only whether it held, so
//! these series are recomputed from the frames: the velocity is the recorded speed along the
//! heading, a lane coordinate system is read as the road's (no lane-length stretching), and an
//! assigned-route or trajectory coordinate system as the road's too. Where a condition's
//! options go beyond that, the chart shows the §8.7 quantity named in its label.

use engine::domain::{
    Acceleration6d, BoundingBox, DistanceDirection, DistanceMode, MovableObject, PhysicalObject,
    TrafficParticipant, Vector3, Vehicle, VehicleCategory, Velocity6d,
};
use opendrive::Pose;

use crate::manifest::{EntityInfo, MeasureSpec};
use crate::run::{Run, DEFAULT_BOX_SIZE};
use crate::trajectories::{Sample, Track};

/// One series: the spec (the first condition that measures it) and a value per frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// What is measured.
    pub spec: MeasureSpec,
    /// Every condition threshold on the same quantity: (condition, rule, value).
    pub thresholds: Vec<(String, String, f64)>,
    /// The §8.7 method the values come from.
    pub method: &'static str,
    /// Unit, `s` or `m`.
    pub unit: &'static str,
    /// One value per frame; `None` where either entity is absent or the quantity has no value
    /// (off the road, never colliding, standing still).
    pub values: Vec<Option<f64>>,
}

/// Whether two specs measure the same quantity (they differ at most in rule and value).
fn same_quantity(a: &MeasureSpec, b: &MeasureSpec) -> bool {
    (
        &a.quantity,
        &a.entity,
        &a.reference,
        a.freespace,
        &a.coordinate_system,
        &a.relative_distance_type,
    ) == (
        &b.quantity,
        &b.entity,
        &b.reference,
        b.freespace,
        &b.coordinate_system,
        &b.relative_distance_type,
    )
}

/// The series of every distinct quantity the run's conditions measure.
pub fn series(run: &Run) -> Vec<Series> {
    let mut out: Vec<Series> = Vec::new();
    for spec in &run.manifest.measures {
        let threshold = (spec.condition.clone(), spec.rule.clone(), spec.value);
        if let Some(s) = out.iter_mut().find(|s| same_quantity(&s.spec, spec)) {
            s.thresholds.push(threshold);
            continue;
        }
        let mut s = series_of(run, spec);
        s.thresholds.push(threshold);
        out.push(s);
    }
    out
}

/// The series of one quantity (no thresholds).
pub fn series_of(run: &Run, spec: &MeasureSpec) -> Series {
    let (method, unit) = method(spec);
    Series {
        spec: spec.clone(),
        thresholds: Vec::new(),
        method,
        unit,
        values: values(run, spec),
    }
}

/// The §8.7 method and unit of a spec.
fn method(spec: &MeasureSpec) -> (&'static str, &'static str) {
    match spec.quantity.as_str() {
        "timeHeadway" => ("time_headway (§8.7.5.1.2)", "s"),
        "timeToCollision" => ("time_to_collision (§8.7.5.1.1)", "s"),
        _ => match (
            spec.relative_distance_type.as_str(),
            spec.coordinate_system.as_str(),
        ) {
            ("euclidianDistance", _) => ("euclidian distance", "m"),
            (_, "entity" | "world") => ("object_distance (§8.7.2.1.1)", "m"),
            _ => ("space_gap (§8.7.5.1.3)", "m"),
        },
    }
}

/// The entity as a §8.7 traffic participant at `sample`: its box (a point without
/// `freespace`), moving at its speed along its heading.
fn participant(
    info: Option<&EntityInfo>,
    sample: &Sample,
    freespace: bool,
) -> Option<TrafficParticipant> {
    let (c, d) = match (info, freespace) {
        (_, false) => ([0.0; 3], [0.0; 3]),
        (Some(i), true) => (i.box_center, i.box_size),
        (None, true) => ([0.0; 3], DEFAULT_BOX_SIZE),
    };
    let bb = BoundingBox::new(Vector3::new(c[0], c[1], c[2]), d[0], d[1], d[2]).ok()?;
    let [x, y, z, h, p, r] = sample.pose;
    let object = PhysicalObject::new(bb, Pose { x, y, z, h, p, r });
    let movable = MovableObject {
        object,
        velocity: Velocity6d {
            translational: Vector3::new(sample.speed, 0.0, 0.0),
            rotational: Vector3::ZERO,
        },
        acceleration: Acceleration6d::ZERO,
    };
    Some(TrafficParticipant::new(movable, Vec::new()))
}

/// The value of `spec` between samples `a` (entity) and `b` (reference).
fn value(
    run: &Run,
    spec: &MeasureSpec,
    (ia, a): (Option<&EntityInfo>, &Sample),
    (ib, b): (Option<&EntityInfo>, &Sample),
) -> Option<f64> {
    let free = spec.freespace;
    let (pa, pb) = (participant(ia, a, free)?, participant(ib, b, free)?);
    let mode = if free {
        DistanceMode::BoundingBoxes
    } else {
        DistanceMode::ReferencePoints
    };
    let network = run.network.as_ref();
    match spec.quantity.as_str() {
        "timeHeadway" => {
            let vehicle =
                Vehicle::new(participant(ia, a, false)?, VehicleCategory::Car, Vec::new()).ok()?;
            vehicle
                .time_headway(network?, &participant(ib, b, false)?)
                .ok()?
                .map(f64::abs)
        }
        "timeToCollision" => pa.time_to_collision(&pb),
        _ => {
            let dir = match spec.relative_distance_type.as_str() {
                "longitudinal" => DistanceDirection::Longitudinal,
                "lateral" => DistanceDirection::Lateral,
                _ => {
                    return Some(if free {
                        let lon = pa.object_distance(&pb, DistanceDirection::Longitudinal, mode);
                        let lat = pa.object_distance(&pb, DistanceDirection::Lateral, mode);
                        lon.hypot(lat)
                    } else {
                        (b.pose[0] - a.pose[0]).hypot(b.pose[1] - a.pose[1])
                    })
                }
            };
            match spec.coordinate_system.as_str() {
                "entity" | "world" => Some(pa.object_distance(&pb, dir, mode).abs()),
                _ => {
                    let network = network?;
                    let gap = pa.space_gap(network, &pb, dir).ok()?;
                    // Overlapping boxes are at distance 0 (OpenSCENARIO 1.3 §6.4); space_gap
                    // reports the overlap with the sign opposite to who is ahead, which the
                    // reference points tell.
                    let points = participant(ia, a, false)?
                        .space_gap(network, &participant(ib, b, false)?, dir)
                        .ok()?;
                    let overlap =
                        free && (gap == 0.0 || (points != 0.0 && gap.signum() != points.signum()));
                    Some(if overlap { 0.0 } else { gap.abs() })
                }
            }
        }
    }
}

/// The values of `spec` at every frame of the run.
fn values(run: &Run, spec: &MeasureSpec) -> Vec<Option<f64>> {
    let n = run.trajectories.times.len();
    let track = |name: &str| run.trajectories.tracks.iter().find(|t| t.name == name);
    let info = |t: &Track| run.manifest.entities.iter().find(|e| e.id == t.id);
    let (Some(ta), Some(tb)) = (track(&spec.entity), track(&spec.reference)) else {
        return vec![None; n];
    };
    let mut out = vec![None; n];
    let mut j = 0;
    for a in &ta.samples {
        while j < tb.samples.len() && tb.samples[j].frame < a.frame {
            j += 1;
        }
        if let Some(b) = tb.samples.get(j).filter(|b| b.frame == a.frame) {
            out[a.frame as usize] = value(run, spec, (info(ta), a), (info(tb), b));
        }
    }
    out
}
