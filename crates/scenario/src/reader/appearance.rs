//! Readers for controller-value overrides and appearance actions (OpenSCENARIO 1.3, "Actions",
//! XSD `OverrideControllerValueAction`, `AppearanceAction`, `LightStateAction`,
//! `AnimationAction`, `Color`). The deprecated `value` of brake overrides (1.0–1.1) reads
//! as BrakePercent and the deprecated `number` of OverrideGearAction as a ManualGear.

use crate::error::{ErrorKind, Result};
use crate::model::{
    AnimationAction, AnimationType, AppearanceAction, BrakeInput, BrakeOverride, Color, ColorValue,
    Gear, GearOverride, LightKind, LightState, LightStateAction, OverrideControllerValueAction,
    PedalOverride, SteeringOverride,
};
use crate::reader::context::{Ctx, Node};

/// Reads XSD `OverrideControllerValueAction`.
pub(crate) fn read_override_controller_value_action<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
) -> Result<OverrideControllerValueAction> {
    let mut out = OverrideControllerValueAction::default();
    if let Some(t) = ctx.opt_child(n, "Throttle") {
        out.throttle = Some(read_pedal(ctx, t)?);
    }
    if let Some(b) = ctx.opt_child(n, "Brake") {
        out.brake = Some(read_brake(ctx, b)?);
    }
    if let Some(c) = ctx.opt_child(n, "Clutch") {
        out.clutch = Some(read_pedal(ctx, c)?);
    }
    if let Some(p) = ctx.opt_child(n, "ParkingBrake") {
        out.parking_brake = Some(read_brake(ctx, p)?);
    }
    if let Some(s) = ctx.opt_child(n, "SteeringWheel") {
        out.steering_wheel = Some(SteeringOverride {
            active: ctx.req(s, "active")?,
            value: ctx.req(s, "value")?,
            max_rate: ctx.opt(s, "maxRate")?,
            max_torque: ctx.opt(s, "maxTorque")?,
        });
    }
    if let Some(g) = ctx.opt_child(n, "Gear") {
        let gear = if let Some(m) = ctx.opt_child(g, "ManualGear") {
            Gear::Manual(ctx.req(m, "number")?)
        } else if let Some(a) = ctx.opt_child(g, "AutomaticGear") {
            Gear::Automatic(ctx.req(a, "gear")?)
        } else {
            ctx.warn(
                g,
                "OverrideGearAction@number is deprecated, read as ManualGear".into(),
            );
            let number: f64 = ctx.req(g, "number")?;
            // The deprecated attribute is a double holding a gear number; gears are small
            // integers, so rounding loses nothing a scenario can mean.
            Gear::Manual(
                number
                    .round()
                    .clamp(f64::from(i32::MIN), f64::from(i32::MAX)) as i32,
            )
        };
        out.gear = Some(GearOverride {
            active: ctx.req(g, "active")?,
            gear,
        });
    }
    Ok(out)
}

fn read_pedal<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<PedalOverride> {
    Ok(PedalOverride {
        active: ctx.req(n, "active")?,
        value: ctx.req(n, "value")?,
        max_rate: ctx.opt(n, "maxRate")?,
    })
}

/// Reads XSD `OverrideBrakeAction` or `OverrideParkingBrakeAction`.
fn read_brake<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<BrakeOverride> {
    let (input, max_rate) = if let Some(p) = ctx.opt_child(n, "BrakePercent") {
        (
            BrakeInput::Percent(ctx.req(p, "value")?),
            ctx.opt(p, "maxRate")?,
        )
    } else if let Some(f) = ctx.opt_child(n, "BrakeForce") {
        (
            BrakeInput::Force(ctx.req(f, "value")?),
            ctx.opt(f, "maxRate")?,
        )
    } else {
        ctx.warn(
            n,
            format!(
                "{}@value is deprecated, read as BrakePercent",
                n.tag_name().name()
            ),
        );
        (BrakeInput::Percent(ctx.req(n, "value")?), None)
    };
    Ok(BrakeOverride {
        active: ctx.req(n, "active")?,
        input,
        max_rate,
    })
}

/// Reads XSD `AppearanceAction`.
pub(crate) fn read_appearance_action<'a>(
    ctx: &mut Ctx<'a>,
    n: Node<'a>,
) -> Result<AppearanceAction> {
    let c = ctx.choice(n, "LightStateAction, AnimationAction")?;
    Ok(match c.tag_name().name() {
        "LightStateAction" => AppearanceAction::LightState(read_light_state_action(ctx, c)?),
        "AnimationAction" => AppearanceAction::Animation(read_animation_action(ctx, c)?),
        _ => return Err(ctx.unexpected(n, c, "LightStateAction, AnimationAction")),
    })
}

