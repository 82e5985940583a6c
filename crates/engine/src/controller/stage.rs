//! The controllers stage of a step (OpenSCENARIO 1.3 §7.2.2.1 motion control): every user
//! controller holding a domain gives its [`Command`] from a [`ControllerView`] of the world
//! at the step's start, then every entity moves, the domains without a command as the default
//! controller moves them.
//!
//! The lane index ([`LaneIndex`]) is built once per step, and only when some built-in model
//! holds a domain, so runs without user controllers cost what they did. All commands are
//! worked out before any entity moves (a synchronous update): the result does not depend on
//! the order of the entities.
//!
//! Applying a command: an acceleration is bounded by the vehicle's Performance
//! (`maxAcceleration`, `maxDeceleration`) and integrated ballistically (the speed stops at 0,
//! models::idm); the distance travelled then follows the lane as the default controller does,
//! through route, lane changes and links. A lane change command starts the same lateral
//! transition the route's lane changes use. A curvature moves the entity along an arc off its
//! lane track (its road position looked up after the move); a pose places it.

use opendrive::{Direction, Real, RoadNetwork};

use super::command::{Command, Lateral, Longitudinal, Merged};
use super::default::{measure, move_entity};
use super::drivers::{DriverModel, Instance, Model};
use super::one_gap::{resolve as resolve_one_gap, Change};
use super::parallel::StepWorld;
use super::properties::MotionDomains;
use super::table::{ControllerTable, EntityControllers, StageStorage};
use super::view::ControllerView;
use crate::models::idm::ballistic_step;
use crate::models::single_track::arc_step;
use crate::store::lane_index::LaneIndex;
use crate::store::World;
use crate::world::finite::all_finite;
use crate::world::lane_change::{begin as begin_route_lane_change, step as step_route_lane_change};
use crate::world::Entity;

