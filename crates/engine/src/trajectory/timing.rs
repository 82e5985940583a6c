//! `TimeReference` and `Timing` of FollowTrajectoryAction (OpenSCENARIO 1.3 §6.9
//! "Trajectories", XSD `TimeReference`, `Timing`): the trajectory's own times map to simulation
//! time as t_sim = t_traj · scale + offset, where t_sim counts from the start of the
//! simulation (`domainAbsoluteRelative="absolute"`) or from the start of the action
//! (`"relative"`).
//!
//! With `initialDistanceOffset` d the trajectory is logically truncated at d and "the time that
//! would be taken to reach this point is deducted from all calculated waypoint time values"
//! (OpenSCENARIO 1.3, FollowTrajectoryAction/@initialDistanceOffset): the clock then reads
//! t_traj = (t_sim − offset)/scale + (T(d) − T(0)), see [`TrajectoryClock::skipping`].
//!
//! Without a TimeReference (XSD `TimeReference/None`) the times are ignored and the action
//! controls the lateral domain only: the entity keeps its own longitudinal motion along the
//! trajectory (OpenSCENARIO 1.3 §6.9; semantics-pitfalls #7). With Timing it controls both.

use opendrive::Real;
use scenario::{ReferenceContext, SourcePos, Timing};

use super::error::{check_finite, TrajectoryError, TrajectoryErrorKind};

/// Whether FollowTrajectoryAction with this time reference controls the longitudinal domain
/// (only with `Timing`; with `None` it is lateral only).
pub fn controls_longitudinal(time_reference: Option<&Timing>) -> bool {
    time_reference.is_some()
}

/// The clock of one FollowTrajectoryAction: its Timing and the simulation time it started.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrajectoryClock {
    relative: bool,
    offset: Real,
    scale: Real,
    action_start: Real,
    /// Trajectory time skipped by initialDistanceOffset (s), added to every reading.
    skipped: Real,
}

impl TrajectoryClock {
    /// The clock of `timing` for an action started at simulation time `action_start` (s).
    /// `pos` names the action for errors: a scale that is not finite and > 0, or a
    /// non-finite offset.
    pub fn new(
        timing: &Timing,
        action_start: Real,
        pos: &SourcePos,
    ) -> Result<Self, TrajectoryError> {
        check_finite(
            &[
                ("Timing offset", timing.offset),
                ("action start time", action_start),
            ],
            pos,
        )?;
        if !(timing.scale.is_finite() && timing.scale > 0.0) {
            return Err(TrajectoryError::new(
                TrajectoryErrorKind::Scale(timing.scale),
                pos,
            ));
        }
        Ok(Self {
            relative: timing.domain_absolute_relative == ReferenceContext::Relative,
            offset: timing.offset,
            scale: timing.scale,
            action_start,
            skipped: 0.0,
        })
    }

    /// This clock with `skipped` seconds of trajectory time deducted from every waypoint time:
    /// for an action that starts `initialDistanceOffset` into the trajectory, `skipped` is the
    /// trajectory time from the start to that point. A non-finite `skipped` is ignored.
    pub fn skipping(self, skipped: Real) -> Self {
        Self {
            skipped: if skipped.is_finite() { skipped } else { 0.0 },
            ..self
        }
    }

    /// The trajectory time at simulation time `sim_time`: (t_sim − offset)/scale, with t_sim
    /// counted from the action's start when relative, plus the skipped time.
    pub fn trajectory_time(&self, sim_time: Real) -> Real {
        let reference = if self.relative {
            sim_time - self.action_start
        } else {
            sim_time
        };
        (reference - self.offset) / self.scale + self.skipped
    }

    /// The simulation time of trajectory time `t`: (t − skipped) · scale + offset (+ the
    /// action's start when relative).
    pub fn simulation_time(&self, t: Real) -> Real {
        let reference = (t - self.skipped) * self.scale + self.offset;
        if self.relative {
            reference + self.action_start
        } else {
            reference
        }
    }

    /// d(trajectory time)/d(simulation time) = 1/scale.
    pub fn rate(&self) -> Real {
        1.0 / self.scale
    }
}
