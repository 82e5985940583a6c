//! The actions that control a vehicle's gap to another object (ASAM OpenSCENARIO DSL 2.1 §8.8.3
//! actions for vehicle: `change_space_gap`, `keep_space_gap`, `change_time_headway`,
//! `keep_time_headway`), lowered to the engine's LongitudinalDistanceAction (OpenSCENARIO 1.3
//! §7.7.2.1), whose distance controller has the dynamics:
//!
//! | action | LongitudinalDistanceAction | ends |
//! | --- | --- | --- |
//! | `change_space_gap(target, direction, reference)` | `distance` = target, `freespace` (the space gap is between the bounding boxes, §8.7.5.1.3), road coordinates, `continuous="false"` | when the gap is reached (the engine: within 0.1 m) |
//! | `keep_space_gap(reference, direction)` | as above, the gap at its start, `continuous="true"` | with its phase |
//! | `change_time_headway(target, direction, reference)` | `timeGap` = target between the reference points (§8.7.5.1.2 measures the headway "from reference point to reference point"), `continuous="false"` | when the headway is reached |
//! | `keep_time_headway(reference, direction)` | as above, the headway at its start, `continuous="true"` | with its phase |
//!
//! `direction`: `behind` (the actor behind the reference) is `displacement`
//! trailingReferencedEntity, `ahead` leadingReferencedEntity, none `any` (the side the actor is
//! on); `keep_space_gap`'s `longitudinal` is `any`. The controller's limits are
//! [`GAP_ACCELERATION`] and [`GAP_DECELERATION`] and the vehicle's maximum speed.
//!
//! The lateral directions of the space gap (`gap_direction` `left`, `right`, `inside`,
//! `outside`; `keep_space_gap`'s `distance_direction` `lateral`) lower to the engine's
//! LateralDistanceAction (OpenSCENARIO 1.3 §7.7.2.2) between the bounding boxes (`freespace`),
//! measured across the road (road coordinates), at most [`LATERAL_GAP_ACCELERATION`] and
//! [`LATERAL_GAP_SPEED`] sideways; the actor keeps its speed along the road:
//!
//! | `direction` | LateralDistanceAction `displacement` |
//! | --- | --- |
//! | `left` (the actor left of the reference) | leftToReferencedEntity |
//! | `right` | rightToReferencedEntity |
//! | `inside` (towards the road's centre line: right-hand traffic, left) | leftToReferencedEntity |
//! | `outside` (away from it: right) | rightToReferencedEntity |
//! | `lateral` (`keep_space_gap`) | any (the side the actor is on) |
//!
//! A change ends when the engine has the gap within 0.01 m; where the plan knows both actors
//! across the road at the phase's start, the place the change leads to must be in a driving
//! lane of the road (else an error). `change_time_headway` has only `ahead` and `behind`
//! (`headway_direction`): a headway is longitudinal.
//!
//! On a vehicle group (the library's group forms, non-normative §8.7.18) the members form a
//! chain along the formation: the members nearest the reference keep the gap to it, each
//! other member to its neighbour on the reference's side (`member_reference`).
//!
//! The gap or headway a `keep_*` action keeps is the one at its start: the target of the gap
//! action the actor ran just before (to the same reference), else the plan's gap between the two
//! tracks at the phase's start. Where the plan does not know the tracks then (a phase that
//! starts on a run-time condition, or an actor the engine's gap controller moves) the engine
//! measures the gap or headway as the action starts and keeps it (oscsim's option `at_start`
//! of the LongitudinalDistanceAction and the LateralDistanceAction, no XML form).
//! While the engine's controller moves the actor the plan does not know its track: a later
//! phase of the actor must start on a run-time condition (an `until`, a `wait`, or the gap
//! action's own end), else an error.
//!
//! Between two actors driving against s (`plan::against`) the same lowering holds: the engine
//! measures road coordinates turned to the actor's direction of travel, so `behind`, `left`,
//! `inside` are the driver's, as the plan's view has them; the check of a lateral place after a
//! run-time start carries the direction (`StateCheck::roads`).

use scenario::{
    CoordinateSystem, DynamicConstraints, GapAtStart, LateralAction, LateralDisplacement,
    LongitudinalAction, LongitudinalDisplacement, PrivateAction, StateCheck,
    StoryboardElementState,
};

use super::action_args::missing;
use super::planner::{Gap, Planner};
use super::speed_actions::Slot;
use super::types::{Planned, When, MAX_SPEED, POSITION_TOLERANCE};
use crate::error::{Error, ErrorKind as K};
use crate::resolve::{arg, Action, Invoke, Phase, Val};

