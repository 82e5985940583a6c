//! The world of a running scenario (OpenSCENARIO 1.3 §8 "Scenario at runtime"): the road
//! network, the entity store, simulation time, parameter and variable values and traffic signal
//! states. It answers the read-only questions of positions and conditions through
//! [`EntityQuery`] and [`ConditionContext`].

use std::collections::{BTreeMap, HashMap};
use std::sync::Arc;

use opendrive::{normalize_angle, Direction, Pose, Real, RoadNetwork, RoadPosition};
use scenario::expr::Value;

use crate::condition::ConditionContext;
use crate::position::lane_at;
use crate::position::{EntityQuery, EntityView};
use crate::routing::RoutingOptions;
use crate::storyboard::{ConditionId, StateView};
use crate::world::entity::{Entity, EntityId};
use crate::world::lane_track::LaneTrack;
use crate::world::lanes::curvature;

/// A located point farther than this (m) from every lane is off the road: the entity then
/// moves straight along its heading instead of following a lane.
const ON_ROAD_TOLERANCE: Real = 0.5;

/// Road network, entities and global values of one run.
#[derive(Debug)]
pub struct World {
    /// The road network.
    pub network: Arc<RoadNetwork>,
    /// The entity store, by id. Reached from outside this module only through the methods
    /// below, each write marking the entity in `written`.
    entities: Vec<Entity>,
    /// By entity index: written since the lane index last read the store
    /// ([`World::for_lane_index`]), by any way but the controllers stage's moves' walk
    /// ([`World::moves`], which enters each entity it moves in the index itself).
    written: Vec<bool>,
    names: HashMap<String, EntityId>,
    /// Simulation time of the current step (s).
    pub time: f64,
    pub(crate) parameters: BTreeMap<String, Value>,
    /// The ConstraintGroups of the global parameters that have some, by name.
    pub(crate) parameter_constraints: BTreeMap<String, Vec<scenario::ValueConstraintGroup>>,
    pub(crate) variables: BTreeMap<String, Value>,
    /// Traffic signal controllers and signal states (crate::signals).
    pub(crate) signals: crate::signals::Signals,
    /// Monitors (MonitorDeclaration, OpenSCENARIO 1.3) and their values, by name.
    pub(crate) monitors: BTreeMap<String, bool>,
    /// Values set from outside for UserDefinedValueCondition.
    pub(crate) user_values: crate::condition::UserValueRegistry,
    /// Trailer mounting points and connections (§7.2.2.6).
    pub(crate) trailers: super::trailer::Trailers,
    /// The run's seed ([`EngineConfig::seed`](crate::EngineConfig::seed)): routeStrategy
    /// `random` and spawned traffic draw from streams keyed by it (set by `Engine::new`).
    pub(crate) seed: u64,
    /// The scenario's entity selections, expanded when used (store/selection.rs).
    pub(crate) selections: super::selection::Selections,
    /// Environment set by EnvironmentActions (actions/environment.rs).
    pub(crate) environment: crate::world::EnvironmentState,
    /// The marks state checks noted, by slot (condition/mark.rs).
    pub(crate) marks: crate::condition::Marks,
    /// The marks' slots by name, given when the storyboard was built (for
    /// [`ConditionContext::mark_id`]; the runtime resolves every name then).
    pub(crate) mark_ids: crate::condition::MarkIds,
}

impl World {
    /// A world on `network` with `entities` (ids must be their indices).
    pub(crate) fn new(network: Arc<RoadNetwork>, entities: Vec<Entity>) -> Self {
        let names = entities
            .iter()
            .map(|e| (e.name.clone(), e.id))
            .collect::<HashMap<_, _>>();
        World {
            network,
            written: vec![false; entities.len()],
            entities,
            names,
            time: 0.0,
            parameters: BTreeMap::new(),
            parameter_constraints: BTreeMap::new(),
            variables: BTreeMap::new(),
            signals: crate::signals::Signals::default(),
            monitors: BTreeMap::new(),
            user_values: crate::condition::UserValueRegistry::default(),
            trailers: super::trailer::Trailers::default(),
            seed: 0,
            selections: super::selection::Selections::default(),
            environment: crate::world::EnvironmentState::default(),
            marks: crate::condition::Marks::default(),
            mark_ids: crate::condition::MarkIds::default(),
        }
    }

