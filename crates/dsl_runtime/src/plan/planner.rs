//! The planner's working state: the entities registered so far with their planned tracks, the
//! phases planned, and what the scenario's events and routes are; the other `plan` modules add
//! methods that plan phases, invocations and conditions on it.

use std::cell::RefCell;
use std::collections::{BTreeMap, HashMap, HashSet};

use scenario::{ConditionGroup, StoryboardElementState, Trigger};

use super::types::{Entity, PhasePlan, Settings, When};
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{ActorKind, Along, At, Cond, Draws, Object, Phase};
use crate::road::PlanRoad;
use crate::track::Track;
use crate::trigger::act_state;

/// Where an event specification is used: what its event context starts with (ASAM
/// OpenSCENARIO DSL 2.1 §7.3.10.4).
#[derive(Debug, Clone, Copy)]
pub(super) enum EventCtx<'w> {
    /// An `on` handler of the scenario: the start of the run.
    Run,
    /// An `on` handler of the behavior invoked at the phase of this path: the start of the
    /// invocation (its handlers' Acts run from the invocation's start to its end; an event it
    /// emits can only be waited on inside the invocation, where its key is known).
    Invocation(&'w str),
    /// The `wait` or `until` of a phase: the phase's start.
    Phase {
        path: &'w str,
        site: &'w Site,
        start: &'w When,
        until: bool,
    },
}

/// An event condition the planner translates where the event is used: the condition (or why
/// it cannot be run), where it is written, and, for an `on` handler's, its own event context
/// (the run, or the invocation it belongs to; a declared event takes the context of the place
/// it is used).
pub(crate) type EventUse<'a> = (&'a Result<Cond, Error>, &'a Site, Option<EventCtx<'a>>);

