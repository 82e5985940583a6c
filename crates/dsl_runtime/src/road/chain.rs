//! The roads of a plan, one after another (ASAM OpenDRIVE 1.8 §10.3 road linkage, §11.5 lane
//! linkage, §12 junction connections): from a start road, each road's successor as the engine's
//! default controller drives onto it without a route (the first lane link in the road model's
//! order, `opendrive::RoadNetwork::successors`), for as long as the driving lanes run on
//! unchanged.
//!
//! A road continues onto the next when every driving lane of its right side (right-hand
//! traffic: lanes running in +s) at its end that has a successor leads, by its first lane
//! link, onto one and the same road, entered at its start, in a lane of the same id. That keeps
//! the plan's lane ids the engine's on every road of the chain. The chain stops where a lane
//! is renumbered (a link `-3` → `-4`), where lanes part at a junction (each lane's first
//! connection onto another road), where the next road is entered against its s (contact point
//! `end`), at a road already in the chain (a loop), and after [`MAX_ROADS`] roads. The
//! standard leaves the choice at a junction to the routing; the first connection is the one
//! the engine takes, so the plan and the run agree.

use opendrive::{LaneHandle, Road, RoadNetwork};

/// The most roads a chain holds.
pub(crate) const MAX_ROADS: usize = 64;

/// Driving lanes of the right side of a lane section, in file order.
pub(crate) fn right_driving(section: &opendrive::LaneSection) -> impl Iterator<Item = i32> + '_ {
    section
        .right
        .iter()
        .filter(|l| l.lane_type.is_drivable())
        .map(|l| l.id)
}

/// Whether `road` has a driving lane on the right side of its first lane section.
pub(crate) fn drivable(road: &Road) -> bool {
    road.lane_sections
        .first()
        .is_some_and(|ls| right_driving(ls).next().is_some())
}

/// The roads from `start` on (`start` first), as indices into `net.roads()`.
pub(crate) fn chain(net: &RoadNetwork, start: usize) -> Vec<usize> {
    let mut out = vec![start];
    while out.len() < MAX_ROADS {
        // `out` is never empty: it starts with `start`.
        let last = out[out.len() - 1];
        match next(net, last) {
            Some(n) if !out.contains(&n) && drivable(&net.roads()[n]) => out.push(n),
            _ => break,
        }
    }
    out
}

/// The road after road `ri` (see the module doc), if the lanes run on unchanged.
fn next(net: &RoadNetwork, ri: usize) -> Option<usize> {
    let road = &net.roads()[ri];
    let k = road.lane_sections.len().checked_sub(1)?;
    let mut found = None;
    for lane in right_driving(&road.lane_sections[k]) {
        let h = LaneHandle {
            road: ri as u32,
            section: k as u32,
            lane,
        };
        let Some(n) = net.successors(h).first().copied() else {
            continue;
        };
        if n.lane != lane || n.section != 0 {
            return None;
        }
        match found {
            None => found = Some(n.road as usize),
            Some(r) if r != n.road as usize => return None,
            Some(_) => {}
        }
    }
    found
}

/// Whether the driving lanes of road `after`'s left side (right-hand traffic: driven in −s)
/// at its start run on, by their first lane link, onto road `before` at its end in lanes of
/// the same ids: the roads of a chain driven against s. Else what is found, as the rest of a
/// sentence "expected …, found …".
pub(crate) fn runs_back(net: &RoadNetwork, after: usize, before: usize) -> Result<(), String> {
    let road = &net.roads()[after];
    let Some(first) = road.lane_sections.first() else {
        return Ok(());
    };
    let last = net.roads()[before].lane_sections.len().saturating_sub(1);
    for lane in first
        .left
        .iter()
        .filter(|l| l.lane_type.is_drivable())
        .map(|l| l.id)
    {
        let h = LaneHandle {
            road: after as u32,
            section: 0,
            lane,
        };
        let Some(n) = net.successors(h).first().copied() else {
            continue;
        };
        let to = &net.roads()[n.road as usize].id;
        if n.road as usize != before || n.lane != lane || n.section as usize != last {
            return Err(format!(
                "lane {lane} of road {} leading onto lane {} of road {to}",
                road.id, n.lane
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ids(file: &str, start: &str) -> Vec<String> {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/roads")
            .join(file);
        let net = RoadNetwork::from_file(&path).expect("reads");
        let i = net
            .roads()
            .iter()
            .position(|r| r.id == start)
            .expect("road");
        chain(&net, i)
            .into_iter()
            .map(|k| net.roads()[k].id.clone())
            .collect()
    }

    #[test]
    fn a_chain_follows_links_and_first_connections_while_lanes_keep_their_ids() {
        // Road 0's successor is road 1 (lanes 1 and -1 link to the same ids).
        assert_eq!(ids("manual_add_of_geometries0.xodr", "0"), ["0", "1"]);
        // Road 0 ends in junction 1; its first connection is connecting road 1, whose
        // successor is road 2; road 2 has no successor.
        assert_eq!(ids("junction_trippel_twoway0.xodr", "0"), ["0", "1", "2"]);
        // Road 1's lane -3 links to lane -4 of road 2: renumbered, the chain stops.
        assert_eq!(ids("road_link_unequal_number_of_lanes0.xodr", "1"), ["1"]);
        // No link at all.
        assert_eq!(ids("two_roads.xodr", "1"), ["1"]);
    }
}
