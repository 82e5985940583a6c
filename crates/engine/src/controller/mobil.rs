//! The `mobil` controller (OpenSCENARIO 1.3 §6.6, both motion domains): the IDM drives the
//! longitudinal domain ([`super::car_following::IdmController`]) and MOBIL
//! ([`crate::models::mobil`]) decides each step whether to change to the lane on the left or
//! the right.
//!
//! A candidate lane is one the view offers ([`ControllerView::neighbour_lane`]: drivable, on
//! the entity's road at its s, driven the same way) with no entity alongside the entity in it,
//! behind a road mark that may be crossed towards it where the entity is (OpenDRIVE 1.8 §11.8:
//! `laneChange`, else the paint; a solid line is not crossed, [`opendrive::RoadMark::permits_lane_change`]).
//! The accelerations MOBIL weighs are the IDM's, with this controller's parameters for the
//! changer and for both followers (the model's usual reading: the others' behaviour is not
//! known, MOBIL evaluates them with the same car-following model):
//!
//! - own: a_c behind the present leader, ã_c behind the target lane's leader;
//! - old follower o (behind in the present lane): a_o behind the changer, ã_o behind the
//!   changer's leader at gap g_o + length + g_c;
//! - new follower n (behind in the target lane): a_n behind the target lane's leader at gap
//!   g_n + length + g_l, ã_n behind the changer at gap g_n.
//!
//! Of the lanes where a change is safe and worth it, the one with the larger margin is taken;
//! the change has the lateral shape of the route's lane changes (cubic over the distance that
//! keeps the peak lateral acceleration at 1 m/s², controller/lane_change.rs). Further
//! decisions wait while a lateral transition runs, for [`MIN_CHANGE_INTERVAL`] after a change,
//! and below [`MIN_CHANGE_SPEED`] (a change at rest would be a sideways jump). A
//! LaneChangeAction of the scenario on the lateral domain is carried out the same way, to the
//! lane it names.

use opendrive::Real;

use super::car_following::{with_red_light, IdmController};
use super::command::{Command, Controller, Lateral, Longitudinal, Strategy};
use super::view::{ControllerView, NeighbourLane, Side};
use crate::models::idm::{IdmParameters, Leader};
use crate::models::mobil::{FollowerChange, LaneChangeCandidate, MobilParameters};

/// Least time between two lane changes of one entity (s).
pub const MIN_CHANGE_INTERVAL: Real = 3.0;
/// Least speed at which the controller changes lanes (m/s).
pub const MIN_CHANGE_SPEED: Real = 1.0;

/// The `mobil` controller.
#[derive(Debug, Clone)]
pub struct MobilController {
    idm: IdmController,
    /// The MOBIL parameters.
    pub mobil: MobilParameters,
    /// A lane a LaneChangeAction asked for, not yet started.
    pending: Option<i32>,
    /// Time of the last change started (s).
    last_change: Real,
}

impl MobilController {
    /// A controller with `idm` and `mobil` parameters.
    pub fn new(idm: IdmParameters, desired_given: bool, mobil: MobilParameters) -> Self {
        MobilController {
            idm: IdmController::new(idm, desired_given),
            mobil,
            pending: None,
            last_change: Real::NEG_INFINITY,
        }
    }

    /// The MOBIL verdict on changing into `lane` (module doc); `None` when the lane is
    /// occupied alongside or its road mark may not be crossed.
    fn judge(&self, view: &ControllerView<'_>, lane: &NeighbourLane) -> Option<Real> {
        if lane.occupied || !lane.crossing_permitted {
            return None;
        }
        let p = &self.idm.params;
        let v = view.entity().speed.max(0.0);
        let len = view.length();
        let to = |g: super::view::Gap| Leader {
            gap: g.gap,
            speed: g.speed,
        };
        let own_leader = view.leader();
        // A red light ahead (run option stop_at_red_lights) stands across both lanes: no
        // incentive to change for it.
        let a_c = p.acceleration(v, with_red_light(view, own_leader.map(to)));
        let own_after = p.acceleration(v, with_red_light(view, lane.leader.map(to)));
        let old_follower = view.follower().map(|o| {
            let vo = o.speed.max(0.0);
            let behind_me = Leader {
                gap: o.gap,
                speed: v,
            };
            let behind_leader = own_leader.map(|l| Leader {
                gap: o.gap + len + l.gap,
                speed: l.speed,
            });
            FollowerChange {
                before: p.acceleration(vo, Some(behind_me)),
                after: p.acceleration(vo, behind_leader),
            }
        });
        let new_follower = lane.follower.map(|n| {
            let vn = n.speed.max(0.0);
            let before = lane.leader.map(|l| Leader {
                gap: n.gap + len + l.gap,
                speed: l.speed,
            });
            FollowerChange {
                before: p.acceleration(vn, before),
                after: p.acceleration(
                    vn,
                    Some(Leader {
                        gap: n.gap,
                        speed: v,
                    }),
                ),
            }
        });
        let verdict = self.mobil.judge(&LaneChangeCandidate {
            own: FollowerChange {
                before: a_c,
                after: own_after,
            },
            old_follower,
            new_follower,
            toward_keep_side: lane.toward_keep_side,
        });
        verdict.change().then_some(verdict.margin)
    }

    /// The lane to change to now, if any.
    fn decide(&mut self, view: &ControllerView<'_>) -> Option<i32> {
        let e = view.entity();
        let track = e.track.as_ref()?;
        if track.blend.is_some() || e.lateral_action.is_some() {
            return None;
        }
        if let Some(lane) = self.pending.take() {
            return (lane != track.lane_id).then_some(lane);
        }
        if e.speed < MIN_CHANGE_SPEED || view.time() - self.last_change < MIN_CHANGE_INTERVAL {
            return None;
        }
        let mut best: Option<(Real, i32)> = None;
        for side in [Side::Left, Side::Right] {
            let Some(lane) = view.neighbour_lane(side) else {
                continue;
            };
            if let Some(margin) = self.judge(view, &lane) {
                if best.map_or(true, |(m, _)| margin > m) {
                    best = Some((margin, lane.lane));
                }
            }
        }
        best.map(|(_, lane)| lane)
    }
}

impl Controller for MobilController {
    fn model(&self) -> &'static str {
        "mobil"
    }

    fn activate(&mut self, view: &ControllerView<'_>) {
        self.idm.on_activate(view);
    }

    fn strategy(&mut self, strategy: Strategy) -> Option<String> {
        match strategy {
            Strategy::Lane(lane) => {
                self.pending = Some(lane);
                Some(format!("lane change to lane {lane}"))
            }
            other => self.idm.on_strategy(other),
        }
    }

    fn step(&mut self, view: &ControllerView<'_>, _dt: Real) -> Command {
        let lateral = self.decide(view).map(|lane| {
            self.last_change = view.time();
            Lateral::ChangeLane(lane)
        });
        Command::Motion {
            longitudinal: Some(Longitudinal::Acceleration(self.idm.acceleration(view))),
            lateral,
        }
    }
}
