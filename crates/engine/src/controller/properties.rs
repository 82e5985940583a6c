//! Which model a `Controller` element asks for (OpenSCENARIO 1.3 §6.6 "Controllers": a
//! controller's behaviour is given by its `Properties`, XSD `Controller`, `Properties`,
//! `Property`), read from `<Property name="model" value="…"/>` and the model's own properties,
//! all in SI units:
//!
//! | `model` | properties |
//! | --- | --- |
//! | `idm` | `desiredSpeed` (m/s), `timeHeadway` (s), `minimumGap` (m), `maxAcceleration` (m/s²), `comfortableDeceleration` (m/s²), `accelerationExponent` |
//! | `mobil` | those of `idm`, and `politeness`, `changeThreshold` (m/s²), `safeDeceleration` (m/s²), `rightBias` (m/s²) |
//! | `acc` | `setSpeed` (m/s), `timeGap` (s), `minimumGap` (m), `maxAcceleration` (m/s²), `maxDeceleration` (m/s²), `maxJerk` (m/s³) |
//! | `vehicle_dynamics` | `steeringRatio`, `steeringWheelInertia` (kg·m²) |
//! | `external` | none |
//!
//! A property left out takes the model's default (see each model); `desiredSpeed` and
//! `setSpeed` default to the entity's speed when the controller is activated. An unknown
//! `model`, a property the model does not have, or a value that is not a finite number in the
//! property's range is an error at the `Property` element. A controller without a `model`
//! property is not one of oscsim's: it is kept for the record and the default controller
//! keeps its domains. So is one that esmini identifies as its own, whatever its properties
//! (esmini's ALKS controllers have a `model` property of their own): one with an
//! `esminiController` property, or named as one of esmini's controllers ([`ESMINI_CONTROLLERS`];
//! esmini takes the Controller's name as its type when no `esminiController` is given).

use scenario::{Controller, ControllerType, SourcePos};

use crate::error::Error;
use crate::models::acc::AccParameters;
use crate::models::idm::IdmParameters;
use crate::models::mobil::MobilParameters;

/// The motion domains a controller can hold (OpenSCENARIO 1.3 §6.6.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct MotionDomains {
    /// Longitudinal.
    pub longitudinal: bool,
    /// Lateral.
    pub lateral: bool,
}

impl MotionDomains {
    /// Both domains.
    pub const BOTH: MotionDomains = MotionDomains {
        longitudinal: true,
        lateral: true,
    };
    /// The longitudinal domain only.
    pub const LONGITUDINAL: MotionDomains = MotionDomains {
        longitudinal: true,
        lateral: false,
    };

    /// "longitudinal", "lateral", "longitudinal and lateral" or "none".
    pub fn describe(self) -> &'static str {
        match (self.longitudinal, self.lateral) {
            (true, true) => "longitudinal and lateral",
            (true, false) => "longitudinal",
            (false, true) => "lateral",
            (false, false) => "none",
        }
    }
}

/// The settings of a built-in model, as written.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ModelSettings {
    /// `idm`; `desired_speed` `None`: the speed at activation.
    Idm {
        /// The IDM parameters (desired speed as given or a placeholder).
        idm: IdmParameters,
        /// `desiredSpeed` was given.
        desired_speed_given: bool,
    },
    /// `mobil` on `idm`.
    Mobil {
        /// The IDM parameters.
        idm: IdmParameters,
        /// `desiredSpeed` was given.
        desired_speed_given: bool,
        /// The MOBIL parameters.
        mobil: MobilParameters,
    },
    /// `acc`; `set_speed_given` false: the speed at activation.
    Acc {
        /// The ACC parameters.
        acc: AccParameters,
        /// `setSpeed` was given.
        set_speed_given: bool,
    },
    /// `vehicle_dynamics`.
    VehicleDynamics {
        /// `steeringRatio`.
        steering_ratio: Option<f64>,
        /// `steeringWheelInertia`.
        steering_inertia: Option<f64>,
    },
    /// `external`.
    External,
}

impl ModelSettings {
    /// The model's name as written in `model`.
    pub fn name(&self) -> &'static str {
        match self {
            ModelSettings::Idm { .. } => "idm",
            ModelSettings::Mobil { .. } => "mobil",
            ModelSettings::Acc { .. } => "acc",
            ModelSettings::VehicleDynamics { .. } => "vehicle_dynamics",
            ModelSettings::External => "external",
        }
    }

    /// The domains the model can hold.
    pub fn domains(&self) -> MotionDomains {
        match self {
            ModelSettings::Idm { .. } | ModelSettings::Acc { .. } => MotionDomains::LONGITUDINAL,
            _ => MotionDomains::BOTH,
        }
    }
}

/// What a `Controller` element is to oscsim.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ControllerKind {
    /// One of the built-in models, on the domains it may hold (the model's, narrowed by
    /// `controllerType`).
    Model {
        /// The settings.
        settings: ModelSettings,
        /// The motion domains it may be activated on.
        domains: MotionDomains,
    },
    /// The default controller by name (`Controller name="default"` with no properties).
    Default,
    /// A controller of another tool: no `model` property. `what` says whose, for the log.
    Foreign {
        /// "esminiController ACCController", or the controller's name.
        what: String,
    },
}