/// Stage 3: commands, then moves (module doc). Returns whether every placed entity's state
/// is finite after its move: the step's finite-state guard (engine runtime/finite.rs) is
/// tested here, in the walk that moves the entities, while each entity is in the core's cache
/// (a walk of its own over 4,000 entities was 8 % of an `idm` run, issue 31).
/// `threads`: the run option [`EngineConfig::controller_threads`](crate::EngineConfig), the
/// threads the driver models' commands are worked out on when many vehicles have one
/// (controller/parallel.rs: the same bits for any count).
pub(crate) fn step(
    world: &mut World,
    controllers: &mut ControllerTable,
    time: Real,
    dt: Real,
    threads: usize,
) -> bool {
    // The stage's storage of the last step, taken out of the table while the table's
    // controllers are stepped, and put back at the end.
    let mut storage = std::mem::take(&mut controllers.stage);
    let StageStorage {
        index,
        merged,
        parallel,
        changes,
    } = &mut storage;
    merged.clear();
    // The lane index is built where some model holds a domain, and then the moves' walk
    // enters each entity in it after its move (store/lane_refresh.rs).
    let indexed = controllers.any_held();
    if indexed {
        index.refresh_from(world);
        let index: &LaneIndex = index;
        let (entities, network, signals) = (world.entities(), &world.network, &world.signals);
        let at_start = StepWorld {
            time,
            dt,
            entities,
            network,
            index,
            signals,
        };
        // The controllers holding a domain, entity by entity in index order, each entity's in
        // the order they were assigned; the `idm` and `mobil` models by value (drivers.rs).
        let (runs, drivers, per_entity) = controllers.walk();
        // With threads asked and many driver models: their commands first, on the threads.
        let threaded = parallel.work_out(threads, runs, drivers, at_start);
        let mut rest = runs;
        while let Some(first) = rest.first() {
            let i = first.entity;
            let n = rest.iter().take_while(|r| r.entity == i).count();
            let (of_entity, after) = rest.split_at(n);
            rest = after;
            // Whether the entity is placed, from the driver inputs the index copied (a line
            // of the compact table, not of the 1.3 kB entity: store/driver_inputs.rs).
            let (Some(e), Some(input)) = (entities.get(i), index.input(i).filter(|r| r.placed))
            else {
                continue;
            };
            let mut m = Merged::default();
            // A driver model's lane change (its place, the lane), for one_gap.rs.
            let mut change = None;
            for run in of_entity {
                let held = run.held;
                let command = match run.model {
                    // A driver model reads no host input (that is the `external` model's); its
                    // command is an acceleration and a lane change, merged as `Command::Motion`
                    // of the two is below (drivers.rs).
                    Model::Driver(k) => {
                        let (a, lane) = if threaded {
                            parallel.command(k)
                        } else {
                            let view = ControllerView::new(
                                time, e, input, entities, network, index, None, signals,
                            )
                            .stepping(dt);
                            drivers[k].command(&view)
                        };
                        if held.longitudinal {
                            m.longitudinal = Some(Longitudinal::Acceleration(a));
                        }
                        if held.lateral {
                            m.lateral = lane.map(Lateral::ChangeLane);
                            change = lane.map(|l| (k, l));
                        } else if lane.is_some() && !of_entity.iter().any(|r| r.held.lateral) {
                            // Only an `idm` holding a mandatory lane gives a lane without the
                            // lateral domain (strategy.rs hands it one only where no user
                            // controller holds that domain): its change is started on the
                            // default controller's lane track, as the route's lane changes.
                            if matches!(drivers[k], DriverModel::Idm(_)) {
                                m.lateral = lane.map(Lateral::ChangeLane);
                                change = lane.map(|l| (k, l));
                            }
                        }
                        continue;
                    }
                    Model::Boxed { slot } => {
                        let ctrl = &mut per_entity[i];
                        let external = ctrl.external;
                        let Some(Instance::Boxed(instance)) = ctrl.assigned[slot].instance.as_mut()
                        else {
                            continue;
                        };
                        let view = ControllerView::new(
                            time, e, input, entities, network, index, external, signals,
                        )
                        .stepping(dt);
                        instance.step(&view, dt)
                    }
                };
                match command {
                    Command::Pose(p) if held == MotionDomains::BOTH => m.pose = Some(p),
                    Command::Pose(_) => {}
                    Command::Motion {
                        longitudinal,
                        lateral,
                    } => {
                        if held.longitudinal {
                            m.longitudinal = longitudinal;
                        }
                        if held.lateral {
                            m.lateral = lateral;
                        }
                    }
                }
            }
            merged.push((i, m));
            if let Some((k, lane)) = change {
                changes.push(Change::asked(merged.len() - 1, k, lane));
            }
        }
        // Two changes into one gap: the one behind yields (one_gap.rs).
        resolve_one_gap(changes, merged, at_start, drivers);
    }
    let (net, entities, signals) = world.moves();
    let n = entities.len();
    if indexed {
        index.begin_moves(n);
    }
    let mut finite = true;
    let tested = |e: &Entity| !e.placed || all_finite(e);
    // The commands, in increasing entity index (the runs' order), met in the walk.
    let mut commands = merged.iter().peekable();
    for i in 0..n {
        let e = &mut entities[i];
        match commands.next_if(|(j, _)| *j == i) {
            Some((_, m)) if e.placed => apply(net, e, controllers.of_mut(i), m, dt),
            _ => {
                // Run option stop_at_red_lights (signals/red_light.rs); off: nothing.
                signals.govern_speed(net, i, e, dt);
                move_entity(net, e, dt, None);
            }
        }
        // The entity moved before this one is tested and entered in the lane index now, not
        // this one: a load of a value its move is still storing would wait for the store
        // (the test, reading the values just written two at a time, took more than the
        // separate walk it replaced).
        if let Some(before) = i.checked_sub(1) {
            let e = &entities[before];
            finite &= tested(e);
            if indexed {
                index.enter_moved(net, e);
            }
        }
    }
    if let Some(e) = entities.last() {
        finite &= tested(e);
        if indexed {
            index.enter_moved(net, e);
        }
    }
    index.end_moves(indexed.then_some(n));
    controllers.stage = storage;
    finite
}

