//! Private actions (OpenSCENARIO 1.3, "Actions", XSD `PrivateAction` and its
//! choices): longitudinal, lateral, visibility, synchronize, controller, teleport, routing,
//! appearance, trailer. Speeds m/s, distances m, times s, angles rad.

use crate::model::{AnimationAction, LightStateAction, OverrideControllerValueAction};
use crate::model::{
    Controller, CoordinateSystem, DynamicsDimension, DynamicsShape, FollowingMode,
    LateralDisplacement, LongitudinalDisplacement, Position, ReferenceContext, Route,
    SpeedTargetValueType, Trajectory,
};

/// Private actions (XSD `PrivateAction`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum PrivateAction {
    /// LongitudinalAction.
    Longitudinal(LongitudinalAction),
    /// LateralAction.
    Lateral(LateralAction),
    /// VisibilityAction.
    Visibility(VisibilityAction),
    /// SynchronizeAction.
    Synchronize(Box<SynchronizeAction>),
    /// ControllerAction (the deprecated direct ActivateControllerAction reads as its
    /// ActivateController form).
    Controller(Box<ControllerAction>),
    /// TeleportAction.
    Teleport(Position),
    /// RoutingAction.
    Routing(Box<RoutingAction>),
    /// AppearanceAction (1.2+).
    Appearance(AppearanceAction),
    /// TrailerAction (1.3).
    Trailer(TrailerAction),
    /// oscsim's state check, an action with no XML form (the DSL runtime writes it for what
    /// its plan cannot decide before the run: an `at: start` constraint of a phase that starts
    /// on a run-time condition, ASAM OpenSCENARIO DSL 2.1 §8.9; the XML reader never does):
    /// when it starts, the actor's state must be as given, else the action fails (an error
    /// record in the event log, and the run stops with that error). It ends in the step it
    /// starts.
    Check(Box<StateCheck>),
    /// oscsim's creation of random traffic, an action with no XML form (the DSL runtime
    /// writes it for a `random_traffic_vehicle_group` created where its plan does not know
    /// every other vehicle's place, ASAM OpenSCENARIO DSL 2.1 §8.7.18.1; the XML reader never
    /// does): when it starts, the members it names (its actor the first of them) are dealt
    /// among the places the other vehicles have then by [`crate::traffic_deal`]'s rule and
    /// put there at rest (the DSL runtime's SpeedAction and ActivateControllerAction after it
    /// give each its start speed and driver). No room: the action fails (an error record in
    /// the event log, and the run stops with that error). It ends in the step it starts.
    CreateRandomTraffic(Box<RandomTrafficCreation>),
}

/// What oscsim's creation of random traffic ([`PrivateAction::CreateRandomTraffic`]) deals.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RandomTrafficCreation {
    /// The group's name, for the error.
    pub group: String,
    /// The members (entity names) and their start speeds (m/s), drawn by the plan from the
    /// run's seed.
    pub members: Vec<(String, f64)>,
    /// The roads the lanes run over, in +s order: OpenDRIVE road id and the s along the
    /// roads where it starts (m; the lanes' ids are the same on each).
    pub roads: Vec<(String, f64)>,
    /// The roads' length together (m): a distance u against s is the s of `length` − u.
    pub length: f64,
    /// The lanes the members may be dealt to, each over its stretch of the roads.
    pub lanes: Vec<crate::traffic_deal::LaneSpan>,
    /// Another entity and a lane count: only the lane that many lanes to the left (right when
    /// negative) of that entity's lane when the action starts, in the entity's direction of
    /// travel (0: its lane), and among `lanes`.
    pub beside: Option<(String, i64)>,
    /// The seed of the action's draws ([`crate::traffic_deal::Draws`]), drawn by the plan
    /// from the run's seed.
    pub seed: u64,
}

/// What a speed change at a rate ([`StateCheck::speed_at_rate`]) must be done within.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RateWithin {
    /// The phase's length (s): at rate a the change takes \|v − v₀\|/a.
    Time(f64),
    /// The distance (m) that ends the phase (`distance(d)`): at rate a the change covers
    /// \|v² − v₀²\|/(2a).
    Distance(f64),
}

