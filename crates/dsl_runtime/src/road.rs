//! The road the planner places and moves the actors on (ASAM OpenDRIVE 1.8 §9 roads, §11
//! lanes): the first road of the network with driving lanes on its right side (right-hand
//! traffic: those lanes run in +s). Lanes are counted in the DSL's way (ASAM OpenSCENARIO DSL
//! 2.1 §8.9 `lane()` modifier): 1 is the rightmost driving lane in the direction of travel, or
//! the leftmost with `from: left`.

use opendrive::RoadNetwork;

/// The road of a plan.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlanRoad<'a> {
    road: &'a opendrive::Road,
}

impl<'a> PlanRoad<'a> {
    /// The first road with a driving lane on its right side, if any.
    pub(crate) fn pick(net: &'a RoadNetwork) -> Option<Self> {
        net.roads()
            .iter()
            .find(|r| {
                r.lane_sections
                    .first()
                    .is_some_and(|ls| ls.right.iter().any(|l| l.lane_type.is_drivable()))
            })
            .map(|road| PlanRoad { road })
    }

    /// The OpenDRIVE id.
    pub(crate) fn id(&self) -> &str {
        &self.road.id
    }

    /// Its length (m).
    pub(crate) fn length(&self) -> f64 {
        self.road.length
    }

    /// Driving lanes of the right side at `s`, rightmost first (−3, −2, −1).
    pub(crate) fn driving_lanes(&self, s: f64) -> Vec<i32> {
        let s = s.clamp(0.0, self.road.length);
        let mut ids: Vec<i32> = self
            .road
            .lane_section_at(s)
            .right
            .iter()
            .filter(|l| l.lane_type.is_drivable())
            .map(|l| l.id)
            .collect();
        ids.sort_unstable();
        ids
    }

    /// The lane numbered `n` (1 = rightmost, or leftmost with `from_left`) at `s`.
    pub(crate) fn numbered(&self, n: i64, from_left: bool, s: f64) -> Option<i32> {
        let mut lanes = self.driving_lanes(s);
        if from_left {
            lanes.reverse();
        }
        usize::try_from(n - 1)
            .ok()
            .and_then(|i| lanes.get(i).copied())
    }

    /// The lane `n` lanes to the left (or right) of `id` at `s`.
    pub(crate) fn beside(&self, id: i32, left: bool, n: i64, s: f64) -> Option<i32> {
        let lanes = self.driving_lanes(s);
        let i = lanes.iter().position(|l| *l == id)? as i64;
        let j = if left { i + n } else { i - n };
        usize::try_from(j).ok().and_then(|j| lanes.get(j).copied())
    }
}
