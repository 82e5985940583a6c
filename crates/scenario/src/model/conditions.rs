//! Entity and value conditions (OpenSCENARIO 1.3 "Conditions", XSD `EntityCondition` and
//! `ByValueCondition` with all their choices). Distances in m, speeds in m/s, accelerations in
//! m/s², times in s, angles in rad.

use crate::model::{
    AngleType, CoordinateSystem, DirectionalDimension, ObjectType, Position, RelativeDistanceType,
    RoutingAlgorithm, Rule, StoryboardElementState, StoryboardElementType,
};

/// Conditions on entities (XSD `EntityCondition`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum EntityCondition {
    /// EndOfRoadCondition: at the end of the road for `duration` s.
    EndOfRoad {
        /// s.
        duration: f64,
    },
    /// CollisionCondition: collides with an entity or any object of a type.
    Collision(CollisionTarget),
    /// OffroadCondition: off the road for `duration` s.
    Offroad {
        /// s.
        duration: f64,
    },
    /// TimeHeadwayCondition, s.
    TimeHeadway {
        /// The entity ahead.
        entity_ref: String,
        /// Value, s.
        value: f64,
        /// Rule.
        rule: Rule,
        /// How the distance is measured.
        measure: DistanceMeasure,
    },
    /// TimeToCollisionCondition, s.
    TimeToCollision {
        /// The target.
        target: TimeToCollisionTarget,
        /// Value, s.
        value: f64,
        /// Rule.
        rule: Rule,
        /// How the distance is measured.
        measure: DistanceMeasure,
    },
    /// AccelerationCondition, m/s².
    Acceleration {
        /// Value, m/s².
        value: f64,
        /// Rule.
        rule: Rule,
        /// Component (1.2+); absent: magnitude.
        direction: Option<DirectionalDimension>,
    },
    /// StandStillCondition: stands still for `duration` s.
    StandStill {
        /// s.
        duration: f64,
    },
    /// SpeedCondition, m/s.
    Speed {
        /// Value, m/s.
        value: f64,
        /// Rule.
        rule: Rule,
        /// Component (1.2+); absent: magnitude.
        direction: Option<DirectionalDimension>,
    },
    /// RelativeSpeedCondition: own speed minus the entity's, m/s.
    RelativeSpeed {
        /// Reference entity.
        entity_ref: String,
        /// Value, m/s.
        value: f64,
        /// Rule.
        rule: Rule,
        /// Component (1.2+).
        direction: Option<DirectionalDimension>,
    },
    /// TraveledDistanceCondition, m.
    TraveledDistance {
        /// m.
        value: f64,
    },
    /// ReachPositionCondition (deprecated since 1.2; same as a DistanceCondition ≤ tolerance).
    ReachPosition {
        /// The position.
        position: Position,
        /// Tolerance radius, m.
        tolerance: f64,
    },
    /// DistanceCondition to a position, m.
    Distance {
        /// The position.
        position: Position,
        /// Value, m.
        value: f64,
        /// Rule.
        rule: Rule,
        /// How the distance is measured.
        measure: DistanceMeasure,
    },
    /// RelativeDistanceCondition to an entity, m.
    RelativeDistance {
        /// Reference entity.
        entity_ref: String,
        /// Value, m.
        value: f64,
        /// Rule.
        rule: Rule,
        /// How the distance is measured.
        measure: DistanceMeasure,
    },
    /// RelativeClearanceCondition (1.2+): lanes free of entities.
    RelativeClearance {
        /// Consider opposite lanes.
        opposite_lanes: bool,
        /// Forward distance, m.
        distance_forward: Option<f64>,
        /// Backward distance, m.
        distance_backward: Option<f64>,
        /// Between bounding boxes.
        free_space: bool,
        /// Lane ranges (from, to) relative to the triggering entity's lane.
        relative_lane_ranges: Vec<(Option<i32>, Option<i32>)>,
        /// Only these entities count (empty: all).
        entity_refs: Vec<String>,
    },
    /// AngleCondition (1.3): own absolute angle, rad.
    Angle {
        /// Which angle.
        angle_type: AngleType,
        /// Angle, rad.
        angle: f64,
        /// Tolerance, rad.
        angle_tolerance: f64,
        /// Frame.
        coordinate_system: Option<CoordinateSystem>,
    },
    /// RelativeAngleCondition (1.3): angle relative to an entity, rad.
    RelativeAngle {
        /// Reference entity.
        entity_ref: String,
        /// Which angle.
        angle_type: AngleType,
        /// Angle, rad.
        angle: f64,
        /// Tolerance, rad.
        angle_tolerance: f64,
        /// Frame.
        coordinate_system: Option<CoordinateSystem>,
    },
    /// oscsim's distance travelled since a mark, a condition with no XML form (the DSL runtime
    /// writes it for `distance(d)` in a phase without a duration that starts on a run-time
    /// condition, ASAM OpenSCENARIO DSL 2.1 §8.9; the XML reader never does): the triggering
    /// entity's odometer has advanced `value` m or more since the state check that noted the
    /// mark ([`crate::StateCheck::mark`]) ran on it. False before that.
    TraveledSinceMark {
        /// The mark's name.
        mark: String,
        /// m.
        value: f64,
    },
    /// oscsim's gap reached since a mark, a condition with no XML form (the DSL runtime writes
    /// it for `position(time: t / neither, ahead_of/behind: x, at: end)` in a phase without a
    /// duration that starts on a run-time condition; the XML reader never does): the
    /// triggering entity's s minus x's, less the gap's offset at x's speed now
    /// ([`crate::SpeedGap::offset`]), is 0 or of the sign opposite to the one it had when the
    /// state check noted the mark (it has reached its place from the side it started on).
    /// False before that, and while either is off x's road.
    GapReachedSinceMark {
        /// The mark's name.
        mark: String,
        /// The place relative to x.
        gap: crate::SpeedGap,
    },
    /// oscsim's place along the plan's roads reached, a condition with no XML form (the DSL
    /// runtime writes it for a route through points in other lanes in a phase that starts on
    /// a run-time condition, ASAM OpenSCENARIO DSL 2.1 §8.9 `along`, §8.12.2.1
    /// `create_route`; the XML reader never does): the triggering entity's place in the
    /// measure of `roads` ([`crate::PlanRoads`]: the plan's s over several roads; on one road,
    /// the road the entity is on, its own s; against s the distance u = L − s along the
    /// direction of travel) is `value` or beyond. False while it is off those roads.
    PlaceReached {
        /// The place (m, in the roads' measure).
        value: f64,
        /// The roads it is measured along, and the direction of travel.
        roads: crate::PlanRoads,
    },
}

