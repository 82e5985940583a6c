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
//! transition the route's lane changes use, over its whole length where the lane it goes to
//! links onto the next road (world/lane_change.rs `room_for`). A curvature moves the entity along an arc off its
//! lane track (its road position looked up after the move); a pose places it.

use opendrive::{Real, RoadNetwork};

use super::command::{Command, Commanded, Lateral, Longitudinal, Merged};
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
use crate::world::lane_change::{
    begin as begin_route_lane_change, room_for, step as step_route_lane_change,
};
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
    walk::<true>(world, controllers, time, dt, threads)
}

/// [`step`]; with `SHORTCUT` (always, but in the test that compares the two) the runs of an
/// entity that one driver model alone commands take the short way: no grouping of the
/// entity's runs, and a command that is an acceleration alone kept as such
/// ([`Commanded`]), not as a [`Merged`] command. Without it every command is merged as the
/// general rule merges any entity's runs. The same merged command either way: a single run
/// sets what [`driver_lateral`] says on an empty command, as the general rule does.
fn walk<const SHORTCUT: bool>(
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
        commanded,
        merged,
        parallel,
        changes,
    } = &mut storage;
    commanded.clear();
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
        // Entity indices and places of merged commands fit in u32: entity ids are u32.
        let at = |i: usize| i as u32;
        let mut rest = runs;
        // The short way's view of a driver model (no host input), moved along.
        let mut moving: Option<ControllerView<'_>> = None;
        while let Some((first, after)) = rest.split_first() {
            let i = first.entity;
            // The short way: a driver model is the entity's only run.
            if let (true, Model::Driver(k), false) = (
                SHORTCUT,
                first.model,
                after.first().is_some_and(|r| r.entity == i),
            ) {
                rest = after;
                // Whether the entity is placed, as below.
                let (Some(e), Some(input)) = (entities.get(i), index.input(i).filter(|r| r.placed))
                else {
                    continue;
                };
                let model = &mut drivers[k];
                let (a, lane) = if threaded {
                    parallel.command(k)
                } else {
                    // One view moved from entity to entity: a view is 9 values.
                    let view = match &mut moving {
                        Some(view) => {
                            view.move_to(e, input);
                            view
                        }
                        None => moving.insert(
                            ControllerView::new(
                                time, e, input, entities, network, index, None, signals,
                            )
                            .stepping(dt),
                        ),
                    };
                    model.command(view)
                };
                let held = first.held;
                let lateral = driver_lateral(held.lateral, held.lateral, lane, model);
                match (held.longitudinal, lateral.flatten()) {
                    (true, None) => commanded.push(Commanded {
                        entity: at(i),
                        merged: Commanded::ACCELERATION,
                        a,
                    }),
                    (longitudinal, lane) => {
                        let m = Merged {
                            longitudinal: longitudinal.then_some(Longitudinal::Acceleration(a)),
                            lateral: lane.map(Lateral::ChangeLane),
                            pose: None,
                        };
                        merged.push((i, m));
                        let place = merged.len() - 1;
                        commanded.push(Commanded {
                            entity: at(i),
                            merged: at(place),
                            a,
                        });
                        if let Some(lane) = lane {
                            changes.push(Change::asked(place, k, lane));
                        }
                    }
                }
                continue;
            }
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
                        let entity_lateral = of_entity.iter().any(|r| r.held.lateral);
                        if let Some(lane) =
                            driver_lateral(held.lateral, entity_lateral, lane, &drivers[k])
                        {
                            m.lateral = lane.map(Lateral::ChangeLane);
                            change = lane.map(|l| (k, l));
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
            let place = merged.len() - 1;
            commanded.push(Commanded {
                entity: at(i),
                merged: at(place),
                a: 0.0,
            });
            if let Some((k, lane)) = change {
                changes.push(Change::asked(place, k, lane));
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
    // Every commanded entity has its controllers' entry (its runs came from them); grown here
    // once, in case, rather than asked of each command (`of_mut`'s growth check).
    if let Some(last) = commanded.last() {
        controllers.of_mut(last.entity as usize);
    }
    let (_, _, per_entity) = controllers.walk();
    let mut finite = true;
    // Called after the move of entity `i` (or with `i` = n after the last): the entity moved
    // before it is tested and entered in the lane index now, not this one: a load of a value
    // its move is still storing would wait for the store (the test, reading the values just
    // written two at a time, took more than the separate walk it replaced).
    let mut moved = |entities: &[Entity], i: usize| {
        if let Some(e) = i.checked_sub(1).and_then(|before| entities.get(before)) {
            finite &= !e.placed || all_finite(e);
            if indexed {
                index.enter_moved(net, e);
            }
        }
    };
    // An entity without a command: run option stop_at_red_lights (signals/red_light.rs; off:
    // nothing), then the default controller's move.
    let mut by_default = |i: usize, e: &mut Entity| {
        signals.govern_speed(net, i, e, dt);
        move_entity(net, e, dt, None);
    };
    // The commands, in increasing entity index (the runs' order), each after the entities
    // before it that have none.
    let mut next = 0;
    for c in commanded.iter() {
        let i = c.entity as usize;
        debug_assert!(i >= next, "the commands in increasing entity index");
        while next < i.min(n) {
            by_default(next, &mut entities[next]);
            moved(entities, next);
            next += 1;
        }
        let (Some(e), Some(ctrl)) = (entities.get_mut(i), per_entity.get_mut(i)) else {
            // Never: the command walk read entity i, and its entry was grown above.
            continue;
        };
        if e.placed {
            // ACCELERATION names no place (u32::MAX: there are fewer merged commands than
            // entities, whose ids are u32).
            match merged.get(c.merged as usize) {
                None => apply(net, e, ctrl, &Merged::acceleration(c.a), dt),
                Some((_, m)) => apply(net, e, ctrl, m, dt),
            }
        } else {
            by_default(i, e);
        }
        moved(entities, i);
        next = i + 1;
    }
    while next < n {
        by_default(next, &mut entities[next]);
        moved(entities, next);
        next += 1;
    }
    moved(entities, n);
    index.end_moves(indexed.then_some(n));
    controllers.stage = storage;
    finite
}

/// Whether a driver model's run sets its entity's lateral command, and to what (the lane to
/// change to, or none): a run holding the lateral domain sets it; one without it sets it only
/// to an `idm`'s lane (its mandatory lane: strategy.rs hands it one only where no user
/// controller holds that domain) and only where no run of the entity (`entity_lateral`)
/// holds the lateral domain: its change is then started on the default controller's lane
/// track, as the route's lane changes. `None`: the run leaves the lateral command as it is.
#[inline]
fn driver_lateral(
    held_lateral: bool,
    entity_lateral: bool,
    lane: Option<i32>,
    model: &DriverModel,
) -> Option<Option<i32>> {
    if held_lateral || (lane.is_some() && !entity_lateral && matches!(model, DriverModel::Idm(_))) {
        Some(lane)
    } else {
        None
    }
}

/// Moves `e` by the merged command `m` over `dt` s. Inlined at both of its calls, so that the
/// one with an acceleration alone drops the branches of the other commands.
#[inline(always)]
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
        Some(Longitudinal::Acceleration(a)) => Some(accelerate(e, a, dt)),
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
            let room = room_for(net, track, lane);
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

/// The speed at the end and the distance of `e`'s move at acceleration `a` over `dt` s: `a`
/// bounded by the vehicle's Performance (`maxAcceleration`, `maxDeceleration`), the ballistic
/// step (models::idm), the speed at the end bounded by `maxSpeed`: `min(v, maxSpeed)` of
/// [`Entity::max_speed`], with the Performance asked once. The ballistic step's speed is never
/// NaN (0, or `max(next, 0)`, which is 0 where `next` is NaN), so without a Performance the
/// bound (+inf) leaves it as it is, and with one the bound is the one comparison that `min`
/// makes of two numbers that are not NaN (a NaN `maxSpeed` leaves `v`, as `min` does): the
/// same bits as `v.min(e.max_speed())` (test: `the_bounded_step_is_the_straightforward_one`).
#[inline(always)]
fn accelerate(e: &Entity, a: Real, dt: Real) -> (Real, Real) {
    let v0 = e.speed.max(0.0);
    match e.performance {
        Some(p) => {
            let a = a.clamp(-p.max_deceleration, p.max_acceleration);
            let (v, d) = ballistic_step(v0, a, dt);
            (if p.max_speed < v { p.max_speed } else { v }, d)
        }
        None => ballistic_step(v0, a, dt),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::controller::command::Strategy;
    use crate::controller::properties::{ControllerKind, ModelSettings};
    use crate::controller::table::Assigned;
    use crate::controller::test_world::crowded;
    use crate::models::acc::AccParameters;
    use crate::models::idm::IdmParameters;
    use crate::models::mobil::MobilParameters;
    use crate::world::ActiveDomains;

    /// Entity `i`'s controllers by `i % 8`: 0, 1 and 7 `mobil` on both domains (the short
    /// way: an acceleration alone, or a lane change merged); 2 `idm` (the short way), every
    /// second one handed mandatory lane −2 (its lane merged without the lateral domain);
    /// 3 `mobil` longitudinally only (its lanes not merged); 4 `mobil` laterally only (no
    /// acceleration: merged); 5 `acc` longitudinally and `mobil` laterally (two runs: the
    /// general merge either way); 6 none (the default controller).
    fn controllers(n: usize) -> ControllerTable {
        let mut t = ControllerTable::default();
        let idm = |i: usize| IdmParameters {
            desired_speed: [22.0, 30.0, 36.0][i % 3],
            ..IdmParameters::default()
        };
        let mobil = |i: usize| ModelSettings::Mobil {
            idm: idm(i),
            desired_speed_given: true,
            mobil: MobilParameters {
                politeness: [0.5, 0.0, 0.2][i % 3],
                change_threshold: [0.1, 0.0][i % 2],
                ..MobilParameters::default()
            },
        };
        for i in 0..n {
            let settings = match i % 8 {
                0 | 1 | 3 | 4 | 7 => vec![(mobil(i), [true, true], [i % 8 != 4, i % 8 != 3])],
                2 => vec![(
                    ModelSettings::Idm {
                        idm: idm(i),
                        desired_speed_given: true,
                    },
                    [true, false],
                    [true, false],
                )],
                5 => vec![
                    (
                        ModelSettings::Acc {
                            acc: AccParameters::new(30.0),
                            set_speed_given: true,
                        },
                        [true, false],
                        [true, false],
                    ),
                    (mobil(i), [true, true], [false, true]),
                ],
                _ => vec![],
            };
            // (settings, the domains it is defined for, the domains activated)
            for (slot, (settings, [dl, dt], [al, at])) in settings.into_iter().enumerate() {
                let instance = t.instantiate(&settings);
                let before = t.held_by(i);
                t.of_mut(i).assigned.push(Assigned {
                    name: format!("c{i}.{slot}"),
                    object_controller: None,
                    kind: ControllerKind::Model {
                        settings,
                        domains: MotionDomains {
                            longitudinal: dl,
                            lateral: dt,
                        },
                    },
                    active: ActiveDomains {
                        longitudinal: al,
                        lateral: at,
                        lighting: false,
                        animation: false,
                    },
                    instance: Some(instance),
                });
                t.recount_entity(i, before);
                if i % 16 == 2 {
                    let c = t.instance_mut(i, slot).expect("idm");
                    assert!(c.strategy(Strategy::MandatoryLane(Some(-2))).is_some());
                }
            }
        }
        t
    }

    /// The short way of the stage's walk (`walk::<true>`, what `step` runs) gives the step of
    /// the general merge of every entity's runs (`walk::<false>`) bit for bit: 40 steps of
    /// 0.05 s of three crowded highways of 330 cars with the eight kinds of controllers of
    /// [`controllers`] (on one thread, and with the commands on 2 threads: 290 driver models,
    /// above the 256 from which a step uses them), every entity's state (pose, speeds, lane
    /// track, road position, Debug of the f64s: their shortest round-trip digits) and every
    /// controller's state the same after each step. Both kinds of short command occur, and lane
    /// changes (merged) many times.
    #[test]
    fn the_shortcut_gives_the_general_merge_bit_for_bit() {
        let (mut alone, mut changed) = (0, 0);
        for (seed, threads) in [(1, 1), (2, 2), (3, 1)] {
            let (mut short, mut general) = (crowded(330, seed), crowded(330, seed));
            let n = short.entities().len();
            let (mut ts, mut tg) = (controllers(n), controllers(n));
            for k in 0..40 {
                let time = k as Real * 0.05;
                let fs = walk::<true>(&mut short, &mut ts, time, 0.05, threads);
                let fg = walk::<false>(&mut general, &mut tg, time, 0.05, threads);
                assert_eq!(fs, fg, "seed {seed} step {k}");
                assert_eq!(
                    format!("{:?}", short.entities()),
                    format!("{:?}", general.entities()),
                    "seed {seed} step {k}"
                );
                let models = format!("{:?}", ts.walk().1);
                assert_eq!(models, format!("{:?}", tg.walk().1), "seed {seed} step {k}");
                let c = &ts.stage.commanded;
                alone += c
                    .iter()
                    .filter(|c| c.merged == Commanded::ACCELERATION)
                    .count();
                changed += ts
                    .stage
                    .merged
                    .iter()
                    .filter(|(_, m)| matches!(m.lateral, Some(Lateral::ChangeLane(_))))
                    .count();
                // The general merge keeps no command as an acceleration alone.
                assert!(tg
                    .stage
                    .commanded
                    .iter()
                    .all(|c| c.merged != Commanded::ACCELERATION));
            }
            for i in 0..n {
                assert_eq!(
                    format!("{:?}", ts.of(i).map(|c| (c.lane_change, c.steered))),
                    format!("{:?}", tg.of(i).map(|c| (c.lane_change, c.steered))),
                    "seed {seed} entity {i}"
                );
            }
        }
        assert!(alone > 20_000, "{alone} accelerations alone");
        assert!(changed > 50, "{changed} lane changes merged");
    }

    /// [`accelerate`] gives the bits of the straightforward rule (the acceleration clamped by
    /// the Performance, the ballistic step from `max(speed, 0)`, the speed's `min` with
    /// `Entity::max_speed`) for every combination of 8 speeds, 9 accelerations and 6
    /// Performances at the boundaries: ±0, a standstill, speeds and accelerations that
    /// overflow, ±inf and NaN (a NaN speed starts from 0; a NaN acceleration ends at 0), a
    /// `maxSpeed` of 0, of the speed itself, +inf and NaN (NaN leaves the speed, as `min`
    /// does), no Performance (no bound). 8 · 9 · 6 = 432 moves of 0.05 s.
    #[test]
    fn the_bounded_step_is_the_straightforward_one() {
        let speeds = [
            0.0,
            -0.0,
            13.9,
            -2.0,
            1e300,
            f64::MAX,
            f64::INFINITY,
            f64::NAN,
        ];
        let accelerations = [
            0.0,
            -0.0,
            1.5,
            -3.0,
            -1e6,
            1e306,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        let performance = |max_speed, max_acceleration, max_deceleration| {
            Some(scenario::Performance {
                max_speed,
                max_acceleration,
                max_deceleration,
                max_acceleration_rate: None,
                max_deceleration_rate: None,
            })
        };
        let performances = [
            None,
            performance(30.0, 3.0, 6.0),
            performance(0.0, 3.0, 6.0),
            performance(13.9, 0.0, 0.0),
            performance(f64::INFINITY, f64::INFINITY, f64::INFINITY),
            performance(f64::NAN, 3.0, 6.0),
        ];
        let bits = |(v, d): (Real, Real)| (v.to_bits(), d.to_bits());
        let mut moves = 0;
        for speed in speeds {
            for a in accelerations {
                for p in performances {
                    let mut e = crate::world::finite::tests::car();
                    e.speed = speed;
                    e.performance = p;
                    let straightforward = {
                        let a = match e.performance {
                            Some(p) => a.clamp(-p.max_deceleration, p.max_acceleration),
                            None => a,
                        };
                        let (v, d) = ballistic_step(e.speed.max(0.0), a, 0.05);
                        (v.min(e.max_speed()), d)
                    };
                    assert_eq!(
                        bits(accelerate(&e, a, 0.05)),
                        bits(straightforward),
                        "speed {speed}, a {a}, {p:?}"
                    );
                    moves += 1;
                }
            }
        }
        assert_eq!(moves, 8 * 9 * 6);
    }
}
