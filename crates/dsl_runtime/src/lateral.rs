//! The `lateral(distance, measure_by, side)` modifier (ASAM OpenSCENARIO DSL 2.1 §8.9
//! movement modifiers, `lateral`: "an actor's lateral position (t-coordinate) relative to the
//! road or another actor") as an offset from the centre of the actor's lane.
//!
//! Without a reference object the distance is measured from a line of the actor's lane to a
//! line of the actor, both named by `measure_by` (`lat_measure_by`, actor first, lane second):
//! the actor's `left` side, `center` or `right` side, the lane's `left` border, centre or
//! `right` border. From a border the distance is counted into the lane (the standard's
//! example: "1.5 m measured from the right side of the vehicle to the lane edge on the right");
//! from the lane's centre it is counted to `side` (left or right, required there). With t to
//! the left and the actor's offset o from the lane centre:
//!
//! o + a = r + σ·d, where a = +w/2, 0, −w/2 (actor left, centre, right; w its width),
//! r = +W/2, 0, −W/2 (lane left border, centre, right border; W the lane's width) and σ = −1
//! from the left border, +1 from the right one, ±1 for `side` from the centre.
//!
//! The reference point must stay in the lane (|o| ≤ W/2), else the constraint is unsatisfiable.
//! `closest` (the library's default) needs a second object to be defined and `distance_range`
//! is not declared by the library: both are errors, as are the forms relative to another
//! actor (`side_of`, `left_of`, `right_of`, `same_as`), which are not planned yet.

use crate::error::{Error, ErrorKind as K};
use crate::modifier::Mod;
use crate::value::{Ctx, Val};

/// The offset from the lane centre (m, + left) that `m` asks for in a lane `lane_width` wide,
/// for an actor `width` wide.
pub(crate) fn lane_offset(
    ctx: &Ctx<'_>,
    m: &Mod<'_>,
    lane_width: f64,
    width: f64,
) -> Result<f64, Error> {
    for key in ["side_of", "left_of", "right_of", "same_as"] {
        if let Some(e) = m.arg(key) {
            return Err(ctx.files.err(
                K::Unsupported,
                e.span,
                format!("expected lateral(…) relative to the actor's lane, found `{key}:` (lateral distances to another actor are not planned yet)"),
            ));
        }
    }
    let d = match m.arg("distance") {
        Some(e) => ctx.number(e)?,
        None => {
            return Err(ctx.files.err(
                K::Modifier,
                m.app.span,
                "expected a distance in lateral(…), found none",
            ))
        }
    };
    let measure = match m.arg("measure_by").map(|e| ctx.eval(e)).transpose()? {
        Some(Val::Enum(v)) => v,
        _ => "closest".to_string(),
    };
    let Some((actor, lane)) = measure.split_once("_to_") else {
        return Err(ctx.files.err(
            K::Unsupported,
            m.app.span,
            format!("expected measure_by naming a side of the actor and a line of its lane (left_to_left, right_to_right, center_to_center …), found {measure} (it needs a reference object)"),
        ));
    };
    let a = match actor {
        "left" => width / 2.0,
        "right" => -width / 2.0,
        _ => 0.0,
    };
    let (r, sigma) = match lane {
        "left" => (lane_width / 2.0, -1.0),
        "right" => (-lane_width / 2.0, 1.0),
        _ => match m.arg("side").map(|e| ctx.eval(e)).transpose()? {
            Some(Val::Enum(s)) if s == "left" => (0.0, 1.0),
            Some(Val::Enum(s)) if s == "right" => (0.0, -1.0),
            _ => {
                return Err(ctx.files.err(
                    K::Modifier,
                    m.app.span,
                    format!("expected side: left or right in lateral(…, measure_by: {measure}) (which side of the lane's centre), found none"),
                ))
            }
        },
    };
    let o = r + sigma * d - a;
    if o.abs() > lane_width / 2.0 + 1e-9 {
        return Err(ctx.files.err(
            K::Unsatisfiable,
            m.app.span,
            format!("expected the actor's reference point in its lane ({lane_width:.2} m wide), found lateral(…) puts it {o:.2} m from the lane's centre"),
        ));
    }
    Ok(o)
}
