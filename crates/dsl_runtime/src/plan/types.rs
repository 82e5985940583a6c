//! The plan's data (ASAM OpenSCENARIO DSL 2.1 §7.3.9 phases, §8.9 movement modifiers): when
//! each phase starts and ends, what the actors do in it, and the limits and tolerances the
//! planner holds them to. The `lower` stage turns it into the 1.x model.

use scenario::{ConditionGroup, PrivateAction, Trigger};

use crate::error::Site;
use crate::resolve::{ActorData, At};
use crate::track::Track;
use crate::trigger::sim_time;

/// Maximum speed of a DSL vehicle (m/s): the DSL's vehicle has no performance fields, so every
/// vehicle has those of the bundled catalogs' cars.
pub(crate) const MAX_SPEED: f64 = 70.0;
/// Maximum acceleration and deceleration of a DSL vehicle (m/s²).
pub(crate) const MAX_ACCELERATION: f64 = 10.0;

/// How far from a constraint's value the plan may end (m), for `position(…, at: end)` checked
/// against a constant speed.
pub const POSITION_TOLERANCE: f64 = 0.5;

/// How far from a speed the engine may find an actor where it checks one at a phase end
/// (m/s): the speed actions end on their targets exactly, so this only absorbs round-off.
pub(crate) const SPEED_TOLERANCE: f64 = 0.01;

/// How far from a `lateral(…)` offset a later phase may start (m).
pub(crate) const LATERAL_TOLERANCE: f64 = 0.01;

/// How far from a heading asked the engine may find an actor where it checks one (rad,
/// 0.057°): its heading on a curved lane is the road's at the s its steps reach, which a hand
/// computation meets to 1e-4 rad (`yaw_world.osc`); a wrong heading is off by far more.
pub(crate) const HEADING_TOLERANCE: f64 = 1e-3;

/// A moment of the plan.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum When {
    /// At this simulation time (s).
    At(f64),
    /// When this trigger fires.
    Dyn(Trigger),
    /// Never (the run's bound ends it).
    Never,
    /// With the enclosing parallel (filled in once it is known).
    Pending,
}

impl When {
    /// The earlier of two ends.
    pub(crate) fn or(self, other: When) -> When {
        match (self, other) {
            (When::Pending, x) | (x, When::Pending) => x,
            (When::Never, x) | (x, When::Never) => x,
            (When::At(a), When::At(b)) => When::At(a.min(b)),
            (a, b) => {
                let mut groups = a.groups();
                groups.extend(b.groups());
                When::Dyn(Trigger {
                    condition_groups: groups,
                })
            }
        }
    }

    /// As OR-ed condition groups.
    pub(crate) fn groups(&self) -> Vec<ConditionGroup> {
        match self {
            When::At(t) => vec![ConditionGroup {
                conditions: vec![sim_time(
                    *t,
                    scenario::Rule::GreaterOrEqual,
                    scenario::SourcePos::start_of(std::sync::Arc::from(std::path::Path::new(""))),
                )],
            }],
            When::Dyn(t) => t.condition_groups.clone(),
            When::Never | When::Pending => Vec::new(),
        }
    }

    /// The time, when the plan knows it.
    pub(crate) fn time(&self) -> Option<f64> {
        match self {
            When::At(t) => Some(*t),
            _ => None,
        }
    }
}