/// What oscsim's state check ([`PrivateAction::Check`]) requires of its actor when it starts
/// (the default requires nothing).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StateCheck {
    /// What is checked and where it is written, for the error ("lane(1) at f.osc:29:13").
    pub what: String,
    /// The lane the actor must be in: OpenDRIVE road id and lane id.
    pub lane: Option<(String, i32)>,
    /// Another entity and a lane count: the actor must be in the lane that many lanes to the
    /// left (right when negative) of that entity's lane, counted as a LaneChangeAction's
    /// RelativeTargetLane counts them (in the entity's direction of travel, skipping lane 0).
    pub lane_of: Option<(String, i32)>,
    /// A mark noted before on the actor and a lane count: the actor must be on the road it
    /// was on then, in the lane that many lanes to the left (right when negative) of the lane
    /// it was in, counted as a RelativeTargetLane counts them (ASAM OpenSCENARIO DSL 2.1 §8.9
    /// `keep_lane()` (0), `change_lane(n, side)` at the end of a phase that starts on a
    /// run-time condition, where the plan does not know that lane).
    pub lane_at_mark: Option<(String, i32)>,
    /// The actor's s on that road (m, its reference point) and the tolerance (m).
    pub s: Option<(f64, f64)>,
    /// The actor's lateral offset from its lane's centre (m, positive left) and the tolerance
    /// (m).
    pub offset: Option<(f64, f64)>,
    /// The actor's lateral offset from its lane's centre as k·W + c (m, positive left), W the
    /// lane's width where the actor is (m), given as (k, c) with the tolerance (m): an offset
    /// measured from a border of the lane (ASAM OpenSCENARIO DSL 2.1 §8.9 `lateral(d,
    /// measure_by)`, in a phase that starts on a run-time condition, where the plan does not
    /// know the width there).
    pub offset_in_width: Option<(f64, f64, f64)>,
    /// Where the actor must be along the road relative to another entity, and the tolerance
    /// (m).
    pub gap: Option<(SpeedGap, f64)>,
    /// Another entity, the actor's t minus that entity's (m, road coordinates, reference
    /// points, positive when the actor is to its left), and the tolerance (m).
    pub beside: Option<(String, f64, f64)>,
    /// Another entity and a t (m, positive left): the point that far across the road from the
    /// entity's t at the actor's s must lie in a driving lane of the actor's side of the road
    /// (ASAM OpenSCENARIO DSL 2.1 §8.8.3 `change_space_gap` to the left or right, in a phase
    /// that starts on a run-time condition: the place the gap puts the actor, which the plan
    /// checks at a known start).
    pub beside_in_lane: Option<(String, f64)>,
    /// A place across a straight line in the world beside another entity (ASAM OpenSCENARIO
    /// DSL 2.1 §8.9 `lateral(d, side_of/left_of/right_of: x)` beside a walk along a crossing,
    /// §8.12.2.2.9: "beside x" across the crossing's line, the walk's route).
    pub across_line: Option<AcrossLine>,
    /// A speed change of the given shape over the given time (s) to the target, starting with
    /// the check (the SpeedAction beside it): its peak rate must fit the actor's Performance,
    /// which would otherwise stretch it in time (ASAM OpenSCENARIO DSL 2.1 §8.9 `speed(…,
    /// at: end)`, §8.8.2.12 `change_speed`, in a phase that starts on a run-time condition).
    pub speed_change: Option<(SpeedTarget, DynamicsShape, f64)>,
    /// A speed change to the target at the given rate (m/s², a SpeedAction of dimension
    /// `rate`), starting with the check: from the speed the actor has then it must be done
    /// within the phase, its length or the distance that ends it (ASAM OpenSCENARIO DSL 2.1
    /// §8.9 `change_speed`/`speed(…, at: end)` beside `acceleration(a)`, or beside
    /// `distance(d)` without a duration, in a phase that starts on a run-time condition; the
    /// phase's end would otherwise cut the change short).
    pub speed_at_rate: Option<(SpeedTarget, f64, RateWithin)>,
    /// An acceleration (m/s²) held over the given time (s), starting with the check (the
    /// AccelerationAction beside it): from the speed the actor has then it must end within 0
    /// and the actor's maximum speed (ASAM OpenSCENARIO DSL 2.1 §8.9 `acceleration(a)` alone,
    /// in a phase that starts on a run-time condition; the vehicle would otherwise stand, or
    /// stay at its top speed, with an acceleration of 0 before the phase ends).
    pub held_acceleration: Option<(f64, f64)>,
    /// The actor's speed (m/s): another entity's speed at the moment (`None`: 0) plus the
    /// value, and the tolerance (m/s).
    pub speed: Option<(Option<String>, f64, f64)>,
    /// A mark noted before on the actor, the distance (m) it must have travelled since (its
    /// odometer), and the tolerance (m).
    pub travelled: Option<(String, f64, f64)>,
    /// The roads the places are measured along (the default: the road the actor is on, in
    /// +s): on a plan over several roads `lane` holds on any of them (the lane ids are the
    /// same on each), and `s`, `gap` and the mark's gap measure the plan's s, a road's s plus
    /// its start; for an actor driving them against s ([`PlanRoads::against`]) `s`, `gap`,
    /// the mark's gap and every offset and t (`offset`, `offset_in_width`, `beside`,
    /// `beside_in_lane`) are measured along its direction of travel: u = L − s, t to its left.
    pub roads: PlanRoads,
    /// A mark the check notes on the actor when it runs (after the requirements above hold):
    /// its odometer, and with a gap its place relative to the gap's entity, for the conditions
    /// [`crate::EntityCondition::TraveledSinceMark`] and
    /// [`crate::EntityCondition::GapReachedSinceMark`] and a later check's `travelled`.
    pub mark: Option<Mark>,
    /// The actor's heading (ASAM OpenSCENARIO DSL 2.1 §8.9 `yaw`/`orientation` measured in the
    /// world or from another object, where the plan does not know the actor's place: a phase
    /// that starts on a run-time condition, or an end it does not know).
    pub heading: Option<HeadingCheck>,
    /// The requirements hold at every step from the check's start until it is stopped (its
    /// phase's end), not only when it starts: the action runs until then, checking them again
    /// in each step (§8.9 `at: all`); a mark is noted at the start only.
    pub throughout: bool,
    /// Held ([`Self::throughout`]): the entity of `gap` and `lane_of` is read as projected from
    /// the check's start (ASAM OpenSCENARIO DSL 2.1 §8.9.1.1.3 `track: projected`): along its
    /// lane at the speed it has then (a time gap at that speed), in its lane then, whatever it
    /// does after.
    pub projected: bool,
}

