//! Relations of another actor to a member of random traffic (ASAM OpenSCENARIO DSL 2.1 §8.9
//! `position`, `lane`, `speed` relative to another actor; §8.7.18.1 non-normative: the group
//! "defines the initial conditions of actors", its members "act as 'noise'").
//!
//! The plan draws the members' places and start speeds from the run's seed once every other
//! actor is placed (`random_traffic`), and their motion after the start is their driver
//! model's, which the plan does not know. So what the plan can know of a member is its start:
//! a relation to a member at the start of another actor's first phase (`position(d, behind:
//! g.vehicles[0], at: start)`, `lane(same_as: …, at: start)`, `speed(same_as: …, at:
//! start)`) reads the placed member — that actor is placed once more after the members
//! (`place::place` with the members fixed where they were drawn; every actor that relates to
//! none is placed as before, and the members kept the gap from them). Such an actor is placed
//! where the members did not keep a gap from it, so its box must not overlap a member's in its
//! lane: where the seed put one there, an error at the relation naming the member
//! (the scenario asks for a place the noise occupies in that run).
//!
//! A group of the plan (a `vehicle_group`, not random traffic) in its members' first phase is
//! placed so too: each of its members is held and placed from the member as drawn, the group's
//! formation kept (`convoy.drive() with: position(40m, behind: g.vehicles[0], at: start)`).
//! A group's phase that is the first of some of its members only (others of them acted
//! before) places those from the member as drawn, and the others read it in the engine's
//! run-time forms at the phase start, as after any first phase (`reads_members`, per member).
//!
//! Random traffic relating to a member (of other random traffic, or its own) is what its
//! planners take of any other actor, read where the member is: on the creating phase
//! `lane(…: m)` deals to the member's lane as drawn, its group dealt before (the groups are
//! dealt in the order of their names; a member of a group dealt after, or of the group itself,
//! an error at the modifier, `Unsatisfiable`); after the creation `lane(…: m)` and
//! `change_lane(…, reference: m)` are the engine's RelativeTargetLane on m at the phase start
//! (`random_traffic_actions`); a speed or place relative to it is the errors of §8.7.18.1 that
//! those planners give for any other actor.
//!
//! A place at: all (`position`, `lane`) in the first phase is the start's too (the plan checks
//! a place at: all relative to any actor at the phase start). After the actor's first phase,
//! and as a gap action's reference, a relation to a member reads a motion only the engine
//! knows (the member's model's): the phase is planned in the engine's run-time forms
//! (`plan::runtime`: the checks at the start, the SpeedAction to the member's speed as the
//! engine reads it, the TravelAction, the distance controller), as for any actor the engine
//! moves (`Planner::reads_members`); where they set the actor's motion the actor is the
//! engine's from then on, as after a gap action.
//!
//! A member drawn in a lane driven in −s drives against s: an actor placed in its lane or along
//! it takes its direction, placed on the view against s (`take_members_directions`).
//!
//! A relation at the first phase's end, an acceleration relative to a member and a heading
//! measured from it in the first phase are the same run-time forms (the heading the engine's
//! check).
//!
//! An actor placed along or beside one that takes an oncoming member's direction takes it in
//! turn. Bad input (`Unsatisfiable`): a place (`position`, `lane`, `lateral`, any `at`), a
//! speed (`speed(same_as/faster_than/slower_than: …)`, any `at`) or an acceleration
//! (`acceleration(a, same_as/faster_than/slower_than: …)`) of a member, in a phase of its own,
//! relative to another member (§8.7.18.1: "the behavioral model assigned to each vehicle
//! defines the actual behavior of the vehicle within the group", so its lane, place, speed and
//! acceleration among the group's members are its model's, as for a lane, position or path action
//! creating the group); a relation to the group
//! as a whole (it has no place, speed or lane of its own; the checker refuses the typed
//! arguments first). A condition measures a member at run time: `until
//! ego.space_gap(g.vehicles[0]) < 10m`.

use std::collections::{HashMap, HashSet};

use super::place::{place, Start, ToPlace};
use super::planner::Planner;
use super::random_traffic::UNPLACED;
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{At, Invoke, Kind, ModKind, Modifier, Phase};
use crate::road::PlanRoad;

/// A relation at the start of an actor's first phase to a member of random traffic.
pub(super) struct MemberRelation {
    /// The actor.
    actor: String,
    /// The member.
    member: String,
    /// The argument that names the member.
    site: Site,
    /// A place (`position`, `lane`): along a direction of travel; a speed has none.
    directed: bool,
}

/// The relations to members of random traffic and the actors they hold out of the first
/// placement (`Planner::hold_dependents`), placed once the members are drawn
/// (`Planner::place_relative_to_members`).
pub(super) struct MemberDependents {
    /// Each actor placed from a member.
    pub relations: Vec<MemberRelation>,
    /// Those actors and the ones placed from them.
    pub held: HashSet<String>,
}