    /// Adds entity `e` to the store (a spawned object, OpenSCENARIO 1.3 §7.2.2.3), giving it
    /// the next id; its name must be new.
    pub(crate) fn spawn(&mut self, mut e: Entity) -> EntityId {
        let id = EntityId(self.entities.len() as u32);
        e.id = id;
        self.names.insert(e.name.clone(), id);
        self.entities.push(e);
        self.written.push(true);
        id
    }

    /// All entities in declaration order.
    pub fn entities(&self) -> &[Entity] {
        &self.entities
    }

    /// The entity with handle `id`. Panics if `id` is not from this world.
    pub fn entity(&self, id: EntityId) -> &Entity {
        &self.entities[id.index()]
    }

    /// The entity with handle `id`, to change: marked written (the lane index enters it
    /// anew at its next refresh). Panics if `id` is not from this world.
    pub(crate) fn entity_mut(&mut self, id: EntityId) -> &mut Entity {
        self.written[id.index()] = true;
        &mut self.entities[id.index()]
    }

    /// [`World::entity_mut`] beside the road network it moves on.
    pub(crate) fn entity_on_network_mut(&mut self, id: EntityId) -> (&RoadNetwork, &mut Entity) {
        self.written[id.index()] = true;
        (&self.network, &mut self.entities[id.index()])
    }

    /// Every entity, to change: all marked written.
    pub(crate) fn entities_mut(&mut self) -> &mut [Entity] {
        self.written.fill(true);
        &mut self.entities
    }

    /// The store for the controllers stage's moves' walk (controller/stage.rs): the network,
    /// every entity to move, and the signals that may govern their speed. The entities are
    /// **not** marked written: the walk enters each one it moves in the lane index right after
    /// its move (`LaneIndex::enter_moved`), or, where it enters none, has the index forget
    /// its moves' entries (`LaneIndex::end_moves`; store/lane_refresh.rs).
    pub(crate) fn moves(
        &mut self,
    ) -> (
        &Arc<RoadNetwork>,
        &mut [Entity],
        &mut crate::signals::Signals,
    ) {
        (&self.network, &mut self.entities, &mut self.signals)
    }

    /// The store as the lane index reads it (store/lane_refresh.rs): the network, the
    /// entities and, by entity index, whether each was written since the index last read
    /// them; the reader clears the marks it has taken in.
    pub(crate) fn for_lane_index(&mut self) -> (&Arc<RoadNetwork>, &[Entity], &mut [bool]) {
        (&self.network, &self.entities, &mut self.written)
    }

    /// Runs `f` on this world with `entities` in place of its store, then puts the store
    /// back (`entities` gets its own again): the step-start copy conditions read
    /// (runtime/trigger_view.rs). Nothing is written.
    pub(crate) fn with_entities<R>(
        &mut self,
        entities: &mut Vec<Entity>,
        f: impl FnOnce(&World) -> R,
    ) -> R {
        std::mem::swap(entities, &mut self.entities);
        let result = f(self);
        std::mem::swap(entities, &mut self.entities);
        result
    }

    /// The handle of the entity called `name`.
    pub fn id(&self, name: &str) -> Option<EntityId> {
        self.names.get(name).copied()
    }

    /// The current value of a parameter.
    pub fn parameter_value(&self, name: &str) -> Option<&Value> {
        self.parameters.get(name)
    }

    /// The current value of a variable.
    pub fn variable_value(&self, name: &str) -> Option<&Value> {
        self.variables.get(name)
    }

    /// Places entity `id` at `pose` with road position `found`; when it stands on a lane, the
    /// default controller follows that lane (OpenSCENARIO 1.3 §7.5.1: it keeps the lane),
    /// whatever its heading: the heading relative to the lane's direction of travel is kept, so
    /// an object turned sideways on a vehicle (drop-bike.xosc) travels along the lane with it.
    /// An entity turned more than 90° from the reference line's direction travels towards −s.
    pub(crate) fn place_resolved(&mut self, id: EntityId, pose: Pose, found: Option<RoadPosition>) {
        self.written[id.index()] = true;
        place_on_lane(&self.network, &mut self.entities[id.index()], pose, found);
    }