/// A place a [`StateCheck`] requires of its actor across a straight line in the world, beside
/// another entity (oscsim, no XML form; see [`StateCheck::across_line`]): with `n` the line's
/// unit normal, the entity's box (its footprint, turned to its heading) projected on `n` the
/// interval [lo, hi], the actor's reference point projected on `n` minus (lo + hi)/2 must be
/// `per_extent`·(hi − lo) + `offset` within `tolerance`.
#[derive(Debug, Clone, PartialEq)]
pub struct AcrossLine {
    /// The other entity.
    pub entity_ref: String,
    /// The line's unit normal in the road network's inertial frame (x, y); "across" is
    /// measured along it.
    pub normal: (f64, f64),
    /// The factor of the entity's extent across the line (m/m): ½ measured to the side of its
    /// box towards +`normal`, −½ to the other, 0 to its middle.
    pub per_extent: f64,
    /// The rest of the actor's place across the line from the middle of the entity's box (m).
    pub offset: f64,
    /// How far the actor's place may be from the one asked (m).
    pub tolerance: f64,
}

/// A heading a [`StateCheck`] requires of its actor (oscsim, no XML form): the heading `from`
/// gives plus `angle`, within `tolerance`, in the road network's inertial frame (OpenDRIVE's
/// x, y; counter-clockwise about z from +x, as OpenSCENARIO 1.x counts a heading).
#[derive(Debug, Clone, PartialEq)]
pub struct HeadingCheck {
    /// What the angle is measured from.
    pub from: HeadingFrom,
    /// The angle added to it (rad).
    pub angle: f64,
    /// How far from the heading asked the actor's may be (rad).
    pub tolerance: f64,
    /// The measure and angle as the scenario gives them, for the error ("absolute 0.7854 rad",
    /// "length_to_width from `npc` 1.5708 rad").
    pub measure: String,
}

/// What a [`HeadingCheck`]'s angle is measured from.
#[derive(Debug, Clone, PartialEq)]
pub enum HeadingFrom {
    /// The inertial frame's +x (0).
    World,
    /// Another entity's heading at the moment.
    Entity(String),
    /// The heading of the road's s-axis where the actor is.
    Road,
}

/// The roads an OpenSCENARIO DSL plan measures an actor's places along, and in which
/// direction (oscsim, no XML form; ASAM OpenSCENARIO DSL 2.1 §8.9 places measured along the
/// actor's route; ASAM OpenDRIVE 1.8 §11.2 lanes driven in −s). The default is one road, the
/// one the actor is on, in +s: what the engine measured before plans over several roads and
/// actors driving against s, so every 1.x scenario and every earlier output is unchanged.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PlanRoads {
    /// The roads of a plan over several roads, each with the plan's s at its start (m, a
    /// road's s plus the lengths of the roads before it), in +s order (empty: one road, the
    /// one the actor is on, in its own s).
    pub chain: Vec<(String, f64)>,
    /// The actor drives the roads against s (oncoming traffic in a lane driven in −s): its
    /// places are measured along its direction of travel, in u = L − s (L the length of the
    /// roads: the chain's, or the one road's) and with t to its left (−t).
    pub against: bool,
}

/// A mark a [`StateCheck`] notes (see [`StateCheck::mark`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    /// Its name, unique in the scenario.
    pub name: String,
    /// The place relative to another entity whose side the mark notes: the actor's s minus the
    /// entity's less [`SpeedGap::offset`] at the entity's speed then.
    pub gap: Option<SpeedGap>,
    /// With a gap: the gap's entity is taken as projected from the mark on (ASAM OpenSCENARIO
    /// DSL 2.1 §8.9.1.1.3 `track: projected`): along its lane at the speed it has then, the
    /// gap at that speed.
    pub projected: bool,
}

/// A place along the road relative to another entity, at a distance that may depend on that
/// entity's speed v at the moment it is measured: the actor's s minus the entity's (reference
/// points) is ±max(time·|v|, at_least) m, + when the actor is ahead.
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedGap {
    /// The other entity.
    pub entity_ref: String,
    /// The actor ahead of the entity (else behind it).
    pub ahead: bool,
    /// The time at the entity's speed (s).
    pub time: f64,
    /// The least distance (m).
    pub at_least: f64,
}

impl SpeedGap {
    /// The actor's s minus the entity's when the entity moves at `v` (m/s).
    pub fn offset(&self, v: f64) -> f64 {
        let d = (self.time * v.abs()).max(self.at_least);
        if self.ahead {
            d
        } else {
            -d
        }
    }
}

/// A transition (XSD `TransitionDynamics`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TransitionDynamics {
    /// Shape.
    pub dynamics_shape: DynamicsShape,
    /// What `value` measures.
    pub dynamics_dimension: DynamicsDimension,
    /// Duration (s), distance (m) or rate (unit/s).
    pub value: f64,
    /// followingMode (1.2+).
    pub following_mode: Option<FollowingMode>,
}

/// Limits for distance keeping (XSD `DynamicConstraints`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DynamicConstraints {
    /// m/s².
    pub max_acceleration: Option<f64>,
    /// m/s³ (1.2+).
    pub max_acceleration_rate: Option<f64>,
    /// m/s².
    pub max_deceleration: Option<f64>,
    /// m/s³ (1.2+).
    pub max_deceleration_rate: Option<f64>,
    /// m/s.
    pub max_speed: Option<f64>,
}

