//! `random_traffic_vehicle_group` (ASAM OpenSCENARIO DSL 2.1 §8.7.18.1, non-normative:
//! "adding entities to a scenario to have more participants in the scenario. By generating
//! multiple vehicles in the surrounding environment of the scenario these vehicles act as
//! 'noise' in the scenario"; "the group defines the initial conditions of actors in the
//! scenario, meaning their creation and destruction. The behavioral model assigned to each
//! vehicle defines the actual behavior of the vehicle within the group").
//!
//! `g.drive()` on such a group creates its members at the start of the run and hands each to
//! the engine's driver model. The standard is silent on every number; oscsim's choices
//! (docs/dsl.md, the random traffic row):
//!
//! - **Desired speed** v0: the drive's `speed(v)`, else the planner's 50 km/h.
//! - **Start speeds**: each member's drawn uniformly in [0.9·v0, 1.1·v0] from the run's seed
//!   (`Options::seed`; [`START_SPREAD`]).
//! - **Where**: the plan's driving lanes of both directions (OpenDRIVE 1.8 §11.2, right-hand
//!   traffic: the left side's lanes driven in −s; noise on a two-way road is oncoming traffic
//!   too): the lanes `PlanRoad::driving_lanes` gives on the plan road and on its view against s
//!   (`PlanRoad::against`, s then the distance u along the direction of travel), sampled every
//!   [`LANE_STEP`] m, each member's box wholly within a stretch of one lane. A member placed in
//!   a lane driven in −s drives against s (lowered with its lane's driving direction; the
//!   engine's `mobil` model follows its leader in that direction and changes lanes only to a
//!   lane driven the same way). `along(r)` on the route the runtime chooses (the plan's roads,
//!   a route in +s) keeps the members to +s, as does a plan whose left lanes do not run on over
//!   its roads. Between any two vehicles in a lane, in the lane's own direction — member and
//!   member, member and another actor of the scenario, an oncoming one included — at least the IDM's desired gap at a standstill plus one
//!   headway at the fastest start speed on the road, s0 + v_max·T (bumper to bumper, s0 = 2 m,
//!   T = 1.6 s, the engine's IDM defaults). The members are dealt to the free stretches one at
//!   a time, a stretch drawn with a weight equal to the room left in it (so traffic spreads
//!   evenly over the road, and the directions share it by their free lane length), then each stretch's members are spread uniformly over its slack:
//!   n draws in [0, F] sorted, F the stretch's length less the members' lengths and gaps
//!   (each arrangement at the minimum gap equally likely). No stretch with room left for a
//!   member is an error at the group naming how many fit.
//! - **Driver**: an ObjectController per member with the engine's `mobil` model (IDM car
//!   following with MOBIL lane changes, the engine's defaults for every other parameter),
//!   `desiredSpeed` v0, activated in the Init on the domains its model holds
//!   ([`driver_domains`]; the `idm` of members kept in their lanes holds the longitudinal one
//!   only): the member drives by the model
//!   from the first step to the end of the run (the drive's phase ending does not stop it:
//!   the group defines creation, the model the behaviour).
//!
//! - **Lanes**: `lane(n [, from: left])` (at: start or all) deals the members to the lane so
//!   numbered in each direction of travel only (`PlanRoad::numbered` on the plan road and on
//!   its view against s); `lane(n, same_as/side_of/left_of/right_of: x)` to x's lane or the
//!   one n beside it, in x's direction, where the plan has x at the creation; at: all, `keep_lane()` and `follow_lane()` (`drive() with:
//!   keep_lane()`, §8.8.3.2) keep them there: their model is then the engine's `idm`, the
//!   IDM without MOBIL's lane changes.
//! - **Several groups**: placed in the order of their names, each after every other actor and
//!   the members of the groups before it, which it keeps the gap from.
//!
//! The phase that creates the members is the group's first, `drive()`, `move()`,
//! `follow_lane()` or `remain_stationary()` (placed standing, desired speed 0), or a speed
//! action (`change_speed(v)`, `assign_speed(v)`, `keep_speed()`: created as by `drive()`
//! without a speed, then the action given to each member's model as a later one is; at the
//! start the model has it from the Init), and starts with the run or later
//! (`random_traffic_late`: dealt by the plan, or by the engine where the plan does not know
//! the others' places). Its modifiers say where the members are dealt
//! (`random_traffic_creation`); what would set a member's motion is bad input there. The
//! group's later actions are given to each member's model (`random_traffic_actions`).

