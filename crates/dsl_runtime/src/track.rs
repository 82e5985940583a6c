//! Planned longitudinal motion of one actor: its speed over time as a sequence of stretches of
//! change (linear or constant-jerk, sinusoidal, or a step), the speed holding between them;
//! its integral (the distance along its lane), and the lane and offset it is in. The planner
//! extends it as it plans each phase; after the last change the speed holds.
//!
//! A lane is stored with the id it has where it was planned; a lane section further on may
//! number the same lane differently (ASAM OpenDRIVE 1.8 §11.5 lane linkage, `<link><successor
//! id=…>`). So the stored ids stay private here: the lane at a time, and the s the distance
//! along it reaches, are read on a plan road ([`Track::lane_on`], [`Track::s_on`]), which
//! follows the lane's links (`PlanRoad::lane_along`) as the engine does.

use std::f64::consts::PI;

use crate::road::PlanRoad;

/// How the speed changes over a stretch.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Shape {
    /// A linear change to `v1` over `span` s (possibly cut short).
    Linear { v1: f64, span: f64 },
    /// Acceleration `a0` at the stretch's start, changing at `jerk` (m/s³).
    Poly { a0: f64, jerk: f64 },
    /// A sinusoidal change by `dv` over `period` s (the fraction done after τ is
    /// (1 − cos(πτ/period))/2, the engine's sinusoidal shape), possibly cut short.
    Sine { dv: f64, period: f64 },
    /// A jump to `v1` at the stretch's start (it takes no time).
    Step { v1: f64 },
}

impl Shape {
    /// Speed gained and distance covered `tau` s into the stretch, starting at speed `v`.
    fn advance(&self, v: f64, tau: f64) -> (f64, f64) {
        match *self {
            Shape::Linear { v1, span } => {
                let v_end = v + (v1 - v) * tau / span;
                (v_end - v, 0.5 * (v + v_end) * tau)
            }
            Shape::Poly { a0, jerk } => (
                a0 * tau + 0.5 * jerk * tau * tau,
                v * tau + 0.5 * a0 * tau * tau + jerk * tau * tau * tau / 6.0,
            ),
            Shape::Sine { dv, period } => {
                let w = PI / period;
                (
                    dv * (1.0 - (w * tau).cos()) / 2.0,
                    v * tau + dv / 2.0 * (tau - (w * tau).sin() / w),
                )
            }
            Shape::Step { v1 } => (v1 - v, v1 * tau),
        }
    }

    /// Acceleration `tau` s into the stretch (m/s²), which started at speed `v`.
    fn acceleration(&self, v: f64, tau: f64) -> f64 {
        match *self {
            Shape::Linear { v1, span } => (v1 - v) / span,
            Shape::Poly { a0, jerk } => a0 + jerk * tau,
            Shape::Sine { dv, period } => dv * PI / (2.0 * period) * (PI * tau / period).sin(),
            Shape::Step { .. } => 0.0,
        }
    }
}

/// A stretch of speed change from `t0` to `t1`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Stretch {
    t0: f64,
    t1: f64,
    shape: Shape,
}

