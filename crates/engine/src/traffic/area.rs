//! TrafficAreaAction (OpenSCENARIO 1.3 XSD `TrafficAreaAction`, `TrafficArea`, `RoadRange`):
//! `numberOfEntities` spawned vehicles in an area given as a polygon of positions or as road
//! ranges.
//!
//! A RoadRange's RoadCursors each give a road, a start s (default 0) and lanes (none: every
//! drivable lane); the range runs `length` m along the road from there (default: to the road's
//! end). Vehicles appear, one per step as in the swarm, at random free lane points of the area
//! (polygon: inside it, by the even-odd rule; ranges: a random cursor, s and lane), at
//! [`DEFAULT_SPEED`](super::swarm::DEFAULT_SPEED) (the action has no speed). With
//! `continuous` the area is kept filled: a vehicle that leaves it is removed and replaced;
//! without, the action stops once it has spawned `numberOfEntities`.

use opendrive::Real;
use rand::Rng;
use scenario::{TrafficDistributionEntry, TrafficMix};

use super::spawn::{add, lane_point, remove};
use super::spawning::{Running, Tables};
use super::swarm::{ATTEMPTS, DEFAULT_SPEED};
use crate::error::Error;
use crate::store::World;

/// Where an area's vehicles may be.
#[derive(Debug, Clone)]
pub(crate) enum Shape {
    /// Polygon corners (world x, y), at least three.
    Polygon(Vec<(Real, Real)>),
    /// (road id, s from, s to, lanes; empty = every drivable lane).
    Ranges(Vec<(String, Real, Real, Vec<i32>)>),
}

/// An area's settings.
#[derive(Debug, Clone)]
pub(crate) struct Area {
    shape: Shape,
    count: usize,
    continuous: bool,
    mix: TrafficMix,
    /// Vehicles spawned so far.
    made: usize,
}

impl Area {
    /// An area action keeping `count` vehicles from `distribution` in `shape`.
    pub(crate) fn new(
        shape: Shape,
        count: u32,
        continuous: bool,
        distribution: &[TrafficDistributionEntry],
    ) -> Self {
        Area {
            shape,
            count: count as usize,
            continuous,
            mix: TrafficMix {
                definition: None,
                distribution: distribution.to_vec(),
            },
            made: 0,
        }
    }

    /// Whether world point (x, y), on road `road` at `s` in lane `lane`, lies in the area.
    fn contains(&self, x: Real, y: Real, at: Option<(&str, Real, i32)>) -> bool {
        match &self.shape {
            Shape::Polygon(corners) => in_polygon(corners, x, y),
            Shape::Ranges(ranges) => at.is_some_and(|(road, s, lane)| {
                ranges.iter().any(|(r, from, to, lanes)| {
                    r == road
                        && (*from..=*to).contains(&s)
                        && (lanes.is_empty() || lanes.contains(&lane))
                })
            }),
        }
    }

    /// A random point of the area to try (world x, y).
    fn draw(&self, world: &World, run: &mut Running) -> Option<(Real, Real)> {
        match &self.shape {
            Shape::Polygon(corners) => {
                let (mut lo, mut hi) = ((Real::MAX, Real::MAX), (Real::MIN, Real::MIN));
                for &(x, y) in corners {
                    lo = (lo.0.min(x), lo.1.min(y));
                    hi = (hi.0.max(x), hi.1.max(y));
                }
                let x = lo.0 + (hi.0 - lo.0) * run.rng.gen::<f64>();
                let y = lo.1 + (hi.1 - lo.1) * run.rng.gen::<f64>();
                in_polygon(corners, x, y).then_some((x, y))
            }
            Shape::Ranges(ranges) => {
                if ranges.is_empty() {
                    return None;
                }
                let (road_id, from, to, lanes) = &ranges[run.rng.gen_range(0..ranges.len())];
                let road = world.network.road(road_id)?;
                let s = from + (to.min(road.length) - from).max(0.0) * run.rng.gen::<f64>();
                let lane = if lanes.is_empty() {
                    let candidates: Vec<i32> = road
                        .lane_section_at(s)
                        .lanes()
                        .filter(|l| l.id != 0 && l.lane_type.is_drivable())
                        .map(|l| l.id)
                        .collect();
                    *candidates.get(run.rng.gen_range(0..candidates.len().max(1)))?
                } else {
                    lanes[run.rng.gen_range(0..lanes.len())]
                };
                let pose = road.lane_pose(lane, s, 0.0).ok()?;
                Some((pose.x, pose.y))
            }
        }
    }

    /// One step; `false` once a one-off area has spawned all its vehicles.
    pub(crate) fn step(
        &mut self,
        world: &mut World,
        tables: &mut Tables<'_>,
        run: &mut Running,
    ) -> Result<bool, Error> {
        if self.continuous {
            let outside: Vec<_> = run
                .members
                .iter()
                .copied()
                .filter(|&id| {
                    let e = world.entity(id);
                    let at = e
                        .road_position
                        .as_ref()
                        .map(|r| (r.road_id.as_str(), r.s, r.lane_id));
                    !self.contains(e.pose.x, e.pose.y, at)
                })
                .collect();
            for id in outside {
                remove(world, tables.spawning, &run.name, id);
            }
            run.members.retain(|&id| world.entity(id).placed);
        } else if self.made >= self.count {
            return Ok(false);
        }
        if run.members.len() >= self.count {
            return Ok(true);
        }
        for _ in 0..ATTEMPTS {
            let Some((x, y)) = self.draw(world, run) else {
                continue;
            };
            let Some(pose) = lane_point(world, x, y) else {
                continue;
            };
            let at = world.network.locate(pose.x, pose.y, Some(pose.h));
            let at = at.as_ref().map(|r| (r.road_id.as_str(), r.s, r.lane_id));
            if !self.contains(pose.x, pose.y, at) {
                continue;
            }
            add(world, tables, run, &self.mix, pose, DEFAULT_SPEED)?;
            self.made += 1;
            break;
        }
        Ok(true)
    }
}

/// Even-odd rule: whether (x, y) lies inside the polygon `corners`.
fn in_polygon(corners: &[(Real, Real)], x: Real, y: Real) -> bool {
    let mut inside = false;
    let n = corners.len();
    for i in 0..n {
        let (a, b) = (corners[i], corners[(i + n - 1) % n]);
        if (a.1 > y) != (b.1 > y) && x < (b.0 - a.0) * (y - a.1) / (b.1 - a.1) + a.0 {
            inside = !inside;
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::in_polygon;

    /// The unit square and an L shape (the notch (1..2, 1..2) cut from the 2 × 2 square).
    #[test]
    fn even_odd_rule() {
        let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        assert!(in_polygon(&square, 0.5, 0.5));
        assert!(!in_polygon(&square, 1.5, 0.5));
        let l = [
            (0.0, 0.0),
            (2.0, 0.0),
            (2.0, 1.0),
            (1.0, 1.0),
            (1.0, 2.0),
            (0.0, 2.0),
        ];
        assert!(in_polygon(&l, 0.5, 1.5) && in_polygon(&l, 1.5, 0.5));
        assert!(!in_polygon(&l, 1.5, 1.5));
    }
}
