//! OpenDRIVE signals as ASAM OSI 3.8 `TrafficLight` and `TrafficSign` objects of the ground
//! truth (osi_trafficlight.proto, osi_trafficsign.proto; OpenDRIVE 1.8 §14 "Signals").
//!
//! [`TrafficSignals::new`] places every `<signal>` of the road network once; each frame,
//! [`TrafficSignals::add_to`] writes them with the live states of the engine's traffic signal
//! controllers (an OpenSCENARIO `TrafficSignal` is named by the OpenDRIVE signal's `id`).
//!
//! Placement (OpenDRIVE 1.8 §14.2): the signal stands at (s, t) of its road; its bottom edge
//! is `zOffset` above the road surface there, its face `width` wide and `height` high,
//! `length` thick. Its face looks against the traffic it is for: `orientation` "+" (valid in
//! the +s direction) faces −s, so the view normal, OSI's x axis of `base.orientation`, has
//! yaw = road heading + π + `hOffset`; "-" faces +s, yaw = road heading + `hOffset`; "none"
//! takes `hOffset` from the reference line, yaw = road heading + `hOffset`. `pitch` and `roll`
//! are the signal's own. `base.position` is the centre of the box.
//!
//! - Traffic lights ([`crate::signal_types::light_type`]) become one `TrafficLight` per bulb,
//!   bulbs stacked top to bottom over the face (each `height / n` high; a light without
//!   `height` gets 0.3 m per bulb, the large lens class of EN 12368), colour and icon from
//!   the type, mode from the signal's current state, in every frame.
//! - Every other signal becomes a `TrafficSign` (main sign only): `country`, `code` = `type`,
//!   `sub_code` = `subtype`, the OSI type where one fits, `value` with its unit. A static
//!   signal (`dynamic="no"`) is `VARIABILITY_FIXED` and goes with the static data (first frame
//!   or every frame, `--osi-static`); a dynamic one is `VARIABILITY_VARIABLE`, goes in every
//!   frame, and carries its current OpenSCENARIO state as `value.text`.
//! - ids: from the run's [`crate::ids::IdAllocator`], keyed by road id, the signal's index in
//!   its road's `<signals>` and the bulb (OpenDRIVE ids need not be unique across roads), so
//!   they are globally unique and the same in every frame. They are handed out after the
//!   first frame's entities, so a trace keeps its entity ids when signals are added, and kept
//!   beside each signal; each frame writes its lights and signs over the last frame's
//!   (module `reuse`), so the signals allocate nothing per frame.
//! - `classification.assigned_lane_id`: the OSI ids of the lanes the signal is for, in the
//!   lane section at its s ([`Road::signal_lanes`], OpenDRIVE 1.8 §14.2): the lanes of its
//!   `<validity>` ranges, else the drivable lanes of the direction its `orientation` names
//!   (both for "none"); every bulb of a light carries the light's lanes.
//! - `source_reference`: {reference: the OpenDRIVE file, type `net.asam.opendrive`,
//!   identifier: [signal id]}.
//! - Missing width, height or length leave that dimension 0 (the signal's size is unknown).

use opendrive::{normalize_angle, Road, RoadNetwork, Signal};

use crate::entity::base_stationary;
use crate::ground_truth::FrameBuilder;
use crate::ids::{IdAllocator, IdKey};
use crate::osi3::traffic_light::Classification as LightClassification;
use crate::osi3::traffic_sign::main_sign::Classification as SignClassification;
use crate::osi3::traffic_sign::{MainSign, Variability};
use crate::osi3::{BaseStationary, Identifier, TrafficLight, TrafficSign, TrafficSignValue};
use crate::reuse;
use crate::signal_types::{bulb_modes, light_type, sign_type, value_unit, LightType};

/// `ExternalReference.type` of OpenDRIVE sources.
pub const OPENDRIVE_REFERENCE_TYPE: &str = "net.asam.opendrive";

/// Height of one bulb of a light whose signal has no `height` (m).
pub const DEFAULT_BULB_HEIGHT: f64 = 0.3;

/// Where a signal stands: the centre of its bottom edge and the orientation of its face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SignalPlacement {
    /// Centre of the bottom edge, world frame (m).
    pub bottom: [f64; 3],
    /// Yaw of the view normal (rad, in (−π, π]), pitch and roll (rad).
    pub orientation: [f64; 3],
    /// Length (thickness), width and height (m; 0 where not given).
    pub dimension: [f64; 3],
}