/// How a distance-based condition measures (the attributes `freespace`,
/// `coordinateSystem`, `relativeDistanceType` and `routingAlgorithm` shared by
/// TimeHeadwayCondition, TimeToCollisionCondition, DistanceCondition and
/// RelativeDistanceCondition).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DistanceMeasure {
    /// Between bounding boxes (true) or reference points.
    pub freespace: bool,
    /// Measurement frame (1.1+; absent: entity).
    pub coordinate_system: Option<CoordinateSystem>,
    /// Distance type (1.1+; absent: euclidian). Required by RelativeDistanceCondition.
    pub relative_distance_type: Option<RelativeDistanceType>,
    /// Routing algorithm for road distances (1.2+).
    pub routing_algorithm: Option<RoutingAlgorithm>,
}

/// What a CollisionCondition watches (XSD `CollisionCondition` choice).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum CollisionTarget {
    /// EntityRef.
    EntityRef(String),
    /// ByType.
    ByType(ObjectType),
}

/// The target of a TimeToCollisionCondition (XSD `TimeToCollisionConditionTarget`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum TimeToCollisionTarget {
    /// A position.
    Position(Position),
    /// An entity.
    EntityRef(String),
}

/// Conditions on values (XSD `ByValueCondition`).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ByValueCondition {
    /// ParameterCondition (parameters are constants after load; kept for completeness).
    Parameter {
        /// Parameter name.
        parameter_ref: String,
        /// Rule.
        rule: Rule,
        /// Value as text.
        value: String,
    },
    /// TimeOfDayCondition.
    TimeOfDay {
        /// Rule.
        rule: Rule,
        /// dateTime as written.
        date_time: String,
    },
    /// SimulationTimeCondition, s.
    SimulationTime {
        /// s.
        value: f64,
        /// Rule.
        rule: Rule,
    },
    /// StoryboardElementStateCondition.
    StoryboardElementState {
        /// Element type.
        storyboard_element_type: StoryboardElementType,
        /// Element name.
        storyboard_element_ref: String,
        /// State or transition.
        state: StoryboardElementState,
    },
    /// UserDefinedValueCondition.
    UserDefinedValue {
        /// Name.
        name: String,
        /// Rule.
        rule: Rule,
        /// Value as text.
        value: String,
    },
    /// TrafficSignalCondition.
    TrafficSignal {
        /// Signal name.
        name: String,
        /// State as text.
        state: String,
    },
    /// TrafficSignalControllerCondition.
    TrafficSignalController {
        /// Controller name.
        traffic_signal_controller_ref: String,
        /// Phase name.
        phase: String,
    },
    /// VariableCondition (1.2+).
    Variable {
        /// Variable name.
        variable_ref: String,
        /// Rule.
        rule: Rule,
        /// Value as text.
        value: String,
    },
    /// A periodic event on the simulation clock: ASAM OpenSCENARIO DSL 2.1 §7.3.10.4
    /// `every(period, offset: offset)` counted from the start of the run, or from the latest
    /// start of an Act (`since`). An oscsim extension with no XML form (the DSL runtime writes
    /// it; the XML reader never does): it holds in the step whose interval (t − step, t]
    /// reaches a trigger point offset + k·period, k ≥ 0 (the standard moves a trigger point
    /// that falls between steps to the next step), t the time since the run's start, or since
    /// the step in which the Act last started (false before it ever started).
    SimulationTimeEvery {
        /// The period (s, above 0).
        period: f64,
        /// The first trigger point (s, 0 or more).
        offset: f64,
        /// The engine's step the scenario was planned for (s, above 0).
        step: f64,
        /// The Act whose latest startTransition is the clock's 0 (`None`: the run's start):
        /// the DSL's event context of an `on` handler of an invoked behavior, whose
        /// invocation starts at a moment only the run knows.
        since: Option<String>,
    },
    /// The time since the latest start of an Act is `value` s or more: ASAM OpenSCENARIO DSL
    /// 2.1 §7.3.10.4 `elapsed(value)` in an `on` handler of an invoked behavior whose
    /// invocation (the Act) starts at a moment only the run knows. An oscsim extension with no
    /// XML form: true from the step `value` s (rounded up to a step) after the step in which the
    /// Act last started, false before the Act ever started.
    ElapsedSinceStart {
        /// The Act.
        act: String,
        /// s (0 or more).
        value: f64,
        /// The engine's step the scenario was planned for (s, above 0).
        step: f64,
    },
}