/// Longitudinal actions (XSD `LongitudinalAction`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum LongitudinalAction {
    /// SpeedAction.
    Speed {
        /// SpeedActionDynamics.
        dynamics: TransitionDynamics,
        /// SpeedActionTarget.
        target: SpeedTarget,
    },
    /// LongitudinalDistanceAction.
    LongitudinalDistance {
        /// Reference entity.
        entity_ref: String,
        /// Keep it up.
        continuous: bool,
        /// Distance, m (exclusive with time_gap).
        distance: Option<f64>,
        /// Time gap, s.
        time_gap: Option<f64>,
        /// Between bounding boxes.
        freespace: bool,
        /// Displacement (1.1+).
        displacement: Option<LongitudinalDisplacement>,
        /// Frame (1.1+).
        coordinate_system: Option<CoordinateSystem>,
        /// Limits.
        dynamic_constraints: Option<DynamicConstraints>,
        /// oscsim's option, no XML form (the DSL runtime writes it for ASAM OpenSCENARIO DSL
        /// 2.1 §8.8.3 `keep_space_gap` / `keep_time_headway` in a phase that starts on a
        /// run-time condition, whose gap to keep is the one at its start; the XML reader
        /// writes `None`): with `distance` and `time_gap` both absent, keep the distance or
        /// the time gap the engine measures when the action starts.
        at_start: Option<GapAtStart>,
        /// oscsim's option, no XML form (the DSL runtime writes it for ASAM OpenSCENARIO DSL
        /// 2.1 §8.9 `position(ahead_of/behind: x)` without a distance or time, held after a
        /// run-time start: oscsim's default gap, max(2 s · v_x, 10 m + the facing overhangs);
        /// the XML reader writes `None`): with `time_gap`, the distance kept is at least this
        /// (m): the larger of `time_gap` × the reference's speed and it, at every step.
        at_least: Option<f64>,
    },
    /// oscsim's AccelerationAction, an action with no XML form (the DSL runtime writes it for
    /// ASAM OpenSCENARIO DSL 2.1 §8.8.2 `assign_acceleration`, `change_acceleration` and
    /// `keep_acceleration`; the XML reader never does): the actor's longitudinal acceleration
    /// goes from its value at the start to `target` (`None`: the value at the start) under
    /// `dynamics` (`time`: over that duration; `rate`: at that peak jerk, m/s³; `step`: at
    /// once), then holds. The speed follows it; the action ends when the speed reaches 0 or
    /// the vehicle's maximum with the acceleration pushing past it, and otherwise runs until a
    /// later longitudinal action replaces it (or, with `ends_at_target`, when the transition
    /// is over).
    Acceleration {
        /// The acceleration to reach (m/s²); `None`: keep the one at the start.
        target: Option<f64>,
        /// How it is reached.
        dynamics: TransitionDynamics,
        /// The action ends in the step that completes the transition, the target reached
        /// (ASAM OpenSCENARIO DSL 2.1 §8.8.2.14: `change_acceleration` ends when its target
        /// acceleration is reached),
        /// instead of holding it: for a change whose length depends on the acceleration the
        /// engine finds at its start, so that the end is the engine's to tell.
        ends_at_target: bool,
    },
    /// oscsim's RelativeAccelerationAction, an action with no XML form (the DSL runtime writes
    /// it for ASAM OpenSCENARIO DSL 2.1 §8.9 `acceleration(…, faster_than/slower_than/same_as:
    /// x)` where x's acceleration over the phase is not the plan's to know; the XML reader
    /// never does): with `continuous`, in each step the actor's acceleration is
    /// `entity_ref`'s plus `value` (m/s²), so after τ s its speed is v₀ + (v_x − v_x₀) +
    /// value·τ (v₀, v_x₀ both speeds at the start, v_x the reference's now); without, the
    /// reference's acceleration at the start plus `value`, held. It ends as the
    /// AccelerationAction does (0 m/s or the vehicle's maximum speed with the acceleration
    /// pushing past it), and otherwise runs until a later longitudinal action replaces it.
    RelativeAcceleration {
        /// The reference entity.
        entity_ref: String,
        /// Added to the reference's acceleration (m/s²).
        value: f64,
        /// Follow the reference's acceleration in every step (else: its value at the start).
        continuous: bool,
        /// As the rate of a speed change (§8.9 `acceleration(…)` beside `change_speed` or
        /// `speed(…, at: end)`): the actor's speed moves toward this speed at the magnitude of
        /// the acceleration above and the action ends when it reaches it; not reached in time,
        /// the action fails. `None`: the acceleration itself, as above.
        to_speed: Option<Box<SpeedChange>>,
        /// A transition to that acceleration (DSL 2.1 §8.9.1.1.4 `acceleration(…, shape: s)`
        /// relative to x after a run-time start, the shape's `change_acceleration` dynamics):
        /// from the actor's acceleration at the start under these dynamics (a rate's span
        /// from the target read over the first step), reaching the reference's acceleration
        /// plus the value, then following it (`continuous`) or holding it. `None`: at once.
        transition: Option<TransitionDynamics>,
        /// With `transition`: the action ends in the step that completes it, as the
        /// AccelerationAction's `ends_at_target`.
        ends_at_target: bool,
    },
    /// oscsim's TravelAction, an action with no XML form (the DSL runtime writes it for a
    /// `position(…, at: end)` or `distance(…)` over a phase of known duration that starts on a
    /// run-time condition, ASAM OpenSCENARIO DSL 2.1 §8.9; the XML reader never does): when it
    /// starts, the engine works out from the actor's state then the profile of two linear
    /// halves the DSL plan uses (v₀ → v_m over T/2, v_m → v_e over T/2, v_m = (4·Δs/T − v₀ −
    /// v_e)/2) and runs it as a SpeedProfileAction in `position` mode. A profile outside
    /// `limits` (or not monotonous when asked) fails the action: an error record in the event
    /// log, and the run stops with that error.
    Travel(Box<Travel>),
    /// oscsim's free-road acceleration of a driver model, an action with no XML form (the DSL
    /// runtime writes it for ASAM OpenSCENARIO DSL 2.1 §8.9 `acceleration(…)` of a member of a
    /// `random_traffic_vehicle_group` in a phase of its own, §8.7.18.1: "the behavioral model
    /// assigned to each vehicle defines the actual behavior of the vehicle within the group"):
    /// handed to the `idm` or `mobil` model holding the entity's longitudinal domain, whose
    /// free-road term a·(1 − (v/v0)^δ) it replaces by `target` while the model's interaction
    /// term toward its leader still applies (the command is the target less that term), until
    /// an action with `None` gives the model its own free-road term back. Completes at once.
    ModelAcceleration {
        /// The free-road acceleration (`None`: release it).
        target: Option<ModelAcceleration>,
    },
    /// SpeedProfileAction (1.2+).
    SpeedProfile {
        /// Reference entity for relative speeds.
        entity_ref: Option<String>,
        /// followingMode.
        following_mode: FollowingMode,
        /// Limits.
        dynamic_constraints: Option<DynamicConstraints>,
        /// Entries: (speed m/s, time s).
        entries: Vec<SpeedProfileEntry>,
    },
}

