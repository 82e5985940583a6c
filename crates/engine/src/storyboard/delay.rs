//! Condition delay as a shift in time, OpenSCENARIO 1.3 class `Condition` (attribute `delay`).
//!
//! The standard defines `delay` as the "time elapsed after the edge condition is verified, until
//! the condition returns true to the scenario". oscsim therefore applies the edge first
//! ([`EdgeDetector`](super::EdgeDetector)) and delays its output: at time t the condition reports
//! the edge output it had at t − delay, and false before the first sample that old. This is a
//! shift of the whole signal, not a timer started once: a condition that was true for 0.5 s is
//! reported true for 0.5 s, `delay` seconds later, and an AND with another condition sees the
//! shifted signal (esmini issues #202, #237, #371 discuss engines that latch instead).
//!
//! Samples arrive at the simulation's fixed steps, so t − delay is looked up with half a step of
//! slack: the shift is rounded to the nearest step (a delay of 0.25 s at dt = 0.1 s shifts by
//! 0.2 s or 0.3 s depending on float rounding, never by more than half a step off). The line only
//! stores the times at which the value changed, so its length is the number of changes within the
//! last `delay` seconds.

use std::collections::VecDeque;

/// The delayed output of one condition.
#[derive(Debug, Clone, PartialEq)]
pub struct DelayLine {
    delay: f64,
    /// `(time, value)` at each change of the value, oldest first; the value before the first
    /// entry is false.
    changes: VecDeque<(f64, bool)>,
}

impl DelayLine {
    /// A line shifting by `delay` seconds (`delay` ≥ 0 and finite; checked when the storyboard
    /// is built).
    pub fn new(delay: f64) -> Self {
        DelayLine {
            delay,
            changes: VecDeque::new(),
        }
    }

    /// The delay in seconds.
    pub fn delay(&self) -> f64 {
        self.delay
    }

    /// Forgets all samples.
    pub fn reset(&mut self) {
        self.changes.clear();
    }

    /// Records `value` at `time` and returns the value at `time − delay` (false if no sample
    /// is that old). `dt` is the step length, used as the rounding slack (half a step). Times
    /// must not decrease between calls.
    pub fn update(&mut self, time: f64, dt: f64, value: bool) -> bool {
        let last = self.changes.back().is_some_and(|&(_, v)| v);
        if value != last {
            self.changes.push_back((time, value));
        }
        let target = time - self.delay + 0.5 * dt;
        // Drop changes superseded by a later change that is itself old enough.
        while self.changes.len() > 1 && self.changes[1].0 <= target {
            self.changes.pop_front();
        }
        match self.changes.front() {
            Some(&(at, v)) if at <= target => v,
            // No change old enough: the value before the first change, false.
            _ => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Feeds `values` at t = k·dt and returns the outputs.
    fn run(delay: f64, dt: f64, values: &[bool]) -> Vec<bool> {
        let mut line = DelayLine::new(delay);
        values
            .iter()
            .enumerate()
            .map(|(k, &v)| line.update(k as f64 * dt, dt, v))
            .collect()
    }

    #[test]
    fn zero_delay_is_the_identity() {
        let values = [false, true, true, false, true];
        assert_eq!(run(0.0, 0.1, &values), values);
    }

    #[test]
    fn a_pulse_is_shifted_not_latched() {
        // Input true at k = 1, 2 (t = 0.1, 0.2); delay 0.3 s = 3 steps, so the output is true
        // at k = 4, 5 (t = 0.4, 0.5) and false again at k = 6, where a timer would stay true.
        let values = [false, true, true, false, false, false, false, false];
        assert_eq!(
            run(0.3, 0.1, &values),
            [false, false, false, false, true, true, false, false]
        );
    }

    #[test]
    fn before_the_first_old_enough_sample_the_output_is_false() {
        // Always true, delay 0.2 s at dt 0.1 s: false at t = 0, 0.1; true from t = 0.2.
        assert_eq!(run(0.2, 0.1, &[true; 4]), [false, false, true, true]);
    }

    #[test]
    fn the_shift_is_rounded_to_the_nearest_step() {
        // delay 0.26 s at dt 0.1 s is 2.6 steps, rounded to 3: the rising edge at k = 1 shows at
        // k = 4.
        let values = [false, true, true, true, true, true];
        assert_eq!(
            run(0.26, 0.1, &values),
            [false, false, false, false, true, true]
        );
    }

    #[test]
    fn only_changes_are_stored() {
        let mut line = DelayLine::new(1.0);
        for k in 0..100 {
            line.update(k as f64 * 0.1, 0.1, true);
        }
        assert_eq!(line.changes.len(), 1);
    }
}