    /// The default controller takes `actor` on from its pose (a FollowTrajectoryAction over,
    /// or a controller handing back its lateral domain): it follows the lane at its pose;
    /// `hold` keeps it in place for the rest of this step.
    pub(crate) fn release_to_road(&mut self, actor: EntityId, hold: bool) {
        let pose = self.entity(actor).pose;
        let found = self.network.locate(pose.x, pose.y, Some(pose.h));
        self.place_resolved(actor, pose, found);
        self.entity_mut(actor).held = hold;
    }

    /// A lateral movement stopped midway (a lateral action, or a controller's lane change): the
    /// actor keeps the lateral position it has, in the lane that holds it.
    pub(crate) fn keep_lateral_position(&mut self, actor: EntityId) {
        let (net, e) = self.entity_on_network_mut(actor);
        let Some(track) = &mut e.track else {
            return;
        };
        if track.blend.take().is_some() {
            if let Some((lane, offset)) = net
                .road(&track.road_id)
                .and_then(|r| lane_at(r, track.s, track.t))
            {
                track.lane_id = lane;
                track.offset = offset;
            }
        }
    }

    /// The view of entity `e` for positions and conditions.
    pub(crate) fn view<'a>(&'a self, e: &'a Entity) -> EntityView<'a> {
        EntityView {
            road_position: e.road_position.as_ref(),
            speed: e.speed,
            velocity: e.velocity,
            acceleration: e.acceleration,
            odometer: e.odometer,
            route: e.route.as_ref(),
            ..EntityView::new(&e.name, e.kind.object_type(), e.pose, e.bounding_box)
        }
    }
}

/// [`World::place_resolved`] for one entity: places `e` at `pose` with road position `found`
/// and, on a lane, gives it the lane track the default controller follows.
pub(crate) fn place_on_lane(
    net: &RoadNetwork,
    e: &mut Entity,
    pose: Pose,
    found: Option<RoadPosition>,
) {
    e.placed = true;
    e.pose = pose;
    e.track = None;
    e.road_position = None;
    let Some(mut rp) = found else {
        return;
    };
    let on_road = rp.distance <= ON_ROAD_TOLERANCE;
    // The heading of the lane's centre line (plus the constant offset) relative to the
    // reference line, atan2(t′, 1 − κ·t): what the default controller adds to the road's
    // heading (controller/default.rs, place_on_track), so it is taken out of the kept
    // relative heading; `rp.relative_heading` counts from the reference line, and keeping
    // it whole would count a widening lane's slope twice.
    let mut slope = 0.0;
    if let Some(road) = net.road(&rp.road_id) {
        if let Some((lane, offset)) = lane_at(road, rp.s, rp.t) {
            rp.lane_id = lane;
            rp.offset = offset;
            if let Ok(span) = road.lane_span(lane, rp.s) {
                slope = span.d_center().atan2(1.0 - curvature(road, rp.s) * rp.t);
            }
        }
    }
    let rel = normalize_angle(rp.relative_heading);
    let (direction, along) = if rel.abs() <= std::f64::consts::FRAC_PI_2 {
        (Direction::Forward, normalize_angle(rel - slope))
    } else {
        (
            Direction::Backward,
            normalize_angle(rel - std::f64::consts::PI - slope),
        )
    };
    let road = net.road_handle(&rp.road_id);
    if let (true, Some(road)) = (on_road, road) {
        e.track = Some(LaneTrack {
            road_id: rp.road_id.clone(),
            road,
            lane_id: rp.lane_id,
            s: rp.s,
            t: rp.t,
            offset: rp.offset,
            direction,
            relative_heading: along,
            blend: None,
            curvature: None,
            lanes: None,
            frame: None,
        });
    }
    e.road_position = Some(rp);
}

