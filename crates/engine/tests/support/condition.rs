//! Shared harness of the position and condition tests: a fake runtime (`FakeWorld`) that
//! implements `EntityQuery` and `ConditionContext` over a corpus road network, with builders
//! for entities, positions and conditions.

#![allow(dead_code)] // each test file uses a different part

use std::collections::HashMap;
use std::path::Path;
use std::sync::Arc;

use engine::condition::{ConditionContext, SelectionId};
use engine::domain::{BoundingBox, Position3d, Route, Vector3};
use engine::position::{EntityQuery, EntityView};
use engine::storyboard::{
    ActDesc, ActionDesc, ActionHost, ActionId, ActionStatus, ConditionDesc, ConditionEdge,
    ConditionId, ConditionSource, EventDesc, ManeuverDesc, ManeuverGroupDesc, Priority, StateView,
    StoryDesc, Storyboard, StoryboardDesc, TransitionRecord, TransitionSink, TriggerDesc,
};
use engine::EntityId;
use opendrive::{Pose, RoadNetwork, RoadPosition};
use scenario::expr::Value;
use scenario::{ObjectType, Orientation, Position, PositionKind, ReferenceContext, SourcePos};

/// A corpus road network, by path relative to `shared/corpus/`.
pub fn corpus_road(rel: &str) -> RoadNetwork {
    // The corpus is part of the test fixture; a missing file is a broken checkout.
    RoadNetwork::from_file(&crate::corpus::corpus(rel)).expect("corpus road network loads")
}

/// The source position every test position claims to come from.
pub fn here() -> SourcePos {
    SourcePos {
        file: Arc::from(Path::new("test.xosc")),
        line: 7,
        col: 9,
    }
}

/// A position of `kind` written at `test.xosc:7:9`.
pub fn at(kind: PositionKind) -> Position {
    Position { kind, pos: here() }
}

/// An orientation; `absolute` picks the reference context.
pub fn orientation(h: f64, absolute: bool) -> Option<Orientation> {
    Some(Orientation {
        h,
        p: 0.0,
        r: 0.0,
        reference: Some(if absolute {
            ReferenceContext::Absolute
        } else {
            ReferenceContext::Relative
        }),
    })
}

/// A 4.5 m × 1.8 m × 1.5 m car box whose centre is 1.4 m ahead of the rear axle.
pub fn car_box() -> BoundingBox {
    // Finite, non-negative values: always a valid box.
    BoundingBox::new(Position3d::new(1.4, 0.0, 0.75), 4.5, 1.8, 1.5).expect("valid box")
}

/// One entity of the fake world: what an `EntityView` shows, owned.
#[derive(Debug, Clone)]
pub struct FakeEntity {
    pub name: String,
    pub object_type: ObjectType,
    pub pose: Pose,
    pub road_position: Option<RoadPosition>,
    pub speed: f64,
    pub velocity: Vector3,
    pub acceleration: Vector3,
    pub odometer: f64,
    pub bounding_box: BoundingBox,
    pub route: Option<Route>,
    pub trajectory: Option<engine::trajectory::Trajectory>,
}

/// Storyboard hosts for the fake: every condition false, every action ends at once.
struct Idle;

impl ConditionSource for Idle {
    fn value(&mut self, _: ConditionId, _: f64, _: &StateView<'_>) -> bool {
        false
    }
}

impl ActionHost for Idle {
    fn start(&mut self, _: ActionId) {}
    fn stop(&mut self, _: ActionId) {}
    fn status(&self, _: ActionId) -> ActionStatus {
        ActionStatus::Ended
    }
}

impl TransitionSink for Idle {
    fn record(&mut self, _: TransitionRecord) {}
}

/// A storyboard Story "S" / Act "A" (no trigger) / ManeuverGroup "G" / Maneuver "M" / Event
/// "E" (start trigger: condition 0, never true) / Action "X".
fn small_storyboard() -> Storyboard {
    let desc = StoryboardDesc {
        name: "storyBoard".into(),
        init_actions: vec![],
        stories: vec![StoryDesc {
            name: "S".into(),
            acts: vec![ActDesc {
                name: "A".into(),
                start_trigger: None,
                stop_trigger: None,
                maneuver_groups: vec![ManeuverGroupDesc {
                    name: "G".into(),
                    maximum_execution_count: 1,
                    maneuvers: vec![ManeuverDesc {
                        name: "M".into(),
                        events: vec![EventDesc {
                            name: "E".into(),
                            priority: Priority::Override,
                            maximum_execution_count: 1,
                            start_trigger: Some(TriggerDesc::single(ConditionDesc {
                                name: "never".into(),
                                id: ConditionId(0),
                                edge: ConditionEdge::None,
                                delay: 0.0,
                                origin: None,
                            })),
                            actions: vec![ActionDesc {
                                name: "X".into(),
                                id: ActionId(0),
                            }],
                        }],
                    }],
                }],
            }],
        }],
        stop_trigger: None,
    };
    // A fixed, well-formed description.
    Storyboard::new(&desc).expect("small storyboard builds")
}