/// Places `signal` on `road` (module doc).
pub fn placement(road: &Road, signal: &Signal) -> Result<SignalPlacement, opendrive::Error> {
    let pose = road.pose(signal.s, signal.t)?;
    let turn = match signal.orientation.trim() {
        "+" => std::f64::consts::PI,
        _ => 0.0,
    };
    let size = |v: Option<f64>| v.filter(|x| x.is_finite() && *x > 0.0).unwrap_or(0.0);
    Ok(SignalPlacement {
        bottom: [pose.x, pose.y, pose.z + signal.z_offset],
        orientation: [
            normalize_angle(pose.h + turn + signal.h_offset),
            signal.pitch,
            signal.roll,
        ],
        dimension: [size(signal.length), size(signal.width), size(signal.height)],
    })
}

/// One signal of the network, placed.
#[derive(Debug, Clone)]
struct Placed {
    road: String,
    index: usize,
    signal: Signal,
    at: SignalPlacement,
    light: Option<LightType>,
    /// The ids of its bulbs (of the sign: one), once handed out.
    ids: Vec<Identifier>,
    /// Its lane section and the OpenDRIVE ids of the lanes it is for
    /// ([`Road::signal_lanes`]), for `assigned_lane_id`.
    lanes: (usize, Vec<i32>),
    /// Their OSI ids, looked up once (the lanes' ids are handed out before the first frame
    /// and never change).
    lane_ids: Option<Vec<Identifier>>,
}

impl Placed {
    /// The OSI ids of the lanes `p` is for (those the lanes were built with), in the buffer
    /// `old`.
    fn assigned_lanes(&mut self, ids: &IdAllocator, old: Vec<Identifier>) -> Vec<Identifier> {
        let (section, lanes) = &self.lanes;
        let road = &self.road;
        let lane_ids = self.lane_ids.get_or_insert_with(|| {
            lanes
                .iter()
                .filter_map(|&l| ids.lane(road, *section, l))
                .collect()
        });
        reuse::ids(old, lane_ids)
    }
}

/// The id of bulb `bulb` (a sign: 0) kept in `kept`, handed out under `key()` the first
/// time (bulbs are asked for in order).
fn kept_id(
    kept: &mut Vec<Identifier>,
    ids: &mut IdAllocator,
    bulb: usize,
    key: impl FnOnce() -> IdKey,
) -> Identifier {
    if let Some(&id) = kept.get(bulb) {
        return id;
    }
    let id = ids.id(key());
    kept.push(id);
    id
}

/// The signals of a road network, placed once for the run (module doc).
#[derive(Debug, Clone, Default)]
pub struct TrafficSignals {
    signals: Vec<Placed>,
    map_reference: Option<String>,
}

impl TrafficSignals {
    /// Places every signal of `network` (roads and signals in file order); `map_reference` (the
    /// OpenDRIVE file) goes into the source references. A signal that cannot be placed (its s
    /// beyond its road) is left out with a warning, returned beside.
    pub fn new(network: &RoadNetwork, map_reference: Option<&str>) -> (Self, Vec<String>) {
        let mut warnings = Vec::new();
        let mut signals = Vec::new();
        for road in network.roads() {
            for (index, signal) in road.signals.iter().enumerate() {
                match placement(road, signal) {
                    Ok(at) => signals.push(Placed {
                        road: road.id.clone(),
                        index,
                        signal: signal.clone(),
                        at,
                        light: light_type(&signal.signal_type),
                        ids: Vec::new(),
                        lanes: (road.lane_section_index(signal.s), road.signal_lanes(signal)),
                        lane_ids: None,
                    }),
                    Err(e) => warnings.push(format!(
                        "OSI: signal '{}' of road '{}' left out of the ground truth: {e}",
                        signal.id, road.id
                    )),
                }
            }
        }
        let map_reference = map_reference.map(str::to_owned);
        (
            TrafficSignals {
                signals,
                map_reference,
            },
            warnings,
        )
    }

    /// Whether the network has no signal.
    pub fn is_empty(&self) -> bool {
        self.signals.is_empty()
    }

    /// Adds the lights (with the states `state` gives by signal id) and, where they belong in
    /// this frame, the signs to `frame`.
    pub fn add_to<'s>(
        &mut self,
        frame: &mut FrameBuilder<'_>,
        state: impl Fn(&str) -> Option<&'s str>,
    ) {
        let with_static = frame.carries_static_data();
        let map_reference = self.map_reference.as_deref();
        for p in &mut self.signals {
            let current = state(&p.signal.id);
            match p.light {
                Some(light) => add_light(frame, map_reference, p, light, current),
                None if p.signal.dynamic || with_static => {
                    add_sign(frame, map_reference, p, current)
                }
                None => {}
            }
        }
    }
}