fn read_light_state_action<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<LightStateAction> {
    let t = ctx.child(n, "LightType")?;
    let k = ctx.choice(t, "VehicleLight, UserDefinedLight")?;
    let light_type = match k.tag_name().name() {
        "VehicleLight" => LightKind::Vehicle(ctx.req(k, "vehicleLightType")?),
        "UserDefinedLight" => LightKind::UserDefined(ctx.req(k, "userDefinedLightType")?),
        _ => return Err(ctx.unexpected(t, k, "VehicleLight, UserDefinedLight")),
    };
    let s = ctx.child(n, "LightState")?;
    let color = match ctx.opt_child(s, "Color") {
        Some(c) => Some(read_color(ctx, c)?),
        None => None,
    };
    Ok(LightStateAction {
        light_type,
        light_state: LightState {
            mode: ctx.req(s, "mode")?,
            luminous_intensity: ctx.opt(s, "luminousIntensity")?,
            flashing_on_duration: ctx.opt(s, "flashingOnDuration")?,
            flashing_off_duration: ctx.opt(s, "flashingOffDuration")?,
            color,
        },
        transition_time: ctx.opt(n, "transitionTime")?,
    })
}

/// Reads XSD `Color`.
fn read_color<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<Color> {
    let value = if let Some(c) = ctx.opt_child(n, "ColorRgb") {
        ColorValue::Rgb {
            red: ctx.req(c, "red")?,
            green: ctx.req(c, "green")?,
            blue: ctx.req(c, "blue")?,
        }
    } else if let Some(c) = ctx.opt_child(n, "ColorCmyk") {
        ColorValue::Cmyk {
            cyan: ctx.req(c, "cyan")?,
            magenta: ctx.req(c, "magenta")?,
            yellow: ctx.req(c, "yellow")?,
            key: ctx.req(c, "key")?,
        }
    } else {
        return Err(ctx.err(
            n,
            ErrorKind::MissingElement {
                parent: "Color".into(),
                expected: "one of ColorRgb, ColorCmyk".into(),
            },
        ));
    };
    Ok(Color {
        color_type: ctx.req(n, "colorType")?,
        value,
    })
}

/// Reads XSD `AnimationAction`.
fn read_animation_action<'a>(ctx: &mut Ctx<'a>, n: Node<'a>) -> Result<AnimationAction> {
    const EXPECTED: &str =
        "ComponentAnimation, PedestrianAnimation, AnimationFile, UserDefinedAnimation";
    let t = ctx.child(n, "AnimationType")?;
    let k = ctx.choice(t, EXPECTED)?;
    let animation_type = match k.tag_name().name() {
        "ComponentAnimation" => {
            let c = ctx.choice(k, "VehicleComponent, UserDefinedComponent")?;
            match c.tag_name().name() {
                "VehicleComponent" => {
                    AnimationType::VehicleComponent(ctx.req(c, "vehicleComponentType")?)
                }
                "UserDefinedComponent" => {
                    AnimationType::UserDefinedComponent(ctx.req(c, "userDefinedComponentType")?)
                }
                _ => return Err(ctx.unexpected(k, c, "VehicleComponent, UserDefinedComponent")),
            }
        }
        "PedestrianAnimation" => {
            let mut gestures = Vec::new();
            for g in ctx.children(k, "PedestrianGesture") {
                gestures.push(ctx.req(g, "gesture")?);
            }
            AnimationType::Pedestrian {
                motion: ctx.opt(k, "motion")?,
                user_defined: ctx.opt(k, "userDefinedPedestrianAnimation")?,
                gestures,
            }
        }
        "AnimationFile" => {
            let f = ctx.child(k, "File")?;
            AnimationType::File {
                filepath: ctx.req(f, "filepath")?,
                time_offset: ctx.opt(k, "timeOffset")?,
            }
        }
        "UserDefinedAnimation" => {
            AnimationType::UserDefined(ctx.req(k, "userDefinedAnimationType")?)
        }
        _ => return Err(ctx.unexpected(t, k, EXPECTED)),
    };
    let state = match ctx.opt_child(n, "AnimationState") {
        Some(s) => Some(ctx.req(s, "state")?),
        None => None,
    };
    Ok(AnimationAction {
        animation_type,
        looping: ctx.opt(n, "loop")?,
        animation_duration: ctx.opt(n, "animationDuration")?,
        state,
    })
}
