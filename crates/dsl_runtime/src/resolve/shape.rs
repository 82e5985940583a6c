//! The `shape:` of a movement modifier (ASAM OpenSCENARIO DSL 2.1 §8.9.1.1.4 parameter
//! `shape`, §8.9.1.2 shape object description), read into the arguments of the §8.8 action
//! whose dynamics it describes.
//!
//! A shape is a struct with a `duration()` and a `compute(time)` giving the state variable
//! over the phase. The library's common shapes (`common_speed_shape`,
//! `common_acceleration_shape`, `common_lateral_shape`) have no `compute` the program writes:
//! "`target`, `rate_profile` and `rate_peak` provide a complete set of constraints to resolve
//! the target shape" (§8.9.1.2), and the standard's semantic clarifications name them as the
//! dynamics of `change_speed`, `change_acceleration` (§8.8.2.12 Code 100: `change_speed(target,
//! rate_profile, rate_peak)` is `move() with: speed(shape: spd_shape)` for the common speed
//! shape of those three values) and of a lateral change. So a common shape is read as those
//! three arguments, and the planner runs the action's own dynamics with them
//! (`plan::shapes`); a `common_position_shape` (the position along the lane, whose rate is the
//! speed) on `position(…, at: end)` or `distance(…)` as the speed profile that covers the
//! distance (`plan::position_shape`). A struct of the program's own that inherits `any_shape`
//! has no dynamics the planner runs: an error at the argument, saying so.
//!
//! The shape's `target` and the modifier's own value may overlap (`speed(50kph, at: end,
//! shape: s)`, §8.9.1.1.4 Code 79: "the shape's target parameter can be taken from the speed
//! modifier"): the modifier's value is the target then, and a shape whose target is set
//! otherwise (not the library's default 0) must agree with it.

use super::eval::Eval;
use super::value::{Arg, Args, Val};
use crate::error::{Error, ErrorKind as K};

/// The state variable a common shape shapes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ShapeKind {
    /// `common_speed_shape`: the speed (`rate_peak` an acceleration).
    Speed,
    /// `common_acceleration_shape`: the acceleration (`rate_peak` a jerk).
    Acceleration,
    /// `common_lateral_shape`: the lateral position (`rate_peak` a lateral speed).
    Lateral,
    /// `common_position_shape`: the position along the lane (`rate_peak` a speed).
    Position,
}

impl ShapeKind {
    /// The library struct of this kind.
    pub(crate) fn library_name(self) -> &'static str {
        match self {
            ShapeKind::Speed => "common_speed_shape",
            ShapeKind::Acceleration => "common_acceleration_shape",
            ShapeKind::Lateral => "common_lateral_shape",
            ShapeKind::Position => "common_position_shape",
        }
    }
}

/// A modifier's common shape, read: its kind and its `target`, `rate_profile` and `rate_peak`
/// as the arguments of the action whose dynamics they are (each written at the `shape:`
/// argument). A `rate_peak` of 0 (the library's default) is left out: no peak was given.
#[derive(Debug, Clone)]
pub(crate) struct Shape {
    /// Which state variable.
    pub kind: ShapeKind,
    /// `target` (absent when it is the library's default 0), `rate_profile`, `rate_peak`.
    pub args: Args,
}

/// The shape kind modifier `name` takes, if any.
fn kind_for(name: &str) -> Option<ShapeKind> {
    match name {
        "speed" | "change_speed" => Some(ShapeKind::Speed),
        "acceleration" => Some(ShapeKind::Acceleration),
        "lateral" | "change_lane" | "lane" => Some(ShapeKind::Lateral),
        "position" | "distance" => Some(ShapeKind::Position),
        _ => None,
    }
}

/// Reads the `shape:` argument `a` of modifier `name`.
pub(crate) fn read(ctx: &Eval<'_>, name: &str, a: &Arg) -> Result<Shape, Error> {
    let Some(kind) = kind_for(name) else {
        return Err(a.site.err(
            K::Modifier,
            format!("expected `{name}(…)` without shape: (oscsim runs the shapes of speed, change_speed, acceleration, lane, change_lane, lateral, position and distance), found one"),
        ));
    };
    let want = kind.library_name();
    let path = match a.eval()? {
        Val::Instance(p) => p,
        _ => {
            return Err(a.site.err(
                K::Modifier,
                format!(
                    "expected a {want} instance as the shape of `{name}(…)`, found another value"
                ),
            ))
        }
    };
    let value = ctx.lookup(&path).map(|(_, v)| v);
    let ty = value.and_then(|v| ctx.type_of(v)).map_or_else(
        || "another value".to_string(),
        |c| ctx.model.compound(c).name.clone(),
    );
    if !value.is_some_and(|v| ctx.is_a(v, want)) {
        let own = value.is_some_and(|v| ctx.is_a(v, "any_shape"))
            && ![
                "common_speed_shape",
                "common_acceleration_shape",
                "common_lateral_shape",
                "common_position_shape",
            ]
            .iter()
            .any(|c| value.is_some_and(|v| ctx.is_a(v, c)));
        let why = if own {
            format!("`{ty}`, a shape of the program's own: its compute() is no dynamics the engine runs (oscsim runs the library's common shapes, whose target, rate_profile and rate_peak are those of the §8.8 actions)")
        } else {
            format!("`{ty}`")
        };
        return Err(a.site.err(
            K::Modifier,
            format!("expected a {want} as the shape of `{name}(…)`, found {why}"),
        ));
    }
    let field = |f: &str| Arg {
        site: a.site.clone(),
        path: None,
        value: ctx.value_at(&format!("{path}.{f}")).ok_or_else(|| {
            a.site.err(
                K::Value,
                format!("expected a value for `{f}` of the shape, found none"),
            )
        }),
    };
    let mut args = Args::new();
    for f in ["target", "rate_profile", "rate_peak"] {
        let v = field(f);
        let default = matches!(v.value, Ok(Val::Num(x)) if x == 0.0) && f != "rate_profile";
        if !default {
            args.push((f.to_string(), v));
        }
    }
    Ok(Shape { kind, args })
}