/// Largest acceleration of the gap controller (m/s²): the largest average acceleration ISO
/// 15622 allows an adaptive cruise control, the controller these actions describe.
pub(crate) const GAP_ACCELERATION: f64 = 2.0;
/// Largest deceleration of the gap controller (m/s²): ISO 15622's largest average deceleration
/// of an adaptive cruise control.
pub(crate) const GAP_DECELERATION: f64 = 3.5;
/// Largest lateral acceleration of a lateral gap action (m/s²): ISO 11270's limit of the lateral
/// acceleration a lane keeping assistance may command.
pub(crate) const LATERAL_GAP_ACCELERATION: f64 = 3.0;
/// Largest lateral speed of a lateral gap action (m/s): the peak lateral speed of an unhurried
/// `change_lane()` (`lateral_actions`), so that no gap is opened faster than a lane is changed.
pub(crate) const LATERAL_GAP_SPEED: f64 = 1.0;

/// What a gap keeps, without its value.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    Space,
    Headway,
    Lateral,
}

impl Kind {
    fn of(g: &Gap) -> Kind {
        match g {
            Gap::Space(_) => Kind::Space,
            Gap::Headway(_) => Kind::Headway,
            Gap::Lateral(_) => Kind::Lateral,
        }
    }

    fn with(self, x: f64) -> Gap {
        match self {
            Kind::Space => Gap::Space(x),
            Kind::Headway => Gap::Headway(x),
            Kind::Lateral => Gap::Lateral(x),
        }
    }
}

/// Which way a gap action measures, from its `direction`.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Measure {
    /// Along the road.
    Longitudinal(LongitudinalDisplacement),
    /// Across the road (a space gap only).
    Lateral(LateralDisplacement),
}