/// A fake runtime over one road network.
pub struct FakeWorld {
    pub network: RoadNetwork,
    pub entities: Vec<FakeEntity>,
    pub time: f64,
    pub parameters: HashMap<String, Value>,
    pub variables: HashMap<String, Value>,
    pub user_values: HashMap<String, Value>,
    pub signals: HashMap<String, String>,
    pub controller_phases: HashMap<String, String>,
    pub time_of_day: Option<f64>,
    pub storyboard: Storyboard,
    pub selections: HashMap<String, Vec<String>>,
}

impl FakeWorld {
    /// An empty world on `network`, at time 0, with the small storyboard not yet stepped.
    pub fn new(network: RoadNetwork) -> Self {
        Self {
            network,
            entities: Vec::new(),
            time: 0.0,
            parameters: HashMap::new(),
            variables: HashMap::new(),
            user_values: HashMap::new(),
            signals: HashMap::new(),
            controller_phases: HashMap::new(),
            time_of_day: None,
            storyboard: small_storyboard(),
            selections: HashMap::new(),
        }
    }

    /// Runs one storyboard step at time `t` (conditions all false, actions end at once).
    pub fn step_storyboard(&mut self, t: f64) {
        let mut idle = Idle;
        let mut idle2 = Idle;
        let mut idle3 = Idle;
        // Finite increasing times and a positive dt: the step cannot fail.
        self.storyboard
            .step(t, 0.05, &mut idle, &mut idle2, &mut idle3)
            .expect("storyboard steps");
    }

    /// Places a car named `name` at `pose` (road position looked up with its heading).
    pub fn place(&mut self, name: &str, pose: Pose) -> &mut FakeEntity {
        self.place_as(name, ObjectType::Vehicle, pose)
    }

    /// Places an entity of `object_type` at `pose`.
    pub fn place_as(&mut self, name: &str, object_type: ObjectType, pose: Pose) -> &mut FakeEntity {
        let road_position = self
            .network
            .locate(pose.x, pose.y, Some(pose.h))
            .filter(|rp| rp.distance <= 1e-9);
        // Placed again: in its own place, so that its id (its index) stays.
        let at = self.entities.iter().position(|e| e.name == name);
        let e = FakeEntity {
            name: name.into(),
            object_type,
            pose,
            road_position,
            speed: 0.0,
            velocity: Vector3::ZERO,
            acceleration: Vector3::ZERO,
            odometer: 0.0,
            bounding_box: car_box(),
            route: None,
            trajectory: None,
        };
        let i = match at {
            Some(i) => {
                self.entities[i] = e;
                i
            }
            None => {
                self.entities.push(e);
                self.entities.len() - 1
            }
        };
        &mut self.entities[i]
    }

    /// Places a car on lane `lane` of road `road` at `s`, heading along the lane's driving
    /// direction (`forward`: along +s).
    pub fn place_on_lane(
        &mut self,
        name: &str,
        road: &str,
        lane: i32,
        s: f64,
        forward: bool,
    ) -> &mut FakeEntity {
        // Test inputs name lanes that exist.
        let mut pose = self
            .network
            .lane_pose(road, lane, s, 0.0)
            .expect("lane exists");
        if !forward {
            pose.h = opendrive::normalize_angle(pose.h + std::f64::consts::PI);
        }
        self.place(name, pose)
    }

    /// Moves entity `name` to `pose`.
    pub fn move_to(&mut self, name: &str, pose: Pose) {
        let e = self.entity_mut(name);
        let (kind, speed, v) = (e.object_type, e.speed, e.velocity);
        let e = self.place_as(name, kind, pose);
        e.speed = speed;
        e.velocity = v;
    }

    /// The entity `name`, mutable.
    pub fn entity_mut(&mut self, name: &str) -> &mut FakeEntity {
        // Tests only ask for entities they placed.
        self.entities
            .iter_mut()
            .find(|e| e.name == name)
            .expect("entity placed by the test")
    }

    /// Sets the forward speed of `name` (velocity along its x-axis).
    pub fn set_speed(&mut self, name: &str, speed: f64) {
        let e = self.entity_mut(name);
        e.speed = speed;
        e.velocity = Vector3::new(speed, 0.0, 0.0);
    }
}

fn view(e: &FakeEntity) -> EntityView<'_> {
    let mut v = EntityView::new(&e.name, e.object_type, e.pose, e.bounding_box);
    v.road_position = e.road_position.as_ref();
    v.speed = e.speed;
    v.velocity.translational = e.velocity;
    v.acceleration.translational = e.acceleration;
    v.odometer = e.odometer;
    v.route = e.route.as_ref();
    v.trajectory = e.trajectory.as_ref();
    v
}

impl EntityQuery for FakeWorld {
    fn entity(&self, name: &str) -> Option<EntityView<'_>> {
        self.entities.iter().find(|e| e.name == name).map(view)
    }

    fn entities(&self) -> Box<dyn Iterator<Item = EntityView<'_>> + '_> {
        Box::new(self.entities.iter().map(view))
    }

    fn road_network(&self) -> &RoadNetwork {
        &self.network
    }
}

