//! `avoid_collisions(true)` (ASAM OpenSCENARIO DSL 2.1 §8.9 movement modifiers,
//! `avoid_collisions`): in its phase the actor's speed is the engine's IDM car following
//! (OpenSCENARIO 1.3 §6.6 user-defined controllers; the engine's `idm` controller, Treiber,
//! Hennecke and Helbing 2000, with the paper's highway parameters), its planned speed the
//! desired speed: it drives at that speed on a free road and slows behind a slower vehicle
//! ahead in its lane instead of running into it.
//!
//! Lowered as an AssignControllerAction (an inline Controller `avoid_collisions`, Property
//! `model` = `idm`, `desiredSpeed` = the speed the plan gives the actor at the phase start or
//! reaches with the phase's speed modifier), activated on the longitudinal domain with the
//! phase, and an ActivateControllerAction that deactivates it when the phase ends (the phase's
//! `after` actions): from then on the actor keeps the speed the controller left it at. A
//! SpeedAction of the phase sets the controller's desired speed anew (the engine's reading).
//!
//! Every actor that moves: a vehicle with the paper's parameters, a person or an animal with a
//! walker's ([`WALKER_IDM`]: the same model, a pedestrian's gaps and rates), so a walker slows
//! behind a slower one, or stops behind one standing, in its lane (the engine's leader is
//! whatever is ahead in the lane, a vehicle, walker or stationary object). A
//! `stationary_object` does not move: `avoid_collisions(true)` on one is an error.
//!
//! Either direction of travel: the `idm` controller finds the leader from the vehicle's front
//! bumper along its lane in its lane track's direction (engine `ControllerView::leader`), so a
//! vehicle in a lane driven in −s (`plan::against`) follows the vehicle ahead of it towards −s.
//!
//! The plan no longer knows the actor's track from the phase start (as after a gap action):
//! a later phase of the actor at a time the plan sets is an error, and so are modifiers that
//! plan a distance for the phase (`position(…, at: end)`, `distance(…)`) and the gap actions,
//! whose own controller holds the speed. Nor where the actor is at the phase end: a route it
//! drives `along` is checked at the start only (`plan::route`). `avoid_collisions(false)`, and a phase without the
//! modifier, drive the planned motion (the library declares `avoid: bool` with no default;
//! oscsim's vehicles follow their plan unless asked to avoid).

use scenario::{Controller, ControllerAction, ControllerDomains, PrivateAction, Properties};

use super::planner::Planner;
use super::types::Planned;
use crate::error::{Error, ErrorKind as K, Site};
use crate::resolve::{Action, ActorKind, At, Invoke, ModKind, Modifier, Val};

/// The controller's name in the 1.x model.
const CONTROLLER: &str = "avoid_collisions";

/// The IDM's parameters for a person or an animal (`Property` names of the engine's `idm`
/// controller, SI units), oscsim's choice where the standard names none: a walker keeps
/// `minimumGap` 0.5 m to the one ahead when both stand (about a step: the distance people
/// queue at), a `timeHeadway` of 1 s when walking, starts at up to `maxAcceleration` 1 m/s²
/// and slows at a `comfortableDeceleration` of 1.5 m/s² (a walker stops within a step or two
/// from 1.4 m/s); δ stays the model's 4.
pub(super) const WALKER_IDM: [(&str, f64); 4] = [
    ("minimumGap", 0.5),
    ("timeHeadway", 1.0),
    ("maxAcceleration", 1.0),
    ("comfortableDeceleration", 1.5),
];

/// An inline Controller `name` running the engine's `model` (`idm`, `mobil`) at desired speed
/// `desired` (m/s), the model's `params` as given and its other parameters the model's
/// defaults, written at `site`.
pub(super) fn model_controller(
    name: &str,
    model: &str,
    desired: f64,
    params: &[(&str, f64)],
    site: &Site,
) -> Controller {
    let pos = site.pos.clone();
    let mut properties = vec![
        ("model".to_string(), model.to_string()),
        ("desiredSpeed".to_string(), format!("{desired}")),
    ];
    properties.extend(params.iter().map(|(k, v)| (k.to_string(), format!("{v}"))));
    Controller {
        name: name.to_string(),
        controller_type: None,
        properties: Properties {
            positions: vec![pos.clone(); properties.len()],
            properties,
            files: Vec::new(),
            custom_content: Vec::new(),
        },
        catalog: None,
        pos,
    }
}