pub(crate) struct Planner<'a> {
    pub road: PlanRoad<'a>,
    pub settings: Settings,
    /// What each actor path of the tree is.
    pub objects: &'a BTreeMap<String, Option<Object>>,
    pub entities: Vec<Entity>,
    pub index: HashMap<String, usize>,
    pub groups: HashMap<String, Vec<String>>,
    /// The groups whose formation spreads over the lanes (common route, not single-lane).
    pub across: HashSet<String>,
    /// The `random_traffic_vehicle_group`s → where the tree first names each
    /// (`random_traffic`).
    pub random: HashMap<String, Site>,
    pub first_leaf: HashMap<String, String>,
    pub phases: Vec<PhasePlan>,
    /// The speed each actor's last planned speed change ends at (known also when the times
    /// are not).
    pub last_v: HashMap<String, f64>,
    /// Event name → the paths of the phases that emit it.
    pub emits: HashMap<String, Vec<(String, Site)>>,
    /// Event name → the conditions that make it occur: its declared one (`event e is c`) and
    /// those of the `on c: emit e` handlers.
    pub events: HashMap<String, Vec<EventUse<'a>>>,
    /// Leaf path → its `along(…)` routes, with when each holds.
    pub alongs: HashMap<String, Vec<(At, Along)>>,
    /// Lane field (a free one-lane route, a `target:` lane) → its lane on the plan road and
    /// what bound it (`lane_fields`, `route::check`).
    pub route_lanes: HashMap<String, (i32, String)>,
    /// Lane field the map's modifiers bound → the road of its lane and the plan's s of its
    /// lane section's start and end when that road is the plan's (`map_lanes`).
    pub lane_roads: HashMap<String, (String, Option<(f64, f64)>)>,
    /// Road field the map's modifiers bound to a road of the plan (`routes_are_in_sequence`)
    /// → the lane bound on it, the plan's s of the road's start and end, and what bound it.
    pub route_roads: HashMap<String, (i32, (f64, f64), String)>,
    /// Crossing field the map's `crossing_connects` bound → the crossing (`map_crossings`).
    pub crossings: HashMap<String, super::map_crossings::MapCrossing>,
    /// The walks along crossings planned so far (`crossing_beside`).
    pub crossing_lines: Vec<super::types::CrossingLine>,
    /// `lateral(…, x)` at: all of a first phase: (actor, x, phase start, phase end if known,
    /// the modifier), checked once every phase is planned.
    pub beside_checks: Vec<(String, String, f64, Option<f64>, Site)>,
    /// `lateral(…, x)` at: all that the engine follows while x moves sideways
    /// (`lateral_follow`), checked once every phase is planned.
    /// (actor, x, phase start, phase end if known, the actor's t minus x's, the modifier).
    pub beside_follows: Vec<(String, String, f64, Option<f64>, f64, Site)>,
    /// `position(…, ahead_of/behind: x)` and `lane(…: x)` at: all over a phase the plan knows
    /// from its start to its end (`held_relation`), checked once every phase is planned:
    /// (actor, the modifier, phase start, phase end), as `held_relation::HeldRelation` names it.
    pub held_relations: Vec<(String, crate::resolve::Modifier, f64, f64)>,
    /// Yaws measured in the world or from another object (`heading`), checked once every
    /// phase is planned.
    pub heading_asks: Vec<super::types::HeadingAsk>,
    /// The side drawn for each `change_lane(…)` without one (by the modifier's span).
    pub sides: RefCell<HashMap<String, bool>>,
    /// The run's draws after the resolver's.
    pub draws: RefCell<Draws>,
    /// Actors the engine's gap controller moves (`gap_actions`), with the start of the gap
    /// action when the plan knows it: their tracks are not planned from there on.
    pub engine_moved: HashMap<String, Option<f64>>,
    /// Of `engine_moved`, the actors whose lane only the engine sets (a following of the lanes
    /// of an actor the engine moves, `held_relation`), from when: their speed and place along
    /// their lane are still the plan's.
    pub lane_only: HashMap<String, Option<f64>>,
    /// Actors of `lane_only` with a later phase at a time the plan sets (its start and site):
    /// such a phase runs unless something reads the actor's lane from the time the engine
    /// sets it (`lane_read`), the read's time kept here for the error (`lane_blind_error`).
    pub lane_blind: RefCell<BTreeMap<String, LaneBlind>>,
    /// Each actor's last gap action: its reference, what it keeps, and the path of its phase
    /// when the action ends that phase (a change without the phase's own duration or `until`).
    pub gaps: HashMap<String, (String, Gap, Option<String>)>,
    /// A member of a `serial` (its path) → the member before it: the phase whose end starts it.
    pub serial_before: HashMap<String, String>,
    /// The plan's roads driven against s (`PlanRoad::against`), when an actor drives them
    /// so: the road the invocations of such an actor are planned on (`plan_invoke`).
    pub against_road: Option<PlanRoad<'a>>,
    /// Random traffic created after the run's start, placed once every phase is planned
    /// (`random_traffic_late`).
    pub late_random: Vec<super::types::Late>,
    /// Random traffic that found no room at the run's start (`place_random_traffic`): the
    /// error, raised where the group is created then (a group created later is dealt again
    /// at its creation).
    pub unplaced_random: HashMap<String, Error>,
    /// Route field `routes_are_opposite` binds to the plan's roads driven against s → what
    /// bound it (`against::bind_routes`).
    pub against_routes: HashMap<String, String>,
}

/// What a gap action keeps (`gap_actions`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Gap {
    /// A space gap between the bounding boxes (m).
    Space(f64),
    /// A time headway between the reference points (s).
    Headway(f64),
    /// A space gap across the road between the bounding boxes (m).
    Lateral(f64),
}

impl Gap {
    /// The number kept (m or s).
    pub(crate) fn value(self) -> f64 {
        match self {
            Gap::Space(x) | Gap::Headway(x) | Gap::Lateral(x) => x,
        }
    }
}

/// The error of a phase that nothing ends.
pub(crate) fn no_end(p: &Phase) -> Error {
    p.site.err(
        K::NoEnd,
        format!(
            "expected a way for phase `{}` to end (a duration, an until, or a member that ends), found none; give it one or bound the run with --duration",
            p.path
        ),
    )
}

/// A later phase, at a time the plan sets, of an actor whose lane the engine sets
/// (`Planner::lane_blind`).
#[derive(Debug, Clone)]
pub struct LaneBlind {
    /// When the engine sets the actor's lane from (`None`: a run-time start).
    pub since: Option<f64>,
    /// The phase's start (s).
    pub start: f64,
    /// Where the phase is written.
    pub site: Site,
    /// The first time at which the plan read the actor's lane from `since` on, if it did.
    pub read: Option<f64>,
}

/// The error of a stationary object `path` (used at `site`) that no `location(…)` puts anywhere.
pub(crate) fn unlocated(path: &str, site: &Site) -> Error {
    site.err(
        K::UnknownActor,
        format!("expected a location of stationary object `{path}` ({path}.location(pose) before the do, §8.7.3.1.1), found none"),
    )
}