impl Planner<'_> {
    /// Plans `inv`'s gap or headway action for one actor; returns when the action ends on its
    /// own (`None`: with its phase).
    pub(super) fn plan_gap_action(
        &mut self,
        p: &Phase,
        inv: &Invoke,
        slot: Slot<'_>,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Result<Option<When>, Error> {
        let Slot {
            target,
            t0,
            first,
            out,
            ..
        } = slot;
        let measure = measure(inv)?;
        let reference = self.member_reference(p, inv, target, t0, measure)?;
        let headway = matches!(
            inv.kind,
            Action::ChangeTimeHeadway | Action::KeepTimeHeadway
        );
        let change = matches!(inv.kind, Action::ChangeSpaceGap | Action::ChangeTimeHeadway);
        let lateral = matches!(measure, Measure::Lateral(_));
        if lateral {
            // Sideways: the speed along the road stays free, the lateral position is the action's.
            super::lateral_actions::check_lateral_modifiers(inv)?;
        } else {
            super::speed_actions::check_speed_modifiers(inv, first)?;
        }
        let kind = match (headway, lateral) {
            (true, _) => Kind::Headway,
            (false, false) => Kind::Space,
            (false, true) => Kind::Lateral,
        };
        let wanted = if change {
            let a = arg(&inv.args, "target").ok_or_else(|| missing(p, inv, "target"))?;
            let x = a.number()?;
            if x < 0.0 || (headway && x <= 0.0) {
                return Err(a.site.err(
                    K::Argument,
                    format!(
                        "expected a target {} {}, found {x}",
                        if headway { "headway" } else { "gap" },
                        if headway {
                            "above 0 s"
                        } else {
                            "of 0 m or more"
                        }
                    ),
                ));
            }
            Some(kind.with(x))
        } else {
            self.gap_at_start(p, inv, (target, &reference), t0, kind)?
        };
        if let (Measure::Lateral(side), Some(Gap::Lateral(g)), Some(t)) = (measure, wanted, t0) {
            if change {
                self.check_lateral_place(p, target, &reference, t, side, g)?;
            }
        }
        if let (Measure::Lateral(side), Some(Gap::Lateral(g)), None, true) =
            (measure, wanted, t0, change)
        {
            // After a run-time start the engine checks the place then (reference and actor
            // where it finds them).
            out.extend(self.lateral_place_check(
                (inv, &p.site),
                (target, &reference),
                side,
                g,
                name,
            ));
        }
        let n = name(&inv.action);
        let action = match measure {
            Measure::Lateral(side) => PrivateAction::Lateral(LateralAction::LateralDistance {
                entity_ref: reference.clone(),
                continuous: !change,
                distance: wanted.map(Gap::value),
                freespace: true,
                displacement: Some(side),
                coordinate_system: Some(CoordinateSystem::Road),
                dynamic_constraints: Some(DynamicConstraints {
                    max_acceleration: Some(LATERAL_GAP_ACCELERATION),
                    max_acceleration_rate: None,
                    max_deceleration: None,
                    max_deceleration_rate: None,
                    max_speed: Some(LATERAL_GAP_SPEED),
                }),
                // Without a value: the one the engine measures as the action starts.
                at_start: wanted.is_none(),
            }),
            Measure::Longitudinal(displacement) => {
                // Without a value: the one the engine measures as the action starts.
                let (distance, time_gap, at_start) = match (wanted, kind) {
                    (Some(Gap::Headway(t)), _) => (None, Some(t), None),
                    (Some(Gap::Space(d) | Gap::Lateral(d)), _) => (Some(d), None, None),
                    (None, Kind::Headway) => (None, None, Some(GapAtStart::TimeGap)),
                    (None, _) => (None, None, Some(GapAtStart::Distance)),
                };
                PrivateAction::Longitudinal(LongitudinalAction::LongitudinalDistance {
                    entity_ref: reference.clone(),
                    continuous: !change,
                    distance,
                    time_gap,
                    freespace: !headway,
                    displacement: Some(displacement),
                    coordinate_system: Some(CoordinateSystem::Road),
                    dynamic_constraints: Some(DynamicConstraints {
                        max_acceleration: Some(GAP_ACCELERATION),
                        max_acceleration_rate: None,
                        max_deceleration: Some(GAP_DECELERATION),
                        max_deceleration_rate: None,
                        max_speed: Some(MAX_SPEED),
                    }),
                    at_start,
                    at_least: None,
                })
            }
        };
        out.push(Planned::with_phase(target, n.clone(), action, &p.site));
        // From here the engine's controller moves the actor (along the road: once it holds the
        // gap, at the reference's speed; across it: at its own speed).
        self.engine_moves(target, t0);
        // A change that ends its phase (no duration or `until` of the phase's own) leaves the
        // actor at its target when the phase after it starts.
        let ends_phase =
            (change && p.duration.is_none() && p.until.is_none()).then(|| p.path.clone());
        match wanted {
            Some(g) => self
                .gaps
                .insert(target.to_string(), (reference.clone(), g, ends_phase)),
            // Measured by the engine: the plan knows no gap to keep later.
            None => self.gaps.remove(target),
        };
        if !lateral {
            let v_ref = self.last_v.get(&reference).copied().unwrap_or(0.0);
            self.last_v.insert(target.to_string(), v_ref);
        }
        Ok(change.then(|| {
            When::Dyn(scenario::Trigger {
                condition_groups: vec![scenario::ConditionGroup {
                    conditions: vec![crate::trigger::event_state(
                        &n,
                        StoryboardElementState::CompleteState,
                        p.site.pos.clone(),
                    )],
                }],
            })
        }))
    }

    /// The `reference` of a gap action: mandatory, an entity of the plan.
    fn gap_reference(&self, p: &Phase, inv: &Invoke) -> Result<String, Error> {
        let a = arg(&inv.args, "reference").ok_or_else(|| missing(p, inv, "reference"))?;
        a.path
            .as_ref()
            .filter(|x| self.index.contains_key(*x))
            .cloned()
            .ok_or_else(|| {
                a.site.err(
                    K::UnknownActor,
                    "expected a physical object of the scenario as the reference, found another value",
                )
            })
    }

    /// The object `target` keeps its gap to. For an actor: the action's `reference`. For a
    /// member of the vehicle group the action is invoked on, a chain along the formation
    /// (members in the group's order, front to back; a common-route group over several lanes a
    /// row at a time, so a member's neighbour is the one a row ahead or behind in its lane):
    /// the members nearest the reference keep the gap to it, each other member to its
    /// neighbour on the reference's side. Every member keeping its gap to the reference itself
    /// would put them all at one place. Across the road (`left`, `right`, …) every member of a
    /// single-lane group keeps its gap to the reference (they stay one behind the other); a
    /// group over several lanes, whose members are side by side, cannot.
    fn member_reference(
        &self,
        p: &Phase,
        inv: &Invoke,
        target: &str,
        t0: Option<f64>,
        measure: Measure,
    ) -> Result<String, Error> {
        let reference = self.gap_reference(p, inv)?;
        let Some(members) = self.groups.get(&inv.actor) else {
            return Ok(reference);
        };
        let group = &inv.actor;
        if members.contains(&reference) {
            return Err(p.site.err(
                K::Unsatisfiable,
                format!("expected a reference outside group `{group}` in {}(…) on it, found its member `{reference}`", inv.action),
            ));
        }
        let across = self.across.contains(group);
        let displacement = match measure {
            Measure::Lateral(_) if across => {
                return Err(p.site.err(
                    K::Unsatisfiable,
                    format!("expected a single-lane group for a lateral gap in {}(…), found `{group}`, a common-route group whose members drive side by side over several lanes (each keeping the gap across the road to `{reference}` would put them on one line)", inv.action),
                ))
            }
            Measure::Lateral(_) => return Ok(reference),
            Measure::Longitudinal(d) => d,
        };
        let behind = match displacement {
            LongitudinalDisplacement::TrailingReferencedEntity => true,
            LongitudinalDisplacement::LeadingReferencedEntity => false,
            _ => self.group_behind(p, inv, members, &reference, t0)?,
        };
        // Members per row: 1 in a column; over several lanes those beside member 0 at the start.
        let row = if across {
            let s0 = self.s_at(&members[0], 0.0);
            members
                .iter()
                .take_while(|m| (self.s_at(m, 0.0) - s0).abs() < POSITION_TOLERANCE)
                .count()
                .max(1)
        } else {
            1
        };
        // A target of the group's invocation is one of its members (plan_invoke).
        let i = members.iter().position(|m| m == target).unwrap_or(0);
        let neighbour = if behind {
            i.checked_sub(row)
        } else {
            Some(i + row).filter(|j| *j < members.len())
        };
        Ok(neighbour.map_or(reference, |j| members[j].clone()))
    }

    /// Whether group `members` is behind `reference` for a gap action without a direction:
    /// the side the group's last gap action to it kept, else the side the plan has the
    /// reference on at the phase's start (ahead of the first member, or behind the last).
    fn group_behind(
        &self,
        p: &Phase,
        inv: &Invoke,
        members: &[String],
        reference: &str,
        t0: Option<f64>,
    ) -> Result<bool, Error> {
        let kept_to = |m: Option<&String>| {
            m.and_then(|m| self.gaps.get(m))
                .is_some_and(|(r, _, _)| r == reference)
        };
        if kept_to(members.first()) {
            return Ok(true);
        }
        if kept_to(members.last()) {
            return Ok(false);
        }
        let moved = |x: &str| self.engine_moved.contains_key(x);
        if let Some(t) = t0.filter(|_| !moved(reference) && !members.iter().any(|m| moved(m))) {
            let s_r = self.s_at(reference, t);
            if members.iter().all(|m| self.s_at(m, t) < s_r) {
                return Ok(true);
            }
            if members.iter().all(|m| self.s_at(m, t) > s_r) {
                return Ok(false);
            }
        }
        Err(p.site.err(
            K::Unsatisfiable,
            format!(
                "expected `direction: ahead` or `behind` in {}(…) on group `{}` (it decides which member keeps its gap to `{reference}` and which to the member next to it), found none, and the plan has `{reference}` neither ahead of nor behind the whole group at the phase's start",
                inv.action, inv.actor
            ),
        ))
    }

    /// The gap of `kind` between `target` and `reference` at the start of a `keep_*` action:
    /// the target of the actor's change just before (to the same reference, of the same kind;
    /// its phase, ended by it, the member before this one in a serial), else the plan's gap at the phase's start (along the road or across it); `None`
    /// where the plan does not know the gap then (a run-time start, or an actor the engine's
    /// gap controller moves) and the engine measures it as the action starts.
    fn gap_at_start(
        &self,
        p: &Phase,
        inv: &Invoke,
        (target, reference): (&str, &str),
        t0: Option<f64>,
        kind: Kind,
    ) -> Result<Option<Gap>, Error> {
        // The target of the change whose end starts this phase (the member before it in a
        // serial, ended by the change): where the actor is then. Any other phase in between
        // (a wait, a drive, a change cut by its phase's duration) lets the gap drift, and the
        // engine measures it when the action starts (below).
        if let Some((r, g, Some(ended))) = self.gaps.get(target) {
            if r == reference
                && Kind::of(g) == kind
                && self.serial_before.get(&p.path) == Some(ended)
            {
                return Ok(Some(*g));
            }
        }
        let moved =
            self.engine_moved.contains_key(target) || self.engine_moved.contains_key(reference);
        let Some(t) = t0.filter(|_| !moved) else {
            return Ok(None);
        };
        if kind == Kind::Lateral {
            let (t_a, t_r) = (self.t_at(target, t), self.t_at(reference, t));
            let left = t_a > t_r;
            let facing = self.side_extent(target, !left) + self.side_extent(reference, left);
            return Ok(Some(Gap::Lateral(((t_a - t_r).abs() - facing).max(0.0))));
        }
        let (s_a, s_r) = (self.s_at(target, t), self.s_at(reference, t));
        let between = (s_r - s_a).abs();
        if kind == Kind::Headway {
            let v = self.track(reference).at(t).1;
            if v <= 0.0 {
                return Err(p.site.err(
                    K::Unsatisfiable,
                    format!("expected the reference of {}(…) moving at its start, found it standing (no headway to a standing object)", inv.action),
                ));
            }
            return Ok(Some(Gap::Headway(between / v)));
        }
        let overhangs = self.facing_overhangs(target, reference, s_r >= s_a);
        Ok(Some(Gap::Space((between - overhangs).max(0.0))))
    }

    /// After a run-time start, the engine's check that a lateral change of the gap to
    /// `reference` on `side` of it (left or right; `None` for either side, which keeps the
    /// side the actor is on) to `gap` leaves `target`'s reference point in a driving lane of
    /// its side of the road: the point reach = the facing extents + gap across from the
    /// reference's t, at the actor's s.
    fn lateral_place_check(
        &self,
        (inv, site): (&Invoke, &crate::error::Site),
        (target, reference): (&str, &str),
        side: LateralDisplacement,
        gap: f64,
        name: &mut dyn FnMut(&str) -> String,
    ) -> Option<Planned> {
        let left = match side {
            LateralDisplacement::LeftToReferencedEntity => true,
            LateralDisplacement::RightToReferencedEntity => false,
            _ => return None,
        };
        let reach = self.side_extent(reference, left) + gap + self.side_extent(target, !left);
        let check = StateCheck {
            beside_in_lane: Some((reference.to_string(), if left { reach } else { -reach })),
            // Against s the t across is to the left of the direction of travel.
            roads: self.chain(),
            ..StateCheck::default()
        };
        Some(super::runtime::phase_start_check(
            target,
            (&inv.action, site),
            check,
            name("check"),
        ))
    }

    /// Checks that a lateral gap `gap` to `reference` on `side` of it, from the phase's start
    /// `t`, leaves `target`'s reference point in a driving lane of the road.
    fn check_lateral_place(
        &self,
        p: &Phase,
        target: &str,
        reference: &str,
        t: f64,
        side: LateralDisplacement,
        gap: f64,
    ) -> Result<(), Error> {
        let t_r = self.t_at(reference, t);
        let left = match side {
            LateralDisplacement::LeftToReferencedEntity => true,
            LateralDisplacement::RightToReferencedEntity => false,
            _ => self.t_at(target, t) > t_r,
        };
        let reach = self.side_extent(reference, left) + gap + self.side_extent(target, !left);
        let t_a = if left { t_r + reach } else { t_r - reach };
        let s = self.s_at(target, t);
        if self.road.lane_holding(s, t_a).is_some() {
            return Ok(());
        }
        Err(p.site.err(
            K::Unsatisfiable,
            format!(
                "expected a {gap} m gap {} of `{reference}` to leave `{target}` in a driving lane, found it at t = {t_a:.2} m across the road (s = {s:.2} m), off the driving lanes",
                if left { "left" } else { "right" }
            ),
        ))
    }
}

