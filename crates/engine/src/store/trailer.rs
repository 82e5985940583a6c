//! Trailers at runtime (OpenSCENARIO 1.3 §7.2.2.6 "Trailer modeling", XSD `TrailerHitch`,
//! `TrailerCoupler`, `Trailer`, `ConnectTrailerAction`, `DisconnectTrailerAction`): which
//! vehicle tows which, and the one-axle trailer kinematics that move a towed vehicle.
//!
//! A trailer's reference point is its rear axle; its coupler lies `L` = coupler dx ahead of it
//! on its x axis, the tow vehicle's hitch `hitch dx` ahead of the tow's reference point. The
//! coupler is pinned to the hitch; the axle follows the hitch as a tractrix,
//! dθ/ds = sin(α − θ) / L, with α the direction in which the hitch moves and s its travel.
//! Over one step the hitch is taken to move along the straight segment from its previous to its
//! new position (α constant), where the equation has the closed-form solution
//! tan(φ/2) = tan(φ₀/2) · e^(−d/L), φ = θ − α, d the segment's length. The heading is thus
//! integrated exactly for the piecewise-straight hitch path, and the axle is then placed at
//! hitch − L·(cos θ, sin θ), so the coupler sits on the hitch to rounding error whatever dt.
//!
//! A trailer's speed is that of its own reference point (the distance its axle moved in the
//! step over dt, signed as the tow's), so it is lower than the tow's in a curve; esmini reports
//! the tow's speed for its trailers (up to 3.6 m/s apart in its `trailers` run).
//!
//! Chains (truck → trailer → trailer) are moved tow first. A connection made at definition
//! (`Vehicle/Trailer`) lines the trailer up straight behind its tow at the first step, as esmini
//! does; ConnectTrailerAction keeps the trailer where it stands, turned towards the hitch, or
//! lines it up when it has not been placed yet. When the hitch jumps (the tow is teleported),
//! the trailer is lined up behind it again. Inline trailers (`Trailer/Trailer`) become
//! entities named after their tow with a `+` appended (esmini's names: `Ego+`, `Ego++`).
//!
//! Written by hand: no maintained crate models articulated vehicles in this form.

use std::collections::BTreeMap;

use opendrive::{normalize_angle, Pose, Real};
use scenario::{EntityObject, Scenario, ScenarioObject, SourcePos, Trailer};

use crate::error::Error;
use crate::world::entity::{Entity, EntityId};

/// Mounting points of one vehicle (m along its x axis from the reference point).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Joints {
    /// TrailerHitch dx, where a trailer attaches.
    pub hitch: Option<Real>,
    /// TrailerCoupler dx, where this vehicle attaches to a tow.
    pub coupler: Option<Real>,
}

/// One tow → trailer connection.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Link {
    /// The towing vehicle.
    pub tow: EntityId,
    /// The towed vehicle.
    pub trailer: EntityId,
    /// Line the trailer up behind the tow at its first placement.
    pub align: bool,
    /// Hitch position of the previous step, once placed.
    pub last_hitch: Option<(Real, Real)>,
    /// The trailer's pose after the previous step (the default controller may have moved the
    /// entity in between).
    pub last_pose: Pose,
    /// The trailer's odometer after the previous step.
    pub odometer: Real,
}

/// Every vehicle's mounting points and the connections in force.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Trailers {
    /// Each vehicle's mounting points.
    pub(crate) joints: BTreeMap<EntityId, Joints>,
    /// The connections in force.
    pub(crate) links: Vec<Link>,
}

impl Trailers {
    /// The trailer `tow` pulls, if any.
    pub fn trailer_of(&self, tow: EntityId) -> Option<EntityId> {
        self.links.iter().find(|l| l.tow == tow).map(|l| l.trailer)
    }

