//! Reads `<road>` (OpenDRIVE 1.8 §10, XSD `t_road`): attributes, `<link>`, `<type>`/`<speed>`,
//! `<planView>` (§9, `t_road_planView_geometry`), `<elevationProfile>`, `<lateralProfile>`
//! superelevation, and hands `<lanes>`, `<objects>`, `<signals>` to their readers.

use roxmltree::Node;

use super::lanes::read_lanes;
use super::reader::{child, children, missing, read_cubics, read_nested, Reader};
use crate::error::{Error, ErrorKind};
use crate::geometry::{
    Arc, Geometry, GeometryKind, ParamPoly3, ParamRange, PlanView, Poly3, Spiral,
};
use crate::math::GEOMETRY_GAP_TOLERANCE;
use crate::model::{
    ContactPoint, Corner, ElementType, Object, Road, RoadLink, RoadLinks, RoadType, Signal, Speed,
    TrafficRule,
};

/// XSD `t_road`; tolerated problems (plan-view gaps) go to `warnings`.
pub(crate) fn read_road(r: &Reader, node: Node, warnings: &mut Vec<Error>) -> Result<Road, Error> {
    let id = r.req_str(node, "id")?.to_string();
    let length = r.req_positive(node, "length")?;
    let junction = match node.attribute("junction").map(str::trim) {
        None | Some("-1") | Some("") => None,
        Some(j) => Some(j.to_string()),
    };
    let rule = match node.attribute("rule") {
        None | Some("RHT") => TrafficRule::RightHand,
        Some("LHT") => TrafficRule::LeftHand,
        Some(other) => return Err(r.invalid(node, "rule", "RHT or LHT", other)),
    };
    let links = match child(node, "link") {
        Some(l) => RoadLinks {
            predecessor: child(l, "predecessor")
                .map(|p| read_link(r, p))
                .transpose()?,
            successor: child(l, "successor").map(|p| read_link(r, p)).transpose()?,
        },
        None => RoadLinks::default(),
    };
    let mut types = Vec::new();
    for t in children(node, "type") {
        types.push(read_type(r, t)?);
    }
    types.sort_by(|a, b| a.s.total_cmp(&b.s));
    let plan_view = match child(node, "planView") {
        Some(pv) => read_plan_view(r, pv, length, warnings)?,
        None => return Err(missing(r, node, "planView")),
    };
    let elevation = match child(node, "elevationProfile") {
        Some(e) => read_cubics(r, e, "elevation", "s")?,
        None => Vec::new(),
    };
    let superelevation = match child(node, "lateralProfile") {
        Some(e) => read_cubics(r, e, "superelevation", "s")?,
        None => Vec::new(),
    };
    let lanes = child(node, "lanes").ok_or_else(|| missing(r, node, "lanes"))?;
    let lane_offsets = read_cubics(r, lanes, "laneOffset", "s")?;
    let lane_sections = read_lanes(r, lanes, length)?;
    let objects = read_nested(node, "objects", "object", |o| read_object(r, o))?;
    let signals = read_nested(node, "signals", "signal", |s| read_signal(r, s))?;
    Ok(Road {
        id,
        name: node.attribute("name").unwrap_or_default().to_string(),
        length,
        junction,
        rule,
        links,
        types,
        plan_view,
        elevation,
        superelevation,
        lane_offsets,
        lane_sections,
        objects,
        signals,
    })
}

/// `contactPoint` values.
pub(crate) fn read_contact_point(
    r: &Reader,
    node: Node,
    name: &str,
) -> Result<Option<ContactPoint>, Error> {
    match node.attribute(name) {
        None => Ok(None),
        Some("start") => Ok(Some(ContactPoint::Start)),
        Some("end") => Ok(Some(ContactPoint::End)),
        Some(other) => Err(r.invalid(node, name, "start or end", other)),
    }
}

/// XSD `t_road_link_predecessorSuccessor`.
fn read_link(r: &Reader, node: Node) -> Result<RoadLink, Error> {
    let element_type = match r.req_str(node, "elementType")? {
        "road" => ElementType::Road,
        "junction" => ElementType::Junction,
        other => return Err(r.invalid(node, "elementType", "road or junction", other)),
    };
    Ok(RoadLink {
        element_type,
        element_id: r.req_str(node, "elementId")?.to_string(),
        contact_point: read_contact_point(r, node, "contactPoint")?,
    })
}

