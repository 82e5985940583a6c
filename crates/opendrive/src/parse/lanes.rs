//! Reads `<lanes>` (OpenDRIVE 1.8 §11, XSD `t_road_lanes`): lane sections with left, centre
//! and right lanes, widths, borders, heights, speeds and lane links.

use roxmltree::Node;

use super::reader::{child, children, missing, read_cubics, read_nested, Reader};
use crate::error::Error;
use crate::model::{
    Lane, LaneHeight, LaneSection, LaneType, RoadMark, RoadMarkColor, RoadMarkLaneChange,
    RoadMarkLine, RoadMarkType,
};

/// All `<laneSection>`s of a road of `road_length` metres, sorted by s.
pub(crate) fn read_lanes(
    r: &Reader,
    lanes: Node,
    road_length: f64,
) -> Result<Vec<LaneSection>, Error> {
    let mut sections = Vec::new();
    for ls in children(lanes, "laneSection") {
        sections.push(read_section(r, ls, road_length)?);
    }
    if sections.is_empty() {
        return Err(missing(r, lanes, "laneSection"));
    }
    sections.sort_by(|a, b| a.s.total_cmp(&b.s));
    Ok(sections)
}

/// XSD `t_road_lanes_laneSection`.
fn read_section(r: &Reader, node: Node, road_length: f64) -> Result<LaneSection, Error> {
    let s = r.req_s_within(node, road_length, "a laneSection start")?;
    let center_node = child(node, "center").ok_or_else(|| missing(r, node, "center"))?;
    let center_lane = child(center_node, "lane").ok_or_else(|| missing(r, center_node, "lane"))?;
    let center = read_lane(r, center_lane)?;
    let mut left = read_nested(node, "left", "lane", |l| read_lane(r, l))?;
    let mut right = read_nested(node, "right", "lane", |l| read_lane(r, l))?;
    left.sort_by_key(|l| l.id);
    right.sort_by_key(|l| -l.id);
    check_ids(r, node, &left, 1)?;
    check_ids(r, node, &right, -1)?;
    Ok(LaneSection {
        s,
        single_side: r.opt_bool(node, "singleSide", false)?,
        left,
        center,
        right,
    })
}

/// Lane ids on a side must be 1, 2, 3, … (or −1, −2, …) without gaps (§11).
fn check_ids(r: &Reader, section: Node, lanes: &[Lane], sign: i32) -> Result<(), Error> {
    for (k, lane) in lanes.iter().enumerate() {
        let expected = sign * (k as i32 + 1);
        if lane.id != expected {
            let side = if sign > 0 { "left" } else { "right" };
            let node = children(section, side)
                .flat_map(|n| children(n, "lane"))
                .find(|n| {
                    n.attribute("id").and_then(|v| v.trim().parse::<i32>().ok()) == Some(lane.id)
                })
                .unwrap_or(section);
            return Err(r.invalid(
                node,
                "id",
                &format!("consecutive lane ids, next {expected}"),
                &lane.id.to_string(),
            ));
        }
    }
    Ok(())
}

/// XSD `t_road_lanes_laneSection_lr_lane` / `_center_lane`.
fn read_lane(r: &Reader, node: Node) -> Result<Lane, Error> {
    let id = r.req_i32(node, "id")?;
    let lane_type = LaneType::parse(node.attribute("type").unwrap_or("none"));
    let (mut predecessor, mut successor) = (None, None);
    if let Some(link) = child(node, "link") {
        if let Some(p) = child(link, "predecessor") {
            predecessor = Some(r.req_i32(p, "id")?);
        }
        if let Some(s) = child(link, "successor") {
            successor = Some(r.req_i32(s, "id")?);
        }
    }
    let mut heights = Vec::new();
    for h in children(node, "height") {
        heights.push(LaneHeight {
            s_offset: r.req_non_negative(h, "sOffset")?,
            inner: r.opt_f64(h, "inner", 0.0)?,
            outer: r.opt_f64(h, "outer", 0.0)?,
        });
    }
    heights.sort_by(|a, b| a.s_offset.total_cmp(&b.s_offset));
    let speed_limit = match child(node, "speed") {
        Some(sp) => {
            let factor = match sp.attribute("unit").unwrap_or("m/s") {
                "km/h" => 1.0 / 3.6,
                "mph" => 0.447_04,
                _ => 1.0,
            };
            Some(r.req_f64(sp, "max")? * factor)
        }
        None => None,
    };
    Ok(Lane {
        id,
        lane_type,
        level: r.opt_bool(node, "level", false)?,
        predecessor,
        successor,
        widths: read_cubics(r, node, "width", "sOffset")?,
        borders: read_cubics(r, node, "border", "sOffset")?,
        heights,
        speed_limit,
        road_marks: read_road_marks(r, node)?,
    })
}

/// The `<roadMark>`s of a lane (OpenDRIVE 1.8 §11.8), sorted by `sOffset`; the `<line>`s of
/// a `<type>` child give the dash pattern.
fn read_road_marks(r: &Reader, lane: Node) -> Result<Vec<RoadMark>, Error> {
    let mut marks = Vec::new();
    for m in children(lane, "roadMark") {
        let mut lines = Vec::new();
        for line in children(m, "type").flat_map(|t| children(t, "line")) {
            lines.push(RoadMarkLine {
                length: r.opt_non_negative(line, "length", 0.0)?,
                space: r.opt_non_negative(line, "space", 0.0)?,
                t_offset: r.opt_f64(line, "tOffset", 0.0)?,
                s_offset: r.opt_non_negative(line, "sOffset", 0.0)?,
                width: r.maybe_f64(line, "width")?,
            });
        }
        let lane_change = match m.attribute("laneChange") {
            None => None,
            Some(text) => Some(RoadMarkLaneChange::parse(text).ok_or_else(|| {
                r.invalid(m, "laneChange", "increase, decrease, both or none", text)
            })?),
        };
        marks.push(RoadMark {
            s_offset: r.req_non_negative(m, "sOffset")?,
            mark_type: RoadMarkType::parse(m.attribute("type").unwrap_or("none")),
            bold: m.attribute("weight") == Some("bold"),
            color: RoadMarkColor::parse(m.attribute("color").unwrap_or("standard")),
            width: r.maybe_f64(m, "width")?,
            lines,
            lane_change,
        });
    }
    marks.sort_by(|a, b| a.s_offset.total_cmp(&b.s_offset));
    Ok(marks)
}
