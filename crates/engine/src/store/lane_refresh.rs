//! The lane index's entries made in the controllers stage's moves' walk, and at the next
//! step's start made anew only for the entities written since (issue 31; OpenSCENARIO 1.3
//! §8 "Scenario at runtime": between the moves of one step and the commands of the next the
//! output, the triggers and the actions run, semantics-pitfalls #6, and any of them may
//! change an entity).
//!
//! **Why.** The index must describe the world as the commands of a step find it. Built in a
//! walk of its own at the step's start, it loaded each entity's lines a second time per step
//! after the moves' walk of the step before had loaded them: at 4,000 vehicles the store
//! (5 MB) does not stay in the core's 2 MB cache from one walk to the next, and the first load
//! of each entity in each walk was the walks' cost (docs/performance.md, "The walks at 4,000
//! vehicles"). Now the moves' walk enters each entity right after its move, while its lines
//! are in the cache ([`LaneIndex::enter_moved`]), and the step's start enters only those
//! written since.
//!
//! **Why the answers are a full build's.** Every write of an entity outside the moves' walk
//! goes through the store (store/world.rs: `entity_mut`, `entity_on_network_mut`,
//! `entities_mut`, `place_resolved`, `spawn`; the store's entities are private to it), and each
//! marks the entity written. An entity the moves' walk entered and nothing wrote since is as
//! the walk entered it: its footprint, driver inputs and entries are those a build would make
//! now, as a build's entries depend on the entity, the network and the kept borders alone
//! (store/lane_index.rs `enter_with_input`). A written entity, or one added after the walk, is entered
//! anew from what the last settling left (its kept row describes the entries in the lanes),
//! exactly as the walk of a whole build enters every entity, and the lanes are settled again
//! with the entries of the entities not entered standing as they are. Where the moves' walk
//! entered nothing (no model held a domain in that step) the next build enters every entity.
//! Debug builds compare every build with a full one (`LaneIndex::rebuild`), and
//! store/lane_kept_tests.rs does so in random traffic with writes between the walks.

use std::sync::Arc;

use opendrive::RoadNetwork;

use super::lane_index::LaneIndex;
use super::World;
use crate::world::entity::Entity;

impl LaneIndex {
    /// Brings this index up to date with `world`'s store ([`LaneIndex::rebuild`]): where the
    /// last moves' walk entered the entities, only those written since (or added) are entered
    /// anew; the world's marks are then cleared.
    pub fn refresh_from(&mut self, world: &mut World) {
        let (net, entities, written) = world.for_lane_index();
        self.rebuild(net, entities, written);
        written.fill(false);
    }

    /// Before the moves' walk of a step whose index was built ([`LaneIndex::rebuild`]) for
    /// the `n` entities the walk moves.
    pub fn begin_moves(&mut self, n: usize) {
        self.fit(n);
        self.moved = 0;
    }

    /// Enters `e`, just moved, as a build would (its footprint, driver inputs and entries),
    /// its entries waiting for [`end_moves`](Self::end_moves).
    #[inline]
    pub fn enter_moved(&mut self, net: &Arc<RoadNetwork>, e: &Entity) {
        self.enter_with_input(net, e, true);
    }

    /// After the moves' walk: `Some(n)` where it entered each of the `n` entities it moved
    /// (the entries join their lanes now), `None` where it entered none (the next build
    /// enters every entity).
    pub fn end_moves(&mut self, entered: Option<usize>) {
        match entered {
            Some(n) => {
                self.settle(true, None);
                self.moved = n;
            }
            None => self.moved = 0,
        }
    }

    /// Brings the index the moves' walk made up to date with `entities`: those `written`
    /// since (by index) or added after the walk are entered anew (module doc). False, doing
    /// nothing, where the walk entered none of them (or another network's or more entities):
    /// the caller builds the index.
    pub(super) fn refresh(
        &mut self,
        net: &Arc<RoadNetwork>,
        entities: &[Entity],
        written: &[bool],
    ) -> bool {
        let (n, moved) = (entities.len(), self.moved);
        if moved == 0 || moved > n || written.len() != n || !self.numbers(net) {
            return false;
        }
        self.fit(n);
        // Nothing written since the walk (the common case: no action between two steps wrote
        // an entity): nothing to enter. Asked by an OR over every mark, which the compiler
        // does 16 marks to an instruction, where the scan below tests them one by one.
        if moved == n && !written.iter().fold(false, |any, &w| any | w) {
            return true;
        }
        let stale = |i: usize| i >= moved || written[i];
        let mut any = false;
        for i in (0..n).rev().filter(|&i| stale(i)) {
            self.enter_with_input(net, &entities[i], true);
            any = true;
        }
        if any {
            self.settle(true, Some(&stale));
        }
        true
    }
}
