//! Movement modifiers of an invocation, read into the planner's terms (ASAM OpenSCENARIO DSL
//! 2.1 §8.9): which modifier, when it applies (`at: start | end | all`, default `all`) and its
//! arguments by parameter name (positional arguments take the modifier's own parameters in
//! declaration order, as the checker binds them), evaluated. Combinations where an argument
//! would go unread are errors here; the checks against the planned motion are the planner's.

use dsl::semantics::hir::{Expr, ModifierApp};

use super::action::Action;
use super::eval::{bind, Eval};
use super::position::{path_route, Place};
use super::route::{self, Along};
use super::shape::{self, Shape};
use super::value::{arg, Arg, Args, Val};
use crate::error::{Error, ErrorKind as K, Site};

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
    /// `avoid_collisions(avoid)`: with `true` (or no argument) the engine's IDM car following
    /// drives the actor's speed in the phase (`plan::car_following`); `false` adds nothing.
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
#[derive(Debug, Clone)]
pub(crate) struct Modifier {
    /// Which.
    pub kind: ModKind,
    /// Its name as written (`yaw`, `orientation` are one kind).
    pub name: String,
    /// When.
    pub at: At,
    /// `movement_mode: monotonous` (§8.9.1.1): the planned quantity changes in one direction.
    pub monotonous: bool,
    /// `track: projected` (§8.9.1.1.3): the referenced actor's movement as projected from its
    /// state at the phase start (see `crate::plan`), not its actual one.
    pub projected: bool,
    /// Arguments by parameter name.
    pub args: Args,
    /// The route of an `along(…)`.
    pub along: Option<Along>,
    /// The route of an `along(…)` that is a path (`map.create_path(…)`,
    /// `map.resolve_relative_path(…)`, §8.12 `path`, a route): its place and the arguments
    /// that place it (`reference`, `transform`), followed as `follow_path` follows one
    /// (`along_path`).
    pub path: Option<(Place, Args)>,
    /// Its `shape:` (§8.9.1.2), read: the dynamics of its change.
    pub shape: Option<Shape>,
    /// The application.
    pub site: Site,
}

impl Modifier {
    /// The argument `name`.
    pub(crate) fn arg(&self, name: &str) -> Option<&Arg> {
        arg(&self.args, name)
    }
}

/// The arguments that name the actor a modifier is relative to (§8.9: `track` is that actor's
/// movement, actual or projected).
const REFERENCES: [&str; 8] = [
    "ahead_of",
    "behind",
    "same_as",
    "faster_than",
    "slower_than",
    "side_of",
    "left_of",
    "right_of",
];

/// The modifiers the semantic clarification of `action` (§8.8) implies, named after the action
/// (written at `site`) so that messages name what the user wrote: `remain_stationary()` is
/// `move() with: keep_position()` (§8.8.2.10), `keep_speed()` is `move() with: keep_speed()`
/// (§8.8.2.13), `follow_lane()` is `drive() with: keep_lane()` (§8.8.3.2).
pub(crate) fn implied(action: Action, name: &str, site: &Site) -> Vec<Modifier> {
    let kind = match action {
        Action::RemainStationary => ModKind::KeepPosition,
        Action::KeepSpeed => ModKind::KeepSpeed,
        Action::FollowLane => ModKind::KeepLane,
        _ => return Vec::new(),
    };
    vec![Modifier {
        kind,
        name: name.to_string(),
        at: At::All,
        monotonous: false,
        projected: false,
        args: Vec::new(),
        along: None,
        path: None,
        shape: None,
        site: site.clone(),
    }]
}

