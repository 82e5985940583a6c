//! Movement modifiers of an invocation, read into the planner's terms (ASAM OpenSCENARIO DSL
//! 2.1 §8.9): which modifier, when it applies (`at: start | end | all`, default `all`) and its
//! arguments by parameter name (positional arguments take the modifier's own parameters in
//! declaration order, as the checker binds them).

use dsl::semantics::hir::{Expr, ModifierApp};

use crate::error::{Error, ErrorKind as K};
use crate::value::{bind, Ctx, Val};

/// The modifiers the planner runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ModKind {
    /// `speed(…)`
    Speed,
    /// `change_speed(…)`: the speed at the phase end.
    ChangeSpeed,
    /// `acceleration(a)`: the rate of the phase's speed change (alone: a constant
    /// acceleration over the phase).
    Acceleration,
    /// `position(…)`
    Position,
    /// `lane(…)`
    Lane,
    /// `change_lane(…)`: a lane change during the phase.
    ChangeLane,
    /// `distance(d)`: the distance travelled in the phase.
    Distance,
    /// `lateral(…)`: an offset in the lane (`lateral` module).
    Lateral,
    /// `yaw(angle)` and `orientation(yaw, pitch, roll)` relative to the road: checked (the
    /// engine's vehicles drive along their lane; see [`check_orientation`]).
    Orientation,
    /// `along(route)`: the actor follows a route (`route` module).
    Along,
    /// `keep_lane()`: no lane change in the phase (the engine's default motion follows the
    /// lane; a lane change modifier beside it is an error).
    KeepLane,
    /// `keep_speed()`: no speed change in the phase (a speed change beside it is an error).
    KeepSpeed,
    /// `keep_position()`: standing still through the phase (a vehicle moving at its start, or
    /// any movement modifier beside it, is an error).
    KeepPosition,
    /// `physical_movement(option)`: `must_be_physical` forbids speed steps in the phase.
    PhysicalMovement,
    /// `avoid_collisions(false)`: the engine's vehicles do not avoid collisions (`true` is an
    /// error).
    AvoidCollisions,
}

/// When a modifier's constraint holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum At {
    /// At the phase start.
    Start,
    /// At the phase end.
    End,
    /// Throughout.
    All,
}

/// A modifier application, read.
#[derive(Debug)]
pub(crate) struct Mod<'p> {
    /// Which.
    pub kind: ModKind,
    /// When.
    pub at: At,
    /// `movement_mode: monotonous` (§8.9.1.1): the planned quantity changes in one direction.
    pub monotonous: bool,
    /// Arguments by parameter name.
    pub args: Vec<(String, &'p Expr)>,
    /// The application.
    pub app: &'p ModifierApp,
}

impl<'p> Mod<'p> {
    /// The argument `name`.
    pub(crate) fn arg(&self, name: &str) -> Option<&'p Expr> {
        self.args.iter().find(|(n, _)| n == name).map(|(_, e)| *e)
    }
}

