//! Times along a trajectory (OpenSCENARIO 1.3 §6.9: `Vertex/@time`, `Clothoid/@startTime`
//! and `@stopTime`, `ClothoidSplineSegment/@timeStart` with `ClothoidSpline/@timeEnd`,
//! `ControlPoint/@time`): pairs (s, t) in order, the time at which the trajectory point at s
//! is reached. Between two pairs both vary linearly (constant speed from one vertex to the
//! next, the reading of esmini and of the standard's examples); two pairs at one s are a
//! stop, two at one t a jump.

use opendrive::Real;

/// Non-decreasing arc lengths (m) and trajectory times (s), at least two pairs.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct TimeTable {
    s: Vec<Real>,
    t: Vec<Real>,
}

impl TimeTable {
    /// A table of (s, t) pairs, both non-decreasing (checked by the caller), at least two.
    pub(crate) fn new(pairs: Vec<(Real, Real)>) -> Self {
        debug_assert!(pairs.len() >= 2);
        let (s, t) = pairs.into_iter().unzip();
        Self { s, t }
    }

    /// Trajectory time of the first pair (s).
    pub(crate) fn start(&self) -> Real {
        self.t[0]
    }

    /// Trajectory time of the last pair (s).
    pub(crate) fn end(&self) -> Real {
        self.t[self.t.len() - 1]
    }

    /// The time at which s is reached (the first such time where the trajectory stops at s);
    /// clamped to the table's ends.
    pub(crate) fn t_at(&self, s: Real) -> Real {
        interpolate(&self.s, &self.t, s)
    }

    /// Arc length at trajectory time `t`, clamped to the table's ends.
    pub(crate) fn s_at(&self, t: Real) -> Real {
        interpolate(&self.t, &self.s, t)
    }

    /// ds/dt (m/s) at trajectory time `t`: the slope of the pair interval holding t (the later
    /// one at a pair's time); 0 outside the table.
    pub(crate) fn speed_at(&self, t: Real) -> Real {
        if t < self.start() || t >= self.end() {
            return 0.0;
        }
        let i = self.t.partition_point(|&x| x <= t);
        let dt = self.t[i] - self.t[i - 1];
        if dt > 0.0 {
            (self.s[i] - self.s[i - 1]) / dt
        } else {
            0.0
        }
    }

    /// ds/dt (m/s) on arrival at the last pair: the slope of the last interval of positive
    /// duration (0 if the table has none, or ends in a stop).
    pub(crate) fn arrival_speed(&self) -> Real {
        let n = self.t.len();
        (1..n)
            .rev()
            .find(|&i| self.t[i] > self.t[i - 1])
            .map_or(0.0, |i| {
                (self.s[i] - self.s[i - 1]) / (self.t[i] - self.t[i - 1])
            })
    }

    /// The speed-continuous reading of the table for `follow` mode, starting at `v_start`
    /// (m/s of trajectory time, ≥ 0): per pair interval its speeds (begin, end), the speed
    /// varying linearly in time over the interval and covering it exactly, and each interval
    /// beginning at the speed the last one ended with: the end speed is 2·Δs/Δt − begin. A
    /// timed vertex is then reached on time with no jump of speed, which the linear reading's
    /// constant speed per interval cannot give. Where that end speed would be negative (the
    /// interval is too short for the speed brought into it) the interval keeps the linear
    /// reading, constant Δs/Δt, and the speed jumps at its start; a jump in time (Δt = 0)
    /// passes the speed on.
    pub(crate) fn continuous_speeds(&self, v_start: Real) -> Vec<(Real, Real)> {
        let mut v = v_start.max(0.0);
        (1..self.s.len())
            .map(|i| {
                let (ds, dt) = (self.s[i] - self.s[i - 1], self.t[i] - self.t[i - 1]);
                if dt <= 0.0 {
                    return (v, v);
                }
                let end = 2.0 * ds / dt - v;
                let speeds = if end >= 0.0 {
                    (v, end)
                } else {
                    (ds / dt, ds / dt)
                };
                v = speeds.1;
                speeds
            })
            .collect()
    }

    /// Arc length at trajectory time `t` on the reading `speeds` of
    /// [`continuous_speeds`](Self::continuous_speeds), clamped to the table's ends.
    pub(crate) fn s_at_continuous(&self, speeds: &[(Real, Real)], t: Real) -> Real {
        let last = self.t.len() - 1;
        if t <= self.t[0] {
            return self.s[0];
        }
        if t >= self.t[last] {
            return self.s[last];
        }
        let i = self.t.partition_point(|&x| x < t).clamp(1, last);
        let (t0, t1) = (self.t[i - 1], self.t[i]);
        let Some(&(begin, end)) = speeds.get(i - 1).filter(|_| t1 > t0) else {
            return self.s[i];
        };
        let tau = t - t0;
        let s = self.s[i - 1] + begin * tau + (end - begin) * tau * tau / (2.0 * (t1 - t0));
        s.clamp(self.s[i - 1], self.s[i])
    }
}

