//! The cost of a path per routeStrategy (OpenSCENARIO 1.3 §7.5, XSD `RouteStrategy`):
//!
//! | strategy | cost, compared lexicographically |
//! | --- | --- |
//! | `shortest` | (length + lane changes × `opendrive::LANE_CHANGE_COST`, –) |
//! | `fastest` | (Σ length / speed + lane changes × `LANE_CHANGE_COST` / speed, –) |
//! | `leastIntersections` | (junctions entered, length + lane-change cost) |
//! | `random` | (Σ length × weight + lane-change cost, –), weights from `random` |
//!
//! Length is driven along the roads' reference lines (|Δs|), as `opendrive::RoadNetwork::route`
//! measures it; `shortest` is that router's cost exactly. The speed of a lane is its
//! `<speed max>` (OpenDRIVE 1.8 §11.7), else its road type's `<speed max>` at the stretch's
//! entry (§10.5), else [`DEFAULT_SPEED`]; a road type's "no limit" counts as
//! [`UNLIMITED_ROAD_SPEED`]. A junction is entered when the path moves onto a road of a
//! junction from a road that is not part of it.

use std::cmp::Ordering;

use opendrive::{LaneCost, LaneHandle, PathCost, Real, RoadNetwork, LANE_CHANGE_COST};
use scenario::RouteStrategy;

use super::random::lane_weight;

/// Speed assumed where neither lane nor road type gives one (m/s): 50 km/h, the built-up-area
/// limit of most European road codes (e.g. German StVO §3), the typical setting of the
/// junction networks in the corpus.
pub const DEFAULT_SPEED: Real = 50.0 / 3.6;
/// Speed assumed for a road type whose `<speed max="no limit">` (m/s): 130 km/h, the German
/// advisory motorway speed (Autobahn-Richtgeschwindigkeits-Verordnung).
pub const UNLIMITED_ROAD_SPEED: Real = 130.0 / 3.6;

/// Settings of route planning.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoutingOptions {
    /// Seed of routeStrategy `random`; the runtime passes its run seed, so that equal seeds
    /// plan equal routes.
    pub seed: u64,
    /// Speed where the road network gives none (m/s), for `fastest`.
    pub default_speed: Real,
}

impl Default for RoutingOptions {
    /// Seed 0, [`DEFAULT_SPEED`].
    fn default() -> Self {
        Self {
            seed: 0,
            default_speed: DEFAULT_SPEED,
        }
    }
}

/// A path cost, compared lexicographically (primary first).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Cost {
    pub(crate) primary: Real,
    pub(crate) secondary: Real,
}

impl PathCost for Cost {
    fn plus(self, other: Cost) -> Cost {
        Cost {
            primary: self.primary + other.primary,
            secondary: self.secondary + other.secondary,
        }
    }

    fn total_cmp(&self, other: &Cost) -> Ordering {
        self.primary
            .total_cmp(&other.primary)
            .then_with(|| self.secondary.total_cmp(&other.secondary))
    }
}

/// The cost model of one leg.
pub(crate) struct CostModel<'a> {
    pub(crate) network: &'a RoadNetwork,
    pub(crate) strategy: RouteStrategy,
    pub(crate) random_key: u64,
    pub(crate) default_speed: Real,
}

impl CostModel<'_> {
    /// Speed (m/s) on lane `h` entered at `s`.
    fn speed(&self, h: LaneHandle, s: Real) -> Real {
        let road = self.network.handle_road(h);
        let lane = road.lane_sections[h.section as usize].lane(h.lane);
        let v = lane
            .and_then(|l| l.speed_limit)
            .or_else(|| road.type_at(s).and_then(|t| t.speed).map(|sp| sp.max))
            .unwrap_or(self.default_speed);
        if v.is_infinite() {
            UNLIMITED_ROAD_SPEED
        } else if v > 0.0 {
            v
        } else {
            self.default_speed
        }
    }
}