    /// Every trailer connected now (the entities `follow` places behind their tows).
    pub fn trailers(&self) -> impl Iterator<Item = EntityId> + '_ {
        self.links.iter().map(|l| l.trailer)
    }

    /// The vehicle pulling `trailer`, if any.
    pub fn tow_of(&self, trailer: EntityId) -> Option<EntityId> {
        self.links
            .iter()
            .find(|l| l.trailer == trailer)
            .map(|l| l.tow)
    }

    /// Connects `trailer` to `tow` (ConnectTrailerAction, or `Vehicle/Trailer` with
    /// `align`). Errors name `pos`: a missing hitch or coupler, a coupler dx ≤ 0, a tow that
    /// already pulls a trailer (§7.2.2.6: one at a time), a trailer already towed, or a cycle.
    pub(crate) fn connect(
        &mut self,
        world_names: &dyn Fn(EntityId) -> String,
        tow: EntityId,
        trailer: EntityId,
        align: bool,
        pos: &SourcePos,
    ) -> Result<(), Error> {
        let name = |id| format!("'{}'", world_names(id));
        let joints = |id| self.joints.get(&id).copied().unwrap_or_default();
        if joints(tow).hitch.is_none() {
            return Err(Error::at(
                "a tow vehicle with a TrailerHitch",
                format!("{} without one", name(tow)),
                pos,
            ));
        }
        match joints(trailer).coupler {
            Some(dx) if dx > 0.0 && dx.is_finite() => {}
            Some(dx) => {
                return Err(Error::at(
                    "a TrailerCoupler dx > 0 m (ahead of the trailer's rear axle)",
                    format!("dx = {dx} on {}", name(trailer)),
                    pos,
                ))
            }
            None => {
                return Err(Error::at(
                    "a trailer with a TrailerCoupler",
                    format!("{} without one", name(trailer)),
                    pos,
                ))
            }
        }
        if let Some(old) = self.trailer_of(tow) {
            return Err(Error::at(
                "a tow vehicle without a trailer (one trailer at a time)",
                format!("{} already pulling {}", name(tow), name(old)),
                pos,
            ));
        }
        if let Some(old) = self.tow_of(trailer) {
            return Err(Error::at(
                "a trailer not yet connected",
                format!("{} already towed by {}", name(trailer), name(old)),
                pos,
            ));
        }
        // Walking up from the tow must not reach the trailer.
        let mut up = Some(tow);
        while let Some(id) = up {
            if id == trailer {
                return Err(Error::at(
                    "a trailer chain without a cycle",
                    format!("{} towing {} in a loop", name(tow), name(trailer)),
                    pos,
                ));
            }
            up = self.tow_of(id);
        }
        self.links.push(Link {
            tow,
            trailer,
            align,
            last_hitch: None,
            last_pose: Pose::default(),
            odometer: 0.0,
        });
        Ok(())
    }

    /// Disconnects the trailer `tow` pulls (DisconnectTrailerAction); true if there was one.
    pub(crate) fn disconnect(&mut self, tow: EntityId) -> bool {
        let before = self.links.len();
        self.links.retain(|l| l.tow != tow);
        self.links.len() != before
    }

    /// Links in chain order: a tow's own link comes before the link it tows.
    pub(crate) fn order(&self) -> Vec<usize> {
        let depth = |l: &Link| {
            let mut d = 0usize;
            let mut up = self.tow_of(l.tow);
            // Connect refuses cycles, so the walk ends; the bound guards it anyway.
            while let Some(id) = up.filter(|_| d <= self.links.len()) {
                d += 1;
                up = self.tow_of(id);
            }
            d
        };
        let mut order = (0..self.links.len()).collect::<Vec<_>>();
        order.sort_by_key(|&i| depth(&self.links[i]));
        order
    }
}

/// The world position of a point `dx` ahead of the reference point of a vehicle at `pose`.
pub fn mount_point(pose: &Pose, dx: Real) -> (Real, Real) {
    (pose.x + dx * pose.h.cos(), pose.y + dx * pose.h.sin())
}

/// The trailer heading after its hitch moved from `from` to `to`, the trailer's heading
/// having been `heading` (the tractrix over a straight segment, module doc), for a
/// coupler-to-axle distance `l`.
pub fn tractrix_heading(heading: Real, from: (Real, Real), to: (Real, Real), l: Real) -> Real {
    let (dx, dy) = (to.0 - from.0, to.1 - from.1);
    let d = dx.hypot(dy);
    if d <= f64::EPSILON * l.max(1.0) {
        return heading;
    }
    let alpha = dy.atan2(dx);
    let phi0 = normalize_angle(heading - alpha);
    let phi = 2.0 * ((phi0 / 2.0).tan() * (-d / l).exp()).atan();
    normalize_angle(alpha + phi)
}

/// Reads the mounting points and the connections at definition: each vehicle's TrailerHitch
/// and TrailerCoupler, `TrailerRef` links, and inline `Trailer` objects, which are appended
/// to `entities` (named `<tow>+`) through `make`.
pub(crate) fn from_definitions(
    scenario: &Scenario,
    entities: &mut Vec<Entity>,
    make: impl Fn(EntityId, &ScenarioObject) -> Result<Entity, Error>,
) -> Result<Trailers, Error> {
    let mut trailers = Trailers::default();
    // (tow, its object, the reference or inline trailer) to connect once all exist.
    let mut pending = Vec::new();
    let mut stack = scenario
        .entities
        .scenario_objects
        .iter()
        .enumerate()
        .map(|(i, o)| (EntityId(i as u32), o.clone()))
        .collect::<Vec<_>>();
    while let Some((id, object)) = stack.pop() {
        let EntityObject::Vehicle(v) = &object.entity_object else {
            continue;
        };
        trailers.joints.insert(
            id,
            Joints {
                hitch: v.trailer_hitch.map(|j| j.dx),
                coupler: v.trailer_coupler.map(|j| j.dx),
            },
        );
        match &v.trailer {
            Some(Trailer::Trailer(inline)) => {
                let trailer_id = EntityId(entities.len() as u32);
                let mut e = make(trailer_id, inline)?;
                e.name = format!("{}+", entities[id.index()].name);
                entities.push(e);
                pending.push((id, trailer_id, object.pos.clone()));
                stack.push((trailer_id, (**inline).clone()));
            }
            Some(Trailer::TrailerRef(name)) => {
                let found = entities.iter().find(|e| &e.name == name).ok_or_else(|| {
                    Error::at(
                        "a declared entity",
                        format!("TrailerRef '{name}'"),
                        &object.pos,
                    )
                })?;
                pending.push((id, found.id, object.pos.clone()));
            }
            _ => {}
        }
    }
    pending.sort_by_key(|p| p.0);
    for (tow, trailer, pos) in pending {
        let names = |id: EntityId| entities[id.index()].name.clone();
        trailers.connect(&names, tow, trailer, true, &pos)?;
    }
    Ok(trailers)
}