impl Planner<'_> {
    /// Registers the physical object(s) `path` names (written at `site`); returns the entity
    /// names.
    pub(crate) fn register(&mut self, path: &str, site: &Site) -> Result<Vec<String>, Error> {
        let members = match self.objects.get(path).cloned().flatten() {
            Some(Object::Actor(data)) => vec![(path.to_string(), data)],
            Some(Object::Unlocated) => return Err(unlocated(path, site)),
            Some(Object::Group(members, lanes)) => {
                self.groups.insert(
                    path.to_string(),
                    members.iter().map(|(n, _)| n.clone()).collect(),
                );
                if lanes {
                    self.across.insert(path.to_string());
                }
                members
            }
            Some(Object::RandomTraffic(members)) => {
                // Each member drives as the group's drive asks (`random_traffic`).
                self.groups.insert(
                    path.to_string(),
                    members.iter().map(|(n, _)| n.clone()).collect(),
                );
                self.random
                    .entry(path.to_string())
                    .or_insert_with(|| site.clone());
                members
            }
            None => {
                return Err(site.err(
                    K::UnknownActor,
                    format!("expected a physical object (vehicle, person, animal, stationary_object) or vehicle group of the scenario, found `{path}`"),
                ))
            }
        };
        let mut names = Vec::new();
        for (n, data) in members {
            if !self.index.contains_key(&n) {
                self.index.insert(n.clone(), self.entities.len());
                self.entities.push(Entity {
                    name: n.clone(),
                    data,
                    track: Track::new(0.0, 0.0, -1),
                    yaw: None,
                    against: false,
                    driver: None,
                    created: None,
                });
            }
            names.push(n);
        }
        Ok(names)
    }

    pub(crate) fn track(&self, name: &str) -> &Track {
        &self.entities[self.index[name]].track
    }

    /// s of `name` at time `t`: its track's distance along its lane's centre line from its
    /// start, as s of the road (the engine moves vehicles along lane centres).
    pub(crate) fn s_at(&self, name: &str, t: f64) -> f64 {
        self.s_on(&self.road, name, t)
    }

    /// [`s_at`](Self::s_at) on `road` (the plan road, or the view `name` is planned on).
    pub(crate) fn s_on(&self, road: &PlanRoad<'_>, name: &str, t: f64) -> f64 {
        self.track(name).s_on(road, t)
    }

    /// The lane `name` is in at time `t`: the lane planned for `t`, followed from where it was
    /// planned along its links into the lane sections after it (`Track::lane_on`; the engine
    /// follows them too, ASAM OpenDRIVE 1.8 §11.5 lane linkage). Every lane a phase reads of
    /// an actor is this one (a track's stored ids are private to it).
    pub(crate) fn lane_now(&self, name: &str, t: f64) -> i32 {
        self.lane_on(&self.road, name, t)
    }

    /// [`lane_now`](Self::lane_now) on `road` (the plan road, or the view `name` is planned on).
    pub(crate) fn lane_on(&self, road: &PlanRoad<'_>, name: &str, t: f64) -> i32 {
        self.lane_read(name, t);
        self.track(name).lane_on(road, t)
    }

    /// The lane `name` was planned in last, followed to where the plan last knows it (a phase
    /// that starts on a run-time condition starts from there).
    pub(crate) fn lane_last(&self, name: &str) -> i32 {
        let t = self.last_known();
        self.lane_read(name, t);
        self.track(name).last_lane_on(&self.road, t)
    }

    /// Whether `name` changes lanes between times `a` < `b` (`Track::changes_lane`: the lane
    /// at `a` followed along its links to `b` is not the lane there).
    pub(crate) fn changes_lane(&self, name: &str, a: f64, b: f64) -> bool {
        self.lane_read(name, b);
        self.track(name).changes_lane(&self.road, a, b)
    }

    /// Notes a read of `name`'s lane at `t` where the engine sets that lane then and `name` has
    /// a later phase at a time the plan sets (`lane_blind`): the plan's track has a lane there
    /// the engine does not (`lane_blind_error` refuses the phase).
    fn lane_read(&self, name: &str, t: f64) {
        if let Some(blind) = self.lane_blind.borrow_mut().get_mut(name) {
            if blind.read.is_none() && t >= blind.since.unwrap_or(f64::NEG_INFINITY) {
                blind.read = Some(t);
            }
        }
    }

    /// The error of a phase of an actor whose lane the engine sets (`lane_only`) at a time the
    /// plan sets, where the plan read that lane (`lane_read`), if any.
    pub(crate) fn lane_blind_error(&self) -> Result<(), Error> {
        let blind = self.lane_blind.borrow();
        let Some((name, b, read)) = blind.iter().find_map(|(n, b)| b.read.map(|r| (n, b, r)))
        else {
            return Ok(());
        };
        Err(b.site.err(
            K::Unsatisfiable,
            format!(
                "expected this phase of `{name}` to start on a run-time condition (until, wait), or to leave its lane alone, found it at {:.2} s reading `{name}`'s lane at {read:.2} s, which the engine sets from {} (a following of the lanes of an actor the engine moves, lane(…: x) at: all): the plan knows its speed and its place along its lane, not its lane",
                b.start,
                b.since
                    .map_or("the start of that following".to_string(), |s| format!("{s:.2} s")),
            ),
        ))
    }

    /// From `since` (`None`: a run-time start) the engine moves `name` (a gap action's or a
    /// model's controller, …): the plan plans no track of it from then on (`engine_moved`),
    /// its lane and its motion along it both.
    pub(crate) fn engine_moves(&mut self, name: &str, since: Option<f64>) {
        self.lane_only.remove(name);
        self.engine_moved.insert(name.to_string(), since);
    }

    /// The overhangs of `actor`'s and `other`'s bounding boxes towards each other (m): the
    /// actor's front and the other's rear when the other is ahead, else the reverse; the
    /// distance between the reference points less this is the gap between the boxes.
    pub(crate) fn facing_overhangs(&self, actor: &str, other: &str, other_ahead: bool) -> f64 {
        let bb = |n: &str| self.entities[self.index[n]].data.bounding_box;
        let front = |b: scenario::BoundingBox| b.center[0] + b.length / 2.0;
        let rear = |b: scenario::BoundingBox| b.length / 2.0 - b.center[0];
        let (a, o) = (bb(actor), bb(other));
        if other_ahead {
            front(a) + rear(o)
        } else {
            rear(a) + front(o)
        }
    }

    /// t of `name`'s reference point across the road at time `t` (m): its planned lane's centre
    /// and offset from it.
    pub(crate) fn t_at(&self, name: &str, t: f64) -> f64 {
        self.t_on(&self.road, name, t)
    }

    /// [`t_at`](Self::t_at) on `road` (the plan road, or the view `name` is planned on).
    pub(crate) fn t_on(&self, road: &PlanRoad<'_>, name: &str, t: f64) -> f64 {
        road.lane_center(self.lane_on(road, name, t), self.s_on(road, name, t))
            + self.track(name).offset(t)
    }

    /// How far `name`'s bounding box reaches from its reference point to its left (`left`) or
    /// right side (m).
    pub(crate) fn side_extent(&self, name: &str, left: bool) -> f64 {
        let b = self.entities[self.index[name]].data.bounding_box;
        b.width / 2.0 + if left { b.center[1] } else { -b.center[1] }
    }

    /// The width of `name`'s bounding box (m).
    pub(crate) fn width(&self, name: &str) -> f64 {
        self.entities[self.index[name]].data.bounding_box.width
    }

    /// Whether `name` is a person, who walks on the road's sidewalks (`crate::road`).
    pub(crate) fn walks(&self, name: &str) -> bool {
        matches!(
            self.entities[self.index[name]].data.kind,
            ActorKind::Walker(scenario::PedestrianCategory::Pedestrian)
        )
    }

    pub(crate) fn track_mut(&mut self, name: &str) -> &mut Track {
        let i = self.index[name];
        &mut self.entities[i].track
    }

    /// A draw among `n` choices.
    pub(crate) fn choose(&self, n: usize) -> usize {
        self.draws.borrow_mut().choose(n)
    }

    /// The moment `d` s after phase `path` (written at `site`) starts at `start`.
    pub(crate) fn after(&self, path: &str, site: &Site, start: &When, d: f64) -> When {
        match start {
            When::At(t) => When::At(t + d),
            _ => When::Dyn(Trigger {
                condition_groups: vec![ConditionGroup {
                    conditions: vec![act_state(
                        path,
                        StoryboardElementState::RunningState,
                        // The Act's stop trigger is first sampled one step after it starts.
                        (d - self.settings.dt).max(0.0),
                        site.pos.clone(),
                    )],
                }],
            }),
        }
    }
}