/// Longitudinal motion and lane of an actor.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Track {
    /// s and speed at time 0.
    s0: f64,
    v0: f64,
    stretches: Vec<Stretch>,
    /// (time, distance added): jumps of a teleport.
    jumps: Vec<(f64, f64)>,
    /// (time from which, lane id as numbered where the actor is at that time): private, read
    /// through [`Track::lane_on`], which follows the lane's links from there.
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
            stretches: Vec::new(),
            jumps: Vec::new(),
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

    /// The sideways movements that overlap the open interval (a, b): (start, end) times.
    pub(crate) fn moves_in(&self, a: f64, b: f64) -> Vec<(f64, f64)> {
        self.moves
            .iter()
            .copied()
            .filter(|(m0, m1)| *m0 < b && *m1 > a)
            .collect()
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

    /// s and speed at time `t` (≥ 0), after a step of speed planned at `t`.
    pub(crate) fn at(&self, t: f64) -> (f64, f64) {
        let (s, v, _) = self.state(t);
        let jumped: f64 = self
            .jumps
            .iter()
            .filter(|(from, _)| *from <= t)
            .map(|(_, d)| d)
            .sum();
        (s + jumped, v)
    }

    /// At time `t` the actor is put `d` further along (a teleport); later jumps are dropped.
    pub(crate) fn jump(&mut self, t: f64, d: f64) {
        self.jumps.retain(|(from, _)| *from < t);
        self.jumps.push((t, d));
    }

    /// Acceleration at time `t` (m/s²): of the stretch under way, else 0 (the speed holds).
    /// At a stretch's end, the acceleration it ends with.
    /// A change that starts at `t` has its acceleration from `t` on: an assigned acceleration
    /// is a step of it, which an action starting in the same instant finds (as a step of
    /// speed, `at`).
    pub(crate) fn acceleration(&self, t: f64) -> f64 {
        match self.stretches.iter().find(|r| r.t0 == t && r.t1 > t) {
            Some(r) => r.shape.acceleration(self.at(t).1, 0.0),
            None => self.state(t).2,
        }
    }

    /// The acceleration over (`a`, `b`) as pieces (start, end, m/s²) where it is constant,
    /// split where a planned change starts or ends; `Err(t)` names the first moment from
    /// which it is not constant over a piece (a sinusoidal or constant-jerk change, or a
    /// step of speed, whose acceleration has no finite value).
    pub(crate) fn acceleration_pieces(&self, a: f64, b: f64) -> Result<Vec<(f64, f64, f64)>, f64> {
        let mut cuts = vec![a, b];
        for r in &self.stretches {
            let constant = matches!(r.shape, Shape::Linear { .. }) && r.t1 > r.t0;
            if r.t0 < b && r.t1 > a && !constant || (r.t0 > a && r.t0 < b && r.t1 == r.t0) {
                return Err(r.t0.max(a));
            }
            cuts.extend([r.t0, r.t1].into_iter().filter(|t| *t > a && *t < b));
        }
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        Ok(cuts
            .windows(2)
            .map(|w| (w[0], w[1], self.acceleration(0.5 * (w[0] + w[1]))))
            .collect())
    }

    /// s, speed and acceleration at time `t`.
    fn state(&self, t: f64) -> (f64, f64, f64) {
        let (mut s, mut v, mut now) = (self.s0, self.v0, 0.0);
        // At a change's end (t = its t1), the acceleration it ends with.
        let mut a_end = 0.0;
        for r in &self.stretches {
            // A step at `t` has happened at `t` (the engine sets it in the step from `t`, and
            // an action that starts in the same instant finds it); a change from `t` has not
            // started yet.
            if t < r.t0 || (t == r.t0 && r.t1 > r.t0) {
                break;
            }
            // Hold v from now to the stretch's start.
            s += v * (r.t0 - now);
            let end = t.min(r.t1);
            let tau = end - r.t0;
            let (dv, ds) = r.shape.advance(v, tau);
            s += ds;
            now = end;
            let a = r.shape.acceleration(v, tau);
            if t < r.t1 {
                return (s, v + dv, a);
            }
            v = match r.shape {
                // The end speed exactly, when the change ran its course.
                Shape::Linear { v1, span } if tau == span => v1,
                Shape::Step { v1 } => v1,
                _ => v + dv,
            };
            a_end = if t == r.t1 && r.t1 > r.t0 { a } else { 0.0 };
        }
        (s + v * (t - now), v, a_end)
    }

    /// A new stretch from `t0`: later planned changes are dropped, and one under way at `t0` is
    /// cut there (the speed it reached holds until the new one starts).
    fn push(&mut self, stretch: Stretch) {
        let t0 = stretch.t0;
        self.stretches
            .retain(|r| r.t0 < t0 || (r.t0 == t0 && r.t1 == t0 && stretch.t1 > t0));
        if let Some(last) = self.stretches.last_mut() {
            last.t1 = last.t1.min(t0);
        }
        self.stretches.push(stretch);
    }

    /// Speed changes linearly from its value at `t0` to `v1` at `t1` (a step when equal), and
    /// holds after; later planned changes are dropped.
    pub(crate) fn ramp(&mut self, t0: f64, t1: f64, v1: f64) {
        let shape = if t1 > t0 {
            Shape::Linear { v1, span: t1 - t0 }
        } else {
            Shape::Step { v1 }
        };
        self.push(Stretch { t0, t1, shape });
    }

    /// Speed changes sinusoidally from its value at `t0` to `v1` at `t1`, and holds after.
    pub(crate) fn sine(&mut self, t0: f64, t1: f64, v1: f64) {
        if t1 <= t0 {
            return self.ramp(t0, t1, v1);
        }
        let dv = v1 - self.at(t0).1;
        self.push(Stretch {
            t0,
            t1,
            shape: Shape::Sine {
                dv,
                period: t1 - t0,
            },
        });
    }

    /// From `t0` to `t1` the acceleration starts at `a0` and changes at `jerk`; the speed holds
    /// after `t1`.
    pub(crate) fn jerk(&mut self, t0: f64, t1: f64, a0: f64, jerk: f64) {
        self.push(Stretch {
            t0,
            t1,
            shape: Shape::Poly { a0, jerk },
        });
    }

    /// From `t0` to `t1` the speed is `other`'s plus `delta` (an actor held at a distance from
    /// another, `plan::held_relation`, delta 0; a speed relative to another at: all,
    /// `plan::speed_follow`): a step to `other`'s speed + `delta` at `t0`, then each of
    /// `other`'s changes within the span (their targets + `delta`), the last cut at `t1`, after
    /// which the speed it reached holds; later planned changes are dropped. `Err(t)`: a
    /// sinusoidal change of `other`'s under way at `t0` (its remainder is no change of this
    /// track's kinds), from `t`.
    pub(crate) fn follow(
        &mut self,
        other: &Track,
        (t0, t1): (f64, f64),
        delta: f64,
    ) -> Result<(), f64> {
        self.ramp(t0, t0, other.at(t0).1 + delta);
        for r in other.stretches.iter().filter(|r| r.t1 > t0 && r.t0 < t1) {
            let shape = match r.shape {
                // Targets are speeds (offset by delta); the others are changes of speed.
                Shape::Linear { v1, span } if r.t0 >= t0 => Shape::Linear {
                    v1: v1 + delta,
                    span,
                },
                Shape::Step { v1 } if r.t0 >= t0 => Shape::Step { v1: v1 + delta },
                _ if r.t0 >= t0 => r.shape,
                // Under way at t0: its remainder from t0.
                Shape::Linear { v1, span } => Shape::Linear {
                    v1: v1 + delta,
                    span: r.t0 + span - t0,
                },
                Shape::Poly { a0, jerk } => Shape::Poly {
                    a0: a0 + jerk * (t0 - r.t0),
                    jerk,
                },
                Shape::Sine { .. } | Shape::Step { .. } => return Err(r.t0),
            };
            self.push(Stretch {
                t0: r.t0.max(t0),
                t1: r.t1,
                shape,
            });
        }
        if let Some(last) = self.stretches.last_mut() {
            last.t1 = last.t1.min(t1);
        }
        Ok(())
    }

    /// Whether the actor stands throughout: no speed at the start, no change of speed to
    /// anything but 0, no jump, lane change or sideways movement.
    pub(crate) fn stands(&self) -> bool {
        let still = |r: &Stretch| match r.shape {
            Shape::Linear { v1, .. } | Shape::Step { v1 } => v1 == 0.0,
            Shape::Poly { .. } | Shape::Sine { .. } => false,
        };
        self.v0 == 0.0
            && self.stretches.iter().all(still)
            && self.jumps.is_empty()
            && self.moves.is_empty()
            && self.lanes.len() == 1
    }

    /// The lane planned for time `t`, with the id it has where it was planned, and the time
    /// from which it was planned (private: a lane section between may renumber it).
    fn planned_lane(&self, t: f64) -> (f64, i32) {
        self.lanes
            .iter()
            .rev()
            .find(|(from, _)| *from <= t)
            .copied()
            .unwrap_or(self.lanes[0])
    }

    /// The lane at time 0, where the actor starts (its id there: nothing to follow yet).
    pub(crate) fn start_lane(&self) -> i32 {
        self.planned_lane(0.0).1
    }

    /// s on `road` (the plan road, or the view the actor is planned on) at time `t`: the
    /// track's distance from its start, along the centre line of its lane at time 0 followed
    /// across the lane sections that renumber it (`PlanRoad::s_after`).
    pub(crate) fn s_on(&self, road: &PlanRoad<'_>, t: f64) -> f64 {
        let s0 = self.at(0.0).0;
        road.s_after(self.start_lane(), s0, self.at(t).0 - s0)
    }

    /// The lane the actor is in at time `t` on `road`: the lane planned for `t`, followed from
    /// where it was planned along its links into the lane sections after it
    /// (`PlanRoad::lane_along`; the engine follows them too, ASAM OpenDRIVE 1.8 §11.5).
    pub(crate) fn lane_on(&self, road: &PlanRoad<'_>, t: f64) -> i32 {
        self.followed(road, self.planned_lane(t), t)
    }

    /// The lane planned last (for the time after the last one the plan knows, when a phase
    /// starts at run time), followed to where the actor is at time `t` on `road`.
    pub(crate) fn last_lane_on(&self, road: &PlanRoad<'_>, t: f64) -> i32 {
        self.followed(road, self.planned_lane(f64::MAX), t)
    }

    /// Whether a lane change is planned between times `a` < `b`: the lane at `b` is not the
    /// lane at `a` followed along its links to where the actor is at `b` (the ids alone
    /// differ where a lane section renumbers the lane the actor keeps).
    pub(crate) fn changes_lane(&self, road: &PlanRoad<'_>, a: f64, b: f64) -> bool {
        let (from, lane) = self.planned_lane(b);
        from > a
            && self.followed(road, self.planned_lane(a), b) != self.followed(road, (from, lane), b)
    }

    /// Lane `lane`, planned from time `from`, followed to where the actor is at `t`.
    fn followed(&self, road: &PlanRoad<'_>, (from, lane): (f64, i32), t: f64) -> i32 {
        if !road.renumbers_lanes() {
            return lane;
        }
        road.lane_along(lane, self.s_on(road, from), self.s_on(road, t))
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
    fn acceleration_pieces_split_where_a_change_starts_or_ends() {
        // 10 m/s; 2 m/s² over 1-3 s, then holding: over (0, 4) the pieces 0, 2, 0 m/s².
        let mut t = Track::new(0.0, 10.0, -1);
        t.ramp(1.0, 3.0, 14.0);
        let p = t.acceleration_pieces(0.0, 4.0).unwrap_or_default();
        let want = [(0.0, 1.0, 0.0), (1.0, 3.0, 2.0), (3.0, 4.0, 0.0)];
        assert_eq!(p.len(), 3, "{p:?}");
        for (got, want) in p.iter().zip(want) {
            assert!(
                (got.0 - want.0).abs() < TOL
                    && (got.1 - want.1).abs() < TOL
                    && (got.2 - want.2).abs() < TOL,
                "{p:?}"
            );
        }
        // A sinusoidal change from 5 s has no one acceleration; a step at 6 s none at all.
        t.sine(5.0, 7.0, 20.0);
        assert_eq!(t.acceleration_pieces(4.0, 8.0), Err(5.0));
        let mut s = Track::new(0.0, 10.0, -1);
        s.ramp(6.0, 6.0, 0.0);
        assert_eq!(s.acceleration_pieces(4.0, 8.0), Err(6.0));
        assert!(
            s.acceleration_pieces(6.0, 8.0).is_ok(),
            "a step at the start is before it"
        );
    }

    /// A step of speed at t is the speed an action starting at t finds (`keep_speed()` right
    /// after `assign_speed(v)` keeps v; it kept the speed before the step); a change from t has
    /// not begun at t.
    #[test]
    fn a_step_at_t_has_happened_at_t_and_a_change_from_t_has_not() {
        let mut tr = Track::new(0.0, 0.0, -1);
        tr.ramp(1.0, 1.0, 10.0);
        assert!((tr.at(1.0).1 - 10.0).abs() < TOL);
        assert!(tr.at(1.0).0.abs() < TOL, "no distance at the step");
        tr.ramp(2.0, 4.0, 20.0);
        assert!((tr.at(2.0).1 - 10.0).abs() < TOL);
        assert!((tr.at(2.0).0 - 10.0).abs() < TOL, "10 m at 10 m/s from 1 s");
        assert!((tr.at(3.0).1 - 15.0).abs() < TOL);
        // An acceleration assigned at t is the acceleration at t.
        tr.jerk(4.0, 9.0, 2.0, 0.0);
        assert!((tr.acceleration(4.0) - 2.0).abs() < TOL);
        assert!(
            (tr.at(4.0).1 - 20.0).abs() < TOL,
            "no speed gained at its start"
        );
        // A second step in the same instant replaces the first.
        tr.ramp(5.0, 5.0, 0.0);
        tr.ramp(5.0, 5.0, 7.0);
        assert!((tr.at(5.0).1 - 7.0).abs() < TOL);
    }

    #[test]
    fn standing_is_no_speed_and_no_move() {
        let mut t = Track::new(0.0, 0.0, -1);
        t.ramp(1.0, 1.0, 0.0);
        assert!(t.stands());
        t.ramp(2.0, 3.0, 1.0);
        assert!(!t.stands(), "a ramp to 1 m/s");
        let mut t = Track::new(0.0, 0.0, -1);
        t.set_lane(2.0, -2);
        assert!(!t.stands(), "a lane change");
        assert!(!Track::new(0.0, 5.0, -1).stands(), "5 m/s at the start");
    }

    #[test]
    fn step_and_lanes() {
        let mut t = Track::new(0.0, 10.0, -2);
        t.ramp(1.0, 1.0, 0.0);
        // 10 m in the first second, then standing.
        assert!((t.at(3.0).0 - 10.0).abs() < TOL);
        t.set_lane(2.0, -1);
        assert_eq!(t.planned_lane(1.9), (0.0, -2));
        assert_eq!(t.planned_lane(2.0), (2.0, -1));
    }

    #[test]
    fn sinusoidal_change_and_cut() {
        // 10 → 20 m/s sinusoidally over 4 s from s = 0: v(τ) = 10 + 5·(1 − cos(πτ/4)),
        // s(τ) = 10τ + 5·(τ − (4/π)·sin(πτ/4)): s(2) = 30 − 20/π, s(4) = 60; then 20 m/s.
        let pi = std::f64::consts::PI;
        let mut t = Track::new(0.0, 10.0, -1);
        t.sine(0.0, 4.0, 20.0);
        assert!((t.at(2.0).1 - 15.0).abs() < TOL);
        assert!((t.at(2.0).0 - (30.0 - 20.0 / pi)).abs() < TOL);
        assert!((t.acceleration(2.0) - 10.0 * pi / 8.0).abs() < TOL);
        assert!((t.at(4.0).0 - 60.0).abs() < TOL);
        assert!((t.at(5.0).0 - 80.0).abs() < TOL);
        // A new change at 2 s cuts it: 15 m/s holds from there.
        t.ramp(2.0, 2.0, 15.0);
        assert!((t.at(3.0).0 - (45.0 - 20.0 / pi)).abs() < TOL);
    }

    #[test]
    fn constant_jerk_then_constant_acceleration() {
        // From 10 m/s: a = 2.5·τ for 1.2 s (v = 10 + 1.25τ², s = 10τ + 2.5τ³/6), then 3 m/s².
        let mut t = Track::new(10.0, 10.0, -1);
        t.jerk(0.0, 1.2, 0.0, 2.5);
        t.jerk(1.2, 3.2, 3.0, 0.0);
        assert!((t.at(1.2).1 - 11.8).abs() < TOL);
        assert!((t.at(1.2).0 - 22.72).abs() < TOL);
        assert!((t.acceleration(1.2) - 3.0).abs() < TOL);
        assert!((t.at(3.2).1 - 17.8).abs() < TOL);
        assert!((t.at(3.2).0 - 52.32).abs() < TOL);
        assert!(
            t.acceleration(4.0).abs() < TOL,
            "holding 17.8 m/s after the stretch"
        );
    }
}