/// The `avoid_collisions(…)` of `mods` that asks to avoid (`true`, or no argument), if any.
fn avoiding(mods: &[Modifier]) -> Result<Option<&Modifier>, Error> {
    let Some(m) = mods.iter().find(|m| m.kind == ModKind::AvoidCollisions) else {
        return Ok(None);
    };
    let avoid = match m.arg("avoid") {
        Some(a) => a.eval()? == Val::Bool(true),
        None => true,
    };
    Ok(avoid.then_some(m))
}

impl Planner<'_> {
    /// Checks what `avoid_collisions(true)` among `mods` excludes for `target` (before the
    /// phase's motion is planned).
    pub(super) fn check_avoid_collisions(
        &self,
        inv: &Invoke,
        mods: &[Modifier],
        target: &str,
    ) -> Result<(), Error> {
        let Some(m) = avoiding(mods)? else {
            return Ok(());
        };
        let i = self.index[target];
        if let ActorKind::Stationary(_) = self.entities[i].data.kind {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected a vehicle, person or animal for avoid_collisions(true), found `{target}`, a stationary_object"),
            ));
        }
        if matches!(
            inv.kind,
            Action::ChangeSpaceGap
                | Action::KeepSpaceGap
                | Action::ChangeTimeHeadway
                | Action::KeepTimeHeadway
        ) {
            return Err(m.site.err(
                K::Unsatisfiable,
                format!("expected avoid_collisions(true) beside an action that leaves the speed to it, found {}(…), whose distance controller holds the speed", inv.action),
            ));
        }
        if let Some(c) = mods.iter().find(|q| {
            (q.kind == ModKind::Position && q.at == At::End) || q.kind == ModKind::Distance
        }) {
            return Err(c.site.err(
                K::Unsatisfiable,
                format!("expected no distance planned beside avoid_collisions(true) at {} (the engine's car following sets the speed), found `{}(…)`", m.site.at(), c.name),
            ));
        }
        Ok(())
    }

    /// Plans `avoid_collisions(true)` among `mods` for `target` in its phase starting at `t0`,
    /// once the phase's speed is planned: the controller's assignment at the phase start into
    /// `out`, its deactivation into `after`.
    pub(super) fn plan_avoid_collisions(
        &mut self,
        mods: &[Modifier],
        target: &str,
        t0: Option<f64>,
        name: &mut dyn FnMut(&str) -> String,
        out: &mut Vec<Planned>,
        after: &mut Vec<Planned>,
    ) -> Result<(), Error> {
        let Some(m) = avoiding(mods)? else {
            return Ok(());
        };
        // The speed the plan gives the actor in the phase (its speed modifier's, else the
        // speed it has): the driver's desired speed.
        let desired = self.last_v.get(target).copied().unwrap_or(0.0);
        let params: &[(&str, f64)] = match self.entities[self.index[target]].data.kind {
            ActorKind::Walker(_) => &WALKER_IDM,
            _ => &[],
        };
        let controller = model_controller(CONTROLLER, "idm", desired, params, &m.site);
        let longitudinal = |on: bool| ControllerDomains {
            longitudinal: Some(on),
            ..ControllerDomains::default()
        };
        out.push(Planned::with_phase(
            target,
            name("avoid_collisions"),
            PrivateAction::Controller(Box::new(ControllerAction::Assign {
                controller,
                object_controller_name: None,
                activate: longitudinal(true),
            })),
            &m.site,
        ));
        after.push(Planned::with_phase(
            target,
            name("avoid_collisions_end"),
            PrivateAction::Controller(Box::new(ControllerAction::Activate {
                object_controller_ref: None,
                domains: longitudinal(false),
            })),
            &m.site,
        ));
        // From here the engine's controller moves the actor.
        self.engine_moves(target, t0);
        Ok(())
    }
}