/// y at x on the piecewise-linear graph through (xs, ys), xs non-decreasing: the first
/// interval whose end reaches x, so that a flat stretch of y answers its start.
fn interpolate(xs: &[Real], ys: &[Real], x: Real) -> Real {
    let last = xs.len() - 1;
    if x <= xs[0] {
        return ys[0];
    }
    if x >= xs[last] {
        return ys[last];
    }
    let i = xs.partition_point(|&v| v < x).clamp(1, last);
    let (x0, x1) = (xs[i - 1], xs[i]);
    if x1 > x0 {
        ys[i - 1] + (x - x0) / (x1 - x0) * (ys[i] - ys[i - 1])
    } else {
        ys[i]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stop_and_constant_speed() {
        // 0 m at 0 s, 10 m at 2 s (5 m/s), stop at 10 m until 4 s, 20 m at 6 s.
        let tt = TimeTable::new(vec![(0.0, 0.0), (10.0, 2.0), (10.0, 4.0), (20.0, 6.0)]);
        assert!((tt.s_at(1.0) - 5.0).abs() < 1e-12);
        assert!((tt.s_at(3.0) - 10.0).abs() < 1e-12);
        assert!((tt.s_at(5.0) - 15.0).abs() < 1e-12);
        // s = 10 is first reached at 2 s.
        assert!((tt.t_at(10.0) - 2.0).abs() < 1e-12);
        assert!((tt.t_at(15.0) - 5.0).abs() < 1e-12);
        assert!((tt.speed_at(1.0) - 5.0).abs() < 1e-12);
        assert!(tt.speed_at(3.0).abs() < 1e-12);
        assert!((tt.s_at(-1.0)).abs() < 1e-12 && (tt.s_at(9.0) - 20.0).abs() < 1e-12);
        // Arrival at 20 m over the last interval: 10 m in 2 s.
        assert!((tt.arrival_speed() - 5.0).abs() < 1e-12);
        // A table ending in a stop arrives at rest.
        let stop = TimeTable::new(vec![(0.0, 0.0), (10.0, 2.0), (10.0, 4.0)]);
        assert!(stop.arrival_speed().abs() < 1e-12);
    }

    #[test]
    fn continuous_reading_reaches_each_pair_on_time_without_a_speed_jump() {
        // bicycle_fall_over.xosc's vertices: 100 m at 0 s, 120 at 2, 125 at 2.5, 130 at 3.5,
        // 130 at 4, from 10 m/s. End speeds 2·Δs/Δt − begin: 2·20/2 − 10 = 10,
        // 2·5/0.5 − 10 = 10, 2·5/1 − 10 = 0, 2·0/0.5 − 0 = 0.
        let tt = TimeTable::new(vec![
            (100.0, 0.0),
            (120.0, 2.0),
            (125.0, 2.5),
            (130.0, 3.5),
            (130.0, 4.0),
        ]);
        let v = tt.continuous_speeds(10.0);
        assert_eq!(v, vec![(10.0, 10.0), (10.0, 10.0), (10.0, 0.0), (0.0, 0.0)]);
        // Braking 10 → 0 m/s over 2.5 .. 3.5 s: s(2.8) = 125 + 10·0.3 − 10·0.09/2 = 127.55
        // (esmini's reference row at 2.8 s), s(3.0) = 125 + 5 − 1.25 = 128.75.
        assert!((tt.s_at_continuous(&v, 2.8) - 127.55).abs() < 1e-12);
        assert!((tt.s_at_continuous(&v, 3.0) - 128.75).abs() < 1e-12);
        for (s, t) in [(120.0, 2.0), (125.0, 2.5), (130.0, 3.5), (130.0, 3.9)] {
            assert!((tt.s_at_continuous(&v, t) - s).abs() < 1e-12, "{t}");
        }
        // Too fast for a short interval: 20 m/s into 5 m in 1 s would end at −10 m/s, so the
        // interval keeps its linear 5 m/s (and the next begins from it).
        let short = TimeTable::new(vec![(0.0, 0.0), (5.0, 1.0), (15.0, 2.0)]);
        let v = short.continuous_speeds(20.0);
        assert_eq!(v, vec![(5.0, 5.0), (5.0, 15.0)]);
        assert!((short.s_at_continuous(&v, 0.5) - 2.5).abs() < 1e-12);
    }
}