/// Reads `app`.
pub(crate) fn read<'p>(ctx: &Ctx<'_>, app: &'p ModifierApp) -> Result<Mod<'p>, Error> {
    let name = app.name.text.as_str();
    let kind = match name {
        "speed" => ModKind::Speed,
        "change_speed" => ModKind::ChangeSpeed,
        "acceleration" => ModKind::Acceleration,
        "position" => ModKind::Position,
        "lane" => ModKind::Lane,
        "change_lane" => ModKind::ChangeLane,
        "along" => ModKind::Along,
        "lateral" => ModKind::Lateral,
        "distance" => ModKind::Distance,
        "yaw" | "orientation" => ModKind::Orientation,
        "keep_lane" => ModKind::KeepLane,
        "keep_speed" => ModKind::KeepSpeed,
        "keep_position" => ModKind::KeepPosition,
        "physical_movement" => ModKind::PhysicalMovement,
        "avoid_collisions" => ModKind::AvoidCollisions,
        other => {
            return Err(ctx.files.err(
                K::Modifier,
                app.span,
                format!(
                    "expected a modifier the runtime plans (speed, change_speed, acceleration, position, distance, lane, change_lane, lateral, yaw, orientation, keep_lane, keep_speed, keep_position, along, physical_movement, avoid_collisions), found `{other}`"
                ),
            ))
        }
    };
    if app.target.is_some() {
        return Err(ctx.files.err(
            K::Modifier,
            app.span,
            format!(
                "expected `{name}(…)` on the invoked action, found it applied to another target"
            ),
        ));
    }
    let params: Vec<String> = ctx
        .model
        .modifiers_named(name)
        .first()
        .map(|m| {
            ctx.model
                .compound(*m)
                .fields
                .iter()
                .map(|f| f.name.clone())
                .collect()
        })
        .unwrap_or_default();
    let args = bind(&app.args, &params);
    let at = match args.iter().find(|(n, _)| n == "at") {
        None => At::All,
        Some((_, e)) => match ctx.eval(e)? {
            Val::Enum(m) if m == "start" => At::Start,
            Val::Enum(m) if m == "end" => At::End,
            Val::Enum(m) if m == "all" => At::All,
            _ => {
                return Err(ctx.files.err(
                    K::Modifier,
                    e.span,
                    "expected start, end or all, found another value",
                ))
            }
        },
    };
    // The common parameters (§8.9.1.1): `movement_mode` is planned (see `Mod::monotonous`),
    // `track: actual` is what the engine measures; a projected track and `shape` are not run.
    let mut monotonous = false;
    for (n, e) in &args {
        match n.as_str() {
            "movement_mode" => {
                monotonous = matches!(ctx.eval(e)?, Val::Enum(m) if m == "monotonous");
            }
            "track" if !matches!(ctx.eval(e)?, Val::Enum(t) if t == "actual") => {
                return Err(ctx.files.err(
                    K::Modifier,
                    e.span,
                    "expected track: actual (the engine plans and measures the actual track), found another track (projected tracks are not run)",
                ));
            }
            "shape" => {
                return Err(ctx.files.err(
                    K::Modifier,
                    e.span,
                    format!("expected `{name}(…)` without shape: (the engine's own speed and lane change shapes are planned), found one"),
                ))
            }
            _ => {}
        }
    }
    check_combination(ctx, name, &args)?;
    match kind {
        ModKind::AvoidCollisions => {
            let avoid = match args.iter().find(|(n, _)| n == "avoid") {
                Some((_, e)) => ctx.eval(e)?,
                None => Val::Bool(true),
            };
            if avoid != Val::Bool(false) {
                return Err(ctx.files.err(
                    K::Modifier,
                    app.span,
                    "expected avoid_collisions(false) (the engine's vehicles follow their plan and do not avoid others), found a request to avoid collisions",
                ));
            }
        }
        ModKind::PhysicalMovement => {
            if let Some((_, e)) = args.iter().find(|(n, _)| n == "option") {
                if !matches!(ctx.eval(e)?, Val::Enum(_)) {
                    return Err(ctx.files.err(
                        K::Modifier,
                        e.span,
                        "expected prefer_physical, prefer_non_physical or must_be_physical, found another value",
                    ));
                }
            }
        }
        _ => {}
    }
    Ok(Mod {
        kind,
        at,
        monotonous,
        args,
        app,
    })
}

