//! The finite-state guard of the step: every number of an entity's state (pose, speed,
//! velocity, acceleration, road position) is finite before a frame is written.
//!
//! Each input value is checked where it is read (the scenario crate refuses non-finite
//! attributes, parameters and expression results; actions refuse non-finite targets), but
//! finite extremes can still combine into an overflow: a speed of 1.7e308 m/s moves an
//! off-road entity past f64::MAX metres within a few steps, and a jump from 0 to 1e308 m/s in
//! 0.05 s is an acceleration of 2e309 m/s². Such a step is refused with an error naming the
//! entity, the quantity and the time, instead of writing inf or NaN to the outputs (the state
//! would be corrupt: OpenSCENARIO 1.3 §6.3 coordinates and §7.2.2 entity states are real
//! numbers).

use crate::error::{Error, ErrorKind};
use crate::world::entity::{Entity, EntityId};
use crate::world::finite::{all_finite, first_non_finite};

/// Checks every placed entity of `entities` at simulation time `time`; the first entity whose
/// state is not finite, by name, and the error.
pub(crate) fn check(entities: &[Entity], time: f64) -> Result<(), (String, Error)> {
    entities
        .iter()
        .filter(|e| e.placed && !all_finite(e))
        .find_map(|e| error_of(e, time))
        .map_or(Ok(()), Err)
}

/// The check of a step whose moves tested each entity they moved (controller/stage.rs, in its
/// own walk over the entities: issue 31). `moved`: every placed entity was finite after its
/// move. `later`: the entities changed after the moves, the trailers placed behind their tows
/// (store/trailer.rs), or `None` when those changes are not known one by one (a traffic action
/// ran: it spawns, removes and places vehicles). Every other entity is as the moves left it,
/// so the first entity that is not finite, by index, is the first of `later` that is not; with
/// `None`, or when a moved entity was not finite, every entity is checked ([`check`]). Either
/// way the error names the entity and value [`check`] over every entity names.
pub(crate) fn check_after_moves(
    entities: &[Entity],
    moved: bool,
    later: Option<impl Iterator<Item = EntityId>>,
    time: f64,
) -> Result<(), (String, Error)> {
    let Some(later) = later.filter(|_| moved) else {
        return check(entities, time);
    };
    later
        .filter_map(|id| entities.get(id.index()))
        .filter(|e| e.placed && !all_finite(e))
        .map(|e| e.id)
        .min()
        .and_then(|id| error_of(&entities[id.index()], time))
        .map_or(Ok(()), Err)
}

/// The entity's name and the error of its first value that is not finite, if any.
fn error_of(e: &Entity, time: f64) -> Option<(String, Error)> {
    let (quantity, value) = first_non_finite(e)?;
    let error = Error::new(ErrorKind::NonFinite {
        entity: e.name.clone(),
        quantity,
        value,
        time,
    });
    Some((e.name.clone(), error))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::world::finite::tests::{car, slot};

    /// Three placed cars named a, b, c (indices 0, 1, 2), with `bad` values set to NaN by
    /// (index, quantity).
    fn cars(bad: &[(usize, &str)]) -> Vec<Entity> {
        let mut cars: Vec<Entity> = (0..3u32)
            .map(|i| {
                let mut e = car();
                e.id = EntityId(i);
                e.name = ["a", "b", "c"][i as usize].to_owned();
                e.placed = true;
                e
            })
            .collect();
        for &(i, name) in bad {
            *slot(&mut cars[i], name) = f64::NAN;
        }
        cars
    }

    /// The guard's outcome as text: the entity and the error's message, or "ok".
    fn text(r: Result<(), (String, Error)>) -> String {
        match r {
            Ok(()) => "ok".to_owned(),
            Err((name, e)) => format!("{name}: {e}"),
        }
    }

    /// The check over every entity names the first by index and its first value by name.
    #[test]
    fn the_check_names_the_first_entity_and_value_that_is_not_finite() {
        assert_eq!(text(check(&cars(&[]), 1.0)), "ok");
        let found = text(check(
            &cars(&[(2, "speed"), (1, "yaw rate"), (1, "y")]),
            1.0,
        ));
        assert_eq!(
            found,
            "b: expected a finite y of entity 'b' at t = 1.000 s, found NaN (an overflow of \
             extreme values)"
        );
        let mut unplaced = cars(&[(0, "x")]);
        unplaced[0].placed = false;
        assert_eq!(text(check(&unplaced, 1.0)), "ok");
    }

    /// Wherever the values that are not finite lie (none, a trailer, a moved entity, both,
    /// an unplaced trailer) and whatever the moves and the traffic stage report, the guard
    /// after the moves names what the check over every entity names, as long as the moves'
    /// report is true: `moved` is false when a moved entity is not finite (the trailers are
    /// moved as well before they follow their tows), and every entity not in `later` is
    /// as the moves left it.
    #[test]
    fn the_guard_after_the_moves_names_what_the_check_of_all_names() {
        // (bad values, trailers, the first trailer unplaced)
        type Case<'a> = (&'a [(usize, &'a str)], &'a [u32], bool);
        let cases: [Case<'_>; 7] = [
            (&[], &[], false),
            (&[], &[1], false),
            (&[(1, "roll")], &[1], false),
            (&[(2, "road t"), (1, "z")], &[2, 1], false),
            (&[(2, "lane offset")], &[0, 2], false),
            (&[(0, "speed")], &[0], true),
            (&[(1, "x"), (2, "x")], &[2], false),
        ];
        for (bad, trailers, unplaced) in cases {
            let mut entities = cars(bad);
            if unplaced {
                entities[trailers[0] as usize].placed = false;
            }
            let all = text(check(&entities, 2.5));
            let later = || trailers.iter().map(|&i| EntityId(i));
            // The moves found every entity not in `later` finite.
            let moved = entities
                .iter()
                .filter(|e| !trailers.contains(&e.id.0))
                .all(|e| !e.placed || all_finite(e));
            let fast = text(check_after_moves(&entities, moved, Some(later()), 2.5));
            assert_eq!(fast, all, "{bad:?} trailers {trailers:?}");
            let none = text(check_after_moves(
                &entities,
                moved,
                None::<std::iter::Empty<_>>,
                2.5,
            ));
            assert_eq!(none, all, "{bad:?}, a traffic action ran");
            // A non-finite moved entity: everything is checked.
            let slow = text(check_after_moves(&entities, false, Some(later()), 2.5));
            assert_eq!(slow, all, "{bad:?}, a moved entity was not finite");
        }
    }
}
