//! Run option `stop_at_red_lights` ([`crate::EngineConfig::stop_at_red_lights`], `oscsim run
//! --stop-at-red-lights`; off by default, so that runs keep their results): vehicles the
//! default controller moves stop before a vehicle traffic light showing red, and drive on
//! when it no longer does. OpenSCENARIO 1.3 leaves the default controller's reaction to
//! signals open (§7.5.1); this is oscsim's choice, documented in docs/signals.md.
//!
//! - Which lights: OpenDRIVE signals of type `1000001` (the three-light vehicle signal of the
//!   OpenDRIVE catalogue, red on top, matched whatever the `country`) on the road the vehicle
//!   is on, ahead of it, valid for its direction of travel (`orientation` "+" for travel
//!   towards +s, "-" towards −s, "none" for both) and, when it has `<validity>` elements, for
//!   the vehicle's lane (OpenDRIVE 1.8 §14.2). Red: the first field of the signal's
//!   OpenSCENARIO state (`on;off;off`) is `on` or `flashing`; yellow and green are "go".
//! - Stop point: the vehicle's front [`STOP_GAP`] before the signal's s.
//! - Braking: when the distance d from the stop point falls to the braking distance at
//!   [`COMFORT_DECELERATION`] (v² / 2b), the vehicle brakes with a = v² / 2d fixed then, its
//!   speed capped each step by √(2·a·d) (and by d / dt, so that no step crosses the point),
//!   which ends standing at the stop point. If stopping would need more than the vehicle's
//!   `maxDeceleration` (default 8 m/s²), the vehicle is too close and drives through (the
//!   dilemma zone of a light turning red).
//! - Driving on: once no red light holds it, the vehicle returns to the speed it had when it
//!   began to brake at [`COMFORT_ACCELERATION`] (or its `maxAcceleration`, if lower); a
//!   SpeedAction that sets a speed meanwhile takes over from there.
//! - Vehicles whose longitudinal motion a built-in car-following controller holds (`idm`,
//!   `acc`, `mobil`; controller module `car_following`) see the red light as a standing
//!   obstacle at the signal's s ([`crate::controller::ControllerView::red_light`]) and stop
//!   the way their model stops behind a standing vehicle (the IDM at its minimum gap s0 before
//!   the signal), unless stopping would need more than the vehicle's `maxDeceleration` (the
//!   same dilemma zone as above: it drives through).

use std::collections::BTreeMap;

use opendrive::{Direction, Real, RoadNetwork};

use crate::world::{Entity, EntityKind};

/// Distance between the vehicle's front and the signal's s when it stands (m).
pub const STOP_GAP: Real = 1.0;
/// Deceleration at which a vehicle begins to brake for a red light (m/s²).
pub const COMFORT_DECELERATION: Real = 3.0;
/// Acceleration with which a vehicle drives on (m/s²).
pub const COMFORT_ACCELERATION: Real = 2.0;
/// Deceleration assumed for a vehicle without Performance (m/s²).
const DEFAULT_MAX_DECELERATION: Real = 8.0;

/// One vehicle held by red lights.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Hold {
    /// The deceleration chosen when braking began (m/s²), while a red light holds it.
    braking: Option<Real>,
    /// The speed to return to (m/s).
    resume: Real,
    /// The speed this option gave the vehicle last step (m/s): a higher speed at the next step
    /// is an action's, and becomes the speed to return to.
    last: Real,
}

/// The vehicles held by red lights, by entity index.
#[derive(Debug, Clone, Default)]
pub(crate) struct RedLights {
    /// Whether the option is on.
    pub(crate) enabled: bool,
    holds: BTreeMap<usize, Hold>,
}

