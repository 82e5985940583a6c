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
//! `closest` (the library's default; §8.9.22 "closest lateral distance between object and
//! physical_object") measures from the lane's border nearest to the actor to the actor's side
//! facing it, so d ≤ (W − w)/2 (d = (W − w)/2 centres the actor); `side` names that border (o =
//! ±((W − w)/2 − d)), required unless d centres the actor. `distance_range` is not declared by
//! the library (an error).
//!
//! Relative to another actor x (`side_of: x, side: …`, `left_of: x`, `right_of: x`) the
//! distance is measured in t from a line of x to a line of the actor, the actor on the given
//! side: t_a + a = t_x + r + σ·d, with a and r the actor's and x's side terms (±w/2, 0) as
//! above and σ = +1 on the left of x, −1 on its right. `closest` is then the gap between the
//! facing sides (the actor's right side and x's left side when it is on x's left). The actor's
//! lane is the one it is placed in by `lane(…)`, or else the driving lane containing t_a. This
//! form places the actor at the start of the run (its first phase); `at: all` then keeps it
//! beside x while x moves sideways (`lateral_follow`). At the start of a later phase it is
//! checked (against the plan's tracks at a known start, by the engine after a run-time one);
//! `at: end` is a lateral target where the plan has x at the phase end (`lateral_end`).
//! `same_as` (the same t) is an error: two vehicles cannot share it.

use crate::error::{Error, ErrorKind as K};
use crate::resolve::{Modifier, Val};

/// [`lane_offset`] as k·W + c in the lane's width W, (k, c): each form's lane term is 0 or
/// ±W/2 (a border), so the offset is affine in W; read from the offsets at `lane_width` and
/// 1 m wider. A lane 1 m wider makes every form of `lane_offset` that holds at `lane_width`
/// hold but `closest` without a side at the d that centres the actor, which centres it in
/// any width (k = 0, c = 0).
pub(crate) fn offset_in_width(
    m: &Modifier,
    lane_width: f64,
    width: f64,
) -> Result<(f64, f64), Error> {
    let o = lane_offset(m, lane_width, width)?;
    let k = lane_offset(m, lane_width + 1.0, width).map_or(0.0, |wider| wider - o);
    Ok((k, o - k * lane_width))
}