/// One phase of the plan.
#[derive(Debug, Clone)]
pub(crate) struct PhasePlan {
    /// Its path (the Act's name).
    pub path: String,
    /// Where it is written.
    pub site: Site,
    /// Start.
    pub start: When,
    /// End.
    pub end: When,
    /// What the actors do.
    pub actions: Vec<Planned>,
    /// What the actors go on doing after the phase, until another action controls the same
    /// motion (an acceleration an action set holds): lowered to an Act of their own that runs
    /// from the phase's start to the scenario's end.
    pub persist: Vec<Planned>,
    /// What the actors do when the phase ends (a controller the phase activated, deactivated):
    /// lowered to an Act of their own that starts at the phase's end.
    pub after: Vec<Planned>,
    /// The phase lasts until its end (all but `emit`, an instant).
    pub hold: bool,
    /// The command of an instant phase to the event log (a CustomCommandAction): its type
    /// and content, `("emit", event)` for `emit`, `("call", "m(args)")` for `call`.
    pub command: Option<(&'static str, String)>,
}

/// An action of a phase.
#[derive(Debug, Clone)]
pub(crate) struct Planned {
    /// The entity.
    pub entity: String,
    /// When it starts, if not with its phase: at an absolute time, or on a trigger (the end
    /// of another action's Event).
    pub at: Option<When>,
    /// Its name.
    pub name: String,
    /// The action.
    pub action: PrivateAction,
    /// The modifier it comes from.
    pub site: Site,
}

impl Planned {
    /// `action` of `entity`, starting with its phase (no absolute start time).
    pub(crate) fn with_phase(
        entity: &str,
        name: String,
        action: PrivateAction,
        site: &Site,
    ) -> Self {
        Planned {
            entity: entity.to_string(),
            at: None,
            name,
            action,
            site: site.clone(),
        }
    }
}

/// A physical object of the plan.
#[derive(Debug, Clone)]
pub(crate) struct Entity {
    /// Its name (the actor's path).
    pub name: String,
    /// Its kind and fields (bounding box, category, axles, location).
    pub data: ActorData,
    /// Planned motion.
    pub track: Track,
    /// Its yaw relative to the road's s-axis from the start (rad) and the `yaw(…)` or
    /// `orientation(…)` that asks for it in its first phase, when other than 0 (§8.9.9; the
    /// actor stands throughout the run).
    pub yaw: Option<(f64, Site)>,
    /// It drives against s (`crate::road`): its track's s is the distance u = L − s along its
    /// direction of travel, its offsets are to the left of that direction.
    pub against: bool,
    /// The driver model that drives it from the start (a member of random traffic,
    /// `random_traffic`): its ObjectController, activated in the Init on both domains.
    pub driver: Option<scenario::Controller>,
    /// A member of random traffic created after the run's start (`random_traffic_late`): it
    /// has no Init, its creating phase places it; when, if the plan knows (`Some(None)`: after
    /// a run-time condition).
    pub created: Option<Option<f64>>,
}

/// The whole plan.
#[derive(Debug, Clone)]
pub(crate) struct Plan {
    /// The roads the actors drive on, in driving order: OpenDRIVE id and the plan's s at the
    /// road's start (`crate::road`). Never empty.
    pub roads: Vec<(String, f64)>,
    /// The plan's s at the end of its last road (m).
    pub end: f64,
    /// The roads come from a route through points (`map.create_route`): the engine is given
    /// them as a route (it would take a junction's first connection otherwise).
    pub routed: bool,
    /// The physical objects, in the order the `do` tree first names them, then the located
    /// stationary objects it does not name.
    pub entities: Vec<Entity>,
    /// The phases, children before their composition.
    pub phases: Vec<PhasePlan>,
    /// The emissions of the scenario's `on` handlers.
    pub handlers: Vec<HandlerPlan>,
}

impl Plan {
    /// The road and its own s at the plan's s `s` (the later road at a joint).
    pub(crate) fn on_road(&self, s: f64) -> (&str, f64) {
        let i = self.roads.iter().rposition(|r| r.1 <= s).unwrap_or(0);
        let (id, start) = &self.roads[i];
        (id, s - start)
    }
}

/// One `emit e` of an `on` handler: a repeatable 1.x Event that starts at each occurrence of
/// the handler's event, so that each emission is logged.
#[derive(Debug, Clone)]
pub(crate) struct HandlerPlan {
    /// `on.0`: the handler's index among the scenario's `on` directives (`do.round_two.on.0`
    /// for a handler of the behavior invoked at `do.round_two`).
    pub act: String,
    /// The command's type: `emit`, or `call` (an external method the host runs).
    pub command_type: &'static str,
    /// The emitted event's name, or the call's content.
    pub event: String,
    /// When the handler's event occurs.
    pub trigger: Trigger,
    /// The `emit` directive.
    pub site: Site,
    /// For a handler of an invoked behavior: the start and end of the invocation's phase (its
    /// Act runs between them); `None`: for the whole run.
    pub span: Option<(When, When)>,
}

/// Options of planning.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Settings {
    /// The engine's step (s).
    pub dt: f64,
    /// A phase may have no end (the run is bounded from outside).
    pub open_end: bool,
}