/// The moves of the lane-graph search (`opendrive::RoadNetwork::route_by`) under a strategy.
impl LaneCost for CostModel<'_> {
    type Cost = Cost;

    /// Driving `length` metres of lane `h`, entered at `s`.
    fn along(&self, h: LaneHandle, s: Real, length: Real) -> Cost {
        match self.strategy {
            RouteStrategy::Fastest => Cost {
                primary: length / self.speed(h, s),
                secondary: 0.0,
            },
            RouteStrategy::LeastIntersections => Cost {
                primary: 0.0,
                secondary: length,
            },
            RouteStrategy::Random => Cost {
                primary: length * lane_weight(self.random_key, h),
                secondary: 0.0,
            },
            _ => Cost {
                primary: length,
                secondary: 0.0,
            },
        }
    }

    /// One lane change on lane `h` at `s`: driving `LANE_CHANGE_COST` metres more, unweighted
    /// under `random` (the weights choose among roads, not lane changes).
    fn lane_change(&self, h: LaneHandle, s: Real) -> Cost {
        match self.strategy {
            RouteStrategy::Random => Cost {
                primary: LANE_CHANGE_COST,
                secondary: 0.0,
            },
            _ => self.along(h, s, LANE_CHANGE_COST),
        }
    }

    /// Moving from lane `from` onto lane `to` (next section, next road, through a junction).
    fn enter(&self, from: LaneHandle, to: LaneHandle) -> Cost {
        let entered = self.strategy == RouteStrategy::LeastIntersections
            && enters_junction(self.network, from, to);
        Cost {
            primary: if entered { 1.0 } else { 0.0 },
            secondary: 0.0,
        }
    }
}

/// Whether moving from lane `from` to lane `to` enters a junction.
pub(crate) fn enters_junction(network: &RoadNetwork, from: LaneHandle, to: LaneHandle) -> bool {
    entered(
        network.handle_road(from).junction.as_deref(),
        network.handle_road(to).junction.as_deref(),
    )
}

/// Whether moving from road `from` to road `to` (ids) enters a junction.
pub(crate) fn enters_junction_by_id(network: &RoadNetwork, from: &str, to: &str) -> bool {
    let junction = |id: &str| network.road(id).and_then(|r| r.junction.as_deref());
    entered(junction(from), junction(to))
}

/// A junction is entered when the new road belongs to one the old road is not part of.
fn entered(from: Option<&str>, to: Option<&str>) -> bool {
    to.is_some() && to != from
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Road "1": type speed 108 km/h; lane −1 has its own 18 km/h, lane −2 none. Road "2": no
    /// type at all. Road "3": type speed "no limit".
    const XODR: &str = r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>
      <road id="1" length="10" junction="-1"><type s="0" type="town"><speed max="108" unit="km/h"/></type>
        <planView><geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry></planView>
        <lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right>
          <lane id="-1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/><speed sOffset="0" max="18" unit="km/h"/></lane>
          <lane id="-2" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane>
        </right></laneSection></lanes></road>
      <road id="2" length="10" junction="-1">
        <planView><geometry s="0" x="0" y="50" hdg="0" length="10"><line/></geometry></planView>
        <lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right>
          <lane id="-1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane>
        </right></laneSection></lanes></road>
      <road id="3" length="10" junction="-1"><type s="0" type="motorway"><speed max="no limit"/></type>
        <planView><geometry s="0" x="0" y="100" hdg="0" length="10"><line/></geometry></planView>
        <lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right>
          <lane id="-1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane>
        </right></laneSection></lanes></road>
    </OpenDRIVE>"#;

    #[test]
    fn speed_comes_from_lane_then_road_type_then_default() {
        // A constant fixture that parses.
        let net = RoadNetwork::from_str(XODR, std::path::Path::new("speeds.xodr")).unwrap();
        let model = CostModel {
            network: &net,
            strategy: RouteStrategy::Fastest,
            random_key: 0,
            default_speed: DEFAULT_SPEED,
        };
        let h = |road: &str, lane: i32| net.lane_handle(road, lane, 5.0).unwrap();
        // 18 km/h = 5 m/s on lane −1; 108 km/h = 30 m/s from the road type on lane −2;
        // 50 km/h by default on road 2; 130 km/h for "no limit" on road 3.
        assert!((model.speed(h("1", -1), 5.0) - 5.0).abs() < 1e-12);
        assert!((model.speed(h("1", -2), 5.0) - 30.0).abs() < 1e-12);
        assert!((model.speed(h("2", -1), 5.0) - 50.0 / 3.6).abs() < 1e-12);
        assert!((model.speed(h("3", -1), 5.0) - 130.0 / 3.6).abs() < 1e-12);
        // Fastest: 10 m on lane −1 take 2 s; a lane change there costs 10 m / 5 m/s = 2 s.
        assert!((model.along(h("1", -1), 0.0, 10.0).primary - 2.0).abs() < 1e-12);
        assert!((model.lane_change(h("1", -1), 0.0).primary - 2.0).abs() < 1e-12);
    }
}
