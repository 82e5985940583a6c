//! Planned longitudinal motion of one actor: a piecewise-linear speed profile over time, its
//! integral (s along the road) and the lane it is in. The planner extends it as it plans each
//! phase; after its last change the speed holds.

/// A stretch of linear speed change from `t0` to `t1`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Ramp {
    t0: f64,
    t1: f64,
    v1: f64,
}

/// Longitudinal motion and lane of an actor.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Track {
    /// s and speed at time 0.
    s0: f64,
    v0: f64,
    ramps: Vec<Ramp>,
    /// (time from which, lane id).
    lanes: Vec<(f64, i32)>,
    /// (time from which, offset from the lane centre, m).
    offsets: Vec<(f64, f64)>,
    /// Planned sideways movements (lane and offset changes): (start, end) times.
    moves: Vec<(f64, f64)>,
}

impl Track {
    /// An actor at `s` in `lane` driving at `v` at time 0.
    pub(crate) fn new(s: f64, v: f64, lane: i32) -> Self {
        Track {
            s0: s,
            v0: v,
            ramps: Vec::new(),
            lanes: vec![(0.0, lane)],
            offsets: vec![(0.0, 0.0)],
            moves: Vec::new(),
        }
    }

    /// The actor moves sideways from `t0` to `t1` (a lane or lane offset change).
    pub(crate) fn add_move(&mut self, t0: f64, t1: f64) {
        self.moves.push((t0, t1));
    }

    /// The start of the first sideways movement that overlaps the open interval (a, b).
    pub(crate) fn moving_in(&self, a: f64, b: f64) -> Option<f64> {
        self.moves
            .iter()
            .filter(|(m0, m1)| *m0 < b && *m1 > a)
            .map(|(m0, _)| *m0)
            .fold(None, |acc: Option<f64>, x| {
                Some(acc.map_or(x, |y| y.min(x)))
            })
    }

    /// The offset from the lane centre at time `t` (the last one planned from t or before).
    pub(crate) fn offset(&self, t: f64) -> f64 {
        self.offsets
            .iter()
            .rev()
            .find(|(from, _)| *from <= t)
            .map_or(0.0, |(_, o)| *o)
    }

    /// From time `t` on, the actor is `offset` from its lane's centre.
    pub(crate) fn set_offset(&mut self, t: f64, offset: f64) {
        self.offsets.retain(|(from, _)| *from < t);
        self.offsets.push((t, offset));
    }

    /// s and speed at time `t` (≥ 0).
    pub(crate) fn at(&self, t: f64) -> (f64, f64) {
        let (mut s, mut v, mut now) = (self.s0, self.v0, 0.0);
        for r in &self.ramps {
            if t <= r.t0 {
                break;
            }
            // Hold v from now to the ramp's start.
            s += v * (r.t0 - now);
            let end = t.min(r.t1);
            let span = r.t1 - r.t0;
            let v_end = if span > 0.0 {
                v + (r.v1 - v) * (end - r.t0) / span
            } else {
                r.v1
            };
            s += 0.5 * (v + v_end) * (end - r.t0);
            now = end;
            if t < r.t1 {
                return (s, v_end);
            }
            v = r.v1;
        }
        (s + v * (t - now), v)
    }

    /// Speed changes linearly from its value at `t0` to `v1` at `t1` (a step when equal), and
    /// holds after; later planned changes are dropped.
    pub(crate) fn ramp(&mut self, t0: f64, t1: f64, v1: f64) {
        self.ramps.retain(|r| r.t1 <= t0);
        self.ramps.push(Ramp { t0, t1, v1 });
    }

    /// The lane at time `t`.
    pub(crate) fn lane(&self, t: f64) -> i32 {
        self.lanes
            .iter()
            .rev()
            .find(|(from, _)| *from <= t)
            .map_or(self.lanes[0].1, |(_, l)| *l)
    }

    /// From time `t` on, the actor is in `lane`, at its centre (a lane change ends there).
    pub(crate) fn set_lane(&mut self, t: f64, lane: i32) {
        self.lanes.retain(|(from, _)| *from < t);
        self.lanes.push((t, lane));
        self.set_offset(t, 0.0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TOL: f64 = 1e-9;

    #[test]
    fn constant_speed_then_ramp() {
        // 10 m/s from s = 5 m; at 2 s a linear ramp to 20 m/s over 2 s.
        let mut t = Track::new(5.0, 10.0, -1);
        t.ramp(2.0, 4.0, 20.0);
        // s(2) = 5 + 20 = 25; s(3) = 25 + (10 + 15)/2 = 37.5; s(4) = 25 + 30 = 55; s(5) = 75.
        assert!((t.at(2.0).0 - 25.0).abs() < TOL);
        assert!((t.at(3.0).0 - 37.5).abs() < TOL);
        assert!((t.at(3.0).1 - 15.0).abs() < TOL);
        assert!((t.at(4.0).0 - 55.0).abs() < TOL);
        assert!((t.at(5.0).0 - 75.0).abs() < TOL);
        assert!((t.at(5.0).1 - 20.0).abs() < TOL);
    }

    #[test]
    fn step_and_lanes() {
        let mut t = Track::new(0.0, 10.0, -2);
        t.ramp(1.0, 1.0, 0.0);
        // 10 m in the first second, then standing.
        assert!((t.at(3.0).0 - 10.0).abs() < TOL);
        t.set_lane(2.0, -1);
        assert_eq!(t.lane(1.9), -2);
        assert_eq!(t.lane(2.0), -1);
    }
}