/// Checks `keep_lane()`, `keep_speed()` and `physical_movement(must_be_physical)` against the
/// other modifiers of their invocation: a lane change beside `keep_lane`, a speed change beside
/// `keep_speed`, or a step of speed (`speed(v)` in a later phase, `step`: the speeds before and
/// after) beside either `keep_speed` or `must_be_physical` is an error at that modifier.
pub(crate) fn check_keeps(
    ctx: &Ctx<'_>,
    mods: &[Mod<'_>],
    step: Option<(&Mod<'_>, f64, f64)>,
) -> Result<(), Error> {
    let step = step.filter(|(_, v0, v1)| (v1 - v0).abs() > 1e-9);
    for k in mods {
        match k.kind {
            ModKind::KeepLane => {
                if let Some(c) = mods.iter().find(|m| {
                    m.kind == ModKind::ChangeLane || (m.kind == ModKind::Lane && m.at == At::End)
                }) {
                    return Err(ctx.files.err(
                        K::Unsatisfiable,
                        c.app.span,
                        format!(
                            "expected no lane change beside keep_lane() at {}, found `{}(…)`",
                            ctx.files.at(k.app.span),
                            c.app.name.text
                        ),
                    ));
                }
            }
            ModKind::KeepPosition => {
                let moves = |m: &&Mod<'_>| match m.kind {
                    ModKind::ChangeSpeed
                    | ModKind::Acceleration
                    | ModKind::Distance
                    | ModKind::ChangeLane => true,
                    ModKind::Lane | ModKind::Position | ModKind::Lateral => m.at == At::End,
                    // speed(0) (or 0 at the end) agrees; anything else moves.
                    ModKind::Speed => !matches!(
                        (m.arg("speed").map(|e| ctx.number(e)), m.arg("faster_than").or(m.arg("slower_than")).or(m.arg("same_as"))),
                        (Some(Ok(v)), None) if v == 0.0
                    ),
                    _ => false,
                };
                if let Some(c) = mods.iter().find(moves) {
                    return Err(ctx.files.err(
                        K::Unsatisfiable,
                        c.app.span,
                        format!(
                            "expected no movement beside keep_position() at {}, found `{}(…)`",
                            ctx.files.at(k.app.span),
                            c.app.name.text
                        ),
                    ));
                }
            }
            ModKind::KeepSpeed => {
                if let Some(c) = mods.iter().find(|m| {
                    matches!(m.kind, ModKind::ChangeSpeed | ModKind::Acceleration)
                        || (matches!(m.kind, ModKind::Speed | ModKind::Position) && m.at == At::End)
                }) {
                    return Err(ctx.files.err(
                        K::Unsatisfiable,
                        c.app.span,
                        format!(
                            "expected no speed change beside keep_speed() at {}, found `{}(…)`",
                            ctx.files.at(k.app.span),
                            c.app.name.text
                        ),
                    ));
                }
                if let Some((c, v0, v1)) = step {
                    return Err(ctx.files.err(
                        K::Unsatisfiable,
                        c.app.span,
                        format!("expected the speed kept beside keep_speed() at {}, found a step from {v0:.2} m/s to {v1:.2} m/s", ctx.files.at(k.app.span)),
                    ));
                }
            }
            ModKind::PhysicalMovement => {
                let must = matches!(k.arg("option").map(|e| ctx.eval(e)).transpose()?, Some(Val::Enum(o)) if o == "must_be_physical");
                if let (true, Some((c, v0, v1))) = (must, step) {
                    return Err(ctx.files.err(
                        K::Unsatisfiable,
                        c.app.span,
                        format!("expected a physical movement (physical_movement(must_be_physical) at {}), found a step of speed from {v0:.2} m/s to {v1:.2} m/s at the phase start; use change_speed(…) or speed(…, at: end)", ctx.files.at(k.app.span)),
                    ));
                }
            }
            _ => {}
        }
    }
    Ok(())
}

/// Checks `yaw(…)` and `orientation(…)` (§8.9 yaw, orientation) against the plan's motion: the
/// engine's vehicles drive along their lane's centre line (or at a constant offset from it), so
/// their yaw, pitch and roll relative to the road are 0 except while they change lane or lane
/// offset, and 0 again when such a change ends (the sinusoidal shape ends with no lateral
/// speed). A zero angle relative to the road (the default measure) therefore holds at the
/// start and end of every phase, and throughout one without a lane change or a
/// `lateral(…, at: end)`; anything else is an error: a non-zero angle, an angle relative to
/// another object, to north, or absolute, which the planner does not steer.
pub(crate) fn check_orientation(ctx: &Ctx<'_>, mods: &[Mod<'_>]) -> Result<(), Error> {
    /// Angles within this of 0 are 0 (rad): a thousandth of a degree.
    const ZERO: f64 = 1e-3 * std::f64::consts::PI / 180.0;
    for m in mods.iter().filter(|m| m.kind == ModKind::Orientation) {
        let name = m.app.name.text.as_str();
        if let Some(e) = m.arg("relative_to") {
            return Err(ctx.files.err(
                K::Unsupported,
                e.span,
                format!("expected {name}(…) relative to the road, found relative_to: (orientations relative to another object are not planned yet)"),
            ));
        }
        let measure = if name == "yaw" {
            "measure_by"
        } else {
            "measured_by"
        };
        if let Some(e) = m.arg(measure) {
            if !matches!(ctx.eval(e)?, Val::Enum(v) if v == "relative_to_road") {
                return Err(ctx.files.err(
                    K::Unsupported,
                    e.span,
                    format!("expected {measure}: relative_to_road, found another measure (absolute and north-relative orientations are not planned yet)"),
                ));
            }
        }
        let angles: &[&str] = if name == "yaw" {
            &["angle"]
        } else {
            &["yaw", "pitch", "roll"]
        };
        for a in angles {
            if let Some(e) = m.arg(a) {
                let x = ctx.number(e)?;
                if x.abs() > ZERO {
                    return Err(ctx.files.err(
                        K::Unsatisfiable,
                        e.span,
                        format!("expected {a} 0 relative to the road (the engine's vehicles drive along their lane), found {x:.4} rad"),
                    ));
                }
            }
        }
        if m.at == At::All {
            if let Some(c) = mods.iter().find(|q| {
                q.kind == ModKind::ChangeLane
                    || (matches!(q.kind, ModKind::Lane | ModKind::Lateral) && q.at == At::End)
            }) {
                return Err(ctx.files.err(
                    K::Unsatisfiable,
                    c.app.span,
                    format!("expected no lateral movement while {name}(…) at {} holds throughout the phase (the actor turns while it moves sideways), found `{}(…)`", ctx.files.at(m.app.span), c.app.name.text),
                ));
            }
        }
    }
    Ok(())
}