impl RedLights {
    /// Sets the speed of vehicle `e` (entity index `i`) for the coming move of `dt` s, as the
    /// module doc says; `red(id)` tells whether signal `id` shows red.
    pub(crate) fn govern(
        &mut self,
        net: &RoadNetwork,
        red: impl Fn(&str) -> bool,
        i: usize,
        e: &mut Entity,
        dt: Real,
    ) {
        // A pose set by an action for this step (trajectories, teleports) is not the
        // default controller's move.
        if !self.enabled || e.kind != EntityKind::Vehicle || e.held {
            return;
        }
        let v = e.speed.max(0.0);
        let mut hold = self.holds.get(&i).copied();
        if let Some(h) = hold.as_mut() {
            if v > h.last + 1e-9 {
                h.resume = v;
            }
        }
        let max_decel = max_deceleration(e);
        let accel = e.performance.map_or(COMFORT_ACCELERATION, |p| {
            p.max_acceleration.min(COMFORT_ACCELERATION)
        });
        let braking = hold.and_then(|h| h.braking);
        let next = match stop_distance(net, &red, e) {
            Some(d) => {
                // Within a nanometre of the stop point counts as there (the steps' sums round).
                let room = if d > 1e-9 { d } else { 0.0 };
                let needed = v * v / (2.0 * room.max(1e-9));
                let a = match braking {
                    Some(a) => Some(a),
                    // Too close to stop: drive through.
                    None if needed > max_decel => None,
                    None if needed >= COMFORT_DECELERATION => Some(needed),
                    None => None,
                };
                match a {
                    Some(a) => {
                        let cap = (2.0 * a * room).sqrt().min(room / dt);
                        Some((v.min(cap), Some(a)))
                    }
                    // Driving on towards a red light further away: not above the speed
                    // from which it can still stop comfortably.
                    None if hold.is_some() && needed <= max_decel => {
                        let cap = (2.0 * COMFORT_DECELERATION * room).sqrt();
                        Some(((v + accel * dt).min(cap), None))
                    }
                    None => hold.map(|_| (v + accel * dt, None)),
                }
            }
            None => hold.map(|_| (v + accel * dt, None)),
        };
        match next {
            Some((speed, braking)) => {
                let resume = hold.map_or(v, |h| h.resume);
                if braking.is_none() && speed >= resume {
                    self.holds.remove(&i);
                    set_speed(e, resume.max(v));
                } else {
                    let last = speed;
                    self.holds.insert(
                        i,
                        Hold {
                            braking,
                            resume,
                            last,
                        },
                    );
                    set_speed(e, speed);
                }
            }
            None => {
                self.holds.remove(&i);
            }
        }
    }
}

/// The deceleration vehicle `e` can brake with (m/s²): its Performance `maxDeceleration`, else
/// [`DEFAULT_MAX_DECELERATION`].
fn max_deceleration(e: &Entity) -> Real {
    e.performance
        .map_or(DEFAULT_MAX_DECELERATION, |p| p.max_deceleration)
}

/// Whether vehicle `e` can still stop within `distance` m at its maximum deceleration; a light
/// it cannot stop for it drives through (the dilemma zone, module doc).
pub(crate) fn can_stop_within(e: &Entity, distance: Real) -> bool {
    let v = e.speed.max(0.0);
    v * v <= 2.0 * max_deceleration(e) * distance.max(0.0)
}

/// Sets the speed of the coming move (also when the lateral motion goes first, which moves at
/// the step's start speed, controller/default.rs).
fn set_speed(e: &mut Entity, v: Real) {
    e.speed = v;
    e.start_speed = e.start_speed.min(v);
}

/// Distance from `e`'s stop point before the nearest red vehicle light ahead on its road
/// (module doc), if there is one; negative when the front is already past the stop point but
/// not past the signal.
fn stop_distance(net: &RoadNetwork, red: &impl Fn(&str) -> bool, e: &Entity) -> Option<Real> {
    light_ahead(net, red, e).map(|ahead| ahead - STOP_GAP)
}

/// Distance from `e`'s front bumper to the nearest vehicle light ahead on its road that shows
/// red and is valid for its direction of travel (module doc), if there is one.
pub(crate) fn light_ahead(
    net: &RoadNetwork,
    red: &impl Fn(&str) -> bool,
    e: &Entity,
) -> Option<Real> {
    let track = e.track.as_ref()?;
    let road = net.road_at(track.road);
    let sign = match track.direction {
        Direction::Forward => 1.0,
        Direction::Backward => -1.0,
    };
    let bb = e.bounding_box;
    let front = bb.center().x + bb.length() / 2.0;
    road.signals
        .iter()
        .filter(|s| s.signal_type.trim() == "1000001")
        .filter(|s| match s.orientation.trim() {
            "+" => sign > 0.0,
            "-" => sign < 0.0,
            _ => true,
        })
        .filter(|s| s.valid_for_lane(track.lane_id))
        .filter_map(|s| {
            let ahead = (s.s - track.s) * sign - front;
            (ahead > 0.0 && red(&s.id)).then_some(ahead)
        })
        .min_by(|a, b| a.total_cmp(b))
}

/// Whether OpenSCENARIO state `state` of a vehicle light shows red (its first, top field is on).
pub(crate) fn shows_red(state: &str) -> bool {
    matches!(
        state
            .split(';')
            .next()
            .map(|f| f.trim().to_ascii_lowercase())
            .as_deref(),
        Some("on" | "flashing")
    )
}