use std::collections::{HashMap, HashSet};

use scenario::traffic_deal::{self, LaneSpan, Member, Occupant};
use scenario::ControllerDomains;

use super::car_following::model_controller;
use super::place::Start;
use super::planner::Planner;
use super::speed_actions::speed_target;
use super::types::{Creation, Late, Planned, When};
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{Action, Invoke, Kind, Phase};
use crate::road::PlanRoad;

/// The start of a member before [`Planner::place_random_traffic`] places it.
pub(super) const UNPLACED: Start = Start {
    lane: -1,
    s: 0.0,
    v: 0.0,
    offset: 0.0,
};

/// Start speeds are drawn uniformly within this fraction of the desired speed either side.
pub(crate) const START_SPREAD: f64 = 0.1;
/// The spacing along s at which the driving lanes are sampled (m).
pub(super) const LANE_STEP: f64 = 1.0;
/// The ObjectController's name.
pub(super) const CONTROLLER: &str = "random_traffic";

/// The domains a member's driver `c` is activated on: those its engine model holds (engine
/// README "Controllers": `mobil` both, `idm` the longitudinal one). The `idm` holds no lateral
/// domain: asked for it, the engine's record said "lateral is not a domain of this controller:
/// not activated" at every idm member's creation; a mandatory lane it is handed later it
/// decides on without holding that domain (engine controller/strategy.rs).
pub(crate) fn driver_domains(c: &scenario::Controller) -> ControllerDomains {
    let mobil = c
        .properties
        .properties
        .iter()
        .any(|(k, v)| k == "model" && v == "mobil");
    ControllerDomains {
        longitudinal: Some(true),
        lateral: mobil.then_some(true),
        ..ControllerDomains::default()
    }
}

/// Another vehicle on the road as `Planner::deal` counts it.
pub(super) type Other = Occupant;

/// The lanes random traffic is dealt to (else every driving lane).
#[derive(Debug, Clone, Copy)]
pub(super) enum Lanes {
    /// The lane numbered n from the right (from the left) in each direction.
    Numbered(i64, bool),
    /// This lane id.
    Id(i32),
}

