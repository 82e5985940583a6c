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
//! Every other relation to a member or the group — at: all or end, in a later phase, in an
//! action's argument, from a group, across directions of travel (a member or the actor driving
//! against s) — would read a motion the plan does not have: an error at the argument (measure
//! a member at run time in a condition instead: `until ego.space_gap(g.vehicles[0]) < 10m`).

use std::collections::{HashMap, HashSet};

use super::place::{place, Start, ToPlace};
use super::planner::Planner;
use super::random_traffic::UNPLACED;
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{At, Kind, ModKind, Phase};
use crate::road::PlanRoad;

/// A relation at the start of an actor's first phase to a member of random traffic.
pub(super) struct MemberRelation {
    /// The actor.
    actor: String,
    /// The member.
    member: String,
    /// The argument that names the member.
    site: Site,
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
            let actor_first = self.index.contains_key(&inv.actor)
                && !self.random_member(&inv.actor)
                && self.first_leaf.get(&inv.actor) == Some(&leaf.path);
            for (m, key, a) in inv.all_args() {
                let Some(x) = a.path.as_deref() else {
                    continue;
                };
                if x == inv.actor || !(self.random_member(x) || self.random.contains_key(x)) {
                    continue;
                }
                let at_start = m.is_some_and(|m| {
                    m.at == At::Start
                        && matches!(m.kind, ModKind::Position | ModKind::Lane | ModKind::Speed)
                });
                if actor_first && at_start && self.random_member(x) {
                    out.push(MemberRelation {
                        actor: inv.actor.clone(),
                        member: x.to_string(),
                        site: a.site.clone(),
                    });
                    continue;
                }
                let what = m.map_or_else(
                    || format!("{}(…)", inv.action),
                    |m| format!("{}(…)", m.name),
                );
                return Err(a.site.err(
                    K::Unsupported,
                    format!("expected `{key}:` of {what} to name an actor the plan moves, or a member of random traffic at: start of the first phase of an actor (the member's place and speed as drawn from the seed), found `{x}` of random traffic here (its motion is the engine's driver model's: the plan does not know it; measure it at run time in a condition instead)"),
                ));
            }
        }
        Ok(out)
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
        let against =
            |n: &str| oncoming.contains(n) || to_place.iter().any(|q| q.name == n && q.against);
        for r in relations {
            if against(&r.member) || against(&r.actor) {
                return Err(r.site.err(
                    K::Unsupported,
                    format!("expected `{}` and `{}` of random traffic both driving in +s to relate them at the start, found one driving against s (as this run's seed draws the members)", r.actor, r.member),
                ));
            }
        }
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