impl ConditionContext for FakeWorld {
    fn simulation_time(&self) -> f64 {
        self.time
    }
    fn parameter(&self, name: &str) -> Option<Value> {
        self.parameters.get(name).cloned()
    }
    fn variable(&self, name: &str) -> Option<Value> {
        self.variables.get(name).cloned()
    }
    fn storyboard(&self) -> StateView<'_> {
        self.storyboard.view()
    }
    fn user_defined_value(&self, name: &str) -> Option<Value> {
        self.user_values.get(name).cloned()
    }
    fn traffic_signal_state(&self, name: &str) -> Option<&str> {
        self.signals.get(name).map(String::as_str)
    }
    fn traffic_signal_controller_phase(&self, name: &str) -> Option<&str> {
        self.controller_phases.get(name).map(String::as_str)
    }
    fn time_of_day(&self) -> Option<f64> {
        self.time_of_day
    }
    /// Selections numbered in the order of their names.
    fn selection_id(&self, name: &str) -> Option<SelectionId> {
        let mut names: Vec<&String> = self.selections.keys().collect();
        names.sort();
        names
            .iter()
            .position(|n| *n == name)
            .map(|i| SelectionId(i as u32))
    }
    fn selection_members(&self, id: SelectionId) -> Vec<EntityId> {
        let mut names: Vec<&String> = self.selections.keys().collect();
        names.sort();
        names
            .get(id.0 as usize)
            .map(|n| {
                self.selections[*n]
                    .iter()
                    .filter_map(|m| self.entity_id(m))
                    .collect()
            })
            .unwrap_or_default()
    }
}

/// A condition of `kind` named "C" (edge none, no delay) written at `test.xosc:7:9`.
pub fn condition(kind: scenario::ConditionKind) -> scenario::Condition {
    scenario::Condition {
        name: "C".into(),
        condition_edge: scenario::ConditionEdge::None,
        delay: 0.0,
        kind,
        pos: here(),
    }
}

/// A ByEntityCondition on `entities`, `all` or any of them.
pub fn by_entity(
    entities: &[&str],
    all: bool,
    entity_condition: scenario::EntityCondition,
) -> scenario::Condition {
    condition(scenario::ConditionKind::ByEntity {
        triggering_entities: scenario::TriggeringEntities {
            rule: if all {
                scenario::TriggeringEntitiesRule::All
            } else {
                scenario::TriggeringEntitiesRule::Any
            },
            entity_refs: entities.iter().map(|s| s.to_string()).collect(),
        },
        entity_condition,
    })
}

/// A distance measure.
pub fn measure(
    freespace: bool,
    coordinate_system: Option<scenario::CoordinateSystem>,
    relative_distance_type: Option<scenario::RelativeDistanceType>,
) -> scenario::DistanceMeasure {
    scenario::DistanceMeasure {
        freespace,
        coordinate_system,
        relative_distance_type,
        routing_algorithm: None,
    }
}

/// The raw value of `c` in `w` with a fresh memory; panics on an evaluation error.
pub fn eval(w: &FakeWorld, c: &scenario::Condition) -> bool {
    let mut state = engine::condition::ConditionState::new();
    match engine::condition::evaluate(c, w, &mut state) {
        Ok(v) => v,
        Err(e) => panic!("condition failed: {e}"),
    }
}

/// The error of evaluating `c` in `w`, as text.
pub fn eval_error(w: &FakeWorld, c: &scenario::Condition) -> String {
    let mut state = engine::condition::ConditionState::new();
    match engine::condition::evaluate(c, w, &mut state) {
        Ok(v) => panic!("expected an error, got {v}"),
        Err(e) => e.to_string(),
    }
}

/// The raw value of `c` at simulation time `t`, with the condition's memory `state` kept by
/// the caller across calls (duration conditions).
pub fn eval_at(
    w: &mut FakeWorld,
    t: f64,
    c: &scenario::Condition,
    state: &mut engine::condition::ConditionState,
) -> bool {
    w.time = t;
    match engine::condition::evaluate(c, &*w, state) {
        Ok(v) => v,
        Err(e) => panic!("condition failed: {e}"),
    }
}

/// A RelativeLanePosition to "Ego": `d_lane` lanes and `ds` m along the reference line.
pub fn relative_lane_to_ego(d_lane: i32, ds: f64) -> Position {
    at(PositionKind::RelativeLane {
        entity_ref: "Ego".into(),
        d_lane,
        ds: Some(ds),
        ds_lane: None,
        offset: None,
        orientation: None,
    })
}

/// A RelativeRoadPosition to `entity`: (ds, dt).
pub fn relative_road_to(entity: &str, ds: f64, dt: f64) -> Position {
    at(PositionKind::RelativeRoad {
        entity_ref: entity.into(),
        ds,
        dt,
        orientation: None,
    })
}
