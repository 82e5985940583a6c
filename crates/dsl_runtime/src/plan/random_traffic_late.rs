//! Random traffic created after the run's start (ASAM OpenSCENARIO DSL 2.1 §8.7.18.1,
//! non-normative: "the group defines the initial conditions of actors in the scenario, meaning
//! their creation and destruction").
//!
//! A `random_traffic_vehicle_group` whose creating phase (`random_traffic_actions`) starts
//! after 0 enters the scenario then: its members have no Init (the engine keeps an entity
//! without one out of the world, its frames and every selection until it is placed) and are
//! dealt by `scenario::traffic_deal`'s rule (the free stretches of the driving lanes, the
//! seed's draws, the gap s0 + v_max·T) among the places every other vehicle has then. Its
//! members are created once every phase is planned, their draws after those of the phases.
//!
//! - At a time t the plan knows, with every other vehicle's place at t the plan's: the plan
//!   deals them (`Planner::deal`) and the creating phase places each member: a TeleportAction
//!   to its LanePosition (a TeleportAction of a story puts an entity that is not in the world
//!   there), a SpeedAction (a step) to its drawn start speed, and an ActivateControllerAction
//!   of its driver on both domains, in that order at the phase start.
//! - After a run-time condition, or beside a vehicle the engine moves then (a gap action's or
//!   `avoid_collisions(true)`'s controller, the members of other random traffic): the plan
//!   does not know the places, so the engine deals them when the phase starts, by the same
//!   rule over the lanes the plan gives it (oscsim's `CreateRandomTraffic`, no XML form,
//!   `engine::actions::random_traffic`), from a seed the plan draws from the run's; then the
//!   same SpeedAction and ActivateControllerAction of each member. No room then fails the run
//!   with the plan's message.

use scenario::{
    ControllerAction, ControllerDomains, LongitudinalAction, Position, PositionKind, PrivateAction,
    RandomTrafficCreation, SpeedTarget,
};

use super::action_args::timed;
use super::planner::Planner;
use super::random_traffic::{driver_domains, Other, CONTROLLER};
use super::types::{Late, Planned};
use crate::error::{Error, Site};

