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
    /// `keep_lane()`, `keep_speed()`, `along(…)`, `physical_movement(…)`,
    /// `avoid_collisions(…)`: what the engine's default motion already does.
    Kept,
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
        "keep_lane" | "keep_speed" | "along" | "physical_movement" | "avoid_collisions" => {
            ModKind::Kept
        }
        other => {
            return Err(ctx.files.err(
                K::Modifier,
                app.span,
                format!(
                    "expected a modifier the runtime plans (speed, change_speed, acceleration, position, lane, change_lane, keep_lane, keep_speed, along), found `{other}`"
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
    Ok(Mod {
        kind,
        at,
        args,
        app,
    })
}