impl Planner<'_> {
    /// Whether `name` is a member of a `random_traffic_vehicle_group`.
    pub(super) fn random_member(&self, name: &str) -> bool {
        self.random.keys().any(|g| {
            self.groups
                .get(g)
                .is_some_and(|m| m.iter().any(|n| n == name))
        })
    }

    /// Places the members of every random traffic group among `starts` (the other actors
    /// placed but those `held` for `random_traffic_relations`; those in `against` driving
    /// against s, their starts in u), from the phase that creates them among `leaves`.
    /// Returns the members placed against s.
    pub(super) fn place_random_traffic(
        &mut self,
        leaves: &[&Phase],
        starts: &mut HashMap<String, Start>,
        against: &HashSet<String>,
        held: &HashSet<String>,
    ) -> Result<HashSet<String>, Error> {
        let mut oncoming = HashSet::new();
        // Members of the groups placed before this one: others for the next group.
        let mut placed: HashSet<String> = HashSet::new();
        let mut groups: Vec<(String, Site)> = self
            .random
            .iter()
            .map(|(g, s)| (g.clone(), s.clone()))
            .collect();
        groups.sort_by(|a, b| a.0.cmp(&b.0));
        for (g, site) in groups {
            let members = self.groups[&g].clone();
            let Some(first) = members.first().and_then(|m| self.first_leaf.get(m)) else {
                continue;
            };
            let leaf = leaves.iter().find(|l| &l.path == first);
            let inv = match leaf.map(|l| &l.kind) {
                Some(Kind::Invoke(inv)) => Some(inv),
                _ => None,
            };
            let mut c = self.creation(&g, inv)?;
            self.bind_lane_field(&g, &mut c, Some(starts), &site)?;
            // A speed action creating the group: the models' desired speed from the start,
            // its target or (keep_speed) each member's own start speed.
            let given = match (leaf, inv) {
                (Some(p), Some(inv))
                    if matches!(inv.kind, Action::ChangeSpeed | Action::AssignSpeed) =>
                {
                    Some(Some(speed_target(inv, p)?))
                }
                (_, Some(inv)) if inv.kind == Action::KeepSpeed => Some(None),
                _ => None,
            };
            // Every other actor already placed (members of the groups before this one
            // included), with its direction (its start in u against s).
            let others: Vec<Other> = self
                .entities
                .iter()
                .filter(|e| !self.random_member(&e.name) || placed.contains(&e.name))
                // Placed from a member once the members are drawn (`random_traffic_relations`).
                .filter(|e| !held.contains(&e.name))
                .filter_map(|e| {
                    let st = starts.get(&e.name)?;
                    let back = against.contains(&e.name) || oncoming.contains(&e.name);
                    Some(self.other(&e.name, back, st.lane, st.s, st.v))
                })
                .collect();
            let beside = match &c.beside {
                Some(b) => {
                    // A member of random traffic: where the seed drew it, if its group was
                    // dealt before this one.
                    let drawn = !self.random_member(&b.x) || placed.contains(&b.x);
                    let x_at = starts
                        .get(&b.x)
                        .filter(|_| !held.contains(&b.x) && drawn)
                        .map(|st| {
                            let back = against.contains(&b.x) || oncoming.contains(&b.x);
                            (back, st.lane, st.s)
                        });
                    Some(self.beside_lane(&g, b, x_at)?)
                }
                None => None,
            };
            // No room: an error if the group is created at the start (`plan_random_traffic`),
            // else dealt again when it is created.
            let dealt = match self.deal(&g, &site, &members, &c, &others, beside) {
                Ok(dealt) => dealt,
                Err(e) => {
                    self.unplaced_random.insert(g.clone(), e);
                    members
                        .iter()
                        .map(|m| (m.clone(), false, UNPLACED))
                        .collect()
                }
            };
            for (m, back, st) in dealt {
                if back {
                    oncoming.insert(m.clone());
                }
                placed.insert(m.clone());
                starts.insert(m, st);
            }
            let Creation { v0, keep_lane, .. } = c;
            for m in &members {
                let e = self.index[m];
                // Lane changes by MOBIL, unless the members keep their lanes: the IDM alone.
                let model = if keep_lane { "idm" } else { "mobil" };
                let v0 = match given {
                    Some(Some(v)) => v,
                    Some(None) => starts.get(m).map_or(v0, |st| st.v),
                    None => v0,
                };
                self.entities[e].driver = Some(model_controller(CONTROLLER, model, v0, &[], &site));
                // From the start the engine's model moves the member.
                self.engine_moves(m, Some(0.0));
            }
        }
        Ok(oncoming)
    }

    /// The box of actor `name` (`back`: driving against s) in lane `lane` at s `s` (u against
    /// s), at speed `v`, as `deal` counts it.
    pub(super) fn other(&self, name: &str, back: bool, lane: i32, s: f64, v: f64) -> Other {
        let b = self.entities[self.index[name]].data.bounding_box;
        let front = b.center[0] + b.length / 2.0;
        let rear = b.length / 2.0 - b.center[0];
        Occupant {
            against: back,
            lane,
            rear: s - rear,
            front: s + front,
            speed: v,
        }
    }

    /// Deals the members of random traffic `g` (written at `site`) as creation `c` asks over
    /// the free stretches of the driving lanes among `others` (module doc; the rule is
    /// `scenario::traffic_deal`'s, which the engine shares): each member's name, whether it
    /// drives against s, and its start (s: u against s).
    pub(super) fn deal(
        &mut self,
        g: &str,
        site: &Site,
        members: &[String],
        c: &Creation,
        others: &[Other],
        beside: Option<(bool, i32)>,
    ) -> Result<Vec<(String, bool, Start)>, Error> {
        let speeds = self.start_speeds(members, c.v0);
        let spans = self.lane_spans(c, beside);
        let dealt: Vec<Member> = members.iter().map(|m| self.member(m)).collect();
        let draws = &self.draws;
        let dealt = traffic_deal::deal(&spans, others, &dealt, &speeds, &mut || {
            draws.borrow_mut().uniform()
        })
        .map_err(|e| {
            let (expected, found) = e.message(members.len(), g);
            site.err(
                K::Unsatisfiable,
                format!("expected {expected}, found {found}"),
            )
        })?;
        Ok(dealt
            .into_iter()
            .map(|d| {
                (
                    members[d.member].clone(),
                    d.against,
                    Start {
                        lane: d.lane,
                        s: d.s,
                        v: speeds[d.member],
                        offset: 0.0,
                    },
                )
            })
            .collect())
    }

    /// The members' start speeds, each drawn uniformly in [0.9·v0, 1.1·v0] from the run's
    /// seed.
    pub(super) fn start_speeds(&self, members: &[String], v0: f64) -> Vec<f64> {
        members
            .iter()
            .map(|_| {
                v0 * (1.0 - START_SPREAD + 2.0 * START_SPREAD * self.draws.borrow_mut().uniform())
            })
            .collect()
    }

    /// Member `m` as the dealing counts it: its length and rear bumper to reference point.
    pub(super) fn member(&self, m: &str) -> Member {
        let b = self.entities[self.index[m]].data.bounding_box;
        Member {
            length: b.length,
            rear: b.length / 2.0 - b.center[0],
        }
    }

    /// The driving lanes creation `c` deals to, over the plan's roads (and, unless `along(r)`
    /// keeps the members to +s, their view against s: OpenDRIVE 1.8 §11.2, the left side's
    /// lanes driven in −s); `beside`: only that lane, in that direction.
    pub(super) fn lane_spans(
        &mut self,
        c: &Creation,
        beside: Option<(bool, i32)>,
    ) -> Vec<LaneSpan> {
        // The lanes dealt to: numbered in each direction, or one lane beside another actor
        // in that actor's direction only.
        let route_lane = c.route.and_then(|r| r.lane);
        let lane = match (beside, route_lane) {
            (Some((_, id)), _) | (None, Some(id)) => Some(Lanes::Id(id)),
            (None, None) => c.lane.map(|(n, left)| Lanes::Numbered(n, left)),
        };
        let (forward, back) = match (beside, c.route) {
            (Some((against, _)), _) => (!against, against),
            (None, Some(r)) => (!r.against, r.against),
            (None, None) => (true, !c.along),
        };
        let mut spans = if forward {
            lane_spans(&self.road, false, lane)
        } else {
            Vec::new()
        };
        if back {
            if self.against_road.is_none() {
                if let Ok(view) = self.road.against() {
                    self.against_road = Some(view);
                }
            }
            if let Some(view) = &self.against_road {
                spans.extend(lane_spans(view, true, lane));
            }
        }
        // `position(d)` from d on along each lane's direction; a bound road's stretch.
        let length = self.road.length();
        let within = |sp: &LaneSpan| {
            let (mut a, mut b) = (sp.from, sp.to);
            if let Some(d) = c.from_u {
                a = a.max(d);
            }
            if let Some((s0, s1)) = c.route.and_then(|r| r.span) {
                let (u0, u1) = if sp.against {
                    (length - s1, length - s0)
                } else {
                    (s0, s1)
                };
                a = a.max(u0);
                b = b.min(u1);
            }
            (b > a).then_some(LaneSpan {
                from: a,
                to: b,
                ..*sp
            })
        };
        spans.iter().filter_map(within).collect()
    }

    /// Action `inv` of random traffic `inv.actor` (phase `p`, starting at `t0`): the phase
    /// that creates its members (planned by `place_random_traffic`: their starts and drivers)
    /// or a later action given to their models (`random_traffic_actions`) into `out` (and
    /// `after`, at the phase end); what it cannot run is an error. Returns the phase's end when the action sets it.
    pub(super) fn plan_random_traffic(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        t0: Option<f64>,
        out: &mut Vec<Planned>,
        after: &mut Vec<Planned>,
    ) -> Result<Option<When>, Error> {
        let g = &inv.actor;
        let first = self.groups[g]
            .iter()
            .all(|m| self.first_leaf.get(m) == Some(&p.path));
        if !first {
            return self.plan_random_traffic_action(p, inv, t0, out, after);
        }
        let speed_action = matches!(
            inv.kind,
            Action::ChangeSpeed | Action::AssignSpeed | Action::KeepSpeed
        );
        if !speed_action
            && !matches!(
                inv.kind,
                Action::Move | Action::FollowLane | Action::RemainStationary
            )
        {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected drive(), move(), follow_lane(), remain_stationary(), change_speed(…), assign_speed(…) or keep_speed() creating random traffic `{g}` (the engine's driver model drives its members from then on: \"the behavioral model assigned to each vehicle defines the actual behavior of the vehicle within the group\", §8.7.18.1, so their lanes, places and paths are the model's), found {}(…)", inv.action),
            ));
        }
        if t0.is_some_and(|t| t <= 0.0) {
            if let Some(e) = self.unplaced_random.remove(g) {
                return Err(e);
            }
        } else {
            // Created among the others' places then, once every phase is planned: by the
            // plan, or by the engine where the plan does not know them (`random_traffic_late`).
            let creation = self.creation(g, Some(inv))?;
            self.late_random.push(Late {
                group: g.clone(),
                at: t0,
                phase: p.path.clone(),
                creation,
            });
        }
        if speed_action {
            // Created as by drive() (start speeds drawn around the default desired speed),
            // then the action given to each member's model as a later one is (its
            // modifiers, read by the creation, are not the model's). Created at the start,
            // the models have it from the Init (`place_random_traffic`): only its end here.
            let given = Invoke {
                modifiers: Vec::new(),
                ..inv.clone()
            };
            if t0.is_some_and(|t| t <= 0.0) {
                let (mut none, mut nor) = (Vec::new(), Vec::new());
                return self.plan_random_traffic_action(p, &given, t0, &mut none, &mut nor);
            }
            return self.plan_random_traffic_action(p, &given, t0, out, after);
        }
        Ok(None)
    }
}