/// The offset from the lane centre (m, + left) that `m` asks for in a lane `lane_width` wide,
/// for an actor `width` wide.
pub(crate) fn lane_offset(m: &Modifier, lane_width: f64, width: f64) -> Result<f64, Error> {
    for key in ["side_of", "left_of", "right_of", "same_as"] {
        if let Some(e) = m.arg(key) {
            // Every caller plans a reference first (`beside`, `lateral_end`, `lateral_follow`,
            // `shape_relative`): here it would be no offset in the lane.
            return Err(e.site.err(
                K::Modifier,
                format!("expected lateral(…) relative to the actor's lane here, found `{key}:` (a lateral position beside another actor is planned from where the plan has that actor)"),
            ));
        }
    }
    let (d, measure) = distance_and_measure(m)?;
    if measure == "closest" {
        return closest_to_border(m, d, lane_width, width);
    }
    let Some((actor, lane)) = measure.split_once("_to_") else {
        return Err(m.site.err(
            K::Modifier,
            format!("expected measure_by naming a side of the actor and a line of its lane (left_to_left, right_to_right, center_to_center …), found {measure}"),
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
        _ => match m.arg("side").map(|e| e.eval()).transpose()? {
            Some(Val::Enum(s)) if s == "left" => (0.0, 1.0),
            Some(Val::Enum(s)) if s == "right" => (0.0, -1.0),
            _ => {
                return Err(m.site.err(
                    K::Modifier,
                    format!("expected side: left or right in lateral(…, measure_by: {measure}) (which side of the lane's centre), found none"),
                ))
            }
        },
    };
    let o = r + sigma * d - a;
    if o.abs() > lane_width / 2.0 + 1e-9 {
        return Err(m.site.err(
            K::Unsatisfiable,
            format!("expected the actor's reference point in its lane ({lane_width:.2} m wide), found lateral(…) puts it {o:.2} m from the lane's centre"),
        ));
    }
    Ok(o)
}

/// The offset of `lateral(d, measure_by: closest, side: …)` without a reference: the closest
/// lateral distance between the actor and its lane's borders is d, from the border on `side`
/// (module doc). Without `side` the actor may be either side of the centre, unless d puts it
/// on the centre; d larger than that is no closest distance (the actor would be nearer the
/// other border).
fn closest_to_border(m: &Modifier, d: f64, lane_width: f64, width: f64) -> Result<f64, Error> {
    // The gap to each border when the actor is centred.
    let centred = (lane_width - width) / 2.0;
    if d < 0.0 {
        return Err(m.site.err(
            K::Value,
            format!("expected a closest distance of 0 m or more in lateral(…, measure_by: closest), found {d} m"),
        ));
    }
    if d > centred + 1e-9 {
        return Err(m.site.err(
            K::Unsatisfiable,
            format!("expected a closest distance of at most {centred:.2} m to a border of the {lane_width:.2} m lane for an actor {width:.2} m wide (centred), found {d} m"),
        ));
    }
    match m.arg("side").map(|e| e.eval()).transpose()? {
        Some(Val::Enum(s)) if s == "left" => Ok(centred - d),
        Some(Val::Enum(s)) if s == "right" => Ok(d - centred),
        _ if (centred - d).abs() <= 1e-9 => Ok(0.0),
        _ => Err(m.site.err(
            K::Modifier,
            format!("expected side: left or right in lateral({d} m, measure_by: closest) without a reference object (which border of the lane the actor is closest to), found none"),
        )),
    }
}

/// The reference actor of a `lateral(…)` and the side the actor is on (+1 left, −1 right), if
/// it has one.
pub(crate) fn reference(m: &Modifier) -> Result<Option<(&crate::resolve::Arg, f64)>, Error> {
    if let Some(e) = m.arg("same_as") {
        return Err(e.site.err(
            K::Unsatisfiable,
            "expected lateral(…) beside another actor (side_of, left_of, right_of), found same_as: (two vehicles cannot share a lateral position)",
        ));
    }
    if let Some(e) = m.arg("left_of") {
        return Ok(Some((e, 1.0)));
    }
    if let Some(e) = m.arg("right_of") {
        return Ok(Some((e, -1.0)));
    }
    let Some(e) = m.arg("side_of") else {
        return Ok(None);
    };
    match m.arg("side").map(|x| x.eval()).transpose()? {
        Some(Val::Enum(s)) if s == "left" => Ok(Some((e, 1.0))),
        Some(Val::Enum(s)) if s == "right" => Ok(Some((e, -1.0))),
        _ => Err(m.site.err(
            K::Modifier,
            "expected side: left or right with side_of: in lateral(…), found none",
        )),
    }
}

/// t of the actor's reference line (its centre) for a `lateral(…)` relative to an actor whose
/// centre is at t `t_x` and whose width is `w_x`: t_a = t_x + r + σ·d − a (module doc).
pub(crate) fn beside(
    m: &Modifier,
    sigma: f64,
    (t_x, w_x): (f64, f64),
    width: f64,
) -> Result<f64, Error> {
    let (d, measure) = distance_and_measure(m)?;
    let (actor, other) = match measure.split_once("_to_") {
        Some(pair) => pair,
        // The facing sides.
        None if sigma > 0.0 => ("right", "left"),
        None => ("left", "right"),
    };
    let side = |which: &str, w: f64| match which {
        "left" => w / 2.0,
        "right" => -w / 2.0,
        _ => 0.0,
    };
    Ok(t_x + side(other, w_x) + sigma * d - side(actor, width))
}

/// The `distance` and `measure_by` (default `closest`) of a `lateral(…)`.
fn distance_and_measure(m: &Modifier) -> Result<(f64, String), Error> {
    let d = match m.arg("distance") {
        Some(e) => e.number()?,
        None => {
            return Err(m
                .site
                .err(K::Modifier, "expected a distance in lateral(…), found none"))
        }
    };
    let measure = match m.arg("measure_by").map(|e| e.eval()).transpose()? {
        Some(Val::Enum(v)) => v,
        _ => "closest".to_string(),
    };
    Ok((d, measure))
}