/// XSD `t_road_type` with `t_road_type_speed`.
fn read_type(r: &Reader, node: Node) -> Result<RoadType, Error> {
    let speed = match child(node, "speed") {
        Some(sp) => {
            let max_text = r.req_str(sp, "max")?;
            let max = match max_text {
                "no limit" | "undefined" => f64::INFINITY,
                _ => r.req_f64(sp, "max")?,
            };
            let factor = match sp.attribute("unit").unwrap_or("m/s") {
                "m/s" => 1.0,
                "km/h" => 1.0 / 3.6,
                "mph" => 0.447_04,
                other => return Err(r.invalid(sp, "unit", "m/s, km/h or mph", other)),
            };
            Some(Speed { max: max * factor })
        }
        None => None,
    };
    Ok(RoadType {
        s: r.req_non_negative(node, "s")?,
        road_type: r.req_str(node, "type")?.to_string(),
        speed,
    })
}

/// XSD `t_road_planView`: at least one `<geometry>`, sorted by s. A geometry starting more
/// than [`GEOMETRY_GAP_TOLERANCE`] from where the previous one ends is a warning (OpenDRIVE
/// 1.8 §9.2: the reference line is continuous; each geometry is still placed by its own x, y).
fn read_plan_view(
    r: &Reader,
    node: Node,
    road_length: f64,
    warnings: &mut Vec<Error>,
) -> Result<PlanView, Error> {
    let mut geometries = Vec::new();
    for g in children(node, "geometry") {
        geometries.push((read_geometry(r, g, road_length)?, g));
    }
    if geometries.is_empty() {
        return Err(missing(r, node, "geometry"));
    }
    geometries.sort_by(|a, b| a.0.s.total_cmp(&b.0.s));
    for pair in geometries.windows(2) {
        let ((prev, _), (next, next_node)) = (&pair[0], &pair[1]);
        let end = prev.eval(next.s);
        let gap = (end.x - next.x).hypot(end.y - next.y);
        if gap > GEOMETRY_GAP_TOLERANCE {
            warnings.push(r.error_at(
                *next_node,
                ErrorKind::Inconsistent {
                    element: "geometry".into(),
                    expected: format!(
                        "a start within {GEOMETRY_GAP_TOLERANCE} m of the previous geometry's end"
                    ),
                    found: format!("a gap of {gap:.4} m"),
                },
            ));
        }
    }
    Ok(PlanView::new(
        geometries.into_iter().map(|(g, _)| g).collect(),
    ))
}

/// XSD `t_road_planView_geometry` and its curve element.
fn read_geometry(r: &Reader, node: Node, road_length: f64) -> Result<Geometry, Error> {
    let s = r.req_s_within(node, road_length, "a geometry start")?;
    let x = r.req_f64(node, "x")?;
    let y = r.req_f64(node, "y")?;
    let hdg = r.req_f64(node, "hdg")?;
    let length = r.req_positive(node, "length")?;
    let curve = node.children().find(|c| c.is_element()).ok_or_else(|| {
        r.error_at(
            node,
            ErrorKind::MissingElement {
                element: "geometry".into(),
                child: "line, arc, spiral, poly3 or paramPoly3".into(),
            },
        )
    })?;
    let kind = match curve.tag_name().name() {
        "line" => GeometryKind::Line,
        "arc" => GeometryKind::Arc(Arc {
            curvature: r.req_f64(curve, "curvature")?,
        }),
        "spiral" => GeometryKind::Spiral(Spiral::new(
            r.req_f64(curve, "curvStart")?,
            r.req_f64(curve, "curvEnd")?,
            length,
        )),
        "poly3" => GeometryKind::Poly3(Poly3::new(
            r.req_f64(curve, "a")?,
            r.req_f64(curve, "b")?,
            r.req_f64(curve, "c")?,
            r.req_f64(curve, "d")?,
            length,
        )),
        "paramPoly3" => {
            let range = match curve.attribute("pRange").unwrap_or("normalized") {
                "arcLength" => ParamRange::ArcLength,
                "normalized" => ParamRange::Normalized,
                other => return Err(r.invalid(curve, "pRange", "arcLength or normalized", other)),
            };
            let mut u = [0.0; 4];
            let mut v = [0.0; 4];
            for (i, (ku, kv)) in [("aU", "aV"), ("bU", "bV"), ("cU", "cV"), ("dU", "dV")]
                .into_iter()
                .enumerate()
            {
                u[i] = r.req_f64(curve, ku)?;
                v[i] = r.req_f64(curve, kv)?;
            }
            GeometryKind::ParamPoly3(ParamPoly3::new(u, v, range, length))
        }
        other => {
            return Err(r.error_at(
                curve,
                ErrorKind::InvalidValue {
                    element: "geometry".into(),
                    attribute: "(child element)".into(),
                    expected: "line, arc, spiral, poly3 or paramPoly3".into(),
                    found: other.to_string(),
                },
            ))
        }
    };
    Ok(Geometry::new(s, x, y, hdg, length, kind))
}