impl Planner<'_> {
    /// Places the members of random traffic created after the start among the other actors'
    /// places then and adds their creation to the creating phases (module doc).
    pub(super) fn create_late_random_traffic(&mut self) -> Result<(), Error> {
        for mut late in std::mem::take(&mut self.late_random) {
            let g = &late.group.clone();
            let site = self.random[g].clone();
            self.bind_lane_field(g, &mut late.creation, None, &site)?;
            let members = self.groups[g].clone();
            let Some(k) = self.phases.iter().position(|ph| ph.path == late.phase) else {
                continue;
            };
            let known = late
                .at
                .and_then(|t| self.others_at(&members, t).map(|o| (t, o)));
            let mut actions: Vec<(String, &str, PrivateAction)> = Vec::new();
            match known {
                Some((t, others)) => {
                    let beside = match &late.creation.beside {
                        Some(b) => {
                            let x_at = self.index.get(&b.x).map(|&i| {
                                let e = &self.entities[i];
                                (e.against, self.lane_now(&e.name, t), self.s_at(&e.name, t))
                            });
                            Some(self.beside_lane(g, b, x_at)?)
                        }
                        None => None,
                    };
                    let dealt = self.deal(g, &site, &members, &late.creation, &others, beside)?;
                    for (m, back, st) in dealt {
                        let view = if back {
                            self.against_road.as_ref().unwrap_or(&self.road)
                        } else {
                            &self.road
                        };
                        let (road, s, _) = view.lane_position(st.s, 0.0);
                        let teleport = PrivateAction::Teleport(Position {
                            kind: PositionKind::Lane {
                                road_id: road.id.clone(),
                                lane_id: st.lane.to_string(),
                                s,
                                offset: Some(0.0),
                                orientation: None,
                            },
                            pos: site.pos.clone(),
                        });
                        actions.push((m.clone(), "create", teleport));
                        actions.push((m.clone(), "speed", step(st.v)));
                        let i = self.index[&m];
                        actions.push((
                            m.clone(),
                            "driver",
                            activate(self.entities[i].driver.as_ref()),
                        ));
                        self.entities[i].against = back;
                    }
                }
                None => {
                    let (create, speeds) = self.engine_creation(g, &members, &late);
                    actions.push((members[0].clone(), "create", create));
                    for (m, v) in members.iter().zip(speeds) {
                        let driver = self.entities[self.index[m]].driver.as_ref();
                        actions.push((m.clone(), "speed", step(v)));
                        actions.push((m.clone(), "driver", activate(driver)));
                    }
                }
            }
            self.add_creation(k, &late, actions, &site);
        }
        Ok(())
    }

    /// Every other vehicle as the dealing counts it at `t`, when the plan knows them all then
    /// (`None`: one the engine moves then).
    fn others_at(&self, members: &[String], t: f64) -> Option<Vec<Other>> {
        let mut others = Vec::new();
        for e in self.entities.iter().filter(|e| !members.contains(&e.name)) {
            let moved = self
                .engine_moved
                .get(&e.name)
                .is_some_and(|since| since.is_none_or(|s| s <= t));
            if moved {
                return None;
            }
            let (lane, v) = (self.lane_now(&e.name, t), self.track(&e.name).at(t).1);
            others.push(self.other(&e.name, e.against, lane, self.s_at(&e.name, t), v));
        }
        Some(others)
    }

    /// The engine's creation of `members` of random traffic `g` as `late` asks (module doc),
    /// and their start speeds.
    fn engine_creation(
        &mut self,
        g: &str,
        members: &[String],
        late: &Late,
    ) -> (PrivateAction, Vec<f64>) {
        let speeds = self.start_speeds(members, late.creation.v0);
        // Beside another actor: every driving lane of both directions, the engine keeping x's
        // lane or the one beside it.
        let mut c = late.creation.clone();
        if c.beside.is_some() {
            c.along = false;
            c.lane = None;
        }
        let lanes = self.lane_spans(&c, None);
        // The engine's draws: a seed from the run's (integer-only: the top 53 bits).
        let seed = (self.draws.borrow_mut().uniform() * (1u64 << 53) as f64) as u64;
        let creation = RandomTrafficCreation {
            group: g.to_string(),
            members: members
                .iter()
                .cloned()
                .zip(speeds.iter().copied())
                .collect(),
            roads: self.road.starts(),
            length: self.road.length(),
            lanes,
            beside: late.creation.beside.as_ref().map(|b| (b.x.clone(), b.by)),
            seed,
        };
        (
            PrivateAction::CreateRandomTraffic(Box::new(creation)),
            speeds,
        )
    }

    /// Adds `actions` (member, what, action), in order, to the creating phase `k` of `late`,
    /// and marks its members created then and moved by the engine from then on.
    fn add_creation(
        &mut self,
        k: usize,
        late: &Late,
        actions: Vec<(String, &str, PrivateAction)>,
        site: &Site,
    ) {
        let path = &late.phase;
        // Before the phase's own actions (a speed action creating the group, given to the
        // models once they drive).
        let created: Vec<Planned> = actions
            .into_iter()
            .enumerate()
            .map(|(i, (m, what, a))| {
                let name = format!("{path}/{m}/{}:{what}", i + 1);
                Planned::with_phase(&m, name, a, site)
            })
            .collect();
        self.phases[k].actions.splice(0..0, created);
        for m in self.groups[&late.group].clone() {
            let e = self.index[&m];
            self.entities[e].created = Some(late.at);
            self.engine_moves(&m, late.at);
        }
    }
}

/// A SpeedAction (a step) to `v`.
fn step(v: f64) -> PrivateAction {
    PrivateAction::Longitudinal(LongitudinalAction::Speed {
        dynamics: timed(scenario::DynamicsShape::Step, 0.0),
        target: SpeedTarget::Absolute(v),
    })
}

/// The ActivateControllerAction of a member's driver `c` on the domains its model holds
/// ([`driver_domains`]).
fn activate(c: Option<&scenario::Controller>) -> PrivateAction {
    PrivateAction::Controller(Box::new(ControllerAction::Activate {
        object_controller_ref: Some(CONTROLLER.to_string()),
        domains: c.map(driver_domains).unwrap_or(ControllerDomains {
            lateral: Some(true),
            longitudinal: Some(true),
            ..ControllerDomains::default()
        }),
    }))
}