/// The names of esmini's built-in controllers (esmini 3.x `Controller*::GetTypeNameStatic`,
/// as its scenarios use them in `esminiController` or as the Controller's name).
pub const ESMINI_CONTROLLERS: [&str; 18] = [
    "ACCController",
    "ALKSController",
    "ALKS_R157SM_Controller",
    "ControllerRel2Abs",
    "ECE_ALKS_RefDriverController",
    "ExternalController",
    "FollowGhostController",
    "FollowReferenceController",
    "FollowRouteController",
    "HIDController",
    "InteractiveController",
    "LoomingController",
    "NaturalDriver",
    "OffroadFollower",
    "SloppyDriverController",
    "SumoController",
    "UDPDriverController",
    "DynamicsController",
];

/// The model names, for messages.
const MODELS: &str = "idm, mobil, acc, vehicle_dynamics, external";
const IDM_PROPERTIES: [&str; 6] = [
    "desiredSpeed",
    "timeHeadway",
    "minimumGap",
    "maxAcceleration",
    "comfortableDeceleration",
    "accelerationExponent",
];
const MOBIL_PROPERTIES: [&str; 4] = [
    "politeness",
    "changeThreshold",
    "safeDeceleration",
    "rightBias",
];
const ACC_PROPERTIES: [&str; 6] = [
    "setSpeed",
    "timeGap",
    "minimumGap",
    "maxAcceleration",
    "maxDeceleration",
    "maxJerk",
];
const VEHICLE_PROPERTIES: [&str; 2] = ["steeringRatio", "steeringWheelInertia"];

/// The range a property's value must lie in.
#[derive(Debug, Clone, Copy)]
enum Range {
    /// ≥ 0.
    NonNegative,
    /// > 0.
    Positive,
    /// Any finite number.
    Any,
}

/// One property with its place, for reading.
struct Prop<'a> {
    name: &'a str,
    value: &'a str,
    pos: &'a SourcePos,
}

/// The properties of `c` with their places (the controller's own place where a property has
/// none recorded).
fn props(c: &Controller) -> Vec<Prop<'_>> {
    let p = &c.properties;
    p.properties
        .iter()
        .enumerate()
        .map(|(i, (name, value))| Prop {
            name,
            value,
            pos: p.positions.get(i).unwrap_or(&c.pos),
        })
        .collect()
}

fn number(p: &Prop<'_>, range: Range) -> Result<f64, Error> {
    let (expected, ok): (&str, fn(f64) -> bool) = match range {
        Range::NonNegative => ("a finite number ≥ 0", |v| v >= 0.0),
        Range::Positive => ("a finite number > 0", |v| v > 0.0),
        Range::Any => ("a finite number", |_| true),
    };
    match p.value.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && ok(v) => Ok(v),
        _ => Err(Error::at(
            format!("{expected} for property '{}'", p.name),
            format!("'{}'", p.value),
            p.pos,
        )),
    }
}

/// Reads `c` (module doc).
pub fn classify(c: &Controller) -> Result<ControllerKind, Error> {
    let all = props(c);
    if let Some(p) = all.iter().find(|p| p.name == "esminiController") {
        return Ok(ControllerKind::Foreign {
            what: format!("'{}' (esminiController {})", c.name, p.value),
        });
    }
    if ESMINI_CONTROLLERS.contains(&c.name.as_str()) {
        return Ok(ControllerKind::Foreign {
            what: format!("'{}' (an esmini controller)", c.name),
        });
    }
    let Some(model) = all.iter().find(|p| p.name == "model") else {
        if c.properties.properties.is_empty() && c.name.eq_ignore_ascii_case("default") {
            return Ok(ControllerKind::Default);
        }
        return Ok(ControllerKind::Foreign {
            what: format!("'{}' (no model property)", c.name),
        });
    };
    let rest: Vec<&Prop<'_>> = all.iter().filter(|p| p.name != "model").collect();
    let settings = match model.value.trim() {
        "idm" => {
            let (idm, given) = read_idm(&rest, &[])?;
            ModelSettings::Idm {
                idm,
                desired_speed_given: given,
            }
        }
        "mobil" => {
            let (idm, given) = read_idm(&rest, &MOBIL_PROPERTIES)?;
            let mut mobil = MobilParameters::default();
            for p in rest.iter().filter(|p| MOBIL_PROPERTIES.contains(&p.name)) {
                match p.name {
                    "politeness" => mobil.politeness = number(p, Range::Any)?,
                    "changeThreshold" => mobil.change_threshold = number(p, Range::NonNegative)?,
                    "safeDeceleration" => mobil.safe_deceleration = number(p, Range::Positive)?,
                    _ => mobil.right_bias = number(p, Range::Any)?,
                }
            }
            ModelSettings::Mobil {
                idm,
                desired_speed_given: given,
                mobil,
            }
        }
        "acc" => {
            let mut acc = AccParameters::new(0.0);
            let mut given = false;
            for p in &rest {
                match p.name {
                    "setSpeed" => {
                        acc.set_speed = number(p, Range::NonNegative)?;
                        given = true;
                    }
                    "timeGap" => acc.time_gap = number(p, Range::Positive)?,
                    "minimumGap" => acc.minimum_gap = number(p, Range::NonNegative)?,
                    "maxAcceleration" => acc.max_acceleration = Some(number(p, Range::Positive)?),
                    "maxDeceleration" => acc.max_deceleration = Some(number(p, Range::Positive)?),
                    "maxJerk" => acc.max_jerk = Some(number(p, Range::Positive)?),
                    _ => return Err(unknown(p, "acc", &ACC_PROPERTIES)),
                }
            }
            ModelSettings::Acc {
                acc,
                set_speed_given: given,
            }
        }
        "vehicle_dynamics" => {
            let (mut steering_ratio, mut steering_inertia) = (None, None);
            for p in &rest {
                match p.name {
                    "steeringRatio" => steering_ratio = Some(number(p, Range::Positive)?),
                    "steeringWheelInertia" => steering_inertia = Some(number(p, Range::Positive)?),
                    _ => return Err(unknown(p, "vehicle_dynamics", &VEHICLE_PROPERTIES)),
                }
            }
            ModelSettings::VehicleDynamics {
                steering_ratio,
                steering_inertia,
            }
        }
        "external" => {
            if let Some(p) = rest.first() {
                return Err(unknown(p, "external", &[]));
            }
            ModelSettings::External
        }
        other => {
            return Err(Error::at(
                format!("a controller model ({MODELS})"),
                format!("'{other}'"),
                model.pos,
            ))
        }
    };
    let domains = narrow(settings.domains(), c.controller_type, &settings, &c.pos)?;
    Ok(ControllerKind::Model { settings, domains })
}