/// Moves `e` by the merged command `m` over `dt` s.
fn apply(net: &RoadNetwork, e: &mut Entity, ctrl: &mut EntityControllers, m: &Merged, dt: Real) {
    // The heading and speed along the travel before the move, for the two branches that
    // measure here (`move_entity` measures its own).
    let before = |e: &Entity| (e.pose.h, e.travel_component(e.velocity.translational));
    if let Some(p) = m.pose {
        let (old_h, old_v) = before(e);
        let (dx, dy) = (p.x - e.pose.x, p.y - e.pose.y);
        let along = dx * p.h.cos() + dy * p.h.sin();
        e.pose = p;
        e.track = None;
        e.speed = along / dt;
        e.odometer += dx.hypot(dy);
        e.road_position = net.locate(p.x, p.y, Some(p.h));
        ctrl.steered = true;
        measure(e, old_h, old_v, dt);
        return;
    }
    // The longitudinal motion: (speed at the end, distance), or the default controller's.
    let motion = match m.longitudinal {
        Some(Longitudinal::Acceleration(a)) => {
            let a = match e.performance {
                Some(p) => a.clamp(-p.max_deceleration, p.max_acceleration),
                None => a,
            };
            let (v, d) = ballistic_step(e.speed.max(0.0), a, dt);
            Some((v.min(e.max_speed()), d))
        }
        Some(Longitudinal::Motion {
            speed, distance, ..
        }) => Some((speed, distance)),
        None => None,
    };
    if let Some(Lateral::Curvature(k)) = m.lateral {
        let (old_h, old_v) = before(e);
        let (v, d) = motion.unwrap_or((e.speed, e.speed * dt));
        let (x, y, h) = arc_step(e.pose.x, e.pose.y, e.pose.h, d, k);
        e.pose.x = x;
        e.pose.y = y;
        e.pose.h = opendrive::normalize_angle(h);
        e.track = None;
        e.speed = v;
        e.odometer += d.abs();
        e.road_position = net.locate(x, y, Some(e.pose.h));
        if let Some(rp) = &e.road_position {
            // Follow the ground: the height of the road surface under the entity.
            if let Ok(ground) = net.road_pose(&rp.road_id, rp.s, rp.t) {
                e.pose.z = ground.z;
            }
        }
        ctrl.steered = true;
        measure(e, old_h, old_v, dt);
        return;
    }
    if std::mem::take(&mut ctrl.steered) {
        // Back from steering or a pose: the default controller keeps the lane it is on.
        e.track = None;
        if let Some(rp) = net.locate(e.pose.x, e.pose.y, Some(e.pose.h)) {
            crate::store::place_on_lane(net, e, e.pose, Some(rp));
        }
    }
    let distance = motion.map(|(_, d)| d);
    if let Some(track) = e.track.as_mut() {
        if let Some(Lateral::ChangeLane(lane)) = m.lateral {
            let speed = motion.map_or(e.speed, |(v, _)| v);
            let room = net
                .road(&track.road_id)
                .map_or(0.0, |r| match track.direction {
                    Direction::Forward => r.length - track.s,
                    Direction::Backward => track.s,
                });
            ctrl.lane_change = begin_route_lane_change(net, track, lane, speed, e.odometer, room);
        }
        if let Some(change) = ctrl.lane_change {
            let d = distance.unwrap_or(e.speed * dt);
            if !step_route_lane_change(&change, track, e.odometer, d) {
                ctrl.lane_change = None;
            }
        }
    }
    if let Some((v, _)) = motion {
        e.speed = v;
    }
    move_entity(net, e, dt, distance);
}