/// One `TrafficLight` per bulb of `p`, written over the frame's next lights.
fn add_light(
    frame: &mut FrameBuilder<'_>,
    map_reference: Option<&str>,
    p: &mut Placed,
    light: LightType,
    state: Option<&str>,
) {
    let n = light.bulbs.len();
    let [length, width, height] = p.at.dimension;
    let bulb = if height > 0.0 {
        height / n as f64
    } else {
        DEFAULT_BULB_HEIGHT
    };
    let modes = bulb_modes(state, n);
    for (k, (&color, mode)) in light.bulbs.iter().zip(modes).enumerate() {
        // Bulb k from the top: its centre (n − k − ½) bulb heights above the bottom edge.
        let up = (n - k) as f64 * bulb - bulb / 2.0;
        let (slot, ids) = frame.next_traffic_light();
        let id = kept_id(&mut p.ids, ids, k, || IdKey::TrafficLight {
            road: p.road.clone(),
            signal: p.index,
            bulb: k,
        });
        let old = std::mem::take(slot);
        let old_lanes = old.classification.map(|c| c.assigned_lane_id);
        *slot = TrafficLight {
            id: Some(id),
            base: Some(base(&p.at, up, [length, width, bulb])),
            classification: Some(LightClassification {
                color: Some(color as i32),
                icon: Some(light.icon as i32),
                mode: Some(mode as i32),
                assigned_lane_id: p.assigned_lanes(ids, old_lanes.unwrap_or_default()),
                is_out_of_service: Some(false),
            }),
            source_reference: source_reference(old.source_reference, map_reference, &p.signal),
        };
    }
}

/// The `TrafficSign` of `p`, written over the frame's next sign.
fn add_sign(
    frame: &mut FrameBuilder<'_>,
    map_reference: Option<&str>,
    p: &mut Placed,
    state: Option<&str>,
) {
    let (slot, ids) = frame.next_traffic_sign();
    let id = kept_id(&mut p.ids, ids, 0, || IdKey::TrafficSign {
        road: p.road.clone(),
        signal: p.index,
    });
    let old = std::mem::take(slot);
    let mut old_class = old
        .main_sign
        .and_then(|m| m.classification)
        .unwrap_or_default();
    let lanes = p.assigned_lanes(ids, std::mem::take(&mut old_class.assigned_lane_id));
    let s = &p.signal;
    let variability = if s.dynamic {
        Variability::Variable
    } else {
        Variability::Fixed
    };
    let text = state.filter(|_| s.dynamic);
    let value = (s.value.is_some() || text.is_some()).then(|| TrafficSignValue {
        value: s.value,
        value_unit: s.value.map(|_| value_unit(&s.unit) as i32),
        text: reuse::string(old_class.value.and_then(|v| v.text), text),
    });
    let [length, width, height] = p.at.dimension;
    *slot = TrafficSign {
        id: Some(id),
        main_sign: Some(MainSign {
            base: Some(base(&p.at, height / 2.0, [length, width, height])),
            classification: Some(SignClassification {
                variability: Some(variability as i32),
                r#type: Some(sign_type(&s.country, &s.signal_type, &s.subtype) as i32),
                value,
                assigned_lane_id: lanes,
                is_out_of_service: Some(false),
                country: reuse::string(old_class.country, Some(&s.country)),
                code: reuse::string(old_class.code, Some(&s.signal_type)),
                sub_code: reuse::string(old_class.sub_code, Some(&s.subtype)),
            }),
        }),
        source_reference: source_reference(old.source_reference, map_reference, s),
    };
}

/// `source_reference` of `signal`: {the OpenDRIVE file, `net.asam.opendrive`, [signal id]},
/// in the buffers of `old`.
fn source_reference(
    old: Vec<crate::osi3::ExternalReference>,
    map_reference: Option<&str>,
    signal: &Signal,
) -> Vec<crate::osi3::ExternalReference> {
    reuse::source_reference(old, map_reference, OPENDRIVE_REFERENCE_TYPE, &[&signal.id])
}

/// The box of a face part whose centre is `up` metres above the bottom edge of `at`.
fn base(at: &SignalPlacement, up: f64, dimension: [f64; 3]) -> BaseStationary {
    let [x, y, z] = at.bottom;
    base_stationary([x, y, z + up], at.orientation, dimension)
}