/// Reads `app`.
pub(crate) fn read(ctx: &Eval<'_>, app: &ModifierApp) -> Result<Modifier, Error> {
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
    let params = params(ctx, name);
    let bound = bind(&app.args, &params);
    let args: Args = bound.iter().map(|(n, e)| (n.clone(), ctx.arg(e))).collect();
    let mut at = match arg(&args, "at") {
        None => At::All,
        Some(e) => match e.eval()? {
            Val::Enum(m) if m == "start" => At::Start,
            Val::Enum(m) if m == "end" => At::End,
            Val::Enum(m) if m == "all" => At::All,
            _ => {
                return Err(e.site.err(
                    K::Modifier,
                    "expected start, end or all, found another value",
                ))
            }
        },
    };
    // The common parameters (§8.9.1.1): `movement_mode` is planned (see `Mod::monotonous`),
    // `track` is the referenced actor's (actual, or projected from its state at the phase
    // start: `Modifier::projected`); `shape` gives the change's dynamics (`shape` module).
    let mut monotonous = false;
    let mut projected = false;
    let mut shape = None;
    for (n, e) in &args {
        match n.as_str() {
            "movement_mode" => {
                monotonous = matches!(e.eval()?, Val::Enum(m) if m == "monotonous");
            }
            "track" => {
                projected = matches!(e.eval()?, Val::Enum(t) if t == "projected");
                if projected && !REFERENCES.iter().any(|k| arg(&args, k).is_some()) {
                    return Err(e.site.err(
                        K::Modifier,
                        format!("expected track: projected on `{name}(…)` relative to another actor ({}), found no reference (the track is the referenced actor's movement)", REFERENCES.join(", ")),
                    ));
                }
            }
            "shape" => shape = Some(shape::read(ctx, name, e)?),
            _ => {}
        }
    }
    check_combination(ctx, name, &bound)?;
    if shape.is_some() {
        // A shape is a change from the phase start (§8.9.1.2: compute's time is measured from
        // the start of the phase): it holds at the end, where the modifier's own value is.
        if at == At::Start {
            return Err(ctx.files.err(
                K::Modifier,
                app.span,
                format!("expected `{name}(…)` with a shape at: all or at: end (the shape is the change over the phase), found at: start"),
            ));
        }
        at = At::End;
    }
    match kind {
        ModKind::AvoidCollisions => {
            let avoid = match arg(&args, "avoid") {
                Some(e) => e.eval()?,
                None => Val::Bool(true),
            };
            if !matches!(avoid, Val::Bool(_)) {
                return Err(ctx.files.err(
                    K::Modifier,
                    app.span,
                    "expected avoid_collisions(true) or avoid_collisions(false), found another value",
                ));
            }
        }
        ModKind::PhysicalMovement => {
            if let Some(e) = arg(&args, "option") {
                if !matches!(e.eval()?, Val::Enum(_)) {
                    return Err(e.site.err(
                        K::Modifier,
                        "expected prefer_physical, prefer_non_physical or must_be_physical, found another value",
                    ));
                }
            }
        }
        _ => {}
    }
    let site = ctx.site(app.span);
    let (mut along, mut path) = (None, None);
    if kind == ModKind::Along {
        let route = bound.iter().find(|(n, _)| n == "route").map(|(_, e)| *e);
        match route.map(|e| path_route(ctx, e)).transpose()?.flatten() {
            Some(p) => path = Some(p),
            None => along = Some(route::read(ctx, &args, route, &site)?),
        }
    }
    Ok(Modifier {
        kind,
        name: name.to_string(),
        at,
        monotonous,
        projected,
        args,
        along,
        path,
        shape,
        site,
    })
}

/// Rejects argument combinations where one argument would go unread: two references (or a
/// distance and a time) where the planner takes one, `side` without `side_of`, `from` or an
/// explicit lane number beside `same_as`.
fn check_combination(ctx: &Eval<'_>, name: &str, args: &[(String, &Expr)]) -> Result<(), Error> {
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
    Ok(())
}

/// The parameters of the modifier `name` in declaration order (positional arguments bind to
/// them in that order).
pub(crate) fn params(ctx: &Eval<'_>, name: &str) -> Vec<String> {
    ctx.model
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
        .unwrap_or_default()
}