/// The driving lanes of `road` (the plan's roads in +s, or the view of them driven against s:
/// `against`, s then the distance u along the direction of travel), each over the stretches
/// where it runs, sampled every [`LANE_STEP`] m, in lane order; with `lane` only the lane so
/// numbered in that direction (or of that id) where it is.
pub(super) fn lane_spans(road: &PlanRoad<'_>, against: bool, lane: Option<Lanes>) -> Vec<LaneSpan> {
    let length = road.length();
    let steps = (length / LANE_STEP).floor() as usize;
    let mut spans: Vec<(i32, f64, f64)> = Vec::new();
    let mut open: Vec<(i32, f64, f64)> = Vec::new();
    for k in 0..=steps + 1 {
        let s = (k as f64 * LANE_STEP).min(length);
        let lanes = match lane {
            _ if k > steps => Vec::new(),
            Some(Lanes::Numbered(n, from_left)) => {
                road.numbered(n, from_left, s, false).into_iter().collect()
            }
            Some(Lanes::Id(id)) => road
                .driving_lanes(s)
                .into_iter()
                .filter(|l| *l == id)
                .collect(),
            None => road.driving_lanes(s),
        };
        let (keep, closed): (Vec<_>, Vec<_>) =
            open.into_iter().partition(|(l, _, _)| lanes.contains(l));
        spans.extend(closed);
        open = keep
            .into_iter()
            .map(|(l, a, _)| (l, a, s))
            .collect::<Vec<_>>();
        for l in lanes {
            if !open.iter().any(|o| o.0 == l) {
                open.push((l, s, s));
            }
        }
    }
    spans.sort_by(|a, b| a.0.cmp(&b.0).then(a.1.total_cmp(&b.1)));
    spans
        .into_iter()
        .map(|(lane, from, to)| LaneSpan {
            against,
            lane,
            from,
            to,
        })
        .collect()
}