/// XSD `t_road_objects_object`.
fn read_object(r: &Reader, node: Node) -> Result<Object, Error> {
    Ok(Object {
        id: r.req_str(node, "id")?.to_string(),
        name: node.attribute("name").unwrap_or_default().to_string(),
        object_type: node.attribute("type").unwrap_or_default().to_string(),
        s: r.req_f64(node, "s")?,
        t: r.req_f64(node, "t")?,
        z_offset: r.opt_f64(node, "zOffset", 0.0)?,
        hdg: r.opt_f64(node, "hdg", 0.0)?,
        pitch: r.opt_f64(node, "pitch", 0.0)?,
        roll: r.opt_f64(node, "roll", 0.0)?,
        length: r.maybe_f64(node, "length")?,
        width: r.maybe_f64(node, "width")?,
        height: r.maybe_f64(node, "height")?,
        radius: r.maybe_f64(node, "radius")?,
        orientation: node.attribute("orientation").unwrap_or("none").to_string(),
        outlines: read_nested(node, "outlines", "outline", |o| read_outline(r, o))?
            .into_iter()
            .chain(
                children(node, "outline")
                    .map(|o| read_outline(r, o))
                    .collect::<Result<Vec<_>, Error>>()?,
            )
            .collect(),
    })
}

/// XSD `t_road_objects_object_outlines_outline`: its `cornerRoad` or `cornerLocal` corners, in
/// order.
fn read_outline(r: &Reader, node: Node) -> Result<Vec<Corner>, Error> {
    node.children()
        .filter(|c| c.is_element())
        .filter_map(|c| match c.tag_name().name() {
            "cornerRoad" => Some(r.req_f64(c, "s").and_then(|s| {
                Ok(Corner::Road {
                    s,
                    t: r.req_f64(c, "t")?,
                })
            })),
            "cornerLocal" => Some(r.req_f64(c, "u").and_then(|u| {
                Ok(Corner::Local {
                    u,
                    v: r.req_f64(c, "v")?,
                })
            })),
            _ => None,
        })
        .collect()
}

/// XSD `t_road_signals_signal`.
fn read_signal(r: &Reader, node: Node) -> Result<Signal, Error> {
    let text = |name: &str| node.attribute(name).unwrap_or_default().to_string();
    Ok(Signal {
        id: r.req_str(node, "id")?.to_string(),
        name: text("name"),
        s: r.req_f64(node, "s")?,
        t: r.req_f64(node, "t")?,
        z_offset: r.opt_f64(node, "zOffset", 0.0)?,
        orientation: node.attribute("orientation").unwrap_or("none").to_string(),
        dynamic: r.opt_bool(node, "dynamic", false)?,
        country: text("country"),
        signal_type: text("type"),
        subtype: text("subtype"),
        value: r.maybe_f64(node, "value")?,
        unit: text("unit"),
        h_offset: r.opt_f64(node, "hOffset", 0.0)?,
        pitch: r.opt_f64(node, "pitch", 0.0)?,
        roll: r.opt_f64(node, "roll", 0.0)?,
        width: r.maybe_f64(node, "width")?,
        height: r.maybe_f64(node, "height")?,
        length: r.maybe_f64(node, "length")?,
        validity: children(node, "validity")
            .map(|v| Ok((r.req_i32(v, "fromLane")?, r.req_i32(v, "toLane")?)))
            .collect::<Result<_, Error>>()?,
    })
}