/// How a gap action measures, from its `direction` (none: along the road, either side).
fn measure(inv: &Invoke) -> Result<Measure, Error> {
    let Some(a) = arg(&inv.args, "direction") else {
        return Ok(Measure::Longitudinal(LongitudinalDisplacement::Any));
    };
    let d = match a.eval()? {
        Val::Enum(d) => d,
        _ => {
            return Err(a
                .site
                .err(K::Argument, "expected a direction, found another value"))
        }
    };
    Ok(match d.as_str() {
        "behind" => Measure::Longitudinal(LongitudinalDisplacement::TrailingReferencedEntity),
        "ahead" => Measure::Longitudinal(LongitudinalDisplacement::LeadingReferencedEntity),
        "longitudinal" => Measure::Longitudinal(LongitudinalDisplacement::Any),
        // Right-hand traffic: the inside of the road is to the left.
        "left" | "inside" => Measure::Lateral(LateralDisplacement::LeftToReferencedEntity),
        "right" | "outside" => Measure::Lateral(LateralDisplacement::RightToReferencedEntity),
        "lateral" => Measure::Lateral(LateralDisplacement::Any),
        _ => {
            return Err(a.site.err(
                K::Argument,
                format!("expected a gap direction (ahead, behind, left, right, inside, outside, longitudinal, lateral) in {}(…), found `{d}`", inv.action),
            ))
        }
    })
}