/// Rejects argument combinations where one argument would go unread: two references (or a
/// distance and a time) where the planner takes one, `side` without `side_of`, `from` or an
/// explicit lane number beside `same_as`, and the relative forms of `acceleration`.
fn check_combination(ctx: &Ctx<'_>, name: &str, args: &[(String, &Expr)]) -> Result<(), Error> {
    let has = |n: &str| args.iter().find(|(a, _)| a == n).map(|(_, e)| *e);
    let refs: Vec<&str> = [
        "same_as", "side_of", "left_of", "right_of", "ahead_of", "behind",
    ]
    .into_iter()
    .chain(["faster_than", "slower_than"])
    .filter(|r| has(r).is_some())
    .collect();
    let second = |what: &str, e: &Expr| {
        ctx.files.err(
            K::Modifier,
            e.span,
            format!("expected one of {what} in {name}(…), found a second one"),
        )
    };
    if let [_, r, ..] = refs.as_slice() {
        if let Some(e) = has(r) {
            return Err(second("the reference objects", e));
        }
    }
    if let (Some(_), Some(e)) = (has("distance"), has("time")) {
        return Err(second("distance and time", e));
    }
    // lateral(…) without a reference reads side: from the lane's centre.
    let side_unread = match name {
        "lane" => has("side_of").is_none(),
        "lateral" => has("left_of").is_some() || has("right_of").is_some(),
        _ => false,
    };
    if side_unread {
        if let Some(e) = has("side") {
            return Err(ctx.files.err(
                K::Modifier,
                e.span,
                format!("expected side: with side_of: in {name}(…), found it without (left_of/right_of name their side)"),
            ));
        }
    }
    if name == "lane" {
        if let (Some(e), false) = (has("from"), refs.is_empty()) {
            return Err(ctx.files.err(
                K::Modifier,
                e.span,
                "expected from: in lane(…) without a reference object (it counts lanes from the road's edge), found both",
            ));
        }
        if let (Some(e), Some(_)) = (has("lane"), has("same_as")) {
            return Err(ctx.files.err(
                K::Modifier,
                e.span,
                "expected no lane number beside same_as: in lane(…) (the lane is the other object's), found one",
            ));
        }
    }
    if name == "acceleration" {
        if let Some(r) = refs.first().and_then(|r| has(r)) {
            return Err(ctx.files.err(
                K::Unsupported,
                r.span,
                "expected acceleration(a) (an absolute rate), found a relative form (faster_than, slower_than, same_as: not planned yet)",
            ));
        }
    }
    Ok(())
}