/// Whether relation `m` to a member places an actor from it at the start of the actor's first
/// phase: a speed, a place (`position`, `lane`, `lateral`) at: start or all. At: all is the start's, where
/// the member is as drawn: docs/dsl.md's rule for any actor, a speed at: all a step to it at
/// the phase start, a place at: all the placement and a check at the start.
fn placed_from(m: Option<&Modifier>) -> bool {
    m.is_some_and(|m| {
        m.at != At::End
            && matches!(
                m.kind,
                ModKind::Position | ModKind::Lane | ModKind::Lateral | ModKind::Speed
            )
    })
}

impl Planner<'_> {
    /// The relations of other actors to members of random traffic among `leaves` the plan
    /// runs (module doc); any other reference to a member or a group of random traffic is an
    /// error at the argument.
    pub(super) fn random_traffic_relations(
        &self,
        leaves: &[&Phase],
    ) -> Result<Vec<MemberRelation>, Error> {
        let mut out = Vec::new();
        if self.random.is_empty() {
            return Ok(out);
        }
        for leaf in leaves {
            let Kind::Invoke(inv) = &leaf.kind else {
                continue;
            };
            // The actors this phase places when it is their first: the actor, or each member
            // of a group of the plan's (not of random traffic) whose first phase it is.
            let placed: Vec<&String> = match self.groups.get(&inv.actor) {
                Some(ms) if !self.random.contains_key(&inv.actor) => ms.iter().collect(),
                Some(_) => Vec::new(),
                None => self
                    .index
                    .get_key_value(&inv.actor)
                    .into_iter()
                    .map(|(k, _)| k)
                    .collect(),
            };
            // Those of them whose first phase this is: placed from the member as drawn; the
            // others (members of a group that acted before) read it at run time
            // (`reads_members`).
            let firsts: Vec<&String> = placed
                .iter()
                .copied()
                .filter(|a| !self.random_member(a) && self.first_leaf.get(*a) == Some(&leaf.path))
                .collect();
            for (m, key, a) in inv.all_args() {
                let Some(x) = a.path.as_deref() else {
                    continue;
                };
                if x == inv.actor || !(self.random_member(x) || self.random.contains_key(x)) {
                    continue;
                }
                if !firsts.is_empty() && placed_from(m) && self.random_member(x) {
                    out.extend(firsts.iter().map(|actor| MemberRelation {
                        actor: (*actor).clone(),
                        member: x.to_string(),
                        site: a.site.clone(),
                        directed: m.is_some_and(|m| m.kind != ModKind::Speed),
                    }));
                    continue;
                }
                // A member given a place, a speed or an acceleration relative to another
                // member in a phase of its own (`g.vehicles[0].drive() with: position(20m,
                // behind: g.vehicles[1])`, `speed(same_as: g.vehicles[1])`, `acceleration(1mpsps,
                // faster_than: g.vehicles[1])`): bad input, as a lane, position or path action
                // creating the group is (§8.7.18.1: a member's behaviour within the group, its
                // lane, place, path, speed and acceleration, is its model's). Before, the speed
                // ran: the other member's speed at the phase start handed to the model as its
                // desired speed; and the acceleration ran as nothing: the engine ignored its
                // RelativeAccelerationAction, the member's model holding the longitudinal
                // domain (issue 27).
                if let Some(m) = m.filter(|m| {
                    matches!(
                        m.kind,
                        ModKind::Position
                            | ModKind::Lane
                            | ModKind::Lateral
                            | ModKind::Speed
                            | ModKind::Acceleration
                    ) && self.random_member(&inv.actor)
                        && self.random_member(x)
                }) {
                    let (what, whose) = match m.kind {
                        ModKind::Speed => ("speed", "speed is"),
                        ModKind::Acceleration => ("acceleration", "acceleration is"),
                        _ => ("place", "lane and place are"),
                    };
                    return Err(m.site.err(
                        K::Unsatisfiable,
                        format!("expected no {what} of `{}`, a member of random traffic, relative to `{x}`, found `{}(…)`: \"the behavioral model assigned to each vehicle defines the actual behavior of the vehicle within the group\" (§8.7.18.1), so a member's {whose} its model's, which the seed and the traffic around it decide; relate another actor to the member instead", inv.actor, m.name),
                    ));
                }
                // Random traffic relating to a member (of its own group or another's): what
                // its planners take of another actor, read where the member is then
                // (`random_traffic_creation`, `random_traffic_actions`), the rest their
                // errors (§8.7.18.1).
                if self.random.contains_key(&inv.actor) && self.random_member(x) {
                    continue;
                }
                // After the actor's first phase (for a group, of each member that acted
                // before), a gap action's reference, a relation at the first phase's end, an
                // acceleration or a heading relative to it: the engine's run-time forms
                // (`reads_members`).
                if self.random_member(x) && !self.random.contains_key(&inv.actor) {
                    continue;
                }
                let what = m.map_or_else(
                    || format!("{}(…)", inv.action),
                    |m| format!("{}(…)", m.name),
                );
                // The group as a whole, or a member relating to another: bad input.
                return Err(a.site.err(
                    K::Unsatisfiable,
                    format!("expected `{key}:` of {what} to name one vehicle, found `{x}` of random traffic here: {}", if self.random.contains_key(x) { "the group has no place, speed or lane of its own (no formation and no leader: §8.7.18.1, it \"defines the initial conditions of actors\", each member's model its behaviour); name a member, g.vehicles[i]" } else { "a member's motion is its driver model's (§8.7.18.1), which no relation of it to another actor changes" }),
                ));
            }
        }
        Ok(out)
    }

    /// Whether invocation `inv` (phase `p`) relates `target` (its actor, or a member of its
    /// group) to a member of random traffic after `target`'s first phase
    /// (`random_traffic_relations` let only those and gap actions through): `Some(moves)`, planned in the engine's run-time forms, as after a start the
    /// plan does not know (the member's motion is its model's); `moves`: the engine then sets
    /// the actor's motion (a speed, a place at the end, a gap), so the plan no longer knows
    /// its track, as after a gap action; a check of a place at the start leaves it known.
    pub(super) fn reads_members(&self, p: &Phase, inv: &Invoke, target: &str) -> Option<bool> {
        if self.random.is_empty() || self.random.contains_key(&inv.actor) {
            return None;
        }
        let mut found = None;
        for (m, _, a) in inv.all_args() {
            if !a.path.as_deref().is_some_and(|x| self.random_member(x)) {
                continue;
            }
            // The first phase's relations at its start place the actor from the member as
            // drawn (for a group, each member whose first phase it is).
            if placed_from(m) && self.first_leaf.get(target) == Some(&p.path) {
                continue;
            }
            let check = m.is_some_and(|m| {
                m.at != At::End
                    && matches!(m.kind, ModKind::Position | ModKind::Lane | ModKind::Lateral)
            });
            found = Some(found.unwrap_or(false) || !check);
        }
        found
    }

    /// The actors placed from a member of random traffic (`relations`), and those placed
    /// from them, held out of the first placement (fixed at a placeholder that
    /// `place_random_traffic` does not count) until the members are drawn.
    pub(super) fn hold_dependents(
        &self,
        to_place: &mut [ToPlace<'_>],
        relations: Vec<MemberRelation>,
    ) -> MemberDependents {
        let mut held: HashSet<String> = relations.iter().map(|r| r.actor.clone()).collect();
        loop {
            let more: Vec<String> = to_place
                .iter()
                .filter(|q| !held.contains(&q.name))
                .filter(|q| {
                    q.mods.iter().any(|m| {
                        m.args
                            .iter()
                            .any(|(_, a)| a.path.as_deref().is_some_and(|x| held.contains(x)))
                    })
                })
                .map(|q| q.name.clone())
                .collect();
            if more.is_empty() {
                break;
            }
            held.extend(more);
        }
        for q in to_place.iter_mut().filter(|q| held.contains(&q.name)) {
            q.fixed = Some(UNPLACED);
        }
        MemberDependents { relations, held }
    }

    /// The direction of travel of the actors placed from members of random traffic
    /// (`dependents`), the members drawn (`oncoming`: those driving against s): an actor placed
    /// in a member's lane or along its lane (`lane`, `position`) drives the member's way, on
    /// the view against s for an oncoming member (OpenDRIVE 1.8 §11.2: its lane is driven in
    /// −s), unless it is declared driving the other way, an error at the relation (a place
    /// "behind" or "in the lane of" an actor driving the opposite way names none, as between
    /// any two actors; as this run's seed draws the member). A speed has no direction. An actor
    /// placed from two members of opposite directions is an error at its relation; the actors
    /// placed along or beside such an actor in turn take its direction. The
    /// oncoming members are marked against s in `to_place`, their starts being in u = L − s.
    fn take_members_directions(
        &self,
        to_place: &mut [ToPlace<'_>],
        oncoming: &HashSet<String>,
        dependents: &MemberDependents,
    ) -> Result<(), Error> {
        let MemberDependents { relations, held } = dependents;
        for q in to_place.iter_mut() {
            q.against |= oncoming.contains(&q.name);
        }
        let mut actors: Vec<&String> = held.iter().collect();
        actors.sort();
        for a in actors {
            let mut directed = relations.iter().filter(|r| &r.actor == a && r.directed);
            let Some(first) = directed.next() else {
                continue;
            };
            let back = oncoming.contains(&first.member);
            if let Some(r) = directed.find(|r| oncoming.contains(&r.member) != back) {
                return Err(r.site.err(
                    K::Unsatisfiable,
                    format!("expected the members of random traffic that `{a}` is placed from to drive one way, found `{}` and `{}` driving opposite ways (as this run's seed draws them)", first.member, r.member),
                ));
            }
            let Some(q) = to_place.iter_mut().find(|q| &q.name == a) else {
                continue;
            };
            if q.against && !back {
                return Err(first.site.err(
                    K::Unsatisfiable,
                    format!("expected `{a}`, which drives against s, placed from a member of random traffic driving its way, found `{}` driving in +s (as this run's seed draws it): a place along or beside an actor driving the opposite way names none", first.member),
                ));
            }
            if back && !q.against {
                q.against = true;
            }
        }
        // The actors placed from those in turn (held with them) take the direction of the
        // actors they are placed along or beside, until none changes.
        loop {
            let against: HashSet<String> = to_place
                .iter()
                .filter(|q| q.against)
                .map(|q| q.name.clone())
                .collect();
            let mut changed = false;
            for q in to_place
                .iter_mut()
                .filter(|q| held.contains(&q.name) && !q.against)
            {
                let directed = q.mods.iter().filter(|m| {
                    matches!(m.kind, ModKind::Position | ModKind::Lane | ModKind::Lateral)
                });
                let refs: Vec<(&str, &Site)> = directed
                    .flat_map(|m| m.args.iter())
                    .filter_map(|(_, a)| Some((a.path.as_deref()?, &a.site)))
                    .filter(|(x, _)| held.contains(*x) || self.random_member(x))
                    .collect();
                let Some((x, site)) = refs.iter().find(|(x, _)| against.contains(*x)) else {
                    continue;
                };
                if let Some((y, _)) = refs.iter().find(|(y, _)| !against.contains(*y)) {
                    return Err(site.err(
                        K::Unsatisfiable,
                        format!("expected the actors `{}` is placed from driving one way, found `{x}` driving against s and `{y}` in +s (as this run's seed draws the members)", q.name),
                    ));
                }
                q.against = true;
                changed = true;
            }
            if !changed {
                return Ok(());
            }
        }
    }

    /// Places the actors `dependents` holds (`hold_dependents`) among `starts` once the members
    /// of random traffic are drawn (`oncoming`: those placed against s), every other actor and
    /// the members fixed where they are; checks that none of them overlaps a member in its lane
    /// (module doc), an error at the relation's argument.
    pub(super) fn place_relative_to_members(
        &self,
        road: &PlanRoad<'_>,
        to_place: &mut [ToPlace<'_>],
        starts: &mut HashMap<String, Start>,
        oncoming: &HashSet<String>,
        dependents: &MemberDependents,
        entity: &dyn Fn(&str) -> Option<String>,
    ) -> Result<(), Error> {
        let MemberDependents { relations, held } = dependents;
        let Some(first) = relations.first() else {
            return Ok(());
        };
        self.take_members_directions(to_place, oncoming, dependents)?;
        // Everyone but the held actors where they are; the members at their draws.
        for q in to_place.iter_mut() {
            if held.contains(&q.name) {
                q.fixed = None;
            } else if q.fixed.is_none() || self.random_member(&q.name) {
                q.fixed = starts.get(&q.name).copied();
            }
        }
        let again = place(road, self.against_road.as_ref(), to_place, entity)?;
        // In name order: the first overlap found is the same in every run of one seed.
        let mut members: Vec<String> = starts
            .keys()
            .filter(|n| self.random_member(n))
            .cloned()
            .collect();
        members.sort();
        let mut actors: Vec<&String> = held.iter().collect();
        actors.sort();
        let span = |n: &str, st: &Start| {
            let b = self.entities[self.index[n]].data.bounding_box;
            (
                st.s - (b.length / 2.0 - b.center[0]),
                st.s + b.center[0] + b.length / 2.0,
            )
        };
        for a in actors {
            let r = relations.iter().find(|r| &r.actor == a).unwrap_or(first);
            let st = again[a];
            let (rear, front) = span(a, &st);
            for m in &members {
                let sm = starts[m];
                let (mr, mf) = span(m, &sm);
                if sm.lane == st.lane && rear < mf && mr < front {
                    return Err(r.site.err(
                        K::Unsatisfiable,
                        format!("expected `{a}` placed from `{}` of random traffic clear of its members, found it over `{m}` in lane {} (s {rear:.2} to {front:.2} m against {mr:.2} to {mf:.2} m, as this run's seed draws them)", r.member, st.lane),
                    ));
                }
            }
            starts.insert(a.clone(), st);
        }
        Ok(())
    }
}
