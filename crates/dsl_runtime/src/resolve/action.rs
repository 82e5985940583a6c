//! The movement actions of the standard library by name (ASAM OpenSCENARIO DSL 2.1 §8.8): what
//! an invocation's action is, for the modifiers it implies, the places it takes and the phase
//! tree.

/// The movement actions of the standard library (ASAM OpenSCENARIO DSL 2.1 §8.8).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Action {
    /// `move()`, `drive()`, `walk()`: motion set by the modifiers alone.
    Move,
    /// `remain_stationary()`.
    RemainStationary,
    /// `assign_position(…)`.
    AssignPosition,
    /// `assign_orientation(…)`.
    AssignOrientation,
    /// `assign_speed(…)`.
    AssignSpeed,
    /// `assign_acceleration(…)`.
    AssignAcceleration,
    /// `change_position(…)`.
    ChangePosition,
    /// `change_speed(…)`.
    ChangeSpeed,
    /// `keep_speed()`.
    KeepSpeed,
    /// `change_acceleration(…)`.
    ChangeAcceleration,
    /// `keep_acceleration()`.
    KeepAcceleration,
    /// `follow_path(…)`.
    FollowPath,
    /// `follow_trajectory(…)`.
    FollowTrajectory,
    /// `replay_path(…)`: a path followed exactly (the dynamic limits may be violated).
    ReplayPath,
    /// `replay_trajectory(…)`: a trajectory followed exactly.
    ReplayTrajectory,
    /// `follow_lane(…)`.
    FollowLane,
    /// `change_lane(…)`.
    ChangeLane,
    /// `change_space_gap(…)`.
    ChangeSpaceGap,
    /// `keep_space_gap(…)`.
    KeepSpaceGap,
    /// `change_time_headway(…)`.
    ChangeTimeHeadway,
    /// `keep_time_headway(…)`.
    KeepTimeHeadway,
    /// An action the program declares itself.
    Other,
}

impl Action {
    /// Whether the action moves along a path (no time stamps): `follow_path`, `replay_path`.
    pub(crate) fn along_path(self) -> bool {
        matches!(self, Action::FollowPath | Action::ReplayPath)
    }

    /// The standard library's action named `name`.
    pub(super) fn of_library(name: &str) -> Action {
        match name {
            "move" | "drive" | "walk" => Action::Move,
            "remain_stationary" => Action::RemainStationary,
            "assign_position" => Action::AssignPosition,
            "assign_orientation" => Action::AssignOrientation,
            "assign_speed" => Action::AssignSpeed,
            "assign_acceleration" => Action::AssignAcceleration,
            "change_position" => Action::ChangePosition,
            "change_speed" => Action::ChangeSpeed,
            "keep_speed" => Action::KeepSpeed,
            "change_acceleration" => Action::ChangeAcceleration,
            "keep_acceleration" => Action::KeepAcceleration,
            "follow_path" => Action::FollowPath,
            "follow_trajectory" => Action::FollowTrajectory,
            "replay_path" => Action::ReplayPath,
            "replay_trajectory" => Action::ReplayTrajectory,
            "follow_lane" => Action::FollowLane,
            "change_lane" => Action::ChangeLane,
            "change_space_gap" => Action::ChangeSpaceGap,
            "keep_space_gap" => Action::KeepSpaceGap,
            "change_time_headway" => Action::ChangeTimeHeadway,
            "keep_time_headway" => Action::KeepTimeHeadway,
            _ => Action::Other,
        }
    }
}
