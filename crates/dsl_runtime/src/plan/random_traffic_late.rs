//! Random traffic created after the run's start (ASAM OpenSCENARIO DSL 2.1 §8.7.18.1,
//! non-normative: "the group defines the initial conditions of actors in the scenario, meaning
//! their creation and destruction").
//!
//! A `random_traffic_vehicle_group` whose creating phase (`random_traffic_actions`) starts at
//! a time t the plan knows after 0 enters the scenario then: its members have no Init (the
//! engine keeps an entity without one out of the world, its frames and every selection until
//! it is placed) and are dealt, as at the start (`Planner::deal`: the free stretches of the
//! driving lanes, the seed's draws, the gap s0 + v_max·T), among the places the plan has for
//! every other actor at t. The creating phase then places each member: a TeleportAction to
//! its LanePosition (a TeleportAction of a story puts an entity that is not in the world
//! there), a SpeedAction (a step) to its drawn start speed, and an ActivateControllerAction of
//! its driver on both domains, in that order at the phase start. Its members are placed once
//! every phase is planned (so the others' places at t are known), their draws after those of
//! the phases.
//!
//! The plan must know where every other vehicle is at t: an actor the engine moves then (a
//! gap action's or `avoid_collisions(true)`'s controller, the members of other random
//! traffic) is an error at the group, and so is a creating phase after a run-time condition
//! (`plan_random_traffic`).

use scenario::{
    ControllerAction, ControllerDomains, LongitudinalAction, Position, PositionKind, PrivateAction,
    SpeedTarget,
};

use super::action_args::timed;
use super::planner::Planner;
use super::random_traffic::{Other, CONTROLLER};
use super::types::Planned;
use crate::error::{Error, ErrorKind as K};

impl Planner<'_> {
    /// Places the members of random traffic created after the start among the other actors'
    /// places then and adds their creation to the creating phases (module doc).
    pub(super) fn create_late_random_traffic(&mut self) -> Result<(), Error> {
        for late in std::mem::take(&mut self.late_random) {
            let (g, t) = (&late.group, late.at);
            let site = self.random[g].clone();
            let members = self.groups[g].clone();
            let mut others: Vec<Other> = Vec::new();
            for e in &self.entities {
                if members.contains(&e.name) {
                    continue;
                }
                let moved = self
                    .engine_moved
                    .get(&e.name)
                    .is_some_and(|since| since.map_or(true, |s| s <= t));
                if moved {
                    return Err(site.err(
                        K::Unsupported,
                        format!("expected every other vehicle's place known to the plan when random traffic `{g}` is created at {t:.2} s, found `{}` moved by the engine's driver model or controller then", e.name),
                    ));
                }
                let tr = self.track(&e.name);
                let (lane, v) = (tr.lane(t), tr.at(t).1);
                others.push(self.other(&e.name, e.against, lane, self.s_at(&e.name, t), v));
            }
            let beside = match &late.creation.beside {
                Some(b) => {
                    let x_at = self.index.get(&b.x).and_then(|&i| {
                        let e = &self.entities[i];
                        let moved = self
                            .engine_moved
                            .get(&e.name)
                            .is_some_and(|since| since.map_or(true, |s| s <= t));
                        (!moved).then(|| {
                            (
                                e.against,
                                self.track(&e.name).lane(t),
                                self.s_at(&e.name, t),
                            )
                        })
                    });
                    Some(self.beside_lane(g, b, x_at)?)
                }
                None => None,
            };
            let dealt = self.deal(g, &site, &members, &late.creation, &others, beside)?;
            let Some(k) = self.phases.iter().position(|ph| ph.path == late.phase) else {
                continue;
            };
            for (i, (m, back, st)) in dealt.into_iter().enumerate() {
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
                let speed = PrivateAction::Longitudinal(LongitudinalAction::Speed {
                    dynamics: timed(scenario::DynamicsShape::Step, 0.0),
                    target: SpeedTarget::Absolute(st.v),
                });
                let activate = PrivateAction::Controller(Box::new(ControllerAction::Activate {
                    object_controller_ref: Some(CONTROLLER.to_string()),
                    domains: ControllerDomains {
                        lateral: Some(true),
                        longitudinal: Some(true),
                        ..ControllerDomains::default()
                    },
                }));
                let path = &late.phase;
                for (j, (what, a)) in [("create", teleport), ("speed", speed), ("driver", activate)]
                    .into_iter()
                    .enumerate()
                {
                    let name = format!("{path}/{m}/{}:{what}", 3 * i + j + 1);
                    self.phases[k]
                        .actions
                        .push(Planned::with_phase(&m, name, a, &site));
                }
                let e = self.index[&m];
                self.entities[e].created = Some(t);
                self.entities[e].against = back;
                self.engine_moved.insert(m.clone(), Some(t));
            }
        }
        Ok(())
    }
}