/// What a yaw is measured from.
#[derive(Debug, Clone)]
pub(crate) enum Frame {
    /// The world's heading plus this (0 `absolute`, π/2 `relative_to_north`), and the measure's
    /// name.
    World(f64, &'static str),
    /// Another object's heading plus this (its axis), the object's path, and the measure's
    /// name.
    Object(f64, String, String),
    /// The road's heading where the actor is (a yaw relative to the road in a later phase of
    /// an actor whose first phase asks for a heading measured so, whose yaw relative to the
    /// road is known only once the plan is made).
    Road,
}

/// A yaw in a [`Frame`] asked of an actor over a phase, checked once the plan is made
/// (`heading`).
#[derive(Debug, Clone)]
pub(crate) struct HeadingAsk {
    /// The actor.
    pub actor: String,
    /// What ψ is measured from.
    pub frame: Frame,
    /// ψ (rad).
    pub angle: f64,
    /// When it holds.
    pub at: At,
    /// The phase's start (s), if the plan knows it (else a run-time condition starts it: the
    /// engine checks the heading, `heading::engine_checks`).
    pub t0: Option<f64>,
    /// The phase's path (its Act), where the engine's checks go.
    pub phase: String,
    /// The modifier's name (`yaw`, `orientation`).
    pub modifier: String,
    /// The phase's end, if the plan knows it (s).
    pub end: Option<f64>,
    /// The phase is the actor's first.
    pub first: bool,
    /// The angle's place.
    pub site: Site,
}

/// What the phase creating random traffic asks (`Planner::creation`).
#[derive(Debug, Clone)]
pub(crate) struct Creation {
    /// The members' desired speed (m/s).
    pub v0: f64,
    /// Whether `along(r)` keeps them to +s.
    pub along: bool,
    /// The lane `lane(n [, from: left])` numbers, in each direction.
    pub lane: Option<(i64, bool)>,
    /// Whether they keep their lanes (the IDM without MOBIL).
    pub keep_lane: bool,
    /// The lane relative to another actor `lane(same_as/side_of/left_of/right_of: x)` puts
    /// them in.
    pub beside: Option<Beside>,
    /// `position(d, at: start)`: dealt only from d on along each lane's direction of travel.
    pub from_u: Option<f64>,
    /// `along(r)` on a lane, a road the map's modifiers bound, or the roads against s.
    pub route: Option<RouteOnly>,
    /// `along(r)` on a lane field no actor has bound yet: the lane another actor along it
    /// starts in (`Planner::bind_lane_field`).
    pub lane_field: Option<String>,
}

/// The part of the roads `along(r)` keeps random traffic to (`Planner::creation`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct RouteOnly {
    /// Only this lane.
    pub lane: Option<i32>,
    /// Only over this stretch of the plan's s (m, in +s).
    pub span: Option<(f64, f64)>,
    /// Only the lanes driven against s.
    pub against: bool,
}

/// `lane(n, same_as/side_of/left_of/right_of: x, side: …)` on the phase creating random
/// traffic: x, and how many lanes to its left (+) or right (−) (0: x's lane).
#[derive(Debug, Clone)]
pub(crate) struct Beside {
    /// The other actor.
    pub x: String,
    /// Lanes to x's left (+) or right (−), in x's direction of travel.
    pub by: i64,
    /// The modifier.
    pub site: Site,
}

/// Random traffic created after the start.
pub(crate) struct Late {
    /// The group.
    pub group: String,
    /// When its creating phase starts (s), if the plan knows (`None`: after a run-time
    /// condition).
    pub at: Option<f64>,
    /// That phase's path.
    pub phase: String,
    /// What it asks.
    pub creation: Creation,
}

/// A point of a crossing: lane, the plan's s and t (m).
pub(crate) type CrossingPoint = (i32, f64, f64);

/// A walk of an actor along a crossing's line, as the plan knows it: from its start to its
/// end in the plan's (s, t), timed from `t0` to `t1`; `uniform` when at one speed (a walk, a
/// move or a drive; a speed action's place in between is not the plan's).
#[derive(Debug, Clone)]
pub(crate) struct CrossingLine {
    pub actor: String,
    pub t0: f64,
    pub t1: f64,
    pub from: (f64, f64),
    pub to: (f64, f64),
    pub uniform: bool,
}

impl CrossingLine {
    /// The line's (s, t) from its two points.
    pub(crate) fn new(
        actor: &str,
        (t0, t1): (f64, f64),
        a: CrossingPoint,
        b: CrossingPoint,
    ) -> Self {
        CrossingLine {
            actor: actor.to_string(),
            t0,
            t1,
            from: (a.1, a.2),
            to: (b.1, b.2),
            uniform: true,
        }
    }
}