/// The free-road acceleration a [`LongitudinalAction::ModelAcceleration`] hands a driver model.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ModelAcceleration {
    /// This acceleration (m/s², along the direction of travel).
    Absolute(f64),
    /// `entity_ref`'s acceleration plus `value` (m/s²): with `continuous`, its acceleration as
    /// the model reads it at each step's start (over the step before), else the one it has
    /// when the action starts, held.
    Relative {
        /// The reference entity.
        entity_ref: String,
        /// Added to the reference's acceleration (m/s²).
        value: f64,
        /// Read at every step (else once, when the action starts).
        continuous: bool,
    },
    /// The rate of a change to `speed` (m/s): the model's desired speed becomes `speed`, and
    /// its free-road term is `rate`'s value (an `Absolute` or `Relative` one) in magnitude,
    /// signed toward `speed`, the last step's term cut so that the step ends at `speed`, until
    /// the entity's speed reaches `speed`; from then the model's own free-road term (toward
    /// `speed`, its desired speed). A later speed or free-road acceleration replaces it.
    /// With `of` (oscsim's relative target, ASAM OpenSCENARIO DSL 2.1 §8.9 `speed(v,
    /// faster_than/slower_than/same_as: x, at: end)` at the rate of `acceleration(…)`), the
    /// speed is that entity's plus `speed`: its speed as the action starts, fixed
    /// (`projected`), else read at every step's start, the model's desired speed following it
    /// and the rate kept toward it (cut in the step that reaches it) until a later action
    /// replaces or releases it.
    Toward {
        /// The speed the change ends at (m/s); with `of`, added to that entity's speed.
        speed: f64,
        /// Its rate (m/s²; the sign is the change's).
        rate: Box<ModelAcceleration>,
        /// The entity whose speed `speed` is added to (`None`: `speed` itself).
        of: Option<SpeedOf>,
    },
}

/// The speed change a RelativeAccelerationAction's acceleration is the rate of
/// ([`LongitudinalAction::RelativeAcceleration`]).
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedChange {
    /// What is asked and where it is written, for the error ("acceleration(…) at f.osc:9:13").
    pub what: String,
    /// The speed to reach (m/s); with [`SpeedChange::of`], added to that entity's speed.
    pub speed: f64,
    /// oscsim's relative target, no XML form (ASAM OpenSCENARIO DSL 2.1 §8.9
    /// `speed(same_as/faster_than/slower_than: x, at: end)` at the rate of another actor's
    /// acceleration, in a phase that starts on a run-time condition): the speed to reach is
    /// this entity's plus [`SpeedChange::speed`]. `None`: `speed` itself.
    pub of: Option<SpeedOf>,
    /// The time from the action's start within which it must be reached (s): else an error
    /// record in the event log, and the run stops with that error.
    pub within: f64,
}

/// The entity whose speed a [`SpeedChange`] aims at ([`SpeedChange::of`]).
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedOf {
    /// The entity.
    pub entity_ref: String,
    /// Its speed as the action starts, fixed (ASAM OpenSCENARIO DSL 2.1 §8.9.1.1.3 `track:
    /// projected`); else read in every step, the change toward it and, once there, following
    /// it at the same rate until the action is stopped (`track: actual`: "the vehicle reacts
    /// to the behavior of the referenced vehicle"), so the action does not end by itself.
    pub projected: bool,
}

/// What a LongitudinalDistanceAction with `at_start` keeps: the value of its kind the engine
/// measures when it starts ([`LongitudinalAction::LongitudinalDistance`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GapAtStart {
    /// The distance (between bounding boxes with `freespace`), as `distance` would give it.
    Distance,
    /// The time gap: the distance over the reference's speed, as `timeGap` would give it.
    TimeGap,
}

/// What oscsim's TravelAction ([`LongitudinalAction::Travel`]) covers, and how.
#[derive(Debug, Clone, PartialEq)]
pub struct Travel {
    /// What is asked and where it is written, for the error ("position(…) at f.osc:29:13").
    pub what: String,
    /// Where the actor must be at the end.
    pub goal: TravelGoal,
    /// The duration T (s) from the action's start.
    pub duration: f64,
    /// The speed at the end (m/s); `None`: the speed the actor has at the start.
    pub end_speed: Option<f64>,
    /// The speed at the end as another entity's at the start plus a value (m/s), in place of
    /// `end_speed`.
    pub end_speed_of: Option<(String, f64)>,
    /// The speed only rises or only falls (v_m between v₀ and v_e).
    pub monotonous: bool,
    /// The highest speed (m/s) and the highest acceleration or deceleration (m/s²) the profile
    /// may have.
    pub limits: (f64, f64),
    /// The roads the travel is measured along (as [`StateCheck::roads`]; the default: the
    /// road the actor is on, in +s): on a plan over several roads a [`TravelGoal::RoadS`] is
    /// the plan's s, another entity is measured on any of these roads, and the distance runs
    /// along the actor's lane across their joints; for an actor driving them against s
    /// ([`PlanRoads::against`]) the goal and the gap are u = L − s, along its direction of
    /// travel.
    pub roads: PlanRoads,
}

