//! A path as the route of `along(…)` (ASAM OpenSCENARIO DSL 2.1 §8.9 `along`: "the actor
//! moves along the route"; §8.12 `path inherits route`, "a polyline of points", made by the
//! map's `create_path(points, interpolation)`, `create_path_odr_points(…)` or
//! `create_path_route_points(…)` (their points placed on the network by the plan stage,
//! `crate::plan`'s `road_path`), or `resolve_relative_path(relative_path, reference,
//! transform)`, follow_path's `relative:` with that reference and transform):
//! `drive()`, `move()` or `walk()` with
//! `along(p)` follows p's line as `follow_path(absolute: p)` does (§8.8.2.16), the
//! FollowTrajectoryAction along the path at the speed the phase gives, in following mode
//! `follow` (steered within the vehicle's limits), the phase ending where the path does
//! (`crate::plan`'s trajectory actions). `along`'s `start_offset` and `end_offset` are
//! follow_path's: the part of the path followed.
//!
//! oscsim's choices where the standard is silent: a path is followed throughout (`at: all`,
//! the default), as the route decides where the actor is at each moment; `at: start` or
//! `at: end` (which would only say where it is then, a path having no lanes to be "on") and
//! another action along a path (a lane change or a speed action, whose own motion is not
//! the path's) are errors at the `along`, and so is a second `along(…)` beside it (two
//! routes at once).

use super::action::Action;
use super::modifier::{At, ModKind, Modifier};
use super::position::{Place, PlaceArg};
use super::value::Args;
use crate::error::{Error, ErrorKind as K};

/// The action an invocation of `kind` with `modifiers` runs when one of them is `along(…)` of
/// a path: `follow_path`, the path pushed on `places` as its `absolute:` and along's offsets
/// on `args`, the `along` taken out of `modifiers`; else `kind`, nothing changed.
pub(super) fn follow(
    kind: Action,
    places: &mut Vec<PlaceArg>,
    args: &mut Args,
    modifiers: &mut Vec<Modifier>,
) -> Result<Action, Error> {
    let Some(i) = modifiers.iter().position(|m| m.path.is_some()) else {
        return Ok(kind);
    };
    let m = modifiers.remove(i);
    let wrong = |what: &str| {
        m.site.err(
            K::Modifier,
            format!("expected drive(), move() or walk() with along(…) of a path at: all (the actor follows the path's line throughout, as follow_path does), found {what}"),
        )
    };
    if kind != Action::Move {
        return Err(wrong("another action (its own motion is not the path's)"));
    }
    if m.at != At::All {
        return Err(wrong(
            "at: start or end (a path has no lanes to be on at one moment)",
        ));
    }
    if let Some(other) = modifiers.iter().find(|o| o.kind == ModKind::Along) {
        return Err(other.site.err(
            K::Modifier,
            format!(
                "expected one route beside along(…) of a path at {}, found another along(…)",
                m.site.at()
            ),
        ));
    }
    for name in ["start_offset", "end_offset"] {
        if let Some(a) = m.arg(name) {
            args.push((name.to_string(), a.clone()));
        }
    }
    if let Some((place, placing)) = m.path {
        // A relative path is follow_path's `relative:`, placed by its reference and transform.
        let param = match place {
            Place::Relative { .. } => "relative",
            _ => "absolute",
        };
        args.extend(placing);
        places.push(PlaceArg {
            param: param.to_string(),
            place,
            site: m.site,
        });
    }
    Ok(Action::FollowPath)
}