/// The IDM parameters from `props`, allowing the names in `also` (read by the caller).
fn read_idm(props: &[&Prop<'_>], also: &[&str]) -> Result<(IdmParameters, bool), Error> {
    let mut idm = IdmParameters::default();
    let mut given = false;
    let model = if also.is_empty() { "idm" } else { "mobil" };
    for p in props {
        match p.name {
            "desiredSpeed" => {
                idm.desired_speed = number(p, Range::NonNegative)?;
                given = true;
            }
            "timeHeadway" => idm.time_headway = number(p, Range::NonNegative)?,
            "minimumGap" => idm.minimum_gap = number(p, Range::NonNegative)?,
            "maxAcceleration" => idm.max_acceleration = number(p, Range::Positive)?,
            "comfortableDeceleration" => idm.comfortable_deceleration = number(p, Range::Positive)?,
            "accelerationExponent" => idm.acceleration_exponent = number(p, Range::Positive)?,
            name if also.contains(&name) => {}
            _ => {
                let names: Vec<&str> = IDM_PROPERTIES.iter().chain(also).copied().collect();
                return Err(unknown(p, model, &names));
            }
        }
    }
    Ok((idm, given))
}

fn unknown(p: &Prop<'_>, model: &str, names: &[&str]) -> Error {
    let expected = if names.is_empty() {
        format!("no property for model '{model}'")
    } else {
        format!("a property of model '{model}' ({})", names.join(", "))
    };
    Error::at(expected, format!("'{}'", p.name), p.pos)
}

/// The model's domains narrowed by `controllerType` (1.2+): `movement` keeps both,
/// `longitudinal` / `lateral` one; a type naming a domain the model cannot hold, or only
/// appearance, is an error at the controller.
fn narrow(
    model: MotionDomains,
    ty: Option<ControllerType>,
    settings: &ModelSettings,
    pos: &SourcePos,
) -> Result<MotionDomains, Error> {
    let asked = match ty {
        None | Some(ControllerType::Movement) => return Ok(model),
        Some(ControllerType::Longitudinal) => MotionDomains::LONGITUDINAL,
        Some(ControllerType::Lateral) => MotionDomains {
            longitudinal: false,
            lateral: true,
        },
        Some(_) => MotionDomains::default(),
    };
    let kept = MotionDomains {
        longitudinal: asked.longitudinal && model.longitudinal,
        lateral: asked.lateral && model.lateral,
    };
    if kept == MotionDomains::default() {
        return Err(Error::at(
            format!(
                "a controllerType in the domains model '{}' controls ({})",
                settings.name(),
                model.describe()
            ),
            ty.map_or("none".to_owned(), |t| format!("'{t}'")),
            pos,
        ));
    }
    Ok(kept)
}

/// A controller model for spawned traffic ([`EngineConfig::traffic_model`](crate::EngineConfig::traffic_model)) or the scenario's
/// vehicles ([`EngineConfig::vehicle_model`](crate::EngineConfig::vehicle_model)).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TrafficModel {
    /// `idm`: the Intelligent Driver Model (longitudinal), the model's default parameters.
    Idm,
    /// `mobil`: IDM and MOBIL lane changes (both domains), the models' default parameters.
    Mobil,
}