/// Where a [`Travel`] ends, measured along the actor's lane centre from where it starts.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum TravelGoal {
    /// This distance (m) further along the lane.
    Distance(f64),
    /// At this s (m) of the road the actor is on (the plan's s with [`Travel::roads`]).
    RoadS(f64),
    /// At that place relative to where the entity is at the end, the entity taken to keep the
    /// speed it has at the start along its lane (so the gap's speed is that one too).
    FromEntity(SpeedGap),
}

/// A speed profile entry (XSD `SpeedProfileEntry`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedProfileEntry {
    /// Speed, m/s.
    pub speed: f64,
    /// Time to reach it, s.
    pub time: Option<f64>,
}

/// A speed target (XSD `SpeedActionTarget`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum SpeedTarget {
    /// AbsoluteTargetSpeed, m/s.
    Absolute(f64),
    /// RelativeTargetSpeed.
    Relative {
        /// Reference entity.
        entity_ref: String,
        /// Delta (m/s) or factor.
        value: f64,
        /// Delta or factor.
        speed_target_value_type: SpeedTargetValueType,
        /// Keep following the reference's speed.
        continuous: bool,
    },
    /// oscsim's target read once, no XML form (the DSL runtime writes it for ASAM OpenSCENARIO
    /// DSL 2.1 `speed(same_as/faster_than/slower_than: x, at: end, track: projected)` in a
    /// phase that starts on a run-time condition, §8.9.1.1.3): the entity's speed when the
    /// action starts plus `value` (m/s), then fixed, whatever the entity does after.
    RelativeAtStart {
        /// Reference entity.
        entity_ref: String,
        /// Delta, m/s.
        value: f64,
    },
}

/// Lateral actions (XSD `LateralAction`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum LateralAction {
    /// LaneChangeAction.
    LaneChange {
        /// Offset in the target lane, m.
        target_lane_offset: Option<f64>,
        /// LaneChangeActionDynamics.
        dynamics: TransitionDynamics,
        /// LaneChangeTarget.
        target: LaneChangeTarget,
    },
    /// LaneOffsetAction.
    LaneOffset {
        /// Keep it up.
        continuous: bool,
        /// Shape.
        dynamics_shape: DynamicsShape,
        /// Maximum lateral acceleration, m/s².
        max_lateral_acc: Option<f64>,
        /// LaneOffsetTarget.
        target: LaneOffsetTarget,
    },
    /// LateralDistanceAction.
    LateralDistance {
        /// Reference entity.
        entity_ref: String,
        /// Keep it up.
        continuous: bool,
        /// Distance, m.
        distance: Option<f64>,
        /// Between bounding boxes.
        freespace: bool,
        /// Displacement (1.1+).
        displacement: Option<LateralDisplacement>,
        /// Frame (1.1+).
        coordinate_system: Option<CoordinateSystem>,
        /// Limits.
        dynamic_constraints: Option<DynamicConstraints>,
        /// oscsim's option, no XML form (the DSL runtime writes it for ASAM OpenSCENARIO DSL
        /// 2.1 §8.8.3 `keep_space_gap(…, lateral)` where its gap at the start is not the
        /// plan's to know; the XML reader writes `false`): without a `distance`, keep the one
        /// the engine measures when the action starts.
        at_start: bool,
    },
    /// oscsim's lane change that arrives at a place along the road, an action with no XML
    /// form (the DSL runtime writes it for ASAM OpenSCENARIO DSL 2.1
    /// `change_position(…, on_road_network: true)` in a phase that starts on a run-time
    /// condition, §8.8.2.11): a LaneChangeAction in the distance dimension over the distance
    /// along the actor's lane from where it is when the action starts to `s`.
    LaneChangeAt(Box<LaneChangeAt>),
    /// oscsim's change of the actor's offset in its own lane to one affine in the lane's
    /// width, an action with no XML form (the DSL runtime writes it for ASAM OpenSCENARIO DSL
    /// 2.1 `lateral(d, measure_by: …, at: end)` measured from a border of the lane, over a
    /// phase that starts on a run-time condition, §8.9; beside a lane change of the phase, in
    /// its target lane): the target offset k·W + c is read with the lane's width W where the
    /// actor is at each step, so it holds with the width where the actor is at the end.
    OffsetInWidth(Box<OffsetInWidth>),
    /// oscsim's following of other entities' lane changes, an action with no XML form (the
    /// DSL runtime writes it for ASAM OpenSCENARIO DSL 2.1 §8.9 `lane(same_as/side_of/left_of/
    /// right_of: x)` at: all of an actor with no sideways motion of its own, one reference per
    /// such relation of the invocation, where the plan does not know x's lane changes,
    /// §8.9.1.1.1 "holds throughout the phase"): whenever a reference begins a lane change on
    /// its road, the actor changes into the lane [`FollowedLane::value`] lanes to the left
    /// (right when negative) of that reference's new lane, counted as a RelativeTargetLane
    /// counts them, to its centre, over the same span and shape (its transition's weight the
    /// reference's at every step); where several begin in the same step, the first of them in
    /// this list; a reference that begins one while another's is mirrored takes over from
    /// where the actor is. Held until stopped.
    FollowLanes(Vec<FollowedLane>),
    /// oscsim's mandatory lane of a driver model, an action with no XML form (the DSL runtime
    /// writes it for ASAM OpenSCENARIO DSL 2.1 `lane(…)` at: all beside an action of a
    /// `random_traffic_vehicle_group` after its creation, §8.7.18.1: "the behavioral model
    /// assigned to each vehicle defines the actual behavior of the vehicle within the group"):
    /// handed to the user controller holding the entity's lateral domain (the `mobil` model),
    /// or where none does to the `idm` holding its longitudinal one, which changes lane by lane to the lane `target` names when the action starts, each
    /// change only into a gap MOBIL's safety criterion accepts, and keeps that lane, making no
    /// change of its own, until an action with `None` releases it. Completes at once.
    MandatoryLane {
        /// The lane to reach and keep (`None`: release the one held).
        target: Option<LaneChangeTarget>,
    },
}

