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
//!   first frame's entities, so a trace keeps its entity ids when signals are added.
//! - `source_reference`: {reference: the OpenDRIVE file, type `net.asam.opendrive`,
//!   identifier: [signal id]}.
//! - Missing width, height or length leave that dimension 0 (the signal's size is unknown).

use opendrive::{normalize_angle, Road, RoadNetwork, Signal};

use crate::entity::base_stationary;
use crate::ground_truth::FrameBuilder;
use crate::ids::IdKey;
use crate::osi3::traffic_light::Classification as LightClassification;
use crate::osi3::traffic_sign::main_sign::Classification as SignClassification;
use crate::osi3::traffic_sign::{MainSign, Variability};
use crate::osi3::{BaseStationary, ExternalReference, TrafficLight, TrafficSign, TrafficSignValue};
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
        &self,
        frame: &mut FrameBuilder<'_>,
        state: impl Fn(&str) -> Option<&'s str>,
    ) {
        let with_static = frame.carries_static_data();
        for p in &self.signals {
            let current = state(&p.signal.id);
            match p.light {
                Some(light) => self.add_light(frame, p, light, current),
                None if p.signal.dynamic || with_static => self.add_sign(frame, p, current),
                None => {}
            }
        }
    }

    /// One `TrafficLight` per bulb of `p`.
    fn add_light(
        &self,
        frame: &mut FrameBuilder<'_>,
        p: &Placed,
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
            let key = IdKey::TrafficLight {
                road: p.road.clone(),
                signal: p.index,
                bulb: k,
            };
            frame.add_traffic_light(
                key,
                TrafficLight {
                    id: None,
                    base: Some(base(&p.at, up, [length, width, bulb])),
                    classification: Some(LightClassification {
                        color: Some(color as i32),
                        icon: Some(light.icon as i32),
                        mode: Some(mode as i32),
                        is_out_of_service: Some(false),
                    }),
                    source_reference: vec![self.source_reference(&p.signal)],
                },
            );
        }
    }

    /// The `TrafficSign` of `p`.
    fn add_sign(&self, frame: &mut FrameBuilder<'_>, p: &Placed, state: Option<&str>) {
        let s = &p.signal;
        let variability = if s.dynamic {
            Variability::Variable
        } else {
            Variability::Fixed
        };
        let text = state.filter(|_| s.dynamic).map(str::to_owned);
        let value = (s.value.is_some() || text.is_some()).then(|| TrafficSignValue {
            value: s.value,
            value_unit: s.value.map(|_| value_unit(&s.unit) as i32),
            text,
        });
        let key = IdKey::TrafficSign {
            road: p.road.clone(),
            signal: p.index,
        };
        let [length, width, height] = p.at.dimension;
        frame.add_traffic_sign(
            key,
            TrafficSign {
                id: None,
                main_sign: Some(MainSign {
                    base: Some(base(&p.at, height / 2.0, [length, width, height])),
                    classification: Some(SignClassification {
                        variability: Some(variability as i32),
                        r#type: Some(sign_type(&s.country, &s.signal_type, &s.subtype) as i32),
                        value,
                        is_out_of_service: Some(false),
                        country: Some(s.country.clone()),
                        code: Some(s.signal_type.clone()),
                        sub_code: Some(s.subtype.clone()),
                    }),
                }),
                source_reference: vec![self.source_reference(s)],
            },
        );
    }

    fn source_reference(&self, signal: &Signal) -> ExternalReference {
        ExternalReference {
            reference: self.map_reference.clone(),
            r#type: Some(OPENDRIVE_REFERENCE_TYPE.to_owned()),
            identifier: vec![signal.id.clone()],
        }
    }
}

/// The box of a face part whose centre is `up` metres above the bottom edge of `at`.
fn base(at: &SignalPlacement, up: f64, dimension: [f64; 3]) -> BaseStationary {
    let [x, y, z] = at.bottom;
    base_stationary([x, y, z + up], at.orientation, dimension)
}
