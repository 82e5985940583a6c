//! Reads `<lanes>` (OpenDRIVE 1.8 §11, XSD `t_road_lanes`): lane sections with left, centre
//! and right lanes, widths, borders, heights, speeds and lane links.

use roxmltree::Node;

use super::reader::{child, children, read_nested, Reader};
use super::road::{missing, read_cubics};
use crate::error::Error;
use crate::model::{Lane, LaneHeight, LaneSection, LaneType};

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
    })
}