/// One entity whose lane changes [`LateralAction::FollowLanes`] follows, and where its actor is
/// from it.
#[derive(Debug, Clone, PartialEq)]
pub struct FollowedLane {
    /// The entity followed.
    pub entity_ref: String,
    /// Lanes to the left of the entity's (0: its lane).
    pub value: i32,
}

/// What oscsim's offset change in the lane's width ([`LateralAction::OffsetInWidth`]) aims at
/// and how long it takes.
#[derive(Debug, Clone, PartialEq)]
pub struct OffsetInWidth {
    /// The lane to change to, its width the one read (`None`: the actor's own lane, an offset
    /// change within it).
    pub lane: Option<LaneChangeTarget>,
    /// k of the target offset k·W + c from the lane's centre (m per m of width, + left).
    pub per_width: f64,
    /// c of the target offset k·W + c (m, + left).
    pub offset: f64,
    /// The transition's shape.
    pub shape: DynamicsShape,
    /// Its duration (s).
    pub duration: f64,
}

/// What oscsim's lane change to a place along the road ([`LateralAction::LaneChangeAt`])
/// changes to, and where it arrives.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneChangeAt {
    /// The lane to change to.
    pub target: LaneChangeTarget,
    /// The offset in it (m).
    pub target_lane_offset: Option<f64>,
    /// The transition's shape.
    pub shape: DynamicsShape,
    /// The s where it arrives (m), ahead of it: of the road the actor is on, or on a plan over
    /// several roads (`roads`) the plan's s.
    pub s: f64,
    /// The plan's roads `s` is measured along (default: one road, the one the actor is on).
    pub roads: PlanRoads,
    /// What asked for it and where it is written, for the error record.
    pub what: String,
}

/// A lane change target (XSD `LaneChangeTarget`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum LaneChangeTarget {
    /// RelativeTargetLane: lanes relative to an entity's lane (positive to the left).
    Relative {
        /// Reference entity.
        entity_ref: String,
        /// Lanes.
        value: i32,
    },
    /// AbsoluteTargetLane: an OpenDRIVE lane id.
    Absolute(String),
    /// oscsim's target beside an entity, no XML form (the DSL runtime writes it for ASAM
    /// OpenSCENARIO DSL 2.1 §8.9 `lateral(d, side_of/left_of/right_of: x, at: end, track:
    /// projected)` after a run-time start): at the action's start, the lane of the actor's road
    /// on its side (its direction of travel) that holds t = the reference's t then + `t`, at the offset from its centre that puts
    /// the actor's reference point there (the action's targetLaneOffset is not read). No
    /// driving lane there fails the action: an error record naming `what`, and a failed run.
    Beside {
        /// The reference entity.
        entity_ref: String,
        /// The actor's t minus the reference's at the action's start (m, + left).
        t: f64,
        /// What asked for it (for the error record).
        what: String,
        /// Follow the reference's t at every step (its actual moves over the transition's
        /// time, oscsim's lane change beside a moving entity), not only at the start.
        follow: bool,
        /// The plan's roads (empty: one road): t on two of them compares where their
        /// reference lines join continuously, so the reference may be on another of them.
        roads: PlanRoads,
    },
    /// oscsim's target numbered across the road, no XML form (the DSL runtime writes it for
    /// ASAM OpenSCENARIO DSL 2.1 §8.9 `lane(n [, from: left])` beside a later action of a
    /// `random_traffic_vehicle_group`, §8.7.18.1): at the action's start, the driving lane
    /// numbered `lane` among the drivable lanes of the reference's side of its road where it
    /// is, 1 the rightmost in its direction of travel (the leftmost with `from_left`). No such
    /// lane there fails the action.
    Numbered {
        /// The entity whose road, side and s the lanes are counted at.
        entity_ref: String,
        /// The lane's number, 1 or more.
        lane: u32,
        /// Counted from the left of the direction of travel, not the right.
        from_left: bool,
    },
}

/// A lane offset target (XSD `LaneOffsetTarget`), m.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum LaneOffsetTarget {
    /// RelativeTargetLaneOffset: offset relative to an entity, m.
    Relative {
        /// Reference entity.
        entity_ref: String,
        /// m.
        value: f64,
    },
    /// AbsoluteTargetLaneOffset, m from the lane centre.
    Absolute(f64),
}

/// VisibilityAction (XSD `VisibilityAction`).
#[derive(Debug, Clone, PartialEq)]
pub struct VisibilityAction {
    /// Visible in image generators.
    pub graphics: bool,
    /// Visible to sensors.
    pub sensors: bool,
    /// Visible to traffic.
    pub traffic: bool,
    /// SensorReferenceSet names (1.2+).
    pub sensor_references: Vec<String>,
}