impl EntityQuery for World {
    fn entity(&self, name: &str) -> Option<EntityView<'_>> {
        let e = &self.entities[self.id(name)?.index()];
        e.placed.then(|| self.view(e))
    }

    fn entities(&self) -> Box<dyn Iterator<Item = EntityView<'_>> + '_> {
        Box::new(
            self.entities
                .iter()
                .filter(|e| e.placed)
                .map(|e| self.view(e)),
        )
    }

    fn road_network(&self) -> &RoadNetwork {
        &self.network
    }

    /// The run's seed for routeStrategy `random` ([`EngineConfig::seed`](crate::EngineConfig)).
    fn routing_options(&self) -> RoutingOptions {
        RoutingOptions {
            seed: self.seed,
            ..RoutingOptions::default()
        }
    }
}

/// The world together with the storyboard's element states: what conditions read, one
/// condition at a time.
pub struct ConditionWorld<'a> {
    /// The world.
    pub world: &'a World,
    /// The storyboard's states at this moment of the step.
    pub storyboard: StateView<'a>,
    /// The condition being evaluated: the key its reports for `selectTriggeringEntities` are
    /// kept under (`ConditionContext::note_triggering`, store/selection/triggering.rs).
    pub condition: ConditionId,
}

impl EntityQuery for ConditionWorld<'_> {
    fn entity(&self, name: &str) -> Option<EntityView<'_>> {
        EntityQuery::entity(self.world, name)
    }

    fn entities(&self) -> Box<dyn Iterator<Item = EntityView<'_>> + '_> {
        EntityQuery::entities(self.world)
    }

    fn road_network(&self) -> &RoadNetwork {
        &self.world.network
    }

    fn routing_options(&self) -> RoutingOptions {
        EntityQuery::routing_options(self.world)
    }
}

impl ConditionContext for ConditionWorld<'_> {
    fn simulation_time(&self) -> f64 {
        self.world.time
    }

    fn parameter(&self, name: &str) -> Option<Value> {
        self.world.parameters.get(name).cloned()
    }

    fn variable(&self, name: &str) -> Option<Value> {
        self.world.variables.get(name).cloned()
    }

    fn storyboard(&self) -> StateView<'_> {
        self.storyboard
    }

    fn entity_id(&self, name: &str) -> Option<EntityId> {
        self.world.id(name)
    }

    /// Entity `id` if placed (the store holds every id the storyboard was built with, and
    /// the spawned ones after).
    fn entity_at(&self, id: EntityId) -> Option<EntityView<'_>> {
        let e = self.world.entities.get(id.index())?;
        e.placed.then(|| self.world.view(e))
    }

    fn selection_id(&self, name: &str) -> Option<crate::condition::SelectionId> {
        self.world.selections.id(name)
    }

    fn selection_members(&self, id: crate::condition::SelectionId) -> Vec<EntityId> {
        self.world.selections.members_of(self.world, id)
    }

    fn mark_id(&self, name: &str) -> Option<crate::condition::MarkId> {
        self.world.mark_ids.get(name)
    }

    fn mark(&self, id: crate::condition::MarkId) -> Option<&crate::condition::Mark> {
        self.world.marks.get(id)
    }

    fn user_defined_value(&self, name: &str) -> Option<Value> {
        self.world.user_values.get(name).cloned()
    }

    fn traffic_signal_state(&self, name: &str) -> Option<&str> {
        self.world.signals.state(name)
    }

    fn traffic_signal_controller_phase(&self, name: &str) -> Option<&str> {
        self.world.signals.phase(name)
    }

    /// Recorded under [`ConditionWorld::condition`], the condition's dense index, not under
    /// `pos`.
    fn note_triggering(&self, _pos: &scenario::SourcePos, value: bool, held: &[EntityId]) {
        let time = self.world.time;
        self.world
            .selections
            .note_triggering(self.condition, time, value, held);
    }

    /// The time of day of the EnvironmentAction in force (seconds since the epoch): its
    /// dateTime, plus the simulation time since it was set when its `animation` is true.
    fn time_of_day(&self) -> Option<f64> {
        let clock = self.world.environment.clock_at(self.world.time)?;
        Some(clock.unix_time)
    }
}

/// The selections' view of the store (`selection::Entities`).
impl super::selection::Entities for World {
    fn entities(&self) -> &[Entity] {
        World::entities(self)
    }
    fn entity(&self, id: EntityId) -> &Entity {
        World::entity(self, id)
    }
    fn id(&self, name: &str) -> Option<EntityId> {
        World::id(self, name)
    }
}