/// SynchronizeAction (XSD `SynchronizeAction`).
#[derive(Debug, Clone, PartialEq)]
pub struct SynchronizeAction {
    /// The master entity.
    pub master_entity_ref: String,
    /// TargetPositionMaster.
    pub target_position_master: Position,
    /// TargetPosition.
    pub target_position: Position,
    /// Tolerance at the master's position, m (1.1+).
    pub target_tolerance_master: Option<f64>,
    /// Tolerance at the own position, m (1.1+).
    pub target_tolerance: Option<f64>,
    /// FinalSpeed.
    pub final_speed: Option<FinalSpeed>,
}

/// FinalSpeed of a SynchronizeAction (XSD `FinalSpeed`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum FinalSpeed {
    /// AbsoluteSpeed, m/s.
    Absolute {
        /// m/s.
        value: f64,
        /// Steady state before the target (1.1+).
        steady_state: Option<SteadyState>,
    },
    /// RelativeSpeedToMaster.
    RelativeToMaster {
        /// Delta m/s or factor.
        value: f64,
        /// Delta or factor.
        speed_target_value_type: SpeedTargetValueType,
        /// Steady state (1.1+).
        steady_state: Option<SteadyState>,
    },
}

/// Steady state before a synchronisation point (XSD group `SteadyState`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum SteadyState {
    /// TargetDistanceSteadyState, m.
    Distance(f64),
    /// TargetTimeSteadyState, s.
    Time(f64),
}

/// Controller actions (XSD `ControllerAction`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ControllerAction {
    /// AssignControllerAction.
    Assign {
        /// The controller (inline, from a catalog, or from an ObjectController).
        controller: Controller,
        /// ObjectController@name when given that way (1.3).
        object_controller_name: Option<String>,
        /// Activation per domain (1.2+): lateral, longitudinal, animation, lighting.
        activate: ControllerDomains,
    },
    /// OverrideControllerValueAction.
    OverrideValues(OverrideControllerValueAction),
    /// ActivateControllerAction.
    Activate {
        /// objectControllerRef (1.3) or the deprecated controllerRef.
        object_controller_ref: Option<String>,
        /// Domains to (de)activate.
        domains: ControllerDomains,
    },
}

/// Per-domain switches (absent: unchanged).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ControllerDomains {
    /// Lateral.
    pub lateral: Option<bool>,
    /// Longitudinal.
    pub longitudinal: Option<bool>,
    /// Animation (1.2+).
    pub animation: Option<bool>,
    /// Lighting (1.2+).
    pub lighting: Option<bool>,
}

/// Routing actions (XSD `RoutingAction`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum RoutingAction {
    /// AssignRouteAction.
    AssignRoute(Route),
    /// FollowTrajectoryAction.
    FollowTrajectory {
        /// The trajectory (TrajectoryRef, or the deprecated direct children).
        trajectory: Box<Trajectory>,
        /// TimeReference: None, or Timing.
        time_reference: Option<Timing>,
        /// TrajectoryFollowingMode.
        following_mode: FollowingMode,
        /// initialDistanceOffset, m (1.1+).
        initial_distance_offset: Option<f64>,
    },
    /// AcquirePositionAction.
    AcquirePosition(Position),
    /// RandomRouteAction (1.3).
    RandomRoute,
    /// oscsim's FollowTrajectoryAction timed at another entity's speed, an action with no XML
    /// form (the DSL runtime writes it for a single-lane group's `follow_trajectory` /
    /// `replay_trajectory`, ASAM OpenSCENARIO DSL 2.1 §8.8.2.17, in a phase that starts on a
    /// run-time condition: member i's stamps are shifted by its distance behind member 0 over
    /// the group's speed then, which the plan does not know).
    FollowTrajectoryAtSpeed(Box<TrajectoryAtSpeed>),
}

/// oscsim's FollowTrajectoryAction timed at another entity's speed
/// ([`RoutingAction::FollowTrajectoryAtSpeed`]): when it starts, with v that entity's speed
/// then (> 0), each time of the trajectory's points (a Polyline's vertices or a Nurbs's
/// control points, in order) is its own plus `distances[i]` / v; then it runs as the
/// FollowTrajectoryAction with those times.
#[derive(Debug, Clone, PartialEq)]
pub struct TrajectoryAtSpeed {
    /// The trajectory, every point timed.
    pub trajectory: Trajectory,
    /// TimeReference/Timing.
    pub time_reference: Timing,
    /// TrajectoryFollowingMode.
    pub following_mode: FollowingMode,
    /// The entity whose speed at the start the distances are covered at.
    pub entity_ref: String,
    /// A distance (m) per point of the trajectory, in order.
    pub distances: Vec<f64>,
    /// What it is and where it is written, for the error when the entity stands
    /// ("replay_trajectory(…) at f.osc:29:13").
    pub what: String,
}

/// Timing of a trajectory (XSD `Timing`): t_sim = (t_traj · scale) + offset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Timing {
    /// Absolute or relative to the action's start.
    pub domain_absolute_relative: ReferenceContext,
    /// Offset, s.
    pub offset: f64,
    /// Scale.
    pub scale: f64,
}

/// Appearance actions (XSD `AppearanceAction`, 1.2+).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum AppearanceAction {
    /// LightStateAction.
    LightState(LightStateAction),
    /// AnimationAction.
    Animation(AnimationAction),
}

/// Trailer actions (XSD `TrailerAction`, 1.3).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum TrailerAction {
    /// ConnectTrailerAction.
    Connect {
        /// The trailer entity.
        trailer_ref: String,
    },
    /// DisconnectTrailerAction.
    Disconnect,
}
